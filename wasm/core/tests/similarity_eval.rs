//! Substitution quality on the project's development set (`tests/data/substitution-dev.tsv`): top-1 and
//! top-5 acceptable FOON-111 equivalents for each variant, printed with eprintln (run with
//! `cargo test --test similarity_eval -- --nocapture`). The shipped configuration must stay above a floor.

mod common;

use foon_core::similarity::ranking::{EmbeddingSimilarity, Options};
use foon_core::similarity::Similarity;
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
    /// (similarity of the first candidate, whether it is acceptable) per query
    firsts: Vec<(f32, bool)>,
    /// (flagged low-confidence, acceptable) of the first candidate per query
    flags: Vec<(bool, bool)>,
}

fn flag_report(name: &str, flags: &[(bool, bool)]) {
    let unflagged: Vec<bool> = flags
        .iter()
        .filter(|(f, _)| !f)
        .map(|(_, ok)| *ok)
        .collect();
    let right = unflagged.iter().filter(|ok| **ok).count();
    let wrong = flags.iter().filter(|(_, ok)| !ok).count();
    let caught = flags.iter().filter(|(f, ok)| *f && !ok).count();
    eprintln!(
        "low-confidence flag ({name}): {:4.1}% of first candidates flagged; {:5.1}% of the unflagged acceptable; {caught}/{wrong} wrong ones flagged",
        100.0 * (flags.len() - unflagged.len()) as f32 / flags.len().max(1) as f32,
        100.0 * right as f32 / unflagged.len().max(1) as f32,
    );
}

/// For the low-confidence flag: share of queries flagged and top-1 accuracy of those not flagged.
fn calibration(name: &str, firsts: &[(f32, bool)], thresholds: &[f32]) {
    for &t in thresholds {
        let kept: Vec<bool> = firsts
            .iter()
            .filter(|(s, _)| *s >= t)
            .map(|(_, ok)| *ok)
            .collect();
        let right = kept.iter().filter(|ok| **ok).count();
        let wrong_flagged = firsts.iter().filter(|(s, ok)| *s < t && !ok).count();
        let wrong = firsts.iter().filter(|(_, ok)| !ok).count();
        eprintln!(
            "  {name}: flag below {t:.2}: {:4.1}% flagged, unflagged top-1 {:5.1}%, {wrong_flagged}/{wrong} errors flagged",
            100.0 * (firsts.len() - kept.len()) as f32 / firsts.len() as f32,
            100.0 * right as f32 / kept.len().max(1) as f32,
        );
    }
}

