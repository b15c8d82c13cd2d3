//! From the modified tree to the plan: units in execution order, progress lines (section IV-A) and one
//! plain sentence per unit.

use super::states::{category, kind, state_text, Category};
use super::tree::{SlotId, TUnitId, Tree};
use crate::foods;
use crate::kb::{Goal, KnowledgeBase};
use crate::model::{ObjectNode, State, StateArg};
use crate::plan::{
    DishClassRef, GoalInfo, IngredientOutcome, Plan, PlanNode, PlanUnit, ProgressLine,
    ProgressState, Query, Status,
};
use crate::taxonomy::{is_mixing_motion, PUT_MOTIONS};
use smol_str::{SmolStr, SmolStrBuilder};
use std::sync::Arc;

pub(crate) struct Parts<'a> {
    pub kb: &'a KnowledgeBase,
    pub tree: &'a Tree<'a>,
    /// The units in execution order, and each slot's plan node (`schedule::schedule`).
    pub order: &'a [TUnitId],
    pub nodes: &'a [Option<Arc<PlanNode>>],
    pub query: Query,
    pub dish_class: Option<DishClassRef>,
    pub notes: Vec<String>,
    pub modified: bool,
    pub goal: &'a Goal,
    pub score: f32,
    pub outcomes: Vec<IngredientOutcome>,
    pub removed: Vec<String>,
    pub format_version: u32,
}

pub(crate) fn plan_node(n: &ObjectNode) -> PlanNode {
    PlanNode {
        label: n.label.clone(),
        states: n.states.iter().map(State::text).collect(),
        // one `contains` list (nearly every node) is sorted and unique already: copied as it is
        ingredients: n
            .contents_list()
            .map_or_else(|| n.ingredients(), <[SmolStr]>::to_vec),
        container: n.container().map(SmolStr::from),
    }
}

pub(crate) fn build(p: Parts) -> Plan {
    let tree = p.tree;
    let order = p.order;
    // the schedule made a node for every slot a live unit uses
    let node = |x: SlotId| match p.nodes.get(x) {
        Some(Some(n)) => Arc::clone(n),
        _ => Arc::new(plan_node(&tree.slots[x].node)),
    };
    let units: Vec<PlanUnit> = order
        .iter()
        .map(|&u| {
            let unit = &tree.units[u];
            PlanUnit {
                inputs: unit.inputs.iter().map(|i| node(i.0)).collect(),
                motion: unit.motion.as_ref().into(),
                outputs: unit.outputs.iter().map(|o| node(o.0)).collect(),
                origin: unit.origin,
                sources: unit.sources.map(Arc::clone).unwrap_or_default(),
            }
        })
        .collect();
    let goal_node = &tree.slots[tree.goal].node;
    let mut relations = Relations {
        tree,
        known: Vec::new(),
    };
    let mut objects = Vec::new();
    let mut steps: Vec<String> = order
        .iter()
        .map(|&u| sentence(tree, u, &mut objects, &mut relations))
        .collect();
    tell_apart(tree, order, &mut steps);
    let uses = Uses::new(tree, order);
    let mut progress_lines = Vec::with_capacity(p.outcomes.len());
    let mut done: Vec<&str> = Vec::with_capacity(p.outcomes.len());
    let mut slots = Vec::new();
    for o in &p.outcomes {
        if o.status != Status::Planned || done.contains(&o.object.as_str()) {
            continue;
        }
        done.push(&o.object);
        if let Some(line) = progress_line(order, &uses, &o.object, &mut slots, &mut relations) {
            progress_lines.push(line);
        }
    }
    let kb_goal = &p.kb.nodes[p.goal.node];
    Plan {
        format_version: p.format_version,
        query: p.query,
        dish_class: p.dish_class,
        notes: p.notes,
        modified: p.modified,
        goal: GoalInfo {
            label: goal_node.label.as_str().into(),
            states: goal_node.states.iter().map(State::text).collect(),
            ingredients: if p.goal.ingredients.is_empty() {
                kb_goal.ingredients()
            } else {
                p.goal.ingredients.clone()
            },
            subgraph: p.goal.subgraph.clone(),
            score: p.score,
            dish_class: p.goal.dish_class,
        },
        units,
        ingredients: p.outcomes,
        removed: p.removed,
        progress_lines,
        steps,
        cautions: Vec::new(),
        trace: None,
        robot: None,
    }
}

/// Two steps that read the same ("Cut the dough on the cutting board", to halve it and then to cut it
/// into strips) each say what their food becomes: "… until it is halved."; when nothing tells them apart,
/// the later says "again". A plan has a few dozen steps: pairs are compared directly.
fn tell_apart(tree: &Tree, order: &[TUnitId], steps: &mut [String]) {
    let repeated: Vec<usize> = (0..steps.len())
        .filter(|&i| (0..steps.len()).any(|j| j != i && steps[j] == steps[i]))
        .collect();
    for i in repeated {
        let unit = &tree.units[order[i]];
        // the food's new plain states: in an output, not in the input of the same name
        let made = unit.outputs.iter().find_map(|&(o, _)| {
            if tree.slots[o].utensil {
                return None;
            }
            let out = &tree.slots[o].node;
            let before = unit
                .inputs
                .iter()
                .map(|&(x, _)| &tree.slots[x].node)
                .find(|n| n.label == out.label)?;
            let new: Vec<&str> = out
                .physical_states()
                .filter(|s| !before.physical_states().any(|b| b == *s))
                .collect();
            (!new.is_empty()).then_some(new)
        });
        if let Some(new) = made {
            let step = &mut steps[i];
            step.pop();
            step.push_str(" until it is ");
            step.push_str(&new.join(" and "));
            step.push('.');
        }
    }
    // what still reads the same is the same action once more (a second spoonful of soy sauce)
    for i in 1..steps.len() {
        let times = steps[..i].iter().filter(|s| **s == steps[i]).count();
        if times > 0 {
            let step = &mut steps[i];
            step.pop();
            step.push_str(match times {
                1 => " again.",
                _ => " once more.",
            });
        }
    }
}

