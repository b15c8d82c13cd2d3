//! Shared helpers for the integration tests that read the public data in `../shared`.
#![allow(dead_code)]

use foon_core::KnowledgeBase;
use std::path::PathBuf;

/// `../shared` beside the repository, or `$FOON_SHARED`.
pub fn shared_dir() -> PathBuf {
    let dir = std::env::var_os("FOON_SHARED")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../../shared"));
    assert!(
        dir.join("foon").is_dir(),
        "the shared data folder is missing at {} (set FOON_SHARED)",
        dir.display()
    );
    dir
}

/// (file name, bytes) of every `.txt` file in a folder, in name order.
pub fn read_dir(dir: &std::path::Path) -> Vec<(String, Vec<u8>)> {
    let mut files: Vec<(String, Vec<u8>)> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
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
    files
}

pub fn foon111(dialect: &str) -> Vec<(String, Vec<u8>)> {
    read_dir(
        &shared_dir()
            .join("foon")
            .join(format!("subgraphs-{dialect}")),
    )
}

pub fn load(files: &[(String, Vec<u8>)]) -> KnowledgeBase {
    foon_core::load(files).unwrap_or_else(|e| panic!("{e}"))
}

/// The shipped food embedding table (`public/data/food-embeddings.bin`).
pub fn embeddings() -> foon_core::EmbeddingSimilarity {
    let path =
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../public/data/food-embeddings.bin");
    let bytes = std::fs::read(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    foon_core::EmbeddingSimilarity::from_bytes(&bytes).unwrap_or_else(|e| panic!("{e}"))
}

/// The dev recipe queries of `../shared/recipes/dev/<type>/<id>.json`, as (path, query), sorted by path.
pub fn dev_queries() -> Vec<(String, foon_core::Query)> {
    let dir = shared_dir().join("recipes").join("dev");
    let mut paths = Vec::new();
    for class in std::fs::read_dir(&dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display())) {
        for file in std::fs::read_dir(class.unwrap().path()).unwrap() {
            let path = file.unwrap().path();
            if path.extension().is_some_and(|x| x == "json") {
                paths.push(path);
            }
        }
    }
    paths.sort();
    paths
        .into_iter()
        .map(|p| {
            let query = serde_json::from_slice(&std::fs::read(&p).unwrap())
                .unwrap_or_else(|e| panic!("{}: {e}", p.display()));
            (p.display().to_string(), query)
        })
        .collect()
}

/// The project's starter knowledge base (`public/kb/starter/*.txt`).
pub fn starter_kb_files() -> Vec<(String, Vec<u8>)> {
    read_dir(&PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../public/kb/starter"))
}

/// Every dev query planned on FOON-111 (plain) with and without modification, in query order:
/// (modified?, plan).
pub fn dev_plans(sim: &dyn foon_core::similarity::Similarity) -> Vec<(bool, foon_core::Plan)> {
    let kb = load(&foon111("plain"));
    let index = foon_core::PlannerIndex::new(&kb);
    let mut plans = Vec::new();
    for (_, q) in dev_queries() {
        for modify in [true, false] {
            let mut request = foon_core::PlanRequest::new(q.clone());
            request.modify = modify;
            let p = foon_core::plan(&kb, &index, sim, &request).unwrap_or_else(|e| panic!("{e}"));
            plans.push((modify, p));
        }
    }
    plans
}
pub mod hand;
