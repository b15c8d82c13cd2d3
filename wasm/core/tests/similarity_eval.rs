//! Substitution quality on the project's development set (`tests/data/substitution-dev.tsv`): top-1 and
//! top-5 acceptable FOON-111 equivalents for each variant, printed with eprintln (run with
//! `cargo test --test similarity_eval -- --nocapture`). The shipped configuration must stay above a floor.

mod common;

use foon_core::similarity::Similarity;
use foon_core::substitute::{EmbeddingSimilarity, Options};
use std::path::PathBuf;

fn repo() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn dev_set() -> Vec<(String, Vec<String>)> {
    let text = std::fs::read_to_string(repo().join("tests/data/substitution-dev.tsv")).unwrap();
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .filter_map(|l| l.split_once('\t'))
        .filter(|(_, ok)| ok.trim() != "-")
        .map(|(q, ok)| (q.to_string(), ok.split('|').map(str::to_string).collect()))
        .collect()
}

struct Score {
    top1: f32,
    top5: f32,
    misses: Vec<String>,
}

fn evaluate(sim: &dyn Similarity, labels: &[&str], dev: &[(String, Vec<String>)]) -> Score {
    let (mut t1, mut t5) = (0, 0);
    let mut misses = Vec::new();
    for (q, ok) in dev {
        let ranked = sim.rank(&foon_core::label::normalize_label(q), labels, 5);
        let hit = |(l, _): &(String, f32)| ok.contains(l);
        if ranked.first().is_some_and(hit) {
            t1 += 1;
        } else {
            let shown: Vec<String> = ranked.iter().map(|(l, s)| format!("{l} {s:.2}")).collect();
            misses.push(format!("{q:>24} -> {}", shown.join(" | ")));
        }
        if ranked.iter().any(hit) {
            t5 += 1;
        }
    }
    let n = dev.len() as f32;
    Score {
        top1: t1 as f32 / n,
        top5: t5 as f32 / n,
        misses,
    }
}

#[test]
fn substitution_quality_on_the_dev_set() {
    let bytes = std::fs::read(repo().join("public/data/food-embeddings.bin")).unwrap();
    let kb = common::load(&common::foon111("plain"));
    let labels: Vec<&str> = kb.ingredient_labels().into_iter().collect();
    let dev = dev_set();
    let base = Options::default();
    let variants: Vec<(&str, Options)> = vec![
        (
            "cosine only (published approach, food vectors)",
            Options::cosine_only(),
        ),
        (
            "+ base ingredients only, exact/stem first",
            Options {
                filter_composites: true,
                exact_first: true,
                ..Options::cosine_only()
            },
        ),
        (
            "+ aliases",
            Options {
                filter_composites: true,
                exact_first: true,
                aliases: true,
                ..Options::cosine_only()
            },
        ),
        (
            "+ head word weighted",
            Options {
                filter_composites: true,
                exact_first: true,
                aliases: true,
                head_weight: base.head_weight,
                ..Options::cosine_only()
            },
        ),
        (
            "+ taxonomy categories (listed names only)",
            Options {
                same_head: 0.0,
                shared_word: 0.0,
                infer_category_above: 2.0,
                ..base.clone()
            },
        ),
        (
            "+ inferred categories for unlisted names",
            Options {
                same_head: 0.0,
                shared_word: 0.0,
                ..base.clone()
            },
        ),
        ("+ lexical head/modifier (shipped)", base.clone()),
    ];
    let mut shipped = None;
    let mut sim = EmbeddingSimilarity::from_bytes(&bytes).unwrap();
    eprintln!(
        "dev set: {} names with acceptable FOON-111 equivalents",
        dev.len()
    );
    for (name, options) in variants {
        sim = sim.with_options(options.clone());
        let s = evaluate(&sim, &labels, &dev);
        eprintln!(
            "{name:<50} top-1 {:5.1}%  top-5 {:5.1}%",
            100.0 * s.top1,
            100.0 * s.top5
        );
        if options == base {
            shipped = Some(s);
        }
    }
    let s = shipped.unwrap();
    if std::env::var_os("FOON_SHOW_MISSES").is_some() {
        for m in &s.misses {
            eprintln!("miss: {m}");
        }
    }
    assert!(s.top1 >= 0.80, "top-1 {:.3} fell below the floor", s.top1);
    assert!(s.top5 >= 0.93, "top-5 {:.3} fell below the floor", s.top5);
}
