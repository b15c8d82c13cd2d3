//! Planning on small hand-made knowledge bases: load, plan (sound by the evaluator's definitions) and
//! look at the result.

use foon_core::contract::decode;
use foon_core::planner::violations;
use foon_core::similarity::Similarity;
use foon_core::{load, plan, Plan, PlannerIndex};

pub fn kb(files: &[(&str, &str)]) -> (foon_core::KnowledgeBase, PlannerIndex) {
    let files: Vec<(String, Vec<u8>)> = files
        .iter()
        .map(|(n, t)| (n.to_string(), t.as_bytes().to_vec()))
        .collect();
    let kb = load(&files).unwrap_or_else(|e| panic!("{e}"));
    let index = PlannerIndex::new(&kb);
    (kb, index)
}

pub fn try_plan(
    files: &[(&str, &str)],
    sim: &dyn Similarity,
    request: &str,
) -> foon_core::Result<Plan> {
    let (kb, index) = kb(files);
    let request = decode::plan_request(request).unwrap_or_else(|e| panic!("{e}"));
    plan(&kb, &index, sim, &request)
}

/// A plan that must exist and be sound: no unit twice, none before its inputs, none dead, the goal made.
pub fn plan_of(files: &[(&str, &str)], sim: &dyn Similarity, request: &str) -> Plan {
    let p = try_plan(files, sim, request).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(violations(&p), Vec::<String>::new(), "{:#?}", p.units);
    p
}

pub fn query(dish: &str, items: &[(&str, &str)]) -> String {
    let items: Vec<String> = items
        .iter()
        .map(|(o, s)| format!(r#"{{"object": "{o}", "state": "{s}"}}"#))
        .collect();
    format!(
        r#"{{"query": {{"type": "{dish}", "ingredients": [{}]}}}}"#,
        items.join(", ")
    )
}

/// The plan's units as "motion: input (states) + ... -> output (states) + ...", in order.
pub fn units(p: &Plan) -> Vec<String> {
    let side = |nodes: &[std::sync::Arc<foon_core::contract::plan::PlanNode>]| {
        let mut names: Vec<String> = nodes
            .iter()
            .map(|n| format!("{} ({})", n.label, n.states.join(", ")))
            .collect();
        names.sort();
        names.join(" + ")
    };
    p.units
        .iter()
        .map(|u| format!("{}: {} -> {}", u.motion, side(&u.inputs), side(&u.outputs)))
        .collect()
}

pub fn outcome<'p>(p: &'p Plan, object: &str) -> &'p foon_core::contract::plan::IngredientOutcome {
    p.ingredients
        .iter()
        .find(|i| i.object == object)
        .unwrap_or_else(|| panic!("no outcome for {object}: {:#?}", p.ingredients))
}

/// The goal node as the plan makes it (the last unit's output with the goal's label).
pub fn goal_contents(p: &Plan) -> Vec<&str> {
    let goal = p
        .units
        .last()
        .and_then(|u| u.outputs.iter().find(|n| n.label == p.goal.label))
        .expect("the last unit makes the goal");
    goal.ingredients.iter().map(|s| s.as_str()).collect()
}

/// Elsewhere in FOON: black pepper sprinkled from its shaker into a bowl.
pub const BLACK_PEPPER: &str = "//
O\tblack pepper\t1
S\tground
S\tin\t[shaker]
O\tbowl\t0
S\tempty
M\tsprinkle\t<Assumed>
O\tblack pepper\t1
S\tground
S\tin\t[bowl]
//
";
