// The Algorithm view's steps (src/app/model/explain.ts) from real explained plans of FOON-111: Alg. 1
// first, one step per node Alg. 2 took from its queue with the search tree growing, one per ingredient,
// pruning, and the final task tree last; and the plan through the WASM API is the same with and without
// `explain`, less the trace.
import { beforeAll, describe, expect, it } from "vitest";
import { explainSteps } from "../../src/app/model/explain";
import { planToGraph } from "../../src/app/model/tree";
import type { FoonPlanner, Plan, PlanRequest } from "../../src/planner/index";
import { everyNthDevQuery, foon111Planner } from "./helpers";

let planner: FoonPlanner;
let requests: PlanRequest[];

beforeAll(() => {
  planner = foon111Planner();
  // every tenth dev query: 32 plans of every dish type
  requests = everyNthDevQuery(10).map((query) => ({ query }));
});

const explained = (r: PlanRequest): Plan => planner.plan({ ...r, explain: true });

describe("explain steps", () => {
  it("has dev queries whose reference goal is of a kin dish type", () => {
    const kin = requests.filter((r) => explained(r).trace!.goal_selection.kin_class !== null);
    expect(kin.length).toBeGreaterThan(0);
  });

  it("says why a runner-up of Alg. 1 was taken when the best goal's tree would be kept next to nothing of", () => {
    const fuller = everyNthDevQuery(1)
      .map((query) => explained({ query }))
      .filter((p) => p.trace!.goal_selection.tie_break === "fuller_tree");
    expect(fuller.length).toBeGreaterThan(0);
    for (const plan of fuller) {
      expect(plan.trace!.goal_selection.candidates[0]!.subgraph).toBe(plan.goal.subgraph);
      expect(explainSteps(plan)![0]!.caption).toContain("this runner-up's keeps more");
    }
  });

  it("replays Alg. 1, every Alg. 2 expansion, each ingredient and pruning, and ends on the final tree", () => {
    for (const request of requests) {
      const plan = explained(request);
      const trace = plan.trace!;
      const steps = explainSteps(plan)!;
      const phases = steps.map((s) => s.phase);
      expect(phases).toEqual([
        "goal",
        ...trace.retrieval.map(() => "retrieval"),
        ...trace.ingredients.map(() => "modification"),
        "pruning",
        "final",
      ]);
      expect(steps[0]!.caption).toContain(plan.goal.reference);
      // a reference borrowed from a kin dish type says so, and leads the candidates
      expect(trace.goal_selection.candidates[0]!.subgraph).toBe(plan.goal.subgraph);
      if (trace.goal_selection.kin_class !== null) expect(steps[0]!.caption).toContain("a dish made the same way");
      expect(steps.at(-1)!.graph).toEqual(planToGraph(plan));
      for (const s of steps) expect(s.caption.length).toBeGreaterThan(20);
    }
  });

  it("grows the search tree one chosen unit at a time, and pruning only takes away", () => {
    const plan = explained(requests[0]!);
    const steps = explainSteps(plan)!;
    const retrieval = steps.filter((s) => s.phase === "retrieval");
    for (let i = 1; i < retrieval.length; i++) {
      const before = new Set(retrieval[i - 1]!.graph.nodes.map((n) => n.id));
      const grown = retrieval[i]!.graph.nodes.filter((n) => !before.has(n.id));
      const motions = grown.filter((n) => n.kind === "motion").length;
      expect(motions).toBe(plan.trace!.retrieval[i]!.chosen === null || grown.length === 0 ? 0 : 1);
    }
    const pruned = steps.find((s) => s.phase === "pruning")!;
    const last = retrieval.at(-1)!;
    const units = (g: typeof last.graph): number => g.nodes.filter((n) => n.kind === "motion").length;
    // a pruned unit modification renamed is no longer the retrieved one: it stays drawn until the end
    expect(units(pruned.graph)).toBeLessThanOrEqual(units(last.graph));
    expect(units(pruned.graph)).toBeGreaterThanOrEqual(units(last.graph) - plan.trace!.pruning.units.length);
  });

  it("has no steps for a plan without a trace, and the plan is the same less the trace", () => {
    for (const request of requests) {
      const off = planner.plan(request);
      expect(explainSteps(off)).toBeNull();
      const { trace, ...on } = explained(request);
      expect(trace).toBeDefined();
      expect(on).toEqual(off);
    }
  });
});
