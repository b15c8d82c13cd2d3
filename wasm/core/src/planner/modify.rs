//! Section III-C: modification of the reference task tree for the query's ingredients (Table I),
//! branches for ingredients from elsewhere in FOON, and pruning of what was not asked for.

use super::index::{Picks, PlannerIndex};
use super::retrieve::{retrieve, retrieve_within, Retrieved};
use super::states::{
    akin, category, food_state_category, has_food_state, is_food_state, kind, state_text, Category,
};
use super::transitions::Verdict;
use super::tree::{dedup_slots, map_contents, rename_item, retain_contents, SlotId, TUnitId, Tree};
use crate::foods;
use crate::kb::KnowledgeBase;
use crate::model::{NodeId, ObjectNode, State, UnitId};
use crate::plan::{Alternative, IngredientOutcome, Match, Origin, Query, Status};
use crate::similarity::Similarity;
use crate::taxonomy::{dish_class_name, is_transfer_motion, is_utensil};
use rustc_hash::{FxHashMap as HashMap, FxHashSet as HashSet};
use smol_str::SmolStr;
use std::borrow::Cow;
use std::cell::RefCell;
use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write;

pub(crate) struct Context<'a> {
    pub kb: &'a KnowledgeBase,
    pub index: &'a PlannerIndex,
    pub sim: &'a dyn Similarity,
    pub class: Option<u32>,
    pub overrides: &'a BTreeMap<String, String>,
    /// The reference recipe's subgraph id.
    pub goal_subgraph: Option<u32>,
    pub scorer: &'a super::score::Scorer<'a>,
    pub trace: &'a super::explain::Recorder,
    /// Asked names the food knowledge reads as another food by their state (basil asked dried is dried
    /// basil), from `foods::query_readings`.
    pub readings: HashMap<String, &'static str>,
}

/// The name the food knowledge judges the asked food `o` by: the food its state says it is, else `o`
/// when the knowledge knows it, else its equivalent `eq`.
fn known_as<'a>(ctx: &'a Context, o: &'a str, eq: &'a str) -> &'a str {
    match ctx.readings.get(o) {
        Some(r) => r,
        None if foods::knows(o) => o,
        None => eq,
    }
}

/// Food states of a node (not its place, contents or an appliance's condition).
pub(crate) fn food_states(node: &ObjectNode) -> Vec<&str> {
    node.physical_states()
        .filter(|s| is_food_state(s))
        .collect()
}

/// `node_category`, except that a node saying nothing of its food is in the category its ingredient is
/// sold in (`PlannerIndex::sold_as`: milk in a cup is liquid, flour in a bag ground).
fn food_category(ctx: &Context, node: &ObjectNode) -> Category {
    food_state_category(node)
        .unwrap_or_else(|| ctx.index.sold_as(&node.label).unwrap_or(Category::Whole))
}

/// "as a liquid", "ground": how an ingredient sold in category `c` comes.
fn sold_words(c: Category) -> &'static str {
    if c == Category::Liquid {
        "as a liquid"
    } else {
        c.name()
    }
}

const SEPARATION: &[Category] = &[
    Category::Trimmed,
    Category::Cut,
    Category::FinelyCut,
    Category::Ground,
];

/// Motions that cannot take more ingredients (a robot cuts one item at a time; what goes into the oven
/// or under the grill is already assembled).
const SINGLE_ITEM_WORDS: &[&str] = &[
    "slice",
    "cut",
    "chop",
    "dice",
    "mince",
    "peel",
    "crack",
    "grate",
    "grind",
    "mash",
    "crush",
    "julienne",
    "core",
    "squeeze",
    "wash",
    "rinse",
    "open",
    "turn",
    "preheat",
    "detach",
    "attach",
    "remove",
    "drain",
    "shave",
    "zest",
    "knead",
    "roll",
    "shape",
    "wrap",
    "unwrap",
    "throw",
    "take out",
    "tear",
    "flip",
    "cover",
    "bake",
    "roast",
    "grill",
    "toast",
    "broil",
    "put inside",
    "insert",
    "microwave",
];

fn accepts_more(motion: &str) -> bool {
    !SINGLE_ITEM_WORDS.iter().any(|w| motion.contains(w))
}

/// How new ingredients join a dish of each class (first preferred): drinks are poured, salads mixed...
fn dish_pattern(class: Option<u32>) -> &'static [&'static str] {
    match class.and_then(dish_class_name) {
        Some("drinks") => &["pour", "blend", "add", "stir", "mix", "shake"],
        Some("salad") => &["mix", "add", "pick-and-place", "pour", "sprinkle", "stir"],
        Some("soup") | Some("sauce") => &["pour", "add", "stir", "mix", "sprinkle"],
        Some("cake") | Some("muffin") | Some("cookie") | Some("bread") | Some("pie")
        | Some("dessert") => &["mix", "pour", "add", "stir", "beat", "sprinkle", "fold"],
        Some("omelette") => &["beat", "mix", "pour", "add", "sprinkle", "stir"],
        Some("rice") | Some("noodle") | Some("pasta") | Some("stir-fry") => {
            &["add", "stir", "pour", "mix", "sprinkle"]
        }
        _ => &["mix", "add", "pour", "stir", "sprinkle"],
    }
}

/// Whether a motion takes more ingredients, and its rank in the dish class's pattern (see
/// `attach_point`). Remembered across plans, per class: every attachment asks it of every unit.
fn motion_fit(class: Option<u32>, motion: &str) -> (bool, usize) {
    type Fits = HashMap<String, (bool, usize)>;
    thread_local! {
        static FIT: RefCell<HashMap<Option<u32>, Fits>> = RefCell::new(HashMap::default());
    }
    if let Some(fit) = FIT.with(|m| m.borrow().get(&class)?.get(motion).copied()) {
        return fit;
    }
    let pattern = dish_pattern(class);
    let pref = pattern
        .iter()
        .position(|m| motion.contains(m))
        .unwrap_or(pattern.len());
    let fit = (accepts_more(motion), pref);
    FIT.with(|m| {
        let mut m = m.borrow_mut();
        let of_class = m.entry(class).or_default();
        // a hostile knowledge base may have any number of motions
        if of_class.len() >= MAX_REMEMBERED_MOTIONS {
            of_class.clear();
        }
        of_class.insert(motion.to_string(), fit);
    });
    fit
}

const MAX_REMEMBERED_MOTIONS: usize = 4096;

/// What happened to one ingredient while it was being planned.
struct Work {
    case: Option<u8>,
    matched: Option<Match>,
    alternatives: Vec<Alternative>,
    low_confidence: bool,
    overridden: bool,
    planned: bool,
    reasons: Vec<String>,
    /// The label the ingredient has in the final tree.
    label: String,
}

