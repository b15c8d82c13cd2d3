//! The retrieval modes beside the paper's heuristic (`docs/robot.md`): the task tree of a node with the
//! fewest functional units, the lowest motion cost, or the highest product of success rates.
//!
//! Each is exact over the search space of Algorithm 2 (the units making the node, then the units making
//! their inputs, down to the kitchen or a starting item of the recipe that needs it): every unit has a
//! weight (1; its motion's cost; −ln of its success rate) and a tree's value is the sum over its distinct
//! units. Knuth's lightest-derivation algorithm (Dijkstra's, over the AND/OR graph) finds the least sum
//! counting a made node once for each unit taking it; that is the tree's own value, and its tree the
//! best, when no tree of the space can hold a unit twice over (no made node feeds two units of the space,
//! no unit makes two of its nodes). Otherwise `exact` searches from that tree for a better one, within a
//! budget. Ties go to fewer units, then to the smaller unit id (the lightest derivation's tree first).

mod exact;

use super::alg2_retrieve::{execution_order, retrieve, Retrieved};
use super::explain::{kb_unit, Recorder};
use super::index::PlannerIndex;
use super::score::Scorer;
use crate::contract::plan::RetrievalMode;
use crate::foon::kb::KnowledgeBase;
use crate::foon::model::{NodeId, UnitId};
use crate::robot::Motions;
use crate::trace::{CandidateUnit, Expansion, Outcome};
use rustc_hash::{FxHashMap as HashMap, FxHashSet as HashSet};
use std::cmp::{Ordering, Reverse};
use std::collections::{BinaryHeap, VecDeque};

/// A tree's value: the sum of its units' weights, then its number of units.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct Value {
    weight: f64,
    units: u32,
}

impl Value {
    /// The value of a tree of the distinct `units`.
    fn of(units: &[UnitId], weight: impl Fn(UnitId) -> f64) -> Value {
        Value {
            weight: units.iter().map(|&u| weight(u)).sum(),
            units: units.len() as u32,
        }
    }

    fn plus(self, other: Value) -> Value {
        Value {
            weight: self.weight + other.weight,
            units: self.units + other.units,
        }
    }
}

impl Eq for Value {}
impl PartialOrd for Value {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}
impl Ord for Value {
    fn cmp(&self, other: &Self) -> Ordering {
        self.weight
            .total_cmp(&other.weight)
            .then(self.units.cmp(&other.units))
    }
}

/// The search space below `root`: each unit (not one needing what it makes), with the inputs it needs
/// made (not kitchen items, not starting items of its recipe).
fn search_space(
    kb: &KnowledgeBase,
    index: &PlannerIndex,
    root: NodeId,
) -> HashMap<UnitId, Vec<NodeId>> {
    let mut space: HashMap<UnitId, Vec<NodeId>> = HashMap::default();
    let mut seen: HashSet<NodeId> = HashSet::from_iter([root]);
    let mut queue = VecDeque::from([root]);
    while let Some(node) = queue.pop_front() {
        for &u in kb.producers.get(node.0).map_or(&[][..], Vec::as_slice) {
            let unit = &kb.units[u];
            if space.contains_key(&u) || unit.input_nodes().any(|n| n == node) {
                continue;
            }
            let mut needed: Vec<NodeId> = unit
                .input_nodes()
                .filter(|&n| !kb.kitchen[n] && !index.starts_in_recipe_of(u, n))
                .collect();
            needed.sort_unstable();
            needed.dedup();
            for &n in &needed {
                if seen.insert(n) {
                    queue.push_back(n);
                }
            }
            space.insert(u, needed);
        }
    }
    space
}

/// What Knuth's algorithm leaves: the search space, each node's least value and the unit giving it, and
/// when each node was final and each unit complete.
struct Lightest {
    space: HashMap<UnitId, Vec<NodeId>>,
    best: HashMap<NodeId, (Value, UnitId)>,
    finished: Finished,
}

