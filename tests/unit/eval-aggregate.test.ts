import { describe, expect, it } from "vitest";
import { metricsTable, percentile } from "../../src/eval/aggregate";
import { brokenInvariants, cautionExamples, formatTable, recipesCsv, summaryCsv } from "../../src/eval/format";
import { parseCsv } from "../../src/eval/csv";
import { planMetrics } from "../../src/eval/metrics";
import { runBatch } from "../../src/eval/runner";
import { PlannerError } from "../../src/planner/index";
import type { PlanRequest } from "../../src/planner/types";
import type { LoadedQuery } from "../../src/eval/types";
import { cleanUnits, plan } from "./eval-fixtures";

const q = (type: string, id: string, object = "tomato"): LoadedQuery => ({ source: `${type}/${id}.json`, query: { id, type, ingredients: [{ object, state: "diced" }] } });

function fakePlanner(request: PlanRequest) {
  if (request.query.ingredients[0]?.object === "nothing") throw new PlannerError({ code: "no_goal", message: "no goal node" });
  const units = cleanUnits();
  return plan(request.modify === false ? [units[0]!, ...units] : units, request.query);
}

let clock = 0;
const now = (): number => (clock += 5);

describe("batch records and the metrics table", () => {
  const records = runBatch(fakePlanner, [q("salad", "a"), q("salad", "b", "nothing"), q("soup", "c")], ["modified", "unmodified"], now);

  it("plans each query in each variant and keeps typed errors", () => {
    expect(records).toHaveLength(6);
    expect(records.filter((r) => !r.ok).map((r) => (r.ok ? "" : r.error.code))).toEqual(["no_goal", "no_goal"]);
    expect(records.every((r) => r.ms === 5)).toBe(true);
  });

  it("aggregates per dish type and overall", () => {
    const rows = metricsTable(records, "modified");
    expect(rows.map((r) => r.group)).toEqual(["salad", "soup", "all"]);
    const all = rows[2]!;
    expect(all).toMatchObject({ queries: 3, plans: 2, errors: 1, errors_by_code: { no_goal: 1 }, units_mean: 4, duplicate_units: 0, dead_units: 0 });
    expect(all.object_share).toBe(1);
    expect(all.dish_share).toBe(1);
    expect(all.pair_share).toBe(1);
    expect(all.ms_total).toBe(15);
    // every unit of the fake plans is the reference tree's
    expect(all.plans_little_reference).toBe(0);
    expect(brokenInvariants(rows)).toEqual([]);
  });

  it("counts the plans that keep next to nothing of their reference task tree", () => {
    // the dish's last unit is the reference's; the rest are branches the ingredients brought
    const mostlyAdded = (request: PlanRequest) => plan(cleanUnits().map((u, i) => ({ ...u, origin: i === 3 ? "attached" : "grafted" })), request.query);
    const added = runBatch(mostlyAdded, [q("bread", "x"), q("salad", "y")], ["modified"], now);
    const kept = runBatch(fakePlanner, [q("salad", "z")], ["modified"], now);
    const rows = metricsTable([...added, ...kept], "modified");
    expect(rows.map((r) => [r.group, r.plans_little_reference])).toEqual([["bread", 1], ["salad", 0.5], ["all", 2 / 3]]);
    expect(formatTable(rows, "title")).toMatch(/plans keeping <= 2 reference units\s+100\.0%\s+50\.0%\s+66\.7%/);
  });

  it("gives the share of plans whose reference is a recipe of the query's own dish type", () => {
    const kinReference = (request: PlanRequest) => {
      const p = plan(cleanUnits(), request.query);
      return { ...p, goal: { ...p.goal, dish_class: 5 } };
    };
    const kin = runBatch(kinReference, [q("bread", "k")], ["modified"], now);
    const own = runBatch(fakePlanner, [q("bread", "o"), q("salad", "s")], ["modified"], now);
    const rows = metricsTable([...kin, ...own], "modified");
    expect(rows.map((r) => [r.group, r.own_type_reference])).toEqual([["bread", 0.5], ["salad", 1], ["all", 2 / 3]]);
    expect(formatTable(rows, "title")).toMatch(/reference of the query's dish type\s+50\.0%\s+100\.0%\s+66\.7%/);
    const summary = parseCsv(summaryCsv(rows));
    expect(summary[1]![summary[0]!.indexOf("own_type_reference")]).toBe("0.5");
    const recipes = parseCsv(recipesCsv([...kin, ...own]));
    expect(recipes.map((r) => r[recipes[0]!.indexOf("reference_own_type")])).toEqual(["reference_own_type", "false", "true", "true"]);
  });

  it("reports broken invariants of the unmodified variant", () => {
    const rows = metricsTable(records, "unmodified");
    expect(rows[2]!.duplicate_units).toBe(2);
    expect(brokenInvariants(rows)).toEqual(["unmodified: duplicated units = 2 (must be 0)"]);
  });

  it("formats a text table and CSV files", () => {
    const rows = metricsTable(records, "modified");
    const text = formatTable(rows, "title");
    expect(text.split("\n")[1]).toMatch(/salad\s+soup\s+all$/);
    expect(text).toContain("typed errors");
    const summary = parseCsv(summaryCsv(rows));
    expect(summary[0]).toContain("dead_units");
    expect(summary).toHaveLength(4);
    const recipes = parseCsv(recipesCsv(records));
    expect(recipes).toHaveLength(7);
    expect(new Set(recipes.map((r) => r.length)).size).toBe(1);
  });

  it("counts each plan's cautions by kind, with examples, beside the structural metrics", () => {
    const uncooked = (request: PlanRequest) => ({
      ...plan(cleanUnits(), request.query),
      cautions: [{ kind: "uncooked" as const, food: "chicken", detail: "chicken reaches salad uncooked" }],
    });
    const rows = metricsTable([...runBatch(uncooked, [q("salad", "u")], ["modified"], now), ...runBatch(fakePlanner, [q("soup", "v")], ["modified"], now)], "modified");
    expect(rows.map((r) => [r.group, r.cautions.uncooked, r.cautions.motion_on_form])).toEqual([["salad", 1, 0], ["soup", 0, 0], ["all", 1, 0]]);
    expect(formatTable(rows, "title")).toMatch(/must-cook foods reaching the dish uncooked\s+1\s+0\s+1/);
    expect(cautionExamples(rows)).toEqual(["modified, first cautions:", "  salad/u uncooked: chicken reaches salad uncooked"]);
    const summary = parseCsv(summaryCsv(rows));
    expect(summary[3]![summary[0]!.indexOf("uncooked")]).toBe("1");
  });

  it("percentile by nearest rank", () => {
    expect(percentile([], 95)).toBe(0);
    expect(percentile([3, 1, 2], 50)).toBe(2);
    expect(percentile(Array.from({ length: 100 }, (_, i) => i + 1), 95)).toBe(95);
  });

  it("the per-plan metrics are pure functions of the plan", () => {
    expect(planMetrics(plan())).toEqual(planMetrics(JSON.parse(JSON.stringify(plan()))));
  });
});
