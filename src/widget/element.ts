// <foon-planner dish-type="salad" ingredients="chopped chili pepper, whole tomato" view="all"
//               theme="light" kb-url="kb/default.foon" mode="most_reliable">
// Emits `plan`, `select` and `error` CustomEvents (bubbling, composed) with typed details.

import { mount, type ErrorEventDetail, type PlanEventDetail, type PlannerHandle, type SelectEventDetail } from "./mount";
import { parseMode } from "../app/query";
import { parseTheme, parseView, type WidgetOptions } from "./options";

const ATTRIBUTES = ["dish-type", "ingredients", "view", "theme", "kb-url", "mode"] as const;

export class FoonPlannerElement extends HTMLElement {
  static readonly observedAttributes: readonly string[] = ATTRIBUTES;
  private handle: PlannerHandle | null = null;

  private options(): WidgetOptions {
    return {
      dishType: this.getAttribute("dish-type") ?? "",
      ingredients: this.getAttribute("ingredients") ?? "",
      view: parseView(this.getAttribute("view")),
      theme: parseTheme(this.getAttribute("theme")),
      kbUrl: this.getAttribute("kb-url") ?? undefined,
      mode: parseMode(this.getAttribute("mode")),
    };
  }

  connectedCallback(): void {
    if (this.handle !== null) return;
    const emit = <T>(type: string, detail: T): void => {
      this.dispatchEvent(new CustomEvent<T>(type, { detail, bubbles: true, composed: true }));
    };
    this.handle = mount(this, this.options(), {
      onPlan: (detail) => emit<PlanEventDetail>("plan", detail),
      onSelect: (detail) => emit<SelectEventDetail>("select", detail),
      onError: (detail) => emit<ErrorEventDetail>("error", detail),
    });
  }

  disconnectedCallback(): void {
    this.handle?.destroy();
    this.handle = null;
  }

  attributeChangedCallback(): void {
    this.handle?.update(this.options());
  }

  /** The current plan, if any. */
  get plan(): PlannerHandle["plan"] {
    return this.handle?.plan ?? null;
  }
}

export function defineFoonPlanner(name = "foon-planner"): void {
  if (customElements.get(name) === undefined) customElements.define(name, FoonPlannerElement);
}

/** The widget's own events, typed for `addEventListener` on a `<foon-planner>`. */
export interface FoonPlannerEventMap {
  plan: CustomEvent<PlanEventDetail>;
  select: CustomEvent<SelectEventDetail>;
  error: CustomEvent<ErrorEventDetail>;
}

// Declaration merging adds typed overloads for the widget's events; other events keep the DOM's types.
export interface FoonPlannerElement {
  addEventListener<K extends keyof FoonPlannerEventMap>(
    type: K,
    listener: (this: FoonPlannerElement, event: FoonPlannerEventMap[K]) => void,
    options?: boolean | AddEventListenerOptions,
  ): void;
  addEventListener(type: string, listener: EventListenerOrEventListenerObject, options?: boolean | AddEventListenerOptions): void;
  removeEventListener<K extends keyof FoonPlannerEventMap>(
    type: K,
    listener: (this: FoonPlannerElement, event: FoonPlannerEventMap[K]) => void,
    options?: boolean | EventListenerOptions,
  ): void;
  removeEventListener(type: string, listener: EventListenerOrEventListenerObject, options?: boolean | EventListenerOptions): void;
}

declare global {
  interface HTMLElementTagNameMap {
    "foon-planner": FoonPlannerElement;
  }
}