/// Where the progress lines look, found in one pass over the order rather than once per ingredient.
struct Uses<'t> {
    /// The slots live units use, and the goal, ascending, with their labels (each line compares them
    /// all: read once here rather than through the slot's node every time).
    live: Vec<(SlotId, &'t str)>,
    /// Per slot: made by a unit (an output that is not also its input).
    made: Vec<bool>,
    /// Per slot: the position of the first unit using it (`usize::MAX` for none).
    first_use: Vec<usize>,
}

impl<'t> Uses<'t> {
    fn new(tree: &'t Tree, order: &[TUnitId]) -> Uses<'t> {
        let mut made = vec![false; tree.slots.len()];
        let mut first_use = vec![usize::MAX; tree.slots.len()];
        for (pos, &u) in order.iter().enumerate().rev() {
            let unit = &tree.units[u];
            for &(i, _) in &unit.inputs {
                first_use[i] = pos;
            }
            for &(o, _) in &unit.outputs {
                made[o] |= !unit.inputs.iter().any(|i| i.0 == o);
            }
        }
        Uses {
            live: tree
                .live_slots()
                .map(|x| (x, tree.slots[x].node.label.as_str()))
                .collect(),
            made,
            first_use,
        }
    }
}

/// "in bowl": two words, in a string of exactly their size (`concat` and `join` take a slower,
/// general path for these few short pieces).
fn spaced(first: &str, second: &str) -> SmolStr {
    let mut out = SmolStrBuilder::with_capacity(first.len() + 1 + second.len());
    out.push_str(first);
    out.push_str(" ");
    out.push_str(second);
    out.finish()
}

fn location(n: &ObjectNode) -> SmolStr {
    n.states
        .iter()
        .find_map(|s| match &s.arg {
            Some(StateArg::Container(c)) => Some(spaced(&s.name, c)),
            _ => None,
        })
        .unwrap_or_default()
}

/// The ingredient's states and places from its starting node, the motions between them, and the dish:
/// once it has gone into a food (flour into the batter), the line follows that food on, to the goal
/// (the batter poured into the pan and baked into the muffin). `slots`: a buffer reused from line to
/// line (the slots a walk passes through, then the vessels `product_of` follows).
fn progress_line<'t>(
    order: &[TUnitId],
    uses: &Uses,
    label: &str,
    slots: &mut Vec<SlotId>,
    relations: &mut Relations<'t>,
) -> Option<ProgressLine> {
    // the slots no unit makes, first used first (else its first slot): the line follows the first that
    // reaches the dish (FOON may also pour some of it into a jar of another mixture), else the first
    let mine = || {
        uses.live
            .iter()
            .filter(|&&(_, l)| l == label)
            .map(|&(x, _)| x)
    };
    let mut starts: Vec<SlotId> = mine().filter(|&x| !uses.made[x]).collect();
    starts.sort_by_key(|&x| uses.first_use[x]);
    if starts.is_empty() {
        starts.extend(mine().next());
    }
    let mut first = None;
    for start in starts {
        let line = line_from(order, uses, label, start, slots, relations);
        if reaches_dish(&line, &relations.tree.slots[relations.tree.goal].node.label) {
            return Some(line);
        }
        first.get_or_insert(line);
    }
    first
}

/// Whether a progress line goes into the dish `goal` (or onto it: butter spread on the pancake).
pub(crate) fn reaches_dish(line: &ProgressLine, goal: &str) -> bool {
    let on = spaced("on", goal);
    line.end_product == goal
        && line.state.iter().any(|s| {
            s.location == on
                || s.physical_state
                    .split(", ")
                    .any(|w| w.strip_prefix("in ") == Some(goal))
        })
}

/// `progress_line` from the starting slot `start`.
fn line_from<'t>(
    order: &[TUnitId],
    uses: &Uses,
    label: &str,
    start: SlotId,
    slots: &mut Vec<SlotId>,
    relations: &mut Relations<'t>,
) -> ProgressLine {
    let tree = relations.tree;
    let mut walked = walk(order, uses, label, start, 0, slots, relations);
    let mut states = walked.states;
    let mut motions = walked.motions;
    let goal = tree.slots[tree.goal].node.label.as_str();
    let mut end_product = goal;
    // each food it goes into is followed on; a food is followed once (FOON has cycles of states)
    let mut followed: Vec<SlotId> = Vec::new();
    while let Some((pos, x)) = walked.into {
        let product = tree.slots[x].node.label.as_str();
        end_product = product;
        // the dish reached: what is done to it then (cut, plated) is the dish's, not the ingredient's,
        // except its cooking (the egg of raw egg noodles is boiled with them)
        if x == tree.goal || product == goal || followed.contains(&x) {
            if let Some((motion, state)) = dish_cooked_after(tree, order, pos, x) {
                motions.push(motion);
                states.push(inside(product, state));
            }
            break;
        }
        followed.push(x);
        // made into itself again (egg white and yolk beaten into egg): its own states go on; so do
        // those of its parts (the white it was cracked into)
        let itself = product == label;
        let part = walked.opened;
        walked = walk(order, uses, product, x, pos + 1, slots, relations);
        if itself {
            states.pop();
        }
        for state in walked.states.into_iter().skip(usize::from(!itself)) {
            states.push(if itself || part {
                state
            } else {
                inside(product, state)
            });
        }
        motions.extend(walked.motions);
    }
    if !foods::shows_cooking(label) {
        unseen_cooking(&mut states);
    }
    carry_states(&mut states);
    ProgressLine {
        ingredient: label.into(),
        state: states,
        motion: motions,
        end_product: end_product.into(),
    }
}

