//! The plan as PDDL (`docs/pddl.md`): a domain with one ground action per functional unit, over
//! object-centred predicates (an object's state, where it is, what it holds), and a problem whose initial
//! state is the kitchen and whose goal is the goal node. Fast Downward solves every dev plan's export with
//! exactly the plan's units (`tests/unit/pddl-planner.test.ts`).

use super::objects::{ident, world, Action, Fact};
use crate::contract::plan::Plan;
use serde::Serialize;
use std::collections::BTreeSet;
use std::fmt::Write;

/// A PDDL domain (one action per functional unit) and problem (init: the kitchen; goal: the goal node).
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Pddl {
    pub domain: String,
    pub problem: String,
}

/// The name of the action of unit `i` (from 0): the motion and the unit's number, `chop-3`.
pub fn action_name(plan: &Plan, i: usize) -> String {
    format!("{}-{}", ident(&plan.units[i].motion), i + 1)
}

pub fn pddl(plan: &Plan) -> Pddl {
    let world = world(plan);
    let name = ident(plan.query.id.as_deref().unwrap_or(&plan.goal.label));
    let mut domain = String::new();
    let _ = writeln!(
        domain,
        ";; foon-planner task tree: one action per functional unit (docs/pddl.md)\n\
         (define (domain foon-{name})\n  (:requirements :strips :negative-preconditions)"
    );
    let mut constants: BTreeSet<&str> = world.objects.iter().map(String::as_str).collect();
    let all = || {
        world
            .actions
            .iter()
            .chain([&world.goal])
            .flat_map(|a| a.pre.iter().chain(&a.pre_not).chain(&a.add).chain(&a.del))
            .chain(&world.init)
    };
    constants.extend(all().filter_map(|f| f.other.as_deref()));
    let list: Vec<&str> = constants.into_iter().collect();
    let _ = writeln!(domain, "  (:constants {})", list.join(" "));
    let predicates: BTreeSet<(&str, bool)> = all()
        .map(|f| (f.predicate.as_str(), f.other.is_some()))
        .collect();
    let _ = writeln!(domain, "  (:predicates");
    for (p, binary) in predicates {
        let _ = writeln!(domain, "    ({p} ?o{})", if binary { " ?x" } else { "" });
    }
    let _ = writeln!(domain, "  )");
    for (i, a) in world.actions.iter().enumerate() {
        let _ = writeln!(domain, "  (:action {}", action_name(plan, i));
        let _ = writeln!(domain, "    :parameters ()");
        let _ = writeln!(domain, "    :precondition (and{})", condition(a));
        let _ = writeln!(
            domain,
            "    :effect (and{}))",
            texts(&a.add, false) + &texts(&a.del, true)
        );
    }
    let _ = writeln!(domain, ")");

    let mut problem = String::new();
    let _ = writeln!(
        problem,
        "(define (problem make-{name})\n  (:domain foon-{name})\n  (:init"
    );
    for f in &world.init {
        let _ = writeln!(problem, "    {}", f.text());
    }
    let _ = writeln!(problem, "  )\n  (:goal (and{}))\n)", condition(&world.goal));
    Pddl { domain, problem }
}

/// What an action needs: its facts, and not the others its objects ever have.
fn condition(a: &Action) -> String {
    texts(&a.pre, false) + &texts(&a.pre_not, true)
}

/// ` (f1) (f2)`, or ` (not (f1)) (not (f2))` when `negated`.
fn texts(facts: &BTreeSet<Fact>, negated: bool) -> String {
    facts
        .iter()
        .map(|f| match negated {
            true => format!(" (not {})", f.text()),
            false => format!(" {}", f.text()),
        })
        .collect()
}
