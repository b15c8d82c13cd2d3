// The plan function of a loaded planner, for the batch runner.

import type { FoonPlanner } from "../planner/index";
import type { PlanFunction } from "./runner";

/** `planner.plan` bound to the planner. */
export function planFunction(planner: FoonPlanner): PlanFunction {
  return (request) => planner.plan(request);
}
