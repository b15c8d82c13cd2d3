// Types of the evaluation workbench: per-plan metrics, batch records, aggregated metrics tables.
// Shared by the CLI (src/cli/eval.ts) and the browser workbench (src/workbench/), so both compute
// the same numbers from the same code.

import type { CautionKind, ErrorCode, Query } from "../planner/types";

/** A plan with tree modification (the method) or the reference tree as retrieved. */
export type Variant = "modified" | "unmodified";
export const VARIANTS: readonly Variant[] = ["modified", "unmodified"];

/** Structural invariants, computed from `units` alone. All three must be 0. */
export interface StructureMetrics {
  units: number;
  /** Units whose (inputs, motion, outputs) already occurred earlier in the plan. */
  duplicate_units: number;
  /** Units with an input that some unit of the plan produces, but only a later one. */
  units_before_inputs: number;
  /** Units none of whose produced outputs is used later, and which do not output the goal. */
  dead_units: number;
  /** Whether some unit outputs the goal (label and states of `plan.goal`). */
  goal_produced: boolean;
  /** What breaks the three invariants, one sentence each ("unit 3 (pour) needs …, first made by unit 7"). */
  violations: string[];
}

export interface CoverageMetrics {
  /** Distinct query objects. */
  query_objects: number;
  /** Of those, the ones that occur in the tree (as a node label or in a node's ingredients). */
  objects_in_tree: number;
  /** Of those, the ones the dish lists (the goal node made last: its label or its ingredients). */
  objects_in_dish: number;
  /** Distinct query (object, state) pairs. */
  query_pairs: number;
  /** Of those, the ones with a node of that label carrying that state. */
  pairs_in_tree: number;
  /** Starting ingredients of the tree that the query did not ask for (labels). */
  extra_ingredients: string[];
  /** Units of the reference task tree the plan keeps (as retrieved, renamed, or given a new ingredient). */
  reference_units: number;
  /** Whether the reference goal node is a dish of the query's own dish class (false for an unknown type). */
  reference_own_type: boolean;
  /** Substitution case per query ingredient (Table I), `none` when no case applied. */
  cases: CaseCounts;
  /** Query ingredients planned with an equivalent of another name. */
  substitutions: number;
  /** Of those, the ones flagged low-confidence. */
  low_confidence: number;
  unplannable: number;
}

export interface CaseCounts {
  c1: number;
  c2: number;
  c3: number;
  c4: number;
  none: number;
}

/** What the planner's food knowledge finds a cook would stop at (`src/eval/plausibility.ts`). */
export interface PlausibilityMetrics {
  cautions: Record<CautionKind, number>;
  /** "kind: detail", one per caution. */
  caution_details: string[];
}

export interface PlanMetrics extends StructureMetrics, CoverageMetrics, PlausibilityMetrics {}

export interface RecipeRef {
  id: string;
  type: string;
}

/** One query planned in one variant: metrics, or the typed error it raised. */
export type EvalRecord =
  | { recipe: RecipeRef; variant: Variant; ok: true; ms: number; metrics: PlanMetrics }
  | { recipe: RecipeRef; variant: Variant; ok: false; ms: number; error: { code: ErrorCode; message: string } };

/** A recipe query as read from a file, with where it came from. */
export interface LoadedQuery {
  source: string;
  query: Query & { id: string };
}

/** One row of the metrics table: a dish type, or `all`. */
export interface MetricsRow {
  group: string;
  variant: Variant;
  queries: number;
  plans: number;
  errors: number;
  errors_by_code: Record<string, number>;
  units_mean: number;
  duplicate_units: number;
  units_before_inputs: number;
  dead_units: number;
  goal_missing: number;
  /** Mean over plans of the share of query objects present in the tree, 0..1. */
  object_share: number;
  /** Mean over plans of the share of query objects the dish lists, 0..1. */
  dish_share: number;
  /** Mean over plans of the share of query (object, state) pairs present, 0..1. */
  pair_share: number;
  /** Mean number of extra starting ingredients per plan. */
  extra_mean: number;
  /** Share of plans with at least one extra starting ingredient, 0..1. */
  plans_with_extra: number;
  /**
   * Share of plans keeping at most `LITTLE_REFERENCE` units of their reference task tree, 0..1: the knowledge
   * base had no recipe of the type like the query, and the plan is mostly the ingredients' own branches.
   */
  plans_little_reference: number;
  /**
   * Share of plans whose reference goal node is a dish of the query's own dish class, 0..1: below 1, the
   * knowledge base lacks a recipe of the type close enough and a kin class's (or any class's) stood in.
   */
  own_type_reference: number;
  cases: CaseCounts;
  substitutions: number;
  low_confidence: number;
  /** low_confidence / substitutions, 0..1 (0 without substitutions). */
  low_confidence_share: number;
  unplannable: number;
  /** Cautions per kind, summed over plans. */
  cautions: Record<CautionKind, number>;
  /** The first few cautions of the group, "type/id kind: detail". */
  caution_examples: string[];
  ms_mean: number;
  ms_p95: number;
  ms_max: number;
  ms_total: number;
}

/** At most this many units kept of the reference task tree is "little" (`plans_little_reference`). */
export const LITTLE_REFERENCE = 2;

/** Structural invariant totals that must be 0 (what `npm test` checks). */
export const INVARIANTS = ["duplicate_units", "units_before_inputs", "dead_units"] as const;
export type Invariant = (typeof INVARIANTS)[number];
