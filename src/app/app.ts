// One planner app instance: a store, the planner service (a Web Worker), the controllers that are the
// store's only writers, and the views chosen for this place (the full page, or a widget's subset). Data
// flows one way: query -> plan -> views.

import { describeError } from "../planner/errors";
import type { PlannerService } from "../worker/client";
import { DrawSchedule } from "./draw-schedule";
import { downloadPlan } from "./export/plan-export";
import { KbController } from "./kb-controller";
import type { KbPersistence } from "./kb-store";
import { mountLayout, type ViewName } from "./layout";
import { PlanController, type PlanEvents } from "./plan-controller";
import { toPlanRequest, type AppQuery } from "./query";
import { Store } from "./store";
import type { DownloadFormat } from "./views/export-panel";

export { ALL_VIEWS, type ViewName } from "./layout";

/** What the embedding page is told: each plan shown, each selection, each error. */
export type AppEvents = PlanEvents;

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

export function createPlannerApp(root: HTMLElement, options: AppOptions): PlannerApp {
  const store = new Store();
  const schedule = new DrawSchedule(store);
  const plans = new PlanController(store, options.planner, schedule, options.events);
  const kbs = new KbController(store, options.planner, plans, options);

  async function exportAs(format: DownloadFormat): Promise<void> {
    const plan = store.state.plan;
    if (plan === null) return;
    try {
      await downloadPlan(plan, toPlanRequest(store.state.query), format, layout.tree, (request, f) => options.planner.exportPlan(request, f));
    } catch (e) {
      store.set({ planError: `Export failed: ${describeError(plans.reportError(e))}` });
    }
  }

  root.classList.add("foon-app");
  const layout = mountLayout(root, options.views, store, schedule, {
    setQuery: (q) => plans.setQuery(q),
    select: (s) => plans.select(s),
    chooseSubstitute: (o, l) => plans.chooseSubstitute(o, l),
    wantTrace: (near) => plans.wantTrace(near),
    exportAs: (f) => void exportAs(f),
    loadFiles: (f) => void kbs.loadFiles(f),
    useBundled: () => void kbs.useBundled(),
    downloadFile: (i) => kbs.downloadFile(i),
  });

  if (options.query !== undefined) store.set({ query: options.query });
  void kbs.start();

  return {
    store,
    root,
    setQuery: (q) => plans.setQuery(q),
    loadKnowledgeBase: async (url) => {
      await kbs.loadUrl(url);
    },
    exportAs,
    restyle: () => layout.restyle(),
    destroy: () => {
      plans.destroyed = true;
      layout.destroy();
      options.planner.dispose();
      kbs.close();
    },
  };
}
