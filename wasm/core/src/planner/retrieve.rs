//! Algorithm 2: the task tree of a node, by best-first search from it down to the kitchen.
//!
//! At each object node not in the kitchen, one of the units producing it is chosen with the heuristic
//! g(u) = Σ_q max_a sim(q, a): the similarity-weighted overlap of the query ingredients q with the
//! ingredients a the unit handles. A unit already in the tree is always reused (no unit appears twice),
//! and a unit that would close a cycle is never chosen, so the search ends on any graph. The result is
//! a valid execution order (every unit after the units making its inputs), unlike a reversed BFS order.

use super::index::PlannerIndex;
use super::score::Scorer;
use crate::kb::KnowledgeBase;
use crate::model::{NodeId, UnitId};
use fixedbitset::FixedBitSet;
use rustc_hash::{FxHashMap as HashMap, FxHashSet as HashSet};
use std::collections::VecDeque;

#[derive(Clone, Debug, Default)]
pub(crate) struct Retrieved {
    /// Chosen units in execution order.
    pub units: Vec<UnitId>,
    /// The unit chosen to make each node that is not taken from the kitchen.
    pub chosen: HashMap<NodeId, UnitId>,
    /// Nodes that needed a unit but every unit making them would close a cycle (used as they are).
    pub blocked: Vec<NodeId>,
}

/// Whether `target` can be reached from `from` following chosen producers (node → unit → inputs).
/// `scratch` is reused between calls (the search asks this for every input of every candidate unit).
fn depends_on(
    kb: &KnowledgeBase,
    chosen: &HashMap<NodeId, UnitId>,
    from: NodeId,
    target: NodeId,
    scratch: &mut (Vec<NodeId>, HashSet<NodeId>),
) -> bool {
    // most inputs are kitchen items nothing chosen makes: answered without the walk
    if from == target {
        return true;
    }
    if !chosen.contains_key(&from) {
        return false;
    }
    let (stack, seen) = scratch;
    stack.clear();
    seen.clear();
    stack.push(from);
    while let Some(n) = stack.pop() {
        if n == target {
            return true;
        }
        if !seen.insert(n) {
            continue;
        }
        if let Some(&u) = chosen.get(&n) {
            stack.extend(kb.units[u].input_nodes());
        }
    }
    false
}

/// A unit making the node being expanded, as the search weighs it.
struct Candidate {
    unit: UnitId,
    /// Already in the tree.
    reused: bool,
    /// Of the recipe of the unit that needs the node (of the preferred subgraph at the root).
    same_recipe: bool,
    /// g(u), asked only when the preferences before it tie: most nodes have a single producer, and g
    /// needs the query's similarities to every ingredient of the unit.
    g: Option<f32>,
}

impl Candidate {
    fn g(&mut self, scorer: &Scorer) -> f32 {
        *self.g.get_or_insert_with(|| scorer.unit(self.unit))
    }

    /// Whether this candidate is preferred to `best`: a unit already in the tree, then one of the
    /// reference recipe (so that the tree stays one coherent recipe), then g(u); ties go to fewer
    /// inputs to make, then to the smaller id (ids follow contents, not file order).
    fn beats(&mut self, best: &mut Candidate, kb: &KnowledgeBase, scorer: &Scorer) -> bool {
        let made = |u: UnitId| {
            kb.units[u]
                .input_nodes()
                .filter(|&n| !kb.kitchen[n])
                .count()
        };
        let ord = (self.reused, self.same_recipe)
            .cmp(&(best.reused, best.same_recipe))
            .then_with(|| self.g(scorer).total_cmp(&best.g(scorer)))
            .then_with(|| made(best.unit).cmp(&made(self.unit)))
            .then(best.unit.cmp(&self.unit));
        ord == std::cmp::Ordering::Greater
    }
}

/// Retrieves the tree making `root`. `root` is expanded even when it is a kitchen item (a goal, or a
/// leaf whose making is asked for); every other kitchen node stops the search. `prefer` is a subgraph id
/// whose units win ties (the reference recipe).
pub(crate) fn retrieve(
    kb: &KnowledgeBase,
    index: &PlannerIndex,
    scorer: &Scorer,
    root: NodeId,
    prefer: Option<u32>,
) -> Retrieved {
    retrieve_within(kb, index, scorer, root, prefer, |_| true).unwrap_or_default()
}

