// The embedding example page: defines <foon-planner> and logs the widgets' events.

import "./widget/index";

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
    write(`#${widget.id} plan: ${plan.units.length} functional units from “${plan.goal.label}”`);
  });
  widget.addEventListener("select", (event) => write(`#${widget.id} select: ${event.detail.step ?? "nothing"}`));
  widget.addEventListener("error", (event) => {
    if (event instanceof CustomEvent) write(`#${widget.id} error: ${JSON.stringify(event.detail)}`);
  });
}