pub(crate) fn modify<'kb>(
    ctx: &Context<'kb>,
    tree: &mut Tree<'kb>,
    query: &Query,
    enabled: bool,
    notes: &mut Vec<String>,
) -> (Vec<IngredientOutcome>, Vec<String>) {
    // names are short: kept inline, not allocated
    let reference_labels: Vec<SmolStr> = tree
        .ingredient_labels()
        .into_iter()
        .map(SmolStr::new)
        .collect();
    let requested: HashSet<&str> = query
        .ingredients
        .iter()
        .map(|i| i.object.as_str())
        .collect();
    let mut claimed: HashSet<String> = HashSet::default();
    // the state each object was first settled in: a name asked twice keeps the first (its one line)
    let mut settled: HashMap<String, String> = HashMap::default();
    let mut works: Vec<Work> = Vec::with_capacity(query.ingredients.len());
    // ingredients to bring from elsewhere in FOON: (work index, equivalent, state)
    let mut pending: Vec<(usize, String, String)> = Vec::new();
    for ing in &query.ingredients {
        let (o, s) = (ing.object.as_str(), ing.state.as_str());
        let mut w = Work {
            case: None,
            matched: None,
            alternatives: Vec::new(),
            low_confidence: false,
            overridden: false,
            planned: false,
            reasons: Vec::new(),
            label: o.to_string(),
        };
        let read = read_as(ctx, o, s);
        if let Some(r) = read {
            w.reasons.push(format!("'{o}' {s} read as '{r}'"));
        }
        let name = read.unwrap_or(o);
        let Some((eq, sim)) = equivalent(ctx, o, name, &reference_labels, &mut w) else {
            works.push(w);
            continue;
        };
        let s = planned_state(ctx, o, &eq, s);
        w.low_confidence = eq != o && ctx.sim.low_confidence(name, &eq, sim);
        let slots = tree.slots_with_label(&eq);
        if !enabled {
            let in_state = best_state_slot(tree, &slots, s, ctx.index.sold_as(&eq));
            judge_unmodified(tree, o, &eq, sim, &slots, in_state, &mut w);
            works.push(w);
            continue;
        }
        if slots.is_empty() {
            // case 4 from elsewhere in FOON (or an exact FOON label the reference tree lacks): attached
            // after pruning, so that it joins a unit that stays
            pending.push((works.len(), eq.clone(), s.to_string()));
            claimed.insert(eq.clone());
            w.matched = Some(Match {
                label: eq.as_str().into(),
                state: SmolStr::default(),
                similarity: sim,
            });
            works.push(w);
            continue;
        }
        // the equivalent is in the tree: substitute (cases 2, 4) or keep (cases 1, 3)
        w.matched = Some(Match {
            label: eq.as_str().into(),
            state: tree_state(tree, &slots, s, ctx.index.sold_as(&eq)),
            similarity: sim,
        });
        if eq != o {
            if requested.contains(eq.as_str()) || claimed.contains(&eq) {
                match copy_branch(tree, &eq, o) {
                    Some(_) => w.reasons.push(format!(
                        "'{eq}' is also needed: its branch was copied for '{o}'"
                    )),
                    None => {
                        // no branch of its own to copy: one from elsewhere in FOON, after pruning
                        w.reasons.push(format!(
                            "'{eq}' is also needed and has no branch of its own to copy"
                        ));
                        pending.push((works.len(), eq.clone(), s.to_string()));
                        works.push(w);
                        continue;
                    }
                }
            } else {
                tree.rename_everywhere(&eq, o);
                w.reasons.push(format!("'{eq}' substituted with '{o}'"));
            }
            claimed.insert(eq.clone());
        }
        claimed.insert(o.to_string());
        // renaming or copying gave `o` its slots; else they are the ones found for `eq`
        let slots = if eq == o {
            slots
        } else {
            tree.slots_with_label(o)
        };
        settle_state(ctx, tree, &eq, o, s, &slots, &mut settled, &mut w);
        w.planned = true;
        works.push(w);
    }

    let mut removed = Vec::new();
    let any_planned = works.iter().any(|w| w.planned) || !pending.is_empty();
    if enabled && !any_planned {
        notes.push(
            "no ingredient of the query could be planned: the reference task tree is kept unpruned"
                .to_string(),
        );
    } else if enabled {
        let keep: BTreeSet<String> = works
            .iter()
            .filter(|w| w.planned)
            .map(|w| w.label.clone())
            .collect();
        ctx.trace.record(|t| t.before_pruning(tree));
        removed = prune(tree, &keep, &requested);
        tree.drop_unneeded();
        ctx.trace.record(|t| t.pruned_from(tree, &removed));
        let present = tree.ingredient_labels();
        // an asked-for ingredient whose units served only pruned ones (butter spread on the bread that
        // was not asked for) comes back as a branch of its own, like a case-4 ingredient
        for (i, w) in works.iter().enumerate() {
            if w.planned && present.binary_search(&w.label.as_str()).is_err() {
                let eq = w
                    .matched
                    .as_ref()
                    .map_or(w.label.clone(), |m| m.label.to_string());
                let s = planned_state(ctx, &w.label, &eq, &query.ingredients[i].state);
                pending.push((i, eq, s.to_string()));
            }
        }
        pending.sort_by_key(|p| p.0);
        for (i, eq, s) in pending {
            let w = &mut works[i];
            let o = query.ingredients[i].object.as_str();
            let lost = w.planned;
            let slots = tree.slots_with_label(o);
            if !lost && !slots.is_empty() {
                // an earlier ingredient of the same name brought it: one branch serves both
                if let Some(m) = w.matched.as_mut() {
                    m.state = tree_state(tree, &slots, &s, ctx.index.sold_as(&eq));
                }
                settle_state(ctx, tree, &eq, o, &s, &slots, &mut settled, w);
                continue;
            }
            // a case-2 substitute was renamed in the tree already: its branch comes from `eq` again
            match add_branch(ctx, tree, &eq, o, &s) {
                Ok((state, reason)) => {
                    settled.entry(o.to_string()).or_insert_with(|| s.clone());
                    if lost {
                        w.reasons.push(format!(
                            "its units went with the pruned ingredients: {reason}"
                        ));
                    } else {
                        w.case = Some(4);
                        if let Some(m) = w.matched.as_mut() {
                            m.state = state;
                        }
                        w.planned = true;
                        w.reasons.push(reason);
                    }
                }
                Err(reason) => {
                    if lost {
                        w.planned = false;
                        w.reasons.push(format!(
                            "its units went with the pruned ingredients and it could not be added again: {reason}"
                        ));
                    } else {
                        w.matched = None;
                        w.reasons.push(reason);
                    }
                }
            }
        }
        for w in works.iter_mut().filter(|w| w.planned) {
            let eq = w
                .matched
                .as_ref()
                .map_or(w.label.as_str(), |m| m.label.as_str());
            if let Some(reason) = prepare_kept(ctx, tree, &w.label, eq) {
                w.reasons.push(reason);
            }
            let given = trim_first(ctx, tree, &w.label, eq);
            if !given.is_empty() {
                w.reasons.push(format!(
                    "{} before it is used, as a cook would",
                    given.join(", then ")
                ));
            }
            fit_states_to_form(ctx, tree, &w.label);
        }
        cook_dish(ctx, tree, notes);
    } else {
        notes.push("modification off: the reference task tree as retrieved".to_string());
    }
    let outcomes = query
        .ingredients
        .iter()
        .zip(works)
        .map(|(ing, w)| IngredientOutcome {
            object: ing.object.as_str().into(),
            state: ing.state.as_str().into(),
            case: w.case,
            matched: w.matched,
            alternatives: w.alternatives,
            low_confidence: w.low_confidence,
            overridden: w.overridden,
            status: if w.planned {
                Status::Planned
            } else {
                Status::Unplannable
            },
            reason: if w.reasons.is_empty() {
                None
            } else {
                Some(w.reasons.join("; "))
            },
        })
        .collect();
    (outcomes, removed)
}

/// Cases 1–4 for an ingredient whose object is in the tree as `o` (`eq` in FOON; `slots`: the live
/// slots of `o`): its state is there (exactly or by category), or the tree is changed to reach it
/// (`restate`), once per object: the same name asked again keeps the state it was first settled in
/// (`settled`), so that its one progress line is right for one of them rather than a mix of both.
#[allow(clippy::too_many_arguments)]
fn settle_state<'kb>(
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
    let state_ok = in_state.is_some() || shown_by_form(tree, known_as(ctx, o, eq), s, slots);
    w.case = Some(match (eq == o, state_ok) {
        (true, true) => 1,
        (false, true) => 2,
        (true, false) => 3,
        (false, false) => 4,
    });
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
    if !state_ok {
        if let Some(first) = settled.get(o) {
            w.reasons.push(format!(
                "kept in the state '{first}' chosen for the same ingredient earlier"
            ));
        } else {
            match restate(ctx, tree, eq, o, s, slots) {
                Ok(reason) | Err(reason) => w.reasons.push(reason),
            }
        }
    }
    settled
        .entry(o.to_string())
        .or_insert_with(|| s.to_string());
    w.planned = true;
}

/// Whether state `s` is the one `food`'s form shows it in, and the tree has it only in states its form is
/// never in (a cream cheese "block"): fitting the states to the form (`fit_states_to_form`) gives it.
fn shown_by_form(tree: &Tree, food: &str, s: &str, slots: &[SlotId]) -> bool {
    let Some(form) = foods::form_of(food) else {
        return false;
    };
    form.state_when_none.as_deref() == Some(s)
        && slots.iter().all(|&x| {
            tree.slots[x]
                .node
                .physical_states()
                .filter(|st| is_food_state(st))
                .all(|st| form.never_in.iter().any(|w| w == st))
        })
}

/// The food an ambiguous name is looked up as, by its state (pepper diced: bell pepper), when the
/// knowledge base has it or something like it and the user has not overridden the name.
fn read_as(ctx: &Context, o: &str, s: &str) -> Option<&'static str> {
    let r = foods::reading(o, s).filter(|&r| r != o && !ctx.overrides.contains_key(o))?;
    let known = ctx.index.is_label(r)
        || ctx
            .sim
            .rank_in_set(r, ctx.index.id, &ctx.index.ingredient_labels, 1)
            .first()
            .is_some_and(|(_, sim)| ctx.sim.accepts(*sim));
    known.then_some(r)
}

/// The equivalent of `o` (looked up as `name`, the food it is read as): an override, itself when it is a
/// FOON label, else the most similar label of the reference tree, else of the whole knowledge base. Fills
/// the alternatives; `None` when unplannable.
fn equivalent(
    ctx: &Context,
    o: &str,
    name: &str,
    tree_labels: &[SmolStr],
    w: &mut Work,
) -> Option<(String, f32)> {
    let ranked = ctx
        .sim
        .rank_in_set(name, ctx.index.id, &ctx.index.ingredient_labels, 6);
    // a name with no likeness at all (similarity 0, as exact matching gives every other name) is no
    // alternative and no closest name
    let alternatives = |eq: &str| -> Vec<Alternative> {
        ranked
            .iter()
            .filter(|(l, s)| l != eq && l != o && *s > 0.0)
            .take(5)
            .map(|(l, s)| Alternative {
                label: l.as_str().into(),
                similarity: *s,
            })
            .collect()
    };
    if let Some(v) = ctx.overrides.get(o) {
        w.overridden = true;
        if !ctx.index.is_label(v) || is_utensil(v) {
            w.alternatives = alternatives("");
            w.reasons.push(format!(
                "override '{v}' is not an ingredient of the knowledge base"
            ));
            return None;
        }
        let sim = if v == o {
            1.0
        } else {
            ctx.sim.similarity(o, v)
        };
        w.alternatives = alternatives(v);
        return Some((v.clone(), sim));
    }
    // a name FOON gives a utensil or container (a cooking spray holds the oil) is planned as the
    // ingredient it clearly holds, else only as the one the user picks from the alternatives offered
    if is_utensil(o) {
        let held = ranked
            .first()
            .filter(|(l, s)| ctx.sim.accepts(*s) && !ctx.sim.low_confidence(name, l, *s));
        if let Some((label, sim)) = held {
            w.alternatives = alternatives(label);
            w.reasons.push(format!(
                "'{o}' is a container in FOON: planned as the ingredient it holds, '{label}'"
            ));
            return Some((label.clone(), *sim));
        }
        w.alternatives = alternatives("");
        w.reasons.push(format!(
            "'{o}' is a utensil or container in FOON, not an ingredient: pick the ingredient it stands for (an override) to plan it"
        ));
        return None;
    }
    if ctx.index.is_label(name) {
        // (a reading is the food itself, named more exactly)
        w.alternatives = alternatives(name);
        return Some((name.to_string(), 1.0));
    }
    let tree_refs: Vec<&str> = tree_labels.iter().map(SmolStr::as_str).collect();
    let in_tree = ctx.sim.rank(name, &tree_refs, 1).into_iter().next();
    let in_kb = ranked.first().cloned();
    ctx.trace
        .record(|t| t.equivalents(name, in_tree.as_ref(), in_kb.as_ref()));
    let pick = match (in_tree, in_kb) {
        (Some(t), k) if ctx.sim.accepts(t.1) && !ctx.sim.low_confidence(name, &t.0, t.1) => {
            Some(t).or(k)
        }
        (t, Some(k)) if ctx.sim.accepts(k.1) && t.as_ref().is_none_or(|t| k.1 > t.1) => Some(k),
        (Some(t), _) if ctx.sim.accepts(t.1) => Some(t),
        _ => None,
    };
    match pick {
        Some((label, sim)) => {
            w.alternatives = alternatives(&label);
            if !tree_labels.iter().any(|l| *l == label) {
                w.reasons
                    .push(format!("equivalent '{label}' found in the universal FOON"));
            }
            Some((label, sim))
        }
        None => {
            w.alternatives = alternatives("");
            w.reasons.push(format!(
                "no equivalent of '{name}' in the knowledge base{}",
                ranked
                    .first()
                    .filter(|(_, s)| *s > 0.0)
                    .map(|(l, s)| format!(" (closest: '{l}', {s:.2})"))
                    .unwrap_or_default()
            ));
            None
        }
    }
}

