// One planner app instance: a store, the planner service (a Web Worker), and the views chosen for this
// place (the full page, or a widget's subset). Data flows one way: query -> plan -> views.

import type { ExportFormat, KnowledgeBaseFile, Plan } from "../planner/types";
import { describeError, PlannerError, toPlannerError } from "../planner/errors";
import type { PlannerService } from "../worker/client";
import { download, el, plural } from "./dom";
import { NO_SELECTION, type Selection } from "./model/tree";
import { isPlannable, toPlanRequest, type AppQuery } from "./query";
import { Store } from "./store";
import { mountExportPanel, type DownloadFormat } from "./views/export-panel";
import { mountKnowledgeBasePanel } from "./views/kb-panel";
import { mountProgressView } from "./views/progress-view";
import { mountQueryEditor } from "./views/query-editor";
import { mountReferenceView } from "./views/reference-view";
import { mountStepsView } from "./views/steps-view";
import { mountSubstitutionsView } from "./views/substitutions-view";
import type { TreeViewHandle } from "./views/tree-view";

export type ViewName = "query" | "tree" | "progress" | "steps" | "substitutions" | "reference" | "export" | "kb";
export const ALL_VIEWS: readonly ViewName[] = ["query", "tree", "progress", "steps", "substitutions", "reference", "export", "kb"];

export interface AppEvents {
  plan?(plan: Plan): void;
  select?(selection: Selection, plan: Plan | null): void;
  error?(error: PlannerError): void;
}

export interface AppOptions {
  planner: PlannerService;
  /** Absolute URL of the bundled (or the embedding page's) knowledge base. */
  kbUrl: string;
  /** Absolute URL of the food embedding table (substitutes by meaning); none: exact names only. */
  embeddingsUrl?: string;
  views: readonly ViewName[];
  query?: AppQuery;
  events?: AppEvents;
}

export interface PlannerApp {
  readonly store: Store;
  readonly root: HTMLElement;
  setQuery(query: AppQuery): void;
  loadKnowledgeBase(url: string): Promise<void>;
  exportAs(format: DownloadFormat): Promise<void>;
  restyle(): void;
  destroy(): void;
}

function slug(text: string): string {
  return text.toLowerCase().replace(/[^a-z0-9]+/g, "-").replace(/^-|-$/g, "") || "plan";
}

async function readFiles(files: File[]): Promise<KnowledgeBaseFile[]> {
  return Promise.all(files.map(async (f) => ({ name: f.name, bytes: new Uint8Array(await f.arrayBuffer()) })));
}

