//! A name's profile: everything the substitution score needs about one name, computed once per name.

use super::words::{is_descriptor, COMPOSITE_GROUPS, UTENSIL_GROUP};
use super::{EmbeddingSimilarity, MAX_CACHED_NAME};
use crate::foon::label::normalize_label;
use crate::similarity::cones::dot;
use crate::similarity::table::{is_stop_word, words, WordStems};
use crate::vocab::food_taxonomy::{is_form_stem, stem_key, Category};
use std::collections::BTreeMap;
use std::sync::Arc;

/// A string with its hash: nearly every comparison of the score is between unequal strings, and those
/// differ at the first compare.
#[derive(Clone, Debug)]
pub(super) struct Hashed {
    pub(super) hash: u64,
    pub(super) text: String,
}

impl Hashed {
    pub(super) fn new(text: String) -> Hashed {
        use std::hash::{BuildHasher, BuildHasherDefault};
        let hash = BuildHasherDefault::<rustc_hash::FxHasher>::default().hash_one(&text);
        Hashed { hash, text }
    }

    /// Words joined by a space (words never hold one, so equal lists give equal texts).
    pub(super) fn words(words: &[String]) -> Hashed {
        Hashed::new(words.join(" "))
    }

    pub(super) fn is_empty(&self) -> bool {
        self.text.is_empty()
    }
}

impl PartialEq for Hashed {
    fn eq(&self, other: &Hashed) -> bool {
        self.hash == other.hash && self.text == other.text
    }
}

/// Everything the score needs about one name, computed once per name.
#[derive(Clone, Debug)]
pub(super) struct Profile {
    /// Normal form as given.
    pub(super) name: Hashed,
    /// The name the embedding and taxonomy use (after the alias list).
    pub(super) canonical: Hashed,
    /// Word stems of `name`.
    pub(super) key: Hashed,
    /// Word stems of the ingredient part of `canonical`, as the table resolves them.
    pub(super) canonical_key: Hashed,
    /// Hashes of the words of `canonical_key`; the last is the head noun.
    pub(super) stems: Vec<u64>,
    pub(super) vector: Option<Vec<f32>>,
    pub(super) category: Option<usize>,
    /// The category's group, by index into the taxonomy's groups.
    pub(super) group: Option<usize>,
    /// Whether the category came from the listed names (not inferred from the vector).
    pub(super) listed: bool,
    /// A dish or a mixture rather than a base ingredient (see `is_composite`).
    pub(super) composite: bool,
    /// A listed kitchen tool, container or appliance.
    pub(super) utensil: bool,
}

impl Profile {
    pub(super) fn traits(&self) -> Traits<'_> {
        Traits {
            class: self.class(),
            stems: &self.stems,
        }
    }

    pub(super) fn class(&self) -> Class {
        Class {
            category: self.category,
            group: self.group,
        }
    }

    pub(super) fn is_known(&self) -> bool {
        self.vector.is_some() || self.category.is_some()
    }
}

/// What `graded` reads of a name besides its vector: from a profile, or from a candidate set's arrays.
#[derive(Clone, Copy)]
pub(super) struct Traits<'a> {
    pub(super) class: Class,
    /// Word hashes (equal words, equal hashes; a bonus, unlike an exact match, is decided on them
    /// alone), the head noun last.
    pub(super) stems: &'a [u64],
}

/// A name's category and the category's group.
#[derive(Clone, Copy)]
pub(super) struct Class {
    pub(super) category: Option<usize>,
    pub(super) group: Option<usize>,
}

/// Taxonomy members that vote on the category of an unlisted name.
pub(super) const INFER_NEIGHBOURS: usize = 7;

impl EmbeddingSimilarity {
    /// The profile of a name, from the cache when it was seen before (candidate labels recur on every
    /// query).
    pub(super) fn profile(&self, name: &str) -> Arc<Profile> {
        if let Some(p) = self.profiles.get(name) {
            return p;
        }
        let p = Arc::new(self.compute_profile(name));
        if name.len() <= MAX_CACHED_NAME {
            self.profiles.insert(name.to_string(), Arc::clone(&p));
        }
        p
    }

    pub(super) fn compute_profile(&self, name: &str) -> Profile {
        let name = normalize_label(name);
        let canonical = match self.aliases.get(&name) {
            Some(alias) if self.options.aliases => alias.clone(),
            _ => name.clone(),
        };
        // the words of the canonical name with their stems (`stem_key`) as the table resolved them
        let words: Vec<(String, Arc<WordStems>)> = words(&canonical)
            .into_iter()
            .filter(|w| !is_stop_word(w))
            .map(|w| {
                let stems = self.table.resolve(&w);
                (w, stems)
            })
            .collect();
        let whole_key: Vec<String> = words.iter().map(|(_, r)| r.stem.clone()).collect();
        let key = if canonical == name {
            whole_key.clone()
        } else {
            stem_key(&name)
        };
        let kept = self.ingredient_words(words, &whole_key);
        // Stems as the table resolves them, so that a plural cut short ("watercres") finds its listing.
        let canonical_key: Vec<String> = kept
            .iter()
            .map(|(_, r)| match r.stems.as_slice() {
                [one] => one.clone(),
                _ => r.stem.clone(),
            })
            .collect();
        let kept: Vec<String> = kept.into_iter().map(|(w, _)| w).collect();
        let vector = self
            .table
            .embed_words(&kept, self.options.head_weight)
            .vector
            .map(unit);
        let listed_category = self.taxonomy.lookup_key(&canonical_key);
        let listed = listed_category.is_some();
        let category = listed_category.or_else(|| self.infer_category(vector.as_ref()?));
        let group = category.map(|c| self.group_of(c));
        let composite = self.is_composite(&name, listed, category);
        let utensil =
            listed && category.is_some_and(|c| self.taxonomy.category(c).group == UTENSIL_GROUP);
        Profile {
            name: Hashed::new(name),
            canonical: Hashed::new(canonical),
            key: Hashed::words(&key),
            canonical_key: Hashed::words(&canonical_key),
            stems: canonical_key
                .into_iter()
                .map(|w| Hashed::new(w).hash)
                .collect(),
            vector,
            category,
            group,
            listed,
            composite,
            utensil,
        }
    }

