// One planner app instance: a store, the planner service (a Web Worker), and the views chosen for this
// place (the full page, or a widget's subset). Data flows one way: query -> plan -> views.

import type { ExportFormat, KnowledgeBaseFile, Plan } from "../planner/types";
import { describeError, PlannerError, toPlannerError } from "../planner/errors";
import type { PlannerService } from "../worker/client";
import { download, el, plural, watchNearScreen } from "./dom";
import { NO_SELECTION, type Selection } from "./model/tree";
import { isPlannable, toPlanRequest, type AppQuery } from "./query";
import { StaleSaveError, type KbPersistence, type SavedKnowledgeBase } from "./kb-store";
import { Store, type AppState } from "./store";
import { mountExportPanel, type DownloadFormat } from "./views/export-panel";
import { mountKnowledgeBasePanel } from "./views/kb-panel";
import { mountProgressView } from "./views/progress-view";
import { mountQueryEditor } from "./views/query-editor";
import { mountReferenceView } from "./views/reference-view";
import { mountStepsView } from "./views/steps-view";
import { mountSubstitutionsView } from "./views/substitutions-view";
import type { TreeViewHandle } from "./views/tree-view";
import type { ExplainViewHandle } from "./views/explain-view";

export type ViewName = "query" | "tree" | "progress" | "steps" | "substitutions" | "reference" | "explain" | "export" | "kb";
export const ALL_VIEWS: readonly ViewName[] = ["query", "tree", "progress", "steps", "substitutions", "reference", "explain", "export", "kb"];

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
  /** Where the user's own knowledge base is saved across reloads and shared with other tabs; none: memory only. */
  persistence?: Promise<KbPersistence>;
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

/** The Performance measure of the last plan: from its request to every view drawn. */
export const SHOWN_MEASURE = "foon:plan shown";
/** The part of it after the worker's answer: drawing the views (the rest is the worker's round trip). */
export const DRAWN_MEASURE = "foon:plan drawn";
/** Marked when the page's first plan is drawn (navigation start to first plan, for the e2e tests and bench). */
export const FIRST_PLAN_MARK = "foon:first-plan";

/** " Shown in 3.1 ms (planner 0.6 ms)." once both are known. */
function timing(state: AppState): string {
  if (state.shownMs === null || state.planMs === null) return "";
  return ` Shown in ${state.shownMs.toFixed(1)} ms (planner ${state.planMs.toFixed(1)} ms).`;
}

