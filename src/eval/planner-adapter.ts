// The plan function of a loaded planner, for the batch runner.

import type { FoonPlanner } from "../planner/index";
import { PlannerError } from "../planner/index";
import type { Plan, PlanRequest } from "../planner/types";
import type { PlanFunction } from "./runner";

interface WithPlan {
  plan(request: PlanRequest): Plan;
}

/** Whether this build's planner module can plan (the planner core lands on main in steps). */
export function plannerCanPlan(planner: object): boolean {
  return hasPlan(planner);
}

function hasPlan(value: object): value is WithPlan {
  return typeof (value as Partial<WithPlan>).plan === "function";
}

/** `planner.plan` bound to the planner; throws a PlannerError if this build has no planner yet. */
export function planFunction(planner: FoonPlanner): PlanFunction {
  if (!hasPlan(planner)) {
    throw new PlannerError({ code: "internal", message: "this build of the planner module has no plan(): the planner core has not landed yet" });
  }
  return (request) => planner.plan(request);
}
