//! Exports of a plan: FOON text (plain dialect, mergeable into a knowledge base), the published
//! progress-line JSON, and PDDL. The plan's own JSON is serde of `Plan`.

use crate::plan::{Plan, PlanNode};
use crate::taxonomy::is_utensil;
use serde::Serialize;
use smol_str::SmolStr;
use std::collections::BTreeSet;
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

/// A PDDL domain (one action per functional unit) and problem (init: the kitchen; goal: the goal node).
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Pddl {
    pub domain: String,
    pub problem: String,
}

/// A PDDL name: lower-case letters, digits and dashes, starting with a letter.
fn ident(text: &str) -> String {
    let mut out = String::new();
    let mut dash = false;
    for c in text.chars() {
        if c.is_ascii_alphanumeric() {
            out.push(c.to_ascii_lowercase());
            dash = false;
        } else if !dash && !out.is_empty() {
            out.push('-');
            dash = true;
        }
    }
    while out.ends_with('-') {
        out.pop();
    }
    if !out.starts_with(|c: char| c.is_ascii_alphabetic()) {
        out.insert_str(0, "x-");
    }
    out
}

/// One ground proposition per object node: `(at-state <label> <states>)` would need typed arguments the
/// nodes do not have, so each node becomes a 0-ary predicate named after its label and states.
fn predicate(n: &PlanNode) -> String {
    let mut name = ident(&n.label);
    for s in &n.states {
        name.push_str("--");
        name.push_str(&ident(s));
    }
    name
}

pub fn pddl(plan: &Plan) -> Pddl {
    let mut preds: BTreeSet<String> = BTreeSet::new();
    let mut produced: BTreeSet<String> = BTreeSet::new();
    let mut consumed: BTreeSet<String> = BTreeSet::new();
    for u in &plan.units {
        for n in &u.inputs {
            preds.insert(predicate(n));
            consumed.insert(predicate(n));
        }
        for n in &u.outputs {
            preds.insert(predicate(n));
            produced.insert(predicate(n));
        }
    }
    let name = ident(plan.query.id.as_deref().unwrap_or(&plan.goal.label));
    let mut domain = String::new();
    let _ = writeln!(
        domain,
        ";; foon-planner: one action per functional unit, in execution order"
    );
    let _ = writeln!(domain, "(define (domain foon-{name})");
    let _ = writeln!(domain, "  (:requirements :strips)");
    let _ = writeln!(domain, "  (:predicates");
    for p in &preds {
        let _ = writeln!(domain, "    ({p})");
    }
    let _ = writeln!(domain, "  )");
    for (i, u) in plan.units.iter().enumerate() {
        let ins: BTreeSet<String> = u.inputs.iter().map(|n| predicate(n)).collect();
        let outs: BTreeSet<String> = u.outputs.iter().map(|n| predicate(n)).collect();
        let _ = writeln!(domain, "  (:action {}-{}", ident(&u.motion), i + 1);
        let _ = writeln!(domain, "    :parameters ()");
        let pre: Vec<String> = ins.iter().map(|p| format!("({p})")).collect();
        let _ = writeln!(domain, "    :precondition (and {})", pre.join(" "));
        let mut eff: Vec<String> = outs.iter().map(|p| format!("({p})")).collect();
        // an input that changes into something else is no longer there
        eff.extend(
            ins.iter()
                .filter(|p| !outs.contains(*p))
                .filter(|p| {
                    u.inputs.iter().any(|n| {
                        predicate(n) == **p
                            && (!is_utensil(&n.label)
                                || u.outputs.iter().any(|o| o.label == n.label))
                    })
                })
                .map(|p| format!("(not ({p}))")),
        );
        let _ = writeln!(domain, "    :effect (and {}))", eff.join(" "));
    }
    let _ = writeln!(domain, ")");

    // the kitchen: inputs no unit of the plan makes
    let kitchen: Vec<&String> = consumed.iter().filter(|p| !produced.contains(*p)).collect();
    let goal = predicate(&PlanNode {
        label: plan.goal.label.clone(),
        states: plan.goal.states.clone(),
        ingredients: Vec::new(),
        container: None,
    });
    let mut problem = String::new();
    let _ = writeln!(problem, "(define (problem make-{name})");
    let _ = writeln!(problem, "  (:domain foon-{name})");
    let _ = writeln!(problem, "  (:init");
    for p in kitchen {
        let _ = writeln!(problem, "    ({p})");
    }
    let _ = writeln!(problem, "  )");
    let _ = writeln!(problem, "  (:goal ({goal}))");
    let _ = writeln!(problem, ")");
    Pddl { domain, problem }
}
