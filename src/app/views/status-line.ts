// The status line under the query: loading, planning, the plan's summary with how long it took to show,
// or the error. `data-state` is the page's own signal (tests and embedding pages wait on it): "ready"
// once every view has drawn the plan, those off screen included.

import { plural } from "../dom";
import type { DrawSchedule } from "../draw-schedule";
import type { AppState, Store } from "../store";

/** " Shown in 3.1 ms (planner 0.6 ms)." once both are known. */
function timing(state: AppState): string {
  if (state.shownMs === null || state.planMs === null) return "";
  return ` Shown in ${state.shownMs.toFixed(1)} ms (planner ${state.planMs.toFixed(1)} ms).`;
}

function stateOf(state: AppState, settled: boolean): string {
  if (state.planError !== null) return "error";
  if (state.planning) return "planning";
  if (state.plan !== null) return settled ? "ready" : "drawing";
  return state.kb === null ? "loading" : "idle";
}

function textOf(state: AppState): string {
  if (state.planError !== null) return state.planError;
  if (state.kb === null) return "Loading the planner and the knowledge base…";
  if (state.planning) return "Planning…";
  if (state.plan === null) return "Add ingredients to plan a task tree.";
  return `Task tree for ${state.plan.query.type || "any dish"}: ${plural(state.plan.units.length, "functional unit")} from “${state.plan.goal.reference}”.${timing(state)}`;
}

export function mountStatusLine(status: HTMLElement, store: Store, schedule: DrawSchedule): () => void {
  const update = (): void => {
    status.dataset.state = stateOf(store.state, schedule.settled);
    const text = textOf(store.state);
    if (status.textContent !== text) status.textContent = text;
  };
  update();
  const stops = [store.subscribe(update), schedule.onSettled(update)];
  return () => stops.forEach((stop) => stop());
}
