//! Development probe: for each name (arguments, or lines of standard input) prints its taxonomy category
//! and its top-5 FOON equivalents, and the time per lookup.
//! `cargo run --release --example similar_probe -- "poblano chile" molass`

use foon_core::similarity::ranking::EmbeddingSimilarity;
use foon_core::similarity::Similarity;
use std::io::BufRead;
use std::path::PathBuf;

fn main() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..");
    let shared = std::env::var_os("FOON_SHARED")
        .map(PathBuf::from)
        .unwrap_or_else(|| root.join("../shared"));
    let bytes = std::fs::read(root.join("public/data/food-embeddings.bin")).expect("table");
    let start = std::time::Instant::now();
    let sim = EmbeddingSimilarity::from_bytes(&bytes).expect("valid table");
    eprintln!("table loaded in {:?}", start.elapsed());
    let dir = shared.join("foon/subgraphs-plain");
    let mut files: Vec<(String, Vec<u8>)> = std::fs::read_dir(&dir)
        .expect("FOON-111")
        .map(|e| e.unwrap().path())
        .map(|p| (p.display().to_string(), std::fs::read(&p).unwrap()))
        .collect();
    files.sort();
    let kb = foon_core::load(&files).expect("FOON-111 loads");
    let labels: Vec<&str> = kb.ingredient_labels().into_iter().collect();
    let mut names: Vec<String> = std::env::args().skip(1).collect();
    if names.is_empty() {
        names = std::io::stdin()
            .lock()
            .lines()
            .map_while(|l| l.ok())
            .collect();
    }
    let start = std::time::Instant::now();
    for name in &names {
        let ranked = sim.rank(name, &labels, 5);
        let cat = sim
            .category_of(name)
            .map(|c| format!("{}/{}", c.group, c.name))
            .unwrap_or_else(|| "-".into());
        let shown: Vec<String> = ranked
            .iter()
            .map(|(l, s)| {
                let flag = if sim.low_confidence(name, l, *s) {
                    "?"
                } else {
                    ""
                };
                format!("{l} {s:.2}{flag}")
            })
            .collect();
        println!("{name:>28} [{cat}] -> {}", shown.join(" | "));
    }
    if !names.is_empty() {
        eprintln!(
            "{:?} per lookup over {} labels (cold cache)",
            start.elapsed() / names.len() as u32,
            labels.len()
        );
    }
}
