// Presentation of the metrics table, shared by the CLI (text) and the workbench (HTML table):
// one line per metric, one column per dish type and `all`. Plus CSV and JSON of the results.

import { toCsv, type Cell } from "./csv";
import { CAUTION_KINDS, CAUTION_LABELS } from "./plausibility";
import { LITTLE_REFERENCE, type EvalRecord, type MetricsRow, type Variant } from "./types";

const pct = (x: number): string => `${(x * 100).toFixed(1)}%`;
const fixed = (digits: number) => (x: number): string => x.toFixed(digits);

export interface MetricLine {
  key: string;
  label: string;
  format: (row: MetricsRow) => string;
  /** A structural invariant: anything but 0 is a failure. */
  invariant?: boolean;
}

export const METRIC_LINES: readonly MetricLine[] = [
  { key: "plans", label: "plans produced", format: (r) => `${r.plans}/${r.queries}` },
  {
    key: "errors",
    label: "typed errors",
    format: (r) => (r.errors === 0 ? "0" : `${r.errors} (${Object.entries(r.errors_by_code).map(([c, n]) => `${c}: ${n}`).join(", ")})`),
  },
  { key: "units_mean", label: "mean units", format: (r) => fixed(1)(r.units_mean) },
  { key: "duplicate_units", label: "duplicated units", format: (r) => String(r.duplicate_units), invariant: true },
  { key: "units_before_inputs", label: "units before their inputs", format: (r) => String(r.units_before_inputs), invariant: true },
  { key: "dead_units", label: "dead units", format: (r) => String(r.dead_units), invariant: true },
  { key: "goal_missing", label: "plans without the goal", format: (r) => String(r.goal_missing) },
  { key: "object_share", label: "query objects in tree", format: (r) => pct(r.object_share) },
  { key: "dish_share", label: "query objects in the dish", format: (r) => pct(r.dish_share) },
  { key: "pair_share", label: "query (object, state) in tree", format: (r) => pct(r.pair_share) },
  { key: "extra_mean", label: "extra ingredients / plan", format: (r) => fixed(2)(r.extra_mean) },
  { key: "plans_with_extra", label: "plans with extras", format: (r) => pct(r.plans_with_extra) },
  { key: "plans_little_reference", label: `plans keeping <= ${LITTLE_REFERENCE} reference units`, format: (r) => pct(r.plans_little_reference) },
  { key: "own_type_reference", label: "reference of the query's dish type", format: (r) => pct(r.own_type_reference) },
  { key: "case1", label: "case 1 (exact)", format: (r) => String(r.cases.c1) },
  { key: "case2", label: "case 2 (object subst.)", format: (r) => String(r.cases.c2) },
  { key: "case3", label: "case 3 (new state)", format: (r) => String(r.cases.c3) },
  { key: "case4", label: "case 4 (both)", format: (r) => String(r.cases.c4) },
  { key: "case_none", label: "no case", format: (r) => String(r.cases.none) },
  { key: "unplannable", label: "unplannable ingredients", format: (r) => String(r.unplannable) },
  { key: "low_confidence_share", label: "low-confidence substitutions", format: (r) => `${pct(r.low_confidence_share)} (${r.low_confidence}/${r.substitutions})` },
  ...CAUTION_KINDS.map((kind): MetricLine => ({ key: kind, label: CAUTION_LABELS[kind], format: (r) => String(r.cautions[kind]) })),
  { key: "ms_mean", label: "time mean (ms)", format: (r) => fixed(1)(r.ms_mean) },
  { key: "ms_p95", label: "time p95 (ms)", format: (r) => fixed(1)(r.ms_p95) },
  { key: "ms_max", label: "time max (ms)", format: (r) => fixed(1)(r.ms_max) },
  { key: "ms_total", label: "time total (s)", format: (r) => fixed(2)(r.ms_total / 1000) },
];

/** The table as plain text for a terminal (metrics down, groups across). */
export function formatTable(rows: readonly MetricsRow[], title: string): string {
  const header = ["", ...rows.map((r) => r.group)];
  const body = METRIC_LINES.map((line) => [line.label, ...rows.map((r) => line.format(r))]);
  const all = [header, ...body];
  const widths = header.map((_, j) => Math.max(...all.map((row) => row[j]!.length)));
  const render = (row: readonly string[]): string => row.map((cell, j) => (j === 0 ? cell.padEnd(widths[j]!) : cell.padStart(widths[j]!))).join("  ");
  return [title, render(header), ...body.map(render)].join("\n") + "\n";
}

