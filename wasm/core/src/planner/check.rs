//! Structural checks of a plan from its `units` alone, with exactly the definitions of the evaluator
//! (`src/eval/structure.ts`): no unit twice, no unit before a unit making one of its inputs (unless the
//! input is something a kitchen has at the start, which the goal never is), no unit whose products nobody
//! uses, the goal made.

use crate::contract::plan::{sorted, Plan, PlanNode, PlanUnit};
use crate::vocab::states::START_STATES;
use rustc_hash::{FxHashMap as HashMap, FxHashSet as HashSet};

/// Identity of a node: label, states and contents as sets, container (borrowed from the node).
pub(crate) type NodeKey<'a> = (&'a str, Vec<&'a str>, Vec<&'a str>, Option<&'a str>);

pub(crate) fn node_key(n: &PlanNode) -> NodeKey<'_> {
    (
        &n.label,
        sorted(&n.states),
        sorted(&n.ingredients),
        n.container.as_deref(),
    )
}

/// A node the kitchen has at the start even when some unit makes it again (an empty bowl, a lid put
/// back, a whole onion): only starting states, not inside anything, containing nothing.
pub fn available_at_start(n: &PlanNode) -> bool {
    n.ingredients.is_empty()
        && n.container.is_none()
        && n.states.iter().all(|s| START_STATES.contains(&s.as_str()))
}

/// Outputs a unit makes: those that are not also among its inputs (utensils pass through).
fn produced_keys(u: &PlanUnit) -> HashSet<NodeKey<'_>> {
    let inputs: HashSet<NodeKey> = u.inputs.iter().map(|n| node_key(n)).collect();
    u.outputs
        .iter()
        .map(|n| node_key(n))
        .filter(|k| !inputs.contains(k))
        .collect()
}

fn unit_key(u: &PlanUnit) -> (&str, Vec<NodeKey<'_>>, Vec<NodeKey<'_>>) {
    let mut ins: Vec<NodeKey> = u.inputs.iter().map(|n| node_key(n)).collect();
    ins.sort();
    let mut outs: Vec<NodeKey> = u.outputs.iter().map(|n| node_key(n)).collect();
    outs.sort();
    (&u.motion, ins, outs)
}

fn is_goal(n: &PlanNode, plan: &Plan) -> bool {
    n.is(&plan.goal.label, &plan.goal.states)
}

