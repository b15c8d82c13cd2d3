// Before initialisation the planner says so clearly instead of failing inside the WASM glue.
import { describe, expect, it } from "vitest";
import { FoonPlanner, PlannerError } from "../../src/planner/index";

describe("planner before initialisation", () => {
  it("throws a not_initialised PlannerError that tells what to call", () => {
    let caught: unknown;
    try {
      FoonPlanner.load([]);
    } catch (e) {
      caught = e;
    }
    expect(caught).toBeInstanceOf(PlannerError);
    expect((caught as PlannerError).code).toBe("not_initialised");
    expect((caught as PlannerError).message).toMatch(/initPlanner/);
  });
});
