//! The final execution order, decided on node *values* — what a plan shows and what the evaluator checks —
//! rather than on the tree's slots. Two slots with the same value are the same node to a reader: a recipe
//! that takes "bowl contains {flour}" from the kitchen while another unit of the plan makes exactly that
//! bowl must come after that unit. So every unit is ordered after every unit that makes one of its
//! inputs, save a value made again after a detour (a pot poured, covered, uncovered): units that do not
//! follow the detour wait for its first making. Where that leaves the order free, the units that use a
//! node and give it back as it was come before the one that changes it (stir in the open pot, then cover
//! it). When that is impossible (a state cycle: the pan is greased again by a unit that needs the greased
//! pan first), the node counts as available from the start and the later unit no longer lists it as a
//! product. The goal is never in the kitchen at the start: a unit that needs it before it is made
//! is dropped. Duplicated units and units whose products nobody uses are dropped.

use super::check::available_at_start;
use super::tree::{SlotId, TUnitId, Tree};
use crate::contract::plan::{IngredientOutcome, PlanNode, Status};
use rustc_hash::FxHashSet as HashSet;
use std::cmp::Reverse;
use std::collections::BinaryHeap;
use std::sync::Arc;

type Value = usize;

/// Values of the slots (ids of distinct nodes) and which of them a kitchen has at the start.
struct Values {
    of_slot: Vec<Value>,
    start: Vec<bool>,
}

/// The order of the units, and each live slot's node as the plan shows it (the schedule changes no
/// node, so these are the plan's nodes; equal nodes share one).
pub(crate) struct Schedule {
    pub order: Vec<TUnitId>,
    pub nodes: Vec<Option<Arc<PlanNode>>>,
}

/// Each live slot's plan node, made once per distinct node, and the slots'
/// values. `value` tells equal nodes apart by id (`Tree::drop_redundant_units`), so the nodes need no hashing
/// here: equal as plan nodes (states and contents as sets) is equal as tree nodes, whose states are
/// sorted and unique. Values are numbered by first slot, from 1: 0 is every slot no live unit uses
/// (never looked at).
fn plan_nodes(tree: &Tree, value: &[usize]) -> (Vec<Option<Arc<PlanNode>>>, Values) {
    let mut nodes = vec![None; tree.slots.len()];
    let mut vals = Values {
        of_slot: vec![0; tree.slots.len()],
        start: vec![false],
    };
    let mut of_value: Vec<Option<(Arc<PlanNode>, Value)>> = vec![None; tree.slots.len()];
    for x in tree.live_slots() {
        let (p, v) = of_value[value[x]].get_or_insert_with(|| {
            let p = Arc::new(PlanNode::from(&*tree.slots[x].node));
            vals.start.push(available_at_start(&p));
            (p, vals.start.len() - 1)
        });
        nodes[x] = Some(Arc::clone(p));
        vals.of_slot[x] = *v;
    }
    (nodes, vals)
}

/// Per unit: its input values (with repeats, sorted), output values (sorted) and the values it makes
/// (outputs that are not inputs, sorted, unique). A shape changes only where a round of `schedule` edits
/// its unit, so it is found once rather than every round.
struct Shapes(Vec<[Vec<Value>; 3]>);

impl Shapes {
    fn new(tree: &Tree, v: &Values, units: &[TUnitId]) -> Shapes {
        let mut shapes = Shapes(vec![Default::default(); tree.units.len()]);
        for &u in units {
            shapes.update(tree, v, u);
        }
        shapes
    }

    /// (Re)computes the unit's shape.
    fn update(&mut self, tree: &Tree, v: &Values, u: TUnitId) {
        let unit = &tree.units[u];
        let sorted = |uses: &[(SlotId, bool)]| {
            let mut values: Vec<Value> = uses.iter().map(|x| v.of_slot[x.0]).collect();
            values.sort_unstable();
            values
        };
        let (inputs, outputs) = (sorted(&unit.inputs), sorted(&unit.outputs));
        let mut made: Vec<Value> = outputs
            .iter()
            .copied()
            .filter(|o| inputs.binary_search(o).is_err())
            .collect();
        made.dedup();
        self.0[u] = [inputs, outputs, made];
    }

