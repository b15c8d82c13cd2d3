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

mod candidates;
mod profile;
mod words;

use crate::error::Result;
use crate::foon::kb::KnowledgeBase;
use crate::foon::label::normalize_label;
use crate::memo::Memo;
use crate::similarity::table::EmbeddingTable;
use crate::similarity::{PairMemory, Prepared, Similarity};
use crate::vocab::food_taxonomy::{aliases, Taxonomy};
use candidates::{CandidateSet, PreparedName, SetProfiles, SetSearch};
use profile::{cosine_of, unit, Class, Hashed, Profile, Traits};
use rustc_hash::FxHashMap as HashMap;
use serde::Serialize;
use std::sync::{Arc, Mutex};

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

/// (query, candidate set, top) of a remembered ranking.
type RankKey = (String, u64, usize);

/// Rankings kept by `rank_in_set`; the cache starts again when it is full.
const RANK_CACHE_LIMIT: usize = 20_000;

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
        let set = CandidateSet::new(profiles, self.table.dims());
        self.rank_among(query, candidates, &set, top, None)
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
        set: &CandidateSet,
        top: usize,
        search: Option<&SetSearch>,
    ) -> Vec<(String, f32)> {
        let q = self.profile(query);
        let max_bonus = self.max_bonus();
        let better = |a: &(&str, f32), b: &(&str, f32)| {
            b.1.total_cmp(&a.1).then_with(|| a.0.cmp(b.0)) == std::cmp::Ordering::Less
        };
        let mut best: Vec<(&'c str, f32)> = Vec::with_capacity(top + 1);
        // `most`: the most a score can be (with a margin for rounding)
        let cannot_place = |best: &[(&str, f32)], most: f32| {
            best.len() == top && best.last().is_some_and(|w| most + 1e-3 < w.1)
        };
        let consider =
            |i: usize, may_be_exact: bool, most_cosine: f32, best: &mut Vec<(&'c str, f32)>| {
                let Some(cand) = candidates.get(i).map(AsRef::as_ref) else {
                    return;
                };
                let place = |most| cannot_place(best, most);
                let Some(score) = self.ranked_score(&q, set, i, may_be_exact, most_cosine, place)
                else {
                    return;
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
            for i in 0..set.len() {
                consider(i, true, f32::INFINITY, &mut best);
            }
        }
        best.into_iter()
            .map(|(l, s)| (l.to_string(), squash(s)))
            .collect()
    }

    /// Candidate i's score for `q` in a ranking; `None` when it is left out, or when `cannot_place` the
    /// most its score can be. `may_be_exact`: false once every candidate that may be an exact match was
    /// considered (a second look at one changes nothing: it placed, or `top` exact matches outrank it);
    /// `most_cosine`: the most its cosine can be.
    fn ranked_score(
        &self,
        q: &Profile,
        set: &CandidateSet,
        i: usize,
        may_be_exact: bool,
        most_cosine: f32,
        cannot_place: impl Fn(f32) -> bool,
    ) -> Option<f32> {
        // the hashes rule most candidates out without reading their profiles
        if may_be_exact && set.may_match(self, q, i) && self.is_exact(q, &set.profiles[i]) {
            return Some(f32::INFINITY);
        }
        let o = &self.options;
        let keep_composites = !o.filter_composites || q.composite;
        if !q.is_known()
            || (!keep_composites && set.composite[i])
            || (o.filter_composites && set.utensil[i])
        {
            return None;
        }
        // many candidates cannot place whatever their cosine and words: neither is read
        let max_words = o.same_head.max(0.0) + o.shared_word.max(0.0);
        let most = self.category_bonus(q.class(), set.class[i]) + max_words;
        if cannot_place(most_cosine + most) {
            return None;
        }
        let cosine = set.cosine(q, i);
        if cannot_place(cosine + most) {
            return None;
        }
        Some(self.graded(q.traits(), set.traits(i), cosine))
    }

    /// `Similarity::similarity` on profiles.
    fn profile_similarity(&self, a: &Profile, b: &Profile) -> f32 {
        if !a.is_known() && !self.is_exact(a, b) {
            return 0.0;
        }
        squash(self.score(a, b))
    }
}

/// Maps the unbounded score to [0, 0.99] monotonically; exact matches (infinite score) give 1.
fn squash(score: f32) -> f32 {
    if score == f32::INFINITY {
        return 1.0;
    }
    let v = 0.99 / (1.0 + (-(score - 0.6) * 5.0).exp());
    (v * 1000.0).round() / 1000.0
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
                self.rank_among(query, candidates, &profiles, top, Some(profiles.search()))
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
            CONFIDENT_FROM
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
