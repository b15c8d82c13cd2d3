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
});
