// The planning actions: a query in, a plan (or its error) into the store, and how long the user waited
// for it. With the knowledge-base controller, the only writer of the store's plan and query.

import { describeError, toPlannerError, type PlannerError } from "../planner/errors";
import type { PlannerService } from "../worker/client";
import type { DrawSchedule } from "./draw-schedule";
import { NO_SELECTION, type Selection } from "./model/tree";
import { isPlannable, toPlanRequest, type AppQuery } from "./query";
import type { Store } from "./store";
import type { Plan } from "../planner/types";

/** The Performance measure of the last plan: from its request to every view on screen drawn. */
export const SHOWN_MEASURE = "foon:plan shown";
/** The part of it after the worker's answer: drawing the views (the rest is the worker's round trip). */
export const DRAWN_MEASURE = "foon:plan drawn";
/** Marked when the page's first plan is drawn (navigation start to first plan, for the e2e tests and bench). */
export const FIRST_PLAN_MARK = "foon:first-plan";

export interface PlanEvents {
  plan?(plan: Plan): void;
  select?(selection: Selection, plan: Plan | null): void;
  error?(error: PlannerError): void;
}

export class PlanController {
  private seq = 0;
  /** Whether the Algorithm view (which replays the plan's explain trace) is near the screen. */
  private traceWanted = false;
  /** Whether the latest plan request asked for the trace. */
  private traceAsked = false;
  destroyed = false;

  constructor(
    private readonly store: Store,
    private readonly planner: PlannerService,
    private readonly schedule: DrawSchedule,
    private readonly events: PlanEvents = {},
  ) {}

  /** Tells the embedding page, and gives the error back to show. */
  reportError(e: unknown): PlannerError {
    const error = toPlannerError(e);
    this.events.error?.(error);
    return error;
  }

  setQuery(query: AppQuery): void {
    this.store.set({ query });
    void this.replan();
  }

  select(selection: Selection): void {
    this.store.set({ selection });
    this.events.select?.(selection, this.store.state.plan);
  }

  /** `label` null: the planner chooses the equivalent of `object` again. */
  chooseSubstitute(object: string, label: string | null): void {
    const overrides = { ...this.store.state.query.overrides };
    if (label === null) delete overrides[object];
    else overrides[object] = label;
    this.setQuery({ ...this.store.state.query, overrides });
  }

  /** The trace is asked for only while its view is near the screen; coming near, the plan is made again with it. */
  wantTrace(near: boolean): void {
    this.traceWanted = near;
    if (near && !this.traceAsked) void this.replan();
  }

  async replan(): Promise<void> {
    const { store } = this;
    const query = store.state.query;
    if (store.state.kb === null) return;
    if (!isPlannable(query)) {
      store.set({ plan: null, planMs: null, planning: false, planError: null, selection: NO_SELECTION });
      return;
    }
    const seq = ++this.seq;
    const requested = performance.now();
    store.set({ planning: true });
    try {
      this.traceAsked = this.traceWanted;
      const result = await this.planner.plan({ ...toPlanRequest(query), explain: this.traceAsked });
      if (result === null || seq !== this.seq || this.destroyed) return; // a newer request replaced this one
      this.show(result.plan, result.ms, requested);
    } catch (e) {
      if (seq !== this.seq || this.destroyed) return;
      store.set({ plan: null, planning: false, planError: describeError(this.reportError(e)), selection: NO_SELECTION });
    }
  }

  /** Hands the plan to the views (those on screen draw it in `set`) and measures the wait on the Performance timeline. */
  private show(plan: Plan, ms: number, requested: number): void {
    const { store } = this;
    const answered = performance.now();
    const keep = store.state.selection.unit !== null && store.state.selection.unit < plan.units.length;
    this.schedule.drawTimes.clear();
    store.set({ plan, planMs: ms, shownMs: null, planning: false, planError: null, selection: keep ? store.state.selection : NO_SELECTION });
    performance.clearMeasures(SHOWN_MEASURE);
    performance.clearMeasures(DRAWN_MEASURE);
    // the detail: each view's drawing and the planner's time in the worker (npm run bench:browser prints them)
    performance.measure(DRAWN_MEASURE, { start: answered, detail: { views: Object.fromEntries(this.schedule.drawTimes), planner: ms } });
    store.set({ shownMs: performance.measure(SHOWN_MEASURE, { start: requested }).duration });
    if (performance.getEntriesByName(FIRST_PLAN_MARK).length === 0) performance.mark(FIRST_PLAN_MARK);
    this.events.plan?.(plan);
  }
}
