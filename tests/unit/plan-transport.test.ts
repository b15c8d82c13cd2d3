// The plan as the app receives it from the WASM module: its shared nodes are written once and then by
// number (wasm/core/src/contract/json.rs), and src/planner/index.ts puts them back. What comes out must be
// the documented plan format, exactly as serde writes it for the `json` export, on the real dev queries.
import { beforeAll, describe, expect, it } from "vitest";
import { FoonPlanner, type Plan, type PlanRequest } from "../../src/planner/index";
import { RETRIEVAL_MODES } from "../../src/planner/types";
import { everyNthDevQuery, foon111Planner } from "./helpers";

let planner: FoonPlanner;
let requests: PlanRequest[];

beforeAll(() => {
  planner = foon111Planner();
  // every fourth dev query, both variants: 160 plans of every dish type
  requests = everyNthDevQuery(4).flatMap((query) => [{ query }, { query, modify: false }]);
});

/** Pairs of units (earlier, later) where a node the earlier one makes is what the later one takes. */
function sharedNodes(plan: Plan): number {
  const made = new Set(plan.units.flatMap((u) => u.outputs));
  return plan.units.flatMap((u) => u.inputs).filter((n) => made.has(n)).length;
}

describe("plan transport", () => {
  it("gives the documented plan format, equal to the json export, for every plan", () => {
    for (const request of requests) {
      const plan = planner.plan(request);
      expect(JSON.parse(JSON.stringify(plan))).toEqual(JSON.parse(planner.exportPlan(request, "json")));
    }
  });

  it("gives a node that several units share as one object, as the planner holds it", () => {
    const modified = requests.filter((r) => r.modify !== false).map((r) => planner.plan(r));
    // what one unit makes, a later one takes: in every modified plan of more than one unit
    for (const plan of modified.filter((p) => p.units.length > 1)) expect(sharedNodes(plan)).toBeGreaterThan(0);
  });

  it("gives the robot view of every retrieval mode, equal to the json export", () => {
    for (const mode of RETRIEVAL_MODES) {
      for (const { query } of requests.filter((r) => r.modify !== false).slice(0, 10)) {
        const request: PlanRequest = { query, robot: { mode, human_steps: 1 } };
        const plan = planner.plan(request);
        expect(JSON.parse(JSON.stringify(plan))).toEqual(JSON.parse(planner.exportPlan(request, "json")));
        expect(plan.robot?.mode).toBe(mode);
        expect(plan.robot?.units.length).toBe(plan.units.length);
        expect(plan.robot?.human_units.length).toBe(Math.min(1, plan.units.length));
      }
    }
  });
});