/// The food's own states without the cooking of the vessel it sits in, for a food that does not show it
/// (salt in a pot of rice is not "partly cooked"; oil in a pan is still "hot"); what it went into ("in
/// rice, cooked") keeps it.
fn unseen_cooking(states: &mut [ProgressState]) {
    let unseen = |w: &str| category(w) == Category::Cooked && kind(w) != Some("heated");
    for s in states
        .iter_mut()
        .filter(|s| !s.physical_state.starts_with("in "))
    {
        if s.physical_state.split(", ").any(unseen) {
            let kept: Vec<&str> = s
                .physical_state
                .split(", ")
                .filter(|w| !unseen(w))
                .collect();
            s.physical_state = kept.join(", ").into();
        }
    }
}

/// A state FOON leaves without food states (milk poured into a bowl, "-") is the one before it: moving a
/// food does not change it.
fn carry_states(states: &mut [ProgressState]) {
    for i in 1..states.len() {
        let before = &states[i - 1].physical_state;
        if states[i].physical_state.is_empty() && !before.starts_with("in ") {
            states[i].physical_state = before.clone();
        }
    }
}

/// The unit after position `pos` that cooks the dish at slot `x` (the only units after the dish is made
/// are the dish's own), as its motion and the cooked dish's state.
fn dish_cooked_after(
    tree: &Tree,
    order: &[TUnitId],
    pos: usize,
    x: SlotId,
) -> Option<(SmolStr, ProgressState)> {
    let u = order.iter().skip(pos + 1).copied().find(|&u| {
        let unit = &tree.units[u];
        foods::cooks(&unit.motion) && unit.inputs.iter().any(|i| i.0 == x)
    })?;
    let unit = &tree.units[u];
    let &(made, _) = unit
        .outputs
        .iter()
        .find(|o| tree.slots[o.0].node.label == tree.slots[x].node.label)?;
    let node = &tree.slots[made].node;
    let state = ProgressState {
        physical_state: state_text(node),
        location: location(node),
    };
    Some((unit.motion.as_ref().into(), state))
}

/// A state of the food an ingredient went into, as the ingredient's: "[baked @ in pan]" of the batter
/// is "[in batter, baked @ in pan]" of the flour; "[in muffin @ …]" stays as it is.
fn inside(product: &str, state: ProgressState) -> ProgressState {
    if state.physical_state.starts_with("in ") {
        return state;
    }
    let physical_state = if state.physical_state.is_empty() {
        spaced("in", product)
    } else {
        SmolStr::from(format!("in {product}, {}", state.physical_state))
    };
    ProgressState {
        physical_state,
        location: state.location,
    }
}

/// One food's part of a progress line: its states from `start`, the motions between them, and the food
/// it went into (its position in the order and slot), if any.
struct Walked {
    states: Vec<ProgressState>,
    motions: Vec<SmolStr>,
    into: Option<(usize, SlotId)>,
    /// `into` is a part the food was opened into (the white an egg was cracked into)
    opened: bool,
}

