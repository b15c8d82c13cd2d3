// The metrics table: batch records aggregated per dish type and overall, per variant.

import { emptyCases } from "./coverage";
import { CAUTION_KINDS, emptyCautionCounts } from "./plausibility";
import { LITTLE_REFERENCE, type CaseCounts, type EvalRecord, type MetricsRow, type PlanMetrics, type Variant } from "./types";

export const ALL = "all";

const mean = (xs: readonly number[]): number => (xs.length === 0 ? 0 : xs.reduce((a, b) => a + b, 0) / xs.length);
const sum = (xs: readonly number[]): number => xs.reduce((a, b) => a + b, 0);
const ratio = (part: number, whole: number): number => (whole === 0 ? 1 : part / whole);

/** Nearest-rank percentile (p in 0..100) of unsorted values; 0 for none. */
export function percentile(values: readonly number[], p: number): number {
  if (values.length === 0) return 0;
  const sorted = [...values].sort((a, b) => a - b);
  const rank = Math.max(1, Math.ceil((p / 100) * sorted.length));
  return sorted[rank - 1]!;
}

function addCases(total: CaseCounts, add: CaseCounts): void {
  total.c1 += add.c1;
  total.c2 += add.c2;
  total.c3 += add.c3;
  total.c4 += add.c4;
  total.none += add.none;
}

/** Examples of cautions kept per group row. */
export const CAUTION_EXAMPLES = 5;

function cautionsOf(records: readonly EvalRecord[]): Pick<MetricsRow, "cautions" | "caution_examples"> {
  const cautions = emptyCautionCounts();
  const examples: string[] = [];
  for (const r of records) {
    if (!r.ok) continue;
    for (const kind of CAUTION_KINDS) cautions[kind] += r.metrics.cautions[kind];
    for (const d of r.metrics.caution_details) if (examples.length < CAUTION_EXAMPLES) examples.push(`${r.recipe.type}/${r.recipe.id} ${d}`);
  }
  return { cautions, caution_examples: examples };
}

export function metricsRow(group: string, variant: Variant, records: readonly EvalRecord[]): MetricsRow {
  const metrics: PlanMetrics[] = [];
  const errorsByCode: Record<string, number> = {};
  for (const r of records) {
    if (r.ok) metrics.push(r.metrics);
    else errorsByCode[r.error.code] = (errorsByCode[r.error.code] ?? 0) + 1;
  }
  const cases = emptyCases();
  for (const m of metrics) addCases(cases, m.cases);
  const substitutions = sum(metrics.map((m) => m.substitutions));
  const lowConfidence = sum(metrics.map((m) => m.low_confidence));
  const ms = records.map((r) => r.ms);
  return {
    group,
    variant,
    queries: records.length,
    plans: metrics.length,
    errors: records.length - metrics.length,
    errors_by_code: Object.fromEntries(Object.entries(errorsByCode).sort(([a], [b]) => a.localeCompare(b))),
    units_mean: mean(metrics.map((m) => m.units)),
    duplicate_units: sum(metrics.map((m) => m.duplicate_units)),
    units_before_inputs: sum(metrics.map((m) => m.units_before_inputs)),
    dead_units: sum(metrics.map((m) => m.dead_units)),
    goal_missing: metrics.filter((m) => !m.goal_produced).length,
    object_share: mean(metrics.map((m) => ratio(m.objects_in_tree, m.query_objects))),
    dish_share: mean(metrics.map((m) => ratio(m.objects_in_dish, m.query_objects))),
    pair_share: mean(metrics.map((m) => ratio(m.pairs_in_tree, m.query_pairs))),
    extra_mean: mean(metrics.map((m) => m.extra_ingredients.length)),
    plans_with_extra: metrics.length === 0 ? 0 : metrics.filter((m) => m.extra_ingredients.length > 0).length / metrics.length,
    plans_little_reference: metrics.length === 0 ? 0 : metrics.filter((m) => m.reference_units <= LITTLE_REFERENCE).length / metrics.length,
    own_type_reference: metrics.length === 0 ? 0 : metrics.filter((m) => m.reference_own_type).length / metrics.length,
    cases,
    substitutions,
    low_confidence: lowConfidence,
    low_confidence_share: substitutions === 0 ? 0 : lowConfidence / substitutions,
    unplannable: sum(metrics.map((m) => m.unplannable)),
    ...cautionsOf(records),
    ms_mean: mean(ms),
    ms_p95: percentile(ms, 95),
    ms_max: ms.length === 0 ? 0 : Math.max(...ms),
    ms_total: sum(ms),
  };
}

/** One row per dish type (sorted) and one `all` row, for one variant. */
export function metricsTable(records: readonly EvalRecord[], variant: Variant): MetricsRow[] {
  const mine = records.filter((r) => r.variant === variant);
  const types = [...new Set(mine.map((r) => r.recipe.type))].sort();
  return [...types.map((t) => metricsRow(t, variant, mine.filter((r) => r.recipe.type === t))), metricsRow(ALL, variant, mine)];
}

/** Variants present in a set of records, in the fixed order (modified first). */
export function variantsOf(records: readonly EvalRecord[]): Variant[] {
  const present = new Set(records.map((r) => r.variant));
  return (["modified", "unmodified"] as const).filter((v) => present.has(v));
}
