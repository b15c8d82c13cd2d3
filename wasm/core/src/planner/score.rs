//! Similarities of one query's ingredients to the knowledge base's labels, remembered for the plan: g(u)
//! of the retrieval (Alg. 2), once per unit, and the ingredient-set coverage of goal selection (Alg. 1).
//! Each similarity is computed at most once per plan (not once per unit, goal and retrieval).

use super::index::PlannerIndex;
use crate::model::UnitId;
use crate::similarity::{Prepared, Similarity};
use rustc_hash::FxHashMap as HashMap;
use std::cell::RefCell;

pub(crate) struct Scorer<'a> {
    sim: &'a dyn Similarity,
    index: &'a PlannerIndex,
    query: &'a [String],
    /// Each query name prepared against the index's labels (by label id).
    prepared: Vec<Box<dyn Prepared + 'a>>,
    /// Label id of each query name, when the knowledge base has it.
    query_ids: Vec<Option<u32>>,
    /// Per query name and label id: (sim(name, label), sim(label, name)), NaN until asked. Both
    /// directions come from one comparison, and goal selection asks both of every pair.
    rows: RefCell<Vec<Vec<(f32, f32)>>>,
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
            rows: RefCell::new(vec![Vec::new(); query.len()]),
            // a plan scores a few hundred units: sized so that the table does not grow step by step
            units: RefCell::new(HashMap::with_capacity_and_hasher(512, Default::default())),
        }
    }

    /// sim(query name `q`, label).
    fn similarity(&self, q: usize, label: u32) -> f32 {
        self.remembered(q, label).0
    }

    /// sim(label, query name `q`).
    fn similarity_to(&self, label: u32, q: usize) -> f32 {
        self.remembered(q, label).1
    }

    fn remembered(&self, q: usize, label: u32) -> (f32, f32) {
        self.in_row(&mut self.rows.borrow_mut()[q], q, label)
    }

    /// The remembered pair of query name `q` (whose row is `row`) and `label`, computed on first ask.
    fn in_row(&self, row: &mut Vec<(f32, f32)>, q: usize, label: u32) -> (f32, f32) {
        if row.is_empty() {
            row.resize(self.index.label_count(), (f32::NAN, f32::NAN));
        }
        let cell = &mut row[label as usize];
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

    /// Label id of query name `q`, when the knowledge base has the name.
    pub fn query_id(&self, q: usize) -> Option<u32> {
        self.query_ids[q]
    }

    pub fn query_len(&self) -> usize {
        self.query.len()
    }

    /// Mean over the query of the best similarity to any of `labels` (exact matches count 1).
    pub fn query_coverage(&self, labels: &[u32]) -> f32 {
        if self.query.is_empty() {
            return 0.0;
        }
        let total: f32 = (0..self.query.len())
            .map(|q| {
                if self.query_ids[q].is_some_and(|id| labels.contains(&id)) {
                    1.0
                } else {
                    labels
                        .iter()
                        .map(|&l| self.similarity(q, l))
                        .fold(0.0f32, f32::max)
                }
            })
            .sum();
        total / self.query.len() as f32
    }

    /// Mean over `labels` of the best similarity to any query name (exact matches count 1).
    pub fn labels_coverage(&self, labels: &[u32]) -> f32 {
        if labels.is_empty() {
            return 0.0;
        }
        let total: f32 = labels
            .iter()
            .map(|&l| {
                if self.query_ids.contains(&Some(l)) {
                    1.0
                } else {
                    (0..self.query.len())
                        .map(|q| self.similarity_to(l, q))
                        .fold(0.0f32, f32::max)
                }
            })
            .sum();
        total / labels.len() as f32
    }

    /// g(u) = Σ_q max_a sim(q, a) over the ingredients a the unit handles (exact matches count 1).
    pub fn unit(&self, u: UnitId) -> f32 {
        if let Some(&g) = self.units.borrow().get(&u) {
            return g;
        }
        let have = self.index.unit_ingredients(u);
        // one borrow for the whole unit: retrieval asks this of every unit making a node
        let mut rows = self.rows.borrow_mut();
        let g = rows
            .iter_mut()
            .enumerate()
            .map(|(q, row)| {
                if self.query_ids[q].is_some_and(|id| have.contains(&id)) {
                    1.0
                } else {
                    have.iter()
                        .map(|&a| self.in_row(row, q, a).0)
                        .fold(0.0f32, f32::max)
                }
            })
            .sum();
        drop(rows);
        self.units.borrow_mut().insert(u, g);
        g
    }
}
