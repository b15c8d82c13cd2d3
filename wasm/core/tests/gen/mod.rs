//! proptest strategies shared by the `prop_*` tests: random FOON graphs written as FOON text in either
//! dialect, and line soups that are almost FOON.
#![allow(dead_code)]

pub mod plans;

use proptest::prelude::*;

/// Cases per property: `PROPTEST_CASES` when set (the bounded robustness step of `scripts/test.sh` raises
/// it), else `default`.
pub fn cases(default: u32) -> u32 {
    std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

pub fn config(default: u32) -> ProptestConfig {
    ProptestConfig {
        cases: cases(default),
        // shrinking a failure of a whole graph can take long; a bounded run must stay bounded
        max_shrink_time: 60_000,
        ..ProptestConfig::default()
    }
}

/// Labels in several spellings of the same object, so that normalisation merges nodes across files.
pub const LABELS: &[&str] = &[
    "tomato",
    "Tomatoes",
    "onion",
    "onions ",
    "egg",
    "bowl",
    "knife",
    "salt",
    "sweet_potato",
    "salad",
    "water",
    "pan",
    "cheese",
    "Leaves",
];
pub const STATES: &[&str] = &[
    "whole",
    "sliced",
    "chopped",
    "cooked",
    "mixed",
    "clean",
    "empty",
    "Raw",
    "fried",
    "off (ready)",
];
// no peel or chop: the reader skips one that turns a food into another (the bad-input corpus tests that),
// which random labels nearly always would
pub const MOTIONS: &[&str] = &[
    "slice",
    "cut",
    "mix",
    "pour",
    "fry",
    "Pick-and-place",
    "stir",
    "boil",
];
pub const CONTAINERS: &[&str] = &["bowl", "pan", "cutting board", "Bowls"];

#[derive(Clone, Debug)]
pub struct Obj {
    pub label: usize,
    pub states: Vec<usize>,
    /// `in [container]` (index into CONTAINERS)
    pub container: Option<usize>,
    /// `contains {…}` (indexes into LABELS)
    pub contains: Vec<usize>,
    pub moves: bool,
    /// goal mark: None, or Some(dish class or none)
    pub goal: Option<Option<u32>>,
}

#[derive(Clone, Debug)]
pub struct Unit {
    pub inputs: Vec<Obj>,
    pub motion: usize,
    pub outputs: Vec<Obj>,
}

pub type File = Vec<Unit>;

fn obj(goal_chance: u32) -> impl Strategy<Value = Obj> {
    (
        0..LABELS.len(),
        proptest::collection::vec(0..STATES.len(), 0..3),
        proptest::option::weighted(0.3, 0..CONTAINERS.len()),
        proptest::collection::vec(0..LABELS.len(), 0..3),
        any::<bool>(),
        // the dish class, when marked, is one of a few known classes (15 salad, 1 soup) or absent
        proptest::option::weighted(
            f64::from(goal_chance) / 100.0,
            prop_oneof![Just(None), Just(Some(15u32)), Just(Some(1u32))],
        ),
    )
        .prop_map(|(label, states, container, contains, moves, goal)| Obj {
            label,
            states,
            container,
            contains,
            moves,
            goal,
        })
}

pub fn unit() -> impl Strategy<Value = Unit> {
    (
        proptest::collection::vec(obj(3), 1..4),
        0..MOTIONS.len(),
        proptest::collection::vec(obj(15), 1..3),
    )
        .prop_map(|(inputs, motion, outputs)| Unit {
            inputs,
            motion,
            outputs,
        })
}

/// A file of 1 to `max_units` units.
pub fn file(max_units: usize) -> impl Strategy<Value = File> {
    proptest::collection::vec(unit(), 1..=max_units)
}

/// How a file is written: dialect, line ends, stray white space.
#[derive(Clone, Copy, Debug)]
pub struct Style {
    pub indexed: bool,
    pub crlf: bool,
    pub trailing_tab: bool,
    pub bom: bool,
}

pub fn style() -> impl Strategy<Value = Style> {
    (any::<bool>(), any::<bool>(), any::<bool>(), any::<bool>()).prop_map(
        |(indexed, crlf, trailing_tab, bom)| Style {
            indexed,
            crlf,
            trailing_tab,
            bom,
        },
    )
}

/// Goal marks of one node must agree on the class within a file (the reader rejects conflicts): the
/// first class given to a label-and-states is used for all its marks.
pub fn consistent_goals(file: &mut File) {
    let mut classes: std::collections::HashMap<String, u32> = Default::default();
    for u in file.iter_mut() {
        for o in u.inputs.iter_mut().chain(u.outputs.iter_mut()) {
            if let Some(Some(class)) = o.goal {
                let first = *classes.entry(format!("{:?}", node_key(o))).or_insert(class);
                o.goal = Some(Some(first));
            }
        }
    }
}

/// What makes two generated objects the same node after normalisation (roughly: label and state words).
fn node_key(o: &Obj) -> (String, Vec<String>, Option<String>, Vec<String>) {
    let mut states: Vec<String> = o
        .states
        .iter()
        .map(|&s| foon_core::foon::label::normalize_word(STATES[s]))
        .collect();
    states.sort();
    states.dedup();
    let mut contains: Vec<String> = o
        .contains
        .iter()
        .map(|&l| foon_core::foon::label::normalize_label(LABELS[l]))
        .collect();
    contains.sort();
    contains.dedup();
    (
        foon_core::foon::label::normalize_label(LABELS[o.label]),
        states,
        o.container
            .map(|c| foon_core::foon::label::normalize_label(CONTAINERS[c])),
        contains,
    )
}

pub fn render(file: &File, style: Style) -> String {
    let mut lines: Vec<String> = Vec::new();
    let mut n = 0usize;
    let mut tag = |kind: char| {
        n += 1;
        if style.indexed {
            format!("{kind}{n}")
        } else {
            kind.to_string()
        }
    };
    let object = |lines: &mut Vec<String>, o: &Obj, tag: &mut dyn FnMut(char) -> String| {
        let flag = u8::from(o.moves);
        let head = tag('O');
        lines.push(match o.goal {
            None => format!("{head}\t{}\t{flag}", LABELS[o.label]),
            Some(None) => format!("!{head}\t{}\t{flag}", LABELS[o.label]),
            Some(Some(c)) => format!("{head}\t{}\t{flag}\t{c}", LABELS[o.label]),
        });
        for &s in &o.states {
            lines.push(format!("{}\t{}", tag('S'), STATES[s]));
        }
        if let Some(c) = o.container {
            lines.push(format!("{}\tin\t[{}]", tag('S'), CONTAINERS[c]));
        }
        if !o.contains.is_empty() {
            let list: Vec<&str> = o.contains.iter().map(|&l| LABELS[l].trim()).collect();
            lines.push(format!("{}\tcontains\t{{{}}}", tag('S'), list.join(", ")));
        }
    };
    for u in file {
        lines.push("//".into());
        for o in &u.inputs {
            object(&mut lines, o, &mut tag);
        }
        let m = tag('M');
        lines.push(format!("{m}\t{}\t<Assumed>", MOTIONS[u.motion]));
        for o in &u.outputs {
            object(&mut lines, o, &mut tag);
        }
    }
    lines.push("//".into());
    let end = match (style.trailing_tab, style.crlf) {
        (true, true) => "\t\r\n",
        (true, false) => "\t\n",
        (false, true) => "\r\n",
        (false, false) => "\n",
    };
    let mut text = if style.bom {
        "\u{feff}".to_string()
    } else {
        String::new()
    };
    for l in lines {
        text.push_str(&l);
        text.push_str(end);
    }
    text
}

/// Several files with distinct names, each written in its own style, goal classes made consistent.
pub fn files(max_files: usize, max_units: usize) -> impl Strategy<Value = Vec<(String, String)>> {
    proptest::collection::vec((file(max_units), style()), 1..=max_files).prop_map(|list| {
        list.into_iter()
            .enumerate()
            .map(|(i, (mut f, s))| {
                consistent_goals(&mut f);
                (format!("g{i:02}.txt"), render(&f, s))
            })
            .collect()
    })
}

/// Lines that are almost FOON: right and wrong line heads, fields, brackets, separators, odd characters.
pub fn line_soup() -> impl Strategy<Value = String> {
    let head = prop_oneof![
        Just("O"),
        Just("S"),
        Just("M"),
        Just("!O"),
        Just("O12"),
        Just("S3"),
        Just("M7"),
        Just("//"),
        Just("#"),
        Just("#@file x.txt"),
        Just("X"),
        Just("o"),
        Just(""),
        Just(" "),
        Just("!!O"),
    ];
    let field = prop_oneof![
        Just("tomato".to_string()),
        Just("1".to_string()),
        Just("0".to_string()),
        Just("15".to_string()),
        Just("99".to_string()),
        Just("[bowl]".to_string()),
        Just("{a,b}".to_string()),
        Just("[bowl".to_string()),
        Just("{}".to_string()),
        Just("[]".to_string()),
        Just("in [pan]".to_string()),
        Just("<1:00,1:10>".to_string()),
        Just("_".to_string()),
        Just(" ".to_string()),
        Just("\u{feff}".to_string()),
        Just("é".to_string()),
        Just("\r".to_string()),
        "[a-z_ \\[\\]{},<>!0-9]{0,12}",
        any::<String>().prop_map(|s| s.chars().take(8).collect()),
    ];
    let line = (head, proptest::collection::vec(field, 0..5)).prop_map(|(h, fields)| {
        let mut l = h.to_string();
        for f in fields {
            l.push('\t');
            l.push_str(&f);
        }
        l
    });
    proptest::collection::vec(line, 0..40).prop_map(|lines| lines.join("\n"))
}
