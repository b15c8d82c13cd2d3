//! Substitution of unseen ingredients by their nearest knowledge-base equivalent: the food-domain word
//! vectors of `table`, plus project knowledge that raw cosine lacks:
//!
//! - exact first: a query equal to a candidate (as written, through an alias, or word stem for word stem)
//!   maps to it with similarity 1;
//! - aliases (`data/food_aliases.tsv`): brand names, spelling variants, mis-singularised forms;
//! - candidates are base ingredients: dishes and mixtures ("egg mixture", "greek salad") are left out
//!   unless the query is itself a dish or a mixture;
//! - the food taxonomy (`data/food_taxonomy.tsv`): the same category first, then the same group; it
//!   encodes handling too (citrus is squeezed for juice, stone fruit is not);
//! - lexical structure: trailing form words ("pecan half", "chard leaf"), shared head nouns and modifiers;
//! - a calibrated low-confidence flag.
//!
//! All of it sits behind the `Similarity` trait, so the planner benefits without changes.

use crate::error::Result;
use crate::foon::kb::KnowledgeBase;
use crate::foon::label::normalize_label;
use crate::memo::Memo;
use crate::similarity::cones::{dot, Cones};
use crate::similarity::table::{is_stop_word, words, EmbeddingTable, WordStems};
use crate::similarity::{PairMemory, Prepared, Similarity};
use crate::vocab::food_taxonomy::{aliases, is_form_stem, stem_key, Category, Taxonomy};
use rustc_hash::FxHashMap as HashMap;
use serde::Serialize;
use std::sync::{Arc, Mutex, OnceLock};

/// Words that describe the state or size of an ingredient, not which ingredient it is; left out of the
/// vector of a phrase the taxonomy does not list ("whole clove", "fresh dill", "large egg").
const DESCRIPTORS: &[&str] = &[
    "fresh",
    "freshly",
    "dried",
    "whole",
    "large",
    "small",
    "medium",
    "big",
    "chopped",
    "minced",
    "sliced",
    "diced",
    "cubed",
    "grated",
    "shredded",
    "crushed",
    "frozen",
    "canned",
    "tinned",
    "cooked",
    "uncooked",
    "raw",
    "organic",
    "boneless",
    "skinless",
    "lean",
    "extra",
    "finely",
    "coarsely",
    "thinly",
    "roughly",
    "peeled",
    "pitted",
    "seeded",
    "halved",
    "quartered",
    "melted",
    "softened",
    "cold",
    "warm",
    "hot",
    "room",
    "temperature",
    "packed",
    "heaping",
    "level",
    "optional",
    "good",
    "quality",
    "best",
    "plain",
    "regular",
    "homemade",
    "store",
    "bought",
    "prepared",
    "instant",
    "quick",
    "low",
    "fat",
    "free",
    "reduced",
    "sodium",
    "light",
    "lite",
    "nonfat",
];

/// Groups whose members are not base ingredients.
const COMPOSITE_GROUPS: &[&str] = &["dish", "mixture"];
/// The group of kitchen tools, containers and appliances: never a substitute for an ingredient.
const UTENSIL_GROUP: &str = "utensil";

/// Knobs of the substitution score; `Options::default()` is the shipped configuration, the others are
/// the variants measured in `tests/similarity_eval.rs`.
#[derive(Clone, Debug, PartialEq)]
pub struct Options {
    /// Leave dishes and mixtures out of the candidates for a base-ingredient query.
    pub filter_composites: bool,
    /// Equal names, aliases and equal word stems rank first with similarity 1.
    pub exact_first: bool,
    pub aliases: bool,
    /// Weight of the last (head) word in a phrase vector.
    pub head_weight: f32,
    /// Added when query and candidate share a taxonomy category.
    pub same_category: f32,
    /// Added when they share only the coarse group.
    pub same_group: f32,
    /// Subtracted when both are known and of different groups.
    pub other_group: f32,
    /// Cosine to the nearest taxonomy member above which an unlisted query takes that member's category.
    pub infer_category_above: f32,
    /// Added when the head nouns are the same word stem.
    pub same_head: f32,
    /// Added when any other word stem is shared.
    pub shared_word: f32,
}

impl Default for Options {
    fn default() -> Options {
        Options {
            filter_composites: true,
            exact_first: true,
            aliases: true,
            head_weight: 2.0,
            same_category: 0.45,
            same_group: 0.12,
            other_group: 0.15,
            infer_category_above: 0.70,
            same_head: 0.10,
            shared_word: 0.05,
        }
    }
}

impl Options {
    /// Raw cosine of averaged word vectors over every candidate: the published approach with a
    /// food-domain table.
    pub fn cosine_only() -> Options {
        Options {
            filter_composites: false,
            exact_first: false,
            aliases: false,
            head_weight: 1.0,
            same_category: 0.0,
            same_group: 0.0,
            other_group: 0.0,
            infer_category_above: 2.0,
            same_head: 0.0,
            shared_word: 0.0,
        }
    }
}

