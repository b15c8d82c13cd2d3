// Downloads of the plan shown: the task-tree picture from the tree view, the plan JSON as the CLI prints
// it, and the planner's text exports (FOON, PDDL, progress lines) made in the worker.

import type { ExportFormat, Plan, PlanRequest } from "../../planner/types";
import { download } from "../dom";
import type { DownloadFormat } from "../views/export-panel";

/** The task-tree picture, when the tree view is loaded. */
export interface TreePicture {
  png(): Promise<Blob>;
  svg(): string;
}

const TEXT_FILES: Record<Exclude<ExportFormat, "json">, [suffix: string, type: string]> = {
  foon: ["task-tree.txt", "text/plain"],
  pddl: ["task-tree.pddl", "text/plain"],
  "pddl-domain": ["domain.pddl", "text/plain"],
  "pddl-problem": ["problem.pddl", "text/plain"],
  progress: ["progress-lines.json", "application/json"],
};

function slug(text: string): string {
  return text.toLowerCase().replace(/[^a-z0-9]+/g, "-").replace(/^-|-$/g, "") || "plan";
}

/** Saves `plan` (made for `request`) as `format`; `exportText` asks the planner for its text exports. */
export async function downloadPlan(
  plan: Plan,
  request: PlanRequest,
  format: DownloadFormat,
  tree: TreePicture | null,
  exportText: (request: PlanRequest, format: ExportFormat) => Promise<string>,
): Promise<void> {
  const base = slug(`${plan.query.type || "any"}-${plan.goal.label}`);
  if (format === "png") {
    if (tree !== null) download(`${base}-task-tree.png`, await tree.png());
  } else if (format === "svg") {
    if (tree !== null) download(`${base}-task-tree.svg`, tree.svg(), "image/svg+xml");
  } else if (format === "json") {
    // the plan as the CLI prints it: the Algorithm view's trace is not part of the task tree
    const { trace: _trace, ...exported } = plan;
    download(`${base}-plan.json`, `${JSON.stringify(exported, null, 2)}\n`, "application/json");
  } else {
    const [suffix, type] = TEXT_FILES[format];
    download(`${base}-${suffix}`, await exportText(request, format), type);
  }
}