/// The states of `label` from slot `start`, through the units of the order from position `from` on.
fn walk<'t>(
    order: &[TUnitId],
    uses: &Uses,
    label: &str,
    start: SlotId,
    mut from: usize,
    seen: &mut Vec<SlotId>,
    relations: &mut Relations<'t>,
) -> Walked {
    let tree = relations.tree;
    // a line has a few states: one allocation each for them and the motions
    let mut states = Vec::with_capacity(4);
    states.push(ProgressState {
        physical_state: state_text(&tree.slots[start].node),
        location: location(&tree.slots[start].node),
    });
    let mut motions = Vec::with_capacity(4);
    let mut at = start;
    seen.clear();
    seen.push(start);
    let mut into = None;
    let mut opened = false;
    let mut last_step: Option<(usize, TUnitId)> = None;
    loop {
        // no unit before the first to use it takes it (one nothing takes leaves the search where it is,
        // for the vessel holding it)
        if uses.first_use[at] != usize::MAX {
            from = from.max(uses.first_use[at]);
        }
        let next = order.iter().enumerate().skip(from).find_map(|(pos, &u)| {
            let unit = &tree.units[u];
            if !unit.inputs.iter().any(|i| i.0 == at) {
                return None;
            }
            // of two pieces of it (the stem cut off a broccoli, the florets), the one a later unit takes
            let pieces = || {
                unit.outputs
                    .iter()
                    .map(|o| o.0)
                    .filter(|&o| tree.slots[o].node.label == label && !seen.contains(&o))
            };
            // what goes into the unit making the dish goes into the dish (FOON's greek salad is poured
            // out beside the salad it was made of)
            let makes_dish = unit.outputs.iter().any(|o| o.0 == tree.goal);
            let out = pieces()
                .find(|&o| uses.first_use[o] != usize::MAX)
                .or_else(|| pieces().next())
                .filter(|_| !makes_dish);
            Some((pos, u, out))
        });
        let Some((pos, u, out)) = next else {
            // FOON lists a food in a bowl both as a node of its own and among the bowl's contents:
            // when no unit takes the node, the units take the bowl
            if let Some(v) = vessel_holding(tree, uses, at, label).filter(|v| !seen.contains(v)) {
                seen.push(v);
                at = v;
                continue;
            }
            // FOON takes the vessel up again as another node of it (the pot the garlic was fried in, later
            // the rice's): the later node listing the food goes on
            if let Some(v) = vessel_again(tree, uses, at, label, from).filter(|v| !seen.contains(v))
            {
                seen.push(v);
                at = v;
                continue;
            }
            // its last node sits in a vessel: what the vessel's contents become (the vessel the unit
            // that last moved it, or made it, put it in, though FOON's vessel may not list it)
            let touched = last_step.or_else(|| {
                let u = tree.producer.get(at).copied().flatten()?;
                Some((order.iter().position(|&v| v == u)?, u))
            });
            if let Some((pos, u)) = touched {
                let container = tree.slots[at].node.container();
                into = tree.units[u]
                    .outputs
                    .iter()
                    .map(|o| o.0)
                    .filter(|&x| tree.slots[x].utensil)
                    .find(|&x| {
                        let n = &tree.slots[x].node;
                        n.contents().any(|i| i == label) || container == Some(n.label.as_str())
                    })
                    .and_then(|x| product_of(tree, order, pos, x, label, seen));
                // the food made of the vessel's contents: the line says so
                if let Some((at, x)) = into {
                    motions.push(tree.units[order[at]].motion.as_ref().into());
                    states.push(ProgressState {
                        physical_state: spaced("in", &tree.slots[x].node.label),
                        location: location(&tree.slots[x].node),
                    });
                }
            }
            break;
        };
        last_step = Some((pos, u));
        motions.push(tree.units[u].motion.as_ref().into());
        match out {
            Some(o) => {
                seen.push(o);
                states.push(ProgressState {
                    physical_state: state_after(
                        label,
                        &tree.units[u].motion,
                        &tree.slots[o].node,
                        states.last().map_or("", |s| s.physical_state.as_str()),
                    ),
                    location: location(&tree.slots[o].node),
                });
                at = o;
                from = pos + 1;
            }
            None => {
                // it went into something else: what lists it (a food made of it), else a new food
                // (the soup simmered into tomato soup, though FOON's pot still lists the soup), else a
                // food that took it in or the vessel holding it; not another ingredient moved along
                let outputs = &tree.units[u].outputs;
                let lists = |food: bool| {
                    outputs.iter().find(|o| {
                        let slot = &tree.slots[o.0];
                        slot.utensil != food && names_in_a_list(&slot.node, label)
                    })
                };
                let fresh = || {
                    let inputs = &tree.units[u].inputs;
                    outputs.iter().find(|o| {
                        let n = &tree.slots[o.0].node;
                        !tree.slots[o.0].utensil
                            && !inputs.iter().any(|i| tree.slots[i.0].node.label == n.label)
                    })
                };
                // a food that took more in (the sauce stirred into the fried rice)
                let grew = || {
                    let inputs = &tree.units[u].inputs;
                    outputs.iter().find(|o| {
                        let n = &tree.slots[o.0].node;
                        !tree.slots[o.0].utensil
                            && inputs.iter().any(|i| {
                                let before = &tree.slots[i.0].node;
                                before.label == n.label
                                    && n.contents().count() > before.contents().count()
                            })
                    })
                };
                // followed in a vessel (the onion in the pot the broth is poured into), it stays in
                // the vessel; the food itself taken in by another goes with that one
                let in_vessel = tree.slots[at].utensil;
                let dish = || outputs.iter().find(|o| o.0 == tree.goal);
                let entered = dish().or_else(|| lists(true)).or_else(fresh).or_else(|| {
                    if in_vessel {
                        lists(false).or_else(grew)
                    } else {
                        grew().or_else(|| lists(false))
                    }
                });
                match entered {
                    Some(&(o, _)) => {
                        let n = &tree.slots[o].node;
                        let state = if tree.slots[o].utensil {
                            // put in a vessel as it was: the same state, a new place; cooked there
                            // when the vessel's contents are
                            let rel = relations.to(&n.label);
                            let before = &states[states.len() - 1].physical_state;
                            let motion = &tree.units[u].motion;
                            let before = prepared_by(
                                label,
                                motion,
                                reshaped_by(motion, before, before.clone()),
                            );
                            ProgressState {
                                physical_state: with_vessel_cooking(&before, n),
                                location: spaced(rel, &n.label),
                            }
                        } else if let Some(state) = opened_into(tree, u, label) {
                            // cracked into its parts (white and yolk): still the food itself
                            opened = true;
                            ProgressState {
                                physical_state: state.into(),
                                location: location(n),
                            }
                        } else {
                            ProgressState {
                                physical_state: spaced("in", &n.label),
                                location: location(n),
                            }
                        };
                        let cooks = crate::foods::cooks(&tree.units[u].motion);
                        if states.last() == Some(&state) && !cooks {
                            // already there (FOON lists what a bowl holds among the inputs of
                            // the next thing added to it): no step of its own, unless it cooks
                            motions.pop();
                        } else {
                            states.push(state);
                        }
                        if tree.slots[o].utensil {
                            // in a vessel: what is done to the vessel's contents is done to it (in the
                            // vessel the unit took, where FOON uses that again rather than its output)
                            seen.push(o);
                            if uses.first_use[o] != usize::MAX || !tree.slots[at].utensil {
                                at = o;
                            }
                            from = pos + 1;
                            continue;
                        }
                        into = product_of(tree, order, pos, o, label, seen);
                    }
                    None => {
                        // a unit that takes it and gives nothing of it back (a mixer turned on
                        // with the bowl in it): the next unit taking it goes on
                        motions.pop();
                        from = pos + 1;
                        continue;
                    }
                }
                break;
            }
        }
    }
    Walked {
        states,
        motions,
        into,
        opened,
    }
}