/// A string with its hash: nearly every comparison of the score is between unequal strings, and those
/// differ at the first compare.
#[derive(Clone, Debug)]
struct Hashed {
    hash: u64,
    text: String,
}

impl Hashed {
    fn new(text: String) -> Hashed {
        use std::hash::{BuildHasher, BuildHasherDefault};
        let hash = BuildHasherDefault::<rustc_hash::FxHasher>::default().hash_one(&text);
        Hashed { hash, text }
    }

    /// Words joined by a space (words never hold one, so equal lists give equal texts).
    fn words(words: &[String]) -> Hashed {
        Hashed::new(words.join(" "))
    }

    fn is_empty(&self) -> bool {
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
struct Profile {
    /// Normal form as given.
    name: Hashed,
    /// The name the embedding and taxonomy use (after the alias list).
    canonical: Hashed,
    /// Word stems of `name`.
    key: Hashed,
    /// Word stems of the ingredient part of `canonical`, as the table resolves them.
    canonical_key: Hashed,
    /// Hashes of the words of `canonical_key`; the last is the head noun.
    stems: Vec<u64>,
    vector: Option<Vec<f32>>,
    category: Option<usize>,
    /// The category's group, by index into the taxonomy's groups.
    group: Option<usize>,
    /// Whether the category came from the listed names (not inferred from the vector).
    listed: bool,
    /// A dish or a mixture rather than a base ingredient (see `is_composite`).
    composite: bool,
    /// A listed kitchen tool, container or appliance.
    utensil: bool,
}

impl Profile {
    fn traits(&self) -> Traits<'_> {
        Traits {
            class: self.class(),
            stems: &self.stems,
        }
    }

    fn class(&self) -> Class {
        Class {
            category: self.category,
            group: self.group,
        }
    }

    fn is_known(&self) -> bool {
        self.vector.is_some() || self.category.is_some()
    }
}

/// What `graded` reads of a name besides its vector: from a profile, or from a candidate set's arrays.
#[derive(Clone, Copy)]
struct Traits<'a> {
    class: Class,
    /// Word hashes (equal words, equal hashes; a bonus, unlike an exact match, is decided on them
    /// alone), the head noun last.
    stems: &'a [u64],
}

/// A name's category and the category's group.
#[derive(Clone, Copy)]
struct Class {
    category: Option<usize>,
    group: Option<usize>,
}

/// Substitution by food-domain word vectors and the project's food knowledge.
pub struct EmbeddingSimilarity {
    table: EmbeddingTable,
    taxonomy: Arc<Taxonomy>,
    aliases: Arc<HashMap<String, String>>,
    options: Options,
    /// Unit vectors of the taxonomy members, one after another (`table.dims()` each), for inferring the
    /// category of unlisted names: every label of a knowledge base is compared with every member once.
    member_vectors: Vec<f32>,
    /// The category of each member of `member_vectors`, in its order.
    member_categories: Vec<usize>,
    /// Below this similarity a substitute is flagged as low confidence (calibrated on the dev set).
    confident_from: f32,
    profiles: Memo<String, Arc<Profile>, PROFILE_CACHE_LIMIT>,
    /// Answers of `rank_in_set` per (query, candidate set, top): ranking every label of a knowledge base
    /// is the costliest step of planning, and ingredient names recur from query to query.
    ranked: Memo<RankKey, Arc<[(String, f32)]>, RANK_CACHE_LIMIT>,
    /// The profiles of the candidate sets last used by `rank_in_set` and `prepare` (a knowledge base's
    /// labels), most recent last, so that a ranking or a comparison does not look each label up again.
    set_profiles: Mutex<Vec<(u64, SetProfiles)>>,
    /// Pairs the planner remembers from plan to plan (goal selection's).
    memory: PairMemory,
}

/// Candidate sets whose profiles are kept (a planner index has two: all labels, ingredient labels).
const SET_PROFILES_KEPT: usize = 4;

/// The profiles of one candidate set, in its order, remembered between calls.
type SetProfiles = Arc<CandidateSet>;

/// The profiles of a candidate set, with what a ranking reads of every candidate laid out in order: a
/// scan of a large knowledge base's labels then reads memory front to back instead of one profile here
/// and one there.
struct CandidateSet {
    profiles: Vec<Arc<Profile>>,
    dims: usize,
    /// `dims` values per candidate: its unit vector, or zeros when `has_vector` is false.
    vectors: Vec<f32>,
    has_vector: Vec<bool>,
    /// Hashes of each candidate's name, canonical name, word-stem key and canonical key: only one
    /// sharing a hash with the query can be an exact match, either way.
    hashes: Vec<[u64; 4]>,
    composite: Vec<bool>,
    utensil: Vec<bool>,
    known: Vec<bool>,
    class: Vec<Class>,
    /// Every candidate's `stems`, one after another; candidate i's are `stems[stem_at[i]..stem_at[i + 1]]`.
    stems: Vec<u64>,
    stem_at: Vec<u32>,
    /// For the rankings of a remembered set (`rank_in_set`), made on the first: the vectors grouped in
    /// cones, and the candidates by the hashes an exact match is decided on.
    search: OnceLock<SetSearch>,
}

