//! Planner defects found by the property tests (`prop_plan.rs`), one test each, minimal input. A test
//! marked `#[ignore]` is a defect still open in the planner (`src/planner/**`, not fixed here); run them with
//! `cargo test --test planner_regressions -- --include-ignored`.

use foon_core::contract::decode;
use foon_core::foon::read::parse_str;
use foon_core::similarity::ExactMatch;
use foon_core::{load, PlannerIndex};

fn plan(kb_text: &str, request: &str) -> foon_core::Plan {
    let kb = load(&[("g00.txt".to_string(), kb_text.as_bytes().to_vec())]).unwrap();
    let index = PlannerIndex::new(&kb);
    let request = decode::plan_request(request).unwrap();
    foon_core::plan(&kb, &index, &ExactMatch, &request).unwrap()
}

/// Found by `planning_on_random_graphs_terminates_in_order_or_fails_typed`: the only input of the unit that
/// makes the goal is pruned (not asked for), leaving "slice" with no inputs; its FOON export then does not
/// read back (`motion_without_inputs`).
#[test]
fn pruning_never_leaves_a_unit_without_inputs() {
    let p = plan(
        "//\nO\ttomato\t0\nM\tslice\t<Assumed>\n!O\tonion\t0\n//\n",
        r#"{"query": {"type": "salad", "ingredients": [{"object": "onion", "state": "whole"}]}}"#,
    );
    assert!(
        p.units.iter().all(|u| !u.inputs.is_empty()),
        "{:#?}",
        p.units
    );
    let text = foon_core::foon_text(&p);
    parse_str("plan.txt", &text).unwrap_or_else(|e| panic!("{e}\n{text}"));
}

/// Found by `planning_on_random_graphs_terminates_in_order_or_fails_typed` (on CI): the query asks for the
/// goal's own object in another state ("cooked leaves" for a salad whose goal is "leaves"). The branch grown
/// to reach that state started from the goal itself, so the plan took the finished goal from the kitchen,
/// cooked it, and made it again. Nothing may use the goal before it is made.
#[test]
fn no_unit_takes_the_goal_before_it_is_made() {
    let p = plan(
        "//\nO\ttomato\t0\nM\tslice\t<Assumed>\n!O\tLeaves\t0\n//\nO\ttomato\t0\nM\tslice\t<Assumed>\nO\ttomato\t0\n//\nO\ttomato\t0\nM\tslice\t<Assumed>\nO\ttomato\t0\nS\tfried\n//\n",
        r#"{"query": {"type": "salad", "ingredients": [{"object": "Leaves", "state": "cooked"}]}}"#,
    );
    let last = p.units.last().expect("a plan with units");
    assert!(
        last.outputs
            .iter()
            .any(|n| n.label == "leaf" && n.states.is_empty()),
        "{:#?}",
        p.units
    );
    for (i, u) in p.units.iter().enumerate() {
        assert!(
            !u.inputs
                .iter()
                .any(|n| n.label == "leaf" && n.states.is_empty()),
            "unit {i} takes the goal: {:#?}",
            p.units
        );
    }
    assert_eq!(foon_core::planner::violations(&p), Vec::<String>::new());
}
