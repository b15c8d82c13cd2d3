// mount(element, options): a planner in any element, in its own shadow root (no CSS leaks either way),
// with its own worker; `update()` changes the query, view or theme, `destroy()` removes it all.

import { createPlannerApp, type PlannerApp } from "../app/app";
import type { Selection } from "../app/model/tree";
import { applyTheme } from "../app/theme";
import type { FoonErrorData, Plan, PlanUnit } from "../planner/types";
import { PagePlanner } from "../app/page-planner";
import { WorkerPlanner } from "../worker/client";
import css from "../app/style.css?inline";
import { WIDGET_VIEWS, widgetIngredients, type WidgetOptions } from "./options";

export type { WidgetOptions, WidgetView } from "./options";

export interface PlanEventDetail {
  plan: Plan;
}
export interface SelectEventDetail {
  selection: Selection;
  unit: PlanUnit | null;
  step: string | null;
}
export interface ErrorEventDetail {
  error: FoonErrorData;
}

export interface MountCallbacks {
  onPlan?(detail: PlanEventDetail): void;
  onSelect?(detail: SelectEventDetail): void;
  onError?(detail: ErrorEventDetail): void;
}

export interface PlannerHandle {
  update(options: Partial<WidgetOptions>): void;
  destroy(): void;
  /** The current plan, if any. */
  readonly plan: Plan | null;
}

const HOST_CSS = `:host { display: block; } :host([hidden]) { display: none; } .frame { border-radius: 8px; padding: 0.5rem; }`;
let sheet: CSSStyleSheet | null = null;
function styles(): CSSStyleSheet {
  if (sheet === null) {
    sheet = new CSSStyleSheet();
    sheet.replaceSync(`${HOST_CSS}\n${css}`);
  }
  return sheet;
}

// Both are found relative to this script's own URL, never the page's: Vite writes each file's path relative to
// the built chunk, so the widget finds them from any origin and sub-path it is loaded from.
/** The bundled knowledge base. */
export const DEFAULT_KB_URL = new URL("../../public/kb/default.foon", import.meta.url).href;
/** The bundled food embedding table (substitutes by meaning). */
export const DEFAULT_EMBEDDINGS_URL = new URL("../../public/data/food-embeddings.bin", import.meta.url).href;

export function mount(element: HTMLElement, initial: WidgetOptions = {}, callbacks: MountCallbacks = {}): PlannerHandle {
  const shadow = element.shadowRoot ?? element.attachShadow({ mode: "open" });
  shadow.adoptedStyleSheets = [styles()];
  const frame = document.createElement("div");
  frame.className = "fp-theme frame";
  const appRoot = document.createElement("div");
  frame.append(appRoot);
  shadow.replaceChildren(frame);

  let options: WidgetOptions = { ...initial };
  let app: PlannerApp | null = null;
  let stopTheme: () => void = () => undefined;
  let stopKbWatch: () => void = () => undefined;

  const kbUrl = (): string => new URL(options.kbUrl ?? DEFAULT_KB_URL, document.baseURI).href;
  const applyQuery = (): void => {
    if (app === null) return;
    const states = app.store.state.kb?.vocabulary.states ?? [];
    const mode = options.mode === undefined ? {} : { mode: options.mode };
    app.setQuery({ dish: options.dishType ?? "", ingredients: widgetIngredients(options.ingredients, states), overrides: {}, ...mode });
  };

  function build(): void {
    stopKbWatch();
    app?.destroy();
    app = createPlannerApp(appRoot, {
      planner: new PagePlanner(new WorkerPlanner()),
      kbUrl: kbUrl(),
      embeddingsUrl: DEFAULT_EMBEDDINGS_URL,
      views: WIDGET_VIEWS[options.view ?? "all"],
      events: {
        plan: (plan) => callbacks.onPlan?.({ plan }),
        select: (selection, plan) => {
          const unit = selection.unit === null || plan === null ? null : (plan.units[selection.unit] ?? null);
          const step = selection.unit === null || plan === null ? null : (plan.steps[selection.unit] ?? null);
          callbacks.onSelect?.({ selection, unit, step });
        },
        error: (error) => callbacks.onError?.({ error: error.toJSON() }),
      },
    });
    // the ingredient phrases are split with the knowledge base's states: (re)apply once it is loaded
    const store = app.store;
    stopKbWatch = store.subscribe((state, previous) => {
      if (state.kb !== null && state.kb !== previous.kb) applyQuery();
    });
  }

  function theme(): void {
    stopTheme();
    stopTheme = applyTheme(frame, options.theme ?? "system", () => app?.restyle());
  }

  build();
  theme();

  return {
    update(next: Partial<WidgetOptions>): void {
      const previous = options;
      options = { ...options, ...next };
      if (options.view !== previous.view || options.kbUrl !== previous.kbUrl) build();
      else if (options.dishType !== previous.dishType || options.ingredients !== previous.ingredients || options.mode !== previous.mode) applyQuery();
      if (options.theme !== previous.theme) theme();
    },
    destroy(): void {
      stopKbWatch();
      stopTheme();
      app?.destroy();
      app = null;
      shadow.replaceChildren();
    },
    get plan(): Plan | null {
      return app?.store.state.plan ?? null;
    },
  };
}
