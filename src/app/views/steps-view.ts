// Steps: the task tree as numbered, recipe-like sentences (the accessible view of the same plan: the
// graph canvas has none). A listbox with roving focus; arrow keys, Home and End move the selection.

import type { Plan } from "../../planner/types";
import { el, uid } from "../dom";
import { selectUnit, type Selection } from "../model/tree";
import type { StateSource } from "../draw-schedule";
import type { AppState } from "../store";

export interface StepsViewActions {
  select(selection: Selection): void;
}

const ORIGIN_WORDS: Record<string, string> = {
  renamed: "renamed by modification",
  grafted: "grafted: added to reach a state",
  copied: "copied branch",
  attached: "takes a new ingredient",
};

const percent = (rate: number): string => `${Math.round(rate * 1000) / 10}%`;

/** A step's motion for a robot: who does it, its cost and success rate (only in a plan with a robot view). */
function robotFigures(plan: Plan, i: number): HTMLElement | null {
  const unit = plan.robot?.units[i];
  if (unit === undefined) return null;
  const who = unit.by === "human" ? "person" : "robot";
  return el("span", { class: `robot-figures ${unit.by}`, "data-by": unit.by, text: ` [${who}: cost ${unit.cost}, ${percent(unit.success_rate)}]` });
}

export function mountStepsView(host: HTMLElement, store: StateSource, actions: StepsViewActions): () => void {
  const titleId = uid("steps-title");
  const list = el("ol", { class: "steps", role: "listbox", "aria-labelledby": titleId });
  const cautions = el("div", { class: "cautions", role: "note", hidden: true });
  const robot = el("p", { class: "robot-summary muted", hidden: true });
  host.replaceChildren(el("h2", { id: titleId, text: "Steps" }), cautions, list, robot);
  let plan: Plan | null = null;

  function items(): HTMLLIElement[] {
    return [...list.querySelectorAll<HTMLLIElement>("li")];
  }

  // what the planner's food knowledge says a cook would stop at: the plan is shown, never silently wrong
  function renderCautions(next: Plan | null): void {
    const found = next?.cautions ?? [];
    cautions.hidden = found.length === 0;
    cautions.replaceChildren(
      el("p", { text: "A cook would check:" }),
      el("ul", {}, ...found.map((c) => el("li", { "data-kind": c.kind, text: c.detail }))),
    );
  }

  // the robot view (docs/robot.md): who does the plan and how likely the robot's part succeeds
  function renderRobot(next: Plan | null): void {
    const view = next?.robot;
    robot.hidden = view === undefined;
    if (view === undefined) return;
    const person = view.human_units.length === 0 ? "" : `; steps ${view.human_units.map((i) => i + 1).join(", ")} by a person`;
    robot.textContent = `Robot: total motion cost ${view.cost}, success ${percent(view.success_rate)}${person}.`;
  }

  function render(next: Plan | null): void {
    plan = next;
    renderCautions(next);
    renderRobot(next);
    if (next === null || next.units.length === 0) {
      list.replaceChildren(el("li", { class: "muted", role: "option", "aria-disabled": "true", text: next === null ? "No plan yet." : "The plan has no steps." }));
      return;
    }
    list.replaceChildren(
      ...next.units.map((u, i) => {
        const sentence = next.steps[i] ?? `${u.motion}.`;
        const origin = ORIGIN_WORDS[u.origin];
        const li = el(
          "li",
          { role: "option", tabindex: i === 0 ? 0 : -1, "aria-selected": "false", "data-unit": i, id: uid("step") },
          el("span", { class: "step-text", text: sentence }),
          origin === undefined ? null : el("span", { class: `origin ${u.origin}`, text: ` (${origin})` }),
          robotFigures(next, i),
        );
        li.addEventListener("click", () => actions.select(selectUnit(next, i)));
        return li;
      }),
    );
  }

  function renderSelection(selection: Selection, focus: boolean): void {
    const all = items();
    all.forEach((li) => {
      const chosen = li.dataset.unit !== undefined && Number(li.dataset.unit) === selection.unit;
      li.setAttribute("aria-selected", String(chosen));
      li.classList.toggle("selected", chosen);
    });
    const chosen = all.find((li) => li.getAttribute("aria-selected") === "true");
    if (chosen !== undefined) {
      all.forEach((li) => (li.tabIndex = li === chosen ? 0 : -1));
      if (focus) chosen.focus();
      else if (chosen.offsetTop < list.scrollTop || chosen.offsetTop + chosen.offsetHeight > list.scrollTop + list.clientHeight) {
        // scroll the list only, never the page (scrollIntoView would move the page too)
        list.scrollTop = chosen.offsetTop - list.offsetTop - 8;
      }
    }
  }

  list.addEventListener("keydown", (event: KeyboardEvent) => {
    if (plan === null || plan.units.length === 0) return;
    const last = plan.units.length - 1;
    const at = store.state.selection.unit ?? -1;
    const target =
      event.key === "ArrowDown" ? Math.min(last, at + 1) :
      event.key === "ArrowUp" ? Math.max(0, at - 1) :
      event.key === "Home" ? 0 :
      event.key === "End" ? last : null;
    if (target === null) return;
    event.preventDefault();
    keyboard = true;
    actions.select(selectUnit(plan, target));
  });

  // focus follows the selection only when it was moved from the keyboard in this list
  let keyboard = false;
  const update = (state: AppState, previous: AppState | null): void => {
    // a re-plan redraws the list: a step that had the focus keeps it (the user may be using the arrow keys)
    const focused = list.contains(document.activeElement);
    if (previous === null || state.plan !== previous.plan) render(state.plan);
    if (previous === null || state.plan !== previous.plan || state.selection !== previous.selection) {
      renderSelection(state.selection, keyboard || focused);
      keyboard = false;
    }
  };
  update(store.state, null);
  return store.subscribe(update);
}
