//! Fuzz target for the plan-request decoder and the planner behind it, on the starter knowledge base with
//! the shipped embedding table (as the app runs). Whatever the text: no panic; a decode error is
//! `bad_query` or `too_large` with a line and column; a decoded request either plans — no unit twice, every
//! unit after the units making its inputs, one step per unit — or fails with a typed error.
#![no_main]

use foon_core::contract::plan::{Plan, PlanNode};
use foon_core::contract::decode;
use foon_core::{load, EmbeddingSimilarity, ErrorCode, KnowledgeBase, PlannerIndex};
use libfuzzer_sys::fuzz_target;
use std::collections::HashSet;
use std::path::PathBuf;
use std::sync::{Arc, OnceLock};

struct World {
    kb: KnowledgeBase,
    index: PlannerIndex,
    sim: EmbeddingSimilarity,
}

fn world() -> &'static World {
    static WORLD: OnceLock<World> = OnceLock::new();
    WORLD.get_or_init(|| {
        let repo = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..");
        let mut files: Vec<(String, Vec<u8>)> = std::fs::read_dir(repo.join("public/kb/starter"))
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.extension().is_some_and(|x| x == "txt"))
            .map(|p| {
                (
                    p.file_name().unwrap().to_string_lossy().into_owned(),
                    std::fs::read(&p).unwrap(),
                )
            })
            .collect();
        files.sort();
        let kb = load(&files).unwrap();
        let index = PlannerIndex::new(&kb);
        let bytes = std::fs::read(repo.join("public/data/food-embeddings.bin")).unwrap();
        let sim = EmbeddingSimilarity::from_bytes(&bytes).unwrap();
        World { kb, index, sim }
    })
}

fn key(n: &Arc<PlanNode>) -> String {
    let mut states = n.states.clone();
    states.sort();
    format!("{} ({})", n.label, states.join(", "))
}

fn check_plan(plan: &Plan) {
    assert_eq!(plan.steps.len(), plan.units.len());
    let made: Vec<HashSet<String>> = plan
        .units
        .iter()
        .map(|u| {
            let ins: HashSet<String> = u.inputs.iter().map(key).collect();
            u.outputs
                .iter()
                .map(key)
                .filter(|n| !ins.contains(n))
                .collect()
        })
        .collect();
    let mut seen = HashSet::new();
    for (i, u) in plan.units.iter().enumerate() {
        let mut ins: Vec<String> = u.inputs.iter().map(key).collect();
        ins.sort();
        let mut outs: Vec<String> = u.outputs.iter().map(key).collect();
        outs.sort();
        assert!(
            seen.insert((ins, u.motion.clone(), outs)),
            "unit {} twice",
            i + 1
        );
        for n in u.inputs.iter().map(key) {
            let later = made[i + 1..].iter().any(|m| m.contains(&n));
            let earlier = made[..i].iter().any(|m| m.contains(&n));
            assert!(
                !later || earlier,
                "unit {} uses '{n}' made only later",
                i + 1
            );
        }
    }
    // the exports render without panicking
    let _ = foon_core::foon_text(plan);
    let _ = foon_core::progress_json(plan);
    let _ = foon_core::pddl(plan);
    let _ = serde_json::to_string(plan).expect("a plan serialises");
}

fuzz_target!(|data: &[u8]| {
    // JavaScript strings reach the decoder as UTF-8; other bytes cannot come from the app
    let Ok(json) = std::str::from_utf8(data) else {
        return;
    };
    match decode::plan_request(json) {
        Err(e) => {
            assert!(
                matches!(e.code, ErrorCode::BadQuery | ErrorCode::TooLarge),
                "{e}"
            );
            assert!(
                e.code == ErrorCode::TooLarge || e.line.is_some_and(|l| l >= 1),
                "{e}"
            );
        }
        Ok(request) => {
            let w = world();
            match foon_core::plan(&w.kb, &w.index, &w.sim, &request) {
                Ok(plan) => check_plan(&plan),
                Err(e) => assert!(
                    matches!(
                        e.code,
                        ErrorCode::BadQuery | ErrorCode::NoGoal | ErrorCode::TooLarge
                    ),
                    "{e}"
                ),
            }
        }
    }
});
