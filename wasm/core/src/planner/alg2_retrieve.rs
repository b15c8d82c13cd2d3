//! Algorithm 2: the task tree of a node, by best-first search from it down to the kitchen.
//!
//! At each object node not in the kitchen, one of the units producing it is chosen with the heuristic
//! g(u) = Σ_q max_a sim(q, a): the similarity-weighted overlap of the query ingredients q with the
//! ingredients a the unit handles. A unit already in the tree is always reused (no unit appears twice),
//! and a unit that would close a cycle is never chosen, so the search ends on any graph. The result is
//! a valid execution order (every unit after the units making its inputs), unlike a reversed BFS order.

use super::explain::{kb_unit, Recorder};
use super::index::PlannerIndex;
use super::score::Scorer;
use crate::foon::kb::KnowledgeBase;
use crate::foon::model::{NodeId, UnitId};
use crate::trace::{CandidateUnit, Expansion, Outcome};
use fixedbitset::FixedBitSet;
use rustc_hash::{FxHashMap as HashMap, FxHashSet as HashSet};
use std::cmp::Ordering;
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

/// The state of one retrieval.
struct Search {
    /// The unit chosen to make each node, handed to the result when the search completes.
    chosen: HashMap<NodeId, UnitId>,
    /// The nodes `chosen` makes: most inputs asked about are kitchen items nothing chosen makes.
    made: FixedBitSet,
    in_tree: FixedBitSet,
    visited: FixedBitSet,
    /// Each node to expand with the unit that needs it (None for the root).
    queue: VecDeque<(NodeId, Option<UnitId>)>,
}

impl Search {
    fn new(kb: &KnowledgeBase, root: NodeId) -> Search {
        let mut visited = FixedBitSet::with_capacity(kb.nodes.len());
        visited.insert(root.0);
        Search {
            chosen: HashMap::default(),
            made: FixedBitSet::with_capacity(kb.nodes.len()),
            in_tree: FixedBitSet::with_capacity(kb.units.len()),
            visited,
            queue: VecDeque::from([(root, None)]),
        }
    }

    /// Whether `target` can be reached from `from` following chosen producers (node → unit → inputs);
    /// only made nodes lead on.
    fn depends_on(&self, kb: &KnowledgeBase, from: NodeId, target: NodeId) -> bool {
        let mut stack = vec![from];
        let mut seen = HashSet::default();
        while let Some(n) = stack.pop() {
            if n == target {
                return true;
            }
            if self.made.contains(n.0) && seen.insert(n) {
                stack.extend(kb.units[self.chosen[&n]].input_nodes());
            }
        }
        false
    }
}

/// The units `chosen` to make `root` and, through them, the nodes each needs made (`needed`,
/// ascending), each unit after the units making its inputs (post-order from the root).
pub(crate) fn execution_order(
    root: NodeId,
    chosen: &HashMap<NodeId, UnitId>,
    needed: impl Fn(UnitId) -> Vec<NodeId>,
) -> Vec<UnitId> {
    let mut order = Vec::new();
    let mut reached: HashSet<NodeId> = HashSet::default();
    // (node, its unit once the unit's inputs are on the stack)
    let mut stack: Vec<(NodeId, Option<UnitId>)> = vec![(root, None)];
    while let Some((node, expanded)) = stack.pop() {
        if let Some(u) = expanded {
            if !order.contains(&u) {
                order.push(u);
            }
            continue;
        }
        let Some(&u) = chosen.get(&node) else {
            continue;
        };
        if !reached.insert(node) || order.contains(&u) {
            continue;
        }
        stack.push((node, Some(u)));
        let inputs = needed(u).into_iter().filter(|n| !reached.contains(n));
        stack.extend(inputs.rev().map(|n| (n, None)));
    }
    order
}

/// The inputs of unit `u`, ascending.
fn sorted_inputs(kb: &KnowledgeBase, u: UnitId) -> Vec<NodeId> {
    let mut inputs: Vec<NodeId> = kb.units[u].input_nodes().collect();
    inputs.sort_unstable();
    inputs
}

/// A unit making the node being expanded, as the search weighs it.
#[derive(Clone)]
struct Candidate {
    unit: UnitId,
    /// Already in the tree.
    reused: bool,
    /// Of the recipe of the unit that needs the node (of the preferred subgraph at the root).
    same_recipe: bool,
    /// Whether the unit needs a node that only the node being made can be made into (a jar uncovered
    /// that only its covering made): asked only when the preferences before it tie.
    detour: Option<bool>,
    /// g(u), asked only when the preferences before it tie: most nodes have a single producer, and g
    /// needs the query's similarities to every ingredient of the unit.
    g: Option<f32>,
}

impl Candidate {
    fn g(&mut self, scorer: &Scorer) -> f32 {
        *self.g.get_or_insert_with(|| scorer.unit(self.unit))
    }

