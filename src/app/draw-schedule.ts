// When each view draws a new plan. A view on screen draws it at once (the plan is "shown" when every such
// view has drawn it); a view off screen draws it when the page is idle after that, or as soon as it
// comes into view, whichever is first. So the page paints the views the user sees without waiting for the
// rest, and everything is drawn before the status line says "ready". Other changes (a selection) reach
// every view at once: they are cheap, and the views stay in step with each other.

import { watchNearScreen } from "./dom";
import type { AppState, Listener, Store } from "./store";

/** What a view reads: the state, and its changes as the schedule delivers them. */
export interface StateSource {
  readonly state: AppState;
  subscribe(listener: Listener): () => void;
}

/** Runs `work` once the page is idle (at most `timeout` ms later), else soon. */
export function whenIdle(work: () => void, timeout = 200): void {
  if (typeof requestIdleCallback === "function") requestIdleCallback(work, { timeout });
  else setTimeout(work, 0);
}

export class DrawSchedule {
  private readonly late = new Set<() => void>();
  private readonly settledListeners = new Set<() => void>();
  /** Milliseconds each view took to draw the latest plan it drew on screen (the bench prints them). */
  readonly drawTimes = new Map<string, number>();

  constructor(private readonly store: Store) {}

  /** Whether every view has drawn the latest state. */
  get settled(): boolean {
    return this.late.size === 0;
  }

  /** Told each time the views that drew later have all drawn. */
  onSettled(listener: () => void): () => void {
    this.settledListeners.add(listener);
    return () => this.settledListeners.delete(listener);
  }

  /** The state as view `name`, mounted in `host`, should see it. */
  source(name: string, host: Element): StateSource & { stop(): void } {
    let listener: Listener | null = null;
    let drawn = this.store.state;
    const draw = (): void => {
      const state = this.store.state;
      const previous = drawn;
      drawn = state;
      const started = performance.now();
      listener?.(state, previous);
      if (state.plan !== previous.plan) this.drawTimes.set(name, performance.now() - started);
    };
    let visible = true; // until the first report: a view never misses a plan it should have drawn
    const stopWatching = watchNearScreen(
      host,
      (near) => {
        visible = near;
        if (near) this.drawNow(draw);
      },
      "0px",
    );
    const unsubscribe = this.store.subscribe((state) => {
      if (this.late.has(draw)) return; // it draws later, the state of then
      if (visible || state.plan === drawn.plan) draw();
      else this.drawLater(draw);
    });
    return {
      get state() {
        return drawn;
      },
      subscribe: (l) => {
        listener = l;
        return () => (listener = null);
      },
      stop: () => {
        unsubscribe();
        stopWatching();
        this.late.delete(draw);
      },
    };
  }

  private drawLater(draw: () => void): void {
    if (this.late.size === 0) whenIdle(() => this.flush());
    this.late.add(draw);
  }

  private drawNow(draw: () => void): void {
    if (!this.late.delete(draw)) return;
    draw();
    if (this.late.size === 0) for (const l of this.settledListeners) l();
  }

  private flush(): void {
    for (const draw of [...this.late]) this.drawNow(draw);
  }
}
