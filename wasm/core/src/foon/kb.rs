//! The universal FOON: the union of any number of subgraphs with exact duplicate units removed,
//! indexed for the planner (producers/consumers of each object node in O(1), goal nodes with their dish
//! class and ingredients, the kitchen). The result never depends on the order the files were given in:
//! nodes and units are numbered in the sorted order of their contents.

use crate::error::{ErrorCode, FoonError, Result};
use crate::foon::model::{FunctionalUnit, NodeId, ObjectNode, UnitId, UnitObject};
use crate::foon::read::Subgraph;
use crate::limits;
use crate::vocab::states::is_start_state;
use crate::vocab::taxonomy::is_utensil;
use rustc_hash::FxHashMap;
use serde::Serialize;
use std::collections::{BTreeMap, BTreeSet, HashMap};
use std::sync::Arc;

/// A goal node of one subgraph: the finished dish that subgraph annotates.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Goal {
    pub node: NodeId,
    /// Dish class index (see `taxonomy`), when the file gives one.
    pub dish_class: Option<u32>,
    /// The subgraph (file) the goal comes from.
    pub subgraph: String,
    /// The dish's ingredients: its `contains {…}` state, else the starting ingredients of its subgraph.
    pub ingredients: Vec<String>,
}

/// Per-file figures, kept for statistics and provenance.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct SubgraphInfo {
    pub name: String,
    /// The recipe's title: its `# title:` line, else the file name read as words (`title_from_name`).
    pub title: String,
    pub units: usize,
}

/// "s01-greek_salad.txt" -> "greek salad", "0097-miso_soup-DONE.txt" -> "miso soup" (FOON-111 marks
/// finished annotations so); the name as given when nothing is left.
pub fn title_from_name(name: &str) -> String {
    let base = name.rsplit(['/', '\\']).next().unwrap_or(name);
    let lower = base.to_ascii_lowercase();
    let mut t = [".txt", ".foon"]
        .iter()
        .find(|ext| lower.ends_with(*ext))
        .map_or(base, |ext| &base[..base.len() - ext.len()]);
    // a leading number, optionally after one letter ("0001-", "s01_")
    let letter = t.chars().next().is_some_and(|c| c.is_ascii_alphabetic()) as usize;
    let digits = t[letter..].bytes().take_while(u8::is_ascii_digit).count();
    if digits > 0 && matches!(t.as_bytes().get(letter + digits), Some(b'-' | b'_')) {
        t = &t[letter + digits + 1..];
    }
    let lower = t.to_ascii_lowercase();
    if lower.ends_with("-done") || lower.ends_with("_done") {
        t = &t[..t.len() - 5];
    }
    let title = t.replace('_', " ").trim().to_string();
    if title.is_empty() {
        base.to_string()
    } else {
        title
    }
}

#[derive(Clone, Debug, PartialEq)]
pub struct KnowledgeBase {
    pub nodes: Vec<ObjectNode>,
    pub units: Vec<FunctionalUnit>,
    /// For each unit, the subgraphs it occurs in (sorted); shared, so that a plan's unit takes a count
    /// rather than a copy of the names.
    pub provenance: Vec<Arc<[String]>>,
    /// For each node, the units that output it.
    pub producers: Vec<Vec<UnitId>>,
    /// For each node, the units that take it as input.
    pub consumers: Vec<Vec<UnitId>>,
    /// For each node, whether it is in the kitchen (a starting item; retrieval stops there).
    pub kitchen: Vec<bool>,
    pub goals: Vec<Goal>,
    pub subgraphs: Vec<SubgraphInfo>,
    /// Units over all files before duplicates were removed.
    pub units_before_merge: usize,
    /// Reader warnings of all files (skipped units), sorted by file and line.
    pub warnings: Vec<FoonError>,
    node_index: FxHashMap<ObjectNode, NodeId>,
}

type UnitKey = (Vec<NodeId>, String, Vec<NodeId>);
/// A merged unit being built: inputs, outputs, and the subgraphs it was seen in.
type MergedUnit = (Vec<UnitObject>, Vec<UnitObject>, BTreeSet<String>);

/// A goal mark in a file: (file, node, dish class).
type GoalMarkOf = (String, NodeId, Option<u32>);

