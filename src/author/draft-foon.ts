// The drafter's subgraph as data, and as plain-dialect FOON text with its marks for the user
// (`# confirm:` comment lines, which the editor lists and highlights).

import { CONFIRM_PREFIX } from "./tokens";

export interface DraftNode {
  label: string;
  /** Physical states ("diced", "mixed"), in the order they were reached. */
  states: string[];
  /** The container it is in, if any. */
  inside: string | null;
  /** What a container or a mixture holds (ingredient labels); null: not a holder. */
  contains: string[] | null;
  /** 1: it moves or changes in the unit; 0: only present (containers, appliances). */
  flag: 0 | 1;
  /** Set on the goal node only. */
  dishClass?: number;
}

export interface DraftUnit {
  inputs: DraftNode[];
  motion: string;
  outputs: DraftNode[];
  /** Guesses the user should confirm. */
  notes: string[];
}

/** A label as FOON can hold it: no tabs, brackets, braces or commas. */
export function foonLabel(text: string): string {
  return text.replace(/[\t[\]{},]/g, " ").replace(/\s+/g, " ").trim().toLowerCase();
}

function nodeLines(n: DraftNode): string[] {
  const lines = [`O\t${n.label}\t${n.flag}${n.dishClass === undefined ? "" : `\t${n.dishClass}`}`];
  for (const s of n.states) lines.push(`S\t${s}`);
  if (n.inside !== null) lines.push(`S\tin\t[${n.inside}]`);
  if (n.contains !== null) lines.push(n.contains.length === 0 ? "S\tempty" : `S\tcontains\t{${[...n.contains].sort().join(",")}}`);
  return lines;
}

const confirm = (note: string): string => `${CONFIRM_PREFIX} ${note}`;

export function draftToFoon(title: string, notes: readonly string[], units: readonly DraftUnit[]): string {
  const lines = [`# title: ${title}`, "# drafted from recipe text: check every unit, then remove the '# confirm:' lines", ...notes.map(confirm)];
  for (const unit of units) {
    lines.push("//", ...unit.notes.map(confirm));
    for (const n of unit.inputs) lines.push(...nodeLines(n));
    lines.push(`M\t${unit.motion}\t<Assumed>`);
    for (const n of unit.outputs) lines.push(...nodeLines(n));
  }
  return `${lines.join("\n")}\n`;
}
