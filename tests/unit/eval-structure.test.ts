import { describe, expect, it } from "vitest";
import { structureMetrics } from "../../src/eval/structure";
import { cleanUnits, node, plan, unit } from "./eval-fixtures";

const goal = plan().goal;

describe("structural invariants from units alone", () => {
  it("a correct plan has no duplicates, no early units, no dead units, and produces its goal", () => {
    expect(structureMetrics(cleanUnits(), goal)).toEqual({ units: 4, duplicate_units: 0, units_before_inputs: 0, dead_units: 0, goal_produced: true, violations: [] });
  });

  it("counts a unit repeated with the same inputs, motion and outputs (in any order)", () => {
    const units = cleanUnits();
    const first = units[0]!;
    const again = unit([...first.inputs].reverse(), first.motion, first.outputs);
    const m = structureMetrics([first, again, ...units.slice(1)], goal);
    expect(m.duplicate_units).toBe(1);
    expect(m.violations).toEqual(["unit 2 (pick-and-place) repeats unit 1"]);
    expect(m.dead_units).toBe(0); // both copies' output is used by the dice unit
  });

  it("a unit scheduled before the unit that makes its input", () => {
    const [a, b, c, d] = cleanUnits();
    const m = structureMetrics([a!, c!, b!, d!], goal);
    expect(m.units_before_inputs).toBe(1);
    expect(m.violations).toEqual([
      "unit 2 (pour) needs tomato [diced; on [cutting board]], first made by unit 3",
      "unit 3 (dice) makes nothing a later unit uses",
    ]);
    expect(m.dead_units).toBe(1); // dicing now happens after the pour that needed it
  });

  it("a unit whose outputs nobody uses and that is not the goal is dead", () => {
    const extra = unit([node("lemon", ["whole"]), node("knife", ["clean"])], "slice", [node("lemon", ["sliced"])]);
    const m = structureMetrics([extra, ...cleanUnits()], goal);
    expect(m.dead_units).toBe(1);
    expect(m.units_before_inputs).toBe(0);
  });

  it("utensils that pass through a unit unchanged are not products (no false 'before inputs')", () => {
    const [a, b, c, d] = cleanUnits();
    // the knife is an input of the dice unit and passes through it: it is not produced there
    const usesKnifeFirst = unit([node("knife", ["clean"]), node("bread", ["whole"])], "slice", [node("bread", ["sliced"])]);
    const eat = unit([node("bread", ["sliced"]), d!.outputs[0]!], "serve", [node("salad", ["mixed", "in [bowl]"], ["salt", "tomato"], "bowl")]);
    const m = structureMetrics([usesKnifeFirst, a!, b!, c!, d!, eat], goal);
    expect(m.units_before_inputs).toBe(0);
  });

  it("states and ingredients compare as sets; the goal compares label and states", () => {
    const units = cleanUnits();
    const last = units[3]!;
    units[3] = unit(last.inputs, last.motion, [node("salad", ["in [bowl]", "mixed"], ["tomato", "salt"], "bowl")]);
    expect(structureMetrics(units, goal).goal_produced).toBe(true);
    expect(structureMetrics(units.slice(0, 3), goal)).toMatchObject({ goal_produced: false, dead_units: 1 });
  });

  it("an empty plan has nothing to count", () => {
    expect(structureMetrics([], goal)).toEqual({ units: 0, duplicate_units: 0, units_before_inputs: 0, dead_units: 0, goal_produced: false, violations: [] });
  });
});