/// Knuth's lightest derivation under `weight` (each at least 0) over the search space below `root`, or
/// `None` when every way of making `root` runs into a cycle.
fn lightest(
    kb: &KnowledgeBase,
    index: &PlannerIndex,
    root: NodeId,
    weight: &dyn Fn(UnitId) -> f64,
) -> Option<Lightest> {
    let space = search_space(kb, index, root);
    let wanted = wanted(&space, root);
    // per node, the units of the space taking it
    let mut takers: HashMap<NodeId, Vec<UnitId>> = HashMap::default();
    let mut waiting: HashMap<UnitId, (usize, Value)> = HashMap::default();
    let mut heap = BinaryHeap::new();
    let mut finished = Finished::default();
    let mut units: Vec<&UnitId> = space.keys().collect();
    units.sort_unstable();
    for &u in units {
        let own = Value {
            weight: weight(u),
            units: 1,
        };
        for &n in &space[&u] {
            takers.entry(n).or_default().push(u);
        }
        waiting.insert(u, (space[&u].len(), own));
        if space[&u].is_empty() {
            offer(kb, &wanted, u, own, &mut heap);
            finished.completed.insert(u, 0);
        }
    }
    // a node's value is final when it leaves the heap; a unit is offered to its outputs once all its
    // needed inputs are final
    let mut best: HashMap<NodeId, (Value, UnitId)> = HashMap::default();
    while let Some(Reverse((value, u, node))) = heap.pop() {
        if best.contains_key(&node) {
            continue;
        }
        best.insert(node, (value, u));
        let tick = best.len();
        finished.nodes.insert(node, tick);
        for &t in takers.get(&node).map_or(&[][..], Vec::as_slice) {
            let (left, sum) = waiting.get_mut(&t)?;
            *left -= 1;
            *sum = sum.plus(value);
            if *left == 0 {
                let sum = *sum;
                offer(kb, &wanted, t, sum, &mut heap);
                finished.completed.insert(t, tick);
            }
        }
    }
    best.get(&root)?;
    Some(Lightest {
        space,
        best,
        finished,
    })
}

/// The nodes to make: the root and the inputs some unit of the space needs made.
fn wanted(space: &HashMap<UnitId, Vec<NodeId>>, root: NodeId) -> HashSet<NodeId> {
    let mut wanted: HashSet<NodeId> = space.values().flatten().copied().collect();
    wanted.insert(root);
    wanted
}

/// Whether a tree of the space can hold a unit twice over in the lightest derivation's count: a made
/// node two units of the space take, or a unit making two nodes to make. Without either, every tree's
/// value is the sum over its distinct units and the lightest derivation is exact.
fn can_share(kb: &KnowledgeBase, space: &HashMap<UnitId, Vec<NodeId>>, root: NodeId) -> bool {
    let wanted = wanted(space, root);
    let mut taken: HashSet<NodeId> = HashSet::default();
    let fed_twice = space.values().flatten().any(|&n| !taken.insert(n));
    fed_twice
        || space.keys().any(|&u| {
            kb.units[u]
                .output_nodes()
                .filter(|o| wanted.contains(o))
                .nth(1)
                .is_some()
        })
}

type Heap = BinaryHeap<Reverse<(Value, UnitId, NodeId)>>;

/// Offers unit `u`, whose tree is worth `value`, to each output it makes that is `wanted`.
fn offer(kb: &KnowledgeBase, wanted: &HashSet<NodeId>, u: UnitId, value: Value, heap: &mut Heap) {
    for o in kb.units[u].output_nodes().filter(|o| wanted.contains(o)) {
        heap.push(Reverse((value, u, o)));
    }
}

/// The value of the best tree making a node with `u` (None when one of its inputs cannot be made).
fn unit_value(
    space: &HashMap<UnitId, Vec<NodeId>>,
    best: &HashMap<NodeId, (Value, UnitId)>,
    weight: &dyn Fn(UnitId) -> f64,
    u: UnitId,
) -> Option<f64> {
    let needed = space.get(&u)?;
    needed
        .iter()
        .try_fold(weight(u), |sum, n| Some(sum + best.get(n)?.0.weight))
}

/// A tree of the search space: its nodes from the root, breadth first, and the unit making each.
struct Tree {
    nodes: Vec<NodeId>,
    chosen: HashMap<NodeId, UnitId>,
}

/// When Knuth's algorithm finished each node (its value final) and completed each unit (its inputs final).
#[derive(Default)]
struct Finished {
    nodes: HashMap<NodeId, usize>,
    completed: HashMap<UnitId, usize>,
}

/// The tree: from the root, breadth first, each node made by a unit already in the tree when one makes it
/// (a unit with two outputs the tree needs counts once) and was complete before the node was final (so no
/// cycle), else by its best unit.
fn choose(kb: &KnowledgeBase, lightest: &Lightest, root: NodeId) -> Tree {
    let Lightest {
        space,
        best,
        finished,
    } = lightest;
    let mut nodes = vec![root];
    let mut chosen: HashMap<NodeId, UnitId> = HashMap::default();
    let mut in_tree: Vec<UnitId> = Vec::new();
    let mut at = 0;
    while at < nodes.len() {
        let n = nodes[at];
        at += 1;
        let reused = in_tree.iter().copied().find(|&u| {
            kb.units[u].output_nodes().any(|o| o == n)
                && finished.completed[&u] < finished.nodes[&n]
        });
        let u = reused.unwrap_or(best[&n].1);
        chosen.insert(n, u);
        if reused.is_some() {
            continue;
        }
        in_tree.push(u);
        for &i in &space[&u] {
            if !nodes.contains(&i) {
                nodes.push(i);
            }
        }
    }
    Tree { nodes, chosen }
}