impl KnowledgeBase {
    /// Merges subgraphs into one universal FOON.
    pub fn merge(subgraphs: &[Subgraph]) -> Result<KnowledgeBase> {
        let units_before_merge = unit_count(subgraphs)?;
        let nodes = numbered_nodes(subgraphs);
        // by reference here: the knowledge base's own index is made once its nodes are moved into it
        let numbers: FxHashMap<&ObjectNode, NodeId> =
            nodes.iter().zip(NodeId::all(nodes.len())).collect();
        let (merged, goal_marks) = merged_units(subgraphs, &numbers);
        let mut units = Vec::with_capacity(merged.len());
        let mut provenance = Vec::with_capacity(merged.len());
        // `objects` sorted both lists, and OR-ing flags keeps them sorted
        for ((_, motion, _), (inputs, outputs, files)) in merged {
            units.push(FunctionalUnit {
                inputs,
                motion,
                outputs,
            });
            provenance.push(files.into_iter().collect());
        }
        let mut subgraph_infos: Vec<SubgraphInfo> = subgraphs
            .iter()
            .map(|g| SubgraphInfo {
                name: g.name.clone(),
                title: g.title.clone().unwrap_or_else(|| title_from_name(&g.name)),
                units: g.units.len(),
            })
            .collect();
        subgraph_infos.sort_by(|a, b| a.name.cmp(&b.name).then(a.units.cmp(&b.units)));

        let mut warnings: Vec<FoonError> = subgraphs
            .iter()
            .flat_map(|g| g.warnings.iter().cloned())
            .collect();
        warnings.sort_by(|a, b| (&a.file, a.line, &a.message).cmp(&(&b.file, b.line, &b.message)));
        let mut kb = KnowledgeBase::from_merged(
            nodes,
            units,
            provenance,
            Vec::new(),
            subgraph_infos,
            units_before_merge,
            warnings,
        );
        let by_subgraph = kb.units_by_subgraph();
        kb.goals = goal_marks
            .into_iter()
            .map(|(subgraph, node, dish_class)| {
                let units = by_subgraph.get(subgraph.as_str());
                let ingredients = kb.goal_ingredients(node, units.map_or(&[], Vec::as_slice));
                Goal {
                    node,
                    dish_class,
                    subgraph,
                    ingredients,
                }
            })
            .collect();
        Ok(kb)
    }

    /// A knowledge base from its merged parts (a merge's, or a snapshot's), with what is derived from
    /// them: producers, consumers, the kitchen and the node index.
    pub(crate) fn from_merged(
        nodes: Vec<ObjectNode>,
        units: Vec<FunctionalUnit>,
        provenance: Vec<Arc<[String]>>,
        goals: Vec<Goal>,
        subgraphs: Vec<SubgraphInfo>,
        units_before_merge: usize,
        warnings: Vec<FoonError>,
    ) -> KnowledgeBase {
        let (producers, consumers) = producers_and_consumers(nodes.len(), &units);
        let kitchen = NodeId::all(nodes.len())
            .zip(&nodes)
            .map(|(i, n)| producers[i].is_empty() || is_raw(n))
            .collect();
        KnowledgeBase {
            node_index: nodes
                .iter()
                .cloned()
                .zip(NodeId::all(nodes.len()))
                .collect(),
            nodes,
            units,
            provenance,
            producers,
            consumers,
            kitchen,
            goals,
            subgraphs,
            units_before_merge,
            warnings,
        }
    }

    pub fn node_id(&self, node: &ObjectNode) -> Option<NodeId> {
        self.node_index.get(node).copied()
    }

    /// Every object node with its id.
    pub fn each_node(&self) -> impl Iterator<Item = (NodeId, &ObjectNode)> {
        NodeId::all(self.nodes.len()).zip(&self.nodes)
    }

    /// Every functional unit with its id.
    pub fn each_unit(&self) -> impl Iterator<Item = (UnitId, &FunctionalUnit)> {
        UnitId::all(self.units.len()).zip(&self.units)
    }

    /// The units of each subgraph, ascending.
    pub fn units_by_subgraph(&self) -> HashMap<&str, Vec<UnitId>> {
        let mut out: HashMap<&str, Vec<UnitId>> = HashMap::new();
        for (u, files) in UnitId::all(self.provenance.len()).zip(&self.provenance) {
            for f in files.iter() {
                out.entry(f.as_str()).or_default().push(u);
            }
        }
        out
    }