    fn inputs(&self, u: TUnitId) -> &[Value] {
        &self.0[u][0]
    }

    fn outputs(&self, u: TUnitId) -> &[Value] {
        &self.0[u][1]
    }

    fn made(&self, u: TUnitId) -> &[Value] {
        &self.0[u][2]
    }
}

/// Orders the live units the goal needs so that the evaluator's invariants hold, editing the tree where
/// the order alone cannot (see the module comment). Returns the order; dropped units are marked dead.
/// `value` and `order`: the slots' values and the tree's order from `Tree::drop_redundant_units`
/// (nothing has changed since).
pub(crate) fn schedule(tree: &mut Tree, value: &[usize], order: Vec<TUnitId>) -> Schedule {
    let (nodes, mut vals) = plan_nodes(tree, value);
    let goal = vals.of_slot[tree.goal];
    // the finished dish is never in the kitchen at the start, whatever its states say
    vals.start[goal] = false;
    let mut units = order;
    let mut shapes = Shapes::new(tree, &vals, &units);
    // each round either settles or removes a product or a unit, so the rounds are bounded
    let limit = 4 * units.len() + 8;
    for _ in 0..limit {
        let before = units.len();
        drop_duplicates(tree, &mut units, &shapes);
        if units.len() != before {
            continue;
        }
        match topological(&units, &shapes, &vals) {
            Ok(order) => {
                let kept = drop_dead(tree, &order, &shapes, &vals, goal);
                if kept.len() == order.len() {
                    return Schedule { order: kept, nodes };
                }
                units = kept;
            }
            Err((p, v, value)) => {
                if value == goal {
                    // never unmake the goal: a unit that needs the finished dish before it is made has
                    // no place in the plan; what it made comes from the kitchen instead
                    tree.units[v].alive = false;
                    units.retain(|&u| u != v);
                } else if break_cycle(tree, &vals, p, value) {
                    shapes.update(tree, &vals, p);
                } else {
                    tree.units[v].inputs.retain(|i| vals.of_slot[i.0] != value);
                    shapes.update(tree, &vals, v);
                }
            }
        }
    }
    Schedule {
        order: units,
        nodes,
    }
}

/// Drops every unit equal in value to an earlier one (its products are the earlier one's).
fn drop_duplicates(tree: &mut Tree, units: &mut Vec<TUnitId>, shapes: &Shapes) {
    let mut seen = HashSet::default();
    let dropped: Vec<TUnitId> = (units.iter().copied())
        .filter(|&u| !seen.insert((&*tree.units[u].motion, shapes.inputs(u), shapes.outputs(u))))
        .collect();
    units.retain(|u| !dropped.contains(u));
    for u in dropped {
        tree.units[u].alive = false;
    }
}

/// "Made before used" edges by position in the unit list: `into[v]` holds (maker, value) for each input
/// of unit `v` that another unit makes.
struct Needs {
    into: Vec<Vec<(usize, Value)>>,
}

impl Needs {
    /// Every maker of every input that is not a kitchen item.
    fn new(units: &[TUnitId], shapes: &Shapes, vals: &Values) -> Needs {
        let mut makers: Vec<Vec<usize>> = vec![Vec::new(); vals.start.len()];
        for (i, &u) in units.iter().enumerate() {
            for &m in shapes.made(u) {
                makers[m].push(i);
            }
        }
        let mut into = vec![Vec::new(); units.len()];
        for (i, &u) in units.iter().enumerate() {
            let mut inputs = shapes.inputs(u).to_vec();
            inputs.dedup(); // sorted: a repeated value follows its first use
            for x in inputs.into_iter().filter(|&x| !vals.start[x]) {
                into[i].extend(makers[x].iter().filter(|&&p| p != i).map(|&p| (p, x)));
            }
        }
        let mut needs = Needs { into };
        for (x, makers) in makers.iter().enumerate().filter(|(_, m)| m.len() > 1) {
            needs.first_making(units, shapes, x, makers);
        }
        needs
    }