/// What lets a ranking skip most of a large candidate set: cones of its vectors (skipped whole when
/// their bound cannot place), and its candidates by name hash and by stem-key hash (an exact match, which
/// outranks everything, is then found without a scan).
struct SetSearch {
    cones: Cones,
    by_name: HashMap<u64, Vec<u32>>,
    by_key: HashMap<u64, Vec<u32>>,
}

impl SetSearch {
    /// Every candidate that `may_match` `q` (and maybe a few more), ascending.
    fn exact_candidates(&self, q: &Profile) -> Vec<usize> {
        let names = [q.name.hash, q.canonical.hash].map(|h| self.by_name.get(&h));
        let keys = [q.key.hash, q.canonical_key.hash].map(|h| self.by_key.get(&h));
        let mut out: Vec<usize> = names
            .into_iter()
            .chain(keys)
            .flatten()
            .flatten()
            .map(|&i| i as usize)
            .collect();
        out.sort_unstable();
        out.dedup();
        out
    }
}

impl CandidateSet {
    fn new(profiles: Vec<Arc<Profile>>, dims: usize) -> CandidateSet {
        let mut vectors = vec![0.0; profiles.len() * dims];
        for (p, row) in profiles.iter().zip(vectors.chunks_exact_mut(dims.max(1))) {
            if let Some(v) = &p.vector {
                row.copy_from_slice(&v[..dims]);
            }
        }
        CandidateSet {
            dims,
            vectors,
            has_vector: profiles.iter().map(|p| p.vector.is_some()).collect(),
            hashes: profiles
                .iter()
                .map(|p| {
                    [
                        p.name.hash,
                        p.canonical.hash,
                        p.key.hash,
                        p.canonical_key.hash,
                    ]
                })
                .collect(),
            composite: profiles.iter().map(|p| p.composite).collect(),
            utensil: profiles.iter().map(|p| p.utensil).collect(),
            known: profiles.iter().map(|p| p.is_known()).collect(),
            class: profiles.iter().map(|p| p.class()).collect(),
            stems: profiles
                .iter()
                .flat_map(|p| p.stems.iter().copied())
                .collect(),
            stem_at: std::iter::once(0)
                .chain(profiles.iter().scan(0u32, |at, p| {
                    *at += p.stems.len() as u32;
                    Some(*at)
                }))
                .collect(),
            profiles,
            search: OnceLock::new(),
        }
    }

    fn search(&self) -> &SetSearch {
        self.search.get_or_init(|| {
            let mut by_name: HashMap<u64, Vec<u32>> = HashMap::default();
            let mut by_key: HashMap<u64, Vec<u32>> = HashMap::default();
            for (i, h) in self.hashes.iter().enumerate() {
                by_name.entry(h[0]).or_default().push(i as u32);
                by_key.entry(h[2]).or_default().push(i as u32);
            }
            SetSearch {
                cones: Cones::new(&self.vectors, self.dims, &self.has_vector),
                by_name,
                by_key,
            }
        })
    }

    fn len(&self) -> usize {
        self.profiles.len()
    }

    /// `may_match` the other way: whether `q` can be an exact match for candidate i.
    fn may_be_matched(&self, q: &Profile, i: usize) -> bool {
        self.hashes[i]
            .iter()
            .any(|&x| x == q.name.hash || x == q.key.hash)
    }
}

/// What a ranking reads of candidate i (in range): from a candidate set's arrays, or from a list of
/// profiles (a one-off ranking of a few names, where laying them out would cost more than the scan).
trait Scanned {
    fn count(&self) -> usize;
    fn profile(&self, i: usize) -> &Profile;
    fn composite(&self, i: usize) -> bool;
    fn utensil(&self, i: usize) -> bool;
    fn may_match(&self, sim: &EmbeddingSimilarity, q: &Profile, i: usize) -> bool;
    fn cosine(&self, q: &Profile, i: usize) -> f32;
    fn class(&self, i: usize) -> Class;
    fn traits(&self, i: usize) -> Traits<'_>;
}

