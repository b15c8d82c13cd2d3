// Messages between the page and the planner worker. Everything is structured-cloneable data.

import type { LoadedFrom } from "./kb-cache";
import type { ExportFormat, FoonErrorData, KnowledgeBaseFile, Plan, PlanRequest, Stats, Vocabulary } from "../planner/types";

export type KnowledgeBaseSource = { kind: "url"; url: string } | { kind: "files"; files: KnowledgeBaseFile[] };

export type WorkerRequest =
  /** `embeddingsUrl`: the food embedding table; without it the planner matches names exactly. */
  | { type: "load"; id: number; source: KnowledgeBaseSource; embeddingsUrl?: string }
  /** Fetch these now for a load to come (no answer): the page is still deciding which knowledge base to load. */
  | { type: "prefetch"; id: number; kbUrl: string; embeddingsUrl?: string }
  | { type: "plan"; id: number; request: PlanRequest }
  | { type: "export"; id: number; request: PlanRequest; format: ExportFormat }
  /** The compiled module and the loaded knowledge base's files, for a copy of the planner on the page's thread. */
  | { type: "copy"; id: number };

export interface LoadedKnowledgeBase {
  /** What was loaded: the bundled URL, or the dropped files' names. */
  name: string;
  stats: Stats;
  vocabulary: Vocabulary;
  warnings: FoonErrorData[];
  /** Whether the embedding table was loaded (else substitutes are found by exact names only). */
  embeddings: boolean;
  /** Whether the knowledge base was parsed from its files or read from a snapshot, the browser's or the build's (`kb-cache.ts`). */
  from: LoadedFrom;
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
 * `embeddings download`: the files (or the bundled knowledge base's snapshot) and the table fetched (the table
 * once per URL); `kb load`: parse and merge (or read a snapshot), index.
 */
export type LoadPhaseName = "wasm" | "kb download" | "embeddings download" | "kb load";

/**
 * What the page needs to load the same planner itself: the module (compiled once, shared), the knowledge base's
 * snapshot (null: none could be made; then the same files are loaded, none when it came from the build's snapshot).
 */
export interface PlannerCopy {
  module: WebAssembly.Module;
  files: KnowledgeBaseFile[];
  embeddings?: Uint8Array;
  snapshot: Uint8Array | null;
}

export type WorkerResponse =
  | { type: "loaded"; id: number; kb: LoadedKnowledgeBase }
  | { type: "planned"; id: number; plan: Plan; ms: number }
  | { type: "exported"; id: number; text: string }
  /** `copy` null: nothing loaded yet, or a knowledge base too large to load on the page's thread. */
  | { type: "copied"; id: number; copy: PlannerCopy | null }
  /** A plan request that a newer one replaced before it ran. */
  | { type: "superseded"; id: number }
  | { type: "error"; id: number; error: FoonErrorData };
