//! The final execution order, decided on node *values* — what a plan shows and what the evaluator checks —
//! rather than on the tree's slots. Two slots with the same value are the same node to a reader: a recipe
//! that takes "bowl contains {flour}" from the kitchen while another unit of the plan makes exactly that
//! bowl must come after that unit. So every unit is ordered after every unit that makes one of its
//! inputs. When that is impossible (a state cycle: the pan is greased again by a unit that needs the
//! greased pan first), the node counts as available from the start and the later unit no longer lists
//! it as a product. The goal is never in the kitchen at the start: a unit that needs it before it is made
//! is dropped. Duplicated units and units whose products nobody uses are dropped.

use super::check::{available_at_start, node_key, NodeKey};
use super::output::plan_node;
use super::tree::{SlotId, TUnitId, Tree};
use crate::model::{ObjectNode, StateArg};
use crate::plan::{IngredientOutcome, PlanNode, Status};
use rustc_hash::{FxHashMap as HashMap, FxHashSet as HashSet};
use std::collections::{BTreeSet, BinaryHeap};
use std::sync::Arc;

type Value = usize;

/// Values of the slots (interned keys) and which of them a kitchen has at the start.
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

/// Each live slot's plan node, made once per distinct node (plan nodes are costly).
fn plan_nodes(tree: &Tree) -> Vec<Option<Arc<PlanNode>>> {
    let mut nodes = vec![None; tree.slots.len()];
    let mut by_node: HashMap<&ObjectNode, Arc<PlanNode>> =
        HashMap::with_capacity_and_hasher(tree.slots.len(), Default::default());
    for x in tree.live_slots() {
        let node: &ObjectNode = &tree.slots[x].node;
        let p = by_node
            .entry(node)
            .or_insert_with(|| Arc::new(plan_node(node)));
        nodes[x] = Some(Arc::clone(p));
    }
    nodes
}

fn values(nodes: &[Option<Arc<PlanNode>>]) -> Values {
    let mut ids: HashMap<NodeKey, Value> =
        HashMap::with_capacity_and_hasher(nodes.len(), Default::default());
    // one value for every slot no live unit uses (never looked at)
    let unused = 0;
    let mut start = vec![false];
    let of_slot = nodes
        .iter()
        .map(|p| {
            let Some(p) = p else {
                return unused;
            };
            let next = ids.len() + 1;
            *ids.entry(node_key(p)).or_insert_with(|| {
                start.push(available_at_start(p));
                next
            })
        })
        .collect();
    Values { of_slot, start }
}

/// A unit's input values (with repeats, sorted) and the values it makes (outputs that are not inputs).
struct Shape {
    inputs: Vec<Value>,
    outputs: Vec<Value>,
    made: BTreeSet<Value>,
}

fn shape(tree: &Tree, v: &Values, u: TUnitId) -> Shape {
    let unit = &tree.units[u];
    let mut inputs: Vec<Value> = unit.inputs.iter().map(|i| v.of_slot[i.0]).collect();
    inputs.sort_unstable();
    let mut outputs: Vec<Value> = unit.outputs.iter().map(|o| v.of_slot[o.0]).collect();
    outputs.sort_unstable();
    let made = outputs
        .iter()
        .copied()
        .filter(|o| inputs.binary_search(o).is_err())
        .collect();
    Shape {
        inputs,
        outputs,
        made,
    }
}

