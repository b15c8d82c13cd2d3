// Where each view goes: the query editor beside the results (status line, task tree, progress lines,
// substitutions, steps and reference, the Algorithm view, export and knowledge-base tools), only the
// views chosen for this place. Views draw through the schedule (those off screen later); the task tree
// and the Algorithm view load their code on their own.

import { whenIdle, type DrawSchedule, type StateSource } from "./draw-schedule";
import { el, watchNearScreen } from "./dom";
import type { Selection } from "./model/tree";
import type { AppQuery } from "./query";
import type { Store } from "./store";
import type { ExplainViewHandle } from "./views/explain-view";
import { mountExportPanel, type DownloadFormat } from "./views/export-panel";
import { mountKnowledgeBasePanel } from "./views/kb-panel";
import { mountProgressView } from "./views/progress-view";
import { mountQueryEditor } from "./views/query-editor";
import { mountReferenceView } from "./views/reference-view";
import { mountStatusLine } from "./views/status-line";
import { mountStepsView } from "./views/steps-view";
import { mountSubstitutionsView } from "./views/substitutions-view";
import { mountTreePreview } from "./views/tree-preview";
import type { TreeViewHandle } from "./views/tree-view";

export type ViewName = "query" | "tree" | "progress" | "steps" | "substitutions" | "reference" | "explain" | "export" | "kb";
export const ALL_VIEWS: readonly ViewName[] = ["query", "tree", "progress", "steps", "substitutions", "reference", "explain", "export", "kb"];

/** What the views may ask for. */
export interface ViewActions {
  setQuery(query: AppQuery): void;
  select(selection: Selection): void;
  chooseSubstitute(object: string, label: string | null): void;
  /** The Algorithm view came near the screen or left it. */
  wantTrace(near: boolean): void;
  exportAs(format: DownloadFormat): void;
  loadFiles(files: File[]): void;
  useBundled(): void;
  downloadFile(index: number): void;
}

export interface Layout {
  /** The task tree view once its code is loaded. */
  readonly tree: TreeViewHandle | null;
  restyle(): void;
  destroy(): void;
}

/** A view's section, and the state as the schedule gives it to that view. */
interface Placed {
  host: HTMLElement;
  source: StateSource;
}

/** Mounted views: their cleanups, and the two whose code loads on its own once it has. */
class Mounted {
  readonly cleanups: (() => void)[] = [];
  tree: TreeViewHandle | null = null;
  explain: ExplainViewHandle | null = null;
  destroyed = false;
}

export function mountLayout(root: HTMLElement, views: readonly ViewName[], store: Store, schedule: DrawSchedule, actions: ViewActions): Layout {
  const mounted = new Mounted();
  const status = el("p", { class: "plan-status", role: "status", "aria-live": "polite" });
  const layout = el("div", { class: "layout" });
  const results = el("div", { class: "results" }, status);
  if (views.includes("query")) {
    const host = el("section", { class: "panel panel-query", "data-view": "query" });
    layout.append(host);
    mounted.cleanups.push(mountQueryEditor(host, store, { setQuery: (q) => actions.setQuery(q) }));
  }
  layout.append(results);
  root.replaceChildren(layout);
  const place = (name: ViewName, parent: HTMLElement): Placed | null => {
    if (!views.includes(name)) return null;
    const host = el("section", { class: `panel panel-${name}`, "data-view": name });
    parent.append(host);
    const source = schedule.source(name, host);
    mounted.cleanups.push(source.stop);
    return { host, source };
  };
  mountResults(results, place, mounted, actions, root);
  mounted.cleanups.push(mountStatusLine(status, store, schedule));

  return {
    get tree() {
      return mounted.tree;
    },
    restyle: () => {
      mounted.tree?.restyle();
      mounted.explain?.restyle();
    },
    destroy: () => {
      mounted.destroyed = true;
      for (const c of mounted.cleanups) c();
      mounted.tree?.destroy();
      mounted.explain?.destroy();
      root.replaceChildren();
    },
  };
}

/** The result views in page order; `place` gives the section of each view chosen for this place. */
function mountResults(results: HTMLElement, place: (name: ViewName, parent: HTMLElement) => Placed | null, mounted: Mounted, actions: ViewActions, root: HTMLElement): void {
  const select = (s: Selection): void => actions.select(s);
  const tree = place("tree", results);
  if (tree !== null) loadTreeView(tree, mounted, select);
  const progress = place("progress", results);
  if (progress !== null) mounted.cleanups.push(mountProgressView(progress.host, progress.source, { select }));
  const substitutions = place("substitutions", results);
  if (substitutions !== null) mounted.cleanups.push(mountSubstitutionsView(substitutions.host, substitutions.source, { chooseSubstitute: (o, l) => actions.chooseSubstitute(o, l) }));
  const pair = el("div", { class: "pair" });
  const steps = place("steps", pair);
  if (steps !== null) mounted.cleanups.push(mountStepsView(steps.host, steps.source, { select }));
  const reference = place("reference", pair);
  if (reference !== null) mounted.cleanups.push(mountReferenceView(reference.host, reference.source));
  if (pair.childElementCount > 0) results.append(pair);
  const explain = place("explain", results);
  if (explain !== null) loadExplainView(explain, mounted, actions);
  const tools = el("div", { class: "pair" });
  const exports = place("export", tools);
  if (exports !== null) mounted.cleanups.push(mountExportPanel(exports.host, exports.source, { exportAs: (f) => actions.exportAs(f) }));
  const kb = place("kb", tools);
  if (kb !== null) mounted.cleanups.push(mountKnowledgeBasePanel(kb.host, kb.source, actions, root));
  if (tools.childElementCount > 0) results.append(tools);
}

/**
 * Cytoscape is most of the page's script: the first plan is drawn as a still picture, and the interactive
 * view loads when the page is next idle after it (neither its download nor its first drawing delay the plan).
 */
function loadTreeView({ host, source }: Placed, mounted: Mounted, select: (s: Selection) => void): void {
  mountTreePreview(host, source, () =>
    whenIdle(() => {
      void import("./views/tree-view").then(({ mountTreeView }) => {
        if (!mounted.destroyed) mounted.tree = mountTreeView(host, source, { select });
      });
    }),
  );
}

/**
 * Far down the page once there is a plan: off screen, re-plans skip the trace and the view draws no steps;
 * scrolled to, it loads (the first time) and the plan is made again with the trace.
 */
function loadExplainView({ host, source }: Placed, mounted: Mounted, actions: ViewActions): void {
  host.append(el("p", { class: "muted", text: "Loading the Algorithm view…" }));
  // before the first plan the page is short and this view near the screen: where it is counts once the
  // plan is drawn above it (else the first plan would be made with the trace, and Cytoscape loaded for it)
  let watching = false;
  const watch = (): void => {
    if (watching || source.state.plan === null) return;
    watching = true;
    whenIdle(() => {
      if (mounted.destroyed) return;
      let loading = false;
      const stop = watchNearScreen(host, (near) => {
        if (near && !loading) {
          loading = true;
          void import("./views/explain-view").then(({ mountExplainView }) => {
            if (!mounted.destroyed) mounted.explain = mountExplainView(host, source);
          });
        }
        actions.wantTrace(near);
      });
      mounted.cleanups.push(stop);
    });
  };
  watch();
  source.subscribe(watch); // the view, once loaded, takes the subscription over
}