    /// The annotated `contains {…}` list of a goal, else the ingredients its subgraph (`units`) starts
    /// from.
    fn goal_ingredients(&self, node: NodeId, units: &[UnitId]) -> Vec<String> {
        let annotated = self.nodes[node].ingredients();
        if !annotated.is_empty() {
            return annotated;
        }
        let produced: BTreeSet<NodeId> = units
            .iter()
            .flat_map(|&u| self.units[u].output_nodes())
            .collect();
        let starting: BTreeSet<String> = units
            .iter()
            .flat_map(|&u| self.units[u].input_nodes())
            .filter(|n| !produced.contains(n))
            .map(|n| self.nodes[n].label.to_string())
            .filter(|l| !is_utensil(l))
            .collect();
        starting.into_iter().collect()
    }

    /// Distinct labels of the nodes that are ingredients (not utensils).
    pub fn ingredient_labels(&self) -> BTreeSet<&str> {
        self.nodes
            .iter()
            .map(|n| n.label.as_str())
            .filter(|l| !is_utensil(l))
            .collect()
    }
}

/// The number of units of all subgraphs before merging: an error when there are none, or too many.
fn unit_count(subgraphs: &[Subgraph]) -> Result<usize> {
    let count: usize = subgraphs.iter().map(|g| g.units.len()).sum();
    let most = limits::MAX_UNITS;
    if count > most {
        let message = format!(
            "the knowledge base has {count} functional units over all files; the limit is {most}"
        );
        return Err(FoonError::new(ErrorCode::TooLarge, message));
    }
    if count == 0 {
        let why = "the knowledge base has no functional units (no FOON files, or only empty ones)";
        return Err(FoonError::new(ErrorCode::EmptyKnowledgeBase, why));
    }
    Ok(count)
}

/// Per node, the units making it and the units taking it.
fn producers_and_consumers(
    nodes: usize,
    units: &[FunctionalUnit],
) -> (Vec<Vec<UnitId>>, Vec<Vec<UnitId>>) {
    let mut producers = vec![Vec::new(); nodes];
    let mut consumers = vec![Vec::new(); nodes];
    for (id, u) in UnitId::all(units.len()).zip(units) {
        for n in u.output_nodes() {
            producers[n].push(id);
        }
        for n in u.input_nodes() {
            consumers[n].push(id);
        }
    }
    (producers, consumers)
}

/// The distinct object nodes of all subgraphs, numbered in sorted order so that ids do not depend on
/// file order.
fn numbered_nodes(subgraphs: &[Subgraph]) -> Vec<ObjectNode> {
    let distinct: BTreeSet<&ObjectNode> = subgraphs
        .iter()
        .flat_map(|g| g.units.iter())
        .flat_map(|u| u.inputs.iter().chain(u.outputs.iter()))
        .map(|o| &o.node)
        .collect();
    distinct.into_iter().cloned().collect()
}

/// The union of all subgraphs' units keyed by (inputs, motion, outputs), motion flags OR-ed over
/// duplicates, with the files each comes from; and the goal marks as (file, node, dish class).
fn merged_units(
    subgraphs: &[Subgraph],
    node_index: &FxHashMap<&ObjectNode, NodeId>,
) -> (BTreeMap<UnitKey, MergedUnit>, BTreeSet<GoalMarkOf>) {
    let mut merged: BTreeMap<UnitKey, MergedUnit> = BTreeMap::new();
    let mut goal_marks: BTreeSet<GoalMarkOf> = BTreeSet::new();
    for g in subgraphs {
        for u in &g.units {
            let ins = objects(&u.inputs, node_index);
            let outs = objects(&u.outputs, node_index);
            let key = (node_ids(&ins), u.motion.clone(), node_ids(&outs));
            let entry = merged
                .entry(key)
                .or_insert_with(|| (ins.clone(), outs.clone(), BTreeSet::new()));
            or_flags(&mut entry.0, &ins);
            or_flags(&mut entry.1, &outs);
            entry.2.insert(g.name.clone());
            for o in u.outputs.iter().chain(u.inputs.iter()) {
                if let Some(mark) = &o.goal {
                    goal_marks.insert((g.name.clone(), node_index[&o.node], mark.dish_class));
                }
            }
        }
    }
    // A node marked as a goal twice in one file, once with its dish class and once without, is one goal.
    let classified: BTreeSet<(String, NodeId)> = goal_marks
        .iter()
        .filter(|(_, _, class)| class.is_some())
        .map(|(file, node, _)| (file.clone(), *node))
        .collect();
    goal_marks.retain(|(file, node, class)| {
        class.is_some() || !classified.contains(&(file.clone(), *node))
    });
    (merged, goal_marks)
}