/// The state of `label` at `node`, made by `motion`: when the motion is the food's first preparation
/// ("crack" for an egg's "cracked"), that state, in place of the whole one FOON may keep ("whole" in the
/// bowl it was cracked into).
fn state_after(label: &str, motion: &str, node: &ObjectNode, before: &str) -> SmolStr {
    prepared_by(label, motion, reshaped_by(motion, before, state_text(node)))
}

/// State text `text` of `label` after `motion`: the food's first preparation when the motion is it
/// (`state_after`).
fn prepared_by(label: &str, motion: &str, text: SmolStr) -> SmolStr {
    let Some(first) = foods::prepared_first(label).filter(|p| p.starts_with(motion)) else {
        return text;
    };
    let mut words: Vec<&str> = text
        .split(", ")
        .filter(|w| !w.is_empty() && *w != first && category(w) != Category::Whole)
        .collect();
    words.insert(0, first);
    words.join(", ").into()
}

/// State text `text` after `motion`, when the motion leaves a food in a state of its own
/// (`foods::leaves_in`) and the food was, and is still shown as, no more than the piece it was bought as
/// (`before`): a "stick" of butter spread is "spread"; "peppercorn, hot" ground into a pan is "ground,
/// hot". The bread the butter is spread on was no such piece and is left as it is.
fn reshaped_by(motion: &str, before: &str, text: SmolStr) -> SmolStr {
    let Some(left) = foods::leaves_in(motion) else {
        return text;
    };
    fn words(s: &str) -> Vec<&str> {
        s.split(", ").filter(|w| !w.is_empty()).collect()
    }
    let piece_only = |ws: &[&str]| {
        ws.iter().all(|w| {
            matches!(
                category(w),
                Category::Whole | Category::Cooked | Category::Other
            )
        })
    };
    let (was, is) = (words(before), words(&text));
    let was_piece = was.iter().any(|w| category(w) == Category::Whole) && piece_only(&was);
    if !was_piece || !piece_only(&is) || is.contains(&left) {
        return text;
    }
    let mut out = vec![left];
    out.extend(is.into_iter().filter(|w| category(w) != Category::Whole));
    out.join(", ").into()
}

/// Whether food `product` is named as a part of food `label` ("egg white" of "egg", but also "egg noodle").
fn is_part(product: &str, label: &str) -> bool {
    product
        .strip_prefix(label)
        .is_some_and(|rest| rest.starts_with(' '))
}

/// The state of `label` when unit `u` opens it into two or more parts of it (an egg cracked into white
/// and yolk): the preparation the food knowledge names for it ("cracked"), if any.
fn opened_into(tree: &Tree, u: TUnitId, label: &str) -> Option<&'static str> {
    let parts = tree.units[u]
        .outputs
        .iter()
        .filter(|o| !tree.slots[o.0].utensil && is_part(&tree.slots[o.0].node.label, label))
        .count();
    // two parts of it made at once: a part, not a food made of it ("egg noodle")
    (parts >= 2).then(|| foods::prepared_first(label)).flatten()
}

/// Whether a state list of `n` names `label` or a part of it (the egg cracked into "egg white" and
/// "egg yolk"): its contents, or what coats it ("floured {flour}").
fn names_in_a_list(n: &ObjectNode, label: &str) -> bool {
    let part = |i: &str| {
        i.strip_prefix(label)
            .is_some_and(|rest| rest.is_empty() || rest.starts_with(' '))
    };
    n.states.iter().any(|s| match &s.arg {
        Some(StateArg::Ingredients(list)) => list.iter().any(|i| part(i)),
        _ => false,
    })
}

/// A food's state `before` in vessel `v`, with the cooking the vessel says its contents had ("halved"
/// in a pot "cooked": "halved, cooked").
fn with_vessel_cooking(before: &SmolStr, v: &ObjectNode) -> SmolStr {
    let cooked = v
        .physical_states()
        .find(|s| category(s) == Category::Cooked && !before.split(", ").any(|w| w == *s));
    let Some(cooked) = cooked else {
        return before.clone();
    };
    // no longer raw
    let mut words: Vec<&str> = before
        .split(", ")
        .filter(|w| !w.is_empty() && !matches!(*w, "uncooked" | "raw"))
        .collect();
    words.push(cooked);
    words.join(", ").into()
}

/// The vessel that node `at` of `label` says it is in, when the vessel lists `label` among its contents
/// and some unit uses it: the first used of those.
fn vessel_holding(tree: &Tree, uses: &Uses, at: SlotId, label: &str) -> Option<SlotId> {
    let container = tree.slots[at].node.container()?;
    uses.live
        .iter()
        .map(|&(x, _)| x)
        .filter(|&x| {
            let slot = &tree.slots[x];
            slot.utensil
                && slot.node.label == container
                && uses.first_use[x] != usize::MAX
                && slot.node.contents().any(|i| i == label)
        })
        .min_by_key(|&x| uses.first_use[x])
}

/// A later node of vessel `at` (first used at or after position `from`) that lists `label` among its
/// contents, when `at` is a vessel holding it.
fn vessel_again(tree: &Tree, uses: &Uses, at: SlotId, label: &str, from: usize) -> Option<SlotId> {
    let vessel = &tree.slots[at];
    if !vessel.utensil || !vessel.node.contents().any(|i| i == label) {
        return None;
    }
    uses.live
        .iter()
        .map(|&(x, _)| x)
        .filter(|&x| {
            let slot = &tree.slots[x];
            x != at
                && slot.utensil
                && slot.node.label == vessel.node.label
                && uses.first_use[x] != usize::MAX
                && uses.first_use[x] >= from
                && slot.node.contents().any(|i| i == label)
        })
        .min_by_key(|&x| uses.first_use[x])
}