/// The case and status of an ingredient when modification is off (`in_state`: its slot in the state
/// asked for, see `best_state_slot`).
fn judge_unmodified(
    tree: &Tree,
    o: &str,
    eq: &str,
    sim: f32,
    slots: &[SlotId],
    in_state: Option<SlotId>,
    w: &mut Work,
) {
    if slots.is_empty() {
        w.case = Some(4);
        w.reasons
            .push("not in the reference task tree (modification off)".to_string());
        return;
    }
    let slot = in_state;
    let state = state_text(&tree.slots[slot.unwrap_or(slots[0])].node);
    w.case = Some(match (eq == o, slot.is_some()) {
        (true, true) => 1,
        (false, true) => 2,
        (true, false) => 3,
        (false, false) => 4,
    });
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
fn tree_state(tree: &Tree, slots: &[SlotId], s: &str, sold: Option<Category>) -> SmolStr {
    let slot = best_state_slot(tree, slots, s, sold).unwrap_or(slots[0]);
    state_text(&tree.slots[slot].node)
}

/// Of a label's live slots, the first in the state `s`.
fn best_exact(tree: &Tree, slots: &[SlotId], s: &str) -> Option<SlotId> {
    slots
        .iter()
        .copied()
        .find(|&x| tree.slots[x].node.physical_states().any(|p| p == s))
}

/// Of a label's live slots, the first in a state akin to `s` (shredded for grated).
fn best_akin(tree: &Tree, slots: &[SlotId], s: &str) -> Option<SlotId> {
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
fn best_state_slot(
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

/// Live slots of `label` downstream of the given units (through units that pass the object on).
fn downstream(tree: &Tree, start: Vec<TUnitId>, label: &str, order: &[TUnitId]) -> Vec<SlotId> {
    let mut out = Vec::new();
    let mut seen_units: HashSet<TUnitId> = HashSet::default();
    let mut seen_slots: HashSet<SlotId> = HashSet::default();
    let mut work = start;
    while let Some(u) = work.pop() {
        if !seen_units.insert(u) {
            continue;
        }
        for &(x, _) in &tree.units[u].outputs {
            if tree.slots[x].node.label == label && seen_slots.insert(x) {
                out.push(x);
                work.extend(tree.consumers(x, order));
            }
        }
    }
    out
}

/// Replaces food states in a node (`old` → `new`; when `old` is empty, `new` is added).
fn replace_states(node: &ObjectNode, old: &[String], new: &str) -> ObjectNode {
    let mut states: Vec<State> = node
        .states
        .iter()
        .filter(|st| !(st.arg.is_none() && old.iter().any(|o| st.name == o.as_str())))
        .cloned()
        .collect();
    states.push(State::plain(new));
    ObjectNode::new(node.label.clone(), states)
}

/// Cases 3 and 4: brings the ingredient `o` (already in the tree, in `slots`; `eq` in FOON) to the
/// state `s`.
fn restate<'kb>(
    ctx: &Context<'kb>,
    tree: &mut Tree<'kb>,
    eq: &str,
    o: &str,
    s: &str,
    slots: &[SlotId],
) -> Result<String, String> {
    let order = tree.order();
    let first_use = |x: SlotId| {
        order
            .iter()
            .position(|&u| tree.units[u].inputs.iter().any(|i| i.0 == x))
            .unwrap_or(usize::MAX)
    };
    let Some(leaf) = slots
        .iter()
        .copied()
        .filter(|&x| !tree.produced(x))
        .min_by_key(|&x| (first_use(x), x))
    else {
        return Err(format!(
            "'{o}' has no starting node in the tree; state kept"
        ));
    };
    let leaf_node = tree.slots[leaf].node.clone();
    let leaf_state = state_text(&leaf_node);
    let leaf_cat = food_category(ctx, &leaf_node);
    let c = category(s);
    if c.is_starting() {
        // Table I, case 3: the tree starts from a processed leaf; add the units making it from raw
        let Some(kb_node) = tree.slots[leaf].kb else {
            return Err(format!(
                "no way to make '{leaf_node}' from '{s}' is known; taken as it is"
            ));
        };
        let r = retrieve(ctx.kb, ctx.index, ctx.scorer, kb_node, ctx.goal_subgraph);
        if r.units.is_empty() {
            return Err(format!(
                "FOON has no way to make '{leaf_state}' {o} from '{s}'; it is taken as it is"
            ));
        }
        let mut slot_of: HashMap<NodeId, SlotId> = [(kb_node, leaf)].into_iter().collect();
        let before = tree.slots.len();
        tree.add_retrieved(ctx.kb, &r, &mut slot_of, Origin::Grafted);
        if eq != o {
            tree.rename_in(before..tree.slots.len(), eq, o);
        }
        return Ok(format!(
            "added {} unit(s) making the tree's '{leaf_state}' {o} from '{s}'",
            r.units.len()
        ));
    }
    if !leaf_cat.reaches(c) {
        // a node without food states is in the category its ingredient is sold in
        let kept = if leaf_state.is_empty() {
            leaf_cat.name().into()
        } else {
            leaf_state
        };
        return Err(format!(
            "state '{s}' cannot be reached from the tree's '{kept}' (not reversible); kept '{kept}'"
        ));
    }
    let motion = state_motion(ctx, o, eq, s)?;
    if let Some(why) = cannot_take(ctx, o, eq, &motion) {
        return Err(format!(
            "state '{s}' not given: {why}; kept the tree's state"
        ));
    }
    if SEPARATION.contains(&c) {
        // swap the tree's own cutting step for one reaching the wanted state
        for &u in &order {
            if let Some((_, old)) = cut_in(tree, u, o) {
                let targets = downstream(tree, vec![u], o, &order);
                for x in targets {
                    let node = replace_states(&tree.slots[x].node, &old, s);
                    tree.slots[x].node = Cow::Owned(node);
                }
                let unit = &mut tree.units[u];
                let before = std::mem::replace(&mut unit.motion, Cow::Owned(motion.clone()));
                if unit.origin == Origin::Reference {
                    unit.origin = Origin::Renamed;
                }
                return Ok(format!(
                    "'{}' ({before}) changed to '{s}' ({motion})",
                    old.join(", ")
                ));
            }
        }
    }
    // The unit bringing the ingredient to the wanted state comes after the tree's last cut of it (a
    // lime chopped, then squeezed), so that nothing cuts what is already juice or mashed; when the tree
    // does not cut it, or the cut piece goes on only as a container's contents through units pruning
    // may drop (a unit after the cut would then make nothing used), before its first use.
    let cut = order.iter().rev().find_map(|&u| {
        let (x, _) = cut_in(tree, u, o)?;
        let goes_on = tree.consumers(x, &order).any(|v| {
            tree.units[v]
                .outputs
                .iter()
                .any(|&(y, _)| y == tree.goal || tree.slots[y].node.label == o)
        });
        (goes_on && food_category(ctx, &tree.slots[x].node).reaches(c)).then_some((x, u))
    });
    let from = cut.map_or_else(|| past_handling(ctx, tree, &order, o, leaf), |(x, _)| x);
    // a whole food its first use opens into other foods (an egg cracked into white and yolk) is not
    // blended or cooked before: those foods are what go on
    if cut.is_none() && !SEPARATION.contains(&c) {
        for v in tree.consumers(from, &order) {
            let outputs = tree.units[v].outputs.iter().map(|&(y, _)| &tree.slots[y]);
            if outputs
                .clone()
                .any(|x| x.node.label == o || x.node.contents().any(|i| i == o))
            {
                continue;
            }
            let foods: Vec<&str> = outputs
                .filter(|x| !x.utensil && !x.node.holds_something())
                .map(|x| x.node.label.as_str())
                .collect();
            if !foods.is_empty() {
                return Err(format!(
                    "state '{s}' not given: '{}' makes the {o} into {} first, which the tree takes on",
                    tree.units[v].motion,
                    foods.join(" and ")
                ));
            }
        }
    }
    let from_node = tree.slots[from].node.clone();
    let old: Vec<String> = food_states(&from_node)
        .into_iter()
        .map(str::to_string)
        .collect();
    // after a cut the ingredient stays where it was cut
    let made = match cut {
        Some(_) => replace_states(&from_node, &old, s),
        None => ObjectNode::new(o, vec![State::plain(s)]),
    };
    let consumers: Vec<TUnitId> = tree.consumers(from, &order).collect();
    let new_slot = add_state_unit(ctx, tree, from, made, &motion);
    for &v in &consumers {
        for i in tree.units[v].inputs.iter_mut() {
            if i.0 == from {
                i.0 = new_slot;
            }
        }
    }
    for x in downstream(tree, consumers, o, &order) {
        let node = replace_states(&tree.slots[x].node, &old, s);
        tree.slots[x].node = Cow::Owned(node);
    }
    Ok(match cut {
        Some((_, u)) => format!(
            "added '{motion}' after '{}' to make it '{s}'",
            tree.units[u].motion
        ),
        None => format!("added '{motion}' to make it '{s}'"),
    })
}

/// Where on `o`'s own chain from `leaf` a change of state can come: past the units that unwrap it, wash
/// it or give it the preparation that comes before anything else (an egg is cracked before it is beaten;
/// cheese is unwrapped before it is grated; berries are washed, then sliced), so that nothing is done to
/// it in its shell or packet; never past the unit it leaves its chain at.
fn past_handling(ctx: &Context, tree: &Tree, order: &[TUnitId], o: &str, leaf: SlotId) -> SlotId {
    let first = foods::prepared_first(known_as(ctx, o, o));
    let handling = |motion: &str| {
        foods::unwraps(motion)
            || foods::washes(motion)
            || first.is_some_and(|p| p.starts_with(motion))
    };
    let chain = own_chain(tree, order, o, leaf);
    let mut past = leaf;
    // the last unit of the chain takes it on: a change of state comes before it at the latest; moves
    // between handlings (into the bowl it is washed in) are passed over
    for &(_, u) in chain.iter().take(chain.len().saturating_sub(1)) {
        let motion = &tree.units[u].motion;
        if !handling(motion) && !is_transfer_motion(motion) {
            break;
        }
        let Some(&(next, _)) = tree.units[u]
            .outputs
            .iter()
            .find(|&&(y, _)| tree.slots[y].node.label == o)
        else {
            break;
        };
        if handling(motion) {
            past = next;
        }
    }
    past
}

/// The motion bringing `o` (`eq` in FOON) into state `s`: the one FOON uses most for the state, if
/// some recipe uses it on a food of the form of `o`, else the one recipes use most on foods of that form
/// (butter is softened as FOON softens butter, not blended as it softens vegetables).
fn state_motion(ctx: &Context, o: &str, eq: &str, s: &str) -> Result<String, String> {
    let model = &ctx.index.transitions;
    let food = known_as(ctx, o, eq);
    let usual = ctx.index.motion_for(s);
    if !model.judges(food) {
        return usual
            .ok_or_else(|| format!("no motion in FOON reaches '{s}'; kept the tree's state"));
    }
    if let Some(m) = usual
        .as_ref()
        .filter(|m| model.makes(food, m, s) == Verdict::Seen)
    {
        return Ok(m.clone());
    }
    model
        .motion_for(food, s)
        // moving a food does not change it (FOON may list ground cumin poured from a leaf)
        .filter(|m| !is_transfer_motion(m))
        .map(str::to_string)
        // a cut the food's form takes, though no recipe here cuts such a food so (cheese diced)
        .or_else(|| usual.filter(|m| foods::cuts(m) && foods::takes(food, m)))
        .ok_or_else(|| {
            format!("no recipe in FOON brings a food like '{o}' to '{s}'; kept the tree's state")
        })
}

/// The state to plan the asked food for: a cooked state of the recipe data that no recipe brings a
/// food like it to ("baked" rice: cooked, in the source's coarse words) is planned as "cooked".
fn planned_state<'s>(ctx: &Context, o: &str, eq: &str, s: &'s str) -> &'s str {
    let coarse = category(s) == Category::Cooked && s != "cooked";
    if coarse && state_motion(ctx, o, eq, s).is_err() && state_motion(ctx, o, eq, "cooked").is_ok()
    {
        "cooked"
    } else {
        s
    }
}

