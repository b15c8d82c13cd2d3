//! `write_plan_json` writes exactly what serde_json writes for the plan types' serde derives (the
//! definition of the format): on every dev plan, and on texts and values that need care.

mod common;
use common::{dev_plans, dev_queries, embeddings, foon111, load};
use foon_core::plan::{PlanNode, Status};
use foon_core::{plan, write_plan_json, Plan, PlanRequest, PlannerIndex};
use proptest::prelude::*;
use std::sync::Arc;

fn direct(p: &Plan) -> String {
    let mut out = Vec::new();
    write_plan_json(p, &mut out);
    String::from_utf8(out).expect("UTF-8")
}

#[test]
fn every_dev_plan_is_written_as_serde_writes_it() {
    let plans = dev_plans(&embeddings());
    assert_eq!(plans.len(), 640);
    for (_, p) in &plans {
        assert_eq!(direct(p), serde_json::to_string(p).unwrap());
    }
}

#[test]
fn optional_fields_escapes_and_odd_numbers_are_written_as_serde_writes_them() {
    let mut p = first_dev_plan();
    let odd = "quote \" backslash \\ slash / controls \u{0}\u{1}\u{8}\t\n\u{b}\u{c}\r\u{1f}\u{7f} é ü 漢 🍅";
    p.query.id = None;
    p.query.ingredients[0].object = odd.to_string();
    p.notes.push(odd.to_string());
    p.goal.score = f32::NAN;
    p.goal.dish_class = None;
    p.dish_class = None;
    p.units[0].inputs[0] = Arc::new(PlanNode {
        label: odd.into(),
        states: vec!["in [bowl]".into(), odd.into()],
        ingredients: vec![],
        container: None,
    });
    let outcome = &mut p.ingredients[0];
    outcome.reason = None;
    outcome.case = None;
    outcome.matched = None;
    outcome.status = Status::Unplannable;
    outcome
        .alternatives
        .iter_mut()
        .for_each(|a| a.similarity = f32::INFINITY);
    p.steps.push(String::new());
    let serde = serde_json::to_string(&p).unwrap();
    assert!(serde.contains(r#"\u0000\u0001\b\t\n\u000b\f\r\u001f"#));
    assert!(!serde.contains(r#""id""#) && !serde.contains(r#""reason":null"#));
    assert_eq!(direct(&p), serde);
}

proptest! {
    #[test]
    fn any_label_is_written_as_serde_writes_it(label in any::<String>(), state in "\\PC*") {
        let mut p = first_dev_plan();
        p.goal.label = label.as_str().into();
        p.goal.states = vec![state.as_str().into()];
        prop_assert_eq!(direct(&p), serde_json::to_string(&p).unwrap());
    }
}

/// One small plan, made once (the property runs many cases).
fn first_dev_plan() -> Plan {
    static FIRST: std::sync::OnceLock<Plan> = std::sync::OnceLock::new();
    FIRST
        .get_or_init(|| {
            let kb = load(&foon111("plain"));
            let index = PlannerIndex::new(&kb);
            let (_, q) = dev_queries().swap_remove(0);
            plan(&kb, &index, &embeddings(), &PlanRequest::new(q)).unwrap()
        })
        .clone()
}
