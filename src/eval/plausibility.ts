// Culinary plausibility of a plan, next to its structure: what the planner's food knowledge finds a cook
// would stop at (the plan's `cautions`, written by `planner::cautions` in the core from the finished
// units and progress lines, so the app, the CLI and the workbench show the same), counted per kind.

import type { CautionKind, Plan } from "../planner/types";
import type { PlausibilityMetrics } from "./types";

export const CAUTION_KINDS: readonly CautionKind[] = ["motion_on_form", "uncooked", "short_of_dish", "left_whole"];

export const CAUTION_LABELS: Record<CautionKind, string> = {
  motion_on_form: "motions on forms that cannot take them",
  uncooked: "must-cook foods reaching the dish uncooked",
  short_of_dish: "asked ingredients short of the dish",
  left_whole: "produce left whole",
};

export const emptyCautionCounts = (): Record<CautionKind, number> => ({ motion_on_form: 0, uncooked: 0, short_of_dish: 0, left_whole: 0 });

export function plausibilityMetrics(plan: Plan): PlausibilityMetrics {
  const counts = emptyCautionCounts();
  for (const c of plan.cautions) counts[c.kind] += 1;
  return { cautions: counts, caution_details: plan.cautions.map((c) => `${c.kind}: ${c.detail}`) };
}