/// Whether a branch retrieved for `eq` handles `o` only as recipes handle foods of its form: every
/// unit on `eq` moves it or brings it into states the transition model has seen for that form.
fn branch_fits(ctx: &Context, o: &str, eq: &str, branch: &Retrieved) -> bool {
    let model = &ctx.index.transitions;
    let food = known_as(ctx, o, eq);
    if eq == o || !model.judges(food) {
        return true;
    }
    branch.units.iter().all(|&u| {
        let unit = &ctx.kb.units[u];
        let takes_eq = unit.input_nodes().any(|n| ctx.kb.nodes[n].label == eq);
        let outs = unit.outputs.iter().map(|x| &ctx.kb.nodes[x.node]);
        !takes_eq
            || outs.filter(|n| n.label == eq).all(|n| {
                let gained: Vec<&str> = food_states(n)
                    .into_iter()
                    .filter(|st| {
                        !unit.input_nodes().any(|i| {
                            ctx.kb.nodes[i].label == eq
                                && ctx.kb.nodes[i].physical_states().any(|p| p == *st)
                        })
                    })
                    .collect();
                if gained.is_empty() {
                    return model.makes(food, &unit.motion, "") != Verdict::Unseen;
                }
                gained
                    .iter()
                    .all(|st| model.makes(food, &unit.motion, st) != Verdict::Unseen)
            })
    })
}

/// The output of unit `u` in which `o` gains a cut (a separation state none of its inputs `o` has),
/// with the states gained.
fn cut_in(tree: &Tree, u: TUnitId, o: &str) -> Option<(SlotId, Vec<String>)> {
    let unit = &tree.units[u];
    unit.outputs.iter().find_map(|&(x, _)| {
        let out = &tree.slots[x].node;
        if out.label != o {
            return None;
        }
        let before: BTreeSet<&str> = unit
            .inputs
            .iter()
            .map(|i| &tree.slots[i.0].node)
            .filter(|n| n.label == o)
            .flat_map(|n| n.physical_states())
            .collect();
        if before.is_empty() && !unit.inputs.iter().any(|i| tree.slots[i.0].node.label == o) {
            return None;
        }
        let g: Vec<String> = food_states(out)
            .into_iter()
            .filter(|st| !before.contains(st) && SEPARATION.contains(&category(st)))
            .map(str::to_string)
            .collect();
        // FOON may leave the state out ("ginger in pot" once grated): the motion says the food is cut
        let in_pieces = |st: &str| {
            matches!(
                category(st),
                Category::Cut | Category::FinelyCut | Category::Ground
            )
        };
        let cut_unsaid = g.is_empty()
            && !food_states(out).into_iter().any(in_pieces)
            && foods::leaves_in(&unit.motion).is_some_and(in_pieces);
        (!g.is_empty() || cut_unsaid).then_some((x, g))
    })
}

/// Adds a unit making `made` (the ingredient in a new state) from slot `from` by `motion`, with the
/// utensil FOON uses most for it; returns the new slot.
fn add_state_unit<'kb>(
    ctx: &Context<'kb>,
    tree: &mut Tree<'kb>,
    from: SlotId,
    made: ObjectNode,
    motion: &str,
) -> SlotId {
    let made = tree.add_slot(Cow::Owned(made));
    // room for the utensil: the list does not grow for it
    let mut inputs = Vec::with_capacity(2);
    inputs.push((from, true));
    if let Some(t) = ctx.index.utensil_for(motion) {
        inputs.push((utensil_slot(ctx.kb, tree, t), false));
    }
    tree.add_unit(inputs, motion, vec![(made, true)], Origin::Grafted);
    made
}

/// A slot for a utensil node: the tree's own when it is a starting item there, else a new one.
fn utensil_slot<'kb>(kb: &'kb KnowledgeBase, tree: &mut Tree<'kb>, n: NodeId) -> SlotId {
    let node = &kb.nodes[n];
    if let Some(x) = tree
        .slots_with_label(&node.label)
        .into_iter()
        .find(|&x| *tree.slots[x].node == *node && !tree.produced(x))
    {
        return x;
    }
    tree.add_slot(Cow::Borrowed(node))
}

/// Case 2 with the equivalent also requested: copies the branch that prepares `eq` for `o` and feeds the
/// copy into the unit where `eq` joins the dish. Returns the copy's last node.
fn copy_branch(tree: &mut Tree, eq: &str, o: &str) -> Option<SlotId> {
    let order = tree.order();
    let is_private = |u: TUnitId| {
        let unit = &tree.units[u];
        let ing_in: Vec<&str> = unit
            .inputs
            .iter()
            .map(|i| &tree.slots[i.0])
            .filter(|x| !x.utensil)
            .map(|x| x.node.label.as_str())
            .collect();
        let ing_out_ok = unit
            .outputs
            .iter()
            .map(|o| &tree.slots[o.0])
            .filter(|x| !x.utensil)
            .all(|x| x.node.label == eq);
        !ing_in.is_empty() && ing_in.iter().all(|&l| l == eq) && ing_out_ok
    };
    let branch: Vec<TUnitId> = order.iter().copied().filter(|&u| is_private(u)).collect();
    let entry = order.iter().copied().find(|&u| {
        !branch.contains(&u)
            && tree.units[u]
                .inputs
                .iter()
                .any(|i| tree.slots[i.0].node.label == eq)
    })?;
    let x = tree.units[entry]
        .inputs
        .iter()
        .map(|i| i.0)
        .find(|&i| tree.slots[i].node.label == eq)?;
    let produced_in_branch: HashSet<SlotId> = branch
        .iter()
        .flat_map(|&u| tree.units[u].outputs.iter().map(|o| o.0))
        .collect();
    let mut copy_of: HashMap<SlotId, SlotId> = HashMap::default();
    let copy = |tree: &mut Tree, s: SlotId, copy_of: &mut HashMap<SlotId, SlotId>| -> SlotId {
        if let Some(&c) = copy_of.get(&s) {
            return c;
        }
        let node = &tree.slots[s].node;
        if node.label != eq && !produced_in_branch.contains(&s) && !node.contents().any(|i| i == eq)
        {
            return s;
        }
        let mut renamed = map_contents(node, &mut |list| rename_item(list, eq, o));
        if renamed.label == eq {
            renamed.label = o.into();
        }
        let c = tree.add_slot(Cow::Owned(renamed));
        copy_of.insert(s, c);
        c
    };
    for &u in &branch {
        let unit = tree.units[u].clone();
        let inputs = unit
            .inputs
            .iter()
            .map(|&(s, m)| (copy(tree, s, &mut copy_of), m))
            .collect();
        let outputs = unit
            .outputs
            .iter()
            .map(|&(s, m)| (copy(tree, s, &mut copy_of), m))
            .collect();
        tree.add_unit(inputs, &unit.motion, outputs, Origin::Copied);
    }
    let new_x = copy(tree, x, &mut copy_of);
    tree.units[entry].inputs.push((new_x, true));
    let carries = tree.carriers(&order);
    tree.add_contents_downstream(entry, o, &order, &carries);
    tree.units[entry].origin = Origin::Attached;
    Some(new_x)
}

/// Knowledge-base nodes of `eq` for state `s`, best first: same state, else one of its kind (grated for
/// shredded), else same category, preferring one not in a vessel food is cooked in, then one without
/// a place (ties: the state most frequent in recipes of the dish class, then overall).
/// The flag says whether the node is in the wanted state (else it is the ingredient as bought).
/// Remembered by the index: the ranking follows from the knowledge base alone, the same in every plan.
fn pick_nodes(ctx: &Context, eq: &str, s: &str) -> Picks {
    // short names are kept inline: no allocation for the look-up
    let key = (ctx.class, SmolStr::new(eq), SmolStr::new(s));
    ctx.index
        .picks
        .get_or_insert_with(key, || rank_nodes(ctx, eq, s).into())
}

