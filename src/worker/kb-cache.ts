// Loading a knowledge base without parsing and merging its files, from the planner's snapshot of it
// (`FoonPlanner.snapshot()`): for the bundled knowledge base, the snapshot `npm run build:kb` ships beside
// its text; for any other, the snapshot kept in IndexedDB after its first load, keyed by a SHA-256 of the
// planner module's bytes and of the files, so that a second visit skips parsing and merging. Another build
// or other files give another key; a damaged snapshot, or one the module cannot read, is not used (the files
// are parsed, and the cache entry replaced). Where there is no IndexedDB (private browsing in some browsers)
// or no WebCrypto (a page not served over HTTPS), nothing is cached and nothing is said: the files are
// parsed as before.

import { FoonPlanner } from "../planner/index";
import type { KnowledgeBaseFile } from "../planner/types";
import { done, request } from "../eval/storage";

export const CACHE_DB_NAME = "foon-planner-kb-cache";
const STORE = "snapshots";
/** The store's index of entries by when they were stored. */
const BY_AGE = "storedAt";
/** Snapshots kept (a user's own knowledge bases, or versions of one): the one stored longest ago goes first. */
export const MAX_ENTRIES = 3;

interface Entry {
  snapshot: Uint8Array;
  storedAt: number;
}

export class KbCache {
  private constructor(private readonly db: IDBDatabase) {}

  /** The cache, or null where IndexedDB is missing or refuses (then the planner parses as before). */
  static async open(factory: IDBFactory | undefined = globalThis.indexedDB): Promise<KbCache | null> {
    if (factory === undefined) return null;
    try {
      const req = factory.open(CACHE_DB_NAME, 1);
      req.onupgradeneeded = () => req.result.createObjectStore(STORE).createIndex(BY_AGE, "storedAt");
      const db = await request(req);
      db.onversionchange = () => db.close();
      return new KbCache(db);
    } catch {
      return null;
    }
  }

  /** The snapshot stored under `key`, or null. */
  async get(key: string): Promise<Uint8Array | null> {
    try {
      const entry = (await request(this.db.transaction(STORE).objectStore(STORE).get(key))) as Entry | undefined;
      return entry?.snapshot instanceof Uint8Array ? entry.snapshot : null;
    } catch {
      return null;
    }
  }

  /** Stores a snapshot under `key` and drops the ones stored longest ago beyond `MAX_ENTRIES`. */
  async put(key: string, snapshot: Uint8Array, now = Date.now()): Promise<void> {
    try {
      const tx = this.db.transaction(STORE, "readwrite");
      const store = tx.objectStore(STORE);
      store.put({ snapshot, storedAt: now } satisfies Entry, key);
      const oldestFirst = await request(store.index(BY_AGE).getAllKeys());
      for (const k of oldestFirst.slice(0, Math.max(0, oldestFirst.length - MAX_ENTRIES))) store.delete(k);
      await done(tx);
    } catch {
      // a full disk or a closed database: the next visit parses again
    }
  }
}

/**
 * The cache key of `files` loaded by the planner module `build` (its bytes' SHA-256, hex): a SHA-256 over the
 * build and each file's name and bytes. Null where WebCrypto is missing.
 */
export async function cacheKey(build: string, files: readonly KnowledgeBaseFile[]): Promise<string | null> {
  const subtle = globalThis.crypto?.subtle;
  if (subtle === undefined) return null;
  const encoder = new TextEncoder();
  const parts: Uint8Array[] = [encoder.encode(`${build}\n`)];
  for (const f of files) parts.push(encoder.encode(`${f.name}\n${f.bytes.byteLength}\n`), f.bytes);
  const all = new Uint8Array(parts.reduce((n, p) => n + p.byteLength, 0));
  let at = 0;
  for (const p of parts) {
    all.set(p, at);
    at += p.byteLength;
  }
  return hex(await subtle.digest("SHA-256", all));
}