impl Scanned for CandidateSet {
    fn count(&self) -> usize {
        self.len()
    }
    fn profile(&self, i: usize) -> &Profile {
        &self.profiles[i]
    }
    fn composite(&self, i: usize) -> bool {
        self.composite[i]
    }
    fn utensil(&self, i: usize) -> bool {
        self.utensil[i]
    }
    fn class(&self, i: usize) -> Class {
        self.class[i]
    }
    fn traits(&self, i: usize) -> Traits<'_> {
        Traits {
            class: self.class[i],
            stems: &self.stems[self.stem_at[i] as usize..self.stem_at[i + 1] as usize],
        }
    }
    /// Whether candidate i can be an exact match for `q`, from hashes alone: false is certain, true
    /// must be confirmed with `is_exact(q, candidate)`.
    fn may_match(&self, sim: &EmbeddingSimilarity, q: &Profile, i: usize) -> bool {
        let h = &self.hashes[i];
        sim.exact_rule(q, |x| x.hash == h[0], |x| x.hash == h[2])
    }
    /// `cosine_of(q, candidate i)`, from the laid-out vectors.
    fn cosine(&self, q: &Profile, i: usize) -> f32 {
        match &q.vector {
            Some(a) if self.has_vector[i] => {
                dot(a, &self.vectors[i * self.dims..(i + 1) * self.dims])
            }
            _ => 0.0,
        }
    }
}

impl Scanned for [Arc<Profile>] {
    fn count(&self) -> usize {
        self.len()
    }
    fn profile(&self, i: usize) -> &Profile {
        &self[i]
    }
    fn composite(&self, i: usize) -> bool {
        self[i].composite
    }
    fn utensil(&self, i: usize) -> bool {
        self[i].utensil
    }
    /// A profile's hashed strings compare by hash first: `is_exact` alone decides.
    fn may_match(&self, _: &EmbeddingSimilarity, _: &Profile, _: usize) -> bool {
        true
    }
    fn cosine(&self, q: &Profile, i: usize) -> f32 {
        cosine_of(q, &self[i])
    }
    fn class(&self, i: usize) -> Class {
        self[i].class()
    }
    fn traits(&self, i: usize) -> Traits<'_> {
        self[i].traits()
    }
}

/// (query, candidate set, top) of a remembered ranking.
type RankKey = (String, u64, usize);

/// Rankings kept by `rank_in_set`; the cache starts again when it is full.
const RANK_CACHE_LIMIT: usize = 20_000;

/// Taxonomy members that vote on the category of an unlisted name.
const INFER_NEIGHBOURS: usize = 7;

/// Names whose profiles are kept; the cache starts again when it is full. Every ranking visits every
/// label of the knowledge base, so the bound must exceed the label count of the largest knowledge base
/// worth planning on (about 50,000 for FOON-111 scaled 100 times): below it, each ranking recomputes
/// every profile.
const PROFILE_CACHE_LIMIT: usize = 100_000;
/// Longer names (no real ingredient) are not cached.
const MAX_CACHED_NAME: usize = 200;

impl std::fmt::Debug for EmbeddingSimilarity {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("EmbeddingSimilarity")
            .field("table", &self.table)
            .field("options", &self.options)
            .finish()
    }
}

/// Similarity at or above which a non-exact substitute of a name the taxonomy lists is not flagged,
/// provided it is of the query's category (see `low_confidence`). Calibrated on the dev set: 18% of
/// first candidates flagged, 94% of the others acceptable, 13 of the 22 wrong ones flagged.
pub const CONFIDENT_FROM: f32 = 0.85;
/// The same for a name the taxonomy does not list (category inferred from its vector). Measured with the
/// dev names taken out of the taxonomy: 40% flagged, 82% of the others acceptable, 28 of 47 wrong flagged.
pub const UNLISTED_CONFIDENT_FROM: f32 = 0.93;

impl EmbeddingSimilarity {
    /// Loads the table of `public/data/food-embeddings.bin` (checksum and version verified:
    /// `BadEmbeddings` on damage) with the shipped options.
    pub fn from_bytes(bytes: &[u8]) -> Result<EmbeddingSimilarity> {
        Ok(EmbeddingSimilarity::new(
            EmbeddingTable::from_bytes(bytes)?,
            Options::default(),
        ))
    }

    pub fn new(table: EmbeddingTable, options: Options) -> EmbeddingSimilarity {
        EmbeddingSimilarity::with_data(
            table,
            options,
            Arc::clone(Taxonomy::builtin()),
            Arc::clone(aliases()),
        )
    }

    /// With another taxonomy and alias list than the built-in ones (for measurements).
    pub fn with_data(
        table: EmbeddingTable,
        options: Options,
        taxonomy: Arc<Taxonomy>,
        aliases: Arc<HashMap<String, String>>,
    ) -> EmbeddingSimilarity {
        let mut member_vectors = Vec::new();
        let mut member_categories = Vec::new();
        for (name, c) in &taxonomy.members {
            if let Some(v) = table.embed_weighted(name, options.head_weight).vector {
                member_vectors.extend(unit(v));
                member_categories.push(*c);
            }
        }
        EmbeddingSimilarity {
            table,
            taxonomy,
            aliases,
            options,
            member_vectors,
            member_categories,
            confident_from: CONFIDENT_FROM,
            profiles: Memo::default(),
            ranked: Memo::default(),
            set_profiles: Mutex::new(Vec::new()),
            memory: PairMemory::default(),
        }
    }

