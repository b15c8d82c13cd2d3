import { describe, expect, it } from "vitest";
import { coverageMetrics, startingIngredients } from "../../src/eval/coverage";
import { planMetrics } from "../../src/eval/metrics";
import type { PlanUnit } from "../../src/planner/types";
import { cleanUnits, node, outcome, plan, unit } from "./eval-fixtures";

describe("coverage of the query", () => {
  it("a plan with every query ingredient in its state", () => {
    const m = coverageMetrics(plan());
    expect(m).toMatchObject({ query_objects: 2, objects_in_tree: 2, objects_in_dish: 2, query_pairs: 2, pairs_in_tree: 2, extra_ingredients: [] });
    expect(m.cases).toEqual({ c1: 2, c2: 0, c3: 0, c4: 0, none: 0 });
  });

  it("counts the units kept of the reference task tree, not the branches added to it", () => {
    expect(coverageMetrics(plan()).reference_units).toBe(4);
    const units = cleanUnits().map((u, i): PlanUnit => ({ ...u, origin: i === 3 ? "attached" : "grafted" }));
    expect(coverageMetrics(plan(units)).reference_units).toBe(1);
  });

  it("tells whether the reference goal is a dish of the query's own type", () => {
    expect(coverageMetrics(plan()).reference_own_type).toBe(true);
    const kin = plan();
    kin.goal = { ...kin.goal, dish_class: 3 };
    expect(coverageMetrics(kin).reference_own_type).toBe(false);
    // an unknown dish type: every class's goals were searched, none is the query's own
    const unknown = { ...plan(), dish_class: null };
    expect(coverageMetrics(unknown).reference_own_type).toBe(false);
  });

  it("counts repeated query ingredients once, and missing objects and states", () => {
    const p = plan(cleanUnits(), {
      ingredients: [
        { object: "tomato", state: "sliced" },
        { object: "tomato", state: "sliced" },
        { object: "basil", state: "chopped" },
      ],
    });
    const m = coverageMetrics(p);
    expect(m).toMatchObject({ query_objects: 2, objects_in_tree: 1, query_pairs: 2, pairs_in_tree: 0 });
  });

  it("an ingredient left in a container the dish does not take is in the tree but not in the dish", () => {
    const units = cleanUnits();
    // the salt is mixed in a cup that nothing takes on; the salad lists only the tomato
    units[3] = unit([node("bowl", ["contains {tomato}"], ["tomato"])], "mix", [node("salad", ["mixed", "in [bowl]"], ["tomato"], "bowl")]);
    units.splice(3, 0, unit([node("cup", ["empty"]), node("salt", ["ground"])], "pour", [node("cup", ["contains {salt}"], ["salt"])]));
    const m = coverageMetrics(plan(units));
    expect(m).toMatchObject({ query_objects: 2, objects_in_tree: 2, objects_in_dish: 1 });
    expect(coverageMetrics(plan(units.slice(0, 3))).objects_in_dish).toBe(0);
  });

  it("starting ingredients are leaves that end up in a mixture, not utensils or containers", () => {
    expect([...startingIngredients(plan())].sort()).toEqual(["salt", "tomato"]);
  });

  it("extra starting ingredients are the ones neither asked for nor chosen as an equivalent", () => {
    const units = cleanUnits();
    const last = units[3]!;
    units[3] = unit([...last.inputs, node("pepper", ["ground"]), node("oregano", ["dried"])], "mix", [node("salad", ["mixed", "in [bowl]"], ["oregano", "pepper", "salt", "tomato"], "bowl")]);
    const p = plan(units, {}, [outcome("tomato", "diced"), outcome("salt", "ground", { case: 2, match: { label: "pepper", state: "ground", similarity: 0.6 } })]);
    expect(coverageMetrics(p).extra_ingredients).toEqual(["oregano"]);
  });

  it("cases, substitutions, low confidence and unplannable ingredients", () => {
    const p = plan(cleanUnits(), {}, [
      outcome("tomato", "diced", { case: 3 }),
      outcome("chili", "chopped", { case: 2, match: { label: "jalapeno", state: "chopped", similarity: 0.7 } }),
      outcome("turkey", "roasted", { case: 4, match: { label: "chicken", state: "baked", similarity: 0.3 }, low_confidence: true }),
      outcome("unobtainium", "raw", { case: null, match: null, status: "unplannable" }),
    ]);
    const m = planMetrics(p);
    expect(m.cases).toEqual({ c1: 0, c2: 1, c3: 1, c4: 1, none: 1 });
    expect(m).toMatchObject({ substitutions: 2, low_confidence: 1, unplannable: 1, units: 4, dead_units: 0 });
  });
});
