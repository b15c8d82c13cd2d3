// The metrics table (same lines as the CLI's text table) and the sortable list of recipes.

import { metricsTable, variantsOf } from "../eval/aggregate";
import { METRIC_LINES } from "../eval/format";
import { recipeKey } from "../eval/queries";
import { ratingItems } from "../eval/ratings";
import type { EvalRecord, LoadedQuery, Variant } from "../eval/types";
import { el } from "./dom";

export function metricsTables(records: readonly EvalRecord[]): HTMLElement[] {
  return variantsOf(records).map((variant) => {
    const rows = metricsTable(records, variant);
    return el(
      "table",
      { class: "metrics", "data-variant": variant },
      el("caption", { text: variant === "modified" ? "With tree modification" : "Without tree modification (reference tree)" }),
      el("thead", {}, el("tr", {}, el("th", { text: "" }), ...rows.map((r) => el("th", { scope: "col", text: r.group })))),
      el(
        "tbody",
        {},
        ...METRIC_LINES.map((line) =>
          el(
            "tr",
            { "data-metric": line.key, class: line.invariant === true ? "invariant" : undefined },
            el("th", { scope: "row", text: line.label }),
            ...rows.map((r) => el("td", { "data-group": r.group, class: line.invariant === true && line.format(r) !== "0" ? "broken" : undefined, text: line.format(r) })),
          ),
        ),
      ),
    );
  });
}

export interface RecipeRow {
  key: string;
  type: string;
  id: string;
  ingredients: number;
  items: number;
  rated: number;
  units: Partial<Record<Variant, number>>;
  objectShare: Partial<Record<Variant, number>>;
  pairShare: Partial<Record<Variant, number>>;
  extras: Partial<Record<Variant, number>>;
  errors: string;
  /** Structural-invariant violations over both variants. */
  violations: number;
  ms: number;
}

export function recipeRows(queries: readonly LoadedQuery[], records: readonly EvalRecord[], ratedCount: (q: LoadedQuery) => number): RecipeRow[] {
  const byRecipe = new Map<string, EvalRecord[]>();
  for (const r of records) {
    const key = recipeKey(r.recipe);
    byRecipe.set(key, [...(byRecipe.get(key) ?? []), r]);
  }
  return queries
    .filter((q) => byRecipe.has(recipeKey(q.query)))
    .map((q) => {
      const key = recipeKey(q.query);
      const row: RecipeRow = {
        key, type: q.query.type, id: q.query.id, ingredients: q.query.ingredients.length, items: ratingItems(q.query.ingredients).length * 2,
        rated: ratedCount(q), units: {}, objectShare: {}, pairShare: {}, extras: {}, errors: "", violations: 0, ms: 0,
      };
      for (const r of byRecipe.get(key) ?? []) {
        row.ms += r.ms;
        if (!r.ok) {
          row.errors = [row.errors, `${r.variant}: ${r.error.code}`].filter((s) => s !== "").join("; ");
          continue;
        }
        const m = r.metrics;
        row.units[r.variant] = m.units;
        row.objectShare[r.variant] = m.query_objects === 0 ? 1 : m.objects_in_tree / m.query_objects;
        row.pairShare[r.variant] = m.query_pairs === 0 ? 1 : m.pairs_in_tree / m.query_pairs;
        row.extras[r.variant] = m.extra_ingredients.length;
        row.violations += m.violations.length;
      }
      return row;
    });
}

interface Column {
  key: string;
  label: string;
  value: (r: RecipeRow) => string | number;
  text?: (r: RecipeRow) => string;
  /** Reveals which plan is modified: hidden in blind mode. */
  revealing?: boolean;
}

const pct = (x: number | undefined): string => (x === undefined ? "–" : `${Math.round(x * 100)}%`);
const num = (x: number | undefined): string => (x === undefined ? "–" : String(x));

export const RECIPE_COLUMNS: readonly Column[] = [
  { key: "type", label: "type", value: (r) => r.type },
  { key: "id", label: "id", value: (r) => r.id },
  { key: "ingredients", label: "ingredients", value: (r) => r.ingredients },
  { key: "rated", label: "rated", value: (r) => r.rated / Math.max(1, r.items), text: (r) => `${r.rated}/${r.items}` },
  { key: "units_mod", label: "units (mod.)", value: (r) => r.units.modified ?? -1, text: (r) => num(r.units.modified), revealing: true },
  { key: "units_ref", label: "units (ref.)", value: (r) => r.units.unmodified ?? -1, text: (r) => num(r.units.unmodified), revealing: true },
  { key: "objects_mod", label: "objects in tree (mod.)", value: (r) => r.objectShare.modified ?? -1, text: (r) => pct(r.objectShare.modified), revealing: true },
  { key: "pairs_mod", label: "(object, state) (mod.)", value: (r) => r.pairShare.modified ?? -1, text: (r) => pct(r.pairShare.modified), revealing: true },
  { key: "pairs_ref", label: "(object, state) (ref.)", value: (r) => r.pairShare.unmodified ?? -1, text: (r) => pct(r.pairShare.unmodified), revealing: true },
  { key: "extras_mod", label: "extras (mod.)", value: (r) => r.extras.modified ?? -1, text: (r) => num(r.extras.modified), revealing: true },
  { key: "errors", label: "errors", value: (r) => r.errors, revealing: true },
  { key: "violations", label: "invariant violations", value: (r) => r.violations, revealing: true },
  { key: "ms", label: "ms", value: (r) => r.ms, text: (r) => r.ms.toFixed(1) },
];

export interface SortState {
  column: string;
  descending: boolean;
}

export function sortRows(rows: RecipeRow[], sort: SortState): RecipeRow[] {
  const column = RECIPE_COLUMNS.find((c) => c.key === sort.column) ?? RECIPE_COLUMNS[0]!;
  const sign = sort.descending ? -1 : 1;
  return [...rows].sort((a, b) => {
    const x = column.value(a);
    const y = column.value(b);
    const c = typeof x === "number" && typeof y === "number" ? x - y : String(x).localeCompare(String(y));
    return sign * c || a.key.localeCompare(b.key);
  });
}

export function recipeTable(rows: readonly RecipeRow[], sort: SortState, blind: boolean, onSort: (column: string) => void, onOpen: (key: string) => void): HTMLTableElement {
  const columns = RECIPE_COLUMNS.filter((c) => !(blind && c.revealing === true));
  const head = el(
    "tr",
    {},
    ...columns.map((c) => {
      const button = el("button", { type: "button", "data-sort": c.key, text: c.label + (sort.column === c.key ? (sort.descending ? " ▼" : " ▲") : "") });
      button.addEventListener("click", () => onSort(c.key));
      return el("th", { scope: "col", "aria-sort": sort.column === c.key ? (sort.descending ? "descending" : "ascending") : undefined }, button);
    }),
  );
  const body = sortRows([...rows], sort).map((r) => {
    const tr = el("tr", { "data-recipe": r.key });
    for (const c of columns) {
      const text = c.text?.(r) ?? String(c.value(r));
      if (c.key === "id") {
        const open = el("button", { type: "button", class: "link", text, title: "rate this recipe" });
        open.addEventListener("click", () => onOpen(r.key));
        tr.append(el("td", {}, open));
      } else tr.append(el("td", { "data-column": c.key, text }));
    }
    return tr;
  });
  return el("table", { id: "recipe-table", class: "recipes" }, el("thead", {}, head), el("tbody", {}, ...body));
}