/// `retrieve`, abandoned (`None`) as soon as it chooses a unit that `allowed` rejects. Every chosen unit
/// is in the result, and a choice never depends on earlier ones being allowed, so `None` means exactly
/// that the whole retrieval would hold a rejected unit; a caller looking for a tree of allowed units
/// learns it without finishing the search.
pub(crate) fn retrieve_within(
    kb: &KnowledgeBase,
    index: &PlannerIndex,
    scorer: &Scorer,
    root: NodeId,
    prefer: Option<u32>,
    allowed: impl Fn(UnitId) -> bool,
) -> Option<Retrieved> {
    // sized for a typical recipe's tree, so that the tables do not grow step by step
    let mut chosen: HashMap<NodeId, UnitId> =
        HashMap::with_capacity_and_hasher(64, Default::default());
    // bit sets over the knowledge base: a few hundred bytes even at 100x FOON-111, cheaper than hashing
    let mut in_tree = FixedBitSet::with_capacity(kb.units.len());
    let mut blocked = Vec::new();
    let mut visited = FixedBitSet::with_capacity(kb.nodes.len());
    let mut scratch = (
        Vec::new(),
        HashSet::with_capacity_and_hasher(64, Default::default()),
    );
    // each node with the unit that needs it (None for the root)
    let mut queue: VecDeque<(NodeId, Option<UnitId>)> = VecDeque::with_capacity(64);
    queue.push_back((root, None));
    visited.insert(root);
    // a chosen unit's inputs, sorted (one buffer for the whole search)
    let mut inputs: Vec<NodeId> = Vec::with_capacity(8);
    while let Some((node, parent)) = queue.pop_front() {
        if node != root && kb.kitchen.get(node).copied().unwrap_or(true) {
            continue;
        }
        // a starting item of the recipe that needs it is taken from the kitchen, as that recipe did
        if parent.is_some_and(|p| index.starts_in_recipe_of(p, node)) {
            continue;
        }
        let Some(producers) = kb.producers.get(node) else {
            continue;
        };
        if producers.is_empty() {
            continue;
        }
        let mut best: Option<Candidate> = None;
        let mut cyclic = false;
        let mut cyclic_in_recipe = false;
        for &u in producers {
            let unit = &kb.units[u];
            if unit.input_nodes().any(|n| n == node) {
                continue; // the unit needs what it makes: it only passes the object on
            }
            let same_recipe = match parent {
                Some(p) => index.share_recipe(u, p),
                None => prefer.is_some_and(|p| index.sources(u).contains(&p)),
            };
            if unit
                .input_nodes()
                .any(|n| depends_on(kb, &chosen, n, node, &mut scratch))
            {
                cyclic = true;
                cyclic_in_recipe |= same_recipe;
                continue; // would close a cycle
            }
            let mut candidate = Candidate {
                unit: u,
                reused: in_tree.contains(u),
                same_recipe,
                g: None,
            };
            let better = match best.as_mut() {
                None => true,
                Some(b) => candidate.beats(b, kb, scorer),
            };
            if better {
                best = Some(candidate);
            }
        }
        let Some(Candidate {
            unit: u,
            same_recipe,
            ..
        }) = best
        else {
            if cyclic && !cyclic_in_recipe {
                blocked.push(node);
            }
            continue;
        };
        if cyclic_in_recipe && !same_recipe {
            // the recipe only makes it again later (a lid put back): it had it from the start, and
            // another recipe's way of making it would bring that recipe along
            continue;
        }
        if !allowed(u) {
            return None;
        }
        chosen.insert(node, u);
        in_tree.insert(u);
        inputs.clear();
        inputs.extend(kb.units[u].input_nodes());
        inputs.sort_unstable();
        for &n in &inputs {
            if !visited.put(n) {
                queue.push_back((n, Some(u)));
            }
        }
    }
    let units = execution_order(kb, &chosen, root, &mut inputs);
    Some(Retrieved {
        units,
        chosen,
        blocked,
    })
}

/// Post-order of the chosen units from `root`: each unit after the units making its inputs.
fn execution_order(
    kb: &KnowledgeBase,
    chosen: &HashMap<NodeId, UnitId>,
    root: NodeId,
    inputs: &mut Vec<NodeId>,
) -> Vec<UnitId> {
    let mut order = Vec::with_capacity(chosen.len());
    let mut done = FixedBitSet::with_capacity(kb.units.len());
    let mut seen_nodes = FixedBitSet::with_capacity(kb.nodes.len());
    // iterative DFS: (node, expanded?), sized for a unit's handful of inputs so that it does not grow
    // step by step
    let mut stack: Vec<(NodeId, bool)> = Vec::with_capacity(8 * chosen.len() + 1);
    stack.push((root, false));
    while let Some((node, expanded)) = stack.pop() {
        let Some(&u) = chosen.get(&node) else {
            continue;
        };
        if expanded {
            if !done.put(u) {
                order.push(u);
            }
            continue;
        }
        if seen_nodes.put(node) || done.contains(u) {
            continue;
        }
        stack.push((node, true));
        inputs.clear();
        inputs.extend(kb.units[u].input_nodes());
        inputs.sort_unstable();
        for &n in inputs.iter().rev() {
            if !seen_nodes.contains(n) {
                stack.push((n, false));
            }
        }
    }
    order
}
