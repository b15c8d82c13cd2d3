//! Properties of the FOON reader on random input: it never panics, whatever the bytes; what it accepts is
//! well formed; written back as FOON text it reads the same; and labels' normal form is stable.

mod gen;
use foon_core::foon::label::{normalize_label, normalize_word};
use foon_core::foon::read::{parse_bytes, parse_str, ParsedObject, Subgraph};
use foon_core::foon::write;
use foon_core::limits;
use proptest::prelude::*;

type Obj = (String, bool, Option<Option<u32>>);
type Shape = Vec<(Vec<Obj>, String, Vec<String>, Vec<Obj>)>;

fn objects(list: &[ParsedObject]) -> Vec<Obj> {
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

/// A subgraph without line numbers: what must survive writing and reading back.
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

fn assert_well_formed(g: &Subgraph) {
    for u in &g.units {
        assert!(!u.inputs.is_empty(), "unit without inputs");
        assert!(!u.outputs.is_empty(), "unit without outputs");
        assert_eq!(normalize_word(&u.motion), u.motion);
        for o in u.inputs.iter().chain(u.outputs.iter()) {
            assert!(!o.node.label.is_empty());
            assert!(o.node.label.chars().count() <= limits::MAX_LABEL_CHARS);
            assert_eq!(normalize_label(&o.node.label), o.node.label);
            assert!(
                o.node.states.windows(2).all(|w| w[0] < w[1]),
                "states not sorted and unique"
            );
        }
    }
    for w in &g.warnings {
        assert!(
            w.file.is_some() && w.line.is_some(),
            "warning without a place: {w}"
        );
    }
}

fn check_round_trip(g: &Subgraph) {
    let text = write::subgraph_text(g);
    let again = parse_str(&g.name, &text)
        .unwrap_or_else(|e| panic!("written text does not read back: {e}\n{text}"));
    assert_eq!(
        shape(&again),
        shape(g),
        "round trip changed the units:\n{text}"
    );
    assert!(again.warnings.is_empty(), "{:?}", again.warnings);
}

proptest! {
    #![proptest_config(gen::config(256))]

    #[test]
    fn arbitrary_bytes_never_panic(bytes in proptest::collection::vec(any::<u8>(), 0..2048)) {
        match parse_bytes("r.txt", &bytes) {
            Ok(g) => assert_well_formed(&g),
            Err(e) => {
                prop_assert_eq!(e.file.as_deref(), Some("r.txt"));
                prop_assert!(!e.message.is_empty());
            }
        }
        let _ = foon_core::load(&[("r.foon".to_string(), bytes)]);
    }

    #[test]
    fn almost_foon_never_panics_and_what_is_read_round_trips(text in gen::line_soup()) {
        match parse_str("soup.txt", &text) {
            Ok(g) => {
                assert_well_formed(&g);
                check_round_trip(&g);
            }
            Err(e) => {
                // every error of a file names a line and column inside the text
                let lines = text.split(['\n', '\r']).count();
                let line = e.line.expect("error without a line");
                prop_assert!(line >= 1 && line <= lines + 1, "line {} of {}: {}", line, lines, e);
                prop_assert!(e.column.is_some_and(|c| c >= 1));
            }
        }
    }

    #[test]
    fn random_graphs_read_in_either_dialect_and_round_trip(f in gen::file(8), style in gen::style()) {
        let mut f = f;
        gen::consistent_goals(&mut f);
        let text = gen::render(&f, style);
        let g = parse_str("g.txt", &text).unwrap_or_else(|e| panic!("{e}\n{text}"));
        prop_assert_eq!(g.units.len(), f.len());
        assert_well_formed(&g);
        prop_assert!(g.warnings.is_empty(), "{:?}", g.warnings);
        check_round_trip(&g);
        // the other dialect and other line ends give the same units
        let other = gen::Style { indexed: !style.indexed, crlf: !style.crlf, ..style };
        let h = parse_str("g.txt", &gen::render(&f, other)).unwrap();
        prop_assert_eq!(shape(&h), shape(&g));
    }

    #[test]
    fn normal_forms_are_stable(text in any::<String>()) {
        let label = normalize_label(&text);
        prop_assert_eq!(normalize_label(&label), label.clone());
        let word = normalize_word(&text);
        prop_assert_eq!(normalize_word(&word), word);
    }
}