fn evaluate(sim: &dyn Similarity, labels: &[&str], dev: &[(String, Vec<String>)]) -> Score {
    let (mut t1, mut t5) = (0, 0);
    let mut misses = Vec::new();
    let mut firsts = Vec::new();
    let mut flags = Vec::new();
    for (q, ok) in dev {
        let ranked = sim.rank(&foon_core::foon::label::normalize_label(q), labels, 5);
        let hit = |(l, _): &(String, f32)| ok.contains(l);
        if let Some(first) = ranked.first() {
            firsts.push((first.1, hit(first)));
            let query = foon_core::foon::label::normalize_label(q);
            flags.push((sim.low_confidence(&query, &first.0, first.1), hit(first)));
        }
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
        firsts,
        flags,
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
    // Generalisation: the same with the dev names taken out of the taxonomy (and of the alias list),
    // so that they are handled as unlisted names are (inferred category, vectors, lexical rules).
    let names: Vec<&str> = dev.iter().map(|(q, _)| q.as_str()).collect();
    let taxonomy = foon_core::vocab::food_taxonomy::Taxonomy::builtin().without(&names);
    let all_aliases = foon_core::vocab::food_taxonomy::aliases();
    let dev_keys: Vec<String> = names
        .iter()
        .map(|n| foon_core::foon::label::normalize_label(n))
        .collect();
    let kept_aliases = all_aliases
        .iter()
        .filter(|(a, _)| !dev_keys.contains(a))
        .map(|(a, b)| (a.clone(), b.clone()))
        .collect();
    sim = sim.with_options(base.clone());
    let sim = sim.with_taxonomy_and_aliases(taxonomy.clone(), (**all_aliases).clone());
    let s = evaluate(&sim, &labels, &dev);
    eprintln!(
        "{:<50} top-1 {:5.1}%  top-5 {:5.1}%",
        "shipped, dev names not in the taxonomy",
        100.0 * s.top1,
        100.0 * s.top5
    );
    let sim = sim.with_taxonomy_and_aliases(taxonomy, kept_aliases);
    let held = evaluate(&sim, &labels, &dev);
    eprintln!(
        "{:<50} top-1 {:5.1}%  top-5 {:5.1}%",
        "shipped, dev names in neither taxonomy nor aliases",
        100.0 * held.top1,
        100.0 * held.top5
    );
    if std::env::var_os("FOON_SHOW_MISSES").is_some() {
        for m in &held.misses {
            eprintln!("unlisted miss: {m}");
        }
    }
    let s = shipped.unwrap();
    let thresholds = [0.7, 0.8, 0.85, 0.9, 0.93, 0.95];
    calibration("listed", &s.firsts, &thresholds);
    calibration("unlisted", &held.firsts, &thresholds);
    flag_report("listed", &s.flags);
    flag_report("unlisted", &held.flags);
    if std::env::var_os("FOON_SHOW_MISSES").is_some() {
        for m in &s.misses {
            eprintln!("miss: {m}");
        }
    }
    // floors a few points below the measured figures, so that regressions fail
    assert!(
        held.top1 >= 0.68,
        "unlisted top-1 {:.3} fell below the floor",
        held.top1
    );
    assert!(
        held.top5 >= 0.80,
        "unlisted top-5 {:.3} fell below the floor",
        held.top5
    );
    assert!(s.top1 >= 0.83, "top-1 {:.3} fell below the floor", s.top1);
    assert!(s.top5 >= 0.94, "top-5 {:.3} fell below the floor", s.top5);
}

/// Grid over the main weights, on the dev set as listed and with the dev names unlisted (ignored: run
/// with `cargo test --release --test similarity_eval -- --ignored --nocapture` when retuning).
#[test]
#[ignore]
fn weight_grid() {
    let bytes = std::fs::read(repo().join("public/data/food-embeddings.bin")).unwrap();
    let kb = common::load(&common::foon111("plain"));
    let labels: Vec<&str> = kb.ingredient_labels().into_iter().collect();
    let dev = dev_set();
    let names: Vec<&str> = dev.iter().map(|(q, _)| q.as_str()).collect();
    let taxonomy = foon_core::vocab::food_taxonomy::Taxonomy::builtin().without(&names);
    let mut sim = EmbeddingSimilarity::from_bytes(&bytes).unwrap();
    for head in [1.0f32, 1.5, 2.0] {
        for cat in [0.2f32, 0.3, 0.45] {
            for group in [0.05f32, 0.12, 0.2] {
                for other in [0.0f32, 0.15, 0.3] {
                    let o = Options {
                        head_weight: head,
                        same_category: cat,
                        same_group: group,
                        other_group: other,
                        ..Options::default()
                    };
                    sim = sim.with_options(o);
                    let listed = evaluate(&sim, &labels, &dev);
                    let unlisted_sim = sim.with_taxonomy_and_aliases(
                        taxonomy.clone(),
                        (**foon_core::vocab::food_taxonomy::aliases()).clone(),
                    );
                    let unlisted = evaluate(&unlisted_sim, &labels, &dev);
                    eprintln!(
                        "head {head} cat {cat} group {group} other {other}: listed {:.1}/{:.1} unlisted {:.1}/{:.1}",
                        100.0 * listed.top1,
                        100.0 * listed.top5,
                        100.0 * unlisted.top1,
                        100.0 * unlisted.top5
                    );
                    sim = unlisted_sim.with_taxonomy_and_aliases(
                        foon_core::vocab::food_taxonomy::Taxonomy::builtin()
                            .as_ref()
                            .clone(),
                        (**foon_core::vocab::food_taxonomy::aliases()).clone(),
                    );
                }
            }
        }
    }
}
