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
