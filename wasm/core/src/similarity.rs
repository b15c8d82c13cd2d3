//! How alike two ingredient names are. The planner takes this as a dependency (goal selection, the
//! retrieval heuristic and substitution all go through it), so the embedding table can replace the
//! exact-match default without touching the planner.

/// A similarity between ingredient names in the normal form of `label::normalize_label`.
pub trait Similarity {
    /// Similarity in [0, 1]; 1 when both names are the same.
    fn similarity(&self, a: &str, b: &str) -> f32;

    /// The `top` best of `candidates` for `query`, best first; ties broken by label so that the order
    /// never depends on the order of `candidates`.
    fn rank(&self, query: &str, candidates: &[&str], top: usize) -> Vec<(String, f32)> {
        let mut scored: Vec<(String, f32)> = candidates
            .iter()
            .map(|c| (c.to_string(), self.similarity(query, c)))
            .collect();
        scored.sort_by(|a, b| b.1.total_cmp(&a.1).then_with(|| a.0.cmp(&b.0)));
        scored.dedup_by(|a, b| a.0 == b.0);
        scored.truncate(top);
        scored
    }

    /// `rank` over a candidate list that never changes for a given `set` id (the labels of one loaded
    /// knowledge base): an implementation may remember the answer per (query, set, top). The default
    /// ranks afresh.
    fn rank_in_set(
        &self,
        query: &str,
        set: u64,
        candidates: &[String],
        top: usize,
    ) -> Vec<(String, f32)> {
        let _ = set;
        let refs: Vec<&str> = candidates.iter().map(String::as_str).collect();
        self.rank(query, &refs, top)
    }

    /// `query` made ready for many comparisons with the members of a candidate list that never changes
    /// for a given `set` id: the planner asks thousands per plan, and an implementation can look the
    /// query and the set up once instead of once per pair. The default compares by name each time.
    fn prepare<'a>(
        &'a self,
        query: &str,
        set: u64,
        candidates: &'a [String],
    ) -> Box<dyn Prepared + 'a> {
        let _ = set;
        Box::new(ByName {
            sim: self,
            query: query.to_string(),
            candidates,
        })
    }

    /// Whether a ranked substitute should be shown as doubtful (the UI then asks the user to pick from
    /// the top candidates). The default trusts only exact matches.
    fn low_confidence(&self, query: &str, label: &str, similarity: f32) -> bool {
        query != label && similarity < 1.0
    }

    /// Whether a candidate this similar may stand in for an ingredient at all.
    fn accepts(&self, sim: f32) -> bool {
        sim >= 0.3
    }
}

/// One name prepared by `Similarity::prepare`; `i` indexes its candidate list (out of range: 0).
pub trait Prepared {
    /// sim(query, candidates[i]).
    fn to(&self, i: usize) -> f32;
    /// sim(candidates[i], query): the similarity need not be symmetric.
    fn from(&self, i: usize) -> f32;

    /// (`to(i)`, `from(i)`), for an implementation that shares work between the two.
    fn both(&self, i: usize) -> (f32, f32) {
        (self.to(i), self.from(i))
    }
}

/// `Similarity::prepare` for an implementation without anything to prepare.
struct ByName<'a, S: ?Sized> {
    sim: &'a S,
    query: String,
    candidates: &'a [String],
}

impl<S: Similarity + ?Sized> Prepared for ByName<'_, S> {
    fn to(&self, i: usize) -> f32 {
        self.candidates
            .get(i)
            .map_or(0.0, |c| self.sim.similarity(&self.query, c))
    }

    fn from(&self, i: usize) -> f32 {
        self.candidates
            .get(i)
            .map_or(0.0, |c| self.sim.similarity(c, &self.query))
    }
}

/// 1 for equal names, 0 otherwise: the planner's behaviour without an embedding table.
#[derive(Clone, Copy, Debug, Default)]
pub struct ExactMatch;

impl Similarity for ExactMatch {
    fn similarity(&self, a: &str, b: &str) -> f32 {
        if a == b {
            1.0
        } else {
            0.0
        }
    }
}
