//! The planner's request and response, exactly the JSON contract of `docs/plan-format.md` (serde).

use crate::foon::model::{ObjectNode, State};
use crate::trace::Trace;
use serde::{Deserialize, Serialize};
use smol_str::SmolStr;
use std::collections::BTreeMap;
use std::sync::Arc;

/// Version of the plan JSON; bump on any incompatible change (and in `docs/plan-format.md`).
pub const FORMAT_VERSION: u32 = 1;

/// One ingredient of a query: an object and the state it should have in the dish.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord, Serialize, Deserialize)]
pub struct QueryIngredient {
    pub object: String,
    #[serde(default)]
    pub state: String,
}

/// A recipe query: dish type and ingredients (the shape of the Recipe1M+-derived query files).
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Query {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub id: Option<String>,
    #[serde(rename = "type", default)]
    pub dish_type: String,
    #[serde(default)]
    pub ingredients: Vec<QueryIngredient>,
}

fn default_true() -> bool {
    true
}

/// What the app and the CLI send.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PlanRequest {
    pub query: Query,
    /// `false` returns the reference task tree as retrieved (the ablation "without modification").
    #[serde(default = "default_true")]
    pub modify: bool,
    /// Query object -> the equivalent label the caller chose.
    #[serde(default)]
    pub overrides: BTreeMap<String, String>,
    /// `true` adds the explain trace (`Plan::trace`); the plan is otherwise the same.
    #[serde(default)]
    pub explain: bool,
    /// How to retrieve the reference task tree and what a robot does (`docs/robot.md`); the plan then
    /// has its robot view (`Plan::robot`). Absent: the paper's heuristic, and no robot view.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub robot: Option<RobotOptions>,
}

/// How Algorithm 2 chooses among the units that make a node.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum RetrievalMode {
    /// The paper's: ingredient overlap g(u), keeping to the reference recipe.
    #[default]
    Heuristic,
    /// The tree with the fewest functional units.
    FewestUnits,
    /// The tree whose motions cost a robot least.
    LowestCost,
    /// The tree a robot most likely carries out (the largest product of success rates).
    MostReliable,
}

/// A request's retrieval mode and robot figures.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RobotOptions {
    #[serde(default)]
    pub mode: RetrievalMode,
    /// Motion -> cost, over the project's table (`data/robot_motions.tsv`).
    #[serde(default)]
    pub motion_costs: BTreeMap<String, f32>,
    /// Motion -> success rate in (0, 1], over the project's table.
    #[serde(default)]
    pub success_rates: BTreeMap<String, f32>,
    /// How many of the least reliable units a person does instead of the robot.
    #[serde(default)]
    pub human_steps: usize,
}

/// Who carries out a unit.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Performer {
    Robot,
    Human,
}

/// A unit's motion as a robot sees it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct RobotUnit {
    pub cost: f64,
    pub success_rate: f64,
    pub by: Performer,
}

/// The plan for a robot: per unit (same order as `Plan::units`) and summed over the robot's units.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct RobotView {
    pub mode: RetrievalMode,
    pub units: Vec<RobotUnit>,
    /// Indices of the units a person does, in plan order.
    pub human_units: Vec<usize>,
    /// Σ cost over the robot's units.
    pub cost: f64,
    /// Π success rate over the robot's units: the chance the robot does its whole part.
    pub success_rate: f64,
}

impl PlanRequest {
    pub fn new(query: Query) -> PlanRequest {
        PlanRequest {
            query,
            modify: true,
            overrides: BTreeMap::new(),
            explain: false,
            robot: None,
        }
    }
}

#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct DishClassRef {
    pub index: u32,
    pub name: String,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct GoalInfo {
    /// The dish the plan makes, named for the query (see `planner/modify/name.rs`).
    pub label: SmolStr,
    /// The reference goal node Algorithm 1 picked, as the knowledge base names it.
    pub reference: SmolStr,
    /// States rendered as FOON text: `sliced`, `in [bowl]`, `contains {a,b}`.
    pub states: Vec<SmolStr>,
    /// The reference goal's ingredient list.
    pub ingredients: Vec<String>,
    /// Source subgraph (file name).
    pub subgraph: String,
    /// Graded similarity of the query's and the goal's ingredient sets, 0..1.
    pub score: f32,
    pub dish_class: Option<u32>,
}

/// An object node as the plan shows it.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
pub struct PlanNode {
    pub label: SmolStr,
    pub states: Vec<SmolStr>,
    /// Its `contains {…}` list, if any.
    pub ingredients: Vec<SmolStr>,
    pub container: Option<SmolStr>,
}

impl From<&ObjectNode> for PlanNode {
    fn from(n: &ObjectNode) -> PlanNode {
        PlanNode {
            label: n.label.clone(),
            states: n.states.iter().map(State::text).collect(),
            ingredients: n.ingredients(),
            container: n.container().map(SmolStr::from),
        }
    }
}