export function createPlannerApp(root: HTMLElement, options: AppOptions): PlannerApp {
  const store = new Store();
  const { planner, events } = options;
  const cleanups: (() => void)[] = [];
  let tree: TreeViewHandle | null = null;
  let explain: ExplainViewHandle | null = null;
  let kbUrl = options.kbUrl;
  let destroyed = false;
  /** The Algorithm view replays the plan's explain trace: asked for while the view is near the screen. */
  let explainNear = false;
  /** Whether the latest plan request asked for the trace. */
  let traceAsked = false;

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
    const requested = performance.now();
    store.set({ planning: true });
    try {
      traceAsked = explainNear;
      const result = await planner.plan({ ...toPlanRequest(query), explain: traceAsked });
      if (result === null || seq !== planSeq || destroyed) return; // a newer request replaced this one
      const answered = performance.now();
      const keep = store.state.selection.unit !== null && store.state.selection.unit < result.plan.units.length;
      store.set({ plan: result.plan, planMs: result.ms, shownMs: null, planning: false, planError: null, selection: keep ? store.state.selection : NO_SELECTION });
      // the views render synchronously in set(): request to views drawn, also on the Performance timeline
      performance.clearMeasures(SHOWN_MEASURE);
      performance.clearMeasures(DRAWN_MEASURE);
      performance.measure(DRAWN_MEASURE, { start: answered });
      store.set({ shownMs: performance.measure(SHOWN_MEASURE, { start: requested }).duration });
      if (performance.getEntriesByName(FIRST_PLAN_MARK).length === 0) performance.mark(FIRST_PLAN_MARK);
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

  let persistence: KbPersistence | null = null;
  /** The user's files in the planner now (null: the bundled knowledge base), kept for downloading. */
  let customFiles: KnowledgeBaseFile[] | null = null;
  let kbSeq = 0;

  async function loadKnowledgeBase(url: string, notice: string | null = null): Promise<boolean> {
    kbUrl = url;
    const seq = ++kbSeq;
    try {
      const kb = await planner.loadUrl(url, options.embeddingsUrl);
      if (seq !== kbSeq || destroyed) return false;
      customFiles = null;
      store.set({ kb, kbSource: "bundled", kbError: null, kbNotice: notice, kbUnsaved: null });
      await replan();
      return true;
    } catch (e) {
      store.set({ kbError: `Could not load ${url}: ${describeError(reportError(e))}` });
      return false;
    }
  }

  /** Loads files into the planner; false (and the previous knowledge base stays) when they do not load. */
  async function applyFiles(files: KnowledgeBaseFile[], notice: string | null): Promise<boolean> {
    const seq = ++kbSeq;
    try {
      const kb = await planner.loadFiles(files, options.embeddingsUrl);
      if (seq !== kbSeq || destroyed) return false;
      customFiles = files;
      store.set({ kb, kbSource: "custom", kbError: null, kbNotice: notice });
      await replan();
      return true;
    } catch (e) {
      store.set({ kbError: `Not loaded: ${describeError(reportError(e))}` });
      return false;
    }
  }

  const filesNotice = (n: number, what: string): string => `Your knowledge base (${plural(n, "file")}) ${what}`;

  /** Another tab saved a newer choice: load it here too. */
  async function applySaved(saved: SavedKnowledgeBase): Promise<void> {
    if (saved.files === null) await loadKnowledgeBase(options.kbUrl, "Another tab switched back to the bundled knowledge base; so did this one.");
    else if (await applyFiles(saved.files, filesNotice(saved.files.length, "was loaded in another tab; it is loaded here too."))) store.set({ kbUnsaved: null });
  }

  /** Writes the choice through to the browser's storage; when it cannot, the files stay in memory and the panel says so. */
  async function persist(files: KnowledgeBaseFile[] | null, savedAt: number): Promise<void> {
    if (persistence === null) return;
    try {
      await persistence.save(files, savedAt);
      if (!destroyed) store.set({ kbUnsaved: null });
    } catch (e) {
      if (destroyed) return;
      if (e instanceof StaleSaveError) {
        await applySaved(e.current);
        return;
      }
      const reason = e instanceof Error ? e.message : String(e);
      store.set({ kbUnsaved: files === null ? null : { reason, names: files.map((f) => f.name) } });
    }
  }

  async function loadFiles(files: File[]): Promise<void> {
    const savedAt = Date.now();
    const read = await readFiles(files);
    if (await applyFiles(read, null)) await persist(read, savedAt);
  }

  async function useBundled(): Promise<void> {
    const savedAt = Date.now();
    if (await loadKnowledgeBase(options.kbUrl)) await persist(null, savedAt);
  }

  function downloadFile(index: number): void {
    const file = customFiles?.[index];
    if (file !== undefined) download(file.name, new Blob([file.bytes as Uint8Array<ArrayBuffer>], { type: "text/plain" }));
  }

  /** On start: the user's saved knowledge base if there is one, else the bundled one. */
  async function start(): Promise<void> {
    if (options.persistence !== undefined) {
      persistence = await options.persistence;
      if (destroyed) return;
      cleanups.push(persistence.onRemoteChange((saved) => void applySaved(saved)));
      const saved = await persistence.restore().catch(() => null);
      if (saved !== null && (await applyFiles(saved, filesNotice(saved.length, "restored.")))) return;
    }
    await loadKnowledgeBase(kbUrl);
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
        // the plan as the CLI prints it: the Algorithm view's trace is not part of the task tree
        const { trace: _trace, ...exported } = plan;
        download(`${base}-plan.json`, `${JSON.stringify(exported, null, 2)}\n`, "application/json");
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
  if (has("explain")) {
    const host = section("explain");
    host.append(el("p", { class: "muted", text: "Loading the Algorithm view…" }));
    results.append(host);
    // far down the page once there is a plan: off screen, re-plans skip the trace and the view draws no steps;
    // scrolled to, it loads (the first time) and the plan is made again with the trace
    let loading = false;
    cleanups.push(
      watchNearScreen(host, (near) => {
        explainNear = near;
        if (!near) return;
        if (!loading) {
          loading = true;
          void import("./views/explain-view").then(({ mountExplainView }) => {
            if (!destroyed) explain = mountExplainView(host, store);
          });
        }
        if (!traceAsked) void replan();
      }),
    );
  }
  const tools = el("div", { class: "pair" });
  if (has("export")) {
    const host = section("export");
    tools.append(host);
    cleanups.push(mountExportPanel(host, store, { exportAs: (f) => void exportAs(f) }));
  }
  if (has("kb")) {
    const host = section("kb");
    tools.append(host);
    cleanups.push(mountKnowledgeBasePanel(host, store, { loadFiles: (f) => void loadFiles(f), useBundled: () => void useBundled(), downloadFile }, root));
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
              ? `Task tree for ${state.plan.query.type || "any dish"}: ${plural(state.plan.units.length, "functional unit")} from “${state.plan.goal.label}”.${timing(state)}`
              : "Add ingredients to plan a task tree.");
    }),
  );

  if (options.query !== undefined) store.set({ query: options.query });
  void start();

  return {
    store,
    root,
    setQuery,
    loadKnowledgeBase: async (url) => {
      await loadKnowledgeBase(url);
    },
    exportAs,
    restyle: () => {
      tree?.restyle();
      explain?.restyle();
    },
    destroy: () => {
      destroyed = true;
      for (const c of cleanups) c();
      tree?.destroy();
      explain?.destroy();
      planner.dispose();
      persistence?.close();
      root.replaceChildren();
    },
  };
}
