// Types of everything that crosses the WASM boundary. They mirror the serde types of foon-core
// (wasm/core/src/stats.rs, plan.rs, error.rs); docs/plan-format.md describes the plan format.

/** A knowledge-base file as given to the loader: one FOON subgraph, or a bundle of them. */
export interface KnowledgeBaseFile {
  name: string;
  bytes: Uint8Array;
}

export interface Stats {
  subgraphs: number;
  units_before_merge: number;
  units: number;
  object_nodes: number;
  labels: number;
  ingredient_labels: number;
  states: number;
  motions: number;
  goal_nodes: number;
  kitchen_nodes: number;
  warnings: number;
  goals_per_class: Record<string, number>;
  recipes_per_class: Record<string, number>;
}

/** Stable error codes of foon-core (ErrorCode::as_str), plus the loader's own. */
export type ErrorCode =
  | "invalid_utf8"
  | "too_large"
  | "unknown_line"
  | "missing_field"
  | "bad_number"
  | "empty_label"
  | "bad_brackets"
  | "state_without_object"
  | "bad_motion"
  | "motion_without_inputs"
  | "unit_without_outputs"
  | "empty_knowledge_base"
  | "bad_query"
  | "bad_embeddings"
  | "no_goal"
  | "not_initialised"
  | "unsupported"
  | "internal";

/** A core error as data (warnings come back in this shape too). */
export interface FoonErrorData {
  code: ErrorCode;
  message: string;
  file?: string;
  line?: number;
  column?: number;
}

// ---- Plans (docs/plan-format.md; wasm/core/src/plan.rs) ----

export interface QueryIngredient {
  object: string;
  state: string;
}

/** A recipe query: the shape of the Recipe1M+-derived query files. */
export interface Query {
  id?: string;
  type: string;
  ingredients: QueryIngredient[];
}

export interface PlanRequest {
  query: Query;
  /** false returns the reference task tree as retrieved (default true). */
  modify?: boolean;
  /** Query object -> the equivalent label the user chose. */
  overrides?: Record<string, string>;
  /** true adds `Plan.trace`: how the plan was found, step by step (default false). */
  explain?: boolean;
  /** The retrieval mode and a robot's figures; the plan then has `robot` (docs/robot.md). */
  robot?: RobotOptions;
}

/** How Algorithm 2 chooses among the units making a node: the paper's heuristic or an exact optimum. */
export type RetrievalMode = "heuristic" | "fewest_units" | "lowest_cost" | "most_reliable";

export const RETRIEVAL_MODES: readonly RetrievalMode[] = ["heuristic", "fewest_units", "lowest_cost", "most_reliable"];

export interface RobotOptions {
  mode?: RetrievalMode;
  /** Motion -> cost (1 = a pick-and-place), over the project's table. */
  motion_costs?: Record<string, number>;
  /** Motion -> success rate in (0, 1], over the project's table. */
  success_rates?: Record<string, number>;
  /** How many of the least reliable units a person does instead of the robot (default 0). */
  human_steps?: number;
}

/** A unit's motion for a robot, in the order of `Plan.units`. */
export interface RobotUnit {
  cost: number;
  success_rate: number;
  by: "robot" | "human";
}

export interface RobotView {
  mode: RetrievalMode;
  units: RobotUnit[];
  /** Indices of the units a person does, in plan order. */
  human_units: number[];
  /** Sum of the robot's units' costs. */
  cost: number;
  /** Product of the robot's units' success rates. */
  success_rate: number;
}

export interface PlanNode {
  label: string;
  states: string[];
  ingredients: string[];
  container: string | null;
}

export type UnitOrigin = "reference" | "renamed" | "grafted" | "copied" | "attached";

export interface PlanUnit {
  inputs: PlanNode[];
  motion: string;
  outputs: PlanNode[];
  origin: UnitOrigin;
  sources: string[];
}

export interface Alternative {
  label: string;
  similarity: number;
}

export type SubstitutionCase = 1 | 2 | 3 | 4;

export interface IngredientOutcome {
  object: string;
  state: string;
  case: SubstitutionCase | null;
  match: { label: string; state: string; similarity: number } | null;
  alternatives: Alternative[];
  low_confidence: boolean;
  overridden: boolean;
  status: "planned" | "unplannable";
  reason?: string;
}