/// `pick_nodes` worked out.
fn rank_nodes(ctx: &Context, eq: &str, s: &str) -> Vec<(NodeId, bool)> {
    let c = category(s);
    type Key = (
        bool,
        bool,
        bool,
        bool,
        bool,
        bool,
        u32,
        u32,
        usize,
        std::cmp::Reverse<NodeId>,
    );
    let mut ranked: Vec<(Key, NodeId)> = Vec::new();
    // a node's food states and their categories, one buffer for all nodes
    let mut food: Vec<&str> = Vec::new();
    let mut cats: Vec<Category> = Vec::new();
    for &n in ctx.index.nodes_of(eq) {
        let node = &ctx.kb.nodes[n];
        food.clear();
        cats.clear();
        for state in node.physical_states() {
            let k = category(state);
            if k != Category::Other {
                food.push(state);
                cats.push(k);
            }
        }
        let exact = food.contains(&s);
        let kin = food.iter().any(|f| akin(f, s));
        let cat = c != Category::Other && cats.contains(&c);
        // a node saying nothing of its food is as bought: whole, unless its ingredient is sold otherwise
        let raw = c.is_starting()
            && ctx.kb.kitchen[n]
            && cats.iter().all(|k| k.is_starting())
            && (!cats.is_empty() || ctx.index.sold_as(eq).is_none());
        if !(exact || cat || raw) {
            continue;
        }
        let (in_class, overall) = ctx.index.state_frequency(ctx.class, eq, &food);
        let bare = node.container().is_none() && !node.holds_something();
        // an ingredient comes from a packet, a shaker, a bowl: not from the pan it was cooked in
        let stored = !node.container().is_some_and(|c| ctx.index.is_heated(c));
        let key = (
            exact,
            kin,
            cat,
            stored,
            !node.holds_something(),
            bare,
            in_class,
            overall,
            usize::MAX - node.states.len(),
            std::cmp::Reverse(n),
        );
        ranked.push((key, n));
    }
    ranked.sort_by_key(|r| std::cmp::Reverse(r.0));
    let mut out: Vec<(NodeId, bool)> = ranked.into_iter().map(|(_, n)| (n, true)).collect();
    // the ingredient as it comes from the kitchen, fresh unless asked preserved (a grape halved is not a
    // raisin), fewest states first
    let preserved = |n: NodeId| {
        c != Category::Preserved
            && ctx.kb.nodes[n]
                .physical_states()
                .any(|st| category(st) == Category::Preserved)
    };
    if let Some(n) = ctx
        .index
        .nodes_of(eq)
        .iter()
        .copied()
        .filter(|&n| ctx.kb.kitchen[n] && !ctx.kb.nodes[n].holds_something())
        .min_by_key(|&n| (preserved(n), ctx.kb.nodes[n].states.len(), n))
        .or_else(|| ctx.index.nodes_of(eq).first().copied())
    {
        out.push((n, false));
    }
    out
}

/// Whether a unit handles `eq` alone (with utensils): a branch with a unit that mixes other ingredients
/// would bring another recipe's dish along.
fn private_unit(kb: &KnowledgeBase, u: UnitId, eq: &str) -> bool {
    kb.units[u].input_nodes().all(|n| {
        let node = &kb.nodes[n];
        (is_utensil(&node.label) || node.label == eq) && node.contents().all(|i| i == eq)
    })
}

/// Per slot, whether a unit that cooks `food` (`foods::cooks_food`) takes it or what it becomes on the
/// way on.
fn cooked_later(tree: &Tree, order: &[TUnitId], food: &str) -> Vec<bool> {
    let mut cooked = vec![false; tree.slots.len()];
    // walked backwards, a unit's outputs are settled before its inputs
    for &v in order.iter().rev() {
        let unit = &tree.units[v];
        let cooks = foods::cooks_food(food, &unit.motion);
        for &(s, _) in &unit.inputs {
            cooked[s] |= cooks || unit.outputs.iter().any(|&(x, _)| x != s && cooked[x]);
        }
    }
    cooked
}

/// Whether `food` joining unit `u` is cooked there or later (`cooked`: `cooked_later` for it): what the
/// unit puts things into (the bowl a ladle fills, not the pot it empties, which may go back on the
/// stove), else any of its outputs.
fn cooks_what_joins(tree: &Tree, cooked: &[bool], u: TUnitId, food: &str) -> bool {
    let unit = &tree.units[u];
    let contents = |x: SlotId| tree.slots[x].node.contents().count();
    let filled: Vec<SlotId> = unit
        .outputs
        .iter()
        .map(|o| o.0)
        .filter(|&x| {
            let label = &tree.slots[x].node.label;
            let had = unit
                .inputs
                .iter()
                .filter(|i| tree.slots[i.0].node.label == *label)
                .map(|i| contents(i.0))
                .max();
            had.is_some_and(|n| contents(x) > n)
        })
        .collect();
    let cooked_later = |x: &SlotId| cooked[*x];
    foods::cooks_food(food, &unit.motion)
        || if filled.is_empty() {
            unit.outputs.iter().map(|o| o.0).any(|x| cooked_later(&x))
        } else {
            filled.iter().any(cooked_later)
        }
}

/// The unit a new ingredient joins: one that can take more ingredients, into an output whose contents
/// reach the goal (`carries`: the tree's `carriers`), by a motion the food can join by (milk poured, not
/// placed), before a unit that cooks it when it must be cooked (`cooked`: `cooked_later`), where
/// ingredients of the same kind go in (salt where the pepper is sprinkled), else with the dish's usual
/// motion, closest to the goal.
#[allow(clippy::too_many_arguments)]
fn attach_point(
    ctx: &Context,
    tree: &Tree,
    order: &[TUnitId],
    carries: &[bool],
    cooked: &[bool],
    o: &str,
    c: Category,
) -> Option<TUnitId> {
    let goal_label = tree.slots[tree.goal].node.label.as_str();
    let food = known_as(ctx, o, o);
    // joins where the dish is cooked after it: it must be cooked, or it gives its taste in the heat
    let wants_heat = foods::must_cook(o) || foods::joins_before_heat(food);
    // closest to the goal first: a unit further from it must do strictly better, so its kin
    // ingredients are worked out only when they could make it
    let mut best: Option<(TUnitId, AttachKey)> = None;
    for &u in order.iter().rev() {
        let unit = &tree.units[u];
        let mut holding = unit
            .outputs
            .iter()
            .filter(|x| tree.slots[x.0].node.holds_something())
            .peekable();
        if holding.peek().is_none() {
            continue;
        }
        let reaches =
            holding.any(|x| carries[x.0]) || unit.outputs.iter().any(|x| x.0 == tree.goal);
        // a unit that adds an ingredient, not one that only moves the dish itself
        let adds = unit.inputs.iter().any(|i| {
            let x = &tree.slots[i.0];
            i.1 && !x.utensil && x.node.label != goal_label
        });
        let fits = foods::joins_by(o, &unit.motion);
        let safe = !wants_heat || cooks_what_joins(tree, cooked, u, food);
        let beats = |kin: bool, pref: usize| {
            let key = (reaches, fits, safe, adds, kin, usize::MAX - pref);
            best.as_ref().is_none_or(|(_, b)| key > *b).then_some(key)
        };
        // not even with kin ingredients and the dish's first motion: its motion is not looked up
        if beats(true, 0).is_none() {
            continue;
        }
        let (more, pref) = motion_fit(ctx.class, &unit.motion);
        if !more || beats(true, pref).is_none() {
            continue;
        }
        let kin = unit.inputs.iter().any(|i| {
            let x = &tree.slots[i.0];
            let n = &x.node;
            !x.utensil
                && n.label != o
                && ((!matches!(c, Category::Whole | Category::Other) && food_category(ctx, n) == c)
                    || {
                        let sim = ctx.scorer.pair(o, &n.label);
                        ctx.sim.accepts(sim) && sim < 1.0
                    })
        });
        if let Some(key) = beats(kin, pref) {
            best = Some((u, key));
            // a unit adding ingredients of the same kind with the dish's first motion into the dish: none
            // beats it
            if key == (true, true, true, true, true, usize::MAX) {
                break;
            }
        }
    }
    // nothing that takes more reaches the dish: the unit that makes it takes the food, so its
    // progress line ends in the dish
    best.filter(|(_, key)| key.0)
        .map(|b| b.0)
        .or_else(|| tree.producer.get(tree.goal).copied().flatten())
}

/// How `attach_point` ranks a unit: reaches the goal, the food joins by its motion, the food is cooked
/// after if it must be, the unit adds an ingredient, kin ingredients join there, the dish's motion rank.
type AttachKey = (bool, bool, bool, bool, bool, usize);

/// Case 4 from the universal FOON: the equivalent's branch for the state, renamed and attached.
/// Returns the chosen state text and a reason.
fn add_branch<'kb>(
    ctx: &Context<'kb>,
    tree: &mut Tree<'kb>,
    eq: &str,
    o: &str,
    asked: &str,
) -> Result<(SmolStr, String), String> {
    let prepared = prepared_state(ctx, o, eq, asked);
    let s = prepared.unwrap_or(asked);
    let mut picked = None;
    let mut misfit = None;
    let candidates = pick_nodes(ctx, eq, s);
    let count = candidates.len();
    // the best few in the state, and always the ingredient as it comes from the kitchen (last)
    let tried = candidates
        .iter()
        .copied()
        .enumerate()
        .filter(|(i, _)| *i < 8 || *i + 1 == count)
        .map(|x| x.1);
    for (n, in_state) in tried {
        if ctx.kb.kitchen[n] {
            picked = Some((n, in_state, Default::default()));
            break;
        }
        let private = |u| private_unit(ctx.kb, u, eq);
        if let Some(r) = retrieve_within(ctx.kb, ctx.index, ctx.scorer, n, None, private) {
            // a branch handling the food as no recipe handles one of its form is kept only as a last
            // resort (tahini is not ground as the seed it was matched with)
            if branch_fits(ctx, o, eq, &r) {
                picked = Some((n, in_state, r));
                break;
            }
            misfit.get_or_insert((n, in_state, r));
        }
    }
    let picked = picked.or(misfit);
    let node = picked.as_ref().map(|p| (p.0, p.1));
    ctx.trace
        .record(|t| t.state_choice(ctx, (o, asked), eq, s, node));
    let before = tree.slots.len();
    // the reason, written into one string as the branch is made (sized for nearly every reason: it
    // does not grow step by step)
    let mut how = String::with_capacity(128);
    how.push_str("not in the reference tree: ");
    if eq != o {
        let _ = write!(how, "'{eq}' substituted with '{o}': ");
    }
    if prepared.is_some() {
        let _ = write!(
            how,
            "'{asked}' names only what {o} is: made '{s}', as a cook would; "
        );
    }
    let Some((n, in_state, r)) = picked else {
        // FOON only makes it together with other ingredients (a prepared product such as taco
        // seasoning, whose recipe would bring another dish along): it is bought ready
        let bare = tree.add_slot(Cow::Owned(ObjectNode::new(eq, Vec::new())));
        let _ = write!(
            how,
            "'{eq}' taken as bought (FOON makes it only together with other ingredients)"
        );
        return finish_branch(
            ctx,
            tree,
            eq,
            o,
            s,
            before,
            bare,
            SmolStr::default(),
            false,
            how,
        );
    };
    // most branches are a kitchen item alone: only units retrieved for one share the tree's utensils
    let (added, made) = if ctx.kb.kitchen[n] || r.units.is_empty() {
        (0, None)
    } else {
        let mut slot_of = starting_utensils(tree, r.units.len());
        tree.add_retrieved(ctx.kb, &r, &mut slot_of, Origin::Grafted);
        (r.units.len(), slot_of.get(&n).copied())
    };
    let last = made.unwrap_or_else(|| tree.add_slot(Cow::Borrowed(&ctx.kb.nodes[n])));
    let _ = write!(how, "'{}' taken from FOON", ctx.kb.nodes[n]);
    if added > 0 {
        let _ = write!(how, " with {added} unit(s) making it");
    }
    let state = state_text(&ctx.kb.nodes[n]);
    finish_branch(ctx, tree, eq, o, s, before, last, state, in_state, how)
}