/** The SHA-256 of a planner module's bytes, hex (the build part of the cache key); null without WebCrypto. */
export async function buildDigest(moduleBytes: BufferSource): Promise<string | null> {
  const subtle = globalThis.crypto?.subtle;
  return subtle === undefined ? null : hex(await subtle.digest("SHA-256", moduleBytes));
}

const hex = (digest: ArrayBuffer): string => [...new Uint8Array(digest)].map((b) => b.toString(16).padStart(2, "0")).join("");

/** The digest's length in a shipped snapshot (hex SHA-256). */
const BUILD_LENGTH = 64;

/** A snapshot shipped with the build (`npm run build:kb`): the digest of the module that wrote it, then the snapshot. */
export function shippedSnapshot(build: string, snapshot: Uint8Array): Uint8Array {
  const out = new Uint8Array(BUILD_LENGTH + snapshot.byteLength);
  out.set(new TextEncoder().encode(build.slice(0, BUILD_LENGTH)));
  out.set(snapshot, BUILD_LENGTH);
  return out;
}

/** The snapshot a shipped file holds when this module (`build`) wrote it, else null. */
export function snapshotOfBuild(build: string, file: Uint8Array): Uint8Array | null {
  const writer = new TextDecoder().decode(file.subarray(0, BUILD_LENGTH));
  return writer === build ? file.subarray(BUILD_LENGTH) : null;
}

/** Where a knowledge base was loaded from: its files (parsed and merged), the browser's cache, or the build's snapshot. */
export type LoadedFrom = "files" | "cache" | "build";

/** A loaded planner, where it came from, and its snapshot when one is at hand. */
export interface CachedLoad {
  planner: FoonPlanner;
  from: LoadedFrom;
  /** The files it was loaded from; none when it came from the build's snapshot. */
  files: KnowledgeBaseFile[];
  /** Stores the snapshot of a parsed knowledge base (nothing when it came from a snapshot); resolves with the snapshot. */
  save: () => Promise<Uint8Array | null>;
}

/**
 * Loads the planner of `files`: from the snapshot cached under `key` when there is one the module reads, else
 * by parsing and merging the files (`save` then stores its snapshot: call it once the first plan is out).
 */
export async function loadThroughCache(
  cache: KbCache | null,
  key: string | null,
  files: KnowledgeBaseFile[],
  embeddings: Uint8Array | undefined,
): Promise<CachedLoad> {
  const stored = cache !== null && key !== null ? await cache.get(key) : null;
  const fromCache = stored === null ? null : FoonPlanner.fromSnapshot(stored, embeddings);
  if (fromCache !== null) return { planner: fromCache, from: "cache", files, save: () => Promise.resolve(stored) };
  const planner = FoonPlanner.load(files, embeddings);
  const save = async (): Promise<Uint8Array | null> => {
    const snapshot = planner.snapshot();
    if (cache !== null && key !== null) await cache.put(key, snapshot);
    return snapshot;
  };
  return { planner, from: "files", files, save };
}

/** A downloaded knowledge base: the build's snapshot of it, if it has one, and its files (fetched when asked for). */
export interface Download {
  shipped: Uint8Array | null;
  files: () => Promise<KnowledgeBaseFile[]>;
}

/**
 * Loads a downloaded knowledge base: from the snapshot shipped with it when this module (`build`, null where
 * it cannot be told) wrote it, else its files through the cache.
 */
export async function loadKnowledgeBase(cache: KbCache | null, build: string | null, download: Download, embeddings: Uint8Array | undefined): Promise<CachedLoad> {
  const shipped = build === null || download.shipped === null ? null : snapshotOfBuild(build, download.shipped);
  const planner = shipped === null ? null : FoonPlanner.fromSnapshot(shipped, embeddings);
  if (planner !== null) return { planner, from: "build", files: [], save: () => Promise.resolve(shipped) };
  const files = await download.files();
  return loadThroughCache(cache, build === null ? null : await cacheKey(build, files), files, embeddings);
}
