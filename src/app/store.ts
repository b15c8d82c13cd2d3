// One store per app instance: state flows one way (query -> plan -> views). Views read the state and call
// actions; they never change it themselves.

import type { LoadedKnowledgeBase } from "../worker/protocol";
import type { Plan } from "../planner/types";
import type { AppQuery } from "./query";
import { EMPTY_QUERY } from "./query";
import type { Selection } from "./model/tree";
import { NO_SELECTION } from "./model/tree";

export interface AppState {
  query: AppQuery;
  kb: LoadedKnowledgeBase | null;
  /** Whether the loaded knowledge base is the bundled one or the user's files. */
  kbSource: "bundled" | "custom";
  kbError: string | null;
  /** News about the knowledge base: restored after a reload, changed in another tab. */
  kbNotice: string | null;
  /** The user's files could not be saved in the browser (full, unavailable): why, and their names. */
  kbUnsaved: { reason: string; names: string[] } | null;
  plan: Plan | null;
  /** Milliseconds the last plan took in the worker. */
  planMs: number | null;
  /** Milliseconds from the plan request to every view drawn with its answer (the status line shows it). */
  shownMs: number | null;
  planning: boolean;
  planError: string | null;
  selection: Selection;
}

export const INITIAL_STATE: AppState = {
  query: EMPTY_QUERY,
  kb: null,
  kbSource: "bundled",
  kbError: null,
  kbNotice: null,
  kbUnsaved: null,
  plan: null,
  planMs: null,
  shownMs: null,
  planning: false,
  planError: null,
  selection: NO_SELECTION,
};

export type Listener = (state: AppState, previous: AppState) => void;

export class Store {
  private current: AppState;
  private readonly listeners = new Set<Listener>();

  constructor(initial: AppState = INITIAL_STATE) {
    this.current = initial;
  }

  get state(): AppState {
    return this.current;
  }

  set(patch: Partial<AppState>): void {
    const previous = this.current;
    this.current = { ...previous, ...patch };
    for (const listener of this.listeners) listener(this.current, previous);
  }

  subscribe(listener: Listener): () => void {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  }
}
