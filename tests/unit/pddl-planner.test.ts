// The PDDL export given to a real planner: every dev plan's domain and problem (FOON-111) are parsed and
// solved by Fast Downward (scripts/pddl_solve.py, in the venv `npm run setup` makes), and the plan found
// has exactly the task tree's units, each once, in an order the schedule allows (the evaluator's own
// definition: no unit before a unit making one of its inputs, none dead, the goal made).
import { execFileSync } from "node:child_process";
import { existsSync, mkdirSync, mkdtempSync, rmSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { readQueries } from "../../src/cli/queries";
import { structureMetrics } from "../../src/eval/structure";
import type { FoonPlanner, Plan, PlanRequest } from "../../src/planner/index";
import { initPlannerFromDisk, loadPlannerFromDisk, ROOT } from "../../src/planner/node";
import { sharedPath } from "./helpers";

const PYTHON = join(ROOT, ".venv/bin/python");
const SOLVER = join(ROOT, "scripts/pddl_solve.py");

type Solved = Record<string, { plan: string[] } | { error: string }>;

let planner: FoonPlanner;
let work: string;
const plans = new Map<string, Plan>();

/** Unit indices (from 0) of the actions found: an action is named `<motion>-<unit number>`. */
function unitsOf(actions: readonly string[]): number[] {
  return actions.map((a) => {
    const match = /-(\d+)$/.exec(a);
    if (match === null) throw new Error(`action '${a}' names no unit`);
    return Number(match[1]) - 1;
  });
}

beforeAll(() => {
  if (!existsSync(PYTHON)) throw new Error(`${PYTHON} is missing: run npm run setup (it makes the venv with Fast Downward)`);
  initPlannerFromDisk();
  planner = loadPlannerFromDisk(sharedPath("foon/subgraphs-plain"));
  work = mkdtempSync(join(tmpdir(), "foon-pddl-"));
  readQueries(sharedPath("recipes/dev")).forEach((q, i) => {
    const request: PlanRequest = { query: q.query };
    const name = String(i).padStart(3, "0");
    mkdirSync(join(work, name));
    writeFileSync(join(work, name, "domain.pddl"), planner.exportPlan(request, "pddl-domain"));
    writeFileSync(join(work, name, "problem.pddl"), planner.exportPlan(request, "pddl-problem"));
    plans.set(name, planner.plan(request));
  });
});

afterAll(() => {
  if (work !== undefined) rmSync(work, { recursive: true, force: true });
});

describe("PDDL export solved by Fast Downward", () => {
  it("solves every dev plan with exactly its units in an order the schedule allows", () => {
    const solved = JSON.parse(execFileSync(PYTHON, [SOLVER, "--batch", work], { encoding: "utf8", maxBuffer: 1 << 26 })) as Solved;
    expect(Object.keys(solved).sort()).toEqual([...plans.keys()].sort());
    const wrong: string[] = [];
    for (const [name, plan] of plans) {
      const result = solved[name]!;
      const where = `${name} (${plan.query.type}/${plan.query.id ?? "?"})`;
      if ("error" in result) {
        wrong.push(`${where}: ${result.error}`);
        continue;
      }
      const order = unitsOf(result.plan);
      // each unit of the task tree exactly once
      const each = [...order].sort((a, b) => a - b);
      if (each.length !== plan.units.length || each.some((u, i) => u !== i)) {
        wrong.push(`${where}: found units ${order.join(",")} of ${plan.units.length}`);
        continue;
      }
      const metrics = structureMetrics(order.map((u) => plan.units[u]!), plan.goal);
      if (metrics.units_before_inputs + metrics.dead_units > 0 || !metrics.goal_produced) {
        wrong.push(`${where}: ${metrics.violations.join("; ") || "the goal is not made"}`);
      }
    }
    expect(wrong).toEqual([]);
  }, 900_000);
});