impl PlanNode {
    /// Whether the node is `label` in the set of `states` (in any order).
    pub fn is(&self, label: &str, states: &[SmolStr]) -> bool {
        self.label == label && sorted(&self.states) == sorted(states)
    }
}

/// A list of states or names in sorted order, for comparing as sets.
pub(crate) fn sorted(list: &[SmolStr]) -> Vec<&str> {
    let mut words: Vec<&str> = list.iter().map(SmolStr::as_str).collect();
    words.sort_unstable();
    words
}

/// How modification touched a unit.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Origin {
    /// As retrieved from FOON.
    Reference,
    /// An object in it was substituted (case 2/4) or its contents changed.
    Renamed,
    /// Added to bring an ingredient to its state (case 3/4), from FOON or made from the most frequent motion.
    Grafted,
    /// A copy of a branch, made so that the original ingredient stays in the tree (case 2).
    Copied,
    /// A unit that received a new ingredient branch as an extra input.
    Attached,
}

#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct PlanUnit {
    /// Nodes are shared: the node a unit makes is the same value where a later unit uses it.
    pub inputs: Vec<Arc<PlanNode>>,
    pub motion: SmolStr,
    pub outputs: Vec<Arc<PlanNode>>,
    pub origin: Origin,
    /// Subgraphs the unit comes from (empty for units the planner made).
    pub sources: Arc<[String]>,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Match {
    pub label: SmolStr,
    pub state: SmolStr,
    pub similarity: f32,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Alternative {
    pub label: SmolStr,
    pub similarity: f32,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Status {
    Planned,
    Unplannable,
}

/// The outcome of one query ingredient.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct IngredientOutcome {
    pub object: SmolStr,
    pub state: SmolStr,
    /// Table I of the paper (1..4); `None` when unplannable before a case applies.
    pub case: Option<u8>,
    #[serde(rename = "match")]
    pub matched: Option<Match>,
    /// Top-5 other equivalents, best first.
    pub alternatives: Vec<Alternative>,
    pub low_confidence: bool,
    pub overridden: bool,
    pub status: Status,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub reason: Option<String>,
}

#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct ProgressState {
    pub physical_state: SmolStr,
    pub location: SmolStr,
}

/// One ingredient's progress line (section IV-A): states and locations, the motions between them, and the
/// end product it goes into.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct ProgressLine {
    pub ingredient: SmolStr,
    pub state: Vec<ProgressState>,
    /// Motion i leads from state i to state i+1.
    pub motion: Vec<SmolStr>,
    /// The first mixture or dish the ingredient joins (the goal when it joins nothing before it).
    pub end_product: SmolStr,
}

/// A kind of culinary error a plan can have.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum CautionKind {
    /// A food takes a motion its form rules out (a powder squeezed, a liquid baked).
    MotionOnForm,
    /// A food that must be cooked reaches the dish uncooked.
    Uncooked,
    /// An asked ingredient's progress line ends short of the goal dish.
    ShortOfDish,
    /// Produce a cook prepares goes into the dish whole and raw.
    LeftWhole,
}

impl CautionKind {
    pub const ALL: [CautionKind; 4] = [
        CautionKind::MotionOnForm,
        CautionKind::Uncooked,
        CautionKind::ShortOfDish,
        CautionKind::LeftWhole,
    ];

    pub fn name(self) -> &'static str {
        match self {
            CautionKind::MotionOnForm => "motion_on_form",
            CautionKind::Uncooked => "uncooked",
            CautionKind::ShortOfDish => "short_of_dish",
            CautionKind::LeftWhole => "left_whole",
        }
    }
}

/// One thing a cook would stop at, with the food and what is wrong in words.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Caution {
    pub kind: CautionKind,
    pub food: String,
    pub detail: String,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Plan {
    pub format_version: u32,
    /// The query as planned, after normalisation of names and removal of duplicates.
    pub query: Query,
    pub dish_class: Option<DishClassRef>,
    pub notes: Vec<String>,
    /// `false` for the reference task tree as retrieved.
    pub modified: bool,
    pub goal: GoalInfo,
    /// In a valid execution order: every produced input is made by an earlier unit. The app's JSON has
    /// shared nodes by number (`contract::json`).
    #[serde(with = "crate::contract::json")]
    pub units: Vec<PlanUnit>,
    /// One per query ingredient (after duplicates were removed), in query order.
    pub ingredients: Vec<IngredientOutcome>,
    /// Labels pruned from the reference tree (not asked for).
    pub removed: Vec<String>,
    pub progress_lines: Vec<ProgressLine>,
    /// One plain sentence per unit, same order as `units`.
    pub steps: Vec<String>,
    /// What a cook would stop at in the plan (`planner::cautions`), in the order found.
    pub cautions: Vec<Caution>,
    /// How the plan was found, step by step (only when the request asked to `explain`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub trace: Option<Trace>,
    /// Each unit's motion cost, success rate and performer (only when the request gave `robot`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub robot: Option<RobotView>,
}