/// The state a cook brings the food to when the asked state `s` is only a category word of the recipe
/// data ("whole veg" onion: chopped; "whole" egg: cracked), from `foods::prepared_state` of the asked food
/// (else its equivalent); None when `s` is a real state or the food is used as it is.
fn prepared_state(ctx: &Context, o: &str, eq: &str, s: &str) -> Option<&'static str> {
    if category(s) != Category::Whole || matches!(s, "washed" | "clean") {
        return None;
    }
    let food = known_as(ctx, o, eq);
    foods::prepared_state(food)
}

/// The utensils the tree starts with, by knowledge-base node: a branch of `units` units shares them
/// rather than duplicating them (sized for the branch's nodes too, a few per unit).
fn starting_utensils(tree: &Tree, units: usize) -> HashMap<NodeId, SlotId> {
    let mut slot_of = HashMap::with_capacity_and_hasher(4 * units + 16, Default::default());
    for x in tree.live_slots() {
        if let Some(k) = tree.slots[x].kb {
            if tree.slots[x].utensil && !tree.produced(x) {
                slot_of.entry(k).or_insert(x);
            }
        }
    }
    slot_of
}

/// The rest of a case-4 branch whose last node is `last`: a unit bringing it to the state `s` when it is
/// not in it (the motion FOON uses most for that state), the renaming to the query's name, and the
/// attachment where the dish takes such ingredients.
#[allow(clippy::too_many_arguments)]
fn finish_branch<'kb>(
    ctx: &Context<'kb>,
    tree: &mut Tree<'kb>,
    eq: &str,
    o: &str,
    s: &str,
    before: SlotId,
    mut last: SlotId,
    mut chosen_state: SmolStr,
    in_state: bool,
    mut how: String,
) -> Result<(SmolStr, String), String> {
    if foods::prepared_first(known_as(ctx, o, eq)).is_some() && !in_state {
        // an egg is cracked before it is beaten or blended
        last = prepare_whole(ctx, tree, eq, o, last, &mut how);
    }
    let c = category(s);
    // milk taken in a cup is liquid milk already; liquid milk cannot be sliced, diced pineapple not made
    // whole (of the starting states only 'whole' speaks of the cut: dried fruit may well be diced)
    let node = &tree.slots[last].node;
    let from = food_category(ctx, node);
    let bought_preserved = matches!(kind(s), Some("dried" | "frozen"));
    if bought_preserved && from == Category::Whole {
        // asked dried or frozen (dried apricots), bought so: no stone or skin to take off then
        let whole: Vec<String> = food_states(node)
            .into_iter()
            .filter(|st| category(st) == Category::Whole)
            .map(str::to_string)
            .collect();
        tree.slots[last].node = Cow::Owned(replace_states(node, &whole, s));
        let _ = write!(how, ", bought '{s}'");
        chosen_state = s.into();
    }
    let node = &tree.slots[last].node;
    let as_sold = ctx.index.sold_as(eq) == Some(c) && !has_food_state(node);
    let shown = shown_by_form(tree, known_as(ctx, o, eq), s, &[last]);
    if !(in_state || as_sold || shown || c == Category::Other) {
        if !from.reaches(c) && (c == Category::Whole || !c.is_starting()) {
            let _ = write!(
                how,
                ", state '{s}' cannot be reached from {} (not reversible)",
                from.name()
            );
        } else if c.is_starting() {
            if chosen_state.is_empty() && !s.is_empty() && from.reaches(c) {
                // an ingredient as bought is in the starting state asked for
                let node = map_states(node, s);
                tree.slots[last].node = Cow::Owned(node);
                chosen_state = s.into();
            }
        } else {
            match state_motion(ctx, o, eq, s) {
                Err(why) => {
                    let _ = write!(how, ", {}", why.trim_end_matches("; kept the tree's state"));
                }
                Ok(m) => match cannot_take(ctx, o, eq, &m) {
                    Some(why) => {
                        let _ = write!(how, ", state '{s}' not given: {why}");
                    }
                    None => {
                        let made = ObjectNode::new(eq, vec![State::plain(s)]);
                        last = add_state_unit(ctx, tree, last, made, &m);
                        let _ = write!(how, ", then '{m}' to make it '{s}'");
                        chosen_state = s.into();
                    }
                },
            }
        }
    }
    last = prepare_whole(ctx, tree, eq, o, last, &mut how);
    if eq != o {
        tree.rename_in(before..tree.slots.len(), eq, o);
    }
    let order = tree.order();
    let carries = tree.carriers(&order);
    let cooked = cooked_later(tree, &order, known_as(ctx, o, eq));
    let Some(m) = attach_point(ctx, tree, &order, &carries, &cooked, o, c) else {
        return Err(format!("no unit of the tree can take '{o}'"));
    };
    if !cooks_what_joins(tree, &cooked, m, known_as(ctx, o, eq)) {
        last = cook_alone(ctx, tree, o, last, &mut how);
    }
    tree.units[m].inputs.push((last, true));
    tree.add_contents_downstream(m, o, &order, &carries);
    tree.units[m].origin = Origin::Attached;
    ctx.trace
        .record(|t| t.attached(o, s, &tree.units[m].motion, dish_pattern(ctx.class)));
    let _ = write!(how, "; added at '{}'", tree.units[m].motion);
    Ok((chosen_state, how))
}

/// Produce still whole (asked "peeled", "washed") brought on to the state a cook gives it
/// (`foods::prepared_state`: a cucumber chopped, an egg cracked) by FOON's motion for that state.
/// Returns the slot the branch now ends in.
fn prepare_whole<'kb>(
    ctx: &Context<'kb>,
    tree: &mut Tree<'kb>,
    eq: &str,
    o: &str,
    last: SlotId,
    how: &mut String,
) -> SlotId {
    let food = known_as(ctx, o, eq);
    let Some(p) = foods::prepared_state(food) else {
        return last;
    };
    let node = &tree.slots[last].node;
    let whole = node.physical_states().all(|st| {
        st != p
            && matches!(
                category(st),
                Category::Whole | Category::Trimmed | Category::Other
            )
    });
    let motion = ctx
        .index
        .motion_for(p)
        .filter(|m| cannot_take(ctx, o, eq, m).is_none());
    let (true, Some(motion)) = (whole, motion) else {
        return last;
    };
    let made = ObjectNode::new(eq, vec![State::plain(p)]);
    let _ = write!(how, ", then '{motion}' to make it '{p}', as a cook would");
    add_state_unit(ctx, tree, last, made, &motion)
}

/// The asked food `o` when the tree takes it to the dish in the piece it is bought as (a block of cheddar
/// poured into the omelette, asked "creamy"; a chicken baked whole for a salad): brought to the state a
/// cook gives it (`foods::prepared_state`: grated, chopped) as `restate` brings a food to an asked
/// state. Foods prepared before anything else (an egg cracked) are the tree's already. Returns the reason.
fn prepare_kept<'kb>(
    ctx: &Context<'kb>,
    tree: &mut Tree<'kb>,
    o: &str,
    eq: &str,
) -> Option<String> {
    let food = known_as(ctx, o, eq);
    let p = foods::prepared_state(food).filter(|_| foods::prepared_first(food).is_none())?;
    let slots = tree.slots_with_label(o);
    let in_piece = slots.iter().all(|&x| {
        tree.slots[x].node.physical_states().all(|st| {
            matches!(
                category(st),
                Category::Whole | Category::Trimmed | Category::Cooked | Category::Other
            )
        })
    });
    if slots.is_empty() || !in_piece {
        return None;
    }
    let how = restate(ctx, tree, eq, o, p, &slots).ok()?;
    Some(format!("kept whole by the tree: {how}, as a cook would"))
}

/// What a cook takes off the asked food before using it (`foods::trims`: an onion's skin before it is
/// cut, a cherry's stone before it joins anything), where the tree has it still on: a unit doing so
/// (FOON's motion for the state, else the trim's own verb) comes at that point of the food's own chain
/// (after it is moved and washed; a peach's stone after it is halved). Returns the states given.
fn trim_first<'kb>(
    ctx: &Context<'kb>,
    tree: &mut Tree<'kb>,
    o: &str,
    eq: &str,
) -> Vec<&'static str> {
    let food = known_as(ctx, o, eq);
    let mut given = Vec::new();
    for trim in foods::trims(food) {
        // FOON's motion for the very state ("peel"), else the trim's own verb (not another trim's)
        let motion = ctx
            .index
            .motion_making(trim.state)
            .unwrap_or(trim.verb)
            .to_string();
        if cannot_take(ctx, o, eq, &motion).is_some() {
            continue;
        }
        let starts: Vec<SlotId> = tree
            .slots_with_label(o)
            .into_iter()
            .filter(|&x| !tree.produced(x))
            .collect();
        for x in starts {
            // with the trims given so far, so that a chain shared by two starts is trimmed once
            let order = tree.order();
            let Some((at, u)) = trim_point(tree, &order, o, x, trim) else {
                continue;
            };
            let node = &tree.slots[at].node;
            let mut states: Vec<State> = node
                .states
                .iter()
                .filter(|st| st.arg.is_some() || category(&st.name) != Category::Whole)
                .cloned()
                .collect();
            states.push(State::plain(trim.state));
            let trimmed = ObjectNode::new(node.label.clone(), states);
            let made = add_state_unit(ctx, tree, at, trimmed, &motion);
            for input in tree.units[u].inputs.iter_mut().filter(|i| i.0 == at) {
                input.0 = made;
            }
            // what it becomes no longer has what was taken off ("halved, unpeeled")
            let order = tree.order();
            for (y, _) in own_chain(tree, &order, o, made).into_iter().skip(1) {
                if tree.slots[y]
                    .node
                    .states
                    .iter()
                    .any(|st| st.name == trim.undone)
                {
                    let n = &tree.slots[y].node;
                    let kept = n.states.iter().filter(|st| st.name != trim.undone).cloned();
                    tree.slots[y].node =
                        Cow::Owned(ObjectNode::new(n.label.clone(), kept.collect()));
                }
            }
            if !given.contains(&trim.state) {
                given.push(trim.state);
            }
        }
    }
    given
}

