// The task tree with Cytoscape.js, laid out left to right towards the goal (`model/layout.ts`): object
// nodes as green circles, motion nodes as red squares, edges input -> motion -> output; nodes that
// modification added, renamed or grafted are outlined and dashed. Selecting a node selects its
// functional unit and ingredient.

import cytoscape, { type CollectionReturnValue, type Core, type ElementDefinition, type StylesheetJson } from "cytoscape";
import type { Plan } from "../../planner/types";
import { el } from "../dom";
import { graphToSvg } from "../export/svg";
import { layoutTree } from "../model/layout";
import { planToGraph, selectNode, type Selection, type TreeGraph } from "../model/tree";
import type { StateSource } from "../draw-schedule";
import type { AppState } from "../store";
import { readColors, type GraphColors } from "../theme-colors";
import { MAX_FIT_ZOOM, MOTION_SIZE, OBJECT_SIZE, placeNodes, treeHead, treeLegend, treeTitle } from "./tree-preview";

export interface TreeViewHandle {
  png(): Promise<Blob>;
  svg(): string;
  /** Re-reads theme colours (after a theme switch). */
  restyle(): void;
  destroy(): void;
}

export interface TreeViewActions {
  select(selection: Selection): void;
}

/** The graph's Cytoscape elements, each node at its place in the layout. */
export function elements(graph: TreeGraph): ElementDefinition[] {
  const at = layoutTree(graph);
  return [
    ...graph.nodes.map((n) => ({
      group: "nodes" as const,
      position: at.get(n.id)!,
      data: { id: n.id, label: n.label, caption: n.detail === "" ? n.label : `${n.label}\n${n.detail}`, kind: n.kind, mark: n.mark ?? "", ingredient: n.ingredient ?? "" },
      classes: [n.kind, n.mark === null ? "" : "marked", n.goal ? "goal" : ""].filter((c) => c !== "").join(" "),
    })),
    ...graph.edges.map((e) => ({ group: "edges" as const, data: { id: e.id, source: e.source, target: e.target } })),
  ];
}

export function stylesheet(c: GraphColors): StylesheetJson {
  return [
    {
      selector: "node",
      style: {
        label: "data(caption)",
        "text-wrap": "wrap",
        "text-max-width": "120px",
        "text-valign": "bottom",
        "text-margin-y": 4,
        "font-size": 10,
        color: c.text,
        "text-outline-color": c.background,
        "text-outline-width": 2,
      },
    },
    { selector: "node.object", style: { shape: "ellipse", width: OBJECT_SIZE, height: OBJECT_SIZE, "background-color": c.object } },
    { selector: "node.motion", style: { shape: "rectangle", width: MOTION_SIZE, height: MOTION_SIZE, "background-color": c.motion } },
    { selector: "node.goal", style: { "border-width": 3, "border-color": c.text, width: OBJECT_SIZE + 8, height: OBJECT_SIZE + 8 } },
    { selector: "node.marked", style: { "border-width": 4, "border-style": "dashed", "border-color": c.mark } },
    { selector: "node.on-line", style: { "underlay-color": c.line, "underlay-opacity": 0.35, "underlay-padding": 6 } },
    { selector: "node.selected", style: { "overlay-color": c.select, "overlay-opacity": 0.45, "overlay-padding": 6 } },
    {
      selector: "edge",
      style: { width: 1.5, "line-color": c.edge, "target-arrow-color": c.edge, "target-arrow-shape": "triangle", "curve-style": "bezier", "arrow-scale": 0.8 },
    },
    { selector: "edge.on-line", style: { "line-color": c.line, "target-arrow-color": c.line, width: 3 } },
  ];
}

/**
 * Shows a graph in place of the one drawn, in one batch. Elements the two graphs share stay (a re-plan
 * usually changes a few nodes): only what is added or changed is restyled and has its label measured again,
 * which is most of what Cytoscape does with a new element.
 */
export function showGraph(cy: Core, graph: TreeGraph): void {
  const next = elements(graph);
  const wanted = new Set(next.map((e) => e.data.id));
  cy.batch(() => {
    cy.elements().filter((e) => !wanted.has(e.id())).remove();
    const added: ElementDefinition[] = [];
    for (const def of next) {
      const drawn = cy.getElementById(def.data.id!);
      if (drawn.empty()) added.push(def);
      else if (def.group === "nodes") updateNode(drawn, def);
    }
    cy.add(added);
  });
}

/** A node kept from the graph drawn before: its place, and its data and marks where they changed. */
function updateNode(node: CollectionReturnValue, def: ElementDefinition): void {
  const { x, y } = def.position!;
  if (node.position("x") !== x || node.position("y") !== y) node.position({ x, y });
  for (const [key, value] of Object.entries(def.data)) if (node.data(key) !== value) node.data(key, value);
  const classes = new Set((def.classes as string).split(" "));
  for (const mark of ["marked", "goal"]) if (node.hasClass(mark) !== classes.has(mark)) node.toggleClass(mark, classes.has(mark));
}

