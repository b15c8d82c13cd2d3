//! Development probe: native plan times over the dev queries on FOON-111, for profiling the planner
//! without the WASM boundary (`npm run bench` gives the figures that count).
//! `cargo run --release --example plan_timing -- [rounds]` (`FOON_DIR` for another FOON folder); under
//! `perf record` or `valgrind --tool=callgrind` for a profile.

use foon_core::{
    plan, write_plan_json, EmbeddingSimilarity, Plan, PlanRequest, PlannerIndex, Query,
};
use std::path::{Path, PathBuf};
use std::time::Instant;

fn txt_files(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut files: Vec<(String, Vec<u8>)> = std::fs::read_dir(dir)
        .expect("FOON folder")
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "txt"))
        .map(|p| (p.display().to_string(), std::fs::read(&p).unwrap()))
        .collect();
    files.sort();
    files
}

fn dev_queries(dir: &Path) -> Vec<Query> {
    let mut paths: Vec<PathBuf> = std::fs::read_dir(dir)
        .expect("recipes/dev")
        .flat_map(|class| std::fs::read_dir(class.unwrap().path()).unwrap())
        .map(|f| f.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .collect();
    paths.sort();
    paths
        .iter()
        .map(|p| serde_json::from_slice(&std::fs::read(p).unwrap()).expect("query JSON"))
        .collect()
}

/// The plan's JSON into `text` (cleared), as the WASM layer writes it, then the plan dropped: a
/// function of its own, for a profile of the output side (`--toggle-collect='*write_json*'`).
#[inline(never)]
fn write_json(p: Plan, text: &mut Vec<u8>) -> usize {
    text.clear();
    write_plan_json(&p, text);
    text.len()
}

fn main() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..");
    let shared = std::env::var_os("FOON_SHARED")
        .map(PathBuf::from)
        .unwrap_or_else(|| root.join("../shared"));
    let rounds: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(3);
    let table = std::fs::read(root.join("public/data/food-embeddings.bin")).expect("table");
    // FOON_DIR: another folder of FOON files (a scaled copy, for instance)
    let dir = std::env::var_os("FOON_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| shared.join("foon/subgraphs-plain"));
    let files = txt_files(&dir);
    let started = Instant::now();
    let kb = foon_core::load(&files).expect("FOON-111 loads");
    let index = PlannerIndex::new(&kb);
    let sim = EmbeddingSimilarity::from_bytes(&table).expect("valid table");
    println!(
        "load (parse + merge + index + embeddings) of {} files: {:?}",
        files.len(),
        started.elapsed()
    );
    let queries = dev_queries(&shared.join("recipes/dev"));
    let mut times = Vec::new();
    let mut text = Vec::new();
    for _ in 0..rounds {
        for q in &queries {
            let started = Instant::now();
            let p = plan(&kb, &index, &sim, &PlanRequest::new(q.clone()));
            // as the WASM layer writes it: into one buffer kept from plan to plan
            let json = p.map(|p| write_json(p, &mut text));
            times.push(started.elapsed().as_secs_f64() * 1e3);
            std::hint::black_box(json.ok());
        }
    }
    if times.is_empty() {
        return;
    }
    times.sort_by(f64::total_cmp);
    let at = |p: f64| times[((p * times.len() as f64) as usize).min(times.len() - 1)];
    println!(
        "plan + JSON ({} queries x {rounds}): median {:.3} ms, p95 {:.3} ms, max {:.3} ms",
        queries.len(),
        at(0.5),
        at(0.95),
        times[times.len() - 1]
    );
}
