// The substitutions panel: every query ingredient with its case of Table I (in words), the equivalent
// the planner chose, its similarity, a low-confidence flag and the top-5 alternatives. Choosing another
// equivalent sets an override and re-plans.

import type { IngredientOutcome, Plan } from "../../planner/types";
import { el, uid } from "../dom";
import { caseText, similarityText, substituteChoices } from "../model/substitutions";
import type { StateSource } from "../draw-schedule";
import type { AppState } from "../store";

export interface SubstitutionsActions {
  /** `label` null: let the planner choose again. */
  chooseSubstitute(object: string, label: string | null): void;
}

function row(outcome: IngredientOutcome, actions: SubstitutionsActions): HTMLTableRowElement {
  const phrase = outcome.state === "" ? outcome.object : `${outcome.state} ${outcome.object}`;
  const equivalent = outcome.match === null ? "—" : outcome.match.state === "" ? outcome.match.label : `${outcome.match.state} ${outcome.match.label}`;
  const selectId = uid("sub");
  const choices = substituteChoices(outcome);
  const picker = el("select", { id: selectId, class: "substitute", "data-object": outcome.object, "aria-label": `Equivalent for ${outcome.object}` });
  picker.append(el("option", { value: "", text: outcome.overridden ? "planner's choice" : `planner's choice${outcome.match === null ? "" : `: ${outcome.match.label}`}` }));
  for (const c of choices) picker.append(el("option", { value: c.label, text: `${c.label} (${similarityText(c.similarity)})` }));
  picker.value = outcome.overridden && outcome.match !== null ? outcome.match.label : "";
  picker.disabled = choices.length === 0;
  picker.addEventListener("change", () => actions.chooseSubstitute(outcome.object, picker.value === "" ? null : picker.value));
  const flags: (Node | string)[] = [];
  if (outcome.low_confidence) flags.push(el("span", { class: "badge warn", title: "The equivalent is not very similar: check it", text: "low confidence" }));
  if (outcome.overridden) flags.push(el("span", { class: "badge", text: "your choice" }));
  if (outcome.status === "unplannable") flags.push(el("span", { class: "badge error", text: "not planned" }));
  const tr = el(
    "tr",
    { "data-object": outcome.object, "data-case": outcome.case ?? "none" },
    el("th", { scope: "row", text: phrase }),
    el("td", { class: "case", text: caseText(outcome) }),
    el("td", { class: "equivalent", text: equivalent }),
    el("td", { class: "similarity", text: outcome.match === null ? "—" : similarityText(outcome.match.similarity) }),
    el(
      "td",
      { class: "flags" },
      ...flags,
      // the planner's explanation can be long: one click away, not in the way of the table
      outcome.reason === undefined ? null : el("details", { class: "reason small" }, el("summary", { text: "why" }), el("span", { text: outcome.reason })),
    ),
    el("td", {}, picker),
  );
  return tr;
}

export function mountSubstitutionsView(host: HTMLElement, store: StateSource, actions: SubstitutionsActions): () => void {
  const body = el("tbody");
  const table = el(
    "table",
    { class: "substitutions" },
    el("caption", { class: "muted small", text: "How each ingredient entered the task tree (the four cases of the paper's Table I)." }),
    el(
      "thead",
      {},
      el("tr", {}, ...["Ingredient", "Case", "Equivalent", "Similarity", "Flags", "Substitute"].map((h) => el("th", { scope: "col", text: h }))),
    ),
    body,
  );
  host.replaceChildren(el("h2", { text: "Substitutions" }), el("div", { class: "table-scroll" }, table));

  const render = (plan: Plan | null): void => {
    body.replaceChildren(
      ...(plan === null || plan.ingredients.length === 0
        ? [el("tr", {}, el("td", { colspan: 6, class: "muted", text: "No ingredients yet." }))]
        : plan.ingredients.map((o) => row(o, actions))),
    );
  };
  const update = (state: AppState, previous: AppState | null): void => {
    if (previous === null || state.plan !== previous.plan) render(state.plan);
  };
  update(store.state, null);
  return store.subscribe(update);
}