/// What is wrong with a plan's structure; empty when nothing is.
pub fn violations(plan: &Plan) -> Vec<String> {
    let units = &plan.units;
    let produced: Vec<HashSet<NodeKey>> = units.iter().map(produced_keys).collect();
    let mut first_producer: HashMap<&NodeKey, usize> = HashMap::default();
    for (i, keys) in produced.iter().enumerate() {
        for k in keys {
            first_producer.entry(k).or_insert(i);
        }
    }
    let mut last_use: HashMap<NodeKey, usize> = HashMap::default();
    for (i, u) in units.iter().enumerate() {
        for n in &u.inputs {
            last_use.insert(node_key(n), i);
        }
    }
    let mut out = Vec::new();
    let mut seen = HashSet::default();
    let mut goal_made = false;
    for (i, u) in units.iter().enumerate() {
        let motion = &u.motion;
        if !seen.insert(unit_key(u)) {
            out.push(format!("unit {i} ({motion}) appears twice"));
        }
        for n in &u.inputs {
            let first = first_producer.get(&node_key(n)).copied();
            let from_kitchen = available_at_start(n) && !is_goal(n, plan);
            if let Some(f) = first.filter(|&f| f >= i && !from_kitchen) {
                let (label, states) = (&n.label, n.states.join(", "));
                let why = format!("takes '{label}' ({states}) made only by unit {f}");
                out.push(format!("unit {i} ({motion}) {why}"));
            }
        }
        let makes_goal = u.outputs.iter().any(|n| is_goal(n, plan));
        goal_made |= makes_goal;
        let used = produced[i]
            .iter()
            .any(|k| last_use.get(k).is_some_and(|&l| l > i));
        if !used && !makes_goal {
            out.push(format!(
                "unit {i} ({motion}) makes nothing a later unit uses"
            ));
        }
    }
    if !goal_made {
        out.push("no unit makes the goal".to_string());
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::Arc;

    fn node(label: &str, states: &[&str]) -> PlanNode {
        PlanNode {
            label: label.into(),
            states: states.iter().map(|&s| s.into()).collect(),
            ingredients: Vec::new(),
            container: None,
        }
    }

    fn unit(inputs: Vec<PlanNode>, motion: &str, outputs: Vec<PlanNode>) -> PlanUnit {
        PlanUnit {
            inputs: inputs.into_iter().map(Arc::new).collect(),
            motion: motion.into(),
            outputs: outputs.into_iter().map(Arc::new).collect(),
            origin: crate::contract::plan::Origin::Reference,
            sources: Arc::default(),
        }
    }

    #[test]
    fn kitchen_start_nodes_may_be_made_again_later() {
        assert!(available_at_start(&node("bowl", &["empty"])));
        assert!(available_at_start(&node("knife", &[])));
        assert!(!available_at_start(&node("onion", &["chopped"])));
        let mut in_bowl = node("onion", &["whole"]);
        in_bowl.container = Some("bowl".into());
        assert!(!available_at_start(&in_bowl));
    }

    #[test]
    fn node_keys_ignore_the_order_of_states() {
        let (a, b) = (
            node("bowl", &["empty", "clean"]),
            node("bowl", &["clean", "empty"]),
        );
        let c = node("bowl", &["clean"]);
        let keys: HashSet<NodeKey> = [node_key(&a), node_key(&b), node_key(&c)]
            .into_iter()
            .collect();
        assert_eq!(keys.len(), 2);
        assert!(node_key(&a) == node_key(&b) && node_key(&a) > node_key(&c));
    }

    fn plan_of(units: Vec<PlanUnit>, goal: &PlanNode) -> Plan {
        Plan {
            format_version: crate::contract::plan::FORMAT_VERSION,
            query: crate::contract::plan::Query {
                id: None,
                dish_type: String::new(),
                ingredients: Vec::new(),
            },
            dish_class: None,
            notes: Vec::new(),
            modified: true,
            goal: crate::contract::plan::GoalInfo {
                label: goal.label.clone(),
                reference: goal.label.clone(),
                states: goal.states.clone(),
                ingredients: Vec::new(),
                subgraph: String::new(),
                score: 0.0,
                dish_class: None,
            },
            units,
            ingredients: Vec::new(),
            removed: Vec::new(),
            progress_lines: Vec::new(),
            steps: Vec::new(),
            cautions: Vec::new(),
            trace: None,
            robot: None,
        }
    }

    #[test]
    fn a_unit_before_the_maker_of_its_input_is_reported() {
        let fried = node("onion", &["fried"]);
        let units = vec![
            unit(vec![node("onion", &["sliced"])], "fry", vec![fried.clone()]),
            unit(
                vec![node("onion", &["whole"])],
                "slice",
                vec![node("onion", &["sliced"])],
            ),
        ];
        let v = violations(&plan_of(units.clone(), &fried));
        // the fry takes what the slice makes later, and the slice makes nothing a later unit uses
        assert_eq!(v.len(), 2, "{v:?}");
        let ordered = vec![units[1].clone(), units[0].clone()];
        assert!(violations(&plan_of(ordered, &fried)).is_empty());
    }

    #[test]
    fn a_unit_listed_twice_is_reported() {
        let sliced = node("onion", &["sliced"]);
        let u = unit(
            vec![node("onion", &["whole"])],
            "slice",
            vec![sliced.clone()],
        );
        let v = violations(&plan_of(vec![u.clone(), u], &sliced));
        assert!(v.iter().any(|x| x.contains("twice")), "{v:?}");
    }
}
