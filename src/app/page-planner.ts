// The planner as the page uses it: the worker loads each knowledge base and makes the first plan (the page
// stays free while the module compiles and the files load), then, once the page is idle after that plan, a
// copy of the planner on the page's own thread makes the re-plans. A re-plan through the worker waits for
// the browser to render the edit's frame before the answer is handled (5-15 ms on a loaded 2-core VM);
// planned here, the plan is drawn in the same task as the edit. The copy instantiates the worker's compiled
// module (no second compile: the code is shared) and loads the worker's snapshot of the parsed knowledge base
// (else the same files); a knowledge base too large to load here without blocking the page stays in the
// worker only.

import { toPlannerError } from "../planner/errors";
import type { FoonPlanner } from "../planner/index";
import type { ExportFormat, KnowledgeBaseFile, Plan, PlanRequest } from "../planner/types";
import type { PlannerService, WorkerPlanner } from "../worker/client";
import type { LoadedKnowledgeBase, PlannerCopy } from "../worker/protocol";
import { whenIdle } from "./draw-schedule";

/** The Performance measure of the copy's load on the page's thread (the bench prints it). */
export const COPY_MEASURE = "foon:page copy load";

/** The worker's side of it: a planner service that can hand over its module and files. */
export type CopyablePlanner = PlannerService & Pick<WorkerPlanner, "copy">;

export class PagePlanner implements PlannerService {
  private local: FoonPlanner | null = null;
  /** Bumped by each load: a copy made of an older knowledge base is dropped. */
  private generation = 0;
  private copying: Promise<void> | null = null;
  /** The copy failed once (a trap, an error the worker did not give): the worker plans from then on. */
  private failed = false;

  constructor(private readonly worker: CopyablePlanner) {}

  /** Whether re-plans run on the page's thread now. */
  get onPage(): boolean {
    return this.local !== null;
  }

  /** Settles when the copy started after the last plan is made (or given up); tests await it. */
  copied(): Promise<void> {
    return this.copying ?? Promise.resolve();
  }

  loadUrl(url: string, embeddingsUrl?: string): Promise<LoadedKnowledgeBase> {
    this.dropCopy();
    return this.worker.loadUrl(url, embeddingsUrl);
  }

  prefetch(url: string, embeddingsUrl?: string): void {
    this.worker.prefetch(url, embeddingsUrl);
  }

  loadFiles(files: KnowledgeBaseFile[], embeddingsUrl?: string): Promise<LoadedKnowledgeBase> {
    this.dropCopy();
    return this.worker.loadFiles(files, embeddingsUrl);
  }

  async plan(request: PlanRequest): Promise<{ plan: Plan; ms: number } | null> {
    const local = this.local;
    if (local !== null) {
      const started = performance.now();
      try {
        return { plan: local.plan(request), ms: performance.now() - started };
      } catch (e) {
        // a bad request is the caller's; anything else (a trap) leaves the copy's state unknown: the worker takes over
        const error = toPlannerError(e);
        if (error.code !== "internal") throw error;
        this.local = null;
        this.failed = true;
      }
    }
    const result = await this.worker.plan(request);
    if (result !== null) this.copyWhenIdle();
    return result;
  }

  exportPlan(request: PlanRequest, format: ExportFormat): Promise<string> {
    return this.worker.exportPlan(request, format);
  }

  dispose(): void {
    this.dropCopy();
    this.worker.dispose();
  }

  private dropCopy(): void {
    this.generation++;
    this.local?.free();
    this.local = null;
    this.copying = null;
  }

  private copyWhenIdle(): void {
    if (this.local !== null || this.copying !== null || this.failed) return;
    const generation = this.generation;
    this.copying = new Promise<void>((resolve) => whenIdle(resolve)).then(() => this.makeCopy(generation));
  }

  private async makeCopy(generation: number): Promise<void> {
    let copy: PlannerCopy | null;
    try {
      copy = await this.worker.copy();
      if (copy === null || generation !== this.generation) return;
      // the glue is loaded only now: the page's first download does not carry it
      const planner = await import("../planner/index");
      await planner.initPlanner(copy.module);
      if (generation !== this.generation) return;
      const started = performance.now();
      const fromSnapshot = copy.snapshot === null ? null : planner.FoonPlanner.fromSnapshot(copy.snapshot, copy.embeddings);
      this.local = fromSnapshot ?? planner.FoonPlanner.load(copy.files, copy.embeddings);
      performance.measure(COPY_MEASURE, { start: started });
    } catch {
      // the worker goes on planning: a copy is only a shortcut
      this.failed = true;
    }
  }
}