/** Where the nodes' centres reach: a fitted viewport still fits while it is the same. */
function extent(cy: Core): string {
  const xs = cy.nodes().map((n) => n.position("x"));
  const ys = cy.nodes().map((n) => n.position("y"));
  return [Math.min(...xs), Math.min(...ys), Math.max(...xs), Math.max(...ys)].join(" ");
}

export function mountTreeView(host: HTMLElement, store: StateSource, actions: TreeViewActions): TreeViewHandle {
  const canvas = el("div", { class: "cy", role: "img", "aria-label": "Task tree graph (the Steps list below is the same plan as text)" });
  const { head, fit, zoomIn, zoomOut } = treeHead();
  const caption = el("p", { class: "muted small tree-caption", "aria-live": "polite" });
  host.replaceChildren(head, treeLegend(), canvas, caption);

  let colors = readColors(host);
  const cy: Core = cytoscape({
    container: canvas,
    style: stylesheet(colors),
    minZoom: 0.1,
    maxZoom: 4,
    autounselectify: true, // selection lives in the store, shown with classes
    boxSelectionEnabled: false,
  });
  let graph: TreeGraph = { nodes: [], edges: [] };
  let plan: Plan | null = null;
  /** The extent the viewport was last fitted to by a plan. */
  let fitted = "";

  cy.on("tap", "node", (event) => actions.select(selectNode(graph, String(event.target.id()))));
  // fit the whole tree, but never blow a small one up past MAX_FIT_ZOOM
  const fitTree = (): void => {
    cy.fit(undefined, 20);
    if (cy.zoom() > MAX_FIT_ZOOM) {
      cy.zoom(MAX_FIT_ZOOM);
      cy.center();
    }
  };
  fit.addEventListener("click", fitTree);
  zoomIn.addEventListener("click", () => cy.zoom({ level: cy.zoom() * 1.25, renderedPosition: { x: cy.width() / 2, y: cy.height() / 2 } }));
  zoomOut.addEventListener("click", () => cy.zoom({ level: cy.zoom() / 1.25, renderedPosition: { x: cy.width() / 2, y: cy.height() / 2 } }));

  function renderPlan(next: Plan | null): void {
    plan = next;
    graph = next === null ? { nodes: [], edges: [] } : planToGraph(next);
    showGraph(cy, graph);
    // fitting measures every element's bounding box: a re-plan that keeps the tree's extent keeps the viewport
    const reach = extent(cy);
    if (reach !== fitted) fitTree();
    fitted = reach;
    canvas.dataset.nodes = String(graph.nodes.length);
    canvas.dataset.edges = String(graph.edges.length);
  }

  function renderSelection(selection: Selection): void {
    cy.batch(() => {
      cy.elements().removeClass("selected on-line");
      const picked = selection.node ?? (selection.unit === null ? null : `m:${selection.unit}`);
      if (picked !== null) cy.getElementById(picked).addClass("selected");
      canvas.dataset.selected = picked ?? "";
      if (selection.ingredient !== null) {
        const on = cy.nodes().filter((n) => n.data("ingredient") === selection.ingredient);
        on.addClass("on-line");
        on.connectedEdges().addClass("on-line");
      }
    });
    const unit = selection.unit === null || plan === null ? undefined : plan.units[selection.unit];
    caption.textContent = unit === undefined ? "Select a node to see its step and progress line." : `Selected: step ${selection.unit! + 1}, ${unit.motion} (${unit.origin === "reference" ? "from the reference task tree" : unit.origin}).`;
  }

  const update = (state: AppState, previous: AppState | null): void => {
    if (previous === null || state.plan !== previous.plan) renderPlan(state.plan);
    if (previous === null || state.plan !== previous.plan || state.selection !== previous.selection) renderSelection(state.selection);
  };
  update(store.state, null);
  const unsubscribe = store.subscribe(update);
  // a hidden container (another view tab) has no size: fit again when it is shown or resized
  const resize = new ResizeObserver(() => {
    cy.resize();
    fitTree();
  });
  resize.observe(canvas);

  return {
    png: async () => cy.png({ output: "blob-promise", full: true, scale: 2, bg: colors.background }),
    // where the nodes are now: the user may have dragged them
    svg: () => graphToSvg(placeNodes(graph, (id) => cy.getElementById(id).position()), graph.edges, colors, treeTitle(plan)),
    restyle: () => {
      colors = readColors(host);
      cy.style(stylesheet(colors));
    },
    destroy: () => {
      unsubscribe();
      resize.disconnect();
      cy.destroy();
    },
  };
}
