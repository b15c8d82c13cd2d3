//! Properties of planning on random knowledge bases and random queries: planning always terminates (within
//! a time bound), never panics, and returns either a plan whose units are in a valid execution order with no
//! unit twice, or a typed error (`bad_query`, `no_goal`, `too_large`). A plan's FOON text export reads back
//! to the same units. Random JSON never panics the plan-request decoder.

mod common;
mod gen;
use foon_core::contract::decode;
use foon_core::contract::plan::{PlanRequest, Query, QueryIngredient};
use foon_core::similarity::{ExactMatch, Similarity};
use foon_core::{load, EmbeddingSimilarity, ErrorCode, KnowledgeBase, Plan, PlannerIndex};
use gen::plans::{foon_round_trip_problems, known_defect, order_problems};
use proptest::prelude::*;
use std::path::PathBuf;
use std::sync::{mpsc, Arc, OnceLock};
use std::time::Duration;

fn repo() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn embeddings() -> Arc<EmbeddingSimilarity> {
    static SIM: OnceLock<Arc<EmbeddingSimilarity>> = OnceLock::new();
    SIM.get_or_init(|| {
        let bytes = std::fs::read(repo().join("public/data/food-embeddings.bin")).unwrap();
        Arc::new(EmbeddingSimilarity::from_bytes(&bytes).unwrap())
    })
    .clone()
}

struct Loaded {
    kb: KnowledgeBase,
    index: PlannerIndex,
}

fn starter() -> Arc<Loaded> {
    static KB: OnceLock<Arc<Loaded>> = OnceLock::new();
    KB.get_or_init(|| {
        let files = common::starter_kb_files();
        let kb = load(&files).unwrap();
        let index = PlannerIndex::new(&kb);
        Arc::new(Loaded { kb, index })
    })
    .clone()
}

/// Seconds one plan may take before the property fails as "does not terminate" (debug builds are slow).
const PLAN_SECONDS: u64 = 30;

/// Plans on another thread, so that a planner that does not terminate fails the test instead of hanging it.
fn plan_bounded(
    loaded: Arc<Loaded>,
    sim: Arc<dyn Similarity + Send + Sync>,
    request: PlanRequest,
) -> foon_core::Result<Plan> {
    let (tx, rx) = mpsc::channel();
    let shown = format!("{request:?}");
    std::thread::spawn(move || {
        let _ = tx.send(foon_core::plan(
            &loaded.kb,
            &loaded.index,
            sim.as_ref(),
            &request,
        ));
    });
    match rx.recv_timeout(Duration::from_secs(PLAN_SECONDS)) {
        Ok(result) => result,
        Err(mpsc::RecvTimeoutError::Timeout) => {
            panic!("planning did not finish in {PLAN_SECONDS} s: {shown}")
        }
        Err(mpsc::RecvTimeoutError::Disconnected) => panic!("the planner panicked on {shown}"),
    }
}

fn check(result: foon_core::Result<Plan>, round_trip: bool) -> Result<(), TestCaseError> {
    if std::env::var_os("FOON_PROP_TRACE").is_some() {
        eprintln!(
            "outcome: {}",
            match &result {
                Ok(p) => format!("plan of {} units", p.units.len()),
                Err(e) => e.code.as_str().to_string(),
            }
        );
    }
    match result {
        Ok(plan) => {
            let problems = order_problems(&plan);
            prop_assert!(problems.is_empty(), "{:?}\n{:#?}", problems, plan.units);
            if round_trip && known_defect(&plan).is_none() {
                let problems = foon_round_trip_problems(&plan);
                prop_assert!(problems.is_empty(), "{}", problems.join("\n"));
            }
        }
        Err(e) => prop_assert!(
            matches!(
                e.code,
                ErrorCode::BadQuery | ErrorCode::NoGoal | ErrorCode::TooLarge
            ),
            "unexpected error {e}"
        ),
    }
    Ok(())
}

const DISHES: &[&str] = &[
    "salad",
    "soup",
    "Salads",
    "drinks",
    "cake",
    "spaceship",
    "",
    "chicken noodle soup",
];
const EXTRA: &[&str] = &[
    "chili pepper",
    "cool whip",
    "tofu",
    "quinoa",
    "lemon",
    "basil",
    "xyzzy",
    "milk",
    "flour",
];

fn ingredient(labels: &'static [&'static str]) -> impl Strategy<Value = QueryIngredient> {
    (
        prop_oneof![
            (0..labels.len()).prop_map(move |i| labels[i].to_string()),
            (0..EXTRA.len()).prop_map(|i| EXTRA[i].to_string()),
            "[a-z ]{0,12}",
        ],
        prop_oneof![
            (0..gen::STATES.len()).prop_map(|i| gen::STATES[i].to_string()),
            Just(String::new()),
            "[a-z]{0,8}",
        ],
    )
        .prop_map(|(object, state)| QueryIngredient { object, state })
}

