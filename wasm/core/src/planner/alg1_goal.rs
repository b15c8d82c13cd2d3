//! Algorithm 1: the reference goal node, by a graded similarity of ingredient sets.

use super::explain::Recorder;
use super::index::PlannerIndex;
use super::score::{GoalFit, Scorer};
use crate::contract::plan::Query;
use crate::foon::kb::{Goal, KnowledgeBase};
use crate::trace::GoalCandidate;
use crate::vocab::foods::{self, Cooking};
use crate::vocab::taxonomy::{dish_class_name, kin_classes};
use std::cmp::Ordering;

#[derive(Clone, Debug)]
pub(crate) struct Chosen<'a> {
    pub goal: &'a Goal,
    pub score: f32,
}

/// The score of a goal for a query: how much of the query the goal covers (weight 2) and how much of the
/// goal the query uses (weight 1, fewer ingredients to prune), as a weighted harmonic mean.
fn score(fit: &GoalFit) -> f32 {
    let (recall, precision) = (fit.recall, fit.precision);
    if recall + precision <= 0.0 {
        return 0.0;
    }
    3.0 * recall * precision / (2.0 * precision + recall)
}

/// Picks the reference goal among goals of `class` (all goals when the class has none), highest score
/// first; ties go to more exact matches, then fewer goal ingredients, then label and subgraph name.
/// Where none fits well, a kin class's goal may be taken instead (`kin_instead`). Records every
/// candidate of the class, best first, in `trace`.
pub(crate) fn select<'a>(
    kb: &'a KnowledgeBase,
    index: &PlannerIndex,
    scorer: &Scorer,
    class: Option<u32>,
    notes: &mut Vec<String>,
    query: &Query,
    trace: &Recorder,
) -> Option<Chosen<'a>> {
    let of_class = class.and_then(|c| index.goals_of_class(c));
    let goals = match of_class {
        Some(goals) => goals,
        None => {
            let why = match class {
                None => format!("unknown dish type '{}'", query.dish_type),
                Some(c) => {
                    let name = dish_class_name(c).unwrap_or("?");
                    format!("no recipe of class '{name}' in the knowledge base")
                }
            };
            notes.push(format!("{why}: searched all goal nodes"));
            index.all_goals()
        }
    };
    let in_class = best_of(kb, scorer, goals, query)?;
    let kin = class.and_then(|c| kin_instead(kb, index, scorer, c, query, &in_class, notes));
    let kin_class = kin.as_ref().map(|(_, k)| *k);
    trace.record(|t| {
        let (mut list, mut tie_break) = candidates(kb, scorer, goals, query);
        if let Some(k) = kin_class {
            // the reference goal leads the list, as it does when it is of the dish type
            let kin_goals = index.goals_of_class(k).expect("a kin class with goals");
            list.insert(0, candidates(kb, scorer, kin_goals, query).0.remove(0));
            tie_break = Some("kin_class".to_string());
        }
        let g = &mut t.goal_selection;
        g.searched_all = of_class.is_none();
        g.kin_class = kin_class.map(|k| dish_class_name(k).unwrap_or("?").to_string());
        (g.candidates, g.tie_break) = (list, tie_break);
    });
    Some(kin.map_or(in_class, |(c, _)| c))
}

/// The goals of the dish type (of all goals when it has none) Alg. 1 ranks after `chosen`, best first.
pub(crate) fn runners_up<'a>(
    kb: &'a KnowledgeBase,
    index: &PlannerIndex,
    scorer: &Scorer,
    class: Option<u32>,
    query: &Query,
    chosen: &Chosen,
) -> Vec<Chosen<'a>> {
    let goals = class
        .and_then(|c| index.goals_of_class(c))
        .unwrap_or_else(|| index.all_goals());
    rated(kb, scorer, goals, query)
        .into_iter()
        .filter(|(r, _)| !std::ptr::eq(r.goal, chosen.goal))
        .map(|(r, _)| r.into())
        .collect()
}

/// The goal of `goals` Alg. 1 prefers (`compare`).
fn best_of<'a>(
    kb: &'a KnowledgeBase,
    scorer: &Scorer,
    goals: &super::index::GoalClass,
    query: &Query,
) -> Option<Chosen<'a>> {
    let best = rated(kb, scorer, goals, query).into_iter().next();
    best.map(|(r, _)| r.into())
}

/// Every goal of `goals` as Alg. 1 weighs it, with its fit, best first (`compare`); a goal that makes
/// what the query brings ready-made loses `MAKES_WHAT_IS_BROUGHT` of its score.
fn rated<'a>(
    kb: &'a KnowledgeBase,
    scorer: &Scorer,
    goals: &super::index::GoalClass,
    query: &Query,
) -> Vec<(Rated<'a>, GoalFit)> {
    let fits = scorer.goal_fits(goals);
    let rate = |(i, ings): &(usize, Vec<u32>)| {
        let fit = fits.fit(ings);
        let goal = &kb.goals[*i];
        let penalty = if makes_what_is_brought(kb, goal, query) {
            MAKES_WHAT_IS_BROUGHT
        } else {
            0.0
        };
        let rated = Rated {
            goal,
            score: score(&fit) - penalty,
            exact: fit.exact,
            ingredients: ings.len(),
        };
        (rated, fit)
    };
    let mut all: Vec<_> = goals.goals.iter().map(rate).collect();
    all.sort_by(|a, b| compare(kb, &b.0, &a.0).0);
    all
}

