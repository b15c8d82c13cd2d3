// The embedding example page: defines <foon-planner> and logs the widgets' events.

import { mount, type PlannerHandle } from "./widget/index";

const log = document.getElementById("log");
function write(line: string): void {
  if (log === null) return;
  const row = document.createElement("div");
  row.textContent = line;
  log.append(row);
}

for (const widget of document.querySelectorAll("foon-planner")) {
  widget.addEventListener("plan", (event) => {
    const plan = event.detail.plan;
    widget.dataset.planned = String(plan.units.length);
    write(`#${widget.id} plan: ${plan.units.length} functional units from “${plan.goal.reference}”`);
  });
  widget.addEventListener("select", (event) => write(`#${widget.id} select: ${event.detail.step ?? "nothing"}`));
  widget.addEventListener("error", (event) => write(`#${widget.id} error: ${event.detail.error.message}`));
}

// The script API: mount(), update(), destroy().
let handle: PlannerHandle | null = null;
const mountButton = document.getElementById("mount-btn") as HTMLButtonElement | null;
const updateButton = document.getElementById("update-btn") as HTMLButtonElement | null;
const destroyButton = document.getElementById("destroy-btn") as HTMLButtonElement | null;
const target = document.getElementById("mounted");
const setButtons = (mounted: boolean): void => {
  if (mountButton !== null) mountButton.disabled = mounted;
  if (updateButton !== null) updateButton.disabled = !mounted;
  if (destroyButton !== null) destroyButton.disabled = !mounted;
};
mountButton?.addEventListener("click", () => {
  if (target === null || handle !== null) return;
  handle = mount(
    target,
    { dishType: "pizza", ingredients: "sliced mushroom, grated mozzarella, tomato sauce", view: "steps", theme: "light" },
    {
      onPlan: ({ plan }) => write(`#mounted plan: ${plan.units.length} functional units for ${plan.query.type} from “${plan.goal.reference}”`),
      onError: ({ error }) => write(`#mounted error: ${error.message}`),
    },
  );
  setButtons(true);
});
updateButton?.addEventListener("click", () => handle?.update({ dishType: "omelette", ingredients: "whole egg, chopped spinach" }));
destroyButton?.addEventListener("click", () => {
  handle?.destroy();
  handle = null;
  setButtons(false);
});
