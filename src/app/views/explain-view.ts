// The Algorithm view: a step-through of how the planner found the task tree (the plan's explain trace,
// `model/explain.ts`): previous / next / play, and the arrow keys, Home and End. The graph grows as the
// search proceeds (the node being expanded and the queue highlighted), modification is replayed
// ingredient by ingredient, then pruning, and the last step shows the final task tree.

import cytoscape, { type Core, type StylesheetJson } from "cytoscape";
import type { Plan } from "../../planner/types";
import { el } from "../dom";
import { explainSteps, type ExplainStep } from "../model/explain";
import type { StateSource } from "../draw-schedule";
import type { AppState } from "../store";
import { readColors, type GraphColors } from "../theme-colors";
import { showGraph, stylesheet } from "./tree-view";

/** The paper (its sections are named in each step's link). */
const PAPER_URL = "https://scholar.google.com/scholar?q=%22Approximate+Task+Tree+Retrieval+in+a+Knowledge+Network+for+Robotic+Cooking%22";
const PLAY_MS = 1500;

export interface ExplainViewHandle {
  restyle(): void;
  destroy(): void;
}

function explainStyles(c: GraphColors): StylesheetJson {
  return [
    ...stylesheet(c),
    { selector: "node.frontier", style: { "border-width": 3, "border-style": "dotted", "border-color": c.line } },
    { selector: "node.focus", style: { "overlay-color": c.select, "overlay-opacity": 0.45, "overlay-padding": 8 } },
  ];
}

function rowList(step: ExplainStep): HTMLElement {
  const list = el("ol", { class: "explain-rows", "aria-label": "What competed at this step" });
  for (const r of step.rows) list.append(el("li", { class: r.chosen ? "chosen" : "" }, el("span", { text: r.text }), " ", el("span", { class: "muted small", text: r.value })));
  return list;
}

export function mountExplainView(host: HTMLElement, store: StateSource): ExplainViewHandle {
  const prev = el("button", { type: "button", text: "◀ Previous", "aria-label": "Previous step" });
  const play = el("button", { type: "button", text: "▶ Play", "aria-pressed": "false" });
  const next = el("button", { type: "button", text: "Next ▶", "aria-label": "Next step" });
  const counter = el("span", { class: "muted small explain-counter" });
  const caption = el("p", { class: "explain-caption", "aria-live": "polite" });
  const section = el("a", { class: "small", href: PAPER_URL, target: "_blank", rel: "noopener" });
  // not `.cy`: the task-tree view's canvas is the one that name finds
  const canvas = el("div", { class: "explain-graph", role: "img", "aria-label": "The task tree as the planner builds it" });
  const rows = el("div", { class: "explain-details" });
  // what is said of a step scrolls in a box of its own: the view keeps one height whatever the step says
  const notes = el("div", { class: "explain-notes", role: "group", tabindex: 0, "aria-label": "This step" }, caption, el("p", { class: "muted small" }, "In the paper: ", section), rows);
  host.tabIndex = 0;
  host.setAttribute("aria-label", "Algorithm: step through how the planner found the task tree (arrow keys, Home, End, space to play)");
  host.replaceChildren(
    el("div", { class: "view-head" }, el("h2", { text: "Algorithm" }), el("div", { class: "toolbar wrap", role: "toolbar", "aria-label": "Steps" }, prev, play, next, counter)),
    canvas,
    notes,
  );

  let colors = readColors(host);
  const cy: Core = cytoscape({ container: canvas, style: explainStyles(colors), minZoom: 0.1, maxZoom: 4, autounselectify: true, boxSelectionEnabled: false });
  let steps: ExplainStep[] = [];
  let at = 0;
  let timer: ReturnType<typeof setInterval> | null = null;

  const fit = (): void => {
    cy.fit(undefined, 20);
    if (cy.zoom() > 1.5) {
      cy.zoom(1.5);
      cy.center();
    }
  };

  function show(index: number): void {
    at = Math.max(0, Math.min(index, steps.length - 1));
    const step = steps[at];
    prev.disabled = at === 0;
    next.disabled = at >= steps.length - 1;
    play.disabled = steps.length < 2;
    if (step === undefined) return;
    host.dataset.step = String(at);
    host.dataset.phase = step.phase;
    counter.textContent = `Step ${at + 1} of ${steps.length}`;
    caption.textContent = step.caption;
    section.textContent = step.section;
    showGraph(cy, step.graph);
    cy.batch(() => {
      cy.elements().removeClass("frontier focus"); // kept elements still carry the previous step's
      for (const id of step.frontier) cy.getElementById(id).addClass("frontier");
      for (const id of step.focus) cy.getElementById(id).addClass("focus");
    });
    fit();
    canvas.dataset.nodes = String(step.graph.nodes.length);
    canvas.dataset.edges = String(step.graph.edges.length);
    rows.replaceChildren(...(step.rows.length === 0 ? [] : [rowList(step)]));
    notes.scrollTop = 0;
    if (at >= steps.length - 1) stop();
  }

  function stop(): void {
    if (timer !== null) clearInterval(timer);
    timer = null;
    play.textContent = "▶ Play";
    play.setAttribute("aria-pressed", "false");
  }

  function togglePlay(): void {
    if (timer !== null) return stop();
    if (at >= steps.length - 1) show(0);
    timer = setInterval(() => show(at + 1), PLAY_MS);
    play.textContent = "❚❚ Pause";
    play.setAttribute("aria-pressed", "true");
  }

  function render(plan: Plan | null): void {
    stop();
    steps = plan === null ? [] : (explainSteps(plan) ?? []);
    host.dataset.steps = String(steps.length);
    if (steps.length === 0) {
      delete host.dataset.step;
      delete host.dataset.phase;
      cy.elements().remove();
      counter.textContent = "";
      caption.textContent = plan === null ? "The planner's steps appear here once there is a plan." : "This plan has no trace.";
      section.textContent = "";
      rows.replaceChildren();
      prev.disabled = next.disabled = play.disabled = true;
      return;
    }
    show(0);
  }

  prev.addEventListener("click", () => show(at - 1));
  next.addEventListener("click", () => show(at + 1));
  play.addEventListener("click", togglePlay);
  const keys: Record<string, () => void> = {
    ArrowRight: () => show(at + 1),
    ArrowDown: () => show(at + 1),
    ArrowLeft: () => show(at - 1),
    ArrowUp: () => show(at - 1),
    Home: () => show(0),
    End: () => show(steps.length - 1),
    " ": togglePlay,
  };
  host.addEventListener("keydown", (event) => {
    const action = keys[event.key];
    // keys typed into the buttons' own handling (space on a focused button clicks it) stay theirs, and up and
    // down in the notes scroll them
    const own = event.key === " " ? event.target instanceof HTMLButtonElement : (event.key === "ArrowUp" || event.key === "ArrowDown") && event.target === notes;
    if (action === undefined || steps.length === 0 || own) return;
    event.preventDefault();
    action();
  });

  const update = (state: AppState, previous: AppState | null): void => {
    if (previous === null || state.plan !== previous.plan) render(state.plan);
  };
  update(store.state, null);
  const unsubscribe = store.subscribe(update);
  const resize = new ResizeObserver(() => {
    cy.resize();
    fit();
  });
  resize.observe(canvas);

  return {
    restyle: () => {
      colors = readColors(host);
      cy.style(explainStyles(colors));
    },
    destroy: () => {
      stop();
      unsubscribe();
      resize.disconnect();
      cy.destroy();
    },
  };
}
