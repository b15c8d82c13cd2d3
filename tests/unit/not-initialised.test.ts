// Before initialisation, and on an engine it cannot run on, the planner says so clearly instead of failing
// inside the WASM glue (every other test initialises it, so the SIMD probe is known to pass where SIMD is).
import { describe, expect, it, vi } from "vitest";
import { FoonPlanner, initPlanner, PlannerError } from "../../src/planner/index";

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

describe("an engine without WebAssembly SIMD", () => {
  it("is refused with an unsupported PlannerError that names the browsers needed", async () => {
    const validate = vi.spyOn(WebAssembly, "validate").mockReturnValue(false);
    try {
      const failure = await initPlanner().then(() => null, (e: unknown) => e);
      expect(failure).toBeInstanceOf(PlannerError);
      expect((failure as PlannerError).code).toBe("unsupported");
      expect((failure as PlannerError).message).toMatch(/SIMD.*Safari 16\.4/);
    } finally {
      validate.mockRestore();
    }
  });
});
