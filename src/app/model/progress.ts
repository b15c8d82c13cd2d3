// Progress lines (section IV-A) as rows of cells for the D3 view: each ingredient's states (with their
// container) and the motions between them, the end product at the right.

import type { Plan } from "../../planner/types";
import { unitsOfIngredient } from "./tree";

export type ProgressCell =
  | { kind: "state"; text: string; location: string; index: number }
  | { kind: "motion"; text: string; index: number; unit: number | null }
  | { kind: "product"; text: string };

export interface ProgressRow {
  ingredient: string;
  cells: ProgressCell[];
}

export function progressRows(plan: Plan): ProgressRow[] {
  return plan.progress_lines.map((line) => {
    const units = unitsOfIngredient(plan, line.ingredient);
    const cells: ProgressCell[] = [];
    line.state.forEach((s, i) => {
      cells.push({ kind: "state", text: s.physical_state === "" ? line.ingredient : s.physical_state, location: s.location, index: i });
      const motion = line.motion[i];
      if (motion !== undefined) cells.push({ kind: "motion", text: motion, index: i, unit: units[i] ?? null });
    });
    cells.push({ kind: "product", text: line.end_product });
    return { ingredient: line.ingredient, cells };
  });
}

/** The widest row, in cells: the view's column count. */
export function columnCount(rows: readonly ProgressRow[]): number {
  return rows.reduce((max, r) => Math.max(max, r.cells.length), 0);
}