/// The product an ingredient goes into (section IV-A): the first food node listing it among its
/// contents, following the vessel it was put in (flour in the bowl → the batter mixed in that bowl).
/// `vessels`: a buffer for the vessels holding it. Returns the product's position in the order and slot.
fn product_of(
    tree: &Tree,
    order: &[TUnitId],
    pos: usize,
    entered: SlotId,
    label: &str,
    vessels: &mut Vec<SlotId>,
) -> Option<(usize, SlotId)> {
    let lists = |x: SlotId| tree.slots[x].node.contents().any(|i| i == label);
    let food = |x: SlotId| !tree.slots[x].utensil;
    if food(entered) {
        return Some((pos, entered));
    }
    // a vessel holding it: the first food made from that vessel's contents
    vessels.clear();
    vessels.push(entered);
    let mut beside = None;
    for (at, &u) in order.iter().enumerate().skip(pos + 1) {
        let unit = &tree.units[u];
        if !unit.inputs.iter().any(|i| vessels.contains(&i.0)) {
            continue;
        }
        // what is made in the vessel is made of its contents, even where FOON's list omits them
        // (a new product: not an input moved along, like the vanilla poured into the same bowl)
        let new = |o: &&(SlotId, bool)| {
            let l = &tree.slots[o.0].node.label;
            !unit.inputs.iter().any(|i| tree.slots[i.0].node.label == *l)
        };
        let made = |o: &&(SlotId, bool)| food(o.0) && tree.slots[o.0].node.label != label;
        let listing = unit.outputs.iter().filter(made).find(|o| lists(o.0));
        let fresh = unit.outputs.iter().filter(made).find(new);
        // a new food beside a vessel that still lists it (an egg poached in the broth): it stays in the
        // vessel, unless nothing is made of that vessel's contents later
        let kept = unit
            .outputs
            .iter()
            .any(|o| tree.slots[o.0].utensil && lists(o.0));
        match (listing, fresh) {
            (Some(&(x, _)), _) => return Some((at, x)),
            (None, Some(&(x, _))) if !kept => return Some((at, x)),
            (None, Some(&(x, _))) => {
                beside.get_or_insert((at, x));
            }
            (None, None) => {}
        }
        vessels.extend(unit.outputs.iter().map(|o| o.0).filter(|&x| lists(x)));
    }
    beside
}

/// FOON motions whose words go around the object in English: ("cut in half", "Cut", " in half") makes "Cut
/// the tomato in half", ("make slits", "Make slits in", "") "Make slits in the mango". ("Break apart the
/// chip" reads well as it is.)
const VERB_FRAMES: &[(&str, &str, &str)] = &[
    ("pick-and-place", "Place", ""),
    ("put inside", "Put", ""),
    ("cut in half", "Cut", " in half"),
    ("make slits", "Make slits in", ""),
    ("cut with slits", "Cut slits in", ""),
    ("cut off ends", "Cut the ends off", ""),
    ("cut off skin", "Cut the skin off", ""),
    ("tuck ends", "Tuck in the ends of", ""),
];

/// The motion as the sentence's capitalised verb, written onto `out`; returns what follows the object.
fn push_verb(out: &mut String, motion: &str) -> &'static str {
    let m = motion.trim_end_matches('*').trim();
    if let Some(&(_, verb, after)) = VERB_FRAMES.iter().find(|f| f.0 == m) {
        out.push_str(verb);
        return after;
    }
    let mut c = m.chars();
    if let Some(f) = c.next() {
        out.extend(f.to_uppercase());
        out.push_str(c.as_str());
    }
    ""
}

/// "the a, the b and the c", written onto `out`.
fn push_list(out: &mut String, items: &[&str]) {
    for (k, item) in items.iter().enumerate() {
        if k > 0 {
            out.push_str(if k + 1 == items.len() { " and " } else { ", " });
        }
        out.push_str("the ");
        out.push_str(item);
    }
}

/// Motions that open or close a container.
const CLOSES: &[&str] = &["open", "close", "cover", "uncover"];
/// Other motions that handle a container itself rather than what it holds.
const HANDLES: &[&str] = &[
    "remove", "attach", "detach", "take out", "turn on", "turn off",
];

/// Whether a motion moves things into a place ("pour into the bowl", "tear and place onto the tray").
fn moves_into(motion: &str) -> bool {
    // a motion is a few bytes: each place compared, without the setup of `str::contains`
    let has = |word: &[u8]| {
        motion
            .as_bytes()
            .windows(word.len())
            .any(|w| w[0] == word[0] && w == word)
    };
    has(b"pour") || has(b"place") || PUT_MOTIONS.contains(&motion) || motion == "add"
}

/// Where a node is (`in [bowl]` as ("in", "bowl"), `attached to [mixer]` as ("to", "mixer")), unless
/// that is one of the `objects` moved. A lid it is covered with, or a tool it is with, is not a place.
fn container_of<'n>(n: &'n ObjectNode, objects: &[&str]) -> Option<(&'n str, &'n str)> {
    n.states.iter().find_map(|s| {
        let Some(StateArg::Container(c)) = &s.arg else {
            return None;
        };
        let rel = match s.name.as_str() {
            "attached to" => "to",
            rel @ ("in" | "on" | "over" | "under") => rel,
            _ => return None,
        };
        (!objects.contains(&c.as_str())).then_some((rel, c.as_str()))
    })
}

