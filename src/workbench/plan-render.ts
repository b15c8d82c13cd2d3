// Renders parts of a plan for raters: an ingredient's progress line and the task tree as a list of
// functional units. Labels come from knowledge bases and queries: text only.

import type { IngredientOutcome, Plan, PlanNode, ProgressLine } from "../planner/types";
import { el } from "./dom";

/** The outcome and progress line of the query ingredient at `index` (query order). */
export function ingredientView(plan: Plan, index: number): { outcome: IngredientOutcome | undefined; line: ProgressLine | undefined } {
  const outcome = plan.ingredients[index];
  if (outcome === undefined) return { outcome, line: undefined };
  const names = [outcome.object, outcome.match?.label].filter((n): n is string => n !== undefined);
  const line = names.map((n) => plan.progress_lines.find((p) => p.ingredient === n)).find((p) => p !== undefined);
  return { outcome, line };
}

export function progressLine(line: ProgressLine | undefined): HTMLElement {
  if (line === undefined) return el("p", { class: "progress-line missing", text: "No progress line: the ingredient is not in this tree." });
  const chain = el("ol", { class: "progress-line" });
  line.state.forEach((state, i) => {
    const where = state.location === "" ? "" : ` (${state.location})`;
    chain.append(el("li", { class: "pl-state" }, el("span", { class: "state", text: state.physical_state === "" ? "—" : state.physical_state }), el("span", { class: "location", text: where })));
    const motion = line.motion[i];
    if (motion !== undefined) chain.append(el("li", { class: "pl-motion", text: motion }));
  });
  chain.append(el("li", { class: "pl-end", text: `→ ${line.end_product}` }));
  return chain;
}

function nodeText(node: PlanNode): string {
  const states = node.states.length === 0 ? "" : ` (${node.states.join(", ")})`;
  return `${node.label}${states}`;
}

/** The task tree as an ordered list of units: inputs → motion → outputs. */
export function taskTree(plan: Plan, showOrigin: boolean): HTMLElement {
  return el(
    "ol",
    { class: "task-tree" },
    ...plan.units.map((unit) =>
      el(
        "li",
        { class: "unit" },
        el("span", { class: "inputs", text: unit.inputs.map(nodeText).join(" + ") }),
        el("span", { class: "motion", text: ` —${unit.motion}→ ` }),
        el("span", { class: "outputs", text: unit.outputs.map(nodeText).join(" + ") }),
        ...(showOrigin && unit.origin !== "reference" ? [el("span", { class: `origin origin-${unit.origin}`, text: unit.origin })] : []),
      ),
    ),
  );
}

/** How the ingredient was planned (case, equivalent, confidence): hidden in blind mode. */
export function outcomeNote(outcome: IngredientOutcome | undefined): HTMLElement {
  if (outcome === undefined) return el("span", { class: "outcome", text: "" });
  const parts: string[] = [];
  if (outcome.case !== null) parts.push(`case ${outcome.case}`);
  if (outcome.match !== null && (outcome.match.label !== outcome.object || outcome.match.state !== outcome.state)) {
    parts.push(`as ${outcome.match.state} ${outcome.match.label} (${outcome.match.similarity.toFixed(2)})`);
  }
  if (outcome.status === "unplannable") parts.push(`unplannable${outcome.reason === undefined ? "" : `: ${outcome.reason}`}`);
  return el("span", { class: outcome.low_confidence ? "outcome low-confidence" : "outcome", text: parts.join(", ") + (outcome.low_confidence ? " — low confidence" : "") });
}