    /// The words of a name (`whole_key`: their stems) that say which ingredient it is: "pecan half",
    /// "chard leaf" are what the form word is of, and "fresh dill" is dill, unless the whole phrase is a
    /// listed name ("bay leaf", "garlic powder").
    fn ingredient_words(
        &self,
        mut kept: Vec<(String, Arc<WordStems>)>,
        whole_key: &[String],
    ) -> Vec<(String, Arc<WordStems>)> {
        let listed_whole = self.taxonomy.lists(whole_key);
        if !listed_whole && kept.iter().any(|(w, _)| !is_descriptor(w)) {
            kept.retain(|(w, _)| !is_descriptor(w));
        }
        let whole = self.taxonomy.lookup_key(whole_key);
        while kept.len() > 1 && kept.last().is_some_and(|(_, r)| is_form_stem(&r.stem)) {
            let shorter: Vec<String> = kept[..kept.len() - 1]
                .iter()
                .map(|(_, r)| r.stem.clone())
                .collect();
            // keep "garlic powder" whole (a spice, not an allium); drop "half" of "pecan half"
            if listed_whole && self.taxonomy.lookup_key(&shorter) != whole {
                break;
            }
            kept.pop();
        }
        kept
    }

    /// Index of a category's group among the taxonomy's groups (first seen first).
    pub(super) fn group_of(&self, category: usize) -> usize {
        let group = &self.taxonomy.category(category).group;
        self.taxonomy
            .categories
            .iter()
            .position(|c| c.group == *group)
            .unwrap_or(category)
    }

    /// The category most of the nearest taxonomy members share (similarity-weighted vote of the
    /// `INFER_NEIGHBOURS` nearest), when the nearest is near enough.
    pub(super) fn infer_category(&self, v: &[f32]) -> Option<usize> {
        let nearer = |a: &(f32, usize), b: &(f32, usize)| b.0.total_cmp(&a.0).then(a.1.cmp(&b.1));
        // the nearest few, nearest first, kept while scanning: most members are not among them
        let mut near: Vec<(f32, usize)> = Vec::with_capacity(INFER_NEIGHBOURS + 1);
        let members = self.member_vectors.chunks_exact(self.table.dims().max(1));
        for (m, &c) in members.zip(&self.member_categories) {
            let item = (dot(m, v), c);
            let full = near.len() == INFER_NEIGHBOURS;
            // strictly below the last kept cannot enter: one float comparison for most members
            if full
                && near
                    .last()
                    .is_some_and(|w| item.0 < w.0 || nearer(&item, w).is_ge())
            {
                continue;
            }
            let at = near.partition_point(|b| nearer(b, &item).is_le());
            near.insert(at, item);
            near.truncate(INFER_NEIGHBOURS);
        }
        if near.first()?.0 < self.options.infer_category_above {
            return None;
        }
        let mut votes: BTreeMap<usize, f32> = BTreeMap::new();
        for (s, c) in near {
            votes.entry(c).and_modify(|v| *v += s).or_insert(s);
        }
        votes
            .into_iter()
            .max_by(|a, b| a.1.total_cmp(&b.1).then(b.0.cmp(&a.0)))
            .map(|(c, _)| c)
    }

    /// The category name of a phrase (listed or inferred), for diagnostics and the UI.
    pub fn category_of(&self, name: &str) -> Option<&Category> {
        self.profile(name)
            .category
            .map(|c| self.taxonomy.category(c))
    }

    pub(super) fn is_composite(&self, name: &str, listed: bool, category: Option<usize>) -> bool {
        let by_category = listed
            && category.is_some_and(|c| {
                COMPOSITE_GROUPS.contains(&self.taxonomy.category(c).group.as_str())
            });
        by_category || name.contains('-') && !name.contains("-and-")
    }
}

/// Cosine of two profiles' unit vectors (0 when either has none).
pub(super) fn cosine_of(q: &Profile, c: &Profile) -> f32 {
    match (&q.vector, &c.vector) {
        (Some(a), Some(b)) => dot(a, b),
        _ => 0.0,
    }
}

pub(super) fn unit(mut v: Vec<f32>) -> Vec<f32> {
    let n = crate::similarity::table::norm(&v);
    if n > 0.0 {
        v.iter_mut().for_each(|x| *x /= n);
    }
    v
}