/// The trace's record of a node of the tree: every unit of the space making it, with the value of the
/// best tree through it.
fn expansion(
    kb: &KnowledgeBase,
    scorer: &Scorer,
    space: &HashMap<UnitId, Vec<NodeId>>,
    node: NodeId,
    chosen: UnitId,
    value: &dyn Fn(UnitId) -> Option<f64>,
    why: &str,
) -> Expansion {
    let candidates: Vec<UnitId> = kb.producers[node]
        .iter()
        .copied()
        .filter(|u| space.contains_key(u))
        .collect();
    Expansion {
        node: kb.nodes[node].to_string(),
        outcome: Outcome::Expanded,
        chosen: candidates.iter().position(|&u| u == chosen),
        why: Some(why.to_string()),
        candidates: candidates
            .iter()
            .map(|&u| CandidateUnit {
                unit: kb_unit(kb, u),
                heuristic: scorer.unit(u),
                reused: false,
                same_recipe: false,
                cycle: value(u).is_none(),
                value: value(u),
            })
            .collect(),
    }
}

/// The best tree making `root`: the lightest derivation's where no tree of the space can share a unit,
/// else the exact search's, and whether it is known to be the best.
fn best_tree(
    kb: &KnowledgeBase,
    lightest: &Lightest,
    root: NodeId,
    weight: &dyn Fn(UnitId) -> f64,
) -> (Tree, bool) {
    let start = choose(kb, lightest, root);
    if !can_share(kb, &lightest.space, root) {
        return (start, true);
    }
    let value = |u: UnitId| unit_value(&lightest.space, &lightest.best, weight, u);
    let mut makers: HashMap<NodeId, Vec<UnitId>> = HashMap::default();
    for &n in lightest.best.keys() {
        let mut units: Vec<(f64, UnitId)> = kb.producers[n]
            .iter()
            .filter_map(|&u| Some((value(u)?, u)))
            .collect();
        units.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
        makers.insert(n, units.into_iter().map(|(_, u)| u).collect());
    }
    let space = exact::Space {
        kb,
        needs: &lightest.space,
        weight: lightest.space.keys().map(|&u| (u, weight(u))).collect(),
        makers,
    };
    let found = exact::search(&space, root, start);
    (found.tree, found.exact)
}

/// The reference task tree in `mode`, or `None` for the heuristic's tree: in the heuristic mode, when
/// every way of making `root` runs into a cycle, and when the heuristic's tree is better by the mode's own
/// measure (after the exact search ran out of budget, or where Algorithm 2 takes from the kitchen a node
/// the search makes; `notes` says so).
#[allow(clippy::too_many_arguments)]
pub(crate) fn retrieve_in_mode(
    kb: &KnowledgeBase,
    index: &PlannerIndex,
    scorer: &Scorer,
    (root, prefer): (NodeId, Option<u32>),
    mode: RetrievalMode,
    motions: &Motions,
    trace: &Recorder,
    notes: &mut Vec<String>,
) -> Option<Retrieved> {
    let why = match mode {
        RetrievalMode::Heuristic => return None,
        RetrievalMode::FewestUnits => "fewest_units",
        RetrievalMode::LowestCost => "lowest_cost",
        RetrievalMode::MostReliable => "most_reliable",
    };
    let weight = |u: UnitId| {
        let figures = motions.figures(&kb.units[u].motion);
        match mode {
            RetrievalMode::LowestCost => figures.cost,
            RetrievalMode::MostReliable => -figures.success_rate.ln(),
            _ => 1.0,
        }
    };
    let Some(lightest) = lightest(kb, index, root, &weight) else {
        notes.push(format!(
            "every tree of retrieval mode {why} runs into a cycle: the heuristic's tree instead"
        ));
        return None;
    };
    let (tree, exact) = best_tree(kb, &lightest, root, &weight);
    if !exact {
        notes.push(format!(
            "retrieval mode {why}: the search for the best tree stopped after {} choices; \
             the best tree found is kept and may not be the best",
            exact::BUDGET
        ));
    }
    let retrieved = Retrieved {
        units: execution_order(root, &tree.chosen, |u| lightest.space[&u].clone()),
        chosen: tree.chosen,
        blocked: Vec::new(),
    };
    let heuristic = retrieve(kb, index, scorer, root, prefer);
    if exact::better(
        Value::of(&heuristic.units, weight),
        Value::of(&retrieved.units, weight),
    ) {
        notes.push(format!(
            "retrieval mode {why}: the paper's heuristic finds a better tree by this mode's measure \
             here (it takes a node two of its units need from the kitchen, as a starting item of the \
             first one's recipe, or the search ran out of budget), and it is kept"
        ));
        return None;
    }
    let trace_why = match exact {
        true => why.to_string(),
        false => format!("{why} (the best tree found: the search budget ran out)"),
    };
    trace.record(|t| {
        let value = |u: UnitId| unit_value(&lightest.space, &lightest.best, &weight, u);
        for &n in &tree.nodes {
            let chosen = retrieved.chosen[&n];
            let e = expansion(kb, scorer, &lightest.space, n, chosen, &value, &trace_why);
            t.retrieval.push(e);
        }
    });
    Some(retrieved)
}
