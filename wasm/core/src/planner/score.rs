//! Similarities of one query's ingredients to the knowledge base's labels, remembered for the plan: g(u)
//! of the retrieval (Alg. 2), once per unit, and the ingredient-set coverage of goal selection (Alg. 1).
//! Each similarity is computed at most once per plan (not once per unit, goal and retrieval).

use super::index::{GoalClass, PlannerIndex};
use crate::model::UnitId;
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
    /// (sim(name, label), sim(label, name)) per query name and label, computed on first ask. Both
    /// directions come from one comparison, and goal selection asks both of every pair.
    pairs: RefCell<PairTable>,
    /// Per query name, its best similarity so far (`recall`, `GoalFits::fit`): one buffer for every
    /// unit and goal.
    best_to: RefCell<Vec<f32>>,
    units: RefCell<HashMap<UnitId, f32>>,
}

impl<'a> Scorer<'a> {
    pub fn new(sim: &'a dyn Similarity, index: &'a PlannerIndex, query: &'a [String]) -> Self {
        Scorer {
            sim,
            index,
            query,
            query_ids: query.iter().map(|q| index.label_id(q)).collect(),
            prepared: query
                .iter()
                .map(|q| sim.prepare(q, index.label_set, index.label_names()))
                .collect(),
            pairs: RefCell::new(PairTable::new(index.label_count(), query.len())),
            best_to: RefCell::new(Vec::with_capacity(query.len())),
            // a plan scores a few hundred units: sized so that the table does not grow step by step
            units: RefCell::new(HashMap::with_capacity_and_hasher(512, Default::default())),
        }
    }

    /// sim(query name `q`, label).
    fn similarity(&self, q: usize, label: u32) -> f32 {
        self.remembered(&mut self.pairs.borrow_mut(), q, label).0
    }

    /// The pair of query name `q` and `label` in `pairs`, computed on first ask.
    fn remembered(&self, pairs: &mut PairTable, q: usize, label: u32) -> (f32, f32) {
        self.in_slot(pairs.slot(label), q, label)
    }

    /// The pair of query name `q` and `label`, whose slot is `cells`, computed on first ask.
    fn in_slot(&self, cells: &mut [(f32, f32)], q: usize, label: u32) -> (f32, f32) {
        let cell = &mut cells[q];
        if cell.0.is_nan() {
            *cell = self.prepared[q].both(label as usize);
        }
        *cell
    }

    /// sim(query name `name`, `label`), remembered when both are known to the scorer (an attachment
    /// asks it of every ingredient of every unit).
    pub fn pair(&self, name: &str, label: &str) -> f32 {
        match (
            self.query.iter().position(|q| q == name),
            self.index.label_id(label),
        ) {
            (Some(q), Some(id)) => self.similarity(q, id),
            _ => self.sim.similarity(name, label),
        }
    }

    /// Goal selection among `goals`: the pairs of the query's names with the goals' ingredients come
    /// from the similarity's memory when it has one (they recur from plan to plan), else from this plan.
    pub fn goal_fits<'s>(&'s self, goals: &'s GoalClass) -> GoalFits<'s, 'a> {
        let len = goals.labels.len();
        let rows = self
            .query
            .iter()
            .map(|q| match self.sim.memory() {
                Some(memory) => memory.row(goals.set, q, len),
                None => Arc::new(PairRow::new(len)),
            })
            .collect();
        GoalFits {
            scorer: self,
            goals,
            rows,
            exact_at: self
                .query_ids
                .iter()
                .map(|id| id.and_then(|id| goals.slot(id)))
                .collect(),
        }
    }

    /// Σ over query names of the best similarity to any of `labels` (exact matches count 1).
    fn recall(&self, labels: &[u32]) -> f32 {
        let mut pairs = self.pairs.borrow_mut();
        // per query name, the best similarity to any of `labels` so far
        let mut best_to = self.best_to.borrow_mut();
        best_to.clear();
        best_to.resize(self.query.len(), 0.0);
        for &l in labels {
            let cells = pairs.slot(l);
            for (q, to) in best_to.iter_mut().enumerate() {
                *to = larger(*to, self.in_slot(cells, q, l).0);
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
        // per query name, the best similarity to any of `slots` so far (one buffer for every goal)
        let mut best_to = self.scorer.best_to.borrow_mut();
        best_to.clear();
        best_to.resize(n, 0.0);
        let mut precision = 0.0f32;
        for &s in slots {
            let mut best_from = 0.0f32;
            for (q, to) in best_to.iter_mut().enumerate() {
                let (there, back) = self.pair(q, s);
                *to = larger(*to, there);
                best_from = larger(best_from, back);
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

    /// (sim(query name `q`, ingredient at `slot`), the converse), remembered in `q`'s row.
    fn pair(&self, q: usize, slot: u32) -> (f32, f32) {
        let row = &self.rows[q];
        row.get(slot as usize).unwrap_or_else(|| {
            let label = self.goals.labels[slot as usize];
            let pair = self
                .scorer
                .remembered(&mut self.scorer.pairs.borrow_mut(), q, label);
            row.set(slot as usize, pair);
            pair
        })
    }
}

/// Σ over query names of their best similarity, 1 for those `exact` says the labels have.
fn sum_with_exact<T>(query: &[T], best: &[f32], exact: impl Fn(&T) -> bool) -> f32 {
    query
        .iter()
        .zip(best)
        .fold(0.0, |sum, (q, b)| sum + if exact(q) { 1.0 } else { *b })
}

/// The remembered pairs of a plan: each label asked about gets a slot of one cell per query name, side
/// by side (goal selection reads all of a label's cells at once). A row per query name over every label
/// would be written in full on every plan and read at random, which at 100 times FOON-111 is most of
/// goal selection's time.
struct PairTable {
    /// Query names: the cells of a slot.
    width: usize,
    /// Per label id, the index in `cells` of its slot's first cell; `NO_SLOT` until asked.
    slot_of: Vec<u32>,
    /// (sim(name, label), sim(label, name)), NaN until computed.
    cells: Vec<(f32, f32)>,
}

const NO_SLOT: u32 = u32::MAX;

impl PairTable {
    fn new(labels: usize, width: usize) -> PairTable {
        PairTable {
            width,
            slot_of: vec![NO_SLOT; labels],
            cells: Vec::new(),
        }
    }

    /// `label`'s slot, made on first ask.
    fn slot(&mut self, label: u32) -> &mut [(f32, f32)] {
        let slot = &mut self.slot_of[label as usize];
        if *slot == NO_SLOT {
            *slot = self.cells.len() as u32;
            self.cells
                .resize(self.cells.len() + self.width, (f32::NAN, f32::NAN));
        }
        let at = *slot as usize;
        &mut self.cells[at..at + self.width]
    }
}

/// The larger of two similarities (never NaN): `f32::max` is a libm call in WASM, for its NaN rule.
fn larger(a: f32, b: f32) -> f32 {
    if b > a {
        b
    } else {
        a
    }
}