/// How things are put in each container, found once per container: a plan asks about a few
/// containers many times, and each answer looks through every slot.
struct Relations<'t> {
    tree: &'t Tree<'t>,
    known: Vec<(&'t str, &'t str)>,
}

impl<'t> Relations<'t> {
    fn to(&mut self, container: &'t str) -> &'t str {
        if let Some(&(_, rel)) = self.known.iter().find(|k| k.0 == container) {
            return rel;
        }
        let rel = relation_to(self.tree, container);
        self.known.push((container, rel));
        rel
    }
}

/// How things are put in `container`, as the tree's nodes say ("on" a plate, "in" a bowl), else "in".
/// Food says it first: a lid is on the blender jar, the food in it (a pot says it is on the stove).
fn relation_to<'t>(tree: &'t Tree, container: &str) -> &'t str {
    let said_by = |food: bool| {
        tree.slots
            .iter()
            .filter(move |slot| slot.utensil != food)
            .flat_map(|slot| &slot.node.states)
            .find_map(|s| match &s.arg {
                Some(StateArg::Container(c))
                    if c == container && (s.name == "in" || s.name == "on") =>
                {
                    Some(s.name.as_str())
                }
                _ => None,
            })
    };
    said_by(true).or_else(|| said_by(false)).unwrap_or("in")
}