export function createPlannerApp(root: HTMLElement, options: AppOptions): PlannerApp {
  const store = new Store();
  const { planner, events } = options;
  const cleanups: (() => void)[] = [];
  let tree: TreeViewHandle | null = null;
  let kbUrl = options.kbUrl;
  let destroyed = false;

  root.classList.add("foon-app");
  const status = el("p", { class: "plan-status", role: "status", "aria-live": "polite" });
  const has = (v: ViewName): boolean => options.views.includes(v);
  const section = (name: ViewName): HTMLElement => el("section", { class: `panel panel-${name}`, "data-view": name });

  const reportError = (e: unknown): PlannerError => {
    const error = toPlannerError(e);
    events?.error?.(error);
    return error;
  };

  // ---- actions (the only writers of the store) ----

  let planSeq = 0;
  async function replan(): Promise<void> {
    const query = store.state.query;
    if (store.state.kb === null) return;
    if (!isPlannable(query)) {
      store.set({ plan: null, planMs: null, planning: false, planError: null, selection: NO_SELECTION });
      return;
    }
    const seq = ++planSeq;
    store.set({ planning: true });
    try {
      const result = await planner.plan(toPlanRequest(query));
      if (result === null || seq !== planSeq || destroyed) return; // a newer request replaced this one
      const keep = store.state.selection.unit !== null && store.state.selection.unit < result.plan.units.length;
      store.set({ plan: result.plan, planMs: result.ms, planning: false, planError: null, selection: keep ? store.state.selection : NO_SELECTION });
      events?.plan?.(result.plan);
    } catch (e) {
      if (seq !== planSeq || destroyed) return;
      const error = reportError(e);
      store.set({ plan: null, planning: false, planError: describeError(error), selection: NO_SELECTION });
    }
  }

  const setQuery = (query: AppQuery): void => {
    store.set({ query });
    void replan();
  };
  const select = (selection: Selection): void => {
    store.set({ selection });
    events?.select?.(selection, store.state.plan);
  };
  const chooseSubstitute = (object: string, label: string | null): void => {
    const overrides = { ...store.state.query.overrides };
    if (label === null) delete overrides[object];
    else overrides[object] = label;
    setQuery({ ...store.state.query, overrides });
  };

  async function loadKnowledgeBase(url: string): Promise<void> {
    kbUrl = url;
    try {
      const kb = await planner.loadUrl(url, options.embeddingsUrl);
      store.set({ kb, kbSource: "bundled", kbError: null });
      await replan();
    } catch (e) {
      store.set({ kbError: `Could not load ${url}: ${describeError(reportError(e))}` });
    }
  }

  async function loadFiles(files: File[]): Promise<void> {
    try {
      const kb = await planner.loadFiles(await readFiles(files), options.embeddingsUrl);
      store.set({ kb, kbSource: "custom", kbError: null });
      await replan();
    } catch (e) {
      // the previous knowledge base stays loaded
      store.set({ kbError: `Not loaded: ${describeError(reportError(e))}` });
    }
  }

  async function exportAs(format: DownloadFormat): Promise<void> {
    const plan = store.state.plan;
    if (plan === null) return;
    const base = slug(`${plan.query.type || "any"}-${plan.goal.label}`);
    try {
      if (format === "png") {
        if (tree !== null) download(`${base}-task-tree.png`, await tree.png());
        return;
      }
      if (format === "svg") {
        if (tree !== null) download(`${base}-task-tree.svg`, tree.svg(), "image/svg+xml");
        return;
      }
      if (format === "json") {
        download(`${base}-plan.json`, `${JSON.stringify(plan, null, 2)}\n`, "application/json");
        return;
      }
      const names: Record<Exclude<ExportFormat, "json">, [string, string]> = {
        foon: [`${base}-task-tree.txt`, "text/plain"],
        pddl: [`${base}-task-tree.pddl`, "text/plain"],
        "pddl-domain": [`${base}-domain.pddl`, "text/plain"],
        "pddl-problem": [`${base}-problem.pddl`, "text/plain"],
        progress: [`${base}-progress-lines.json`, "application/json"],
      };
      const text = await planner.exportPlan(toPlanRequest(store.state.query), format);
      const [name, type] = names[format];
      download(name, text, type);
    } catch (e) {
      store.set({ planError: `Export failed: ${describeError(reportError(e))}` });
    }
  }

  // ---- views ----

  const layout = el("div", { class: "layout" });
  const results = el("div", { class: "results" }, status);
  if (has("query")) {
    const host = section("query");
    layout.append(host);
    cleanups.push(mountQueryEditor(host, store, { setQuery }));
  }
  layout.append(results);
  root.replaceChildren(layout);
  if (has("tree")) {
    const host = section("tree");
    host.append(el("p", { class: "muted", text: "Loading the graph view…" }));
    results.append(host);
    // Cytoscape is most of the page's script: loaded in parallel with the planner, not before it
    void import("./views/tree-view").then(({ mountTreeView }) => {
      if (!destroyed) tree = mountTreeView(host, store, { select });
    });
  }
  if (has("progress")) {
    const host = section("progress");
    results.append(host);
    cleanups.push(mountProgressView(host, store, { select }));
  }
  if (has("substitutions")) {
    const host = section("substitutions");
    results.append(host);
    cleanups.push(mountSubstitutionsView(host, store, { chooseSubstitute }));
  }
  const pair = el("div", { class: "pair" });
  if (has("steps")) {
    const host = section("steps");
    pair.append(host);
    cleanups.push(mountStepsView(host, store, { select }));
  }
  if (has("reference")) {
    const host = section("reference");
    pair.append(host);
    cleanups.push(mountReferenceView(host, store));
  }
  if (pair.childElementCount > 0) results.append(pair);
  const tools = el("div", { class: "pair" });
  if (has("export")) {
    const host = section("export");
    tools.append(host);
    cleanups.push(mountExportPanel(host, store, { exportAs: (f) => void exportAs(f) }));
  }
  if (has("kb")) {
    const host = section("kb");
    tools.append(host);
    cleanups.push(mountKnowledgeBasePanel(host, store, { loadFiles: (f) => void loadFiles(f), useBundled: () => void loadKnowledgeBase(options.kbUrl) }, root));
  }
  if (tools.childElementCount > 0) results.append(tools);

  cleanups.push(
    store.subscribe((state) => {
      status.dataset.state = state.planError !== null ? "error" : state.planning ? "planning" : state.plan !== null ? "ready" : state.kb === null ? "loading" : "idle";
      status.textContent =
        state.planError ??
        (state.kb === null
          ? "Loading the planner and the knowledge base…"
          : state.planning
            ? "Planning…"
            : state.plan !== null
              ? `Task tree for ${state.plan.query.type || "any dish"}: ${plural(state.plan.units.length, "functional unit")} from “${state.plan.goal.label}”.`
              : "Add ingredients to plan a task tree.");
    }),
  );

  if (options.query !== undefined) store.set({ query: options.query });
  void loadKnowledgeBase(kbUrl);

  return {
    store,
    root,
    setQuery,
    loadKnowledgeBase,
    exportAs,
    restyle: () => tree?.restyle(),
    destroy: () => {
      destroyed = true;
      for (const c of cleanups) c();
      tree?.destroy();
      planner.dispose();
      root.replaceChildren();
    },
  };
}