    /// FOON names a node by its values, so an object put back as it was (a lid taken off again) is the
    /// node it was before: the unit undoing the change makes it from a node that only the change makes.
    /// Chosen, it would leave that node made by nothing, used before the object was ever changed.
    fn detour(&mut self, kb: &KnowledgeBase, index: &PlannerIndex, node: NodeId) -> bool {
        let unit = self.unit;
        *self.detour.get_or_insert_with(|| {
            // a node not in the kitchen has makers (the kitchen holds every node nothing makes)
            kb.units[unit].input_nodes().any(|i| {
                i != node
                    && !kb.kitchen[i]
                    && !index.starts_in_recipe_of(unit, i)
                    && kb.producers[i]
                        .iter()
                        .all(|&p| kb.units[p].input_nodes().any(|n| n == node))
            })
        })
    }

    /// Whether this candidate, making `node`, is preferred to `best` (`Greater`), and which preference
    /// decided it (`WHY`): a unit already in the tree, then one of the reference recipe (so that the
    /// tree stays one coherent recipe), then one that is no detour, then g(u); ties go to fewer inputs
    /// to make, then to the smaller id (ids follow contents, not file order).
    fn decide(
        &mut self,
        best: &mut Candidate,
        node: NodeId,
        kb: &KnowledgeBase,
        index: &PlannerIndex,
        scorer: &Scorer,
    ) -> (Ordering, usize) {
        let made = |u: UnitId| {
            kb.units[u]
                .input_nodes()
                .filter(|&n| !kb.kitchen[n])
                .count()
        };
        // each preference in turn, until one separates the two
        macro_rules! by {
            ($k:expr, $ord:expr) => {
                let ord = $ord;
                if ord.is_ne() {
                    return (ord, $k);
                }
            };
        }
        by!(0, self.reused.cmp(&best.reused));
        by!(1, self.same_recipe.cmp(&best.same_recipe));
        by!(
            2,
            best.detour(kb, index, node)
                .cmp(&self.detour(kb, index, node))
        );
        by!(3, self.g(scorer).total_cmp(&best.g(scorer)));
        by!(4, made(best.unit).cmp(&made(self.unit)));
        by!(5, best.unit.cmp(&self.unit));
        (Ordering::Equal, WHY.len() - 1)
    }
}

/// The preferences of `Candidate::decide`, in order, as the trace names them.
const WHY: [&str; 6] = [
    "reused",
    "same_recipe",
    "no_detour",
    "heuristic",
    "fewer_inputs",
    "id",
];

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
    retrieve_explained(kb, index, scorer, root, prefer, |_| true, &Recorder::OFF)
        .unwrap_or_default()
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
    retrieve_explained(kb, index, scorer, root, prefer, allowed, &Recorder::OFF)
}

/// `retrieve_within`, with every node taken from the queue recorded in `trace` (the reference task tree).
pub(crate) fn retrieve_explained(
    kb: &KnowledgeBase,
    index: &PlannerIndex,
    scorer: &Scorer,
    root: NodeId,
    prefer: Option<u32>,
    allowed: impl Fn(UnitId) -> bool,
    trace: &Recorder,
) -> Option<Retrieved> {
    let mut s = Search::new(kb, root);
    let mut blocked = Vec::new();
    while let Some((node, parent)) = s.queue.pop_front() {
        if node != root && kb.kitchen.get(node.0).copied().unwrap_or(true) {
            trace.record(|t| t.retrieval.push(taken(kb, node, Outcome::Kitchen)));
            continue;
        }
        // a starting item of the recipe that needs it is taken from the kitchen, as that recipe did
        if parent.is_some_and(|p| index.starts_in_recipe_of(p, node)) {
            trace.record(|t| t.retrieval.push(taken(kb, node, Outcome::RecipeStart)));
            continue;
        }
        if kb.producers.get(node.0).is_none_or(Vec::is_empty) {
            continue;
        }
        let ctx = (kb, index, scorer);
        let contest = s.contest(ctx, node, parent, prefer, trace);
        let expansion = |outcome, chosen| weigh(kb, scorer, node, outcome, contest.weighed, chosen);
        let Some(best) = &contest.best else {
            if contest.cyclic && !contest.cyclic_in_recipe {
                blocked.push(node);
            }
            let outcome = if contest.cyclic_in_recipe {
                Outcome::HadFromStart
            } else {
                Outcome::Cycle
            };
            trace.record(|t| t.retrieval.push(expansion(outcome, None)));
            continue;
        };
        let u = best.unit;
        if contest.cyclic_in_recipe && !best.same_recipe {
            // the recipe only makes it again later (a lid put back): it had it from the start, and
            // another recipe's way of making it would bring that recipe along
            trace.record(|t| t.retrieval.push(expansion(Outcome::HadFromStart, None)));
            continue;
        }
        let chosen = Some((u, index));
        trace.record(|t| t.retrieval.push(expansion(Outcome::Expanded, chosen)));
        if !allowed(u) {
            return None;
        }
        s.expand(kb, node, u);
    }
    Some(Retrieved {
        units: execution_order(root, &s.chosen, |u| sorted_inputs(kb, u)),
        chosen: s.chosen,
        blocked,
    })
}

