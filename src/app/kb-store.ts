// The user's own knowledge base survives a reload: the FOON files they load (names and bytes) are written
// through to IndexedDB, restored on start, and forgotten when they switch back to the bundled one.
// Several tabs share one record: every save gets the next version, a save older than the stored one is
// refused (never clobbering newer work), and a BroadcastChannel tells the other tabs to reload it.
// Versioned schema: bump KB_DB_VERSION and add an upgrade step.

import type { KnowledgeBaseFile } from "../planner/types";
import { done, request, StorageError, toStorageError } from "../eval/storage";

export const KB_DB_NAME = "foon-planner-kb";
export const KB_DB_VERSION = 1;
export const KB_CHANNEL = "foon-planner-kb";
export const KB_STORE = "kb";
export const KB_KEY = "current";

export interface SavedKnowledgeBase {
  /** Increases by one on every save, whichever tab saves. */
  version: number;
  /** When the user chose this knowledge base (ms since the epoch): an older choice never replaces it. */
  savedAt: number;
  /** The user's files; null: the bundled knowledge base. */
  files: KnowledgeBaseFile[] | null;
}

/** A save refused because a newer one is stored (by another tab). */
export class StaleSaveError extends Error {
  constructor(readonly current: SavedKnowledgeBase) {
    super(`a newer knowledge base (version ${current.version}) is already saved`);
    this.name = "StaleSaveError";
  }
}

export class KbStore {
  private constructor(private readonly db: IDBDatabase) {}

  static async open(factory: IDBFactory = indexedDB): Promise<KbStore> {
    try {
      const req = factory.open(KB_DB_NAME, KB_DB_VERSION);
      req.onupgradeneeded = (event) => {
        if (event.oldVersion < 1) req.result.createObjectStore(KB_STORE);
      };
      req.onblocked = () => undefined; // an older tab holds the database: open() resolves once it closes it
      const db = await request(req);
      db.onversionchange = () => db.close();
      return new KbStore(db);
    } catch (e) {
      throw toStorageError(e, "cannot open the browser database");
    }
  }

  async load(): Promise<SavedKnowledgeBase | null> {
    try {
      const value = (await request(this.db.transaction(KB_STORE).objectStore(KB_STORE).get(KB_KEY))) as SavedKnowledgeBase | undefined;
      return value ?? null;
    } catch (e) {
      throw toStorageError(e, "cannot read the saved knowledge base");
    }
  }

  /**
   * Saves the files (null: back to the bundled knowledge base) unless a newer choice is stored, in one
   * transaction; resolves with the saved record once it is on disk. Throws StaleSaveError or StorageError.
   */
  async save(files: KnowledgeBaseFile[] | null, savedAt: number): Promise<SavedKnowledgeBase> {
    let stale: SavedKnowledgeBase | null = null;
    let saved: SavedKnowledgeBase | null = null;
    let failure: unknown = null;
    try {
      const tx = this.db.transaction(KB_STORE, "readwrite", { durability: "strict" });
      const store = tx.objectStore(KB_STORE);
      const get = store.get(KB_KEY);
      get.onsuccess = () => {
        const current = (get.result as SavedKnowledgeBase | undefined) ?? null;
        if (current !== null && current.savedAt > savedAt) {
          stale = current;
          return;
        }
        const record: SavedKnowledgeBase = { version: (current?.version ?? 0) + 1, savedAt, files };
        try {
          store.put(record, KB_KEY);
          saved = record;
        } catch (e) {
          failure = e;
          tx.abort();
        }
      };
      await done(tx);
    } catch (e) {
      throw toStorageError(failure ?? e, "cannot save your knowledge base");
    }
    if (stale !== null) throw new StaleSaveError(stale);
    if (saved === null) throw new StorageError("cannot save your knowledge base: nothing was written", false);
    return saved;
  }

  close(): void {
    this.db.close();
  }
}

/** What crosses the BroadcastChannel: only the version; the files are read from IndexedDB. */
export interface KbMessage {
  type: "kb-saved";
  version: number;
}

/** The part of BroadcastChannel this module uses (a fake in unit tests). */
export interface KbChannel {
  postMessage(message: KbMessage): void;
  onmessage: ((event: MessageEvent<KbMessage>) => void) | null;
  close(): void;
}

/** The page's view of the saved knowledge base: restore, save, and news from the other tabs. */
export interface KbPersistence {
  /** Null when nothing is saved or the bundled one was chosen last. */
  restore(): Promise<KnowledgeBaseFile[] | null>;
  /** Throws StorageError (full, unavailable) or StaleSaveError (another tab chose later). */
  save(files: KnowledgeBaseFile[] | null, savedAt?: number): Promise<SavedKnowledgeBase>;
  /** Called with another tab's newer save. */
  onRemoteChange(listener: (saved: SavedKnowledgeBase) => void): () => void;
  close(): void;
}

/** Persistence over a store (null: IndexedDB is unavailable, every save fails) and a channel to the other tabs. */
export function createKbPersistence(store: KbStore | null, channel: KbChannel | null, unavailable = "the browser database is unavailable"): KbPersistence {
  let seen = 0;
  const listeners = new Set<(saved: SavedKnowledgeBase) => void>();
  const need = (): KbStore => {
    if (store === null) throw new StorageError(unavailable, false);
    return store;
  };
  let checking = Promise.resolve();
  if (channel !== null) {
    channel.onmessage = (event) => {
      const message = event.data;
      if (message?.type !== "kb-saved" || message.version <= seen || store === null) return;
      // one check at a time, so two quick messages are applied in order
      checking = checking.then(async () => {
        const saved = await store.load().catch(() => null);
        if (saved === null || saved.version <= seen) return;
        seen = saved.version;
        for (const l of listeners) l(saved);
      });
    };
  }
  return {
    async restore() {
      const saved = await need().load();
      if (saved === null) return null;
      seen = Math.max(seen, saved.version);
      return saved.files;
    },
    async save(files, savedAt = Date.now()) {
      try {
        const saved = await need().save(files, savedAt);
        seen = Math.max(seen, saved.version);
        channel?.postMessage({ type: "kb-saved", version: saved.version });
        return saved;
      } catch (e) {
        if (e instanceof StaleSaveError) seen = Math.max(seen, e.current.version);
        throw e;
      }
    },
    onRemoteChange(listener) {
      listeners.add(listener);
      return () => listeners.delete(listener);
    },
    close() {
      channel?.close();
      store?.close();
    },
  };
}

/** The page's persistence: IndexedDB and a BroadcastChannel when the browser has them. */
export async function openKbPersistence(): Promise<KbPersistence> {
  const channel = typeof BroadcastChannel === "undefined" ? null : (new BroadcastChannel(KB_CHANNEL) as KbChannel);
  try {
    if (typeof indexedDB === "undefined") throw new StorageError("this browser has no IndexedDB", false);
    return createKbPersistence(await KbStore.open(), channel);
  } catch (e) {
    return createKbPersistence(null, channel, e instanceof Error ? e.message : String(e));
  }
}
