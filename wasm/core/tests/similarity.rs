//! The shipped embedding table and the substitution layer: loading and checksum, exact first, unknown
//! words, multi-word phrases, category filtering, and the `similar` JSON.

mod common;

use foon_core::error::ErrorCode;
use foon_core::similarity::ranking::{similar, EmbeddingSimilarity};
use foon_core::similarity::Similarity;
use std::path::PathBuf;
use std::sync::OnceLock;

fn repo() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn table_bytes() -> &'static [u8] {
    static BYTES: OnceLock<Vec<u8>> = OnceLock::new();
    BYTES.get_or_init(|| std::fs::read(repo().join("public/data/food-embeddings.bin")).unwrap())
}

fn sim() -> &'static EmbeddingSimilarity {
    static SIM: OnceLock<EmbeddingSimilarity> = OnceLock::new();
    SIM.get_or_init(|| EmbeddingSimilarity::from_bytes(table_bytes()).unwrap())
}

fn foon() -> &'static foon_core::KnowledgeBase {
    static KB: OnceLock<foon_core::KnowledgeBase> = OnceLock::new();
    KB.get_or_init(|| common::load(&common::foon111("plain")))
}

fn labels() -> Vec<&'static str> {
    foon().ingredient_labels().into_iter().collect()
}

/// The labels as a knowledge base's index holds them (a candidate set for `prepare` and `rank_in_set`).
fn owned_labels() -> Vec<String> {
    labels().into_iter().map(str::to_string).collect()
}

fn top(query: &str, n: usize) -> Vec<String> {
    sim()
        .rank(query, &labels(), n)
        .into_iter()
        .map(|(l, _)| l)
        .collect()
}

#[test]
fn the_shipped_table_loads_and_matches_its_checksum_file() {
    let t = sim().table();
    assert_eq!(t.dims(), 35);
    assert!(t.len() > 6_000, "{} words", t.len());
    // public/data/food-embeddings.bin.sha256 is written by the build script next to the table
    let line =
        std::fs::read_to_string(repo().join("public/data/food-embeddings.bin.sha256")).unwrap();
    assert!(line.ends_with("  food-embeddings.bin\n"), "{line:?}");
    assert_eq!(line.split(' ').next().unwrap().len(), 64);
}

#[test]
fn a_damaged_table_is_bad_embeddings_never_a_panic() {
    let good = table_bytes();
    // one flipped bit anywhere: the CRC catches it
    for at in [
        9,
        30,
        1_000,
        good.len() / 2,
        good.len() - 10,
        good.len() - 1,
    ] {
        let mut bytes = good.to_vec();
        bytes[at] ^= 0x10;
        let e = EmbeddingSimilarity::from_bytes(&bytes).unwrap_err();
        assert_eq!(e.code, ErrorCode::BadEmbeddings, "byte {at}: {e}");
    }
    // truncated anywhere
    for len in [0, 7, 8, 12, 27, 28, 5_000, good.len() - 4, good.len() - 1] {
        let e = EmbeddingSimilarity::from_bytes(&good[..len]).unwrap_err();
        assert_eq!(e.code, ErrorCode::BadEmbeddings, "length {len}");
    }
    // another version (version 1 had a scale per row), even with a consistent checksum
    let mut other = good[..good.len() - 4].to_vec();
    other[8] = 1;
    let crc = foon_core::similarity::table::crc32(&other);
    other.extend_from_slice(&crc.to_le_bytes());
    let e = EmbeddingSimilarity::from_bytes(&other).unwrap_err();
    assert_eq!(e.code, ErrorCode::BadEmbeddings);
    assert!(e.message.contains("version"), "{}", e.message);
}

#[test]
fn exact_labels_map_to_themselves_first() {
    for label in [
        "lemon",
        "olive oil",
        "chicken stock",
        "egg mixture",
        "cream cheese",
    ] {
        let ranked = sim().rank(label, &labels(), 5);
        assert_eq!(ranked[0], (label.to_string(), 1.0), "{label}");
        assert!(ranked[1..].iter().all(|(_, s)| *s < 1.0));
        assert_eq!(sim().similarity(label, label), 1.0);
    }
    // the same name through an alias or another word form is the same ingredient
    assert_eq!(top("cornstarch", 1), vec!["corn starch"]);
    assert_eq!(top("brussels sprouts", 1), vec!["brussel sprout"]);
    assert_eq!(top("Oat", 1), vec!["oats"]);
}

