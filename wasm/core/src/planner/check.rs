//! Structural checks of a plan, used by the tests and available to the CLI: no unit twice, no unit
//! before the units making its inputs, no unit whose products nobody uses, the goal made.

use crate::plan::{Plan, PlanNode};
use crate::taxonomy::RAW_STATES;
use std::collections::HashSet;

/// A node in only raw states (or a bare utensil), available in the kitchen even when some unit also
/// makes it (a lid put back, a cup emptied).
fn is_raw(n: &PlanNode) -> bool {
    n.states.iter().all(|s| RAW_STATES.contains(&s.as_str()))
        && (!n.states.is_empty() || crate::taxonomy::is_utensil(&n.label))
}

/// Whether unit `j` needs unit `i` first: some input of `j` is made by `i`, or by a unit before `j`
/// that needs `i`.
fn needs(units: &[crate::plan::PlanUnit], j: usize, i: usize) -> bool {
    let mut stack = vec![j];
    let mut seen = HashSet::new();
    while let Some(k) = stack.pop() {
        if !seen.insert(k) {
            continue;
        }
        let Some(unit) = units.get(k) else { continue };
        for n in &unit.inputs {
            for (m, earlier) in units.iter().enumerate().take(k) {
                if earlier.outputs.contains(n) && !earlier.inputs.contains(n) {
                    if m == i {
                        return true;
                    }
                    stack.push(m);
                }
            }
        }
    }
    false
}

/// What is wrong with a plan's structure; empty when nothing is.
pub fn violations(plan: &Plan) -> Vec<String> {
    let mut out = Vec::new();
    let units = &plan.units;
    // units that make a node (not merely pass it on)
    let makes =
        |i: usize, n: &PlanNode| units[i].outputs.contains(n) && !units[i].inputs.contains(n);
    let mut seen = HashSet::new();
    for (i, u) in units.iter().enumerate() {
        let mut key_in = u.inputs.clone();
        key_in.sort();
        let mut key_out = u.outputs.clone();
        key_out.sort();
        if !seen.insert((key_in, u.motion.clone(), key_out)) {
            out.push(format!("unit {} ({}) appears twice", i + 1, u.motion));
        }
        for n in &u.inputs {
            if is_raw(n) {
                continue;
            }
            let makers: Vec<usize> = (0..units.len()).filter(|&j| makes(j, n)).collect();
            // a state the recipe returns to (a lid put back) is there from the start: every unit
            // making it again needs this one first
            let returns = makers.iter().all(|&j| j > i && needs(units, j, i));
            if !makers.is_empty() && !makers.iter().any(|&j| j < i) && !returns {
                out.push(format!(
                    "unit {} ({}) needs '{}' before any unit makes it",
                    i + 1,
                    u.motion,
                    n.label
                ));
            }
        }
        let is_goal = |n: &PlanNode| n.label == plan.goal.label && n.states == plan.goal.states;
        let used = u
            .outputs
            .iter()
            .filter(|n| !u.inputs.contains(n))
            .any(|n| is_goal(n) || units[i + 1..].iter().any(|v| v.inputs.contains(n)));
        if !used {
            out.push(format!(
                "unit {} ({}) makes nothing a later unit uses",
                i + 1,
                u.motion
            ));
        }
    }
    if let Some(last) = units.last() {
        if !last
            .outputs
            .iter()
            .any(|n| n.label == plan.goal.label && n.states == plan.goal.states)
        {
            out.push("the last unit does not make the goal".to_string());
        }
    } else {
        out.push("the plan has no units".to_string());
    }
    out
}
