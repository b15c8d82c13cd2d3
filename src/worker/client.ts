// The page's side of the planner worker: promise-returning calls, and stale plan requests resolved as
// `null` (a newer request replaced them) so callers simply ignore them.

import { PlannerError } from "../planner/errors";
import type { ExportFormat, KnowledgeBaseFile, Plan, PlanRequest } from "../planner/types";
import type { LoadedFrom } from "./kb-cache";
import type { KnowledgeBaseSource, LoadedKnowledgeBase, LoadPhase, PlannerCopy, WorkerRequest, WorkerResponse } from "./protocol";
import plannerWorkerUrl from "./planner.worker.ts?worker&url";

/** What a planner worker (or a fake one in tests) must offer the app. */
export interface PlannerService {
  loadUrl(url: string, embeddingsUrl?: string): Promise<LoadedKnowledgeBase>;
  /** Starts downloading what `loadUrl(url, embeddingsUrl)` would, before it is certain to be called. */
  prefetch(url: string, embeddingsUrl?: string): void;
  loadFiles(files: KnowledgeBaseFile[], embeddingsUrl?: string): Promise<LoadedKnowledgeBase>;
  /** Resolves `null` when a newer plan request superseded this one. */
  plan(request: PlanRequest): Promise<{ plan: Plan; ms: number } | null>;
  exportPlan(request: PlanRequest, format: ExportFormat): Promise<string>;
  dispose(): void;
}

interface Pending {
  message: WorkerRequest;
  resolve: (response: WorkerResponse) => void;
  /** Already sent again once after a crash: a second crash on it is reported, not retried. */
  retried: boolean;
}

const NOT_LOADED =
  "its script could not be loaded (a planner on another host must send Access-Control-Allow-Origin, and the page's Content-Security-Policy must allow that host in worker-src)";

/** How many restarts within `RESTART_WINDOW_MS` before the client gives up (a worker that cannot start). */
const MAX_RESTARTS = 3;
const RESTART_WINDOW_MS = 60_000;

export interface WorkerPlannerOptions {
  /** Creates the worker (tests pass a fake). */
  createWorker?: () => Worker;
  /** Told when the worker crashed and was restarted (the knowledge base reloaded, waiting calls resent). */
  onRestart?: (reason: string) => void;
}

/** Same-origin module scripts that import a worker script from another origin, one per script URL. */
const bootstraps = new Map<string, string>();

/**
 * The planner worker, from the worker script next to this one. A page may not start a worker from another
 * origin's script (a widget loaded from a planner host), so then it starts a same-origin module worker (a
 * blob) that imports the real one by its absolute URL: a CORS request, as for any module script. Inside it,
 * `import.meta.url` is the real script's URL, so the WASM module is still found next to it.
 */
function plannerWorker(): Worker {
  const script = new URL(plannerWorkerUrl, import.meta.url);
  const options: WorkerOptions = { type: "module", name: "foon-planner" };
  if (script.origin === self.location.origin) return new Worker(script, options);
  let bootstrap = bootstraps.get(script.href);
  if (bootstrap === undefined) {
    bootstrap = URL.createObjectURL(new Blob([`import ${JSON.stringify(script.href)};\n`], { type: "text/javascript" }));
    bootstraps.set(script.href, bootstrap);
  }
  return new Worker(bootstrap, options);
}

/** A failure that means the WASM module trapped (a panic or an out-of-memory abort): its state is lost. */
function isCrash(response: WorkerResponse): boolean {
  return response.type === "error" && response.error.code === "internal" && response.error.message.startsWith("planner failure");
}

export class WorkerPlanner implements PlannerService {
  private worker!: Worker;
  private readonly pending = new Map<number, Pending>();
  private nextId = 1;
  private latestPlan = 0;
  /** The last load that succeeded: sent again to a restarted worker before anything else. */
  private lastLoad: WorkerRequest | null = null;
  private restarts: number[] = [];
  private readonly createWorker: () => Worker;
  private readonly onRestart: ((reason: string) => void) | undefined;

  constructor(options: WorkerPlannerOptions = {}) {
    this.createWorker = options.createWorker ?? plannerWorker;
    this.onRestart = options.onRestart;
    this.start();
  }

  private start(): void {
    const worker = this.createWorker();
    this.worker = worker;
    worker.onmessage = (event: MessageEvent<WorkerResponse>) => {
      if (worker !== this.worker) return; // a message of a worker already replaced
      const waiting = this.pending.get(event.data.id);
      if (waiting === undefined) return;
      if (isCrash(event.data)) {
        this.crashed(event.data.type === "error" ? event.data.error.message : "planner failure");
        return;
      }
      this.pending.delete(event.data.id);
      if (event.data.type === "loaded" && waiting.message.type === "load") this.lastLoad = waiting.message;
      waiting.resolve(event.data);
    };
    worker.onerror = (event: ErrorEvent) => {
      if (worker !== this.worker) return;
      event.preventDefault?.();
      // a module worker whose script cannot be loaded fails with an empty message
      this.crashed(`planner worker failed: ${event.message || NOT_LOADED}`);
    };
  }