/** The cautions of the `all` row of each variant, as lines to print under the table. */
export function cautionExamples(rows: readonly MetricsRow[]): string[] {
  return rows.filter((r) => r.group === "all" && r.caution_examples.length > 0).flatMap((r) => [`${r.variant}, first cautions:`, ...r.caution_examples.map((e) => `  ${e}`)]);
}

/** Structural invariants that break, as messages (empty when all hold). */
export function brokenInvariants(rows: readonly MetricsRow[]): string[] {
  return rows
    .filter((r) => r.group === "all")
    .flatMap((r) =>
      METRIC_LINES.filter((l) => l.invariant === true && l.format(r) !== "0").map((l) => `${r.variant}: ${l.label} = ${l.format(r)} (must be 0)`),
    );
}

const SUMMARY_COLUMNS = [
  "variant", "group", "queries", "plans", "errors", "errors_by_code", "units_mean", "duplicate_units", "units_before_inputs",
  "dead_units", "goal_missing", "object_share", "dish_share", "pair_share", "extra_mean", "plans_with_extra", "plans_little_reference", "own_type_reference", "case1", "case2", "case3",
  "case4", "case_none", "unplannable", "substitutions", "low_confidence", "low_confidence_share", ...CAUTION_KINDS, "ms_mean", "ms_p95",
  "ms_max", "ms_total",
] as const;

export function summaryCsv(rows: readonly MetricsRow[]): string {
  return toCsv(
    SUMMARY_COLUMNS,
    rows.map((r): Cell[] => [
      r.variant, r.group, r.queries, r.plans, r.errors, Object.entries(r.errors_by_code).map(([c, n]) => `${c}:${n}`).join(" "),
      r.units_mean, r.duplicate_units, r.units_before_inputs, r.dead_units, r.goal_missing, r.object_share, r.dish_share, r.pair_share,
      r.extra_mean, r.plans_with_extra, r.plans_little_reference, r.own_type_reference, r.cases.c1, r.cases.c2, r.cases.c3, r.cases.c4, r.cases.none, r.unplannable,
      r.substitutions, r.low_confidence, r.low_confidence_share, ...CAUTION_KINDS.map((k) => r.cautions[k]), r.ms_mean, r.ms_p95, r.ms_max, r.ms_total,
    ]),
  );
}

const RECIPE_COLUMNS = [
  "type", "id", "variant", "ok", "error_code", "error", "ms", "units", "duplicate_units", "units_before_inputs", "dead_units",
  "goal_produced", "query_objects", "objects_in_tree", "objects_in_dish", "query_pairs", "pairs_in_tree", "extra_ingredients", "reference_units", "reference_own_type", "case1", "case2",
  "case3", "case4", "case_none", "substitutions", "low_confidence", "unplannable", "violations", "cautions",
] as const;

export function recipesCsv(records: readonly EvalRecord[]): string {
  return toCsv(
    RECIPE_COLUMNS,
    records.map((r): Cell[] => {
      const head: Cell[] = [r.recipe.type, r.recipe.id, r.variant, r.ok];
      if (!r.ok) return [...head, r.error.code, r.error.message, r.ms, ...Array<Cell>(RECIPE_COLUMNS.length - 7).fill(null)];
      const m = r.metrics;
      return [
        ...head, null, null, r.ms, m.units, m.duplicate_units, m.units_before_inputs, m.dead_units, m.goal_produced,
        m.query_objects, m.objects_in_tree, m.objects_in_dish, m.query_pairs, m.pairs_in_tree, m.extra_ingredients.join(";"), m.reference_units, m.reference_own_type, m.cases.c1,
        m.cases.c2, m.cases.c3, m.cases.c4, m.cases.none, m.substitutions, m.low_confidence, m.unplannable, m.violations.join(" | "),
        m.caution_details.join(" | "),
      ];
    }),
  );
}

/** The JSON results file: what was run, the metrics table, and every record. */
export interface EvalResults {
  format: "foon-planner-eval";
  version: 1;
  knowledge_base: string;
  variants: Variant[];
  table: MetricsRow[];
  records: EvalRecord[];
}
