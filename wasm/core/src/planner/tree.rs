//! The task tree being modified. Object nodes are *slots* shared by the units that make and use them, so
//! renaming an object or editing a `contains {…}` list changes it everywhere at once and the tree stays a
//! connected graph. Each slot has at most one designated producer; ordering follows producers only.

use super::alg2_retrieve::Retrieved;
use crate::contract::plan::Origin;
use crate::foon::kb::KnowledgeBase;
use crate::foon::model::{NodeId, ObjectNode, State, StateArg};
use crate::vocab::taxonomy::is_utensil;
use rustc_hash::{FxHashMap as HashMap, FxHashSet as HashSet};
use smol_str::SmolStr;
use std::borrow::Cow;
use std::ops::Range;
use std::sync::Arc;

pub(crate) type SlotId = usize;
pub(crate) type TUnitId = usize;

#[derive(Clone, Debug)]
pub(crate) struct Slot<'kb> {
    /// Borrowed from the knowledge base until the tree changes it (most nodes never change).
    pub node: Cow<'kb, ObjectNode>,
    /// The knowledge-base node it was made from, if any.
    pub kb: Option<NodeId>,
    /// Whether the label is a utensil's, set with the label (asked of nearly every slot the planner
    /// touches: a flag instead of hashing the label each time).
    pub utensil: bool,
}

impl Slot<'_> {
    /// Gives the slot another label, keeping `utensil` true to it.
    fn relabel(&mut self, to: &str) {
        self.node.to_mut().label = to.into();
        self.utensil = is_utensil(to);
    }
}

#[derive(Clone, Debug)]
pub(crate) struct TUnit<'kb> {
    pub inputs: Vec<(SlotId, bool)>,
    /// Borrowed from the knowledge base for retrieved units (the tree is dropped after every plan).
    pub motion: Cow<'kb, str>,
    pub outputs: Vec<(SlotId, bool)>,
    pub origin: Origin,
    /// The knowledge base's subgraphs the unit comes from (none for a unit the planner made).
    pub sources: Option<&'kb Arc<[String]>>,
    pub alive: bool,
}

#[derive(Clone, Debug, Default)]
pub(crate) struct Tree<'kb> {
    pub slots: Vec<Slot<'kb>>,
    pub units: Vec<TUnit<'kb>>,
    pub producer: Vec<Option<TUnitId>>,
    pub goal: SlotId,
}

/// Rewrites each of a node's lists of contents in place with `f`, which keeps it sorted and unique as
/// every list is (the reader makes them so); an emptied `contains` list becomes `empty`, and states
/// stay sorted and unique.
pub(crate) fn edit_contents(node: &mut ObjectNode, f: &mut dyn FnMut(&mut Vec<SmolStr>)) {
    node.states.retain_mut(|s| {
        let Some(StateArg::Ingredients(list)) = &mut s.arg else {
            return true;
        };
        f(list);
        debug_assert!(list.windows(2).all(|w| w[0] < w[1]));
        if !list.is_empty() {
            return true;
        }
        if s.name == "contains" {
            *s = State::plain("empty");
            return true;
        }
        false
    });
    node.states.sort();
    node.states.dedup();
}

/// Starts a node's `contains` list, in place of `empty`, with one item (for a node holding nothing).
fn start_contents(node: &mut ObjectNode, item: &str) {
    node.states
        .retain(|s| !(s.name == "empty" && s.arg.is_none()));
    node.states.push(State {
        name: "contains".into(),
        arg: Some(StateArg::Ingredients(vec![item.into()])),
    });
    node.states.sort();
}

/// Adds an item to a list of contents (sorted and unique) unless it is there.
pub(crate) fn add_item(list: &mut Vec<SmolStr>, item: &str) {
    if let Err(at) = list.binary_search_by(|x| x.as_str().cmp(item)) {
        list.insert(at, item.into());
    }
}