    pub fn with_options(self, options: Options) -> EmbeddingSimilarity {
        EmbeddingSimilarity::with_data(self.table, options, self.taxonomy, self.aliases)
    }

    /// The same table and options with other project data (see `with_data`).
    pub fn with_taxonomy_and_aliases(
        self,
        taxonomy: Taxonomy,
        aliases: HashMap<String, String>,
    ) -> EmbeddingSimilarity {
        EmbeddingSimilarity::with_data(
            self.table,
            self.options,
            Arc::new(taxonomy),
            Arc::new(aliases),
        )
    }

    pub fn options(&self) -> &Options {
        &self.options
    }

    pub fn table(&self) -> &EmbeddingTable {
        &self.table
    }

    pub fn taxonomy(&self) -> &Taxonomy {
        &self.taxonomy
    }

    /// The profile of a name, from the cache when it was seen before (candidate labels recur on every
    /// query).
    fn profile(&self, name: &str) -> Arc<Profile> {
        if let Some(p) = self.profiles.get(name) {
            return p;
        }
        let p = Arc::new(self.compute_profile(name));
        if name.len() <= MAX_CACHED_NAME {
            self.profiles.insert(name.to_string(), Arc::clone(&p));
        }
        p
    }

    fn compute_profile(&self, name: &str) -> Profile {
        let name = normalize_label(name);
        let canonical = if self.options.aliases {
            self.aliases
                .get(&name)
                .cloned()
                .unwrap_or_else(|| name.clone())
        } else {
            name.clone()
        };
        // the words of the canonical name with their stems (`stem_key`) as the table resolved them
        let mut kept: Vec<(String, Arc<WordStems>)> = words(&canonical)
            .into_iter()
            .filter(|w| !is_stop_word(w))
            .map(|w| {
                let stems = self.table.resolve(&w);
                (w, stems)
            })
            .collect();
        let whole_key: Vec<String> = kept.iter().map(|(_, r)| r.stem.clone()).collect();
        let key = if canonical == name {
            whole_key.clone()
        } else {
            stem_key(&name)
        };
        // "pecan half", "chard leaf": the ingredient is what the form word is of, unless the whole
        // phrase is a listed name ("bay leaf", "garlic powder").
        let listed_whole = self.taxonomy.lists(&whole_key);
        if !listed_whole {
            let described: Vec<(String, Arc<WordStems>)> = kept
                .iter()
                .filter(|(w, _)| !DESCRIPTORS.contains(&w.as_str()))
                .cloned()
                .collect();
            if !described.is_empty() {
                kept = described;
            }
        }
        let whole = self.taxonomy.lookup_key(&whole_key);
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
        let mut category = self.taxonomy.lookup_key(&canonical_key);
        let listed = category.is_some();
        if category.is_none() {
            if let Some(v) = &vector {
                category = self.infer_category(v);
            }
        }
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

    /// Index of a category's group among the taxonomy's groups (first seen first).
    fn group_of(&self, category: usize) -> usize {
        let group = &self.taxonomy.category(category).group;
        self.taxonomy
            .categories
            .iter()
            .position(|c| c.group == *group)
            .unwrap_or(category)
    }

    /// The category most of the nearest taxonomy members share (similarity-weighted vote of the
    /// `INFER_NEIGHBOURS` nearest), when the nearest is near enough.
    fn infer_category(&self, v: &[f32]) -> Option<usize> {
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
        let mut votes: Vec<(usize, f32)> = Vec::new();
        for (s, c) in near {
            match votes.iter_mut().find(|(vc, _)| *vc == c) {
                Some(v) => v.1 += s,
                None => votes.push((c, s)),
            }
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

    fn is_composite(&self, name: &str, listed: bool, category: Option<usize>) -> bool {
        let by_category = listed
            && category.is_some_and(|c| {
                COMPOSITE_GROUPS.contains(&self.taxonomy.category(c).group.as_str())
            });
        by_category || name.contains('-') && !name.contains("-and-")
    }

    fn is_exact(&self, q: &Profile, c: &Profile) -> bool {
        self.exact_rule(q, |x| *x == c.name, |x| *x == c.key)
    }

    /// When a candidate is an exact match for `q`, given what its name equals (`name_is`) and what its
    /// word-stem key equals (`key_is`): `is_exact` asks with the candidate's strings, a ranking first
    /// with its hashes alone (equal strings have equal hashes).
    fn exact_rule(
        &self,
        q: &Profile,
        name_is: impl Fn(&Hashed) -> bool,
        key_is: impl Fn(&Hashed) -> bool,
    ) -> bool {
        name_is(&q.name)
            || (self.options.exact_first
                && (name_is(&q.canonical)
                    || (!q.key.is_empty() && key_is(&q.key))
                    || (!q.canonical_key.is_empty() && key_is(&q.canonical_key))))
    }

    /// The unbounded score behind `similarity` (higher is better).
    fn score(&self, q: &Profile, c: &Profile) -> f32 {
        if self.is_exact(q, c) {
            return f32::INFINITY;
        }
        self.graded(q.traits(), c.traits(), cosine_of(q, c))
    }

    /// The score of a pair that is not exact, from the cosine of their vectors.
    fn graded(&self, q: Traits, c: Traits, cosine: f32) -> f32 {
        let o = &self.options;
        // adding 0 for no category changes nothing: a cosine is never -0
        let mut s = cosine + self.category_bonus(q.class, c.class);
        let (hq, hc) = (q.stems.last(), c.stems.last());
        if hq.is_some() && hq == hc {
            s += o.same_head;
        }
        let both_heads = |w: &u64| hq == Some(w) && hc == Some(w);
        if q.stems
            .iter()
            .any(|w| c.stems.contains(w) && !both_heads(w))
        {
            s += o.shared_word;
        }
        s
    }

    /// What `graded` adds for the categories of a pair (0 unless both have one): the largest of its
    /// bonuses and the cheapest, so that a ranking rules many candidates out by it before it reads their
    /// words and vectors.
    fn category_bonus(&self, q: Class, c: Class) -> f32 {
        let o = &self.options;
        match (q.category, c.category) {
            (Some(a), Some(b)) if a == b => o.same_category,
            (Some(_), Some(_)) if q.group == c.group => o.same_group,
            (Some(_), Some(_)) => -o.other_group,
            _ => 0.0,
        }
    }

    /// The most `graded` can add to a cosine: a cone whose bound plus this cannot reach the ranking's
    /// last place is not visited.
    fn max_bonus(&self) -> f32 {
        let o = &self.options;
        o.same_category.max(o.same_group).max(0.0) + o.same_head.max(0.0) + o.shared_word.max(0.0)
    }

    /// Ranks candidates for a query; shared by `rank` and the evaluation.
    fn rank_profiles<S: AsRef<str>>(
        &self,
        query: &str,
        candidates: &[S],
        top: usize,
    ) -> Vec<(String, f32)> {
        let profiles: Vec<Arc<Profile>> = candidates
            .iter()
            .map(|c| self.profile(c.as_ref()))
            .collect();
        self.rank_among(query, candidates, profiles.as_slice(), top, None)
    }

    /// The `top` best of `candidates` (with their profiles in `set`, same order), best first, ties by
    /// label, each label once. Keeps only the best few while scanning: a knowledge base has thousands of
    /// labels, and a candidate that cannot place is not scored. With `search` (of a remembered set,
    /// ranked again and again), exact matches are looked up by hash and the cones of vectors are visited
    /// nearest first, until the next cone cannot place; the answer is the full scan's.
    fn rank_among<'c, S: AsRef<str>>(
        &self,
        query: &str,
        candidates: &'c [S],
        set: &(impl Scanned + ?Sized),
        top: usize,
        search: Option<&SetSearch>,
    ) -> Vec<(String, f32)> {
        let q = self.profile(query);
        let keep_composites = !self.options.filter_composites || q.composite;
        let max_bonus = self.max_bonus();
        let max_words = self.options.same_head.max(0.0) + self.options.shared_word.max(0.0);
        let better = |a: &(&str, f32), b: &(&str, f32)| {
            b.1.total_cmp(&a.1).then_with(|| a.0.cmp(b.0)) == std::cmp::Ordering::Less
        };
        let mut best: Vec<(&'c str, f32)> = Vec::with_capacity(top + 1);
        // `most`: the most a score can be (with a margin for rounding)
        let cannot_place = |best: &[(&str, f32)], most: f32| {
            best.len() == top && best.last().is_some_and(|w| most + 1e-3 < w.1)
        };
        // `may_be_exact`: false once every candidate that may be an exact match was considered (a second
        // look at one changes nothing: it placed, or `top` exact matches outrank it); `most_cosine`: the
        // most candidate i's cosine can be
        let consider =
            |i: usize, may_be_exact: bool, most_cosine: f32, best: &mut Vec<(&'c str, f32)>| {
                let Some(cand) = candidates.get(i).map(AsRef::as_ref) else {
                    return;
                };
                // the hashes rule most candidates out without reading their profiles
                let exact =
                    may_be_exact && set.may_match(self, &q, i) && self.is_exact(&q, set.profile(i));
                if !exact
                    && (!q.is_known()
                        || (!keep_composites && set.composite(i))
                        || (self.options.filter_composites && set.utensil(i)))
                {
                    return;
                }
                let score = if exact {
                    f32::INFINITY
                } else {
                    // many candidates cannot place whatever their cosine and words: neither is read
                    let most = self.category_bonus(q.class(), set.class(i)) + max_words;
                    if cannot_place(best, most_cosine + most) {
                        return;
                    }
                    let cosine = set.cosine(&q, i);
                    if cannot_place(best, cosine + most) {
                        return;
                    }
                    self.graded(q.traits(), set.traits(i), cosine)
                };
                let item = (cand, score);
                if best.len() == top && best.last().is_none_or(|w| !better(&item, w)) {
                    return;
                }
                if best.iter().any(|b| b.0 == cand) {
                    return; // the same label listed twice scores the same
                }
                let at = best.partition_point(|b| better(b, &item));
                best.insert(at, item);
                best.truncate(top);
            };
        if let Some(search) = search {
            for i in search.exact_candidates(&q) {
                consider(i, true, f32::INFINITY, &mut best);
            }
            if q.is_known() {
                let cones = &search.cones;
                for (most, k) in cones.bounds(q.vector.as_deref()) {
                    if cannot_place(&best, most + max_bonus) {
                        break; // the cones come nearest first: no later one can place either
                    }
                    for &i in cones.members(k) {
                        consider(i as usize, false, most, &mut best);
                    }
                }
            }
        } else {
            for i in 0..set.count() {
                consider(i, true, f32::INFINITY, &mut best);
            }
        }
        best.into_iter()
            .map(|(l, s)| (l.to_string(), squash(s)))
            .collect()
    }

    /// The profiles of a candidate set, remembered for the last few set ids asked.
    fn set_profiles(&self, set: u64, candidates: &[String]) -> SetProfiles {
        if let Ok(kept) = self.set_profiles.lock() {
            if let Some((_, profiles)) = kept
                .iter()
                .find(|(id, p)| *id == set && p.len() == candidates.len())
            {
                return Arc::clone(profiles);
            }
        }
        let profiles = Arc::new(CandidateSet::new(
            candidates.iter().map(|c| self.profile(c)).collect(),
            self.table.dims(),
        ));
        if let Ok(mut kept) = self.set_profiles.lock() {
            kept.retain(|(id, _)| *id != set);
            if kept.len() >= SET_PROFILES_KEPT {
                kept.remove(0);
            }
            kept.push((set, Arc::clone(&profiles)));
        }
        profiles
    }

    /// `Similarity::similarity` on profiles.
    fn profile_similarity(&self, a: &Profile, b: &Profile) -> f32 {
        if !a.is_known() && !self.is_exact(a, b) {
            return 0.0;
        }
        squash(self.score(a, b))
    }
}

/// A query's profile with the profiles of a candidate set (`Similarity::prepare`).
struct PreparedName<'a> {
    sim: &'a EmbeddingSimilarity,
    query: Arc<Profile>,
    set: SetProfiles,
}

impl Prepared for PreparedName<'_> {
    fn to(&self, i: usize) -> f32 {
        self.set
            .profiles
            .get(i)
            .map_or(0.0, |c| self.sim.profile_similarity(&self.query, c))
    }

    fn from(&self, i: usize) -> f32 {
        self.set
            .profiles
            .get(i)
            .map_or(0.0, |c| self.sim.profile_similarity(c, &self.query))
    }

    fn both(&self, i: usize) -> (f32, f32) {
        let (set, q) = (&self.set, &self.query);
        if i >= set.len() {
            return (0.0, 0.0);
        }
        // the candidate's profile is read only when its hashes allow an exact match: a scan of many
        // labels then reads the set's arrays in order
        if (set.may_match(self.sim, q, i) && self.sim.is_exact(q, &set.profiles[i]))
            || (set.may_be_matched(q, i) && self.sim.is_exact(&set.profiles[i], q))
        {
            return (self.to(i), self.from(i));
        }
        // neither is exact: the graded score is symmetric, so one comparison serves both
        let s = squash(self.sim.graded(q.traits(), set.traits(i), set.cosine(q, i)));
        (
            if q.is_known() { s } else { 0.0 },
            if set.known[i] { s } else { 0.0 },
        )
    }
}

/// Cosine of two profiles' unit vectors (0 when either has none).
fn cosine_of(q: &Profile, c: &Profile) -> f32 {
    match (&q.vector, &c.vector) {
        (Some(a), Some(b)) => dot(a, b),
        _ => 0.0,
    }
}

fn unit(mut v: Vec<f32>) -> Vec<f32> {
    let n = crate::similarity::table::norm(&v);
    if n > 0.0 {
        v.iter_mut().for_each(|x| *x /= n);
    }
    v
}

/// Maps the unbounded score to [0, 0.99] monotonically; exact matches (infinite score) give 1.
fn squash(score: f32) -> f32 {
    if score == f32::INFINITY {
        return 1.0;
    }
    let v = 0.99 / (1.0 + (-(score - 0.6) * 5.0).exp());
    round_half_up(v * 1000.0) / 1000.0
}

/// `x.round()` for `x >= 0` (halves away from zero), from `trunc`: `round` is a libm call in WASM,
/// `trunc` one instruction, and a goal selection squashes tens of thousands of scores.
fn round_half_up(x: f32) -> f32 {
    let whole = x.trunc();
    if x - whole >= 0.5 {
        whole + 1.0
    } else {
        whole
    }
}

impl Similarity for EmbeddingSimilarity {
    fn similarity(&self, a: &str, b: &str) -> f32 {
        self.profile_similarity(&self.profile(a), &self.profile(b))
    }

