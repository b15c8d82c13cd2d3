//! How alike two ingredient names are. The planner takes this as a dependency (goal selection, the
//! retrieval heuristic and substitution all go through it), so the embedding table can replace the
//! exact-match default without touching the planner.

mod cones;
pub mod ranking;
pub mod table;

use rustc_hash::FxHashMap as HashMap;
use std::sync::atomic::{AtomicU64, AtomicUsize, Ordering::Relaxed};
use std::sync::{Arc, Mutex, OnceLock};

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
    /// knowledge base): an implementation may remember the answer per (query, set, top) and share it
    /// (every plan asks it of each of its ingredients). The default ranks afresh.
    fn rank_in_set(
        &self,
        query: &str,
        set: u64,
        candidates: &[String],
        top: usize,
    ) -> Arc<[(String, f32)]> {
        let _ = set;
        let refs: Vec<&str> = candidates.iter().map(String::as_str).collect();
        self.rank(query, &refs, top).into()
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

    /// Where this similarity's pairs may be remembered from plan to plan (`None`: nowhere, the default
    /// for a similarity as cheap as a lookup).
    fn memory(&self) -> Option<&PairMemory> {
        None
    }
}

/// Pairs (sim(name, candidate), sim(candidate, name)) of one similarity, remembered per name and
/// candidate list (named by a set id that never changes for it, as in `Similarity::rank_in_set`): query
/// names recur from plan to plan, and so do the candidates goal selection and g(u) ask of them. The
/// caller fills the rows with this similarity's answers. Bounded: the memory starts again when its rows
/// have made `PAIR_MEMORY_CELLS` cells.
#[derive(Debug, Default)]
pub struct PairMemory {
    /// The rows per set id and name.
    rows: Mutex<HashMap<u64, HashMap<String, Arc<PairRow>>>>,
    /// Cells made by the rows (blocks, and their tables as cells too), counted by the rows themselves.
    cells: Arc<AtomicUsize>,
}

/// Cells made at most: 16 MB.
const PAIR_MEMORY_CELLS: usize = 1 << 21;

impl PairMemory {
    /// The row of `name` against the `len` candidates of `set`, empty on first ask.
    pub fn row(&self, set: u64, name: &str, len: usize) -> Arc<PairRow> {
        let Ok(mut rows) = self.rows.lock() else {
            return Arc::new(PairRow::new(len));
        };
        if let Some(row) = rows.get(&set).and_then(|r| r.get(name)) {
            return Arc::clone(row);
        }
        if self.cells.load(Relaxed) > PAIR_MEMORY_CELLS {
            // rows still in use count on, so the next start comes a little early
            self.cells.store(0, Relaxed);
            rows.clear();
        }
        let row = Arc::new(PairRow::counted(len, Arc::clone(&self.cells)));
        rows.entry(set)
            .or_default()
            .insert(name.to_string(), Arc::clone(&row));
        row
    }
}

/// One name's pairs with a candidate list, by candidate position; each filled once. Atomic cells let
/// plans share a row without a lock (a pair written twice is written the same). The cells come in
/// blocks made on first write: a plan asks about a few dozen of a knowledge base's labels.
#[derive(Debug)]
pub struct PairRow {
    blocks: Box<[OnceLock<Box<[AtomicU64; BLOCK]>>]>,
    /// Cells made, of this row and of others counted together.
    made: Arc<AtomicUsize>,
}

/// Cells per block of a `PairRow`.
const BLOCK: usize = 64;

/// A cell not filled yet: two NaNs, never a pair of similarities.
const UNKNOWN: u64 = u64::MAX;

impl PairRow {
    pub fn new(len: usize) -> PairRow {
        PairRow::counted(len, Arc::default())
    }

    /// A row whose cells are counted in `made`.
    fn counted(len: usize, made: Arc<AtomicUsize>) -> PairRow {
        let blocks = len.div_ceil(BLOCK);
        made.fetch_add(blocks, Relaxed);
        PairRow {
            blocks: (0..blocks).map(|_| OnceLock::new()).collect(),
            made,
        }
    }

    /// The pair at position `i`, when filled.
    pub fn get(&self, i: usize) -> Option<(f32, f32)> {
        let bits = self.blocks.get(i / BLOCK)?.get()?[i % BLOCK].load(Relaxed);
        (bits != UNKNOWN).then(|| {
            (
                f32::from_bits((bits >> 32) as u32),
                f32::from_bits(bits as u32),
            )
        })
    }

    /// Fills position `i` (beyond the candidates: nothing).
    pub fn set(&self, i: usize, (to, from): (f32, f32)) {
        let Some(block) = self.blocks.get(i / BLOCK) else {
            return;
        };
        let block = block.get_or_init(|| {
            self.made.fetch_add(BLOCK, Relaxed);
            Box::new(std::array::from_fn(|_| AtomicU64::new(UNKNOWN)))
        });
        let bits = (u64::from(to.to_bits()) << 32) | u64::from(from.to_bits());
        block[i % BLOCK].store(bits, Relaxed);
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
