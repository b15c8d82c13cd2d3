// The substitution cases of Table I of the paper, in words, and the rows of the substitutions panel.

import type { IngredientOutcome, SubstitutionCase } from "../../planner/types";

export const CASE_WORDS: Record<SubstitutionCase, string> = {
  1: "exact match: used as it is",
  2: "object substituted, same state",
  3: "state reached by a new branch",
  4: "object substituted and a new branch added",
};

export function caseText(outcome: IngredientOutcome): string {
  if (outcome.case === null) return outcome.status === "unplannable" ? "not plannable" : "not matched";
  return `Case ${outcome.case}: ${CASE_WORDS[outcome.case]}`;
}

/** "0.83" for a similarity in 0..1. */
export function similarityText(similarity: number): string {
  return similarity.toFixed(2);
}

/** The choices the panel offers: the planner's equivalent first, then the alternatives, no repeats. */
export function substituteChoices(outcome: IngredientOutcome): { label: string; similarity: number }[] {
  const seen = new Set<string>();
  const out: { label: string; similarity: number }[] = [];
  const push = (label: string, similarity: number): void => {
    if (label === "" || seen.has(label)) return;
    seen.add(label);
    out.push({ label, similarity });
  };
  if (outcome.match !== null) push(outcome.match.label, outcome.match.similarity);
  for (const a of outcome.alternatives) push(a.label, a.similarity);
  return out;
}
