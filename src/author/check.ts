// Checks the FOON text being written, as the planner will read it: the WASM reader's first error (file,
// line, column, reason), its warnings, the drafter's marks still to confirm, and the preview — the
// reference task tree the planner retrieves from the text alone, as a plan the task-tree view draws.

import { toPlannerError } from "../planner/errors";
import type { FoonErrorData, KnowledgeBaseFile, Plan } from "../planner/types";
import type { PlannerService } from "../worker/client";
import type { LoadedKnowledgeBase } from "../worker/protocol";
import { CONFIRM_PREFIX, lineKind } from "./tokens";

export type Severity = "error" | "warning" | "confirm";

export interface Diagnostic {
  severity: Severity;
  /** 1-based; null when the problem has no one place. */
  line: number | null;
  column: number | null;
  reason: string;
}

export interface CheckResult {
  diagnostics: Diagnostic[];
  /** The reference task tree of the text's goal node; null when it does not load or has no goal. */
  preview: Plan | null;
}

/** The planner calls a check makes (a worker in the page, the WASM module directly in tests). */
export type CheckPlanner = Pick<PlannerService, "loadFiles" | "plan">;

export function authoredFile(name: string, text: string): KnowledgeBaseFile {
  return { name, bytes: new TextEncoder().encode(text) };
}

/** The reason of a reader message without its `file:line:column: ` place and ` (code)` suffix. */
function reasonOf(e: FoonErrorData & { reason?: string }): string {
  if (e.reason !== undefined && e.reason !== e.message) return e.reason;
  return e.message.replace(/^[^:]*(:\d+){1,2}: /, "").replace(new RegExp(` \\(${e.code}\\)$`), "");
}

function fromReader(e: FoonErrorData & { reason?: string }, severity: Severity): Diagnostic {
  return { severity, line: e.line ?? null, column: e.column ?? null, reason: reasonOf(e) };
}

/** The drafter's `# confirm: …` lines, each a mark for the user. */
export function confirmMarks(text: string): Diagnostic[] {
  const marks: Diagnostic[] = [];
  text.split("\n").forEach((line, i) => {
    if (lineKind(line) === "confirm") {
      marks.push({ severity: "confirm", line: i + 1, column: 1, reason: line.trim().slice(CONFIRM_PREFIX.length).trim() });
    }
  });
  return marks;
}

async function previewOf(planner: CheckPlanner, kb: LoadedKnowledgeBase): Promise<{ plan: Plan | null; problem: string | null }> {
  const dish = kb.vocabulary.dishes[0];
  const label = kb.vocabulary.labels[0];
  if (dish === undefined || label === undefined) {
    return { plan: null, problem: "no goal node yet: give the last unit's output its dish class as a 4th field of its O line (e.g. O\tgreek salad\t1\t15)" };
  }
  try {
    // modify: false, the ingredient only steers nothing: the reference task tree of the one goal
    const result = await planner.plan({ query: { type: dish.name, ingredients: [{ object: label, state: "" }] }, modify: false });
    return { plan: result?.plan ?? null, problem: null };
  } catch (e) {
    return { plan: null, problem: `no preview: ${reasonOf(toPlannerError(e))}` };
  }
}

/** Loads the text alone into the planner and reports what a user must know about it. */
export async function checkText(planner: CheckPlanner, name: string, text: string): Promise<CheckResult> {
  const marks = confirmMarks(text);
  let kb: LoadedKnowledgeBase;
  try {
    kb = await planner.loadFiles([authoredFile(name, text)]);
  } catch (e) {
    return { diagnostics: [fromReader(toPlannerError(e), "error"), ...marks], preview: null };
  }
  const diagnostics = [...kb.warnings.map((w) => fromReader(w, "warning")), ...marks];
  const { plan, problem } = await previewOf(planner, kb);
  if (problem !== null) diagnostics.push({ severity: "warning", line: null, column: null, reason: problem });
  if (plan !== null && plan.units.length < kb.stats.units) {
    const left = kb.stats.units - plan.units.length;
    diagnostics.push({ severity: "warning", line: null, column: null, reason: `${left} of ${kb.stats.units} functional units are not on the way to the goal node: the planner never retrieves them` });
  }
  return { diagnostics, preview: plan };
}