/// Renames an item of a list of contents (sorted and unique), which stays sorted and unique.
pub(crate) fn rename_item(list: &mut Vec<SmolStr>, from: &str, to: &str) {
    if let Ok(at) = list.binary_search_by(|x| x.as_str().cmp(from)) {
        list.remove(at);
        add_item(list, to);
    }
}

/// Keeps the first use of each slot, in order.
pub(crate) fn dedup_slots(uses: &mut Vec<(SlotId, bool)>) {
    let mut seen = HashSet::default();
    uses.retain(|x| seen.insert(x.0));
}

/// Replaces each use of a slot by the slot standing for it in `alias` (the end of its chain), keeping
/// the first use of each.
fn follow_aliases(uses: &mut Vec<(SlotId, bool)>, alias: &HashMap<SlotId, SlotId>) {
    for i in uses.iter_mut() {
        // bounded, should the aliases ever form a cycle
        for _ in 0..64 {
            match alias.get(&i.0) {
                Some(&a) if a != i.0 => i.0 = a,
                _ => break,
            }
        }
    }
    dedup_slots(uses);
}

/// What a unit does, in values (see `Tree::values`): its motion's id, its inputs' values sorted, a
/// separator, its outputs' values sorted. Units with equal keys are the same step of a plan.
fn value_key(unit: &TUnit, motion: usize, value: &[usize]) -> Vec<usize> {
    let mut ins: Vec<usize> = unit.inputs.iter().map(|i| value[i.0]).collect();
    let mut outs: Vec<usize> = unit.outputs.iter().map(|o| value[o.0]).collect();
    ins.sort_unstable();
    outs.sort_unstable();
    [&[motion][..], &ins, &[usize::MAX], &outs].concat()
}

/// Whether what `node` holds goes on into `theirs`, made by a unit taking it: a food made from a food
/// carries it (a batter baked into a cake, whose list may name the batter's ingredients, or nothing);
/// a food passes on to a vessel listing it, and a container or tool its contents to a node that holds
/// something and is the same vessel, lists all of them or is the food it holds (the board's brownie,
/// cut).
fn passes_on(node: &Slot, theirs: &Slot) -> bool {
    if !node.utensil && !theirs.utensil {
        return true;
    }
    let food = !node.utensil;
    let (node, theirs) = (&node.node, &theirs.node);
    let listed = |x: &str| theirs.contents().any(|c| c == x);
    theirs.holds_something()
        && (theirs.label == node.label
            || (food && listed(&node.label))
            || node.contents().all(|x| x == theirs.label || listed(x)))
}

/// Keeps in a slot's lists of contents only the items `keep` accepts (see `edit_contents`). A node
/// still borrowed from the knowledge base is copied without the items it loses, not whole.
pub(crate) fn retain_contents(node: &mut Cow<ObjectNode>, keep: &dyn Fn(&str) -> bool) {
    let Cow::Borrowed(kb_node) = node else {
        edit_contents(node.to_mut(), &mut |list| list.retain(|x| keep(x)));
        return;
    };
    let states = kb_node
        .states
        .iter()
        .map(|s| State {
            name: s.name.clone(),
            arg: match &s.arg {
                Some(StateArg::Ingredients(list)) => Some(StateArg::Ingredients(
                    list.iter().filter(|x| keep(x)).cloned().collect(),
                )),
                arg => arg.clone(),
            },
        })
        .collect();
    let mut copy = ObjectNode {
        label: kb_node.label.clone(),
        states,
    };
    edit_contents(&mut copy, &mut |_| {});
    *node = Cow::Owned(copy);
}

/// A copy of a node with its lists of contents rewritten (see `edit_contents`).
pub(crate) fn map_contents(node: &ObjectNode, f: &mut dyn FnMut(&mut Vec<SmolStr>)) -> ObjectNode {
    let mut copy = node.clone();
    edit_contents(&mut copy, f);
    copy
}

