// The task-tree layout (src/app/model/layout.ts) on real plans of FOON-111 and on every step of their
// Algorithm view: every node placed, no two nodes of a column overlapping, and every edge running left to
// right towards the goal unless it closes a cycle (an object a unit puts back as it was).
import { beforeAll, describe, expect, it } from "vitest";
import { explainSteps } from "../../src/app/model/explain";
import { layoutTree, ROW_GAP } from "../../src/app/model/layout";
import { planToGraph, type TreeGraph } from "../../src/app/model/tree";
import type { FoonPlanner, PlanRequest } from "../../src/planner/index";
import { everyNthDevQuery, foon111Planner } from "./helpers";

let planner: FoonPlanner;
let requests: PlanRequest[];

beforeAll(() => {
  planner = foon111Planner();
  // every fifth dev query: 64 plans of every dish type
  requests = everyNthDevQuery(5).map((query) => ({ query, explain: true }));
});

/** Whether `to` is reachable from `from` along the graph's edges. */
function reaches(graph: TreeGraph, from: string, to: string): boolean {
  const seen = new Set([from]);
  const todo = [from];
  while (todo.length > 0) {
    const id = todo.pop()!;
    if (id === to) return true;
    for (const e of graph.edges) if (e.source === id && !seen.has(e.target)) (seen.add(e.target), todo.push(e.target));
  }
  return false;
}

/** What is wrong with the graph's layout, if anything. */
function layoutFaults(graph: TreeGraph): string[] {
  const at = layoutTree(graph);
  const faults: string[] = graph.nodes.filter((n) => !at.has(n.id)).map((n) => `${n.id} not placed`);
  const columns = new Map<number, number[]>();
  for (const p of at.values()) columns.set(p.x, [...(columns.get(p.x) ?? []), p.y]);
  for (const [x, ys] of columns) {
    const rows = ys.sort((a, b) => a - b);
    for (let i = 1; i < rows.length; i++) if (rows[i]! - rows[i - 1]! < ROW_GAP) faults.push(`overlap in the column at x ${x}`);
  }
  for (const e of graph.edges) {
    if (at.get(e.source)!.x < at.get(e.target)!.x) continue;
    if (!reaches(graph, e.target, e.source)) faults.push(`${e.id} runs right to left`);
  }
  return faults;
}

describe("task tree layout on FOON-111 plans", () => {
  it("places the task tree of every plan and every step of its Algorithm view", () => {
    let graphs = 0;
    for (const request of requests) {
      const plan = planner.plan(request);
      for (const graph of [planToGraph(plan), ...explainSteps(plan)!.map((s) => s.graph)]) {
        expect(layoutFaults(graph), `${request.query.type}: ${plan.goal.label}`).toEqual([]);
        graphs += 1;
      }
    }
    expect(graphs).toBeGreaterThan(requests.length * 5);
  });
});
