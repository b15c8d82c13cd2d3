// When views draw: on screen at once, off screen when the page is idle or when they come into view, and
// the status line's "ready" only once every view has drawn the plan.
import { afterEach, beforeEach, describe, expect, it, vi } from "vitest";
import { DrawSchedule } from "../../src/app/draw-schedule";
import { NO_SELECTION } from "../../src/app/model/tree";
import { Store, type AppState } from "../../src/app/store";
import { fixturePlan } from "./app-fixtures";

/** A stand-in IntersectionObserver: the test says when an element is on screen. */
class FakeObserver {
  static all: FakeObserver[] = [];
  constructor(private readonly report: (entries: { isIntersecting: boolean }[]) => void) {
    FakeObserver.all.push(this);
  }
  observe(): void {}
  disconnect(): void {}
  show(onScreen: boolean): void {
    this.report([{ isIntersecting: onScreen }]);
  }
}

let idle: (() => void)[] = [];
beforeEach(() => {
  FakeObserver.all = [];
  idle = [];
  vi.stubGlobal("IntersectionObserver", FakeObserver);
  vi.stubGlobal("requestIdleCallback", (work: () => void) => idle.push(work));
});
afterEach(() => vi.unstubAllGlobals());

const runIdle = (): void => idle.splice(0).forEach((work) => work());

function setup(): { store: Store; schedule: DrawSchedule; seen: AppState[] } {
  const store = new Store();
  const schedule = new DrawSchedule(store);
  const source = schedule.source("steps", {} as Element);
  const seen: AppState[] = [];
  source.subscribe((state) => seen.push(state));
  return { store, schedule, seen };
}

describe("draw schedule", () => {
  it("draws a plan at once in a view on screen", () => {
    const { store, schedule, seen } = setup();
    FakeObserver.all[0]!.show(true);
    store.set({ plan: fixturePlan() });
    expect(seen.map((s) => s.plan)).toEqual([store.state.plan]);
    expect(schedule.settled).toBe(true);
    expect(schedule.drawTimes.has("steps")).toBe(true);
  });

  it("draws a plan in a view off screen when the page is idle, then says it has settled", () => {
    const { store, schedule, seen } = setup();
    const settled = vi.fn();
    schedule.onSettled(settled);
    FakeObserver.all[0]!.show(false);
    store.set({ plan: fixturePlan() });
    store.set({ shownMs: 3 }); // later changes wait with it: the view draws the state of then, once
    expect(seen).toEqual([]);
    expect(schedule.settled).toBe(false);
    runIdle();
    expect(seen).toHaveLength(1);
    expect(seen[0]!.shownMs).toBe(3);
    expect(schedule.settled).toBe(true);
    expect(settled).toHaveBeenCalledTimes(1);
  });

  it("draws a waiting plan as soon as the view comes into view", () => {
    const { store, schedule, seen } = setup();
    FakeObserver.all[0]!.show(false);
    store.set({ plan: fixturePlan() });
    FakeObserver.all[0]!.show(true);
    expect(seen).toHaveLength(1);
    expect(schedule.settled).toBe(true);
    runIdle(); // nothing left to draw
    expect(seen).toHaveLength(1);
  });

  it("gives other changes (a selection) to a view off screen at once", () => {
    const { store, seen } = setup();
    FakeObserver.all[0]!.show(false);
    store.set({ selection: { ...NO_SELECTION, unit: 1 } });
    expect(seen.map((s) => s.selection.unit)).toEqual([1]);
  });
});
