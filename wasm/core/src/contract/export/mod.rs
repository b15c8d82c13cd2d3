//! Exports of a plan: FOON text (plain dialect, mergeable into a knowledge base), the published
//! progress-line JSON, and PDDL (`pddl.rs`). The plan's own JSON is serde of `Plan`.

mod objects;
mod pddl;

pub use pddl::{action_name, pddl, Pddl};

use crate::contract::plan::{Plan, PlanNode, ProgressLine};
use crate::foon::write::object_line;
use crate::vocab::taxonomy::is_utensil;
use serde_json::json;
use std::fmt::Write;

fn foon_object(out: &mut String, n: &PlanNode, moves: bool, goal_class: Option<Option<u32>>) {
    object_line(out, &n.label, moves, goal_class);
    for s in &n.states {
        // "in [bowl]" -> "S\tin\t[bowl]"; "contains {a,b}" -> "S\tcontains\t{a,b}"
        let arg_at = (s.contains(' ') && s.ends_with([']', '}']))
            .then(|| s.rfind(" [").or_else(|| s.rfind(" {")).unwrap_or(s.len()));
        let _ = match arg_at {
            Some(at) => writeln!(out, "S\t{}\t{}", &s[..at], s[at..].trim_start()),
            None => writeln!(out, "S\t{s}"),
        };
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
    let goal = &plan.goal;
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

/// Progress lines in the published visualiser's shape:
/// `[{ingredient, state:[{physical_state, location}], motion:[...], end_product}]`.
pub fn progress_json(plan: &Plan) -> serde_json::Value {
    let line = |l: &ProgressLine| {
        let state: Vec<serde_json::Value> = l
            .state
            .iter()
            .map(|s| json!({"physical_state": s.physical_state, "location": s.location}))
            .collect();
        json!({
            "ingredient": l.ingredient,
            "state": state,
            "motion": l.motion,
            "end_product": l.end_product,
        })
    };
    plan.progress_lines.iter().map(line).collect()
}
