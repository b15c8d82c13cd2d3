// The reference recipe the plan started from (the reference goal node and its ingredients), what
// modification removed from it, and the planner's notes.

import type { Plan } from "../../planner/types";
import { el, plural } from "../dom";
import type { StateSource } from "../draw-schedule";
import type { AppState } from "../store";

export function mountReferenceView(host: HTMLElement, store: StateSource): () => void {
  const body = el("div", { class: "reference-body" });
  host.replaceChildren(el("h2", { text: "Reference recipe" }), body);

  const render = (plan: Plan | null, ms: number | null, titles: Record<string, string>): void => {
    if (plan === null) {
      body.replaceChildren(el("p", { class: "muted", text: "The reference task tree appears here once there is a plan." }));
      return;
    }
    const g = plan.goal;
    const asked = new Set(plan.query.ingredients.map((i) => i.object));
    const list = el("ul", { class: "chips", "aria-label": "Ingredients of the reference recipe" });
    for (const i of g.ingredients) list.append(el("li", { class: asked.has(i) ? "chip kept" : "chip", text: i }));
    const removed = el("ul", { class: "chips", "aria-label": "Removed from the reference task tree" });
    for (const r of plan.removed) removed.append(el("li", { class: "chip removed", text: r }));
    const parts: (Node | null)[] = [
      el(
        "p",
        { class: "goal" },
        "Started from ",
        el("strong", { class: "goal-label", text: titles[g.subgraph] ?? g.subgraph }),
        ` (goal node “${g.label}”, ${g.states.join(", ")}; file ${g.subgraph}), ingredient similarity ${g.score.toFixed(2)}` +
          `${plan.dish_class === null ? "" : `, dish class ${plan.dish_class.name}`}.`,
      ),
      el("h3", { text: "Its ingredients" }),
      list,
      el("h3", { text: "Removed (not asked for)" }),
      plan.removed.length === 0 ? el("p", { class: "muted", text: "Nothing." }) : removed,
      plan.notes.length === 0 ? null : el("h3", { text: "Notes" }),
      plan.notes.length === 0 ? null : el("ul", { class: "notes" }, ...plan.notes.map((n) => el("li", { text: n }))),
      el("p", { class: "muted small", text: `${plural(plan.units.length, "functional unit")}${plan.modified ? "" : " (not modified)"}${ms === null ? "" : `, planned in ${Math.round(ms)} ms`}.` }),
    ];
    body.replaceChildren(...parts.filter((p): p is Node => p !== null));
  };
  const update = (state: AppState, previous: AppState | null): void => {
    if (previous === null || state.plan !== previous.plan) render(state.plan, state.planMs, state.kb?.vocabulary.titles ?? {});
  };
  update(store.state, null);
  return store.subscribe(update);
}
