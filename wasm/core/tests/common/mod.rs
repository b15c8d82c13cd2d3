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