export interface ProgressLine {
  ingredient: string;
  state: { physical_state: string; location: string }[];
  motion: string[];
  end_product: string;
}

/** A kind of culinary error the planner's food knowledge finds in a plan (`planner::cautions`). */
export type CautionKind = "motion_on_form" | "uncooked" | "short_of_dish" | "left_whole";

/** What a cook would stop at in a plan: the food and what is wrong, in words. */
export interface Caution {
  kind: CautionKind;
  food: string;
  detail: string;
}

export interface Plan {
  format_version: number;
  query: Query;
  dish_class: { index: number; name: string } | null;
  notes: string[];
  modified: boolean;
  goal: {
    /** The dish the plan makes, named for the query. */
    label: string;
    /** The reference goal node Algorithm 1 picked, as the knowledge base names it. */
    reference: string;
    states: string[];
    ingredients: string[];
    subgraph: string;
    score: number;
    dish_class: number | null;
  };
  units: PlanUnit[];
  ingredients: IngredientOutcome[];
  removed: string[];
  progress_lines: ProgressLine[];
  steps: string[];
  cautions: Caution[];
  /** Only when the request asked to `explain`. */
  trace?: Trace;
  /** Only when the request gave `robot`. */
  robot?: RobotView;
}

// ---- The explain trace (docs/plan-format.md "Explain trace"; wasm/core/src/trace.rs) ----

/** A unit as FOON texts of its nodes. */
export interface TraceUnit {
  inputs: string[];
  motion: string;
  outputs: string[];
}

export interface GoalCandidate {
  node: string;
  subgraph: string;
  ingredients: number;
  recall: number;
  precision: number;
  exact_matches: number;
  score: number;
}

export type GoalTieBreak = "score" | "exact_matches" | "fewer_ingredients" | "name" | "kin_class" | "fuller_tree";

export type ExpansionOutcome = "kitchen" | "recipe_start" | "expanded" | "cycle" | "had_from_start";

export type ChoiceReason =
  | "only"
  | "reused"
  | "same_recipe"
  | "no_detour"
  | "heuristic"
  | "fewer_inputs"
  | "id"
  | Exclude<RetrievalMode, "heuristic">;

export interface CandidateUnit extends TraceUnit {
  heuristic: number;
  reused: boolean;
  same_recipe: boolean;
  cycle: boolean;
  /** In a retrieval mode other than the heuristic: the best tree's value through this unit (least wins). */
  value?: number;
}

export interface Expansion {
  node: string;
  outcome: ExpansionOutcome;
  candidates: CandidateUnit[];
  chosen: number | null;
  why: ChoiceReason | null;
}

export type EquivalentRoute = "override" | "exact" | "tree" | "foon" | "none";

export interface IngredientTrace {
  object: string;
  state: string;
  route: EquivalentRoute;
  tree_match: Alternative | null;
  foon_match: Alternative | null;
  case: SubstitutionCase | null;
  planned: boolean;
  reason: string | null;
  state_choice: {
    node: string | null;
    category: string;
    in_state: boolean;
    frequency_in_class: number;
    frequency_overall: number;
  } | null;
  attached: { motion: string; pattern: string[]; rank: number | null } | null;
}

export interface Trace {
  trace_version: 1;
  goal_selection: { searched_all: boolean; candidates: GoalCandidate[]; kin_class: string | null; tie_break: GoalTieBreak | null };
  retrieval: Expansion[];
  ingredients: IngredientTrace[];
  pruning: { removed: string[]; units: TraceUnit[] };
}

/** Export formats of a plan. */
export type ExportFormat = "json" | "foon" | "pddl" | "pddl-domain" | "pddl-problem" | "progress";

/** Equivalents for a name, as `cli similar` prints them. */
export interface SimilarResult {
  query: string;
  candidates: Alternative[];
}

/** What the query editor offers (`foon_core::Vocabulary`): the knowledge base's dish classes with their
 * recipes, its labels and plain states in the planner's normal forms. */
export interface Vocabulary {
  /** Dish classes that have at least one recipe, with the recipe titles. */
  dishes: { name: string; recipes: string[] }[];
  /** Object labels, sorted. */
  labels: string[];
  /** Plain state names (no container arguments), sorted. */
  states: string[];
  /** Recipe title of every subgraph file: its `# title:` line, else its name ("s01-greek_salad.txt" -> "greek salad"). */
  titles: Record<string, string>;
}
