//! The plan JSON: shared nodes written by number put back as the app's reader does give every unit in
//! full, and the JSON reads back as the same plan: on every dev plan, and on texts and values that need
//! care.

mod common;
use common::{dev_plans, dev_queries, embeddings, foon111, load};
use foon_core::contract::plan::{PlanNode, Status};
use foon_core::{plan, write_plan_json, Plan, PlanRequest, PlannerIndex};
use proptest::prelude::*;
use serde_json::Value;
use std::sync::Arc;

/// The direct writer's JSON, with each node number replaced by the node it stands for, as the app's
/// reader does: every node written in full takes the next number.
fn direct(p: &Plan) -> Value {
    let mut out = Vec::new();
    write_plan_json(p, &mut out);
    let mut plan: Value = serde_json::from_slice(&out).expect("JSON");
    let mut written: Vec<Value> = Vec::new();
    for unit in plan["units"].as_array_mut().expect("units") {
        for side in ["inputs", "outputs"] {
            for node in unit[side].as_array_mut().expect("nodes") {
                match node.as_u64() {
                    Some(k) => *node = written[k as usize].clone(),
                    None => written.push(node.clone()),
                }
            }
        }
    }
    plan
}

/// The plan as JSON with every unit's nodes in full (through text, so that numbers stay `f32`s).
fn full(p: &Plan) -> Value {
    let value = |text: String| serde_json::from_str::<Value>(&text).unwrap();
    let mut plan = value(serde_json::to_string(p).unwrap());
    plan["units"] = value(serde_json::to_string(&p.units).unwrap());
    plan
}

/// The plan read back from its JSON.
fn read_back(p: &Plan) -> Plan {
    let mut out = Vec::new();
    write_plan_json(p, &mut out);
    serde_json::from_slice(&out).expect("the plan reads back")
}

#[test]
fn shared_nodes_are_written_once_and_then_by_number() {
    let p = first_dev_plan();
    let mut out = Vec::new();
    write_plan_json(&p, &mut out);
    let text = String::from_utf8(out).unwrap();
    let full = full(&p).to_string();
    // what one unit makes, the next uses: the dev plan has such nodes
    let numbers = serde_json::from_str::<Value>(&text).unwrap()["units"]
        .as_array()
        .unwrap()
        .iter()
        .flat_map(|u| [&u["inputs"], &u["outputs"]])
        .flat_map(|side| side.as_array().unwrap())
        .filter(|n| n.is_u64())
        .count();
    assert!(numbers > 0, "no shared node written by number");
    assert!(text.len() < full.len());
}

#[test]
fn every_dev_plan_reads_back_whole() {
    let plans = dev_plans(&embeddings());
    assert_eq!(plans.len(), 640);
    for (path, p) in &plans {
        assert_eq!(direct(p), full(p), "{path}");
        let serde: Value = serde_json::from_str(&serde_json::to_string(p).unwrap()).unwrap();
        assert_eq!(serde, full(p), "{path}: serde writes every node in full");
        assert_eq!(&read_back(p), p, "{path}");
    }
}

#[test]
fn optional_fields_escapes_and_odd_numbers_are_written_as_json() {
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
    let mut out = Vec::new();
    write_plan_json(&p, &mut out);
    let text = String::from_utf8(out).unwrap();
    assert!(text.contains(r#"\u0000\u0001\b\t\n\u000b\f\r\u001f"#));
    assert!(text.contains(r#""score":null"#) && text.contains(r#""similarity":null"#));
    assert!(!text.contains(r#""id""#) && !text.contains(r#""reason":null"#));
    assert_eq!(direct(&p), full(&p));
}

proptest! {
    #[test]
    fn any_label_reads_back(label in any::<String>(), state in "\\PC*") {
        let mut p = first_dev_plan();
        p.goal.label = label.as_str().into();
        p.goal.states = vec![state.as_str().into()];
        p.units[0].outputs[0] = Arc::new(PlanNode {
            label: label.as_str().into(),
            states: vec![state.as_str().into()],
            ingredients: vec![],
            container: None,
        });
        prop_assert_eq!(read_back(&p), p);
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
