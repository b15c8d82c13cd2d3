//! Section III-C: modification of the reference task tree for the query's ingredients. The driver is
//! here; each step has its file: `equivalent`, `cases` (Table I), `restate` (cases 3 and 4 in the tree),
//! `branch` (case 2 copies, case 4 from FOON), `attach`, `finish`, `prune` and `name` (the dish and its
//! mixtures named for what they hold).

use super::alg2_retrieve::{retrieve, retrieve_within, Retrieved};
use super::index::PlannerIndex;
use super::transitions::Verdict;
use super::tree::{dedup_slots, map_contents, rename_item, retain_contents, SlotId, TUnitId, Tree};
use crate::contract::plan::{
    Alternative, IngredientOutcome, Match, Origin, Query, QueryIngredient, Status,
};
use crate::foon::kb::KnowledgeBase;
use crate::foon::model::{NodeId, ObjectNode, State, StateArg, UnitId};
use crate::similarity::Similarity;
use crate::vocab::foods;
use crate::vocab::states::{
    akin, category, done_cooking, food_state_category, has_food_state, is_food_state, kind,
    state_text, Category,
};
use crate::vocab::taxonomy::{dish_class_name, dish_class_of, is_transfer_motion, is_utensil};
use rustc_hash::{FxHashMap as HashMap, FxHashSet as HashSet};
use smol_str::SmolStr;
use std::borrow::Cow;
use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write;

mod attach;
mod branch;
mod cases;
mod equivalent;
mod finish;
mod name;
mod prune;
mod restate;

use attach::*;
use branch::*;
use cases::*;
use equivalent::*;
use finish::*;
use name::*;
use prune::*;
use restate::*;

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
    pub readings: &'a HashMap<String, &'static str>,
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

/// The reference tree's ingredient labels as retrieved: all of them, and those of starting foods that lead
/// on to the goal (`Tree::leads_to_goal`).
struct ReferenceLabels {
    all: Vec<SmolStr>,
    reaching: Vec<SmolStr>,
}

/// What happened to one ingredient while it was being planned.
struct Work {
    case: Option<Case>,
    matched: Option<Match>,
    alternatives: Vec<Alternative>,
    low_confidence: bool,
    overridden: bool,
    planned: bool,
    reasons: Vec<String>,
    /// The label the ingredient has in the final tree.
    label: String,
}

impl Work {
    fn new(label: &str) -> Work {
        Work {
            case: None,
            matched: None,
            alternatives: Vec::new(),
            low_confidence: false,
            overridden: false,
            planned: false,
            reasons: Vec::new(),
            label: label.to_string(),
        }
    }
}

/// The driver's record while it goes through the query's ingredients.
#[derive(Default)]
struct Driver {
    /// One per query ingredient, in query order.
    works: Vec<Work>,
    /// Tree labels an ingredient has taken (renamed or kept): a later one copies rather than renames.
    claimed: HashSet<String>,
    /// The state each object was first settled in: a name asked twice keeps the first (its one line).
    settled: HashMap<String, String>,
    /// Ingredients to bring from elsewhere in FOON: (work index, equivalent, state).
    pending: Vec<(usize, String, String)>,
}

pub(crate) fn modify<'kb>(
    ctx: &Context<'kb>,
    tree: &mut Tree<'kb>,
    query: &Query,
    enabled: bool,
    notes: &mut Vec<String>,
) -> (Vec<IngredientOutcome>, Vec<String>) {
    let order = tree.order();
    let reference = ReferenceLabels {
        all: tree
            .ingredient_labels()
            .into_iter()
            .map(SmolStr::new)
            .collect(),
        reaching: tree
            .ingredient_labels()
            .into_iter()
            .filter(|l| tree.leads_to_goal(l, &order))
            .map(SmolStr::new)
            .collect(),
    };
    let requested: HashSet<&str> = query
        .ingredients
        .iter()
        .map(|i| i.object.as_str())
        .collect();
    let mut d = Driver::default();
    for ing in &query.ingredients {
        let w = d.take(ctx, tree, ing, enabled, &requested, &reference);
        d.works.push(w);
    }
    let mut removed = Vec::new();
    let any_planned = d.works.iter().any(|w| w.planned) || !d.pending.is_empty();
    if enabled && !any_planned {
        notes.push(
            "no ingredient of the query could be planned: the reference task tree is kept unpruned"
                .to_string(),
        );
    } else if enabled {
        let keep: BTreeSet<String> = d
            .works
            .iter()
            .filter(|w| w.planned)
            .map(|w| w.label.clone())
            .collect();
        ctx.trace.record(|t| t.before_pruning(tree));
        removed = prune(tree, &keep, &requested);
        tree.drop_unneeded();
        ctx.trace.record(|t| t.pruned_from(tree, &removed));
        d.bring_pending(ctx, tree, query);
        d.finish_planned(ctx, tree, query);
        finish_in_pot(ctx, tree, notes);
        cook_dish(ctx, tree, notes);
        name_for_query(ctx, tree, query, notes);
        name_motions(tree);
    } else {
        notes.push("modification off: the reference task tree as retrieved".to_string());
    }
    let outcomes = query
        .ingredients
        .iter()
        .zip(d.works)
        .map(|(ing, w)| outcome(ing, w))
        .collect();
    (outcomes, removed)
}

