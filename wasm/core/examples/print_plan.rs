//! Development tool: one plan on FOON-111, unit by unit, with its outcomes, progress lines and cautions.
//! `cargo run --example print_plan -- QUERY.json [--exact] [--no-modify]` (`FOON_DIR` for another folder).

use foon_core::contract::plan::PlanNode;
use foon_core::planner::violations;
use foon_core::similarity::{ExactMatch, Similarity};
use foon_core::{plan, EmbeddingSimilarity, PlanRequest, PlannerIndex, Query};
use std::path::PathBuf;
use std::sync::Arc;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let flag = |name: &str| args.iter().any(|a| a == name);
    let query = args
        .iter()
        .find(|a| !a.starts_with("--"))
        .expect("a query file");
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..");
    let dir = std::env::var_os("FOON_DIR")
        .map(PathBuf::from)
        .unwrap_or(root.join("../shared/foon/subgraphs-plain"));
    let mut files: Vec<(String, Vec<u8>)> = std::fs::read_dir(&dir)
        .expect("FOON folder")
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "txt"))
        .map(|p| (p.display().to_string(), std::fs::read(&p).unwrap()))
        .collect();
    files.sort();
    let kb = foon_core::load(&files).unwrap_or_else(|e| panic!("{e}"));
    let index = PlannerIndex::new(&kb);
    let table =
        std::fs::read(root.join("public/data/food-embeddings.bin")).expect("embedding table");
    let embeddings = EmbeddingSimilarity::from_bytes(&table).unwrap_or_else(|e| panic!("{e}"));
    let sim: &dyn Similarity = if flag("--exact") {
        &ExactMatch
    } else {
        &embeddings
    };
    let q: Query =
        serde_json::from_slice(&std::fs::read(query).expect("query file")).expect("query JSON");
    let mut request = PlanRequest::new(q);
    request.modify = !flag("--no-modify");
    let p = plan(&kb, &index, sim, &request).unwrap_or_else(|e| panic!("{e}"));
    let show = |nodes: &[Arc<PlanNode>]| {
        let nodes: Vec<String> = nodes
            .iter()
            .map(|n| format!("{}({})", n.label, n.states.join("; ")))
            .collect();
        nodes.join(" + ")
    };
    for (i, (u, s)) in p.units.iter().zip(&p.steps).enumerate() {
        let (inputs, outputs) = (show(&u.inputs), show(&u.outputs));
        println!(
            "{i:2} [{:?}] {inputs} --{}--> {outputs}\n     {s} {:?}",
            u.origin, u.motion, u.sources
        );
    }
    for o in &p.ingredients {
        let matched = o.matched.as_ref().map(|m| (&m.label, &m.state));
        println!(
            "{} ({}) case {:?} {matched:?} {:?} {:?}",
            o.object, o.state, o.case, o.status, o.reason
        );
    }
    for line in &p.progress_lines {
        println!("line {line:?}");
    }
    println!(
        "goal {:?}\nremoved {:?}\nnotes {:?}\ncautions {:?}",
        p.goal, p.removed, p.notes, p.cautions
    );
    for v in violations(&p) {
        println!("VIOLATION {v}");
    }
}