impl<'kb> Tree<'kb> {
    /// A tree from a retrieval result whose root is the goal.
    pub fn from_retrieved(kb: &'kb KnowledgeBase, r: &Retrieved, root: NodeId) -> Tree<'kb> {
        let mut t = Tree::default();
        let mut slot_of: HashMap<NodeId, SlotId> = HashMap::default();
        t.goal = t.kb_slot(kb, root, &mut slot_of);
        t.add_retrieved(kb, r, &mut slot_of, Origin::Reference);
        t
    }

    fn new_slot(&mut self, node: Cow<'kb, ObjectNode>, kb: Option<NodeId>) -> SlotId {
        let utensil = is_utensil(&node.label);
        self.slots.push(Slot { node, kb, utensil });
        self.producer.push(None);
        self.slots.len() - 1
    }

    fn kb_slot(
        &mut self,
        kb: &'kb KnowledgeBase,
        n: NodeId,
        slot_of: &mut HashMap<NodeId, SlotId>,
    ) -> SlotId {
        *slot_of
            .entry(n)
            .or_insert_with(|| self.new_slot(Cow::Borrowed(&kb.nodes[n]), Some(n)))
    }

    /// Adds retrieved units (all of `r.units`, in order); `slot_of` maps knowledge-base nodes to slots
    /// that already stand for them, no two nodes to one slot.
    pub fn add_retrieved(
        &mut self,
        kb: &'kb KnowledgeBase,
        r: &Retrieved,
        slot_of: &mut HashMap<NodeId, SlotId>,
        origin: Origin,
    ) {
        for &u in &r.units {
            let unit = &kb.units[u];
            let tu = self.units.len();
            let inputs = unit
                .inputs
                .iter()
                .map(|o| (self.kb_slot(kb, o.node, slot_of), o.moves))
                .collect();
            let outputs = unit
                .outputs
                .iter()
                .map(|o| {
                    let s = self.kb_slot(kb, o.node, slot_of);
                    // `slot_of` gives no two nodes one slot: the unit chosen for a node makes its slot,
                    // unless the slot had a maker already
                    if r.chosen.get(&o.node) == Some(&u) && self.producer[s].is_none() {
                        self.producer[s] = Some(tu);
                    }
                    (s, o.moves)
                })
                .collect();
            self.units.push(TUnit {
                inputs,
                motion: Cow::Borrowed(&unit.motion),
                outputs,
                origin,
                sources: Some(&kb.provenance[u]),
                alive: true,
            });
        }
    }

    pub fn add_unit(
        &mut self,
        inputs: Vec<(SlotId, bool)>,
        motion: &str,
        outputs: Vec<(SlotId, bool)>,
        origin: Origin,
    ) -> TUnitId {
        let id = self.units.len();
        for &(s, _) in &outputs {
            if self.producer[s].is_none() {
                self.producer[s] = Some(id);
            }
        }
        self.units.push(TUnit {
            inputs,
            motion: Cow::Owned(motion.to_string()),
            outputs,
            origin,
            sources: None,
            alive: true,
        });
        id
    }

    /// A slot for a node the planner made, or one it takes from the knowledge base as it is (borrowed
    /// until the tree changes it, not copied).
    pub fn add_slot(&mut self, node: Cow<'kb, ObjectNode>) -> SlotId {
        self.new_slot(node, None)
    }

    pub fn produced(&self, s: SlotId) -> bool {
        self.producer
            .get(s)
            .copied()
            .flatten()
            .is_some_and(|u| self.units[u].alive)
    }

    /// Units in a valid execution order: post-order from the goal through designated producers, inputs
    /// visited in the order of their contents (so the result never depends on slot numbering).
    /// Units the goal does not need are not listed.
    pub fn order(&self) -> Vec<TUnitId> {
        let mut order = Vec::new();
        // units done, then slots seen, in one table
        let mut marks = vec![false; self.units.len() + self.slots.len()];
        let (done, seen) = marks.split_at_mut(self.units.len());
        let mut stack: Vec<(SlotId, bool)> = Vec::new();
        stack.push((self.goal, false));
        while let Some((slot, expanded)) = stack.pop() {
            let Some(u) = self.producer.get(slot).copied().flatten() else {
                continue;
            };
            if !self.units[u].alive {
                continue;
            }
            if expanded {
                if !done[u] {
                    done[u] = true;
                    order.push(u);
                }
                continue;
            }
            if seen[slot] || done[u] {
                continue;
            }
            seen[slot] = true;
            stack.push((slot, true));
            // only the inputs a live unit makes, not yet visited, lead anywhere: the others are
            // neither sorted nor stacked (most units then have one or none to sort). Sorted where
            // they are stacked, last first; an input listed twice is passed over once visited.
            let first = stack.len();
            stack.extend(
                self.units[u]
                    .inputs
                    .iter()
                    .filter(|&&(s, _)| !seen[s] && self.produced(s))
                    .map(|&(s, _)| (s, false)),
            );
            stack[first..].sort_by(|(a, _), (b, _)| {
                (&self.slots[*b].node, b).cmp(&(&self.slots[*a].node, a))
            });
        }
        order
    }

    /// Marks units the goal does not need as dead.
    pub fn drop_unneeded(&mut self) {
        let order = self.order();
        self.keep_only(&order);
    }

    /// Marks units outside `order` (the tree's order) as dead; the order stays the same.
    fn keep_only(&mut self, order: &[TUnitId]) {
        let mut keep = vec![false; self.units.len()];
        for &u in order {
            keep[u] = true;
        }
        for (u, keep) in self.units.iter_mut().zip(keep) {
            u.alive &= keep;
        }
    }

    pub fn alive_units(&self) -> impl Iterator<Item = (TUnitId, &TUnit<'kb>)> {
        self.units.iter().enumerate().filter(|(_, u)| u.alive)
    }

    /// Slots used by live units, and the goal, ascending.
    pub fn live_slots(&self) -> impl Iterator<Item = SlotId> {
        let live = self.live_marks();
        (0..self.slots.len()).filter(move |&s| live[s])
    }

    /// Live slots with the label, in slot order.
    pub fn slots_with_label(&self, label: &str) -> Vec<SlotId> {
        (0..self.slots.len())
            .filter(|&s| self.slots[s].node.label == label && self.is_live(s))
            .collect()
    }

    /// Whether the slot is used by a live unit, or is the goal (its live producer's outputs are looked
    /// at first: a made slot is nearly always still among them).
    fn is_live(&self, s: SlotId) -> bool {
        let uses = |u: &TUnit| u.inputs.iter().chain(u.outputs.iter()).any(|x| x.0 == s);
        s == self.goal
            || self.producer[s].is_some_and(|p| self.units[p].alive && uses(&self.units[p]))
            || self.alive_units().any(|(_, u)| uses(u))
    }

    /// Per slot: used by a live unit, or the goal (marks by index: no sort).
    fn live_marks(&self) -> Vec<bool> {
        let mut live = vec![false; self.slots.len()];
        if let Some(goal) = live.get_mut(self.goal) {
            *goal = true;
        }
        for (_, u) in self.alive_units() {
            for x in u.inputs.iter().chain(u.outputs.iter()) {
                live[x.0] = true;
            }
        }
        live
    }

    /// Ingredient labels in the tree (not utensils, not the goal's own label), sorted and unique.
    pub fn ingredient_labels(&self) -> Vec<&str> {
        let goal = self.slots[self.goal].node.label.as_str();
        let mut labels: Vec<&str> = self
            .live_slots()
            .filter(|&s| !self.slots[s].utensil)
            .map(|s| self.slots[s].node.label.as_str())
            .filter(|&l| l != goal)
            .collect();
        labels.sort_unstable();
        labels.dedup();
        labels
    }

    /// Whether a starting food `label` (made by no unit) leads on to the goal: a unit takes a node that is
    /// it or holds it (a bowl listing it) and gives out one that holds it too, or a food made there (the
    /// batter mixed in that bowl), and so on to the goal. FOON has dead ends: oil poured into a pot that
    /// the next unit gives out without it. `order`: the tree's order (`Tree::order`), computed once for
    /// many labels.
    pub fn leads_to_goal(&self, label: &str, order: &[TUnitId]) -> bool {
        let holds = |x: SlotId| {
            let node = &self.slots[x].node;
            node.label == label || node.listed().any(|item| item == label)
        };
        let mut reaches = vec![false; self.slots.len()];
        reaches[self.goal] = true;
        for &u in order.iter().rev() {
            let unit = &self.units[u];
            let made_here = |x: SlotId| {
                let made = &self.slots[x];
                !made.utensil
                    && !unit
                        .inputs
                        .iter()
                        .any(|i| self.slots[i.0].node.label == made.node.label)
            };
            let on = unit
                .outputs
                .iter()
                .any(|o| reaches[o.0] && (holds(o.0) || made_here(o.0)));
            for i in unit.inputs.iter().filter(|i| holds(i.0)) {
                reaches[i.0] |= on;
            }
        }
        (0..self.slots.len())
            .any(|x| reaches[x] && self.slots[x].node.label == label && !self.produced(x))
    }

    /// Live units that take the slot as input, in execution order.
    pub fn consumers<'a>(
        &'a self,
        s: SlotId,
        order: &'a [TUnitId],
    ) -> impl Iterator<Item = TUnitId> + 'a {
        self.consumers_from(s, order, 0).map(|(_, u)| u)
    }

    /// `consumers` from position `from` of the order on, with their positions.
    fn consumers_from<'a>(
        &'a self,
        s: SlotId,
        order: &'a [TUnitId],
        from: usize,
    ) -> impl Iterator<Item = (usize, TUnitId)> + 'a {
        order
            .iter()
            .copied()
            .enumerate()
            .skip(from)
            .filter(move |&(_, u)| self.units[u].inputs.iter().any(|i| i.0 == s))
    }

    /// Renames an object in the given slots, in their labels and their lists of contents.
    pub fn rename_in(&mut self, slots: Range<SlotId>, from: &str, to: &str) {
        let mut touched = vec![false; self.slots.len()];
        for s in slots {
            let slot = &mut self.slots[s];
            if slot.node.label != from && !slot.node.listed().any(|i| i == from) {
                continue;
            }
            edit_contents(slot.node.to_mut(), &mut |list| rename_item(list, from, to));
            if slot.node.label == from {
                slot.relabel(to);
            }
            touched[s] = true;
        }
        for u in self.units.iter_mut() {
            if u.origin == Origin::Reference
                && u.inputs
                    .iter()
                    .chain(u.outputs.iter())
                    .any(|x| touched[x.0])
            {
                u.origin = Origin::Renamed;
            }
        }
    }

    pub fn rename_everywhere(&mut self, from: &str, to: &str) {
        self.rename_in(0..self.slots.len(), from, to);
    }

    /// Renames a food where it is another's surface or vessel ("butter spread on [pancake]").
    pub fn rename_container(&mut self, from: &str, to: &str) {
        for slot in self
            .slots
            .iter_mut()
            .filter(|s| s.node.container() == Some(from))
        {
            let node = slot.node.to_mut();
            for state in &mut node.states {
                if let Some(StateArg::Container(c)) = &mut state.arg {
                    if c == from {
                        *c = to.into();
                    }
                }
            }
            node.states.sort();
        }
    }

    /// Per slot, whether contents added to it reach the goal: it is the goal, or a unit of `order`
    /// takes it and passes its contents on (see `passes_on`) to a slot that reaches the goal. Where an
    /// ingredient joins a unit, only such an output keeps it in the dish (a blender jar emptied of its
    /// oats alone, or a pan the toast leaves, would lose it).
    pub fn carriers(&self, order: &[TUnitId]) -> Vec<bool> {
        let mut carries = vec![false; self.slots.len()];
        carries[self.goal] = true;
        // consumers come after producers in an execution order: walked backwards, a unit's outputs are
        // settled before its inputs are judged
        for &v in order.iter().rev() {
            let unit = &self.units[v];
            for &(s, _) in &unit.inputs {
                let node = &self.slots[s];
                // an empty tool or container passes nothing on, and no caller asks whether it would
                if !carries[s] && (!node.utensil || node.node.holds_something()) {
                    carries[s] = unit
                        .outputs
                        .iter()
                        .any(|&(o, _)| o != s && carries[o] && passes_on(node, &self.slots[o]));
                }
            }
        }
        carries
    }

    /// Adds `label` to the contents of the unit's receiving outputs (of those holding something, the
    /// ones with the longest `contains` list among those that reach the goal, else among all) and,
    /// downstream, to every node that took over those contents. `order` is the tree's order before the
    /// new ingredient's branch joined `unit` (the branch consumes none of those nodes), `carries` its
    /// `carriers`.
    pub fn add_contents_downstream(
        &mut self,
        unit: TUnitId,
        label: &str,
        order: &[TUnitId],
        carries: &[bool],
    ) {
        let Some(u) = self.units.get(unit) else {
            return;
        };
        let count = |o: &(SlotId, bool)| self.slots[o.0].node.ingredient_count();
        let reaching = u.outputs.iter().any(|o| carries[o.0] && count(o) > 0);
        let goal = &self.slots[self.goal].node;
        if !reaching && goal.label != label && u.outputs.iter().any(|o| o.0 == self.goal) {
            // the dish itself lists nothing yet (a tree pruned down to its last unit): it takes the
            // ingredient (never itself) rather than the plate beside it
            start_contents(self.slots[self.goal].node.to_mut(), label);
            return;
        }
        let receives = |o: &(SlotId, bool)| {
            if reaching && !carries[o.0] {
                0
            } else {
                count(o)
            }
        };
        let longest = u.outputs.iter().map(receives).max().unwrap_or(0);
        // each slot to visit goes with where in `order` the units taking it can be: past its maker when
        // that is its designated producer (an execution order puts producers first), else anywhere
        let after = |s: SlotId, maker: TUnitId, at: usize| {
            if self.producer[s] == Some(maker) {
                at + 1
            } else {
                0
            }
        };
        let at = order.iter().position(|&v| v == unit);
        let mut work: Vec<(SlotId, usize)> = u
            .outputs
            .iter()
            .filter(|o| longest > 0 && receives(o) == longest)
            .map(|o| (o.0, at.map_or(0, |at| after(o.0, unit, at))))
            .collect();
        // every slot visited holds contents and lists `label` after its visit, so a slot visited again
        // is passed over here
        while let Some((s, from)) = work.pop() {
            let node = &self.slots[s].node;
            if node.contents().any(|x| x == label) {
                continue;
            }
            // the nodes taking over its contents, judged before the edit (it changes only `s`)
            for (at, v) in self.consumers_from(s, order, from) {
                for &(o, _) in &self.units[v].outputs {
                    // a list to add to: a food listing nothing is where the walk ends
                    let (mine, theirs) = (&self.slots[s], &self.slots[o]);
                    if o != s && theirs.node.holds_something() && passes_on(mine, theirs) {
                        work.push((o, after(o, v, at)));
                    }
                }
            }
            edit_contents(self.slots[s].node.to_mut(), &mut |list| {
                add_item(list, label)
            });
        }
    }

    /// Makes the tree sound at the level of node *values*, which is what a plan shows: a unit identical
    /// to an earlier one is dropped (its products are the earlier one's), and a unit that makes nothing
    /// new that a later unit uses (only passes its inputs on) is dropped, its outputs replaced by the
    /// equal inputs. Repeats until nothing changes; units the goal does not need are dropped. Returns
    /// the slots' values (`values`: the slots live units use afterwards are among those it compared) and
    /// the tree's order as it leaves it.
    pub fn drop_redundant_units(&mut self) -> (Vec<usize>, Vec<TUnitId>) {
        // slots keep their nodes here: compare values by interned id rather than by node
        let value = self.values();
        let motion = self.motion_ids();
        // the tree's order, computed again only after a change
        let mut order = self.order();
        for _ in 0..16 {
            let mut changed = self.join_equal_leaves(&value, &order);
            if changed {
                order = self.order();
            }
            let mut alias: HashMap<SlotId, SlotId> = HashMap::default();
            changed |= self.drop_round(&order, &value, &motion, &mut alias);
            if !changed {
                // as after a round that changed something, the units the goal does not need go
                self.keep_only(&order);
                break;
            }
            // apply the last aliases to every live unit, then forget units the goal no longer needs
            for unit in self.units.iter_mut().filter(|u| u.alive) {
                follow_aliases(&mut unit.inputs, &alias);
            }
            order = self.order();
            self.keep_only(&order);
        }
        (value, order)
    }

    /// One round of `drop_redundant_units` over `order`: drops the units equal to an earlier one or
    /// making nothing new, recording in `alias` the slot standing for each output of a dropped unit.
    /// Whether it dropped any.
    fn drop_round(
        &mut self,
        order: &[TUnitId],
        value: &[usize],
        motion: &[usize],
        alias: &mut HashMap<SlotId, SlotId>,
    ) -> bool {
        let mut changed = false;
        // position of the last unit using each slot (inputs as they are at the start of the round)
        let mut last_use: Vec<Option<usize>> = vec![None; self.slots.len()];
        for (pos, &u) in order.iter().enumerate() {
            for i in &self.units[u].inputs {
                last_use[i.0] = Some(pos);
            }
        }
        let mut first: HashMap<Vec<usize>, TUnitId> = HashMap::default();
        // per output of a dropped unit, the foods only it took (see `put_in`)
        let mut carried: HashMap<SlotId, Vec<SlotId>> = HashMap::default();
        for (pos, &u) in order.iter().enumerate() {
            let inputs = &self.units[u].inputs;
            let foods: Vec<SlotId> = inputs
                .iter()
                .filter_map(|i| carried.remove(&i.0))
                .flatten()
                .collect();
            self.units[u]
                .inputs
                .extend(foods.into_iter().map(|x| (x, true)));
            follow_aliases(&mut self.units[u].inputs, alias);
            let unit = &self.units[u];
            let makes_goal = unit.outputs.iter().any(|o| o.0 == self.goal);
            let key = value_key(unit, motion[u], value);
            if !makes_goal {
                if let Some(&f) = first.get(&key) {
                    let theirs = self.units[f].outputs.clone();
                    for &(o, _) in &self.units[u].outputs {
                        if let Some(&(t, _)) = theirs.iter().find(|t| value[t.0] == value[o]) {
                            if t != o {
                                alias.insert(o, t);
                            }
                        }
                    }
                    self.units[u].alive = false;
                    changed = true;
                    continue;
                }
            }
            // new products a later unit uses (or the goal)
            let ins = &key[1..=unit.inputs.len()];
            let useful = unit.outputs.iter().any(|&(o, _)| {
                !ins.contains(&value[o]) && (o == self.goal || last_use[o].is_some_and(|l| l > pos))
            });
            if makes_goal && !useful {
                // the goal's last unit changes nothing: the goal is its equal input
                if let Some(&(i, _)) = unit.inputs.iter().find(|i| value[i.0] == value[self.goal]) {
                    if self.producer[i].is_some() {
                        self.goal = i;
                        self.units[u].alive = false;
                        return true;
                    }
                }
            }
            if !useful && !makes_goal {
                let foods = self.put_in(u, |x| last_use[x] != Some(pos));
                for &(o, _) in &unit.outputs {
                    carried.entry(o).or_default().extend(&foods);
                    if let Some(&(i, _)) = unit.inputs.iter().find(|i| value[i.0] == value[o]) {
                        if i != o {
                            alias.insert(o, i);
                        }
                    }
                }
                self.units[u].alive = false;
                changed = true;
            }
            first.insert(key, u);
        }
        changed
    }

    /// The foods unit `u` puts in for good: no output of it names them and no later unit takes them
    /// (`taken_later`). Where the unit is dropped as making nothing new (the egg poured into a bowl pruning
    /// left empty, which then looks like the egg's own), they go on with the unit that takes what it
    /// filled, so their lines keep their start.
    fn put_in(&self, u: TUnitId, taken_later: impl Fn(SlotId) -> bool) -> Vec<SlotId> {
        let unit = &self.units[u];
        let named = |x: SlotId| {
            let label = &self.slots[x].node.label;
            unit.outputs
                .iter()
                .any(|o| self.slots[o.0].node.label == *label)
        };
        unit.inputs
            .iter()
            .map(|i| i.0)
            .filter(|&x| !self.slots[x].utensil && !named(x) && !taken_later(x))
            .collect()
    }

    /// An id per unit, equal for units with the same motion.
    fn motion_ids(&self) -> Vec<usize> {
        let mut ids: HashMap<&str, usize> = HashMap::default();
        self.units
            .iter()
            .map(|u| {
                let next = ids.len();
                *ids.entry(u.motion.as_ref()).or_insert(next)
            })
            .collect()
    }

    /// An id per slot, equal for slots with equal nodes, below the number of slots.
    /// `drop_redundant_units` compares only slots that live units use (it edits only those units, and
    /// only among their slots): every other slot gets an id of its own.
    fn values(&self) -> Vec<usize> {
        let live = self.live_marks();
        let mut ids: HashMap<&ObjectNode, usize> = HashMap::default();
        let mut next = 0;
        self.slots
            .iter()
            .zip(live)
            .map(|(s, live)| {
                let fresh = next;
                let id = if live {
                    *ids.entry(&s.node).or_insert(fresh)
                } else {
                    fresh
                };
                if id == fresh {
                    next += 1;
                }
                id
            })
            .collect()
    }

    /// A starting slot equal in value to a slot some unit makes is the same node in the plan: it is
    /// joined to the made one, so its users come after its maker, when that makes no cycle.
    fn join_equal_leaves(&mut self, value: &[usize], order: &[TUnitId]) -> bool {
        // per value, the first slot made with it (value ids are below the number of slots)
        let mut made: Vec<Option<SlotId>> = vec![None; self.slots.len()];
        for &u in order {
            let unit = &self.units[u];
            for &(o, _) in &unit.outputs {
                if self.producer[o] == Some(u)
                    && !unit.inputs.iter().any(|i| value[i.0] == value[o])
                {
                    made[value[o]].get_or_insert(o);
                }
            }
        }
        let mut changed = false;
        for &v in order {
            for k in 0..self.units[v].inputs.len() {
                let x = self.units[v].inputs[k].0;
                if self.produced(x) {
                    continue;
                }
                let Some(y) = made[value[x]] else {
                    continue;
                };
                if y == x || self.depends_on_unit(y, v) {
                    continue;
                }
                self.units[v].inputs[k].0 = y;
                changed = true;
            }
        }
        changed
    }

    /// Whether making slot `s` needs unit `v` (through designated producers).
    fn depends_on_unit(&self, s: SlotId, v: TUnitId) -> bool {
        let mut stack = vec![s];
        let mut seen = HashSet::default();
        while let Some(x) = stack.pop() {
            if !seen.insert(x) {
                continue;
            }
            if let Some(u) = self.producer.get(x).copied().flatten() {
                if !self.units[u].alive {
                    continue;
                }
                if u == v {
                    return true;
                }
                stack.extend(self.units[u].inputs.iter().map(|i| i.0));
            }
        }
        false
    }
}
