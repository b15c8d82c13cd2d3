//! Similarities of one query's ingredients to the knowledge base's labels, remembered: g(u) of the
//! retrieval (Alg. 2), once per unit, and the ingredient-set coverage of goal selection (Alg. 1). Each
//! similarity is computed at most once per plan (not once per unit, goal and retrieval), and at most once
//! in all when the similarity has a memory (`Similarity::memory`): query names recur from plan to plan.

use super::index::{GoalClass, PlannerIndex};
use crate::foon::model::UnitId;
use crate::similarity::{PairRow, Prepared, Similarity};
use rustc_hash::FxHashMap as HashMap;
use std::cell::RefCell;
use std::sync::Arc;

/// The fit of a goal's ingredient set with the query's.
pub(crate) struct GoalFit {
    /// Mean over the query of the best similarity to any goal ingredient (exact matches count 1).
    pub recall: f32,
    /// Mean over the goal's ingredients of the best similarity to any query name (exact matches count 1).
    pub precision: f32,
    /// Query names the goal has exactly.
    pub exact: usize,
}

pub(crate) struct Scorer<'a> {
    sim: &'a dyn Similarity,
    index: &'a PlannerIndex,
    query: &'a [String],
    /// Each query name prepared against the index's labels (by label id).
    prepared: Vec<Box<dyn Prepared + 'a>>,
    /// Label id of each query name, when the knowledge base has it.
    query_ids: Vec<Option<u32>>,
    /// Per query name, (sim(name, label), sim(label, name)) by label id, computed on first ask (both
    /// directions come from one comparison, and goal selection asks both of every pair); from the
    /// similarity's memory when it has one.
    rows: Vec<Arc<PairRow>>,
    units: RefCell<HashMap<UnitId, f32>>,
}

impl<'a> Scorer<'a> {
    pub fn new(sim: &'a dyn Similarity, index: &'a PlannerIndex, query: &'a [String]) -> Self {
        let labels = index.label_names().len();
        Scorer {
            sim,
            index,
            query,
            query_ids: query.iter().map(|q| index.label_id(q)).collect(),
            prepared: query
                .iter()
                .map(|q| sim.prepare(q, index.label_set, index.label_names()))
                .collect(),
            rows: rows(sim, index.label_set, query, labels),
            units: RefCell::new(HashMap::default()),
        }
    }

    /// (sim(query name `q`, label), sim(label, name `q`)), computed on first ask.
    fn both(&self, q: usize, label: u32) -> (f32, f32) {
        let row = &self.rows[q];
        row.get(label as usize).unwrap_or_else(|| {
            let pair = self.prepared[q].both(label as usize);
            row.set(label as usize, pair);
            pair
        })
    }

    /// sim(query name `name`, `label`), remembered when both are known to the scorer (an attachment
    /// asks it of every ingredient of every unit).
    pub fn pair(&self, name: &str, label: &str) -> f32 {
        match (
            self.query.iter().position(|q| q == name),
            self.index.label_id(label),
        ) {
            (Some(q), Some(id)) => self.both(q, id).0,
            _ => self.sim.similarity(name, label),
        }
    }

