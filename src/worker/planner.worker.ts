// The planner's Web Worker: owns the WASM module and the loaded knowledge base, so planning never blocks
// the page. Plan requests are coalesced: only the newest pending one runs, older ones are answered
// `superseded` (a WASM call cannot be interrupted, but the queue behind it can be dropped).

import { compiledModule, FoonPlanner, initPlanner, PlannerError, toPlannerError } from "../planner/index";
import type { PlanRequest } from "../planner/types";
import { buildDigest, type Download, KbCache, loadKnowledgeBase } from "./kb-cache";
import { LatestOnly } from "./latest";
import type { KnowledgeBaseSource, LoadedKnowledgeBase, LoadPhase, LoadPhaseName, PlannerCopy, WorkerRequest, WorkerResponse } from "./protocol";

const scope = self as unknown as DedicatedWorkerGlobalScope;

let planner: FoonPlanner | null = null;
/**
 * The loaded knowledge base's files and its snapshot (made and cached once the first plan is out), for a copy
 * of the planner on the page's thread.
 */
let loaded: (Omit<PlannerCopy, "module" | "snapshot"> & { snapshot: () => Promise<Uint8Array | null> }) | null = null;

/**
 * The largest knowledge base the page may load a copy of, by its snapshot (or else its FOON text): its load
 * blocks the page's thread (60-70 ms from the 88 kB snapshot of the 0.7 MB starter, 0.1-0.3 s from its text,
 * on a loaded 2-core VM), and its memory is held twice.
 */
const MAX_COPY_SNAPSHOT_BYTES = 250_000;
const MAX_COPY_TEXT_BYTES = 2_000_000;
const pendingPlans = new LatestOnly<{ id: number; request: PlanRequest }>();
let planScheduled = false;

function reply(message: WorkerResponse): void {
  scope.postMessage(message);
}

/**
 * The module next to the glue code, compiled as it streams in (from its bytes where the host sends another
 * type than `application/wasm`), and its bytes' digest, which keys the knowledge-base cache to this build.
 * Compiled here rather than by the glue so that the page can be given it.
 */
async function compileModule(): Promise<{ module: WebAssembly.Module; build: string | null }> {
  const url = new URL("../../wasm/pkg/foon_wasm_bg.wasm", import.meta.url);
  const response = await fetch(url);
  if (!response.ok) throw new PlannerError({ code: "internal", message: `${url.href}: HTTP ${response.status}` });
  if ((response.headers.get("content-type") ?? "").startsWith("application/wasm")) {
    const [module, build] = await Promise.all([WebAssembly.compileStreaming(response.clone()), response.arrayBuffer().then(buildDigest)]);
    return { module, build };
  }
  const bytes = await response.arrayBuffer();
  return { module: await WebAssembly.compile(bytes), build: await buildDigest(bytes) };
}

// The module is fetched and compiled from the worker's start, while the page still decides what to load;
// a failure here is reported by the load that awaits the same promise.
const wasmReady = compileModule().then(async ({ module, build }) => {
  await initPlanner(module);
  return build;
});
wasmReady.catch(() => undefined);
const cacheReady = KbCache.open();

/**
 * The bundled knowledge base, and the snapshot of it that `npm run build:kb` writes with this build's module:
 * loading the bundled one downloads and reads the snapshot instead of its text (which stays the source, for
 * authoring and export, and is loaded instead when the snapshot is another build's).
 */
const BUNDLED_KB = new URL("../../public/kb/default.foon", import.meta.url).href;
const BUNDLED_SNAPSHOT = new URL("../../public/kb/default.kb", import.meta.url).href;

/** What a load of `url` downloads first: the bundled knowledge base's snapshot, else the URL itself. */
const firstDownload = (url: string): string => (url === BUNDLED_KB ? BUNDLED_SNAPSHOT : url);

/** Knowledge-base downloads started by a prefetch, each taken by the next load of its URL. */
const prefetched = new Map<string, Promise<Response>>();

async function fetchFile(url: string): Promise<Response> {
  const early = prefetched.get(url);
  prefetched.delete(url);
  const response = await (early ?? fetch(url));
  if (!response.ok) throw new PlannerError({ code: "internal", message: `${url}: HTTP ${response.status}` });
  // hosts with a page fallback answer a missing file with their index page: say so, not "unknown line"
  if ((response.headers.get("content-type") ?? "").includes("text/html")) {
    throw new PlannerError({ code: "internal", message: `${url}: not found (the server sent a web page, not a FOON file)` });
  }
  return response;
}

const fileName = (url: string): string => new URL(url).pathname.split("/").pop() ?? "knowledge base";

async function textFiles(url: string): Promise<{ name: string; bytes: Uint8Array }[]> {
  const response = await fetchFile(url);
  return [{ name: fileName(url), bytes: new Uint8Array(await response.arrayBuffer()) }];
}

async function download(source: KnowledgeBaseSource): Promise<{ name: string } & Download> {
  if (source.kind === "files") {
    prefetched.clear(); // the page restored the user's own files: what it fetched in case it did not is not needed
    return { name: source.files.map((f) => f.name).join(", "), shipped: null, files: () => Promise.resolve(source.files) };
  }
  const name = fileName(source.url);
  if (source.url === BUNDLED_KB) {
    const shipped = await fetchFile(BUNDLED_SNAPSHOT).then(
      async (r) => new Uint8Array(await r.arrayBuffer()),
      () => null, // built without one: the text is loaded
    );
    return { name, shipped, files: () => textFiles(source.url) };
  }
  const files = await textFiles(source.url);
  return { name, shipped: null, files: () => Promise.resolve(files) };
}

