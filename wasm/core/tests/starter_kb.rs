//! The starter knowledge base in `public/kb/starter/` (written for this project, one recipe subgraph per
//! file): every file parses without warnings, merges, has one classified goal, keeps to the documented
//! vocabulary (`public/kb/VOCABULARY.md`, read here so the doc and the data cannot drift), and every
//! goal can be made from kitchen items.

mod common;
use common::{load, read_dir};
use foon_core::foon::read::{parse_bytes, Subgraph};
use foon_core::{KnowledgeBase, NodeId, ObjectNode, StateArg, UnitId};
use std::collections::{BTreeMap, BTreeSet, HashSet};
use std::path::PathBuf;

fn kb_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../public/kb")
}

fn starter_files() -> Vec<(String, Vec<u8>)> {
    let files = read_dir(&kb_dir().join("starter"));
    assert!(!files.is_empty(), "no starter files");
    files
}

fn parsed() -> Vec<Subgraph> {
    starter_files()
        .iter()
        .map(|(name, bytes)| parse_bytes(name, bytes).unwrap_or_else(|e| panic!("{e}")))
        .collect()
}

/// How a state is written in the vocabulary table: `sliced`, `in [..]`, `contains {..}`.
fn vocab_key(name: &str, arg: &Option<StateArg>) -> String {
    match arg {
        None => name.to_string(),
        Some(StateArg::Container(_)) => format!("{name} [..]"),
        Some(StateArg::Ingredients(_)) => format!("{name} {{..}}"),
    }
}

/// The first column of the table under `## States` in VOCABULARY.md: "| `state` | category | ... |".
fn vocabulary_states() -> BTreeMap<String, String> {
    let doc = std::fs::read_to_string(kb_dir().join("VOCABULARY.md")).expect("VOCABULARY.md");
    let section = doc
        .split("\n## States")
        .nth(1)
        .expect("a '## States' section")
        .split("\n## ")
        .next()
        .unwrap();
    let mut states = BTreeMap::new();
    for line in section.lines() {
        let cells: Vec<&str> = line.split('|').map(str::trim).collect();
        if cells.len() >= 4 && cells[1].starts_with('`') && cells[1].ends_with('`') {
            let state = cells[1].trim_matches('`').to_string();
            assert!(
                states.insert(state.clone(), cells[2].to_string()).is_none(),
                "state {state} listed twice"
            );
        }
    }
    assert!(
        states.len() > 50,
        "states table not found ({} rows)",
        states.len()
    );
    states
}

/// Every label of the table under `## Labels` in VOCABULARY.md: "| group | label, label, ... |".
fn vocabulary_labels() -> BTreeSet<String> {
    let doc = std::fs::read_to_string(kb_dir().join("VOCABULARY.md")).expect("VOCABULARY.md");
    let section = doc
        .split("\n## Labels")
        .nth(1)
        .expect("a '## Labels' section")
        .split("\n## ")
        .next()
        .unwrap();
    let labels: BTreeSet<String> = section
        .lines()
        .filter_map(|line| line.split('|').nth(2))
        .flat_map(|cell| cell.split(',').map(|l| l.trim().to_string()))
        .filter(|l| !l.is_empty() && !l.starts_with('-'))
        .collect();
    assert!(
        labels.len() > 100,
        "labels table not found ({} labels)",
        labels.len()
    );
    labels
}

fn starter_kb() -> KnowledgeBase {
    load(&starter_files())
}

#[test]
fn every_file_parses_without_warnings_and_names_its_dish() {
    for g in parsed() {
        assert!(g.warnings.is_empty(), "{}: {:?}", g.name, g.warnings);
        assert!(!g.units.is_empty(), "{}: no units", g.name);
        let marks: Vec<_> = g
            .units
            .iter()
            .flat_map(|u| u.inputs.iter().chain(u.outputs.iter()))
            .filter(|o| o.goal.is_some())
            .collect();
        assert_eq!(marks.len(), 1, "{}: goal marks", g.name);
        let last = g.units.last().unwrap();
        assert!(
            last.outputs.iter().any(|o| o.goal.is_some()),
            "{}: the goal is not an output of the last unit",
            g.name
        );
    }
}