/// The units making a node, weighed against each other (`Search::contest`).
#[derive(Default)]
struct Contest {
    best: Option<Candidate>,
    /// Some unit would close a cycle; one of the recipe that needs the node would.
    cyclic: bool,
    cyclic_in_recipe: bool,
    /// The candidates as weighed, when recording (cyclic ones without a place in the contest).
    weighed: Vec<(Option<Candidate>, UnitId)>,
}

impl Search {
    /// The best of the units making `node`, needed by unit `parent` (`None` for the root, where units
    /// of subgraph `prefer` count as the recipe's).
    fn contest(
        &mut self,
        (kb, index, scorer): (&KnowledgeBase, &PlannerIndex, &Scorer),
        node: NodeId,
        parent: Option<UnitId>,
        prefer: Option<u32>,
        trace: &Recorder,
    ) -> Contest {
        let mut c = Contest::default();
        for &u in &kb.producers[node] {
            let unit = &kb.units[u];
            if unit.input_nodes().any(|n| n == node) {
                continue; // the unit needs what it makes: it only passes the object on
            }
            let same_recipe = match parent {
                Some(p) => index.share_recipe(u, p),
                None => prefer.is_some_and(|p| index.sources(u).contains(&p)),
            };
            if unit.input_nodes().any(|n| self.depends_on(kb, n, node)) {
                c.cyclic = true;
                c.cyclic_in_recipe |= same_recipe;
                trace.record(|_| c.weighed.push((None, u)));
                continue; // would close a cycle
            }
            let mut candidate = Candidate {
                unit: u,
                reused: self.in_tree.contains(u.0),
                same_recipe,
                detour: None,
                g: None,
            };
            trace.record(|_| c.weighed.push((Some(candidate.clone()), u)));
            let better = (c.best.as_mut()).is_none_or(|b| {
                candidate.decide(b, node, kb, index, scorer).0 == Ordering::Greater
            });
            if better {
                c.best = Some(candidate);
            }
        }
        c
    }

    /// Unit `u` makes `node`: its inputs are searched next, in id order.
    fn expand(&mut self, kb: &KnowledgeBase, node: NodeId, u: UnitId) {
        self.chosen.insert(node, u);
        self.made.insert(node.0);
        self.in_tree.insert(u.0);
        for n in sorted_inputs(kb, u) {
            if !self.visited.put(n.0) {
                self.queue.push_back((n, Some(u)));
            }
        }
    }
}

/// The record of a node the search took as it is, without looking for a unit.
fn taken(kb: &KnowledgeBase, node: NodeId, outcome: Outcome) -> Expansion {
    Expansion {
        node: kb.nodes[node].to_string(),
        outcome,
        candidates: Vec::new(),
        chosen: None,
        why: None,
    }
}

/// The record of a node the search looked for a unit to make: its candidates with g(u) (worked out for
/// each here, as the search asks it only of ties), the unit `chosen` and the preference that chose it
/// over the closest runner-up (the one that lasted longest in `Candidate::decide`).
fn weigh(
    kb: &KnowledgeBase,
    scorer: &Scorer,
    node: NodeId,
    outcome: Outcome,
    mut weighed: Vec<(Option<Candidate>, UnitId)>,
    chosen: Option<(UnitId, &PlannerIndex)>,
) -> Expansion {
    let at = chosen.and_then(|(u, _)| weighed.iter().position(|w| w.1 == u));
    let why = chosen.zip(at).and_then(|((_, index), at)| {
        let mut winner = weighed[at].0.clone()?;
        let deepest = weighed
            .iter_mut()
            .enumerate()
            .filter(|(k, _)| *k != at)
            .filter_map(|(_, w)| w.0.as_mut())
            .map(|rival| winner.decide(rival, node, kb, index, scorer).1)
            .max();
        Some(deepest.map_or("only", |k| WHY[k]).to_string())
    });
    let candidates = weighed
        .into_iter()
        .map(|(c, u)| CandidateUnit {
            unit: kb_unit(kb, u),
            heuristic: scorer.unit(u),
            reused: c.as_ref().is_some_and(|c| c.reused),
            same_recipe: c.as_ref().is_some_and(|c| c.same_recipe),
            cycle: c.is_none(),
            value: None,
        })
        .collect();
    Expansion {
        node: kb.nodes[node].to_string(),
        outcome,
        candidates,
        chosen: at,
        why,
    }
}
