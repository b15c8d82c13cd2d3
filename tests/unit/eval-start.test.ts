import { describe, expect, it } from "vitest";
import { availableAtStart, structureMetrics } from "../../src/eval/structure";
import { cleanUnits, node, plan, unit } from "./eval-fixtures";

describe("things a kitchen has before cooking starts", () => {
  it("empty, clean or whole things, not inside anything and containing nothing", () => {
    expect(availableAtStart(node("bowl", ["empty"]))).toBe(true);
    expect(availableAtStart(node("pot lid"))).toBe(true);
    expect(availableAtStart(node("onion", ["whole"]))).toBe(true);
    expect(availableAtStart(node("onion", ["whole", "on [cutting board]"], [], "cutting board"))).toBe(false);
    expect(availableAtStart(node("bowl", ["contains {garlic}"], ["garlic"]))).toBe(false);
    expect(availableAtStart(node("onion", ["sliced"]))).toBe(false);
  });

  it("an empty bowl used first and emptied again later is not 'before its inputs'", () => {
    const units = cleanUnits();
    const empty = unit([node("bowl", ["contains {tomato}"], ["tomato"]), node("plate", ["empty"])], "pour", [node("bowl", ["empty"]), node("plate", ["contains {tomato}"], ["tomato"])]);
    const m = structureMetrics([...units.slice(0, 3), empty, ...units.slice(3)], plan().goal);
    expect(m.units_before_inputs).toBe(0);
  });

  it("but never the finished dish: a unit taking the goal before it is made is reported", () => {
    const leaves = node("leaf");
    const cooked = node("leaf", ["cooked"]);
    const units = [unit([leaves], "cook", [cooked]), unit([cooked], "slice", [leaves])];
    const m = structureMetrics(units, { ...plan().goal, label: "leaf", states: [] });
    expect(availableAtStart(leaves)).toBe(true);
    expect(m.units_before_inputs).toBe(1);
    expect(m.violations[0]).toContain("unit 1 (cook) needs");
  });
});

describe("states a recipe returns to", () => {
  it("a lid taken off and put back was there from the start: no order could do better", () => {
    const onPot = node("lid", ["on [pot]"], [], "pot");
    const off = node("lid", ["on [counter]"], [], "counter");
    const units = [
      unit([onPot, node("pot", ["contains {water}"], ["water"])], "uncover", [off, node("pot", ["open", "contains {water}"], ["water"])]),
      unit([node("pot", ["open", "contains {water}"], ["water"]), node("salt", ["ground"])], "sprinkle", [node("pot", ["open", "contains {salt,water}"], ["salt", "water"])]),
      unit([off, node("pot", ["open", "contains {salt,water}"], ["salt", "water"])], "cover", [onPot, node("soup", ["boiled"], ["salt", "water"], "pot")]),
    ];
    const m = structureMetrics(units, { ...plan().goal, label: "soup", states: ["boiled"] });
    expect(m).toMatchObject({ units_before_inputs: 0, dead_units: 0, goal_produced: true });
  });

  it("but a unit that could have run first and did not is reported", () => {
    const [a, b, c, d] = cleanUnits();
    expect(structureMetrics([a!, c!, b!, d!], plan().goal).units_before_inputs).toBe(1);
  });
});
