// How right a draft is: each functional unit as a signature — its motion, the ingredients it acts on
// (a mixture counts as what it contains) and the container it happens in — compared with the units a
// person wrote for the same recipe. Names of intermediate nodes and the order of units do not count.

import table from "./draft-table.json";
import type { DraftUnit } from "./draft-foon";

const TOOLS = new Set(Object.values(table.tools));

/** "mix: olive oil, vinegar @ small bowl" */
export function unitSignature(u: DraftUnit): string {
  const foods = u.inputs.filter((n) => n.flag === 1 && !TOOLS.has(n.label));
  const labels = [...new Set(foods.flatMap((n) => ((n.contains?.length ?? 0) > 0 ? n.contains! : [n.label])))].sort();
  const container = u.inputs.find((n) => n.flag === 0 && n.contains !== null)?.label ?? foods.find((n) => n.inside !== null)?.inside ?? null;
  return `${u.motion}: ${labels.join(", ")}${container === null ? "" : ` @ ${container}`}`;
}

/** A written signature in the same normal form (ingredients sorted, single spaces). */
export function normalizeSignature(line: string): string {
  const [head, rest = ""] = line.split(":", 2) as [string, string?];
  const [foods, container] = rest.split("@").map((s) => s.trim()) as [string, string?];
  const labels = foods.split(",").map((f) => f.trim().toLowerCase()).filter((f) => f !== "").sort();
  return `${head.trim().toLowerCase()}: ${labels.join(", ")}${container === undefined || container === "" ? "" : ` @ ${container.toLowerCase()}`}`;
}

export interface DraftScore {
  /** Units of the person's subgraph that the draft has too. */
  right: number;
  expected: number;
  drafted: number;
  missed: string[];
  extra: string[];
}

/** Matches drafted and expected signatures one to one (a multiset intersection). */
export function scoreDraft(drafted: readonly string[], expected: readonly string[]): DraftScore {
  const left = [...drafted];
  const missed: string[] = [];
  for (const e of expected) {
    const i = left.indexOf(e);
    if (i === -1) missed.push(e);
    else left.splice(i, 1);
  }
  return { right: expected.length - missed.length, expected: expected.length, drafted: drafted.length, missed, extra: left };
}
