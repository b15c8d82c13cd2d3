//! Algorithm 1: the reference goal node, by a graded similarity of ingredient sets.

use super::index::PlannerIndex;
use super::score::{GoalFit, Scorer};
use crate::foods::{self, Cooking};
use crate::kb::{Goal, KnowledgeBase};
use crate::plan::Query;
use crate::taxonomy::{dish_class_name, kin_classes};
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
pub(crate) fn select<'a>(
    kb: &'a KnowledgeBase,
    index: &PlannerIndex,
    scorer: &Scorer,
    class: Option<u32>,
    notes: &mut Vec<String>,
    query: &Query,
) -> Option<Chosen<'a>> {
    let dish_type = &query.dish_type;
    let goals = match class.and_then(|c| index.goals_of_class(c)) {
        Some(goals) => goals,
        None => {
            notes.push(match class {
                None => format!("unknown dish type '{dish_type}': searched all goal nodes"),
                Some(c) => format!(
                    "no recipe of class '{}' in the knowledge base: searched all goal nodes",
                    dish_class_name(c).unwrap_or("?")
                ),
            });
            index.all_goals()
        }
    };
    let in_class = best_of(kb, scorer, goals)?;
    let Some(class) = class else {
        return Some(in_class);
    };
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
    if fit(&in_class) >= WEAK_FIT {
        return Some(in_class);
    }
    let kin = kin_classes(class)
        .filter_map(|k| best_of(kb, scorer, index.goals_of_class(k)?))
        .max_by(|a, b| fit(a).total_cmp(&fit(b)))
        .filter(|k| fit(k) >= fit(&in_class) + BETTER_BY);
    let Some(kin) = kin else {
        return Some(in_class);
    };
    notes.push(format!(
        "no recipe of this dish type fits the ingredients well ('{}', similarity {:.2}{}): started from \
         '{}' (similarity {:.2}), a dish made the same way",
        kb.nodes[in_class.goal.node].label,
        in_class.score,
        if fit(&in_class) < in_class.score { ", not made from the flour or the like asked for" } else { "" },
        kb.nodes[kin.goal.node].label,
        kin.score
    ));
    Some(kin)
}

/// Whether the goal is made from a food only ever cooked within a dish (flour: a dough, a batter), as a
/// query that asks for one means its dish to be.
fn from_scratch(goal: &Goal) -> bool {
    goal.ingredients
        .iter()
        .any(|i| foods::cooking(i) == Cooking::InDish)
}

/// What a goal not made from scratch loses of its score against a query that is (`select`).
const NOT_FROM_SCRATCH: f32 = 0.3;

/// Below this score the dish type's best goal is a weak reference (`select`).
const WEAK_FIT: f32 = 0.5;
/// How much better another type's goal must fit to be taken instead of a weak one.
const BETTER_BY: f32 = 0.15;

/// The goal of `goals` with the highest score; ties go to more exact matches, then fewer goal
/// ingredients, then label and subgraph name.
fn best_of<'a>(
    kb: &'a KnowledgeBase,
    scorer: &Scorer,
    goals: &super::index::GoalClass,
) -> Option<Chosen<'a>> {
    let fits = scorer.goal_fits(goals);
    let mut best: Option<(Chosen<'a>, usize, usize)> = None;
    for (i, ings) in &goals.goals {
        let g = &kb.goals[*i];
        let fit = fits.fit(ings);
        let (s, exact) = (score(&fit), fit.exact);
        let better = match &best {
            None => true,
            Some((b, bexact, bn)) => {
                let ord = s
                    .total_cmp(&b.score)
                    .then(exact.cmp(bexact))
                    .then(bn.cmp(&ings.len()))
                    .then_with(|| {
                        kb.nodes[b.goal.node]
                            .label
                            .cmp(&kb.nodes[g.node].label)
                            .then(b.goal.subgraph.cmp(&g.subgraph))
                            .then(b.goal.node.cmp(&g.node))
                    });
                ord == Ordering::Greater
            }
        };
        if better {
            best = Some((Chosen { goal: g, score: s }, exact, ings.len()));
        }
    }
    best.map(|b| b.0)
}
