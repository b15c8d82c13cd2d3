//! Figures about a knowledge base, as printed by `cli stats` and shown by the app.

use crate::foon::kb::KnowledgeBase;
use crate::vocab::taxonomy::dish_class_name;
use serde::Serialize;
use std::collections::{BTreeMap, BTreeSet};

#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Stats {
    /// Subgraph files (recipes) merged.
    pub subgraphs: usize,
    pub units_before_merge: usize,
    /// Functional units after exact duplicates were removed.
    pub units: usize,
    pub object_nodes: usize,
    /// Distinct object labels, and those of them that are ingredients (not utensils).
    pub labels: usize,
    pub ingredient_labels: usize,
    /// Distinct state words (relation words included: in, on, contains, ...).
    pub states: usize,
    pub motions: usize,
    pub goal_nodes: usize,
    pub kitchen_nodes: usize,
    /// Units skipped by the reader, with a warning each (see `KnowledgeBase::warnings`).
    pub warnings: usize,
    /// Goal nodes per dish class name ("unclassified" when a goal has no or an unknown class).
    pub goals_per_class: BTreeMap<String, usize>,
    /// Subgraphs (recipes) per dish class name, counting each subgraph once by its first goal.
    pub recipes_per_class: BTreeMap<String, usize>,
}

pub fn stats(kb: &KnowledgeBase) -> Stats {
    let class_name = |c: Option<u32>| {
        c.and_then(dish_class_name)
            .unwrap_or("unclassified")
            .to_string()
    };
    let mut goals_per_class = BTreeMap::new();
    let mut recipe_class: BTreeMap<&str, String> = BTreeMap::new();
    for g in &kb.goals {
        *goals_per_class.entry(class_name(g.dish_class)).or_insert(0) += 1;
        recipe_class
            .entry(g.subgraph.as_str())
            .or_insert_with(|| class_name(g.dish_class));
    }
    let mut recipes_per_class = BTreeMap::new();
    for class in recipe_class.into_values() {
        *recipes_per_class.entry(class).or_insert(0) += 1;
    }
    let labels: BTreeSet<&str> = kb.nodes.iter().map(|n| n.label.as_str()).collect();
    let states: BTreeSet<&str> = kb
        .nodes
        .iter()
        .flat_map(|n| n.states.iter().map(|s| s.name.as_str()))
        .collect();
    let motions: BTreeSet<&str> = kb.units.iter().map(|u| u.motion.as_str()).collect();
    Stats {
        subgraphs: kb.subgraphs.len(),
        units_before_merge: kb.units_before_merge,
        units: kb.units.len(),
        object_nodes: kb.nodes.len(),
        labels: labels.len(),
        ingredient_labels: kb.ingredient_labels().len(),
        states: states.len(),
        motions: motions.len(),
        goal_nodes: kb.goals.len(),
        kitchen_nodes: kb.kitchen.iter().filter(|&&k| k).count(),
        warnings: kb.warnings.len(),
        goals_per_class,
        recipes_per_class,
    }
}