/// The candidates of `goals`, best first, as the trace shows them; with what separated the first two.
fn candidates(
    kb: &KnowledgeBase,
    scorer: &Scorer,
    goals: &super::index::GoalClass,
    query: &Query,
) -> (Vec<GoalCandidate>, Option<String>) {
    let all = rated(kb, scorer, goals, query);
    let tie_break = match all.as_slice() {
        [a, b, ..] => Some(TIE_BREAKS[compare(kb, &a.0, &b.0).1].to_string()),
        _ => None,
    };
    let list = all.iter().map(|(r, fit)| candidate(kb, r, fit)).collect();
    (list, tie_break)
}

/// Where the class's best goal `in_class` fits poorly, a clearly better goal of a kin class
/// (`taxonomy::kin_classes`) and that class, with a note; None to keep `in_class`.
fn kin_instead<'a>(
    kb: &'a KnowledgeBase,
    index: &PlannerIndex,
    scorer: &Scorer,
    class: u32,
    query: &Query,
    in_class: &Chosen<'a>,
    notes: &mut Vec<String>,
) -> Option<(Chosen<'a>, u32)> {
    // the dish type has no recipe like the query (bread asked of flour and yeast, the class holding
    // only toasts of bought bread): a recipe of a kin type (a pizza dough) that fits clearly better is a
    // better reference
    let scratch = query
        .ingredients
        .iter()
        .any(|i| foods::cooking(&i.object) == Cooking::InDish);
    let fit = |c: &Chosen| {
        c.score
            - if scratch && !from_scratch(c.goal) {
                NOT_FROM_SCRATCH
            } else {
                0.0
            }
    };
    if fit(in_class) >= WEAK_FIT {
        return None;
    }
    let kin = kin_classes(class)
        .filter_map(|k| Some((best_of(kb, scorer, index.goals_of_class(k)?, query)?, k)))
        .max_by(|a, b| fit(&a.0).total_cmp(&fit(&b.0)))
        .filter(|(k, _)| fit(k) >= fit(in_class) + BETTER_BY);
    let (kin, kin_class) = kin?;
    notes.push(format!(
        "no recipe of this dish type fits the ingredients well ('{}', similarity {:.2}{}): started from \
         '{}' (similarity {:.2}), a dish made the same way",
        kb.nodes[in_class.goal.node].label,
        in_class.score,
        if fit(in_class) < in_class.score { ", not made from the flour or the like asked for" } else { "" },
        kb.nodes[kin.goal.node].label,
        kin.score
    ));
    Some((kin, kin_class))
}

/// Whether the goal is made from a food only ever cooked within a dish (flour: a dough, a batter), as a
/// query that asks for one means its dish to be.
fn from_scratch(goal: &Goal) -> bool {
    goal.ingredients
        .iter()
        .any(|i| foods::cooking(i) == Cooking::InDish)
}

/// Whether the goal makes from other foods a food the query brings ready-made (egg noodles made from
/// flour and egg, where noodles are asked for): the plan would make them and knead the asked ones in.
fn makes_what_is_brought(kb: &KnowledgeBase, goal: &Goal, query: &Query) -> bool {
    let Some(kind) = foods::kind(&kb.nodes[goal.node].label) else {
        return false;
    };
    let brought = query
        .ingredients
        .iter()
        .any(|i| foods::kind(&i.object) == Some(kind));
    brought
        && !goal
            .ingredients
            .iter()
            .any(|i| foods::kind(i) == Some(kind))
}

/// What a goal loses of its score when it makes a food the query brings (`rated`).
const MAKES_WHAT_IS_BROUGHT: f32 = 0.3;

/// What a goal not made from scratch loses of its score against a query that is (`select`).
const NOT_FROM_SCRATCH: f32 = 0.3;

/// Below this score the dish type's best goal is a weak reference (`select`).
const WEAK_FIT: f32 = 0.5;
/// How much better another type's goal must fit to be taken instead of a weak one.
const BETTER_BY: f32 = 0.15;

/// A goal as Alg. 1 weighs it.
#[derive(Clone)]
struct Rated<'a> {
    goal: &'a Goal,
    score: f32,
    exact: usize,
    ingredients: usize,
}

impl<'a> From<Rated<'a>> for Chosen<'a> {
    fn from(r: Rated<'a>) -> Chosen<'a> {
        Chosen {
            goal: r.goal,
            score: r.score,
        }
    }
}

/// Tie-breaks of `compare`, in order, as the trace names them.
/// (`kin_class` marks a reference goal of a kin dish type, `select`.)
const TIE_BREAKS: [&str; 4] = ["score", "exact_matches", "fewer_ingredients", "name"];

/// Whether `a` is preferred to `b` (`Greater`), and the index in `TIE_BREAKS` of what decided it.
fn compare(kb: &KnowledgeBase, a: &Rated, b: &Rated) -> (Ordering, usize) {
    let by_name = || {
        kb.nodes[b.goal.node]
            .label
            .cmp(&kb.nodes[a.goal.node].label)
            .then(b.goal.subgraph.cmp(&a.goal.subgraph))
            .then(b.goal.node.cmp(&a.goal.node))
    };
    [
        a.score.total_cmp(&b.score),
        a.exact.cmp(&b.exact),
        b.ingredients.cmp(&a.ingredients),
    ]
    .into_iter()
    .enumerate()
    .find(|(_, o)| o.is_ne())
    .map_or_else(|| (by_name(), 3), |(k, o)| (o, k))
}

fn candidate(kb: &KnowledgeBase, r: &Rated, fit: &GoalFit) -> GoalCandidate {
    GoalCandidate {
        node: kb.nodes[r.goal.node].to_string(),
        subgraph: r.goal.subgraph.clone(),
        ingredients: r.ingredients,
        recall: fit.recall,
        precision: fit.precision,
        exact_matches: fit.exact,
        score: r.score,
    }
}
