//! From the modified tree to the plan: units in execution order, progress lines (section IV-A,
//! `progress`) and one plain sentence per unit (`steps`).

use super::tree::{SlotId, TUnit, TUnitId, Tree};
use crate::contract::plan::{
    DishClassRef, GoalInfo, IngredientOutcome, Plan, PlanNode, PlanUnit, ProgressLine,
    ProgressState, Query, Status,
};
use crate::foon::kb::{Goal, KnowledgeBase};
use crate::foon::model::{ObjectNode, State, StateArg};
use crate::vocab::foods;
use crate::vocab::states::{category, kind, state_text, Category};
use crate::vocab::taxonomy::{is_mixing_motion, PUT_MOTIONS};
use smol_str::{format_smolstr, SmolStr};
use std::sync::Arc;

mod progress;
mod steps;

pub(crate) use progress::reaches_dish;
use progress::*;
use steps::*;

pub(crate) struct Parts<'a> {
    pub kb: &'a KnowledgeBase,
    pub tree: &'a Tree<'a>,
    /// The units in execution order, and each slot's plan node (`schedule::schedule`).
    pub order: &'a [TUnitId],
    pub nodes: &'a [Option<Arc<PlanNode>>],
    pub query: Query,
    pub dish_class: Option<DishClassRef>,
    pub notes: Vec<String>,
    pub modified: bool,
    pub goal: &'a Goal,
    pub score: f32,
    pub outcomes: Vec<IngredientOutcome>,
    pub removed: Vec<String>,
    pub format_version: u32,
    /// The food each asked name is read as (`foods::query_readings`, made once per plan).
    pub readings: &'a rustc_hash::FxHashMap<String, &'static str>,
}

pub(crate) fn build(p: Parts) -> Plan {
    let tree = p.tree;
    let order = p.order;
    // the schedule made a node for every slot a live unit uses
    let node = |x: SlotId| match p.nodes.get(x) {
        Some(Some(n)) => Arc::clone(n),
        _ => Arc::new(PlanNode::from(&*tree.slots[x].node)),
    };
    let units: Vec<PlanUnit> = order
        .iter()
        .map(|&u| {
            let unit = &tree.units[u];
            PlanUnit {
                inputs: unit.inputs.iter().map(|i| node(i.0)).collect(),
                motion: unit.motion.as_ref().into(),
                outputs: unit.outputs.iter().map(|o| node(o.0)).collect(),
                origin: unit.origin,
                sources: unit.sources.map(Arc::clone).unwrap_or_default(),
            }
        })
        .collect();
    let goal_node = &tree.slots[tree.goal].node;
    let mut relations = Relations {
        tree,
        known: Vec::new(),
    };
    let mut steps: Vec<String> = order
        .iter()
        .map(|&u| sentence(tree, u, &mut relations))
        .collect();
    tell_apart(tree, order, &mut steps);
    let uses = Uses::new(tree, order);
    let mut progress_lines = Vec::with_capacity(p.outcomes.len());
    let mut done: Vec<&str> = Vec::with_capacity(p.outcomes.len());
    for o in &p.outcomes {
        if o.status != Status::Planned || done.contains(&o.object.as_str()) {
            continue;
        }
        done.push(&o.object);
        // "pepper — ground" is a spice, whatever the tree's other peppers are
        let food = p.readings.get(o.object.as_str()).map_or(&*o.object, |r| *r);
        let line = progress_line(order, &uses, (&o.object, food), &mut relations);
        progress_lines.extend(line);
    }
    let kb_goal = &p.kb.nodes[p.goal.node];
    Plan {
        format_version: p.format_version,
        query: p.query,
        dish_class: p.dish_class,
        notes: p.notes,
        modified: p.modified,
        goal: GoalInfo {
            label: goal_node.label.as_str().into(),
            reference: kb_goal.label.as_str().into(),
            states: goal_node.states.iter().map(State::text).collect(),
            ingredients: if p.goal.ingredients.is_empty() {
                kb_goal.ingredients()
            } else {
                p.goal.ingredients.clone()
            },
            subgraph: p.goal.subgraph.clone(),
            score: p.score,
            dish_class: p.goal.dish_class,
        },
        units,
        ingredients: p.outcomes,
        removed: p.removed,
        progress_lines,
        steps,
        cautions: Vec::new(),
        trace: None,
        robot: None,
    }
}
