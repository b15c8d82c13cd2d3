//! FOON text out of what the reader read: a subgraph, or a whole knowledge base as a bundle (one
//! `#@file` part per subgraph), in the plain dialect. Reading the text back gives the same units, nodes
//! and goals (`tests/prop_roundtrip.rs`), so a custom knowledge base can be exported and re-imported.

use crate::foon::bundle::FILE_MARK;
use crate::foon::kb::KnowledgeBase;
use crate::foon::model::{NodeId, ObjectNode, State, UnitObject};
use crate::foon::read::{GoalMark, ParsedObject, Subgraph};
use std::collections::BTreeMap;
use std::fmt::Write;

fn state_line(out: &mut String, s: &State) {
    let _ = match s.arg_text() {
        None => writeln!(out, "S\t{}", s.name),
        Some(arg) => writeln!(out, "S\t{}\t{arg}", s.name),
    };
}

/// An object line; a goal carries its dish class, or a leading `!` without one.
pub(crate) fn object_line(out: &mut String, label: &str, moves: bool, goal: Option<Option<u32>>) {
    let (bang, class) = match goal {
        None => ("", String::new()),
        Some(None) => ("!", String::new()),
        Some(Some(c)) => ("", format!("\t{c}")),
    };
    let _ = writeln!(out, "{bang}O\t{label}\t{}{class}", u8::from(moves));
}

fn object_lines(out: &mut String, node: &ObjectNode, moves: bool, goal: Option<&GoalMark>) {
    object_line(out, &node.label, moves, goal.map(|g| g.dish_class));
    for s in &node.states {
        state_line(out, s);
    }
}

fn motion_line(out: &mut String, motion: &str, times: &[String]) {
    let _ = write!(out, "M\t{motion}");
    for t in times {
        let _ = write!(out, "\t<{t}>");
    }
    out.push('\n');
}

/// Units given as (inputs, motion, times, outputs), each after a `//` line and the last followed by
/// one: its inputs (written by `object`), its motion line, its outputs.
fn units_text<'u, O: 'u>(
    out: &mut String,
    units: impl Iterator<Item = (&'u [O], &'u str, &'u [String], &'u [O])>,
    object: impl Fn(&mut String, &O),
) {
    let mut any = false;
    for (inputs, motion, times, outputs) in units {
        out.push_str("//\n");
        inputs.iter().for_each(|o| object(out, o));
        motion_line(out, motion, times);
        outputs.iter().for_each(|o| object(out, o));
        any = true;
    }
    if any {
        out.push_str("//\n");
    }
}

/// One subgraph as FOON text (plain dialect); motion times are kept.
pub fn subgraph_text(g: &Subgraph) -> String {
    let mut out = String::new();
    let units = (g.units.iter()).map(|u| (&u.inputs[..], &*u.motion, &u.times[..], &u.outputs[..]));
    units_text(&mut out, units, |out, o: &ParsedObject| {
        object_lines(out, &o.node, o.moves, o.goal.as_ref())
    });
    out
}

/// A knowledge base as a bundle: one part per subgraph with the (merged) units it contributed and its goal
/// marks. Motion times are not kept by the knowledge base, so they are not written.
pub fn kb_bundle(kb: &KnowledgeBase) -> String {
    let mut goals: BTreeMap<(&str, NodeId), Option<u32>> = BTreeMap::new();
    for g in &kb.goals {
        goals.insert((g.subgraph.as_str(), g.node), g.dish_class);
    }
    let mut out = String::new();
    let mut names: Vec<&str> = kb.subgraphs.iter().map(|s| s.name.as_str()).collect();
    names.dedup();
    let by_subgraph = kb.units_by_subgraph();
    for name in names {
        let _ = writeln!(out, "{FILE_MARK}{name}");
        let units = by_subgraph.get(name).map_or(&[][..], Vec::as_slice);
        let units = (units.iter().map(|&u| &kb.units[u]))
            .map(|u| (&u.inputs[..], &*u.motion, &[][..], &u.outputs[..]));
        units_text(&mut out, units, |out, o: &UnitObject| {
            let goal = goals.get(&(name, o.node));
            let goal = goal.map(|&dish_class| GoalMark { dish_class });
            object_lines(out, &kb.nodes[o.node], o.moves, goal.as_ref());
        });
    }
    out
}
