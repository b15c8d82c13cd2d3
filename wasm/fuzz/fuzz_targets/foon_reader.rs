//! Fuzz target for the FOON reader, the bundle splitter and the universal-FOON merge.
//! Whatever the bytes, nothing panics, and:
//! - a read subgraph is well formed (every unit has inputs, a motion and outputs; labels are non-empty,
//!   within the limit and already in normal form), and its FOON text reads back to the same units;
//! - an error names its file and has a message; a warning names file and line;
//! - the bytes as a knowledge base, split into two files, merge to the same universal FOON in either order,
//!   and the knowledge base exported as a bundle re-imports to the same nodes, units and goals.
#![no_main]

use foon_core::foon::label::{normalize_label, normalize_word};
use foon_core::foon::read::{parse_bytes, parse_str, ParsedObject, Subgraph};
use foon_core::foon::write;
use foon_core::{limits, load, KnowledgeBase};
use libfuzzer_sys::fuzz_target;

type Shape = Vec<(
    Vec<(String, bool, Option<Option<u32>>)>,
    String,
    Vec<String>,
    Vec<(String, bool, Option<Option<u32>>)>,
)>;

fn objects(list: &[ParsedObject]) -> Vec<(String, bool, Option<Option<u32>>)> {
    list.iter()
        .map(|o| {
            (
                o.node.to_string(),
                o.moves,
                o.goal.as_ref().map(|g| g.dish_class),
            )
        })
        .collect()
}

fn shape(g: &Subgraph) -> Shape {
    g.units
        .iter()
        .map(|u| {
            (
                objects(&u.inputs),
                u.motion.clone(),
                u.times.clone(),
                objects(&u.outputs),
            )
        })
        .collect()
}

fn check_label(text: &str, label: bool) {
    assert!(!text.is_empty());
    assert!(text.chars().count() <= limits::MAX_LABEL_CHARS);
    let again = if label {
        normalize_label(text)
    } else {
        normalize_word(text)
    };
    assert_eq!(again, text, "not in normal form");
}

fn check_subgraph(g: &Subgraph) {
    for u in &g.units {
        assert!(!u.inputs.is_empty() && !u.outputs.is_empty());
        check_label(&u.motion, false);
        for o in u.inputs.iter().chain(u.outputs.iter()) {
            check_label(&o.node.label, true);
            for s in &o.node.states {
                check_label(&s.name, false);
            }
        }
    }
    for w in &g.warnings {
        assert!(w.file.is_some() && w.line.is_some() && !w.message.is_empty());
    }
}

fn check_kb(kb: &KnowledgeBase) {
    assert!(!kb.units.is_empty());
    for (id, u) in kb.each_unit() {
        for n in u.input_nodes() {
            assert!(kb.consumers[n].contains(&id));
        }
        for n in u.output_nodes() {
            assert!(kb.producers[n].contains(&id));
        }
    }
    // exported as a bundle and read back: the same universal FOON
    let text = write::kb_bundle(kb);
    let again =
        load(&[("export.foon".to_string(), text.into_bytes())]).expect("an exported KB reads back");
    assert_eq!(again.nodes, kb.nodes);
    assert_eq!(again.units, kb.units);
    assert_eq!(again.provenance, kb.provenance);
    assert_eq!(again.goals, kb.goals);
    assert_eq!(again.kitchen, kb.kitchen);
}

fuzz_target!(|data: &[u8]| {
    match parse_bytes("fuzz.txt", data) {
        Ok(g) => {
            check_subgraph(&g);
            let text = write::subgraph_text(&g);
            let again = parse_str("fuzz.txt", &text).expect("written FOON text reads back");
            assert_eq!(shape(&again), shape(&g));
            assert!(
                again.warnings.is_empty(),
                "written text has warnings: {:?}",
                again.warnings
            );
        }
        Err(e) => assert!(e.file.as_deref() == Some("fuzz.txt") && !e.message.is_empty()),
    }
    if let Ok(kb) = load(&[("fuzz.foon".to_string(), data.to_vec())]) {
        check_kb(&kb);
    }
    // two files, merged in both orders (split after a line end chosen by the first byte)
    if let Some(&pick) = data.first() {
        let want = data.len() * pick as usize / 256;
        let cut = data[want..]
            .iter()
            .position(|&b| b == b'\n')
            .map_or(data.len(), |p| want + p + 1);
        let (a, b) = data.split_at(cut);
        let files = [
            ("a.txt".to_string(), a.to_vec()),
            ("b.txt".to_string(), b.to_vec()),
        ];
        let forward = load(&files);
        let backward = load(&[files[1].clone(), files[0].clone()]);
        match (forward, backward) {
            (Ok(x), Ok(y)) => assert_eq!(x, y, "merge depends on file order"),
            // with two bad files the first one's error is reported, so the errors may differ
            (Err(_), Err(_)) => {}
            (x, y) => panic!(
                "one order loads, the other does not: {:?} / {:?}",
                x.err(),
                y.err()
            ),
        }
    }
});