#[test]
fn unknown_words_give_no_candidates() {
    assert!(sim().rank("qwzxv", &labels(), 5).is_empty());
    assert!(sim().rank("", &labels(), 5).is_empty());
    assert_eq!(sim().similarity("qwzxv", "lemon"), 0.0);
    assert!(sim().low_confidence("qwzxv", "lemon", 0.0));
    // an unknown modifier does not hide a known head noun
    assert!(
        top("qwzxv lettuce", 5).contains(&"lettuce".to_string())
            || top("qwzxv lettuce", 1)[0] == "escarole"
    );
}

#[test]
fn words_without_a_vector_fall_back_to_their_parts_or_lost_plural() {
    let t = sim().table();
    assert!(!t.word_stems("asparagu").is_empty());
    assert_eq!(t.word_stems("gingerroot"), vec!["gingerroot"]);
    let parts = t.word_stems("garlicbutter");
    assert_eq!(parts, vec!["garlic", "butter"]);
    assert!(t.embed("qwzxv").vector.is_none());
    assert_eq!(t.embed("qwzxv tomato").unknown, vec!["qwzxv"]);
}

#[test]
fn multi_word_phrases_use_head_nouns_and_modifiers() {
    assert_eq!(top("red wine vinegar", 1), vec!["vinegar"]);
    assert!(
        ["chili pepper", "jalapeno", "green chilli"].contains(&top("poblano chile", 1)[0].as_str())
    );
    assert!(["walnut", "pine nut"].contains(&top("pecan halves", 1)[0].as_str()));
    assert_eq!(top("chicken bouillon", 1)[0], "chicken broth");
    assert_eq!(top("lime juice", 1), vec!["lime juice"]);
    assert_eq!(top("fresh lime juice", 1), vec!["lime juice"]);
}

#[test]
fn candidates_are_base_ingredients_of_the_same_category() {
    for q in [
        "spinach",
        "mozzarella cheese",
        "honey",
        "egg substitute",
        "rum",
    ] {
        for l in top(q, 5) {
            let cat = sim().category_of(&l).map(|c| c.group.clone());
            assert!(
                !matches!(cat.as_deref(), Some("dish") | Some("mixture")),
                "{q} -> {l} is a dish or mixture"
            );
        }
    }
    // the paper's error: an apricot is not squeezed like a lemon
    assert!(!top("apricot", 5)
        .iter()
        .any(|l| l == "lemon" || l == "lime"));
    assert_eq!(sim().category_of("apricot").unwrap().group, "fruit");
    assert!(top("apricot", 5)
        .iter()
        .all(|l| sim().category_of(l).unwrap().group == "fruit"));
    // the same category beats a close vector from another one
    assert_eq!(sim().category_of("kale").unwrap().name, "leafy green");
    assert!(top("kale", 3)
        .iter()
        .all(|l| sim().category_of(l).unwrap().group == "vegetable"));
    // a dish query may map to dishes
    assert!(top("cake", 1)[0].ends_with("cake"));
}

#[test]
fn similar_prints_the_cli_json() {
    let out = similar(
        foon(),
        sim(),
        &[
            "molass".to_string(),
            "Lemon".to_string(),
            "qwzxv".to_string(),
        ],
        3,
    );
    assert_eq!(out.len(), 3);
    assert_eq!(out[0].candidates.len(), 3);
    assert_eq!(out[1].candidates[0].label, "lemon");
    assert!(out[2].candidates.is_empty());
    let json = serde_json::to_value(&out).unwrap();
    assert_eq!(json[0]["query"], "molass");
    assert!(json[0]["candidates"][0]["label"].is_string());
    assert!(json[0]["candidates"][0]["similarity"].is_number());
    assert_eq!(json[1]["candidates"][0]["similarity"], 1.0);
}