/// The slots of food `o` from `x` on while it stays itself (moved, washed, cut), each with the unit
/// taking it next.
fn own_chain(tree: &Tree, order: &[TUnitId], o: &str, x: SlotId) -> Vec<(SlotId, TUnitId)> {
    let mut chain = Vec::new();
    let mut at = Some(x);
    while let Some(x) = at.filter(|x| chain.iter().all(|&(y, _)| y != *x)) {
        let Some(u) = tree.consumers(x, order).next() else {
            break;
        };
        chain.push((x, u));
        at = tree.units[u]
            .outputs
            .iter()
            .map(|o| o.0)
            .find(|&y| tree.slots[y].node.label == o);
    }
    chain
}

/// Where on `o`'s own chain from `x` the trim comes: before its first cut (a peel, a hull), once it is
/// halved (a stone), else before the unit it leaves the chain at (it joins a batter, a blender); None when
/// the chain has it done already, or a peel finds it cut or joined first, or it was bought preserved.
fn trim_point(
    tree: &Tree,
    order: &[TUnitId],
    o: &str,
    x: SlotId,
    trim: &foods::Trim,
) -> Option<(SlotId, TUnitId)> {
    let chain = own_chain(tree, order, o, x);
    let done = |&(y, _): &(SlotId, TUnitId)| {
        tree.slots[y]
            .node
            .physical_states()
            .any(|st| st == trim.state)
    };
    // frozen or dried fruit was bought with its stone and hull taken out, cut fruit too (an avocado
    // bought chopped has no stone left)
    let bought_ready = tree.slots[x].node.physical_states().any(|st| {
        matches!(
            category(st),
            Category::Preserved
                | Category::Cut
                | Category::FinelyCut
                | Category::Ground
                | Category::Liquid
                | Category::Mixed
        )
    });
    if bought_ready || chain.iter().any(done) {
        return None;
    }
    let whole = |y: SlotId| {
        tree.slots[y]
            .node
            .physical_states()
            .all(|st| matches!(category(st), Category::Whole | Category::Other))
    };
    let first_cut = || {
        chain
            .iter()
            .copied()
            .find(|&(_, u)| foods::cuts(&tree.units[u].motion))
    };
    if trim.before_cut {
        return first_cut().filter(|&(y, _)| whole(y));
    }
    // a stone comes out once the fruit is halved, else before it is cut at all (a cherry pitted
    // whole, not in slices); a hull before the first cut
    let halved = chain.iter().copied().find(|&(y, _)| {
        tree.slots[y]
            .node
            .physical_states()
            .any(|st| st == "halved")
    });
    if let Some(point) = halved.or_else(first_cut) {
        return Some(point);
    }
    let &(y, u) = chain.last()?;
    let joins = !tree.units[u]
        .outputs
        .iter()
        .any(|o2| tree.slots[o2.0].node.label == o);
    joins.then_some((y, u))
}

/// The states of the asked food `o` made to fit its form (`foods::Form`): a state it is never in, taken
/// over from a substitute (tahini "ground, powder" like the sesame it replaced), goes; a food left with no
/// state as it starts is shown in its form's ("liquid" oil).
fn fit_states_to_form(ctx: &Context, tree: &mut Tree, o: &str) {
    let Some(form) = foods::form_of(known_as(ctx, o, o)) else {
        return;
    };
    let misfit = |st: &State| st.arg.is_none() && form.never_in.iter().any(|w| *w == st.name);
    for x in tree.slots_with_label(o) {
        let starts = !tree.produced(x);
        let node = &tree.slots[x].node;
        let mut states: Vec<State> = node
            .states
            .iter()
            .filter(|st| !misfit(st))
            .cloned()
            .collect();
        let bare = !states.iter().any(|st| st.arg.is_none());
        let shown = form.state_when_none.as_deref().filter(|_| starts && bare);
        if states.len() == node.states.len() && shown.is_none() {
            continue;
        }
        states.extend(shown.map(State::plain));
        tree.slots[x].node = Cow::Owned(ObjectNode::new(node.label.clone(), states));
    }
}

/// The dish itself cooked last when what is in it must be cooked (the egg of fresh egg noodles, the flour
/// of a batter) and nothing FOON's recipes do on the way cooks it: the reference recipe ends at the raw dish, and the query asks for one to eat.
/// The motion is the one FOON's recipes use to cook foods of its kind.
fn cook_dish<'kb>(ctx: &Context<'kb>, tree: &mut Tree<'kb>, notes: &mut Vec<String>) {
    let node = &tree.slots[tree.goal].node;
    let label = node.label.clone();
    let raw = !node
        .physical_states()
        .any(|st| category(st) == Category::Cooked);
    // what is in it must be cooked: flour, or an egg that was not cooked before it joined (each judged
    // as the food its asked state says it is: fish asked as sauce is fish sauce)
    let must_cook = node
        .contents()
        .any(|c| match foods::cooking(known_as(ctx, c, c)) {
            foods::Cooking::InDish => true,
            foods::Cooking::Alone => !cooked_somewhere(tree, c),
            foods::Cooking::No => false,
        });
    if !raw || !must_cook || body_cooked(tree) {
        return;
    }
    let motion = state_motion(ctx, &label, &label, "cooked").unwrap_or_else(|_| "cook".into());
    let made = ObjectNode::new(label.clone(), vec![State::plain("cooked")]);
    tree.goal = add_state_unit(ctx, tree, tree.goal, made, &motion);
    notes.push(format!(
        "'{label}' is cooked last ('{motion}'): the reference task tree makes it raw"
    ));
}

/// Whether some node of `food` in the tree is cooked (the chicken baked before it joined the salad).
fn cooked_somewhere(tree: &Tree, food: &str) -> bool {
    tree.slots_with_label(food).into_iter().any(|x| {
        tree.slots[x]
            .node
            .physical_states()
            .any(|st| category(st) == Category::Cooked)
    })
}

/// Whether a unit the tree kept from FOON cooks anything: the dish is then cooked on the way (ramen's
/// broth simmered, pancakes fried), whereas the units modification added cook an ingredient alone (noodles
/// boiled before they join a raw dough).
fn body_cooked(tree: &Tree) -> bool {
    tree.alive_units()
        .any(|(_, u)| u.origin != Origin::Grafted && foods::cooks(&u.motion))
}

/// A food that must be cooked on its own (`foods::Cooking::Alone`) and is still raw at `last`, cooked
/// before it joins a dish that does not cook it. Returns the slot the branch now ends in.
fn cook_alone<'kb>(
    ctx: &Context<'kb>,
    tree: &mut Tree<'kb>,
    o: &str,
    last: SlotId,
    how: &mut String,
) -> SlotId {
    let raw = !tree.slots[last]
        .node
        .physical_states()
        .any(|st| category(st) == Category::Cooked);
    if !raw || foods::cooking(known_as(ctx, o, o)) != foods::Cooking::Alone {
        return last;
    }
    let motion = ctx
        .index
        .motion_for("cooked")
        .unwrap_or_else(|| "cook".into());
    let made = ObjectNode::new(o, vec![State::plain("cooked")]);
    let _ = write!(
        how,
        ", '{motion}' to make it cooked (the dish does not cook it)"
    );
    add_state_unit(ctx, tree, last, made, &motion)
}

/// Why the asked food `o` (else its equivalent `eq`, when the food knowledge does not know `o`) cannot
/// take `motion` ("a powder is not squeezed"), or None when it can: a query's state word that only such a
/// motion makes is a coarse category of the recipe data (butter "ground", oil "juice").
fn cannot_take(ctx: &Context, o: &str, eq: &str, motion: &str) -> Option<String> {
    // the asked food's knowledge decides when it has any: horseradish is not handled as the cayenne it
    // replaced
    let food = known_as(ctx, o, eq);
    let form = foods::form_of(food)?;
    (!foods::takes(food, motion)).then(|| format!("{o} ({}) is not '{motion}'", form.name))
}

/// A node without food states given the starting state `s`.
fn map_states(node: &ObjectNode, s: &str) -> ObjectNode {
    let mut states = node.states.clone();
    states.push(State::plain(s));
    ObjectNode::new(node.label.clone(), states)
}

/// Removes from every slot's lists of contents the items `drops` (slot, item) says go; units touching a
/// changed node are marked renamed.
fn drop_contents(tree: &mut Tree, drops: &dyn Fn(SlotId, &str) -> bool) {
    let mut touched = vec![false; tree.slots.len()];
    for (x, (slot, touched)) in tree.slots.iter_mut().zip(touched.iter_mut()).enumerate() {
        if !slot.node.listed().any(|item| drops(x, item)) {
            continue;
        }
        retain_contents(&mut slot.node, &|item| !drops(x, item));
        *touched = true;
    }
    for u in tree.units.iter_mut() {
        if u.alive
            && u.origin == Origin::Reference
            && u.inputs
                .iter()
                .chain(u.outputs.iter())
                .any(|x| touched[x.0])
        {
            u.origin = Origin::Renamed;
        }
    }
}

/// Whether a unit with these inputs handles any ingredient: a non-utensil input or a listed content
/// (`gone` marks the slots pruned).
fn handles_any(tree: &Tree, inputs: &[(SlotId, bool)], gone: &[bool]) -> bool {
    inputs.iter().any(|&(x, _)| handles(tree, x, gone))
}

