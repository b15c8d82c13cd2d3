//! Table I of the paper: the case of an ingredient (its object and its state in the reference tree or
//! not), decided once, and how the tree's state is matched to the state asked for.

use super::*;

/// Table I: whether the query's object (or its equivalent) and its state are in the reference tree.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Case {
    /// Case 1: the object and the state are both in the tree.
    Found,
    /// Case 2: an equivalent object is, in the state asked for: substituted.
    EquivalentObject,
    /// Case 3: the object is, in another state: units bring it to the state.
    OtherState,
    /// Case 4: only an equivalent in another state, or nothing: substituted and brought to the state, or a
    /// branch from the universal FOON.
    EquivalentInOtherState,
}

impl Case {
    /// The case of an object whose tree label is `eq`, with a slot in the asked state or not.
    pub(super) fn of(o: &str, eq: &str, in_state: bool) -> Case {
        match (eq == o, in_state) {
            (true, true) => Case::Found,
            (false, true) => Case::EquivalentObject,
            (true, false) => Case::OtherState,
            (false, false) => Case::EquivalentInOtherState,
        }
    }

    /// Its number in Table I, as the plan reports it.
    pub(super) fn number(self) -> u8 {
        match self {
            Case::Found => 1,
            Case::EquivalentObject => 2,
            Case::OtherState => 3,
            Case::EquivalentInOtherState => 4,
        }
    }
}

/// "as a liquid", "ground": how an ingredient sold in category `c` comes.
pub(super) fn sold_words(c: Category) -> &'static str {
    if c == Category::Liquid {
        "as a liquid"
    } else {
        c.name()
    }
}

/// Cases 1–4 for an ingredient whose object is in the tree as `o` (`eq` in FOON; `slots`: the live
/// slots of `o`): its state is there (exactly or by category), or the tree is changed to reach it
/// (`restate`), once per object: the same food asked again in another state (onion chopped and sliced)
/// keeps the state it was first settled in (`settled`), so that its one progress line is right for one
/// of them rather than a mix of both.
#[allow(clippy::too_many_arguments)]
pub(super) fn settle_state<'kb>(
    ctx: &Context<'kb>,
    tree: &mut Tree<'kb>,
    eq: &str,
    o: &str,
    s: &str,
    slots: &[SlotId],
    settled: &mut HashMap<String, String>,
    w: &mut Work,
) {
    let sold = ctx.index.sold_as(eq);
    let in_state = best_state_slot(tree, slots, s, sold);
    let joining = in_state
        .is_none()
        .then(|| shaped_as_it_joins(tree, slots))
        .flatten()
        .filter(|&(_, st)| st == s)
        .map(|(motion, _)| motion);
    let state_ok = in_state.is_some()
        || joining.is_some()
        || shown_by_form(tree, known_as(ctx, o, eq), s, slots);
    w.case = Some(Case::of(o, eq, state_ok));
    if let Some(motion) = joining {
        w.reasons.push(format!(
            "state '{s}' given as it joins the dish: '{motion}'"
        ));
    }
    if category(s) == Category::Other && !s.is_empty() {
        w.reasons.push(format!(
            "state '{s}' is not in the state taxonomy: kept the tree's state"
        ));
    } else if let Some(x) = in_state.filter(|_| best_exact(tree, slots, s).is_none()) {
        let node = &tree.slots[x].node;
        let c = category(s);
        let as_sold = sold == Some(c) && !has_food_state(node);
        w.reasons
            .push(match node.physical_states().find(|p| akin(p, s)) {
                Some(same) => format!("state '{s}' matched by '{same}', a word for the same state"),
                None if as_sold => format!(
                    "state '{s}' matched by category ({}): '{eq}' comes {}",
                    c.name(),
                    sold_words(c)
                ),
                None => format!("state '{s}' matched by category ({})", c.name()),
            });
    }
    // the same name asked whole and prepared (an egg "whole raw" and "whipped") has one line through both:
    // the prepared state is reached from the whole one it starts in ("mixed" alone prepares nothing)
    let prepared =
        !category(s).is_starting() && (category(s) != Category::Mixed || kind(s).is_some());
    let first = settled
        .get(o)
        .filter(|f| !(prepared && category(f).is_starting()));
    if !state_ok {
        if let Some(first) = first {
            w.reasons.push(format!(
                "kept in the state '{first}' chosen for the same ingredient earlier"
            ));
        } else {
            match restate(ctx, tree, eq, o, s, slots) {
                Ok(reason) | Err(reason) => w.reasons.push(reason),
            }
        }
    }
    if first.is_none() {
        settled.insert(o.to_string(), s.to_string());
    }
    w.planned = true;
}