    /// Every edge as (consumer, maker, value).
    fn edges(&self) -> impl Iterator<Item = (usize, usize, Value)> + '_ {
        (self.into.iter().enumerate()).flat_map(|(v, e)| e.iter().map(move |&(p, x)| (v, p, x)))
    }

    /// A value made again by a unit that needs one of its takers (the open pot made again by the uncover,
    /// after the cover took it): a unit that needs none of the takers the making again needs waits for
    /// the first making only (the rice is stirred in the pot once poured, before it is covered).
    fn first_making(&mut self, units: &[TUnitId], shapes: &Shapes, x: Value, makers: &[usize]) {
        let takes = |u: TUnitId| {
            shapes.inputs(u).binary_search(&x).is_ok()
                && shapes.outputs(u).binary_search(&x).is_err()
        };
        let takers: Vec<bool> = units.iter().map(|&u| takes(u)).collect();
        let again: Vec<usize> = makers
            .iter()
            .copied()
            .filter(|&m| self.needs_any(m, x, |v| takers[v]))
            .collect();
        if again.is_empty() || again.len() == makers.len() {
            return;
        }
        // the takers the making again comes after: the cover, not every taker (FOON's stir takes the pot
        // without giving it back, and the uncover does not need it)
        let detour: Vec<bool> = (0..units.len())
            .map(|t| takers[t] && again.iter().any(|&m| self.needs_any(m, x, |v| v == t)))
            .collect();
        let early: Vec<bool> = (0..units.len())
            .map(|c| !self.needs_any(c, x, |v| detour[v]))
            .collect();
        for (_, edges) in self.into.iter_mut().enumerate().filter(|(c, _)| early[*c]) {
            edges.retain(|&(m, v)| !(v == x && again.contains(&m)));
        }
    }

    /// Whether unit `from` is, or needs (directly or through others, other than for the value `x`), a
    /// unit `found` accepts.
    fn needs_any(&self, from: usize, x: Value, found: impl Fn(usize) -> bool) -> bool {
        walk_finds(self.into.len(), from, found, |v, next| {
            next.extend(self.into[v].iter().filter(|e| e.1 != x).map(|e| e.0));
        })
    }

    /// Drops each edge inside a cycle whose value the consumer also gets from a maker outside it.
    /// False when there is none.
    fn relax(&mut self, comp: &[usize]) -> bool {
        let mut changed = false;
        for (v, edges) in self.into.iter_mut().enumerate() {
            let inner = |&(p, _): &(usize, Value)| comp[p] == comp[v];
            let outside: Vec<Value> = edges.iter().filter(|e| !inner(e)).map(|e| e.1).collect();
            let before = edges.len();
            edges.retain(|e| !(inner(e) && outside.contains(&e.1)));
            changed |= edges.len() != before;
        }
        changed
    }
}

