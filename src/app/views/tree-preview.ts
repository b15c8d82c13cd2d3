// The task tree as a still picture (SVG) in the same layout as the interactive view, shown until that view is
// loaded: Cytoscape is most of the page's script, so it loads once the first plan is on screen, not before.

import type { Plan } from "../../planner/types";
import { el } from "../dom";
import { graphToSvg, type PlacedNode } from "../export/svg";
import { layoutTree, type Point } from "../model/layout";
import { planToGraph, type TreeGraph } from "../model/tree";
import type { StateSource } from "../draw-schedule";
import { readColors } from "../theme-colors";

export const OBJECT_SIZE = 26;
export const MOTION_SIZE = 22;
/** The largest zoom the views fit a tree at: a small tree's labels would be huge. */
export const MAX_FIT_ZOOM = 1.5;

/** The graph's nodes at their places, sized as the views draw them. */
export function placeNodes(graph: TreeGraph, at: (id: string) => Point): PlacedNode[] {
  return graph.nodes.map((n) => ({ ...n, ...at(n.id), size: n.kind === "object" ? (n.goal ? OBJECT_SIZE + 8 : OBJECT_SIZE) : MOTION_SIZE }));
}

export function treeTitle(plan: Plan | null): string {
  return plan === null ? "foon-planner task tree" : `Task tree: ${plan.goal.label} (${plan.query.type || "any dish"})`;
}

export function treeLegend(): HTMLElement {
  return el(
    "ul",
    { class: "legend", "aria-label": "Legend" },
    el("li", {}, el("span", { class: "swatch object", "aria-hidden": "true" }), "object node"),
    el("li", {}, el("span", { class: "swatch motion", "aria-hidden": "true" }), "motion node"),
    el("li", {}, el("span", { class: "swatch marked", "aria-hidden": "true" }), "added, renamed or grafted by modification"),
    el("li", {}, el("span", { class: "swatch goal", "aria-hidden": "true" }), "goal node"),
  );
}

/** The head of both task-tree views: the title and the graph's tools. */
export function treeHead(): { head: HTMLElement; fit: HTMLButtonElement; zoomIn: HTMLButtonElement; zoomOut: HTMLButtonElement } {
  const fit = el("button", { type: "button", text: "Fit" });
  const zoomIn = el("button", { type: "button", "aria-label": "Zoom in", title: "Zoom in", text: "+" });
  const zoomOut = el("button", { type: "button", "aria-label": "Zoom out", title: "Zoom out", text: "−" });
  const head = el("div", { class: "view-head" }, el("h2", { text: "Task tree" }), el("div", { class: "toolbar", role: "toolbar", "aria-label": "Graph" }, fit, zoomIn, zoomOut));
  return { head, fit, zoomIn, zoomOut };
}

/**
 * Draws each plan in `host` until `onFirstPlan`'s caller replaces the host's content with the interactive
 * view (which then takes over the state source's subscription).
 */
export function mountTreePreview(host: HTMLElement, source: StateSource, onFirstPlan: () => void): void {
  const picture = el("div", { class: "cy tree-preview", role: "img", "aria-label": "Task tree graph (the Steps list below is the same plan as text)" });
  // the interactive view's parts in the same places, so that nothing moves when it takes over (its tools too,
  // which work once it has: a head of the title alone is lower than one with buttons)
  const caption = el("p", { class: "muted small tree-caption", text: "Loading the interactive graph…" });
  const { head, ...tools } = treeHead();
  for (const button of Object.values(tools)) button.disabled = true;
  host.replaceChildren(head, treeLegend(), picture, caption);
  let told = false;
  const draw = (plan: Plan | null): void => {
    if (plan === null) {
      picture.replaceChildren();
      return;
    }
    const graph = planToGraph(plan);
    const at = layoutTree(graph);
    const text = graphToSvg(placeNodes(graph, (id) => at.get(id)!), graph.edges, readColors(host), treeTitle(plan));
    // parsed as XML: nothing in it runs, and its labels are escaped
    const svg = document.importNode(new DOMParser().parseFromString(text, "image/svg+xml").documentElement, true);
    // at most MAX_FIT_ZOOM times its size, and never larger than the box (CSS): as the interactive view fits it
    for (const side of ["width", "height"]) svg.setAttribute(side, String(Number(svg.getAttribute(side)) * MAX_FIT_ZOOM));
    picture.replaceChildren(svg);
    if (!told) {
      told = true;
      onFirstPlan();
    }
  };
  draw(source.state.plan);
  source.subscribe((state, previous) => {
    if (state.plan !== previous.plan) draw(state.plan);
  });
}
