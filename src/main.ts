// Demo page entry: loads the planner and the bundled knowledge base, then shows its statistics.

import { FoonPlanner, initPlanner, toPlannerError } from "./planner/index";
import type { Stats } from "./planner/types";

const KB_URL = new URL("kb/default.foon", document.baseURI);

function renderStats(stats: Stats): void {
  const body = document.querySelector<HTMLTableSectionElement>("#stats tbody");
  if (body === null) return;
  const rows: [string, string][] = [
    ["Recipes (subgraphs)", String(stats.subgraphs)],
    ["Functional units before merge", String(stats.units_before_merge)],
    ["Functional units", String(stats.units)],
    ["Object nodes", String(stats.object_nodes)],
    ["Labels", String(stats.labels)],
    ["States", String(stats.states)],
    ["Motions", String(stats.motions)],
    ["Goal nodes", String(stats.goal_nodes)],
    ...Object.entries(stats.recipes_per_class).map(([cls, n]): [string, string] => [`Recipes: ${cls}`, String(n)]),
  ];
  body.replaceChildren(
    ...rows.map(([name, value]) => {
      const tr = document.createElement("tr");
      const th = document.createElement("th");
      th.scope = "row";
      th.textContent = name;
      const td = document.createElement("td");
      td.textContent = value;
      tr.append(th, td);
      return tr;
    }),
  );
}

async function start(): Promise<void> {
  const status = document.getElementById("kb-status");
  try {
    await initPlanner();
    const response = await fetch(KB_URL);
    if (!response.ok) throw new Error(`${KB_URL.pathname}: HTTP ${response.status}`);
    const planner = FoonPlanner.load([{ name: "default.foon", bytes: new Uint8Array(await response.arrayBuffer()) }]);
    const stats = planner.stats();
    renderStats(stats);
    if (status !== null) {
      status.textContent = `Knowledge base loaded: ${stats.subgraphs} recipes, ${stats.units} functional units.`;
      status.dataset.state = "ready";
    }
  } catch (e) {
    if (status !== null) {
      status.textContent = `Could not load the planner: ${toPlannerError(e).message}`;
      status.dataset.state = "error";
    }
  }
}

void start();
