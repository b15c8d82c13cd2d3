// Messages between the page and the planner worker. Everything is structured-cloneable data.

import type { ExportFormat, FoonErrorData, KnowledgeBaseFile, Plan, PlanRequest, Stats, Vocabulary } from "../planner/types";

export type KnowledgeBaseSource = { kind: "url"; url: string } | { kind: "files"; files: KnowledgeBaseFile[] };

export type WorkerRequest =
  /** `embeddingsUrl`: the food embedding table; without it the planner matches names exactly. */
  | { type: "load"; id: number; source: KnowledgeBaseSource; embeddingsUrl?: string }
  /** Fetch these now for a load to come (no answer): the page is still deciding which knowledge base to load. */
  | { type: "prefetch"; id: number; kbUrl: string; embeddingsUrl?: string }
  | { type: "plan"; id: number; request: PlanRequest }
  | { type: "export"; id: number; request: PlanRequest; format: ExportFormat };

export interface LoadedKnowledgeBase {
  /** What was loaded: the bundled URL, or the dropped files' names. */
  name: string;
  stats: Stats;
  vocabulary: Vocabulary;
  warnings: FoonErrorData[];
  /** Whether the embedding table was loaded (else substitutes are found by exact names only). */
  embeddings: boolean;
  /** How long each phase of this load took, on the wall clock (the worker and the page share it). */
  phases: LoadPhase[];
}

/** One phase of loading: `start` and `end` are Unix epoch milliseconds (`timeOrigin + now()`). */
export interface LoadPhase {
  name: LoadPhaseName;
  start: number;
  end: number;
}

/**
 * `wasm`: the module fetched and compiled as it streams in (once per worker); `kb download` and
 * `embeddings download`: the files fetched (the table once per URL); `kb load`: parse, merge, index.
 */
export type LoadPhaseName = "wasm" | "kb download" | "embeddings download" | "kb load";

export type WorkerResponse =
  | { type: "loaded"; id: number; kb: LoadedKnowledgeBase }
  | { type: "planned"; id: number; plan: Plan; ms: number }
  | { type: "exported"; id: number; text: string }
  /** A plan request that a newer one replaced before it ran. */
  | { type: "superseded"; id: number }
  | { type: "error"; id: number; error: FoonErrorData };
