// Messages between the workbench page and its batch worker.

import type { KnowledgeBaseFile, Plan } from "../planner/types";
import type { EvalRecord, LoadedQuery, Variant } from "../eval/types";

export interface RunRequest {
  kind: "run";
  knowledgeBase: KnowledgeBaseFile[];
  /** The food embedding table; null plans with exact name matching. */
  embeddings: Uint8Array | null;
  queries: LoadedQuery[];
  variants: Variant[];
}

export type WorkerMessage =
  | { kind: "loaded"; subgraphs: number; units: number }
  | { kind: "result"; record: EvalRecord; plan: Plan | null; done: number; total: number }
  | { kind: "finished" }
  | { kind: "failed"; message: string };
