//! Algorithm 1: the reference goal node, by a graded similarity of ingredient sets.

use super::index::PlannerIndex;
use super::score::{GoalFit, Scorer};
use crate::kb::{Goal, KnowledgeBase};
use crate::taxonomy::dish_class_name;
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
    dish_type: &str,
) -> Option<Chosen<'a>> {
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