/// The motion and the state it leaves the food in (`motion_states.tsv`) of a unit that takes the food
/// into another and shapes it as it goes (peppercorns ground from the mill into the soup, cheese grated
/// over the dish): no node of the food is left to show that state.
pub(super) fn shaped_as_it_joins(tree: &Tree, slots: &[SlotId]) -> Option<(String, &'static str)> {
    let order = tree.order();
    let label = |x: SlotId| &tree.slots[x].node.label;
    slots.iter().find_map(|&x| {
        tree.consumers(x, &order).find_map(|u| {
            let unit = &tree.units[u];
            let into_another = unit.outputs.iter().all(|o| label(o.0) != label(x));
            let state = foods::leaves_in(&unit.motion).filter(|_| into_another)?;
            Some((unit.motion.to_string(), state))
        })
    })
}

/// Whether state `s` is the one `food`'s form shows it in, and the tree has it only in states its form is
/// never in (a cream cheese "block"): fitting the states to the form (`fit_states_to_form`) gives it.
pub(super) fn shown_by_form(tree: &Tree, food: &str, s: &str, slots: &[SlotId]) -> bool {
    let Some(form) = foods::form_of(food) else {
        return false;
    };
    form.state_when_none.as_deref() == Some(s)
        && slots.iter().all(|&x| {
            tree.slots[x]
                .node
                .physical_states()
                .filter(|st| is_food_state(st))
                .all(|st| foods::never_in(food, st))
        })
}

/// The case and status of an ingredient when modification is off (`in_state`: its slot in the state
/// asked for, see `best_state_slot`).
pub(super) fn judge_unmodified(
    tree: &Tree,
    o: &str,
    eq: &str,
    sim: f32,
    slots: &[SlotId],
    in_state: Option<SlotId>,
    w: &mut Work,
) {
    if slots.is_empty() {
        w.case = Some(Case::EquivalentInOtherState);
        w.reasons
            .push("not in the reference task tree (modification off)".to_string());
        return;
    }
    let slot = in_state;
    let state = state_text(&tree.slots[slot.unwrap_or(slots[0])].node);
    w.case = Some(Case::of(o, eq, slot.is_some()));
    w.matched = Some(Match {
        label: eq.into(),
        state,
        similarity: sim,
    });
    w.planned = true;
    if eq != o || slot.is_none() {
        w.reasons
            .push("used as the reference tree has it (modification off)".to_string());
    }
}

/// The state an ingredient has in the tree, given its label's live slots (`Tree::slots_with_label`,
/// not empty): that of its slot in the state `s` (see `best_state_slot`), else of the first.
pub(super) fn tree_state(
    tree: &Tree,
    slots: &[SlotId],
    s: &str,
    sold: Option<Category>,
) -> SmolStr {
    let slot = best_state_slot(tree, slots, s, sold).unwrap_or(slots[0]);
    state_text(&tree.slots[slot].node)
}

/// Of a label's live slots, the first in the state `s`.
pub(super) fn best_exact(tree: &Tree, slots: &[SlotId], s: &str) -> Option<SlotId> {
    slots
        .iter()
        .copied()
        .find(|&x| tree.slots[x].node.physical_states().any(|p| p == s))
}

/// Of a label's live slots, the first in a state akin to `s` (shredded for grated).
pub(super) fn best_akin(tree: &Tree, slots: &[SlotId], s: &str) -> Option<SlotId> {
    let k = kind(s)?;
    slots.iter().copied().find(|&x| {
        tree.slots[x]
            .node
            .physical_states()
            .any(|p| kind(p) == Some(k))
    })
}

/// Of a label's live slots, one in the state `s`: exactly, else in a state of its kind, else by category;
/// a starting state matches a leaf in a starting state; a node without food states matches a state of the
/// category its ingredient is sold in (`sold`: milk in a cup is liquid milk); a state outside the taxonomy
/// matches any.
pub(super) fn best_state_slot(
    tree: &Tree,
    slots: &[SlotId],
    s: &str,
    sold: Option<Category>,
) -> Option<SlotId> {
    if let Some(x) = best_exact(tree, slots, s).or_else(|| best_akin(tree, slots, s)) {
        return Some(x);
    }
    let c = category(s);
    if c == Category::Other {
        return slots.first().copied();
    }
    let mut slots = slots.iter().copied();
    let categories = |x: SlotId| tree.slots[x].node.physical_states().map(category);
    if c.is_starting() {
        return slots.find(|&x| {
            !tree.produced(x)
                && categories(x)
                    .filter(|&k| k != Category::Other)
                    .all(Category::is_starting)
        });
    }
    // a node in the state's category before one taken to be in it
    slots
        .clone()
        .find(|&x| categories(x).any(|k| k == c))
        .or_else(|| slots.find(|&x| sold == Some(c) && !has_food_state(&tree.slots[x].node)))
}
