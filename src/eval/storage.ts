// Browser storage of the workbench in IndexedDB: ratings (written through on every rating), the
// last batch (queries, records and plans) and settings. Versioned schema: bump DB_VERSION and add
// an upgrade step, never drop the ratings store.

import type { Plan } from "../planner/types";
import { ratingKey, type Rating } from "./ratings";
import type { EvalRecord, LoadedQuery, RecipeRef, Variant } from "./types";

export const DB_NAME = "foon-planner-eval";
export const DB_VERSION = 1;

export interface Settings {
  rater: string;
  blind: boolean;
  /** Seed of the blind order, per browser profile. */
  seed: string;
  /** Position in the rating queue (recipe key). */
  position: string | null;
}

export interface StoredBatch {
  id: string;
  created: string;
  knowledge_base: string;
  variants: Variant[];
  queries: LoadedQuery[];
  records: EvalRecord[];
  status: "running" | "done" | "cancelled" | "failed";
}

/** A plan with the recipe and variant it was made for. */
export interface PlanEntry {
  recipe: RecipeRef;
  variant: Variant;
  plan: Plan;
}

interface StoredRating extends Rating {
  key: string;
}
interface StoredPlan {
  key: string;
  batch: string;
  plan: Plan;
}

/** A storage failure, with `quota` true when the browser ran out of space. */
export class StorageError extends Error {
  constructor(
    message: string,
    readonly quota: boolean,
  ) {
    super(message);
    this.name = "StorageError";
  }
}

/** Wraps an IndexedDB failure (shared with the planner page's knowledge-base store). */
export function toStorageError(e: unknown, what: string): StorageError {
  const name = e instanceof DOMException ? e.name : "";
  const quota = name === "QuotaExceededError" || (e instanceof Error && /quota/i.test(e.message));
  return new StorageError(`${what}: ${e instanceof Error ? e.message : String(e)}`, quota);
}

export function request<T>(req: IDBRequest<T>): Promise<T> {
  return new Promise((resolve, reject) => {
    req.onsuccess = () => resolve(req.result);
    req.onerror = () => reject(req.error);
  });
}

export function done(tx: IDBTransaction): Promise<void> {
  return new Promise((resolve, reject) => {
    tx.oncomplete = () => resolve();
    tx.onerror = () => reject(tx.error);
    tx.onabort = () => reject(tx.error ?? new DOMException("transaction aborted", "AbortError"));
  });
}

const planKey = (batch: string, type: string, id: string, variant: Variant): string => JSON.stringify([batch, type, id, variant]);

export class EvalStore {
  private constructor(private readonly db: IDBDatabase) {}

  static async open(factory: IDBFactory = indexedDB): Promise<EvalStore> {
    const req = factory.open(DB_NAME, DB_VERSION);
    req.onupgradeneeded = (event) => {
      const db = req.result;
      if (event.oldVersion < 1) {
        db.createObjectStore("ratings", { keyPath: "key" });
        db.createObjectStore("batches", { keyPath: "id" });
        db.createObjectStore("plans", { keyPath: "key" }).createIndex("batch", "batch");
        db.createObjectStore("meta");
      }
    };
    req.onblocked = () => undefined; // an older tab holds the database: open() resolves once it closes it
    try {
      const db = await request(req);
      db.onversionchange = () => db.close(); // a newer workbench in another tab upgrades the schema
      return new EvalStore(db);
    } catch (e) {
      throw toStorageError(e, "cannot open the browser database");
    }
  }

  private async write(stores: string[], what: string, body: (tx: IDBTransaction) => void): Promise<void> {
    try {
      const tx = this.db.transaction(stores, "readwrite", { durability: "strict" });
      body(tx);
      await done(tx);
    } catch (e) {
      throw toStorageError(e, what);
    }
  }

  /** Saves ratings (one transaction); resolves once they are on disk. */
  putRatings(ratings: readonly Rating[]): Promise<void> {
    return this.write(["ratings"], "cannot save the rating", (tx) => {
      const store = tx.objectStore("ratings");
      for (const r of ratings) store.put({ ...r, key: ratingKey(r) } satisfies StoredRating);
    });
  }

  async allRatings(): Promise<Rating[]> {
    const rows = (await request(this.db.transaction("ratings").objectStore("ratings").getAll())) as StoredRating[];
    return rows.map(({ key: _key, ...rating }) => rating);
  }

  clearRatings(): Promise<void> {
    return this.write(["ratings"], "cannot clear the ratings", (tx) => tx.objectStore("ratings").clear());
  }

  async settings(): Promise<Settings | null> {
    const value = (await request(this.db.transaction("meta").objectStore("meta").get("settings"))) as Settings | undefined;
    return value ?? null;
  }

  putSettings(settings: Settings): Promise<void> {
    return this.write(["meta"], "cannot save the settings", (tx) => tx.objectStore("meta").put(settings, "settings"));
  }

  /** Replaces the stored batch (and its plans) by a new, empty one. */
  startBatch(batch: StoredBatch): Promise<void> {
    return this.write(["batches", "plans", "meta"], "cannot store the batch", (tx) => {
      tx.objectStore("batches").clear();
      tx.objectStore("plans").clear();
      tx.objectStore("batches").put(batch);
      tx.objectStore("meta").put(batch.id, "batch");
    });
  }

  /** Saves the batch's records and status, and new plans. */
  saveBatch(batch: StoredBatch, plans: readonly PlanEntry[]): Promise<void> {
    return this.write(["batches", "plans"], "cannot store the batch", (tx) => {
      tx.objectStore("batches").put(batch);
      const store = tx.objectStore("plans");
      for (const { recipe, variant, plan } of plans) {
        store.put({ key: planKey(batch.id, recipe.type, recipe.id, variant), batch: batch.id, plan } satisfies StoredPlan);
      }
    });
  }

  async batch(): Promise<StoredBatch | null> {
    const id = (await request(this.db.transaction("meta").objectStore("meta").get("batch"))) as string | undefined;
    if (id === undefined) return null;
    const batch = (await request(this.db.transaction("batches").objectStore("batches").get(id))) as StoredBatch | undefined;
    return batch ?? null;
  }

  async plan(batch: string, type: string, id: string, variant: Variant): Promise<Plan | null> {
    const row = (await request(this.db.transaction("plans").objectStore("plans").get(planKey(batch, type, id, variant)))) as StoredPlan | undefined;
    return row?.plan ?? null;
  }

  close(): void {
    this.db.close();
  }
}
