//! The explain trace of a plan (`PlanRequest.explain`): how the planner went from the query to the task
//! tree, step by step, in the paper's terms. Part of the plan JSON (`docs/plan-format.md`, "Explain
//! trace"); written only when asked for, and never changes the plan.

use serde::{Deserialize, Serialize};

/// Version of the trace JSON; bump on any incompatible change (and in `docs/plan-format.md`).
pub const TRACE_VERSION: u32 = 1;

#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Trace {
    pub trace_version: u32,
    pub goal_selection: GoalSelection,
    /// Algorithm 2: every node taken from the queue, in order.
    pub retrieval: Vec<Expansion>,
    /// Section III-C: one per query ingredient, in query order.
    pub ingredients: Vec<IngredientTrace>,
    pub pruning: Pruning,
}

/// Algorithm 1: the candidate goal nodes, best first (the first is the reference goal).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct GoalSelection {
    /// Whether the dish type had no goal of its class, so that every goal node was a candidate.
    pub searched_all: bool,
    /// The dish type's goals, best first; led by the reference goal of `kin_class` when there is one.
    pub candidates: Vec<GoalCandidate>,
    /// A dish type made the same way whose goal was taken because none of the dish type's fit well.
    pub kin_class: Option<String>,
    /// What separated the reference goal from the runner-up: `score`, `exact_matches`,
    /// `fewer_ingredients`, `name`, `kin_class` or `fuller_tree` (the best-scoring goal's tree kept next
    /// to nothing of itself for the query); `None` with a single candidate.
    pub tie_break: Option<String>,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct GoalCandidate {
    /// The goal node as FOON text.
    pub node: String,
    pub subgraph: String,
    pub ingredients: usize,
    /// Share of the query the goal covers, 0..1.
    pub recall: f32,
    /// Share of the goal the query uses, 0..1.
    pub precision: f32,
    /// Query names the goal has exactly.
    pub exact_matches: usize,
    pub score: f32,
}

/// What the search did with a node it took from the queue.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Outcome {
    /// In the kitchen: taken as it is.
    Kitchen,
    /// A starting item of the recipe that needs it: taken from the kitchen, as that recipe did.
    RecipeStart,
    /// A unit was chosen to make it.
    Expanded,
    /// Every unit making it would close a cycle: taken as available.
    Cycle,
    /// Only the recipe makes it again later (a lid put back): it had it from the start.
    HadFromStart,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Expansion {
    /// The node as FOON text.
    pub node: String,
    pub outcome: Outcome,
    /// The units making the node, as the search weighed them (empty unless it looked for one).
    pub candidates: Vec<CandidateUnit>,
    /// Index in `candidates` of the unit chosen.
    pub chosen: Option<usize>,
    /// The preference that chose it over the closest runner-up: `only` (no rival), `reused`,
    /// `same_recipe`, `no_detour`, `heuristic` (g(u)), `fewer_inputs` or `id`; in another retrieval
    /// mode, the mode (`fewest_units`, `lowest_cost`, `most_reliable`).
    pub why: Option<String>,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CandidateUnit {
    #[serde(flatten)]
    pub unit: TraceUnit,
    /// g(u): the similarity-weighted overlap of the query with the unit's ingredients.
    pub heuristic: f32,
    /// Already in the tree (always reused).
    pub reused: bool,
    /// Of the recipe of the unit that needs the node.
    pub same_recipe: bool,
    /// Would close a cycle: never chosen.
    pub cycle: bool,
    /// In a retrieval mode other than the heuristic: the value of the best tree making the node with this
    /// unit (units, motion cost, or −ln of the success rate; the least wins).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub value: Option<f64>,
}

/// A name and how similar it is to the query's ingredient.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct NameMatch {
    pub label: String,
    pub similarity: f32,
}

/// How the equivalent was found: `override` (the caller's), `exact` (a FOON label), `tree` (most
/// similar in the reference tree), `foon` (most similar in the universal FOON) or `none`.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct IngredientTrace {
    pub object: String,
    pub state: String,
    pub route: String,
    /// Best match in the reference task tree and in the whole knowledge base (looked up only for a
    /// name that is not a FOON label).
    pub tree_match: Option<NameMatch>,
    pub foon_match: Option<NameMatch>,
    /// Table I.
    pub case: Option<u8>,
    pub planned: bool,
    pub reason: Option<String>,
    /// For a branch from the universal FOON: the node chosen by the state taxonomy.
    pub state_choice: Option<StateChoice>,
    /// For a branch from the universal FOON: where it joins the tree.
    pub attached: Option<Attachment>,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct StateChoice {
    /// The knowledge-base node as FOON text (`None`: taken as bought).
    pub node: Option<String>,
    /// The state taxonomy's category of the state asked for.
    pub category: String,
    /// Whether the node is in the state asked for (else the ingredient as it comes from the kitchen).
    pub in_state: bool,
    /// How often the node's food states occur with the ingredient in recipes of the dish class, and
    /// in all recipes.
    pub frequency_in_class: u32,
    pub frequency_overall: u32,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Attachment {
    pub motion: String,
    /// The dish class's motions for new ingredients, first preferred.
    pub pattern: Vec<String>,
    /// Position of the motion in `pattern` (`None`: not in it).
    pub rank: Option<usize>,
}

#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Pruning {
    /// Labels pruned (not asked for).
    pub removed: Vec<String>,
    /// The units that went with them.
    pub units: Vec<TraceUnit>,
    /// The tree's live units before pruning, while it runs (by the tree's number).
    #[serde(skip)]
    pub(crate) alive_before: Vec<(usize, TraceUnit)>,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct TraceUnit {
    pub inputs: Vec<String>,
    pub motion: String,
    pub outputs: Vec<String>,
}
