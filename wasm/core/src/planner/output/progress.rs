//! Progress lines (section IV-A): each ingredient's states and locations and the motions between them,
//! followed into the mixture or dish it joins.

use super::*;

/// Where the progress lines look, found in one pass over the order rather than once per ingredient.
pub(super) struct Uses<'t> {
    /// The slots live units use, and the goal, ascending, with their labels (each line compares them
    /// all: read once here rather than through the slot's node every time).
    pub(super) live: Vec<(SlotId, &'t str)>,
    /// Per slot: made by a unit (an output that is not also its input).
    pub(super) made: Vec<bool>,
    /// Per slot: the position of the first unit using it (`usize::MAX` for none).
    pub(super) first_use: Vec<usize>,
}

impl<'t> Uses<'t> {
    pub(super) fn new(tree: &'t Tree, order: &[TUnitId]) -> Uses<'t> {
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

/// "in bowl": two words.
pub(super) fn spaced(first: &str, second: &str) -> SmolStr {
    format_smolstr!("{first} {second}")
}

pub(super) fn location(n: &ObjectNode) -> SmolStr {
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
/// (the batter poured into the pan and baked into the muffin). `food`: what the label stands for
/// (`foods::query_readings`: black pepper for "pepper — ground").
pub(super) fn progress_line<'t>(
    order: &[TUnitId],
    uses: &Uses,
    (label, food): (&str, &str),
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
        let line = line_from(order, uses, (label, food), start, relations);
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
    (label, food): (&str, &str),
    start: SlotId,
    relations: &mut Relations<'t>,
) -> ProgressLine {
    let tree = relations.tree;
    let mut walked = walk(order, uses, label, start, 0, relations);
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
        walked = walk(order, uses, product, x, pos + 1, relations);
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
    if !foods::shows_cooking(food) {
        unseen_cooking(&mut states);
    }
    if let Some(heated) = foods::state_once_heated(food) {
        melted(&mut states, heated);
    }
    carry_states(&mut states);
    ProgressLine {
        ingredient: label.into(),
        state: states,
        motion: motions,
        end_product: end_product.into(),
    }
}

/// The food's own states once it is heated (butter "cubed, hot" in the pan): `heated`, its form's state
/// then, beside the heat that made it ("melted, hot"); what it went into ("in omelette") is left as it is.
fn melted(states: &mut [ProgressState], heated: &str) {
    for s in states
        .iter_mut()
        .skip_while(|s| !s.physical_state.split(", ").any(is_heat))
        .filter(|s| !s.physical_state.starts_with("in "))
    {
        let heat = s.physical_state.split(", ").filter(|w| is_heat(w));
        let words: Vec<&str> = std::iter::once(heated).chain(heat).collect();
        s.physical_state = words.join(", ").into();
    }
}

/// Whether state word `w` says only that the food is hot ("hot", "warm", "heated"), not how it was cooked.
fn is_heat(w: &str) -> bool {
    category(w) == Category::Cooked && kind(w) == Some("heated")
}

/// The food's own states without the cooking of the vessel it sits in, for a food that does not show it
/// (salt in a pot of rice is not "partly cooked"; oil in a pan is still "hot"); what it went into ("in
/// rice, cooked") keeps it.
pub(super) fn unseen_cooking(states: &mut [ProgressState]) {
    let unseen = |w: &str| category(w) == Category::Cooked && !is_heat(w);
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
pub(super) fn carry_states(states: &mut [ProgressState]) {
    for i in 1..states.len() {
        let before = &states[i - 1].physical_state;
        if states[i].physical_state.is_empty() && !before.starts_with("in ") {
            states[i].physical_state = before.clone();
        }
    }
}

/// The unit after position `pos` that cooks the dish at slot `x` (the only units after the dish is made
/// are the dish's own), as its motion and the cooked dish's state.
pub(super) fn dish_cooked_after(
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
pub(super) fn inside(product: &str, state: ProgressState) -> ProgressState {
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
pub(super) struct Walked {
    pub(super) states: Vec<ProgressState>,
    pub(super) motions: Vec<SmolStr>,
    pub(super) into: Option<(usize, SlotId)>,
    /// `into` is a part the food was opened into (the white an egg was cracked into)
    pub(super) opened: bool,
}

/// The states of `label` from slot `start`, through the units of the order from position `from` on.
pub(super) fn walk<'t>(
    order: &[TUnitId],
    uses: &Uses,
    label: &str,
    start: SlotId,
    from: usize,
    relations: &mut Relations<'t>,
) -> Walked {
    let tree = relations.tree;
    let mut w = Walker {
        tree,
        order,
        uses,
        label,
        seen: vec![start],
        at: start,
        from,
        last_step: None,
        walked: Walked {
            states: vec![ProgressState {
                physical_state: state_text(&tree.slots[start].node),
                location: location(&tree.slots[start].node),
            }],
            motions: Vec::new(),
            into: None,
            opened: false,
        },
    };
    loop {
        // no unit before the first to use it takes it (one nothing takes leaves the search where it is,
        // for the vessel holding it)
        if uses.first_use[w.at] != usize::MAX {
            w.from = w.from.max(uses.first_use[w.at]);
        }
        let Some((pos, u, out)) = w.next_taker() else {
            if !w.take_up_vessel() {
                w.follow_vessel_contents();
                break;
            }
            continue;
        };
        w.last_step = Some((pos, u));
        w.walked.motions.push(tree.units[u].motion.as_ref().into());
        if let Some(o) = out {
            w.step_to(o, u, pos);
        } else if let Some(o) = w.entered(u, pos) {
            if !w.enter(o, u, pos, relations) {
                break;
            }
        } else {
            // a unit that takes it and gives nothing of it back (a mixer turned on with the bowl in
            // it): the next unit taking it goes on
            w.walked.motions.pop();
            w.from = pos + 1;
        }
    }
    w.walked
}

/// Where `walk` is: the slot it follows, the position in the order it searches from, and the line so far.
struct Walker<'a, 't> {
    tree: &'t Tree<'t>,
    order: &'a [TUnitId],
    uses: &'a Uses<'a>,
    label: &'a str,
    /// The slots it passed through.
    seen: Vec<SlotId>,
    at: SlotId,
    from: usize,
    /// The last unit that moved it, and its position.
    last_step: Option<(usize, TUnitId)>,
    walked: Walked,
}

impl<'t> Walker<'_, 't> {
    /// The next unit taking the food, its position, and the piece of the food it gives back (`None` when
    /// the food went into something else).
    fn next_taker(&self) -> Option<(usize, TUnitId, Option<SlotId>)> {
        let (tree, label, at) = (self.tree, self.label, self.at);
        let takers = self.order.iter().enumerate().skip(self.from);
        let takers: Vec<(usize, &TUnitId)> = takers
            .filter(|(_, &u)| tree.units[u].inputs.iter().any(|i| i.0 == at))
            .collect();
        // the same piece taken twice (flour poured into the dough's bowl and sprinkled on the table to
        // knead it on): the line follows it into a vessel, not onto a surface, wherever it comes first
        let into_vessel = |u: TUnitId| {
            tree.units[u].outputs.iter().any(|o| {
                let node = &tree.slots[o.0].node;
                node.label == label && node.states.iter().any(|s| s.name == "in")
            })
        };
        let taker = takers
            .iter()
            .find(|(_, &u)| takers.len() > 1 && into_vessel(u))
            .or(takers.first());
        taker.map(|&(pos, &u)| {
            let unit = &tree.units[u];
            // of two pieces of it (the stem cut off a broccoli, the florets), the one a later unit takes
            let pieces = || {
                unit.outputs
                    .iter()
                    .map(|o| o.0)
                    .filter(|&o| tree.slots[o].node.label == label && !self.seen.contains(&o))
            };
            // what goes into the unit making the dish goes into the dish (FOON's greek salad is poured
            // out beside the salad it was made of)
            let makes_dish = unit.outputs.iter().any(|o| o.0 == tree.goal);
            // a piece nothing uses again beside a food made that lists it (the lemon grated beside its
            // zest, the lime juice poured into the pot beside the rice it is in): the line goes on in that
            let goes_into_food = || {
                unit.outputs.iter().any(|o| {
                    let slot = &tree.slots[o.0];
                    !slot.utensil && slot.node.label != label && names_in_a_list(&slot.node, label)
                })
            };
            let out = pieces()
                .find(|&o| self.uses.first_use[o] != usize::MAX)
                .or_else(|| pieces().next().filter(|_| !goes_into_food()))
                .filter(|_| !makes_dish);
            (pos, u, out)
        })
    }

    /// FOON lists a food in a bowl both as a node of its own and among the bowl's contents: when no unit
    /// takes the node, the units take the bowl; and FOON takes a vessel up again as another node of it
    /// (the pot the garlic was fried in, later the rice's): that node goes on. Whether there was one.
    fn take_up_vessel(&mut self) -> bool {
        let (tree, uses, label) = (self.tree, self.uses, self.label);
        let unseen = |v: &SlotId| !self.seen.contains(v);
        let vessel = vessel_holding(tree, uses, self.at, label)
            .filter(unseen)
            .or_else(|| vessel_again(tree, uses, self.at, label, self.from).filter(unseen));
        if let Some(v) = vessel {
            self.seen.push(v);
            self.at = v;
        }
        vessel.is_some()
    }

    /// Its last node sits in a vessel: what the vessel's contents become (the vessel the unit that last
    /// moved it, or made it, put it in, though FOON's vessel may not list it).
    fn follow_vessel_contents(&mut self) {
        let (tree, order, label, at) = (self.tree, self.order, self.label, self.at);
        let touched = self.last_step.or_else(|| {
            let u = tree.producer.get(at).copied().flatten()?;
            Some((order.iter().position(|&v| v == u)?, u))
        });
        let Some((pos, u)) = touched else {
            return;
        };
        let container = tree.slots[at].node.container();
        let into = tree.units[u]
            .outputs
            .iter()
            .map(|o| o.0)
            .filter(|&x| tree.slots[x].utensil)
            .find(|&x| {
                let n = &tree.slots[x].node;
                n.contents().any(|i| i == label) || container == Some(n.label.as_str())
            })
            .and_then(|x| product_of(tree, order, pos, x, label));
        self.walked.into = into;
        // the food made of the vessel's contents: the line says so
        if let Some((at, x)) = into {
            self.walked
                .motions
                .push(tree.units[order[at]].motion.as_ref().into());
            self.walked.states.push(ProgressState {
                physical_state: spaced("in", &tree.slots[x].node.label),
                location: location(&tree.slots[x].node),
            });
        }
    }

    /// Unit `u` at `pos` gave back `o`, a piece of the food: the food is there now.
    fn step_to(&mut self, o: SlotId, u: TUnitId, pos: usize) {
        let tree = self.tree;
        self.seen.push(o);
        let before = self.walked.states.last();
        let state = state_after(
            self.label,
            &tree.units[u].motion,
            &tree.slots[o].node,
            before.map_or("", |s| s.physical_state.as_str()),
        );
        self.walked.states.push(ProgressState {
            physical_state: state,
            location: location(&tree.slots[o].node),
        });
        self.at = o;
        self.from = pos + 1;
    }

    /// What the food went into at unit `u`: what lists it (a food made of it), else a new food (the soup
    /// simmered into tomato soup, though FOON's pot still lists the soup), else a food that took it in or
    /// the vessel holding it; not another ingredient moved along. `pos`: the unit's place in the order.
    fn entered(&self, u: TUnitId, pos: usize) -> Option<SlotId> {
        let (tree, label) = (self.tree, self.label);
        let outputs = &tree.units[u].outputs;
        let inputs = &tree.units[u].inputs;
        let lists = |food: bool| {
            outputs.iter().find(|o| {
                let slot = &tree.slots[o.0];
                slot.utensil != food && names_in_a_list(&slot.node, label)
            })
        };
        // not one that was there already, as a node or on the surface it is still on (the corn left on
        // the board its kernels were shaved on)
        let fresh = || {
            outputs.iter().find(|o| {
                let n = &tree.slots[o.0].node;
                let on = n.states.iter().find(|s| s.name == "on").and(n.container());
                let stayed = |before: &ObjectNode| {
                    on == Some(before.label.as_str()) && before.contents().any(|c| c == n.label)
                };
                !tree.slots[o.0].utensil
                    && !inputs.iter().any(|i| {
                        let before = &tree.slots[i.0].node;
                        before.label == n.label || stayed(before)
                    })
            })
        };
        // a food that took more in (the sauce stirred into the fried rice)
        let grew = || {
            outputs.iter().find(|o| {
                let n = &tree.slots[o.0].node;
                !tree.slots[o.0].utensil
                    && inputs.iter().any(|i| {
                        let before = &tree.slots[i.0].node;
                        before.label == n.label && n.contents().count() > before.contents().count()
                    })
            })
        };
        // followed in a vessel (the onion in the pot the broth is poured into), it stays in the vessel;
        // the food itself taken in by another goes with that one
        let in_vessel = tree.slots[self.at].utensil;
        let dish = || outputs.iter().find(|o| o.0 == tree.goal);
        // a new food beside the vessel that still holds it (an egg poached in the broth): it stays in
        // the vessel when a food is made of the vessel's contents later
        let beside = || {
            let vessel = lists(false).filter(|_| in_vessel)?;
            product_of(tree, self.order, pos, vessel.0, label).map(|_| vessel)
        };
        let entered = dish()
            .or_else(|| lists(true))
            .or_else(beside)
            .or_else(fresh)
            .or_else(|| {
                if in_vessel {
                    lists(false).or_else(grew)
                } else {
                    grew().or_else(|| lists(false))
                }
            });
        entered.map(|o| o.0)
    }

    /// The food went into `o` at unit `u` (position `pos`): its state there. Whether the walk goes on
    /// (in a vessel: what is done to the vessel's contents is done to it).
    fn enter(&mut self, o: SlotId, u: TUnitId, pos: usize, relations: &mut Relations<'t>) -> bool {
        let tree = self.tree;
        let state = self.state_in(o, u, relations);
        let cooks = crate::vocab::foods::cooks(&tree.units[u].motion);
        if self.walked.states.last() == Some(&state) && !cooks {
            // already there (FOON lists what a bowl holds among the inputs of the next thing added to
            // it): no step of its own, unless it cooks
            self.walked.motions.pop();
        } else {
            self.walked.states.push(state);
        }
        if tree.slots[o].utensil {
            // in the vessel the unit took, where FOON uses that again rather than its output
            self.seen.push(o);
            if self.uses.first_use[o] != usize::MAX || !tree.slots[self.at].utensil {
                self.at = o;
            }
            self.from = pos + 1;
            return true;
        }
        self.walked.into = product_of(tree, self.order, pos, o, self.label);
        false
    }

    /// The food's state in `o`, which unit `u` put it into.
    fn state_in(&mut self, o: SlotId, u: TUnitId, relations: &mut Relations<'t>) -> ProgressState {
        let tree = self.tree;
        let n = &tree.slots[o].node;
        if tree.slots[o].utensil {
            // put in a vessel as it was: the same state, a new place; cooked there when the vessel's
            // contents are
            let rel = relations.to(&n.label);
            let states = &self.walked.states;
            let before = &states[states.len() - 1].physical_state;
            let motion = &tree.units[u].motion;
            let before = prepared_by(
                self.label,
                motion,
                reshaped_by(motion, before, before.clone()),
            );
            ProgressState {
                physical_state: with_vessel_cooking(&before, n),
                location: spaced(rel, &n.label),
            }
        } else if let Some(state) = opened_into(tree, u, self.label) {
            // cracked into its parts (white and yolk): still the food itself
            self.walked.opened = true;
            ProgressState {
                physical_state: state.into(),
                location: location(n),
            }
        } else {
            ProgressState {
                physical_state: spaced("in", &n.label),
                location: location(n),
            }
        }
    }
}

/// The state of `label` at `node`, made by `motion`: when the motion is the food's first preparation
/// ("crack" for an egg's "cracked"), that state, in place of the whole one FOON may keep ("whole" in the
/// bowl it was cracked into).
pub(super) fn state_after(label: &str, motion: &str, node: &ObjectNode, before: &str) -> SmolStr {
    prepared_by(label, motion, reshaped_by(motion, before, state_text(node)))
}

/// State text `text` of `label` after `motion`: the food's first preparation when the motion is it
/// (`state_after`).
pub(super) fn prepared_by(label: &str, motion: &str, text: SmolStr) -> SmolStr {
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
pub(super) fn is_part(product: &str, label: &str) -> bool {
    product
        .strip_prefix(label)
        .is_some_and(|rest| rest.starts_with(' '))
}

/// The state of `label` when unit `u` opens it into two or more parts of it (an egg cracked into white
/// and yolk): the preparation the food knowledge names for it ("cracked"), if any.
pub(super) fn opened_into(tree: &Tree, u: TUnitId, label: &str) -> Option<&'static str> {
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
pub(super) fn names_in_a_list(n: &ObjectNode, label: &str) -> bool {
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
pub(super) fn with_vessel_cooking(before: &SmolStr, v: &ObjectNode) -> SmolStr {
    // a food cooked before it went in is not made "partly cooked" or "hot" by the pot (rice toasted
    // first still is)
    let words = || before.split(", ");
    let cooked_before = words().any(|w| category(w) == Category::Cooked);
    let adds = |s: &str| {
        category(s) == Category::Cooked
            && !words().any(|w| w == s || w == "cooked")
            && !(cooked_before && is_heat(s))
    };
    let cooked = v.physical_states().find(|s| adds(s));
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
pub(super) fn vessel_holding(tree: &Tree, uses: &Uses, at: SlotId, label: &str) -> Option<SlotId> {
    let container = tree.slots[at].node.container()?;
    first_vessel_listing(tree, uses, container, label, 0, at)
}

/// A later node of vessel `at` (first used at or after position `from`) that lists `label` among its
/// contents, when `at` is a vessel holding it.
fn vessel_again(tree: &Tree, uses: &Uses, at: SlotId, label: &str, from: usize) -> Option<SlotId> {
    let vessel = &tree.slots[at];
    if !vessel.utensil || !vessel.node.contents().any(|i| i == label) {
        return None;
    }
    first_vessel_listing(tree, uses, &vessel.node.label, label, from, at)
}

/// The first used node of the vessel named `vessel`, other than `not`, first used at or after position
/// `from`, that lists `label` among its contents.
fn first_vessel_listing(
    tree: &Tree,
    uses: &Uses,
    vessel: &str,
    label: &str,
    from: usize,
    not: SlotId,
) -> Option<SlotId> {
    uses.live
        .iter()
        .map(|&(x, _)| x)
        .filter(|&x| {
            let slot = &tree.slots[x];
            x != not
                && slot.utensil
                && slot.node.label == vessel
                && uses.first_use[x] != usize::MAX
                && uses.first_use[x] >= from
                && slot.node.contents().any(|i| i == label)
        })
        .min_by_key(|&x| uses.first_use[x])
}

/// The product an ingredient goes into (section IV-A): the first food node listing it among its
/// contents, following the vessel it was put in (flour in the bowl → the batter mixed in that bowl).
/// Returns the product's position in the order and slot.
pub(super) fn product_of(
    tree: &Tree,
    order: &[TUnitId],
    pos: usize,
    entered: SlotId,
    label: &str,
) -> Option<(usize, SlotId)> {
    let lists = |x: SlotId| tree.slots[x].node.contents().any(|i| i == label);
    let food = |x: SlotId| !tree.slots[x].utensil;
    if food(entered) {
        return Some((pos, entered));
    }
    // a vessel holding it: the first food made from that vessel's contents
    let mut vessels = vec![entered];
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