/// One plain sentence for a unit: "Slice the tomato on the cutting board." `objects` is a buffer reused
/// from sentence to sentence (the sentence's objects, then its tools after them).
fn sentence<'t>(
    tree: &'t Tree,
    u: TUnitId,
    objects: &mut Vec<&'t str>,
    relations: &mut Relations<'t>,
) -> String {
    let unit = &tree.units[u];
    let node = |x: SlotId| &tree.slots[x].node;
    // the slot's flag rather than a lookup of its label
    let utensil = |x: SlotId| tree.slots[x].utensil;
    objects.clear();
    fn push<'n>(objects: &mut Vec<&'n str>, l: &'n str) {
        if !objects.contains(&l) {
            objects.push(l);
        }
    }
    for &(x, m) in &unit.inputs {
        if m && !utensil(x) {
            push(objects, &node(x).label);
        }
    }
    if objects.is_empty() {
        for &(x, _) in &unit.inputs {
            if !utensil(x) {
                push(objects, &node(x).label);
            }
        }
    }
    // no food among the inputs: the unit works on what a container holds ("Mix the egg and the milk in
    // the bowl with the whisk", "Cook the egg in the pot", "Pour the flour and the salt into the bowl"),
    // not on a tool or the container ("Mix the whisk", "Cook the pot", "Pour the bowl"), unless it handles
    // the container itself: "Place the pot onto the stove", "Cover the pot with the pot lid" (only tools
    // move: the lid) but "Cover the pot" when the pot moves
    let mut holder = None;
    let mut closed = false;
    // the vessel worked on is the one things are taken from, not the one they go into
    let mut from_elsewhere = false;
    let tool = |x: SlotId| utensil(x) && node(x).states.is_empty();
    let motion = unit.motion.trim_end_matches('*');
    let puts = moves_into(motion);
    let tools_only = unit.inputs.iter().any(|&(x, m)| m && tool(x))
        && unit.inputs.iter().all(|&(x, m)| !m || tool(x))
        && !PUT_MOTIONS.contains(&motion);
    let closes = CLOSES.contains(&motion);
    let handles =
        PUT_MOTIONS.contains(&motion) || HANDLES.contains(&motion) || motion.ends_with(" open");
    // food already in a vessel, mixed there into something new, is mixed with all the vessel holds: the
    // blender blends the whole cup, not the honey FOON moves ("Blend the honey, the blueberry and the milk")
    if !objects.is_empty() && !puts && !handles && !closes && is_mixing_motion(motion) {
        let label_of = |x: SlotId| node(x).label.as_str();
        let makes_new = unit.outputs.iter().any(|&(o, _)| {
            !utensil(o) && !unit.inputs.iter().any(|&(i, _)| label_of(i) == label_of(o))
        });
        let inside = |v: &ObjectNode, l: &str| {
            unit.inputs
                .iter()
                .any(|&(i, _)| label_of(i) == l && node(i).container() == Some(v.label.as_str()))
        };
        let vessel = unit
            .inputs
            .iter()
            .map(|&(i, _)| node(i))
            .find(|v| v.holds_something() && objects.iter().all(|l| inside(v, l)));
        if let Some(v) = vessel.filter(|_| makes_new) {
            for l in v.contents() {
                push(objects, l);
            }
        }
    }
    if objects.is_empty() && !handles {
        let vessel = |i: &&(SlotId, bool)| node(i.0).holds_something();
        // a lid is put on or taken off what the unit covers or uncovers, before or after
        let covered = closes
            .then(|| {
                let mut nodes = unit.inputs.iter().chain(&unit.outputs);
                nodes.find(|i| node(i.0).states.iter().any(|s| s.name == "covered"))
            })
            .flatten();
        // a moved tool (a spoon, even an empty or clean one), or a machine holding a vessel (a mixer with
        // its bowl), is not what is worked on; nor is a lid
        let machine = |x: SlotId| {
            let n = node(x);
            let bare_tool =
                utensil(x) && !n.holds_something() && n.states.iter().all(|s| s.arg.is_none());
            bare_tool || n.states.iter().any(|s| s.name == "with")
        };
        let moved = unit.inputs.iter().filter(|i| i.1);
        // what a motion puts somewhere comes out of a vessel other than the one the products are in (a
        // ladle scoops the noodles out of the pot into the bowl)
        let source = |i: &&(SlotId, bool)| {
            vessel(i)
                && !(puts
                    && unit
                        .outputs
                        .iter()
                        .any(|o| node(o.0).container() == Some(&node(i.0).label)))
        };
        let worked = covered.or_else(|| moved.clone().find(vessel)).or_else(|| {
            (closes || moved.clone().all(|i| machine(i.0)))
                .then(|| {
                    let found = unit.inputs.iter().find(source);
                    from_elsewhere = puts && found.is_some();
                    found.or_else(|| unit.inputs.iter().find(vessel))
                })
                .flatten()
        });
        if let Some(&(x, _)) = worked {
            let n = node(x);
            if closes {
                push(objects, &n.label);
                closed = true;
            } else {
                for l in n.contents() {
                    push(objects, l);
                }
                // poured out of it (with more than tools moving): where it goes is the place
                if (tools_only || !puts) && !from_elsewhere {
                    holder = Some((relations.to(&n.label), n.label.as_str()));
                }
            }
        }
    }
    // what moved, the tools it moved with aside ("Cut open the packet with the scissors")
    let mut with_tools = false;
    if objects.is_empty() {
        for &(x, m) in &unit.inputs {
            if m && !tool(x) {
                push(objects, &node(x).label);
                with_tools = true;
            }
        }
    }
    if objects.is_empty() {
        for &(x, m) in &unit.inputs {
            if m {
                push(objects, &node(x).label);
            }
        }
    }
    if objects.is_empty() {
        if let Some(&(x, _)) = unit.inputs.first() {
            push(objects, &node(x).label);
        }
    }
    // where the moved objects end up
    let place = holder.or_else(|| {
        // a container opened or closed where it stands
        if closed {
            return None;
        }
        unit.outputs
            .iter()
            .find_map(|&(x, _)| {
                let n = node(x);
                if !objects.contains(&n.label.as_str()) {
                    return None;
                }
                container_of(n, objects)
            })
            // no moved object says where it is (ingredients that joined the unit, whose lists alone
            // record them): where what now holds one of them is, or that container itself
            .or_else(|| {
                unit.outputs.iter().find_map(|&(x, _)| {
                    let n = node(x);
                    if objects.contains(&n.label.as_str())
                        || !n.contents().any(|c| objects.contains(&c))
                    {
                        return None;
                    }
                    if utensil(x) {
                        return Some((relations.to(&n.label), n.label.as_str()));
                    }
                    container_of(n, objects)
                })
            })
            // nothing the unit makes lists them: the food it makes of them is where they went ("Pour the
            // mixture into the pot", the pot's soup made of it). An emptied jar alone (its food pruned)
            // goes nowhere.
            .or_else(|| {
                let food = |&(x, _): &(SlotId, bool)| {
                    !utensil(x) && objects.contains(&node(x).label.as_str())
                };
                if !unit.inputs.iter().any(food) {
                    return None;
                }
                unit.outputs.iter().find_map(|&(x, _)| {
                    let n = node(x);
                    (!utensil(x) && !objects.contains(&n.label.as_str()))
                        .then(|| container_of(n, objects))
                        .flatten()
                })
            })
    });
    // what is already where the others are put is not put there again (FOON lists what a bowl holds
    // among the inputs of the next thing added to it): the others go onto it ("Pour the maple syrup onto
    // the french toast on the plate"); a bowl of the same name that does not hold it is another bowl
    let mut settled = Vec::new();
    if let Some((_, c)) = place.filter(|_| holder.is_none() && puts) {
        let mut vessels = unit
            .inputs
            .iter()
            .map(|i| node(i.0))
            .filter(|n| n.label == c);
        if let Some(first) = vessels.next() {
            let holds = |n: &ObjectNode, l: &str| n.contents().any(|i| i == l);
            let there = |l: &str| holds(first, l) && vessels.clone().all(|n| holds(n, l));
            let count = objects.iter().filter(|l| there(l)).count();
            if count > 0 && count < objects.len() {
                settled.extend(objects.iter().copied().filter(|l| there(l)));
                objects.retain(|l| !there(l));
            }
        }
    }
    let moved = objects.len();
    for &(x, m) in &unit.inputs {
        let n = node(x);
        if (!m || holder.is_some() || closed || from_elsewhere || with_tools)
            && utensil(x)
            && n.states.is_empty()
            && !objects[..moved].contains(&n.label.as_str())
            && place.is_none_or(|p| p.1 != n.label)
        {
            objects.push(&n.label);
        }
    }
    let (objects, tools) = objects.split_at(moved);
    // sized for most sentences: one allocation
    let mut text = String::with_capacity(64);
    let after = push_verb(&mut text, &unit.motion);
    text.push(' ');
    push_list(&mut text, objects);
    text.push_str(after);
    if let Some((rel, c)) = place {
        let (into, rel) = match (rel, puts) {
            ("in", true) => ("into", "in"),
            ("on", true) => ("onto", "on"),
            (r, _) => (r, r),
        };
        text.push(' ');
        text.push_str(into);
        // a long list of what is there already says less than the container's name
        if (1..=2).contains(&settled.len()) {
            text.push(' ');
            push_list(&mut text, &settled);
            text.push(' ');
            text.push_str(rel);
        }
        for part in [" the ", c] {
            text.push_str(part);
        }
    }
    if !tools.is_empty() {
        text.push_str(" with ");
        push_list(&mut text, tools);
    }
    text.push('.');
    text
}