/// Kahn's order over "made before used" edges, ties in the tree's own order. A consumer whose input is
/// also made by a unit outside its cycle only needs that one. On a cycle, returns the edge to break:
/// (maker, consumer, value), the consumer earliest in the tree's order and the maker latest.
fn topological(
    units: &[TUnitId],
    shapes: &Shapes,
    vals: &Values,
) -> Result<Vec<TUnitId>, (TUnitId, TUnitId, Value)> {
    let n = units.len();
    let mut needs = Needs::new(units, shapes, vals);
    // relax edges into a cycle when the value is available from a maker outside it (each round that
    // changes something removes an edge)
    let comp = loop {
        let comp = components(n, &needs);
        if !needs.relax(&comp) {
            break comp;
        }
    };
    // a cycle (an edge inside a component: there are no loops): break the edge into its earliest
    // consumer from its latest maker
    let worst = (needs.edges())
        .filter(|&(v, p, _)| comp[p] == comp[v])
        .min_by_key(|&(v, p, x)| (v, Reverse(p), x));
    if let Some((v, p, x)) = worst {
        return Err((units[p], units[v], x));
    }
    // each maker's users, once per pair: (maker, consumer) sorted by maker
    let mut arcs: Vec<(usize, usize)> = needs.edges().map(|(v, p, _)| (p, v)).collect();
    arcs.sort_unstable();
    arcs.dedup();
    users_before_change(units, shapes, &mut arcs);
    let mut indegree = vec![0usize; n];
    for &(_, v) in &arcs {
        indegree[v] += 1;
    }
    let mut ready: BinaryHeap<Reverse<usize>> =
        (0..n).filter(|&v| indegree[v] == 0).map(Reverse).collect();
    let mut order = Vec::with_capacity(n);
    while let Some(Reverse(v)) = ready.pop() {
        order.push(units[v]);
        let users = arcs.partition_point(|a| a.0 < v)..arcs.partition_point(|a| a.0 <= v);
        for &(_, w) in &arcs[users] {
            indegree[w] -= 1;
            if indegree[w] == 0 {
                ready.push(Reverse(w));
            }
        }
    }
    Ok(order)
}

/// A node that one unit changes and others use and give back as it was comes to the others first: the
/// rice is stirred in the open pot before the pot is covered, the stove turned off once nothing cooks
/// on it. Added to `arcs` (maker, user by position, sorted) only where the order leaves it free, never
/// closing a cycle.
fn users_before_change(units: &[TUnitId], shapes: &Shapes, arcs: &mut Vec<(usize, usize)>) {
    // (value, unit) for every value a unit gives back as it took it, sorted by value
    let mut passed: Vec<(Value, usize)> = Vec::new();
    for (i, &u) in units.iter().enumerate() {
        let outputs = shapes.outputs(u);
        passed.extend(
            shapes
                .inputs(u)
                .iter()
                .filter(|x| outputs.binary_search(x).is_ok())
                .map(|&x| (x, i)),
        );
    }
    if passed.is_empty() {
        return;
    }
    passed.sort_unstable();
    passed.dedup();
    // the arcs added, apart from the sorted ones until the end
    let mut added: Vec<(usize, usize)> = Vec::new();
    // along the arcs (sorted) and those added, from a unit to those after it
    let after = |v: usize, next: &mut Vec<usize>, added: &[(usize, usize)]| {
        let out = arcs.partition_point(|a| a.0 < v)..arcs.partition_point(|a| a.0 <= v);
        next.extend(arcs[out].iter().map(|a| a.1));
        next.extend(added.iter().filter(|a| a.0 == v).map(|a| a.1));
    };
    for (c, &u) in units.iter().enumerate() {
        let outputs = shapes.outputs(u);
        for &x in shapes.inputs(u) {
            if outputs.binary_search(&x).is_ok() {
                continue;
            }
            let from = passed.partition_point(|e| e.0 < x);
            for &(_, p) in passed[from..].iter().take_while(|e| e.0 == x) {
                // never closing a cycle: `p` must not come after `c` already
                if p != c
                    && !walk_finds(units.len(), c, |v| v == p, |v, next| after(v, next, &added))
                {
                    added.push((p, c));
                }
            }
        }
    }
    if !added.is_empty() {
        arcs.extend(added);
        arcs.sort_unstable();
        arcs.dedup();
    }
}

/// Whether a walk over the units by position from `from` (of `n`), going on from each unit to those
/// `next` adds, comes to a unit `found` accepts.
fn walk_finds(
    n: usize,
    from: usize,
    found: impl Fn(usize) -> bool,
    next: impl Fn(usize, &mut Vec<usize>),
) -> bool {
    let mut seen = vec![false; n];
    let mut stack = vec![from];
    while let Some(v) = stack.pop() {
        if found(v) {
            return true;
        }
        if !std::mem::replace(&mut seen[v], true) {
            next(v, &mut stack);
        }
    }
    false
}

