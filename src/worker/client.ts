// The page's side of the planner worker: promise-returning calls, and stale plan requests resolved as
// `null` (a newer request replaced them) so callers simply ignore them.

import { PlannerError } from "../planner/errors";
import type { ExportFormat, KnowledgeBaseFile, Plan, PlanRequest } from "../planner/types";
import type { KnowledgeBaseSource, LoadedKnowledgeBase, WorkerRequest, WorkerResponse } from "./protocol";

/** What a planner worker (or a fake one in tests) must offer the app. */
export interface PlannerService {
  loadUrl(url: string, embeddingsUrl?: string): Promise<LoadedKnowledgeBase>;
  loadFiles(files: KnowledgeBaseFile[], embeddingsUrl?: string): Promise<LoadedKnowledgeBase>;
  /** Resolves `null` when a newer plan request superseded this one. */
  plan(request: PlanRequest): Promise<{ plan: Plan; ms: number } | null>;
  exportPlan(request: PlanRequest, format: ExportFormat): Promise<string>;
  dispose(): void;
}

interface Pending {
  resolve: (response: WorkerResponse) => void;
}

export class WorkerPlanner implements PlannerService {
  private readonly worker: Worker;
  private readonly pending = new Map<number, Pending>();
  private nextId = 1;
  private latestPlan = 0;

  constructor() {
    this.worker = new Worker(new URL("./planner.worker.ts", import.meta.url), { type: "module", name: "foon-planner" });
    this.worker.onmessage = (event: MessageEvent<WorkerResponse>) => {
      const waiting = this.pending.get(event.data.id);
      if (waiting === undefined) return;
      this.pending.delete(event.data.id);
      waiting.resolve(event.data);
    };
    this.worker.onerror = (event: ErrorEvent) => {
      // a worker that failed to start: fail everything waiting, with the reason
      for (const [id, waiting] of this.pending) {
        waiting.resolve({ type: "error", id, error: { code: "internal", message: `planner worker failed: ${event.message}` } });
      }
      this.pending.clear();
    };
  }

  private send(message: WorkerRequest): Promise<WorkerResponse> {
    return new Promise((resolve) => {
      this.pending.set(message.id, { resolve });
      this.worker.postMessage(message);
    });
  }

  private async load(source: KnowledgeBaseSource, embeddingsUrl: string | undefined): Promise<LoadedKnowledgeBase> {
    const response = await this.send({ type: "load", id: this.nextId++, source, embeddingsUrl });
    if (response.type === "loaded") return response.kb;
    throw errorOf(response);
  }

  loadUrl(url: string, embeddingsUrl?: string): Promise<LoadedKnowledgeBase> {
    return this.load({ kind: "url", url }, embeddingsUrl);
  }

  loadFiles(files: KnowledgeBaseFile[], embeddingsUrl?: string): Promise<LoadedKnowledgeBase> {
    return this.load({ kind: "files", files }, embeddingsUrl);
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

  dispose(): void {
    this.worker.terminate();
    this.pending.clear();
  }
}

function errorOf(response: WorkerResponse): PlannerError {
  if (response.type === "error") return new PlannerError(response.error);
  return new PlannerError({ code: "internal", message: `unexpected worker answer '${response.type}'` });
}