#[test]
fn merged_kb_has_one_classified_goal_per_file() {
    let kb = starter_kb();
    assert!(kb.warnings.is_empty(), "{:?}", kb.warnings);
    let files = starter_files();
    assert!(files.len() >= 120, "{} files", files.len());
    assert_eq!(kb.goals.len(), files.len());
    let mut per_class: BTreeMap<u32, usize> = BTreeMap::new();
    for (name, _) in &files {
        let goals: Vec<_> = kb.goals.iter().filter(|g| &g.subgraph == name).collect();
        assert_eq!(goals.len(), 1, "{name}: goals");
        let g = goals[0];
        let class = g
            .dish_class
            .unwrap_or_else(|| panic!("{name}: goal without dish class"));
        assert!(class < 30, "{name}: dish class {class}");
        *per_class.entry(class).or_default() += 1;
        let node = &kb.nodes[g.node];
        assert!(
            !node.ingredients::<String>().is_empty(),
            "{name}: goal {node} has no contains {{…}}"
        );
        assert_eq!(g.ingredients, node.ingredients::<String>());
    }
    // the eight dish types of the recipe queries (salad, soup, cake, omelette, drinks, bread, noodle, rice),
    // each in its main ways, and the others the app offers
    for (class, min) in [
        (15, 10),
        (1, 10),
        (5, 10),
        (23, 10),
        (9, 10),
        (0, 10),
        (14, 10),
        (19, 10),
        (4, 2),
        (3, 2),
        (13, 2),
        (7, 2),
        (8, 2),
    ] {
        let n = per_class.get(&class).copied().unwrap_or(0);
        assert!(n >= min, "dish class {class}: {n} files, want {min}");
    }
}

#[test]
fn every_unit_changes_something() {
    let kb = starter_kb();
    for (id, u) in kb.units.iter().enumerate() {
        let ins: BTreeSet<NodeId> = u.input_nodes().collect();
        let outs: BTreeSet<NodeId> = u.output_nodes().collect();
        assert!(!outs.is_empty(), "unit {id} ({}) has no outputs", u.motion);
        assert_ne!(ins, outs, "unit {id} ({}) outputs its inputs", u.motion);
        for n in &outs {
            assert!(
                !ins.contains(n),
                "unit {id} ({}, {:?}) outputs {} unchanged",
                u.motion,
                kb.provenance[id],
                kb.nodes[*n]
            );
        }
    }
}

#[test]
fn every_state_is_in_the_vocabulary() {
    let vocab = vocabulary_states();
    let kb = starter_kb();
    let mut unknown: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    let mut used: BTreeSet<String> = BTreeSet::new();
    for n in &kb.nodes {
        for s in &n.states {
            let key = vocab_key(&s.name, &s.arg);
            if !vocab.contains_key(&key) {
                unknown
                    .entry(key.clone())
                    .or_default()
                    .insert(n.label.to_string());
            }
            used.insert(key);
        }
    }
    assert!(
        unknown.is_empty(),
        "states missing from VOCABULARY.md: {unknown:?}"
    );
    let unused: Vec<&String> = vocab.keys().filter(|k| !used.contains(*k)).collect();
    assert!(
        unused.is_empty(),
        "VOCABULARY.md lists unused states: {unused:?}"
    );
}

#[test]
fn every_label_is_in_the_vocabulary() {
    let vocab = vocabulary_labels();
    let kb = starter_kb();
    let unknown: BTreeSet<&str> = kb
        .nodes
        .iter()
        .map(|n| n.label.as_str())
        .filter(|l| !vocab.contains(*l))
        .collect();
    assert!(
        unknown.is_empty(),
        "labels missing from VOCABULARY.md: {unknown:?}"
    );
}