    fn rank(&self, query: &str, candidates: &[&str], top: usize) -> Vec<(String, f32)> {
        self.rank_profiles(query, candidates, top)
    }

    fn rank_in_set(
        &self,
        query: &str,
        set: u64,
        candidates: &[String],
        top: usize,
    ) -> Arc<[(String, f32)]> {
        if query.len() > MAX_CACHED_NAME {
            return self.rank_profiles(query, candidates, top).into();
        }
        self.ranked
            .get_or_insert_with((query.to_string(), set, top), || {
                let profiles = self.set_profiles(set, candidates);
                self.rank_among(query, candidates, &*profiles, top, Some(profiles.search()))
                    .into()
            })
    }

    fn prepare<'a>(
        &'a self,
        query: &str,
        set: u64,
        candidates: &'a [String],
    ) -> Box<dyn Prepared + 'a> {
        Box::new(PreparedName {
            sim: self,
            query: self.profile(query),
            set: self.set_profiles(set, candidates),
        })
    }

    fn low_confidence(&self, query: &str, label: &str, similarity: f32) -> bool {
        if similarity >= 1.0 {
            return false;
        }
        let (q, c) = (self.profile(query), self.profile(label));
        let needed = if q.listed {
            self.confident_from
        } else {
            UNLISTED_CONFIDENT_FROM
        };
        !q.is_known() || q.category.is_none() || q.category != c.category || similarity < needed
    }

    fn memory(&self) -> Option<&PairMemory> {
        Some(&self.memory)
    }
}

