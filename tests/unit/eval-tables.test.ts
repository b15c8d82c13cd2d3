import { describe, expect, it } from "vitest";
import { recipeRows, sortRows } from "../../src/workbench/tables";
import { runBatch } from "../../src/eval/runner";
import type { LoadedQuery } from "../../src/eval/types";
import type { PlanRequest } from "../../src/planner/types";
import { cleanUnits, plan } from "./eval-fixtures";

const q = (type: string, id: string, n: number): LoadedQuery => ({
  source: `${id}.json`,
  query: { id, type, ingredients: Array.from({ length: n }, (_, i) => ({ object: `o${i % 2}`, state: "s" })) },
});

describe("the workbench's recipe list", () => {
  const queries = [q("soup", "b", 3), q("salad", "a", 1), q("salad", "c", 4)];
  const records = runBatch((r: PlanRequest) => plan(cleanUnits(), r.query), queries.slice(0, 2), ["modified", "unmodified"], () => 0);

  it("has one row per planned recipe with per-variant metrics", () => {
    const rows = recipeRows(queries, records, () => 1);
    expect(rows.map((r) => r.key)).toEqual(["soup/b", "salad/a"]);
    expect(rows[0]).toMatchObject({ ingredients: 3, items: 4, rated: 1, units: { modified: 4, unmodified: 4 }, errors: "", violations: 0 });
  });

  it("sorts by any column, both ways, ties by recipe", () => {
    const rows = recipeRows(queries, records, () => 0);
    expect(sortRows(rows, { column: "type", descending: false }).map((r) => r.id)).toEqual(["a", "b"]);
    expect(sortRows(rows, { column: "ingredients", descending: true }).map((r) => r.id)).toEqual(["b", "a"]);
    expect(sortRows(rows, { column: "nope", descending: false }).map((r) => r.id)).toEqual(["a", "b"]);
  });
});