/// Within each file, every input is a kitchen item or was made by an earlier unit of the same file,
/// and kitchen items are made by no unit of the whole starter KB.
#[test]
fn files_are_closed_and_kitchen_items_are_never_produced() {
    let kb = starter_kb();
    for g in parsed() {
        let produced_here: HashSet<&ObjectNode> = g
            .units
            .iter()
            .flat_map(|u| u.outputs.iter().map(|o| &o.node))
            .collect();
        let mut made: HashSet<&ObjectNode> = HashSet::new();
        for u in &g.units {
            for i in &u.inputs {
                if produced_here.contains(&i.node) {
                    assert!(
                        made.contains(&i.node),
                        "{} line {}: {} is used before the unit that makes it",
                        g.name,
                        u.line,
                        i.node
                    );
                } else {
                    let id = kb.node_id(&i.node).unwrap();
                    assert!(
                        kb.producers[id].is_empty(),
                        "{} line {}: kitchen item {} is produced by {:?}",
                        g.name,
                        u.line,
                        i.node,
                        kb.producers[id]
                            .iter()
                            .map(|&p| &kb.provenance[p])
                            .collect::<Vec<_>>()
                    );
                    assert!(
                        i.node.ingredients::<String>().is_empty(),
                        "{}: kitchen item {} holds ingredients",
                        g.name,
                        i.node
                    );
                }
            }
            made.extend(u.outputs.iter().map(|o| &o.node));
        }
    }
}

/// Forward chaining from the kitchen over the given units; returns every node that can be made.
fn reachable(kb: &KnowledgeBase, units: &[UnitId]) -> Vec<bool> {
    let mut have: Vec<bool> = kb.kitchen.clone();
    loop {
        let mut changed = false;
        for &u in units {
            let unit = &kb.units[u];
            if unit.input_nodes().all(|n| have[n]) {
                for n in unit.output_nodes() {
                    if !have[n] {
                        have[n] = true;
                        changed = true;
                    }
                }
            }
        }
        if !changed {
            return have;
        }
    }
}

#[test]
fn every_goal_is_retrievable_from_kitchen_items() {
    let kb = starter_kb();
    let all: Vec<UnitId> = UnitId::all(kb.units.len()).collect();
    let everywhere = reachable(&kb, &all);
    for g in &kb.goals {
        assert!(
            !kb.kitchen[g.node],
            "{}: the goal is a kitchen item",
            g.subgraph
        );
        assert!(
            everywhere[g.node],
            "{}: goal unreachable in the merged KB",
            g.subgraph
        );
        // and from the file's own units alone
        let own = kb.units_by_subgraph()[g.subgraph.as_str()].clone();
        assert!(
            reachable(&kb, &own)[g.node],
            "{}: goal unreachable from its own units",
            g.subgraph
        );
    }
}

#[test]
fn the_merged_starter_kb_has_no_cycles() {
    let kb = starter_kb();
    // node -> nodes made from it
    let mut next: Vec<BTreeSet<NodeId>> = vec![BTreeSet::new(); kb.nodes.len()];
    for u in &kb.units {
        for i in u.input_nodes() {
            next[i].extend(u.output_nodes());
        }
    }
    // iterative three-colour depth-first search
    let mut colour = vec![0u8; kb.nodes.len()];
    for start in NodeId::all(kb.nodes.len()) {
        if colour[start] != 0 {
            continue;
        }
        let mut stack: Vec<(NodeId, Vec<NodeId>)> =
            vec![(start, next[start].iter().copied().collect())];
        colour[start] = 1;
        while let Some((node, rest)) = stack.last_mut() {
            if let Some(child) = rest.pop() {
                match colour[child] {
                    0 => {
                        colour[child] = 1;
                        let succ = next[child].iter().copied().collect();
                        stack.push((child, succ));
                    }
                    1 => panic!("cycle through {} and {}", kb.nodes[*node], kb.nodes[child]),
                    _ => {}
                }
            } else {
                colour[*node] = 2;
                stack.pop();
            }
        }
    }
}

#[test]
fn the_starter_kb_merges_with_foon111() {
    let mut files = common::foon111("plain");
    files.extend(starter_files());
    let kb = load(&files);
    let starter = load(&starter_files());
    assert_eq!(
        kb.units_before_merge,
        load(&common::foon111("plain")).units_before_merge + starter.units_before_merge
    );
    // starter goals keep their class in the union
    for g in &starter.goals {
        assert!(kb
            .goals
            .iter()
            .any(|h| h.subgraph == g.subgraph && h.dish_class == g.dish_class));
    }
}