/// Strongly connected components of the "needs" graph (Tarjan, iterative): a component id per unit.
fn components(n: usize, needs: &Needs) -> Vec<usize> {
    let mut index = vec![usize::MAX; n];
    let mut low = vec![0usize; n];
    let mut on_stack = vec![false; n];
    let mut stack: Vec<usize> = Vec::new();
    let mut comp = vec![usize::MAX; n];
    let mut next = 0usize;
    let mut comps = 0usize;
    // (node, next edge to look at)
    let mut work: Vec<(usize, usize)> = Vec::with_capacity(n);
    for root in 0..n {
        if index[root] != usize::MAX {
            continue;
        }
        work.clear();
        work.push((root, 0));
        while let Some(&mut (v, ref mut e)) = work.last_mut() {
            if *e == 0 && index[v] == usize::MAX {
                index[v] = next;
                low[v] = next;
                next += 1;
                stack.push(v);
                on_stack[v] = true;
            }
            if let Some(&(w, _)) = needs.into[v].get(*e) {
                *e += 1;
                if index[w] == usize::MAX {
                    work.push((w, 0));
                } else if on_stack[w] {
                    low[v] = low[v].min(index[w]);
                }
                continue;
            }
            work.pop();
            if let Some(&(parent, _)) = work.last() {
                low[parent] = low[parent].min(low[v]);
            }
            if low[v] == index[v] {
                while let Some(w) = stack.pop() {
                    on_stack[w] = false;
                    comp[w] = comps;
                    if w == v {
                        break;
                    }
                }
                comps += 1;
            }
        }
    }
    comp
}

/// The maker `p` no longer lists `value` among its products (the node is there from the start, and
/// the unit returns it to that state). False when it has no such output.
fn break_cycle(tree: &mut Tree, vals: &Values, p: TUnitId, value: Value) -> bool {
    let unit = &mut tree.units[p];
    let before = unit.outputs.len();
    unit.outputs.retain(|o| vals.of_slot[o.0] != value);
    unit.outputs.len() != before
}

/// Keeps, from the end, the units making the goal or something a kept later unit uses.
fn drop_dead(
    tree: &mut Tree,
    order: &[TUnitId],
    shapes: &Shapes,
    vals: &Values,
    goal: Value,
) -> Vec<TUnitId> {
    let mut used = vec![false; vals.start.len()];
    let mut kept = Vec::with_capacity(order.len());
    for &u in order.iter().rev() {
        if shapes.outputs(u).contains(&goal) || shapes.made(u).iter().any(|&m| used[m]) {
            for &x in shapes.inputs(u) {
                used[x] = true;
            }
            kept.push(u);
        } else {
            tree.units[u].alive = false;
        }
    }
    kept.reverse();
    kept
}

/// Every planned ingredient must be in the plan as shown (a label or in a list of contents); one the
/// ordering had to drop is reported unplannable with the reason rather than claimed.
pub(crate) fn confirm_planned(tree: &Tree, order: &[TUnitId], outcomes: &mut [IngredientOutcome]) {
    let present = |object: &str| {
        order.iter().any(|&u| {
            let unit = &tree.units[u];
            unit.inputs.iter().chain(&unit.outputs).any(|&(x, _)| {
                let node = &tree.slots[x].node;
                node.label == object || node.listed().any(|i| i == object)
            })
        })
    };
    for o in outcomes.iter_mut() {
        if o.status == Status::Planned && !present(&o.object) {
            o.status = Status::Unplannable;
            let why = "its units were dropped while ordering the plan (they closed a cycle)";
            o.reason = Some(match o.reason.take() {
                Some(r) => format!("{r}; {why}"),
                None => why.to_string(),
            });
        }
    }
}