impl Driver {
    /// Plans one query ingredient in the reference tree: its equivalent, then (with modification on) the
    /// tree renamed or a branch copied for it and its state settled, or it waits in `pending` for a
    /// branch from elsewhere in FOON.
    fn take<'kb>(
        &mut self,
        ctx: &Context<'kb>,
        tree: &mut Tree<'kb>,
        ing: &QueryIngredient,
        enabled: bool,
        requested: &HashSet<&str>,
        reference: &ReferenceLabels,
    ) -> Work {
        let (o, s) = (ing.object.as_str(), ing.state.as_str());
        let mut w = Work::new(o);
        let read = read_as(ctx, o, s);
        if let Some(r) = read {
            w.reasons.push(format!("'{o}' {s} read as '{r}'"));
        }
        let name = read.unwrap_or(o);
        let Some((eq, sim)) = equivalent(ctx, o, name, reference, &mut w) else {
            return w;
        };
        let s = planned_state(ctx, o, &eq, s);
        w.low_confidence = eq != o && ctx.sim.low_confidence(name, &eq, sim);
        let slots = tree.slots_with_label(&eq);
        if !enabled {
            let in_state = best_state_slot(tree, &slots, s, ctx.index.sold_as(&eq));
            judge_unmodified(tree, o, &eq, sim, &slots, in_state, &mut w);
            return w;
        }
        if slots.is_empty() {
            // case 4 from elsewhere in FOON (or an exact FOON label the reference tree lacks): attached
            // after pruning, so that it joins a unit that stays
            self.pending
                .push((self.works.len(), eq.clone(), s.to_string()));
            self.claimed.insert(eq.clone());
            w.matched = Some(Match {
                label: eq.as_str().into(),
                state: SmolStr::default(),
                similarity: sim,
            });
            return w;
        }
        // the equivalent is in the tree: substitute (cases 2, 4) or keep (cases 1, 3)
        w.matched = Some(Match {
            label: eq.as_str().into(),
            state: tree_state(tree, &slots, s, ctx.index.sold_as(&eq)),
            similarity: sim,
        });
        if eq != o && !self.substitute(tree, (&eq, o, s), requested, &mut w) {
            return w;
        }
        self.claimed.insert(o.to_string());
        // renaming or copying gave `o` its slots; else they are the ones found for `eq`
        let slots = if eq == o {
            slots
        } else {
            tree.slots_with_label(o)
        };
        settle_state(ctx, tree, &eq, o, s, &slots, &mut self.settled, &mut w);
        w.planned = true;
        w
    }

    /// The equivalent `eq` in the tree takes the asked name `o`: renamed, or its branch copied where
    /// another ingredient needs `eq` too. False when it has no branch of its own to copy: one from
    /// elsewhere in FOON comes after pruning (`pending`).
    fn substitute(
        &mut self,
        tree: &mut Tree,
        (eq, o, s): (&str, &str, &str),
        requested: &HashSet<&str>,
        w: &mut Work,
    ) -> bool {
        if requested.contains(eq) || self.claimed.contains(eq) {
            if copy_branch(tree, eq, o).is_none() {
                w.reasons.push(format!(
                    "'{eq}' is also needed and has no branch of its own to copy"
                ));
                self.pending
                    .push((self.works.len(), eq.to_string(), s.to_string()));
                return false;
            }
            w.reasons.push(format!(
                "'{eq}' is also needed: its branch was copied for '{o}'"
            ));
        } else {
            tree.rename_everywhere(eq, o);
            w.reasons.push(format!("'{eq}' substituted with '{o}'"));
        }
        self.claimed.insert(eq.to_string());
        true
    }

    /// After pruning: the pending ingredients get their branches from elsewhere in FOON, and so does an
    /// asked-for ingredient whose units served only pruned ones (butter spread on the bread that was not
    /// asked for), like a case-4 ingredient.
    fn bring_pending<'kb>(&mut self, ctx: &Context<'kb>, tree: &mut Tree<'kb>, query: &Query) {
        let present = tree.ingredient_labels();
        for (i, w) in self.works.iter().enumerate() {
            if w.planned && present.binary_search(&w.label.as_str()).is_err() {
                let eq = w
                    .matched
                    .as_ref()
                    .map_or(w.label.clone(), |m| m.label.to_string());
                let s = planned_state(ctx, &w.label, &eq, &query.ingredients[i].state);
                self.pending.push((i, eq, s.to_string()));
            }
        }
        let mut pending = std::mem::take(&mut self.pending);
        // a food that joins the served dish comes last: the others join first where the dish takes them,
        // not where a garnish went in
        pending.sort_by_key(|(i, eq, _)| {
            let o = query.ingredients[*i].object.as_str();
            (foods::joins_served(known_as(ctx, o, eq)), *i)
        });
        for (i, eq, s) in pending {
            let w = &mut self.works[i];
            let o = query.ingredients[i].object.as_str();
            let lost = w.planned;
            let slots = tree.slots_with_label(o);
            if !lost && !slots.is_empty() {
                // an earlier ingredient of the same name brought it: one branch serves both
                if let Some(m) = w.matched.as_mut() {
                    m.state = tree_state(tree, &slots, &s, ctx.index.sold_as(&eq));
                }
                settle_state(ctx, tree, &eq, o, &s, &slots, &mut self.settled, w);
                continue;
            }
            // a case-2 substitute was renamed in the tree already: its branch comes from `eq` again
            let added = add_branch(ctx, tree, &eq, o, &s);
            if added.is_ok() {
                self.settled
                    .entry(o.to_string())
                    .or_insert_with(|| s.clone());
            }
            branch_added(w, lost, added);
        }
    }

    /// What a cook does to each planned ingredient before it is used (`finish`), once per label: a name
    /// asked twice has one line.
    fn finish_planned<'kb>(&mut self, ctx: &Context<'kb>, tree: &mut Tree<'kb>, query: &Query) {
        let mut done: HashSet<String> = HashSet::default();
        for (w, ing) in self.works.iter_mut().zip(&query.ingredients) {
            if !w.planned || !done.insert(w.label.clone()) {
                continue;
            }
            let eq = w
                .matched
                .as_ref()
                .map_or(w.label.as_str(), |m| m.label.as_str());
            if let Some(reason) = prepare_first(ctx, tree, &w.label, eq) {
                w.reasons.push(reason);
            }
            if let Some(reason) = prepare_kept(ctx, tree, &w.label, eq) {
                w.reasons.push(reason);
            }
            if let Some(reason) = cook_before_mash(ctx, tree, &w.label, eq) {
                w.reasons.push(reason);
            }
            let given = trim_first(ctx, tree, &w.label, eq);
            if !given.is_empty() {
                w.reasons.push(format!(
                    "{} before it is used, as a cook would",
                    given.join(", then ")
                ));
            }
            fit_states_to_form(ctx, tree, &w.label, &ing.state);
        }
    }
}

/// Records a branch brought from FOON for an ingredient (`lost`: one whose units went with pruning).
fn branch_added(w: &mut Work, lost: bool, added: Result<(SmolStr, String), String>) {
    match added {
        Ok((state, reason)) => {
            if lost {
                w.reasons.push(format!(
                    "its units went with the pruned ingredients: {reason}"
                ));
            } else {
                w.case = Some(Case::EquivalentInOtherState);
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

/// The plan's outcome of one query ingredient.
fn outcome(ing: &QueryIngredient, w: Work) -> IngredientOutcome {
    IngredientOutcome {
        object: ing.object.as_str().into(),
        state: ing.state.as_str().into(),
        case: w.case.map(Case::number),
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
    }
}
