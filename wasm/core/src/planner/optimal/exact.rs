//! The exact tree of a retrieval mode where units of a tree can share a made node, so the lightest
//! derivation, counting such a node once per unit taking it, may rank trees wrongly.
//!
//! A branch and bound over the unit making each node, the nodes taken in the order Algorithm 2 meets
//! them (from the root, breadth first) and each node's units tried cheapest first (a unit already in the
//! tree, then by the lightest derivation's value, then by unit id). A tree's value is the sum of its
//! distinct units' weights, then their number; a tree replaces the best found only when strictly better,
//! so ties keep the lightest derivation's tree, then the first found. The bound is admissible: each node
//! left that no unit of the tree makes needs a new unit, whose weight it shares at most with the other
//! nodes left that unit makes.
//! (The lightest derivation's values are no bound here: sharing makes a tree lighter than they say.)
//! The search stops after `BUDGET` choices and keeps the best tree found.

use super::{Tree, Value};
use crate::foon::kb::KnowledgeBase;
use crate::foon::model::{NodeId, UnitId};
use rustc_hash::{FxHashMap as HashMap, FxHashSet as HashSet};

/// How many choices of a unit the search makes at most before it keeps the best tree found.
pub(super) const BUDGET: usize = 50_000;

/// What the search needs of the space: per unit its weight and the inputs it needs made, per node the
/// units worth trying (those whose every needed input can be made) in order.
pub(super) struct Space<'a> {
    pub kb: &'a KnowledgeBase,
    pub needs: &'a HashMap<UnitId, Vec<NodeId>>,
    pub weight: HashMap<UnitId, f64>,
    pub makers: HashMap<NodeId, Vec<UnitId>>,
}

/// The best tree the search found, and whether it is known to be the best (the budget did not run out).
pub(super) struct Found {
    pub tree: Tree,
    pub exact: bool,
}

/// The best tree making `root`, starting from `start` (the lightest derivation's tree).
pub(super) fn search(space: &Space, root: NodeId, start: Tree) -> Found {
    let value = value_of(space, &start);
    let mut search = Search {
        space,
        nodes: vec![root],
        listed: HashSet::from_iter([root]),
        chosen: HashMap::default(),
        uses: HashMap::default(),
        made: HashMap::default(),
        value: Value::default(),
        best: (value, start),
    };
    let exact = search.run();
    Found {
        tree: search.best.1,
        exact,
    }
}

/// The value of a tree: the sum over its distinct units.
fn value_of(space: &Space, tree: &Tree) -> Value {
    let mut units: Vec<UnitId> = tree.chosen.values().copied().collect();
    units.sort_unstable();
    units.dedup();
    Value::of(&units, |u| space.weight[&u])
}

/// Weights summed in different orders may differ in their last bits.
const EPSILON: f64 = 1e-9;

pub(super) fn better(a: Value, b: Value) -> bool {
    a.weight < b.weight - EPSILON || (a.weight <= b.weight + EPSILON && a.units < b.units)
}

/// A node being decided: its units to try, the next to try, and how to take back the one tried last.
struct Frame {
    at: usize,
    units: Vec<UnitId>,
    next: usize,
    undo: Option<Undo>,
}

struct Undo {
    node: NodeId,
    unit: UnitId,
    /// How many nodes the tree listed before the unit came in (None when it was in the tree already).
    listed_before: Option<usize>,
}

/// The tree being grown: `nodes` in the order met, the first ones decided (`chosen`), how many nodes each
/// unit of the tree makes in it (`uses`), how many units of the tree make each node (`made`), its value.
struct Search<'s, 'a> {
    space: &'s Space<'a>,
    nodes: Vec<NodeId>,
    listed: HashSet<NodeId>,
    chosen: HashMap<NodeId, UnitId>,
    uses: HashMap<UnitId, u32>,
    made: HashMap<NodeId, u32>,
    value: Value,
    best: (Value, Tree),
}