#[test]
fn ranking_does_not_depend_on_candidate_order() {
    let mut reversed = labels();
    reversed.reverse();
    for q in ["honey", "pecan", "cumin"] {
        assert_eq!(sim().rank(q, &labels(), 5), sim().rank(q, &reversed, 5));
    }
}

#[test]
fn lookup_time() {
    // a timing print, not an assertion (cargo test --release --test similarity -- --nocapture lookup_time)
    let labels = labels();
    let queries = [
        "molass",
        "poblano chile",
        "cool whip",
        "watercres",
        "pecan half",
        "apricot",
    ];
    let start = std::time::Instant::now();
    let rounds = 20;
    for _ in 0..rounds {
        for q in queries {
            std::hint::black_box(sim().rank(q, &labels, 5));
        }
    }
    let per = start.elapsed() / (rounds * queries.len() as u32);
    let start = std::time::Instant::now();
    let loaded = EmbeddingSimilarity::from_bytes(table_bytes()).unwrap();
    let load = start.elapsed();
    std::hint::black_box(loaded);
    eprintln!(
        "rank against {} FOON-111 labels: {per:?} per query; table load: {load:?}",
        labels.len()
    );
}

#[test]
fn the_taxonomy_lists_every_foon111_ingredient_label() {
    let t = sim().taxonomy();
    let missing: Vec<&str> = labels()
        .into_iter()
        .filter(|l| t.lookup(l).is_none())
        .collect();
    assert!(missing.is_empty(), "not in the taxonomy: {missing:?}");
}

#[test]
fn a_prepared_name_scores_every_label_as_the_pairwise_similarity_does() {
    // the planner compares each query name with thousands of labels through `prepare`; it must agree
    // with `similarity` in both directions (the similarity is not symmetric for aliases and unknowns)
    let set = owned_labels();
    for name in [
        "tomato",
        "cool whip",
        "chili pepper",
        "molass",
        "qwzxv",
        "egg mixture",
        "",
    ] {
        let prepared = sim().prepare(name, 7, &set);
        for (i, label) in set.iter().enumerate() {
            assert_eq!(
                prepared.to(i),
                sim().similarity(name, label),
                "{name} -> {label}"
            );
            assert_eq!(
                prepared.from(i),
                sim().similarity(label, name),
                "{label} -> {name}"
            );
        }
        for i in 0..set.len() {
            assert_eq!(
                prepared.both(i),
                (prepared.to(i), prepared.from(i)),
                "{name} <-> {i}"
            );
        }
        assert_eq!(prepared.to(set.len()), 0.0, "out of range");
    }
}

#[test]
fn ranking_in_a_remembered_set_is_the_plain_ranking() {
    // `rank_in_set` keeps profiles and answers between calls and skips candidates that cannot place:
    // neither may change the answer
    let set = owned_labels();
    for name in [
        "cherry tomato",
        "whipped cream",
        "jalapeno",
        "brown sugar",
        "salt",
        "zzz",
    ] {
        for top in [1, 6] {
            let plain = sim().rank(name, &labels(), top);
            assert_eq!(*sim().rank_in_set(name, 11, &set, top), plain, "{name}");
            assert_eq!(
                *sim().rank_in_set(name, 11, &set, top),
                plain,
                "{name}, remembered"
            );
            for (label, s) in &plain {
                assert_eq!(*s, sim().similarity(name, label), "{name} ~ {label}");
            }
            // a ranking of every label never skips one: its head is the short ranking
            let mut all = sim().rank(name, &labels(), set.len());
            all.truncate(top);
            assert_eq!(all, plain, "{name}, top {top}");
        }
    }
    // the remembered set visits its vectors cone by cone, nearest first: every label as a query (an
    // exact match, then its neighbours) ranks as a scan of every label does
    for (i, name) in set.iter().enumerate().step_by(3) {
        let top = 1 + i % 7;
        let plain = sim().rank(name, &labels(), top);
        assert_eq!(*sim().rank_in_set(name, 11, &set, top), plain, "{name}");
    }
}
