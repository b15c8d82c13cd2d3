// Runs a batch: every query through the planner, in each variant, timing each plan and turning
// failures into typed error records. The CLI calls it directly, the workbench from a worker.

import { toPlannerError } from "../planner/index";
import type { Plan, PlanRequest } from "../planner/types";
import { planMetrics } from "./metrics";
import type { EvalRecord, LoadedQuery, Variant } from "./types";

export type PlanFunction = (request: PlanRequest) => Plan;

export interface PlannedRecipe {
  record: EvalRecord;
  /** The plan, when one was produced. */
  plan: Plan | null;
}

/** Plans one query in one variant. `now` is a millisecond clock (performance.now). */
export function runOne(plan: PlanFunction, loaded: LoadedQuery, variant: Variant, now: () => number): PlannedRecipe {
  const recipe = { id: loaded.query.id, type: loaded.query.type };
  const start = now();
  try {
    const result = plan({ query: loaded.query, modify: variant === "modified" });
    const ms = now() - start;
    return { record: { recipe, variant, ok: true, ms, metrics: planMetrics(result) }, plan: result };
  } catch (thrown) {
    const ms = now() - start;
    const error = toPlannerError(thrown);
    return { record: { recipe, variant, ok: false, ms, error: { code: error.code, message: error.message } }, plan: null };
  }
}

/** Plans every query in every variant, in order, calling `onResult` after each. */
export function runBatch(
  plan: PlanFunction,
  queries: readonly LoadedQuery[],
  variants: readonly Variant[],
  now: () => number,
  onResult?: (result: PlannedRecipe, done: number, total: number) => void,
): EvalRecord[] {
  const records: EvalRecord[] = [];
  const total = queries.length * variants.length;
  for (const loaded of queries) {
    for (const variant of variants) {
      const result = runOne(plan, loaded, variant, now);
      records.push(result.record);
      onResult?.(result, records.length, total);
    }
  }
  return records;
}
