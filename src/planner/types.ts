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
  | "internal";

/** A core error as data (warnings come back in this shape too). */
export interface FoonErrorData {
  code: ErrorCode;
  message: string;
  file?: string;
  line?: number;
  column?: number;
}

// ---- Plans (docs/plan-format.md, wasm/core/src/plan.rs) ----

/** One ingredient of a query: an object and the state it should reach ("" when unspecified). */
export interface QueryIngredient {
  object: string;
  state: string;
}

export interface Query {
  id?: string;
  /** The dish type (a dish class name such as "salad", or free text). */
  type: string;
  ingredients: QueryIngredient[];
}

export interface PlanRequest {
  query: Query;
  /** `false` returns the reference task tree as retrieved. Default true. */
  modify?: boolean;
  /** Query object -> the equivalent label the user chose. */
  overrides?: Record<string, string>;
}

/** An object node of the plan. */
export interface PlanNode {
  label: string;
  states: string[];
  ingredients: string[];
  container: string | null;
}

/** How modification touched a functional unit. */
export type UnitOrigin = "reference" | "renamed" | "grafted" | "copied" | "attached";

export interface PlanUnit {
  inputs: PlanNode[];
  motion: string;
  outputs: PlanNode[];
  origin: UnitOrigin;
  sources: string[];
}

export interface IngredientMatch {
  label: string;
  state: string;
  similarity: number;
}

export interface Alternative {
  label: string;
  similarity: number;
}

/** The substitution case of Table I of the paper. */
export type SubstitutionCase = 1 | 2 | 3 | 4;

export interface IngredientOutcome {
  object: string;
  state: string;
  case: SubstitutionCase | null;
  match: IngredientMatch | null;
  alternatives: Alternative[];
  low_confidence: boolean;
  overridden: boolean;
  status: "planned" | "unplannable";
  reason?: string;
}

export interface ProgressState {
  physical_state: string;
  location: string;
}

/** One ingredient's progress line (section IV-A): motion i leads from state i to state i+1. */
export interface ProgressLine {
  ingredient: string;
  state: ProgressState[];
  motion: string[];
  end_product: string;
}

export interface GoalInfo {
  label: string;
  states: string[];
  ingredients: string[];
  subgraph: string;
  score: number;
  dish_class: number | null;
}

export interface Plan {
  format_version: 1;
  query: Query;
  dish_class: { index: number; name: string } | null;
  notes: string[];
  modified: boolean;
  goal: GoalInfo;
  units: PlanUnit[];
  ingredients: IngredientOutcome[];
  removed: string[];
  progress_lines: ProgressLine[];
  steps: string[];
}

/** Formats of `FoonPlanner.export`: FOON text, the plan's JSON, PDDL, the progress lines' JSON. */
export type ExportFormat = "foon" | "json" | "pddl" | "progress";

/** What the query editor offers: the knowledge base's dish classes with their recipes, labels and states. */
export interface Vocabulary {
  /** Dish classes that have at least one recipe, with the recipe titles. */
  dishes: { name: string; recipes: string[] }[];
  /** Object labels, sorted. */
  labels: string[];
  /** Plain state names (no container arguments), sorted. */
  states: string[];
  /** Recipe title of each subgraph file ("s01-greek_salad.txt" -> "Greek salad"). */
  titles: Record<string, string>;
}