/// Whether a slot is an ingredient or holds one (`gone` marks the slots pruned).
fn handles(tree: &Tree, x: SlotId, gone: &[bool]) -> bool {
    let slot = &tree.slots[x];
    !gone[x] && (!slot.utensil || slot.node.holds_something())
}

/// The names a unit's outputs list in their contents that none of its inputs lists or is.
fn made_in(tree: &Tree, inputs: &[(SlotId, bool)], outputs: &[(SlotId, bool)]) -> Vec<String> {
    let known = |item: &str| {
        inputs.iter().any(|&(x, _)| {
            let node = &tree.slots[x].node;
            node.label == item || node.listed().any(|l| l == item)
        })
    };
    let mut made: Vec<String> = outputs
        .iter()
        .flat_map(|&(x, _)| tree.slots[x].node.listed())
        .filter(|item| !known(item))
        .map(str::to_string)
        .collect();
    made.sort_unstable();
    made.dedup();
    made
}

/// The slots of the ingredient the dish is named after (black beans cooked from black beans): those of
/// the goal's label no unit makes, taken only by units before the dish's side. The dish's side (marked in
/// the second vector) is the outputs of the first unit that makes the dish with something in it (the
/// beans cooked with onion), or else makes the goal, and of every unit after it.
fn namesake(tree: &Tree, order: &[TUnitId], live: &[SlotId]) -> (Vec<SlotId>, Vec<bool>) {
    let goal = tree.goal;
    let dish = tree.slots[goal].node.label.as_str();
    let makes_dish = |u: TUnitId| {
        tree.producer[goal] == Some(u)
            || tree.units[u].outputs.iter().any(|&(x, _)| {
                let node = &tree.slots[x].node;
                node.label == dish && node.holds_something()
            })
    };
    let from = order
        .iter()
        .position(|&u| makes_dish(u))
        .unwrap_or(order.len());
    let mut dish_side = vec![false; tree.slots.len()];
    // 1: taken before the dish's side; 2: taken by it
    let mut taken = vec![0u8; tree.slots.len()];
    for (k, &u) in order.iter().enumerate() {
        for &(x, _) in &tree.units[u].inputs {
            taken[x] |= if k < from { 1 } else { 2 };
        }
        if k >= from {
            for &(x, _) in &tree.units[u].outputs {
                dish_side[x] = true;
            }
        }
    }
    // a dish node whose link to the unit making it FOON lost (a brownie cut, not the one baked) is the
    // dish, not an ingredient
    let slots = live
        .iter()
        .copied()
        .filter(|&x| tree.slots[x].node.label == dish && !tree.produced(x) && taken[x] == 1)
        .collect();
    (slots, dish_side)
}

/// Removes every starting ingredient not asked for (`keep`: planned so far; `requested`: the query's
/// names, some still to be brought in), with the units that only served it; containers that held it
/// pass on unchanged, and it leaves every `contains {…}` list. Returns the removed labels.
/// A dish named after one of its ingredients (black beans cooked from black beans) keeps its name: from
/// the unit that makes it on, the name means the dish, and nodes and lists there stay.
fn prune(tree: &mut Tree, keep: &BTreeSet<String>, requested: &HashSet<&str>) -> Vec<String> {
    let order = tree.order();
    // sized once (the slots bound the live ones, and these names and the names listed with them
    // nearly always): a filtered list would grow step by step
    let mut live: Vec<SlotId> = Vec::with_capacity(tree.slots.len());
    live.extend(tree.live_slots());
    // what a unit gives out is made, whether or not it is the unit chosen to make it (the broth FOON's
    // ladle leaves in the bowl beside the ramen is not a starting ingredient)
    let mut made = vec![false; tree.slots.len()];
    for (_, u) in tree.alive_units() {
        for &(x, _) in &u.outputs {
            made[x] = true;
        }
    }
    // only the labels that go are copied
    let mut starting: Vec<&str> = Vec::with_capacity(tree.slots.len());
    starting.extend(
        live.iter()
            .filter(|&&x| !made[x] && !tree.slots[x].utensil)
            .map(|&x| tree.slots[x].node.label.as_str()),
    );
    // names that only the lists of starting nodes give are ingredients too (FOON's "contain {butter}"
    // makes no node of the butter a skillet holds, and the french toast made in it lists butter): not
    // asked for, they go. A name a unit's output lists first is made there (the egg white a crack
    // leaves in the bowl).
    // (asked-for names are set aside first: they are nearly all a starting node lists)
    let named = |item: &str| live.iter().any(|&x| tree.slots[x].node.label == item);
    for &x in live.iter().filter(|&&x| !made[x]) {
        let unnamed =
            |item: &&str| !requested.contains(item) && !keep.contains(*item) && !named(item);
        starting.extend(tree.slots[x].node.listed().filter(unnamed));
    }
    starting.sort_unstable();
    starting.dedup();
    let mut pruned: BTreeSet<String> = starting
        .into_iter()
        .filter(|&l| !keep.contains(l))
        .map(str::to_string)
        .collect();
    let goal = tree.goal;
    let dish = tree.slots[goal].node.label.clone();
    let (namesake_slots, dish_side) = if pruned.remove(dish.as_str()) {
        namesake(tree, &order, &live)
    } else {
        Default::default()
    };
    let namesake = !namesake_slots.is_empty();
    if pruned.is_empty() && !namesake {
        return Vec::new();
    }
    // asked of every live slot and of every name in every list: a hash set rather than the ordered one
    let going: HashSet<&str> = pruned.iter().map(String::as_str).collect();
    // per slot, whether it is pruned
    let mut gone = vec![false; tree.slots.len()];
    // per unit, whether it handled an ingredient before pruning
    let mut had = vec![false; tree.units.len()];
    // per unit, whether something it moved did
    let mut moved_food = vec![false; tree.units.len()];
    for &u in &order {
        let inputs = &tree.units[u].inputs;
        had[u] = handles_any(tree, inputs, &gone);
        moved_food[u] = inputs.iter().any(|&(x, m)| m && handles(tree, x, &gone));
    }
    // the dish's own name stays in the lists of its side, where it means the dish
    drop_contents(tree, &|x, item| {
        going.contains(item) || (namesake && item == dish && !dish_side[x])
    });
    for &x in &live {
        gone[x] = going.contains(tree.slots[x].node.label.as_str());
    }
    for &x in &namesake_slots {
        gone[x] = true;
    }
    // labels that go with the units removed below, beyond those already dropped from the contents
    let mut with_units: BTreeSet<String> = BTreeSet::new();
    let mut alias: HashMap<SlotId, SlotId> = HashMap::default();
    let resolve = |alias: &HashMap<SlotId, SlotId>, mut s: SlotId| {
        for _ in 0..10_000 {
            match alias.get(&s) {
                Some(&t) => s = t,
                None => break,
            }
        }
        s
    };
    // a unit's uses as they are now, in buffers: a kept unit's lists shrink into their own room
    let mut inputs: Vec<(SlotId, bool)> = Vec::new();
    let mut outputs: Vec<(SlotId, bool)> = Vec::new();
    for &u in &order {
        inputs.clear();
        inputs.extend(
            tree.units[u]
                .inputs
                .iter()
                .map(|&(x, m)| (resolve(&alias, x), m))
                .filter(|i| !gone[i.0]),
        );
        outputs.clear();
        outputs.extend(tree.units[u].outputs.iter().filter(|o| !gone[o.0]));
        let makes_goal = outputs.iter().any(|o| o.0 == goal);
        let lost_all = had[u] && !handles_any(tree, &inputs, &gone);
        // nothing new comes out: every output is one of the inputs as they are now
        let no_op = outputs.iter().all(|o| {
            inputs
                .iter()
                .any(|i| i.0 == o.0 || tree.slots[i.0].node == tree.slots[o.0].node)
        });
        // a unit whose moved things all lost their food (an empty bowl poured into the pot, the egg
        // cracked into the broth) acts on nothing, and gives back only things of the names it took
        let label = |x: SlotId| tree.slots[x].node.label.as_str();
        let moves_nothing = moved_food[u]
            && !inputs.iter().any(|&(x, m)| m && handles(tree, x, &gone))
            && outputs
                .iter()
                .all(|o| inputs.iter().any(|i| label(i.0) == label(o.0)));
        if (lost_all || no_op || moves_nothing || outputs.is_empty()) && !makes_goal {
            tree.units[u].alive = false;
            for &(x, _) in &outputs {
                let utensil = tree.slots[x].utensil;
                let node = &tree.slots[x].node;
                let same = inputs
                    .iter()
                    .find(|i| tree.slots[i.0].node == *node)
                    .or_else(|| {
                        inputs
                            .iter()
                            .find(|i| tree.slots[i.0].node.label == node.label)
                    });
                match same {
                    Some(&(i, _)) if i != x => {
                        alias.insert(x, i);
                    }
                    Some(_) => {}
                    None => {
                        let label = node.label.clone();
                        gone[x] = true;
                        if !utensil
                            && !keep.contains(label.as_str())
                            && !going.contains(label.as_str())
                        {
                            with_units.insert(label.to_string());
                        }
                    }
                }
            }
            // what only it put into a container (the egg white and yolk a crack leaves in the pot) goes
            // with it, from the units after it as well
            let made_here = made_in(tree, &inputs, &outputs);
            let stays = |l: &String| {
                keep.contains(l.as_str()) || requested.contains(l.as_str()) || *l == dish
            };
            for item in made_here.into_iter().filter(|l| !stays(l)) {
                for &x in &live {
                    gone[x] |= tree.slots[x].node.label == item;
                }
                with_units.insert(item);
            }
            continue;
        }
        let unit = &mut tree.units[u];
        unit.inputs.clone_from(&inputs);
        dedup_slots(&mut unit.inputs);
        unit.outputs.clone_from(&outputs);
    }
    // the goal may have been passed through a removed unit
    // labels made only by removed units leave the lists of contents as well (the slots still live are
    // listed only when there are such labels)
    if !with_units.is_empty() {
        let still: Vec<SlotId> = tree.live_slots().filter(|&x| !gone[x]).collect();
        with_units.retain(|l| !still.iter().any(|&x| tree.slots[x].node.label == *l));
        if !with_units.is_empty() {
            drop_contents(tree, &|_, item| with_units.contains(item));
            pruned.extend(with_units);
        }
    }
    if namesake {
        pruned.insert(dish.to_string());
    }
    pruned.into_iter().collect()
}
