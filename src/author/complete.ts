// Completion of the knowledge base's objects, states and motions where the caret is: in the name field
// of an `O`, `S` or `M` line. Pure: the editor shows the list and applies the choice.

import { lineKind } from "./tokens";

export interface CompletionWords {
  labels: readonly string[];
  states: readonly string[];
  motions: readonly string[];
}

export interface Completion {
  /** Text offsets of the word being replaced. */
  from: number;
  to: number;
  options: string[];
}

const MAX_OPTIONS = 8;

/** Options for the word at `caret`, best first (prefix matches before word matches); null: none. */
export function completeAt(text: string, caret: number, words: CompletionWords): Completion | null {
  const lineStart = text.lastIndexOf("\n", caret - 1) + 1;
  const lineEndAt = text.indexOf("\n", caret);
  const line = text.slice(lineStart, lineEndAt === -1 ? text.length : lineEndAt);
  const before = text.slice(lineStart, caret);
  const fields = before.split("\t");
  if (fields.length !== 2) return null; // the caret is not in the name field
  const pool = { object: words.labels, state: words.states, motion: words.motions }[lineKind(line) as "object" | "state" | "motion"];
  if (pool === undefined) return null;
  const typed = fields[1]!.toLowerCase();
  if (typed.trim() === "") return null;
  const rest = line.slice(before.length);
  const to = caret + (rest.split("\t", 1)[0]?.length ?? 0);
  const starts = pool.filter((w) => w.startsWith(typed));
  const inside = pool.filter((w) => !w.startsWith(typed) && w.split(/[\s-]/).some((part) => part.startsWith(typed)));
  const options = [...starts, ...inside].filter((w) => w !== typed).slice(0, MAX_OPTIONS);
  return options.length === 0 ? null : { from: caret - fields[1]!.length, to, options };
}

/** The text with a completion applied, and the caret after it. */
export function applyCompletion(text: string, completion: Completion, option: string): { text: string; caret: number } {
  return { text: text.slice(0, completion.from) + option + text.slice(completion.to), caret: completion.from + option.length };
}