    /// Goal selection among `goals`: the pairs of the query's names with the goals' ingredients come
    /// from the similarity's memory when it has one (they recur from plan to plan), else from this plan.
    pub fn goal_fits<'s>(&'s self, goals: &'s GoalClass) -> GoalFits<'s, 'a> {
        GoalFits {
            scorer: self,
            goals,
            rows: rows(self.sim, goals.set, self.query, goals.labels.len()),
            exact_at: self
                .query_ids
                .iter()
                .map(|id| id.and_then(|id| goals.slot(id)))
                .collect(),
        }
    }

    /// Σ over query names of the best similarity to any of `labels` (exact matches count 1).
    fn recall(&self, labels: &[u32]) -> f32 {
        // per query name, the best similarity to any of `labels` so far
        let mut best_to = vec![0.0f32; self.query.len()];
        for &l in labels {
            for (q, to) in best_to.iter_mut().enumerate() {
                *to = to.max(self.both(q, l).0);
            }
        }
        let exact = |id: &Option<u32>| id.is_some_and(|id| labels.contains(&id));
        sum_with_exact(&self.query_ids, &best_to, exact)
    }

    /// g(u) = Σ_q max_a sim(q, a) over the ingredients a the unit handles (exact matches count 1).
    pub fn unit(&self, u: UnitId) -> f32 {
        if let Some(&g) = self.units.borrow().get(&u) {
            return g;
        }
        let g = self.recall(self.index.unit_ingredients(u));
        self.units.borrow_mut().insert(u, g);
        g
    }
}

/// The query against the goals of one class (`Scorer::goal_fits`), by the slots of the goals' ingredients.
pub(crate) struct GoalFits<'s, 'a> {
    scorer: &'s Scorer<'a>,
    goals: &'s GoalClass,
    /// Per query name, its pairs with the goals' ingredients.
    rows: Vec<Arc<PairRow>>,
    /// Per query name, its slot when an ingredient of the goals has it.
    exact_at: Vec<Option<u32>>,
}

impl GoalFits<'_, '_> {
    /// How well a goal's ingredient set (`slots`) and the query's fit each other.
    pub fn fit(&self, slots: &[u32]) -> GoalFit {
        let n = self.rows.len();
        // per query name, the best similarity to any of `slots` so far
        let mut best_to = vec![0.0f32; n];
        let mut precision = 0.0f32;
        for &s in slots {
            let mut best_from = 0.0f32;
            for (q, to) in best_to.iter_mut().enumerate() {
                let (there, back) = self.pair(q, s);
                *to = to.max(there);
                best_from = best_from.max(back);
            }
            precision += if self.exact_at.contains(&Some(s)) {
                1.0
            } else {
                best_from
            };
        }
        let exact = |slot: &Option<u32>| slot.is_some_and(|s| slots.contains(&s));
        let recall = sum_with_exact(&self.exact_at, &best_to, exact);
        GoalFit {
            recall: if n == 0 { 0.0 } else { recall / n as f32 },
            precision: if slots.is_empty() {
                0.0
            } else {
                precision / slots.len() as f32
            },
            exact: self.exact_at.iter().filter(|s| exact(s)).count(),
        }
    }

    /// (sim(query name `q`, ingredient at `slot`), the converse), remembered in `q`'s row only: the
    /// scorer's rows over every label would fill up with a large knowledge base's goal ingredients.
    fn pair(&self, q: usize, slot: u32) -> (f32, f32) {
        let row = &self.rows[q];
        row.get(slot as usize).unwrap_or_else(|| {
            let label = self.goals.labels[slot as usize] as usize;
            let scorer = self.scorer;
            let pair = scorer.rows[q]
                .get(label)
                .unwrap_or_else(|| scorer.prepared[q].both(label));
            row.set(slot as usize, pair);
            pair
        })
    }
}

/// Per query name, its pairs with the `len` candidates of `set`: from the similarity's memory when it
/// has one, else a fresh row.
fn rows(sim: &dyn Similarity, set: u64, query: &[String], len: usize) -> Vec<Arc<PairRow>> {
    let row = |q: &String| match sim.memory() {
        Some(memory) => memory.row(set, q, len),
        None => Arc::new(PairRow::new(len)),
    };
    query.iter().map(row).collect()
}

/// Σ over query names of their best similarity, 1 for those `exact` says the labels have.
fn sum_with_exact<T>(query: &[T], best: &[f32], exact: impl Fn(&T) -> bool) -> f32 {
    query
        .iter()
        .zip(best)
        .fold(0.0, |sum, (q, b)| sum + if exact(q) { 1.0 } else { *b })
}