impl Search<'_, '_> {
    /// Depth first over the choices; false when the budget ran out.
    fn run(&mut self) -> bool {
        let mut steps = 0;
        let mut stack = vec![self.frame(0)];
        while let Some(top) = stack.last_mut() {
            if let Some(undo) = top.undo.take() {
                self.retract(undo);
            }
            let node = self.nodes[top.at];
            let Some(&unit) = top.units.get(top.next) else {
                stack.pop();
                continue;
            };
            top.next += 1;
            if self.closes_cycle(unit, node) {
                continue;
            }
            steps += 1;
            if steps > BUDGET {
                return false;
            }
            top.undo = Some(self.assign(node, unit));
            let at = top.at + 1;
            if !better(self.bound(at), self.best.0) {
                continue;
            }
            if at == self.nodes.len() {
                self.best = (self.value, self.tree());
                continue;
            }
            stack.push(self.frame(at));
        }
        true
    }

    /// The frame deciding `nodes[at]`: the units of the tree making it first (they add nothing).
    fn frame(&self, at: usize) -> Frame {
        let makers = &self.space.makers[&self.nodes[at]];
        let (mut units, others): (Vec<UnitId>, Vec<UnitId>) =
            makers.iter().partition(|u| self.uses.contains_key(u));
        units.extend(others);
        Frame {
            at,
            units,
            next: 0,
            undo: None,
        }
    }

    /// Whether `unit` needs, through the units chosen so far, the node it would make.
    fn closes_cycle(&self, unit: UnitId, node: NodeId) -> bool {
        let mut seen: HashSet<UnitId> = HashSet::from_iter([unit]);
        let mut stack = vec![unit];
        while let Some(u) = stack.pop() {
            for n in &self.space.needs[&u] {
                if *n == node {
                    return true;
                }
                if let Some(&v) = self.chosen.get(n) {
                    if seen.insert(v) {
                        stack.push(v);
                    }
                }
            }
        }
        false
    }

    fn assign(&mut self, node: NodeId, unit: UnitId) -> Undo {
        self.chosen.insert(node, unit);
        let uses = self.uses.entry(unit).or_default();
        *uses += 1;
        let listed_before = (*uses == 1).then(|| {
            let before = self.nodes.len();
            self.value.weight += self.space.weight[&unit];
            self.value.units += 1;
            for o in self.space.kb.units[unit].output_nodes() {
                *self.made.entry(o).or_default() += 1;
            }
            for &n in &self.space.needs[&unit] {
                if self.listed.insert(n) {
                    self.nodes.push(n);
                }
            }
            before
        });
        Undo {
            node,
            unit,
            listed_before,
        }
    }

    fn retract(&mut self, undo: Undo) {
        self.chosen.remove(&undo.node);
        let Some(before) = undo.listed_before else {
            *self.uses.get_mut(&undo.unit).expect("a unit of the tree") -= 1;
            return;
        };
        self.uses.remove(&undo.unit);
        self.value.weight -= self.space.weight[&undo.unit];
        self.value.units -= 1;
        for o in self.space.kb.units[undo.unit].output_nodes() {
            *self.made.get_mut(&o).expect("made by a unit of the tree") -= 1;
        }
        for n in self.nodes.drain(before..) {
            self.listed.remove(&n);
        }
    }

    /// A value no tree completing this one beats. Each node left that no unit of the tree makes needs a
    /// new unit; a new unit making k of those nodes is shared among them, so each costs at least the least
    /// share of a unit making it (its weight over its k, and 1 over k units).
    fn bound(&self, at: usize) -> Value {
        let left: HashSet<NodeId> = self.nodes[at..]
            .iter()
            .copied()
            .filter(|n| self.made.get(n).copied().unwrap_or(0) == 0)
            .collect();
        let (mut weight, mut units) = (0.0, 0.0);
        for n in &left {
            let shares = self.space.makers[n].iter().map(|&u| {
                let k = self.space.kb.units[u]
                    .output_nodes()
                    .filter(|o| left.contains(o))
                    .count() as f64;
                (self.space.weight[&u] / k, 1.0 / k)
            });
            let least = shares.fold((f64::INFINITY, f64::INFINITY), |a, b| {
                (a.0.min(b.0), a.1.min(b.1))
            });
            weight += least.0;
            units += least.1;
        }
        Value {
            weight: self.value.weight + weight,
            units: self.value.units + (units - EPSILON).ceil().max(0.0) as u32,
        }
    }

    fn tree(&self) -> Tree {
        Tree {
            nodes: self.nodes.clone(),
            chosen: self.chosen.clone(),
        }
    }
}