/// The unit's objects by node id, sorted.
fn objects(
    list: &[crate::foon::read::ParsedObject],
    index: &FxHashMap<&ObjectNode, NodeId>,
) -> Vec<UnitObject> {
    let mut out: Vec<UnitObject> = list
        .iter()
        .map(|o| UnitObject {
            node: index[&o.node],
            moves: o.moves,
        })
        .collect();
    out.sort();
    out
}

/// The node ids of sorted objects: sorted too.
fn node_ids(list: &[UnitObject]) -> Vec<NodeId> {
    list.iter().map(|o| o.node).collect()
}

fn or_flags(into: &mut [UnitObject], from: &[UnitObject]) {
    for o in into.iter_mut() {
        o.moves |= from.iter().any(|f| f.node == o.node && f.moves);
    }
}

/// A node in only raw states (whole, clean, empty, off, ...) and in no container: a kitchen item.
fn is_raw(node: &ObjectNode) -> bool {
    !node.states.is_empty()
        && node
            .states
            .iter()
            .all(|s| s.arg.is_none() && is_start_state(&s.name))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::foon::model::State;
    use crate::foon::read::parse_str;

    const A: &str = "//\nO\ttomato\t1\nS\twhole\nO\tknife\t0\nM\tslice\t<Assumed>\nO\ttomato\t1\nS\tsliced\n//\nO\ttomato\t1\nS\tsliced\nO\tbowl\t0\nS\tempty\nM\tadd\t<Assumed>\nO\tbowl\t0\nS\tcontains\t{tomato}\nO\tsalad\t1\t15\nS\tin\t[bowl]\n";
    const B: &str = "//\nO\ttomato\t0\nS\twhole\nO\tknife\t0\nM\tslice\t<1:00,1:10>\nO\ttomato\t1\nS\tsliced\n//\n";

    fn kb(files: &[(&str, &str)]) -> KnowledgeBase {
        let graphs: Vec<Subgraph> = files
            .iter()
            .map(|(n, t)| parse_str(n, t).unwrap())
            .collect();
        KnowledgeBase::merge(&graphs).unwrap()
    }

    #[test]
    fn merges_duplicate_units_and_keeps_provenance() {
        let k = kb(&[("a.txt", A), ("b.txt", B)]);
        assert_eq!(k.units_before_merge, 3);
        assert_eq!(k.units.len(), 2);
        let slice = k.units.iter().position(|u| u.motion == "slice").unwrap();
        assert_eq!(*k.provenance[slice], ["a.txt", "b.txt"]);
        // the flag is 1 in a.txt and 0 in b.txt: OR-ed
        assert!(k.units[slice]
            .inputs
            .iter()
            .any(|o| k.nodes[o.node].label == "tomato" && o.moves));
    }

    #[test]
    fn indexes_producers_consumers_goals_and_kitchen() {
        let k = kb(&[("a.txt", A)]);
        let tomato = |state| k.node_id(&ObjectNode::new("tomato", vec![State::plain(state)]));
        let sliced = tomato("sliced").unwrap();
        assert_eq!(k.producers[sliced].len(), 1);
        assert_eq!(k.consumers[sliced].len(), 1);
        assert!(!k.kitchen[sliced]);
        assert!(k.kitchen[tomato("whole").unwrap()]);
        assert_eq!(k.goals.len(), 1);
        assert_eq!(k.goals[0].dish_class, Some(15));
        assert_eq!(k.nodes[k.goals[0].node].label, "salad");
        // no contains {…} on the goal: derived from the subgraph's starting ingredients, utensils left out
        assert_eq!(k.goals[0].ingredients, vec!["tomato"]);
    }
}