fn request(labels: &'static [&'static str]) -> impl Strategy<Value = PlanRequest> {
    (
        0..DISHES.len(),
        proptest::collection::vec(ingredient(labels), 0..8),
        any::<bool>(),
        proptest::collection::btree_map("[a-z]{1,8}", "[a-z]{1,8}", 0..2),
        any::<bool>(),
    )
        .prop_map(
            |(dish, ingredients, modify, overrides, explain)| PlanRequest {
                query: Query {
                    id: None,
                    dish_type: DISHES[dish].to_string(),
                    ingredients,
                },
                modify,
                overrides,
                explain,
                robot: None,
            },
        )
}

const STARTER_LABELS: &[&str] = &[
    "tomato",
    "cucumber",
    "onion",
    "lettuce",
    "egg",
    "milk",
    "flour",
    "sugar",
    "butter",
    "potato",
    "carrot",
    "rice",
    "chicken",
    "cheese",
    "olive oil",
    "salt",
    "water",
    "garlic",
    "lemon juice",
    "noodle",
];

/// The checks are not vacuous: a real query on the starter knowledge base gives a plan that passes them.
#[test]
fn a_starter_salad_plan_passes_the_checks() {
    let req = decode::plan_request(
        r#"{"query": {"type": "salad", "ingredients": [{"object": "tomato", "state": "sliced"}, {"object": "cucumber", "state": "chopped"}, {"object": "olive oil", "state": ""}]}}"#,
    )
    .unwrap();
    let plan = plan_bounded(starter(), embeddings(), req).unwrap();
    assert!(plan.units.len() >= 3, "{:#?}", plan.units);
    assert_eq!(order_problems(&plan), Vec::<String>::new());
    assert_eq!(known_defect(&plan), None);
    assert_eq!(foon_round_trip_problems(&plan), Vec::<String>::new());
}

proptest! {
    #![proptest_config(gen::config(48))]

    #[test]
    fn planning_on_random_graphs_terminates_in_order_or_fails_typed(
        files in gen::files(4, 8),
        req in request(gen::LABELS),
        embedded in any::<bool>(),
    ) {
        let bytes: Vec<(String, Vec<u8>)> = files.iter().map(|(n, t)| (n.clone(), t.clone().into_bytes())).collect();
        let kb = load(&bytes).unwrap();
        let index = PlannerIndex::new(&kb);
        let sim: Arc<dyn Similarity + Send + Sync> = if embedded { embeddings() } else { Arc::new(ExactMatch) };
        check(plan_bounded(Arc::new(Loaded { kb, index }), sim, req), true)?;
    }

    #[test]
    fn planning_on_the_starter_kb_terminates_in_order_or_fails_typed(req in request(STARTER_LABELS)) {
        check(plan_bounded(starter(), embeddings(), req), true)?;
    }

    #[test]
    fn random_json_never_panics_the_request_decoder(json in json_text()) {
        match decode::plan_request(&json) {
            Ok(req) => check(plan_bounded(starter(), embeddings(), req), false)?,
            Err(e) => {
                prop_assert!(matches!(e.code, ErrorCode::BadQuery | ErrorCode::TooLarge), "{e}");
                prop_assert!(e.message.starts_with("plan request"), "{e}");
            }
        }
    }
}

/// JSON documents shaped roughly like plan requests, with wrong types mixed in.
fn json_text() -> impl Strategy<Value = String> {
    let leaf = prop_oneof![
        Just(serde_json::Value::Null),
        any::<bool>().prop_map(serde_json::Value::Bool),
        any::<i64>().prop_map(|n| serde_json::json!(n)),
        any::<f64>().prop_map(|n| serde_json::json!(n)),
        "[a-z ]{0,10}".prop_map(serde_json::Value::String),
        (0..gen::LABELS.len()).prop_map(|i| serde_json::json!(gen::LABELS[i])),
    ];
    let value = leaf.prop_recursive(4, 32, 6, |inner| {
        prop_oneof![
            proptest::collection::vec(inner.clone(), 0..6).prop_map(serde_json::Value::Array),
            proptest::collection::btree_map(
                prop_oneof![
                    Just("query".to_string()),
                    Just("type".to_string()),
                    Just("ingredients".to_string()),
                    Just("object".to_string()),
                    Just("state".to_string()),
                    Just("modify".to_string()),
                    Just("overrides".to_string()),
                    Just("id".to_string()),
                    "[a-z]{1,5}"
                ],
                inner,
                0..5,
            )
            .prop_map(|m| serde_json::Value::Object(m.into_iter().collect())),
        ]
    });
    prop_oneof![
        value.clone().prop_map(|v| v.to_string()),
        // a well-formed request with one field of a wrong type
        (value, 0..4usize).prop_map(|(v, slot)| {
            let mut req = serde_json::json!({"query": {"type": "salad", "ingredients": [{"object": "tomato", "state": "sliced"}]}});
            match slot {
                0 => req["query"]["type"] = v,
                1 => req["query"]["ingredients"] = v,
                2 => req["query"]["ingredients"][0]["object"] = v,
                _ => req["modify"] = v,
            }
            req.to_string()
        }),
        // cut JSON
        ("[ -~]{0,40}").prop_map(|s| format!("{{\"query\": {s}")),
    ]
}
