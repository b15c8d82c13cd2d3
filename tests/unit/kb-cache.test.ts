// The parsed knowledge base cached in IndexedDB (fake-indexeddb) with the real WASM planner: a second load
// comes from the cache and plans the same; a damaged or other-version entry, other files or another build
// are parsed again (never a wrong plan); without IndexedDB or WebCrypto nothing is cached and the files load.
// The snapshot shipped with the build is read when this build wrote it, else the files are loaded.
import { describe, expect, it, vi } from "vitest";
import { IDBFactory } from "fake-indexeddb";
import { FoonPlanner, type KnowledgeBaseFile, type PlanRequest } from "../../src/planner/index";
import { initPlannerFromDisk, readEmbeddings, readKnowledgeBase, STARTER_KB_DIR } from "../../src/planner/node";
import { cacheKey, KbCache, loadKnowledgeBase, loadThroughCache, MAX_ENTRIES, shippedSnapshot } from "../../src/worker/kb-cache";
import { encode } from "./helpers";

initPlannerFromDisk();
const FILES = readKnowledgeBase(STARTER_KB_DIR);
const EMBEDDINGS = readEmbeddings();
const REQUEST: PlanRequest = { query: { type: "salad", ingredients: [{ object: "tomato", state: "diced" }, { object: "cool whip", state: "whole" }] } };
const BUILD = "build-a";
const expected = JSON.stringify(FoonPlanner.load(FILES, EMBEDDINGS).plan(REQUEST));

async function load(cache: KbCache | null, files: KnowledgeBaseFile[] = FILES, build = BUILD) {
  const loaded = await loadThroughCache(cache, await cacheKey(build, files), files, EMBEDDINGS);
  await loaded.save();
  return loaded;
}

async function freshCache(): Promise<KbCache> {
  const cache = await KbCache.open(new IDBFactory());
  if (cache === null) throw new Error("fake-indexeddb did not open");
  return cache;
}

describe("knowledge-base cache", () => {
  it("parses on the first load and reads the cache on the second, with the same plans", async () => {
    const cache = await freshCache();
    const first = await load(cache);
    expect(first.from).toBe("files");
    const second = await load(cache);
    expect(second.from).toBe("cache");
    expect(JSON.stringify(second.planner.plan(REQUEST))).toBe(expected);
    expect(second.planner.stats()).toEqual(first.planner.stats());
  });

  it("parses again when the entry is damaged or of another format version, and replaces it", async () => {
    const cache = await freshCache();
    const key = (await cacheKey(BUILD, FILES))!;
    const good = FoonPlanner.load(FILES, EMBEDDINGS).snapshot();
    const damaged = good.slice();
    damaged[good.length - 10]! ^= 0x01;
    const otherVersion = good.slice();
    otherVersion[6]! += 1; // the version after the magic "FOONKB"
    for (const entry of [damaged, good.slice(0, good.length >> 1), otherVersion, encode("not a snapshot"), new Uint8Array()]) {
      await cache.put(key, entry);
      const loaded = await load(cache);
      expect(loaded.from).toBe("files");
      expect(JSON.stringify(loaded.planner.plan(REQUEST))).toBe(expected);
      expect(await cache.get(key)).toEqual(good);
    }
  });

  it("keys entries by the build and by every file's name and bytes", async () => {
    const base = await cacheKey(BUILD, FILES);
    const renamed = FILES.map((f, i) => (i === 0 ? { ...f, name: `x${f.name}` } : f));
    const edited = FILES.map((f, i) => (i === 0 ? { ...f, bytes: encode(`${new TextDecoder().decode(f.bytes)}\n`) } : f));
    const keys = [base, await cacheKey("build-b", FILES), await cacheKey(BUILD, renamed), await cacheKey(BUILD, edited), await cacheKey(BUILD, FILES.slice(1))];
    expect(new Set(keys).size).toBe(keys.length);
    expect(await cacheKey(BUILD, FILES)).toBe(base);
    // another knowledge base cached meanwhile is not taken for this one
    const cache = await freshCache();
    await load(cache, FILES.slice(1));
    expect((await load(cache)).from).toBe("files");
    expect((await load(cache, FILES, "build-b")).from).toBe("files");
  });

  it("keeps the entries stored last", async () => {
    const cache = await freshCache();
    for (let i = 0; i <= MAX_ENTRIES; i++) await cache.put(`k${i}`, new Uint8Array([i]), 1000 + i);
    expect(await cache.get("k0")).toBeNull();
    for (let i = 1; i <= MAX_ENTRIES; i++) expect(await cache.get(`k${i}`)).toEqual(new Uint8Array([i]));
  });

  it("loads the files without IndexedDB or WebCrypto", async () => {
    expect(await KbCache.open(undefined)).toBeNull();
    const loaded = await load(null);
    expect(loaded.from).toBe("files");
    expect(JSON.stringify(loaded.planner.plan(REQUEST))).toBe(expected);
    vi.stubGlobal("crypto", {});
    try {
      expect(await cacheKey(BUILD, FILES)).toBeNull();
      const cache = await freshCache();
      expect((await load(cache)).from).toBe("files");
      expect((await load(cache)).from).toBe("files");
    } finally {
      vi.unstubAllGlobals();
    }
  });

  it("reads the build's snapshot when this build wrote it, and loads the files when not", async () => {
    const snapshot = FoonPlanner.load(FILES, EMBEDDINGS).snapshot();
    const damaged = snapshot.slice();
    damaged[100]! ^= 0x04;
    const cases = [
      { shipped: shippedSnapshot(BUILD.padEnd(64, "0"), snapshot), from: "build" },
      { shipped: shippedSnapshot("build-b".padEnd(64, "0"), snapshot), from: "files" },
      { shipped: shippedSnapshot(BUILD.padEnd(64, "0"), damaged), from: "files" },
      { shipped: snapshot, from: "files" },
    ];
    for (const { shipped, from } of cases) {
      let asked = 0;
      const files = (): Promise<KnowledgeBaseFile[]> => Promise.resolve(FILES).finally(() => asked++);
      const loaded = await loadKnowledgeBase(await freshCache(), BUILD.padEnd(64, "0"), { shipped, files }, EMBEDDINGS);
      expect(loaded.from).toBe(from);
      expect(asked).toBe(from === "build" ? 0 : 1);
      expect(JSON.stringify(loaded.planner.plan(REQUEST))).toBe(expected);
    }
  });
});