/// Orders the live units the goal needs so that the evaluator's invariants hold, editing the tree where
/// the order alone cannot (see the module comment). Returns the order; dropped units are marked dead.
pub(crate) fn schedule(tree: &mut Tree) -> Schedule {
    let nodes = plan_nodes(tree);
    let mut vals = values(&nodes);
    let goal = vals.of_slot[tree.goal];
    // the finished dish is never in the kitchen at the start, whatever its states say
    vals.start[goal] = false;
    let mut units: Vec<TUnitId> = tree.order();
    // each round either settles or removes a product or a unit, so the rounds are bounded
    let limit = 4 * units.len() + 8;
    for _ in 0..limit {
        let mut shapes: HashMap<TUnitId, Shape> =
            HashMap::with_capacity_and_hasher(units.len(), Default::default());
        shapes.extend(units.iter().map(|&u| (u, shape(tree, &vals, u))));
        let before = units.len();
        drop_duplicates(tree, &mut units, &shapes);
        if units.len() != before {
            continue;
        }
        match topological(&units, &shapes, &vals) {
            Ok(order) => {
                let kept = drop_dead(tree, &order, &shapes, goal);
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
                } else if !break_cycle(tree, &vals, p, value) {
                    tree.units[v].inputs.retain(|i| vals.of_slot[i.0] != value);
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
fn drop_duplicates(tree: &mut Tree, units: &mut Vec<TUnitId>, shapes: &HashMap<TUnitId, Shape>) {
    let mut seen: HashSet<(&str, &[Value], &[Value])> =
        HashSet::with_capacity_and_hasher(units.len(), Default::default());
    let mut keep = Vec::with_capacity(units.len());
    for &u in units.iter() {
        let s = &shapes[&u];
        let key = (tree.units[u].motion.as_str(), &s.inputs[..], &s.outputs[..]);
        if seen.insert(key) {
            keep.push(u);
        }
    }
    for &u in units.iter() {
        if !keep.contains(&u) {
            tree.units[u].alive = false;
        }
    }
    *units = keep;
}

/// Kahn's order over "made before used" edges, ties in the tree's own order. A consumer whose input is
/// also made by a unit outside its cycle only needs that one. On a cycle, returns the edge to break:
/// (maker, consumer, value), the consumer earliest in the tree's order and the maker latest.
fn topological(
    units: &[TUnitId],
    shapes: &HashMap<TUnitId, Shape>,
    vals: &Values,
) -> Result<Vec<TUnitId>, (TUnitId, TUnitId, Value)> {
    let mut makers: HashMap<Value, Vec<usize>> =
        HashMap::with_capacity_and_hasher(units.len() * 2, Default::default());
    for (i, u) in units.iter().enumerate() {
        for &m in &shapes[u].made {
            makers.entry(m).or_default().push(i);
        }
    }
    // needs[v] = (maker position, value): every maker of every input that is not a kitchen item
    let needs: Vec<Vec<(usize, Value)>> = units
        .iter()
        .enumerate()
        .map(|(i, u)| {
            let mut out = Vec::new();
            // inputs are sorted: a repeated value follows its first use
            let mut last = None;
            for &x in &shapes[u].inputs {
                if vals.start[x] || last.replace(x) == Some(x) {
                    continue;
                }
                for &p in makers.get(&x).map(Vec::as_slice).unwrap_or(&[]) {
                    if p != i {
                        out.push((p, x));
                    }
                }
            }
            out
        })
        .collect();
    let n = units.len();
    let mut needs = needs;
    // relax edges into a cycle when the value is available from a maker outside it (each round that
    // changes something removes an edge)
    loop {
        let comp = components(n, &needs);
        let mut changed = false;
        for v in 0..n {
            let list = &needs[v];
            // only an edge inside v's component can go
            if list.iter().all(|(p, _)| comp[*p] != comp[v]) {
                continue;
            }
            let outside: HashSet<Value> = list
                .iter()
                .filter(|(p, _)| comp[*p] != comp[v])
                .map(|e| e.1)
                .collect();
            let len = list.len();
            needs[v].retain(|(p, x)| comp[*p] != comp[v] || !outside.contains(x));
            changed |= needs[v].len() != len;
        }
        if !changed {
            let sizes = comp.iter().fold(HashMap::default(), |mut m, c| {
                *m.entry(*c).or_insert(0usize) += 1;
                m
            });
            // a cycle: break the edge into its earliest consumer from its latest maker
            let mut worst: Option<(usize, usize, Value)> = None;
            for (v, list) in needs.iter().enumerate() {
                if sizes[&comp[v]] < 2 {
                    continue;
                }
                for &(p, x) in list {
                    if comp[p] != comp[v] {
                        continue;
                    }
                    let better = worst.is_none_or(|(bp, bv, bx)| {
                        (v, usize::MAX - p, x) < (bv, usize::MAX - bp, bx)
                    });
                    if better {
                        worst = Some((p, v, x));
                    }
                }
            }
            if let Some((p, v, x)) = worst {
                return Err((units[p], units[v], x));
            }
            break;
        }
    }
    let mut indegree = vec![0usize; n];
    let mut users: Vec<Vec<usize>> = vec![Vec::new(); n];
    for (v, list) in needs.iter().enumerate() {
        let mut ps: Vec<usize> = list.iter().map(|e| e.0).collect();
        ps.sort_unstable();
        ps.dedup();
        indegree[v] = ps.len();
        for p in ps {
            users[p].push(v);
        }
    }
    let mut ready: BinaryHeap<std::cmp::Reverse<usize>> = (0..n)
        .filter(|&v| indegree[v] == 0)
        .map(std::cmp::Reverse)
        .collect();
    let mut order = Vec::with_capacity(n);
    while let Some(std::cmp::Reverse(v)) = ready.pop() {
        order.push(units[v]);
        for &w in &users[v] {
            indegree[w] -= 1;
            if indegree[w] == 0 {
                ready.push(std::cmp::Reverse(w));
            }
        }
    }
    Ok(order)
}

/// Strongly connected components of the "needs" graph (Tarjan, iterative): a component id per unit.
fn components(n: usize, needs: &[Vec<(usize, Value)>]) -> Vec<usize> {
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
            if let Some(&(w, _)) = needs[v].get(*e) {
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
    shapes: &HashMap<TUnitId, Shape>,
    goal: Value,
) -> Vec<TUnitId> {
    let mut used: HashSet<Value> =
        HashSet::with_capacity_and_hasher(4 * order.len(), Default::default());
    let mut kept = Vec::with_capacity(order.len());
    for &u in order.iter().rev() {
        let s = &shapes[&u];
        if s.outputs.contains(&goal) || s.made.iter().any(|m| used.contains(m)) {
            used.extend(s.inputs.iter().copied());
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
    let slots: BTreeSet<SlotId> = order
        .iter()
        .flat_map(|&u| {
            let unit = &tree.units[u];
            unit.inputs.iter().chain(unit.outputs.iter()).map(|x| x.0)
        })
        .collect();
    let mut present: HashSet<&str> = HashSet::default();
    for &s in &slots {
        let node = &tree.slots[s].node;
        present.insert(node.label.as_str());
        for st in &node.states {
            if let Some(StateArg::Ingredients(list)) = &st.arg {
                present.extend(list.iter().map(String::as_str));
            }
        }
    }
    for o in outcomes.iter_mut() {
        if o.status == Status::Planned && !present.contains(o.object.as_str()) {
            o.status = Status::Unplannable;
            let why = "its units were dropped while ordering the plan (they closed a cycle)";
            o.reason = Some(match o.reason.take() {
                Some(r) => format!("{r}; {why}"),
                None => why.to_string(),
            });
        }
    }
}