// The embedding table is fetched once per URL and reused for every knowledge base loaded after it.
const embeddingTables = new Map<string, Promise<Uint8Array | undefined>>();
function embeddingsOf(url: string | undefined): Promise<Uint8Array | undefined> {
  if (url === undefined) return Promise.resolve(undefined);
  let table = embeddingTables.get(url);
  if (table === undefined) {
    table = fetch(url)
      .then(async (r) => (r.ok ? new Uint8Array(await r.arrayBuffer()) : undefined))
      .catch(() => undefined); // no table: the planner still works, with exact name matching
    embeddingTables.set(url, table);
  }
  return table;
}

/** Wall-clock milliseconds, comparable with the page's (`performance.now()` is per context). */
const clock = (): number => performance.timeOrigin + performance.now();

/** Runs `work`, adding its phase to `phases` when it settles. */
async function phase<T>(phases: LoadPhase[], name: LoadPhaseName, work: () => Promise<T> | T): Promise<T> {
  const start = clock();
  try {
    return await work();
  } finally {
    phases.push({ name, start, end: clock() });
  }
}

async function load(id: number, source: KnowledgeBaseSource, embeddingsUrl: string | undefined): Promise<void> {
  const phases: LoadPhase[] = [];
  const [build, downloaded, embeddings] = await Promise.all([
    phase(phases, "wasm", () => wasmReady),
    phase(phases, "kb download", () => download(source)),
    phase(phases, "embeddings download", () => embeddingsOf(embeddingsUrl)),
  ]);
  // A failed load keeps the previous knowledge base: the user sees the error and can fix the file.
  const next = await phase(phases, "kb load", async () => loadKnowledgeBase(await cacheReady, build, downloaded, embeddings));
  planner?.free();
  planner = next.planner;
  let snapshot: Promise<Uint8Array | null> | null = null;
  loaded = { files: next.files, embeddings, snapshot: () => (snapshot ??= next.save().catch(() => null)) };
  const kb: LoadedKnowledgeBase = {
    name: downloaded.name,
    stats: planner.stats(),
    vocabulary: planner.vocabulary(),
    warnings: planner.warnings(),
    embeddings: embeddings !== undefined,
    from: next.from,
    phases,
  };
  reply({ type: "loaded", id, kb });
}

function runLatestPlan(): void {
  planScheduled = false;
  const job = pendingPlans.take();
  if (job === null) return;
  try {
    if (planner === null) throw new PlannerError({ code: "not_initialised", message: "no knowledge base is loaded yet" });
    const started = performance.now();
    const plan = planner.plan(job.request);
    reply({ type: "planned", id: job.id, plan, ms: performance.now() - started });
    // the knowledge base is cached once its first plan is out, not before
    void loaded?.snapshot();
  } catch (e) {
    reply({ type: "error", id: job.id, error: toPlannerError(e).toJSON() });
  }
}

/** What the page needs for its copy of the planner; null when nothing is loaded or it is too large to load there. */
async function copy(): Promise<PlannerCopy | null> {
  const module = compiledModule();
  const current = loaded;
  if (module === null || current === null) return null;
  const snapshot = await current.snapshot();
  const tooLarge =
    snapshot === null ? current.files.reduce((sum, f) => sum + f.bytes.byteLength, 0) > MAX_COPY_TEXT_BYTES : snapshot.byteLength > MAX_COPY_SNAPSHOT_BYTES;
  return tooLarge ? null : { module, files: current.files, embeddings: current.embeddings, snapshot };
}

scope.onmessage = (event: MessageEvent<WorkerRequest>): void => {
  const message = event.data;
  switch (message.type) {
    case "load":
      load(message.id, message.source, message.embeddingsUrl).catch((e: unknown) => reply({ type: "error", id: message.id, error: toPlannerError(e).toJSON() }));
      break;
    case "prefetch":
      {
        const url = firstDownload(message.kbUrl);
        if (!prefetched.has(url)) {
          const early = fetch(url);
          early.catch(() => undefined); // a failure is the load's to report, if one comes
          prefetched.set(url, early);
        }
      }
      void embeddingsOf(message.embeddingsUrl);
      break;
    case "plan":
      {
        const replaced = pendingPlans.push({ id: message.id, request: message.request });
        if (replaced !== null) reply({ type: "superseded", id: replaced.id });
      }
      if (!planScheduled) {
        planScheduled = true;
        // run after the messages already queued, so a burst of edits plans once
        setTimeout(runLatestPlan, 0);
      }
      break;
    case "copy":
      void copy().then((copy) => reply({ type: "copied", id: message.id, copy }));
      break;
    case "export":
      try {
        if (planner === null) throw new PlannerError({ code: "not_initialised", message: "no knowledge base is loaded yet" });
        reply({ type: "exported", id: message.id, text: planner.exportPlan(message.request, message.format) });
      } catch (e) {
        reply({ type: "error", id: message.id, error: toPlannerError(e).toJSON() });
      }
      break;
  }
};
