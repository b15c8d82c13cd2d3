// Every metric of one plan: the one implementation used by the CLI and the browser workbench.

import type { Plan } from "../planner/types";
import { coverageMetrics } from "./coverage";
import { plausibilityMetrics } from "./plausibility";
import { structureMetrics } from "./structure";
import type { PlanMetrics } from "./types";

export function planMetrics(plan: Plan): PlanMetrics {
  return { ...structureMetrics(plan.units, plan.goal), ...coverageMetrics(plan), ...plausibilityMetrics(plan) };
}
