//! g(u) of the retrieval (Alg. 2) for one query, remembered: the query's similarity to each label is
//! computed once per plan (not once per unit and retrieval), and each unit's score once per plan.

use super::index::PlannerIndex;
use crate::model::UnitId;
use crate::similarity::Similarity;
use std::cell::RefCell;
use std::collections::HashMap;

pub(crate) struct Scorer<'a> {
    sim: &'a dyn Similarity,
    index: &'a PlannerIndex,
    query: &'a [String],
    /// Label id of each query name, when the knowledge base has it.
    query_ids: Vec<Option<u32>>,
    /// Per query name, its similarity to each label id (NaN until asked).
    rows: RefCell<Vec<Vec<f32>>>,
    units: RefCell<HashMap<UnitId, f32>>,
}

impl<'a> Scorer<'a> {
    pub fn new(sim: &'a dyn Similarity, index: &'a PlannerIndex, query: &'a [String]) -> Self {
        Scorer {
            sim,
            index,
            query,
            query_ids: query.iter().map(|q| index.label_id(q)).collect(),
            rows: RefCell::new(vec![Vec::new(); query.len()]),
            units: RefCell::new(HashMap::new()),
        }
    }

    fn similarity(&self, q: usize, label: u32) -> f32 {
        let mut rows = self.rows.borrow_mut();
        let row = &mut rows[q];
        if row.is_empty() {
            row.resize(self.index.label_count(), f32::NAN);
        }
        let cell = &mut row[label as usize];
        if cell.is_nan() {
            *cell = self
                .sim
                .similarity(&self.query[q], self.index.label_name(label));
        }
        *cell
    }

    /// g(u) = Σ_q max_a sim(q, a) over the ingredients a the unit handles (exact matches count 1).
    pub fn unit(&self, u: UnitId) -> f32 {
        if let Some(&g) = self.units.borrow().get(&u) {
            return g;
        }
        let have = self.index.unit_ingredients(u);
        let g = (0..self.query.len())
            .map(|q| {
                if self.query_ids[q].is_some_and(|id| have.contains(&id)) {
                    1.0
                } else {
                    have.iter()
                        .map(|&a| self.similarity(q, a))
                        .fold(0.0f32, f32::max)
                }
            })
            .sum();
        self.units.borrow_mut().insert(u, g);
        g
    }
}