/// One ranked candidate.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Candidate {
    pub label: String,
    pub similarity: f32,
}

/// The candidates for one queried name, best first (empty when the name is unknown).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SimilarResult {
    pub query: String,
    pub candidates: Vec<Candidate>,
}

/// Ranks each name against the knowledge base's ingredient labels (the same candidates and filtering the
/// planner gets through `Similarity::rank`). The CLI's `similar` command prints this as JSON.
pub fn similar(
    kb: &KnowledgeBase,
    sim: &dyn Similarity,
    names: &[String],
    top: usize,
) -> Vec<SimilarResult> {
    let labels: Vec<&str> = kb.ingredient_labels().into_iter().collect();
    names
        .iter()
        .map(|name| {
            let query = normalize_label(name);
            let candidates = sim
                .rank(&query, &labels, top)
                .into_iter()
                .map(|(label, similarity)| Candidate { label, similarity })
                .collect();
            SimilarResult {
                query: name.clone(),
                candidates,
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn taxonomy_finds_longest_listed_ending_and_drops_form_words() {
        let t = Taxonomy::builtin();
        let cat = |p: &str| t.lookup(p).map(|c| t.category(c).name.clone());
        assert_eq!(cat("red wine vinegar").as_deref(), Some("vinegar"));
        assert_eq!(cat("white wine").as_deref(), Some("wine"));
        assert_eq!(cat("Lemons").as_deref(), Some("citrus"));
        assert_eq!(cat("pecan halves").as_deref(), Some("nut"));
        assert_eq!(cat("chard leaf").as_deref(), Some("leafy green"));
        assert_eq!(cat("bay leaf").as_deref(), Some("herb"));
        assert_eq!(cat("egg mixture").as_deref(), Some("mixture"));
        assert_eq!(cat("macaroni and cheese").as_deref(), Some("dish"));
        assert_eq!(cat("zzzq"), None);
    }

    #[test]
    fn aliases_are_in_normal_form() {
        assert_eq!(
            aliases().get("molass").map(String::as_str),
            Some("molasses")
        );
        assert_eq!(
            aliases().get("cool whip").map(String::as_str),
            Some("whipped topping")
        );
    }

    #[test]
    fn rounding_half_up_is_rounding_for_every_squashed_value() {
        // 0 to 1000 in steps of 1/4096, and every f32 around each half-way point, where the two could
        // differ
        let mut x = 0.0f32;
        while x <= 1000.0 {
            assert_eq!(round_half_up(x).to_bits(), x.round().to_bits(), "{x}");
            x += 1.0 / 4096.0;
        }
        for k in 0..1000 {
            let half = k as f32 + 0.5;
            let mut y = f32::from_bits(half.to_bits() - 64);
            while y <= f32::from_bits(half.to_bits() + 64) {
                assert_eq!(round_half_up(y).to_bits(), y.round().to_bits(), "{y}");
                y = f32::from_bits(y.to_bits() + 1);
            }
        }
    }

    #[test]
    fn squash_is_monotone_and_bounded() {
        let mut last = -1.0;
        for i in -20..40 {
            let v = squash(i as f32 / 10.0);
            assert!((0.0..=0.99).contains(&v) && v >= last);
            last = v;
        }
        assert_eq!(squash(f32::INFINITY), 1.0);
    }
}
