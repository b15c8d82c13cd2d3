//! Exports of a plan: FOON text (plain dialect, mergeable into a knowledge base), the published
//! progress-line JSON, and PDDL (`pddl.rs`). The plan's own JSON is serde of `Plan`.

mod objects;
mod pddl;

pub use pddl::{action_name, pddl, Pddl};

use crate::contract::plan::{Plan, PlanNode};
use crate::vocab::taxonomy::is_utensil;
use serde::Serialize;
use smol_str::SmolStr;
use std::fmt::Write;

fn foon_object(out: &mut String, n: &PlanNode, moves: bool, goal_class: Option<Option<u32>>) {
    // the plain dialect marks a goal with its dish class; without a class, with a leading '!'
    match goal_class {
        None => {
            let _ = write!(out, "O\t{}\t{}", n.label, u8::from(moves));
        }
        Some(None) => {
            let _ = write!(out, "!O\t{}\t{}", n.label, u8::from(moves));
        }
        Some(Some(c)) => {
            let _ = write!(out, "O\t{}\t{}\t{c}", n.label, u8::from(moves));
        }
    }
    out.push('\n');
    for s in &n.states {
        // "in [bowl]" -> "S\tin\t[bowl]"; "contains {a,b}" -> "S\tcontains\t{a,b}"
        match s
            .find([' '])
            .filter(|_| s.ends_with(']') || s.ends_with('}'))
        {
            Some(_) => {
                let at = s.rfind(" [").or_else(|| s.rfind(" {")).unwrap_or(s.len());
                let (name, arg) = s.split_at(at);
                let _ = writeln!(out, "S\t{}\t{}", name, arg.trim_start());
            }
            None => {
                let _ = writeln!(out, "S\t{s}");
            }
        }
    }
}

/// The plan's units as a FOON subgraph in the plain dialect; the goal node carries its dish class.
pub fn foon_text(plan: &Plan) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "# foon-planner task tree for '{}' (reference: {}, {})",
        plan.query.id.as_deref().unwrap_or(&plan.query.dish_type),
        plan.goal.label,
        plan.goal.subgraph
    );
    let goal = PlanNode {
        label: plan.goal.label.clone(),
        states: plan.goal.states.clone(),
        ingredients: Vec::new(),
        container: None,
    };
    let is_goal = |n: &PlanNode| n.label == goal.label && n.states == goal.states;
    for (i, u) in plan.units.iter().enumerate() {
        out.push_str("//\n");
        for n in &u.inputs {
            foon_object(&mut out, n, !is_utensil(&n.label), None);
        }
        let _ = writeln!(out, "M\t{}\t<Assumed>", u.motion);
        let last = i + 1 == plan.units.len();
        for n in &u.outputs {
            let mark = (last && is_goal(n)).then_some(plan.goal.dish_class);
            foon_object(&mut out, n, !is_utensil(&n.label), mark);
        }
    }
    out.push_str("//\n");
    out
}

#[derive(Serialize)]
struct PublishedState<'a> {
    physical_state: &'a str,
    location: &'a str,
}

#[derive(Serialize)]
struct PublishedLine<'a> {
    ingredient: &'a str,
    state: Vec<PublishedState<'a>>,
    motion: &'a [SmolStr],
    end_product: &'a str,
}

/// Progress lines in the published visualiser's shape:
/// `[{ingredient, state:[{physical_state, location}], motion:[...], end_product}]`.
pub fn progress_json(plan: &Plan) -> serde_json::Value {
    let lines: Vec<PublishedLine> = plan
        .progress_lines
        .iter()
        .map(|l| PublishedLine {
            ingredient: &l.ingredient,
            state: l
                .state
                .iter()
                .map(|s| PublishedState {
                    physical_state: &s.physical_state,
                    location: &s.location,
                })
                .collect(),
            motion: &l.motion,
            end_product: &l.end_product,
        })
        .collect();
    serde_json::to_value(lines).unwrap_or(serde_json::Value::Null)
}