  /**
   * The worker died or its WASM module trapped: a new worker, the last knowledge base loaded again, and the
   * calls that were waiting sent again once (a call that crashes the new worker too fails with its reason).
   */
  private crashed(reason: string): void {
    const waiting = [...this.pending.values()].sort((a, b) => a.message.id - b.message.id);
    this.pending.clear();
    this.worker.terminate();
    const now = Date.now();
    this.restarts = [...this.restarts.filter((t) => now - t < RESTART_WINDOW_MS), now];
    const fail = (w: Pending, message: string): void => w.resolve({ type: "error", id: w.message.id, error: { code: "internal", message } });
    if (this.restarts.length > MAX_RESTARTS) {
      for (const w of waiting) fail(w, `${reason}; the planner crashed ${MAX_RESTARTS} times in a minute and was not restarted again`);
      // the next call starts a fresh worker, without a knowledge base (not now: one that cannot start would loop)
      this.stopped = true;
      return;
    }
    this.start();
    this.onRestart?.(reason);
    const resend = (): void => {
      for (const w of waiting) {
        if (w.retried) {
          fail(w, `${reason} (twice on this request)`);
          continue;
        }
        this.pending.set(w.message.id, { ...w, retried: true });
        this.worker.postMessage(w.message);
      }
    };
    const reload = this.lastLoad;
    if (reload === null || waiting.some((w) => w.message.type === "load" && !w.retried && w.message.id > reload.id)) {
      resend();
      return;
    }
    // calls made from now on wait until the knowledge base is back in the new worker
    let release!: () => void;
    this.gate = new Promise<void>((resolve) => (release = resolve));
    const message: WorkerRequest = { ...reload, id: this.nextId++ };
    this.pending.set(message.id, {
      message,
      retried: true,
      resolve: (response) => {
        if (response.type === "loaded") resend();
        else for (const w of waiting) fail(w, `${reason}; the knowledge base could not be loaded again`);
        release();
      },
    });
    this.worker.postMessage(message);
  }

  /** Resolved, except while a restarted worker is loading the knowledge base again. */
  private gate: Promise<void> = Promise.resolve();

  /** Given up on after too many crashes: no worker runs until the next call. */
  private stopped = false;

  private send(message: WorkerRequest): Promise<WorkerResponse> {
    if (this.stopped) {
      this.stopped = false;
      this.start();
    }
    return new Promise((resolve) => {
      this.pending.set(message.id, { message, resolve, retried: false });
      const worker = this.worker;
      void this.gate.then(() => {
        // a crash in the meantime resends what was pending itself
        if (worker === this.worker && this.pending.has(message.id)) worker.postMessage(message);
      });
    });
  }

  private async load(source: KnowledgeBaseSource, embeddingsUrl: string | undefined): Promise<LoadedKnowledgeBase> {
    const response = await this.send({ type: "load", id: this.nextId++, source, embeddingsUrl });
    if (response.type !== "loaded") throw errorOf(response);
    measurePhases(response.kb.phases, response.kb.from);
    return response.kb;
  }

  loadUrl(url: string, embeddingsUrl?: string): Promise<LoadedKnowledgeBase> {
    return this.load({ kind: "url", url }, embeddingsUrl);
  }

  loadFiles(files: KnowledgeBaseFile[], embeddingsUrl?: string): Promise<LoadedKnowledgeBase> {
    return this.load({ kind: "files", files }, embeddingsUrl);
  }

  prefetch(url: string, embeddingsUrl?: string): void {
    // nothing answers it: it only starts the worker's downloads
    this.worker.postMessage({ type: "prefetch", id: this.nextId++, kbUrl: url, embeddingsUrl } satisfies WorkerRequest);
  }

  async plan(request: PlanRequest): Promise<{ plan: Plan; ms: number } | null> {
    const id = this.nextId++;
    this.latestPlan = id;
    const response = await this.send({ type: "plan", id, request });
    if (response.type === "superseded" || id !== this.latestPlan) return null;
    if (response.type === "planned") return { plan: response.plan, ms: response.ms };
    throw errorOf(response);
  }

  async exportPlan(request: PlanRequest, format: ExportFormat): Promise<string> {
    const response = await this.send({ type: "export", id: this.nextId++, request, format });
    if (response.type === "exported") return response.text;
    throw errorOf(response);
  }

  /** The worker's compiled module and loaded files, for a copy of the planner on the page's thread (null: none to give). */
  async copy(): Promise<PlannerCopy | null> {
    const response = await this.send({ type: "copy", id: this.nextId++ });
    if (response.type === "copied") return response.copy;
    throw errorOf(response);
  }

  dispose(): void {
    this.worker.terminate();
    this.pending.clear();
  }
}

/** The worker's load phases on the page's Performance timeline, as `foon:<phase>` measures (`detail.from`: files, cache or build). */
function measurePhases(phases: readonly LoadPhase[], from: LoadedFrom): void {
  for (const p of phases) {
    performance.measure(`foon:${p.name}`, { start: p.start - performance.timeOrigin, end: p.end - performance.timeOrigin, detail: { from } });
  }
}

function errorOf(response: WorkerResponse): PlannerError {
  if (response.type === "error") return new PlannerError(response.error);
  return new PlannerError({ code: "internal", message: `unexpected worker answer '${response.type}'` });
}
