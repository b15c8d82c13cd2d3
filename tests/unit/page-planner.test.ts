// The page's planner: the worker plans until the page has its own copy, then the copy makes the re-plans
// (the same plans, loaded from the worker's snapshot or else its files), and a new knowledge base, a copy
// refused or a copy that cannot load leave it to the worker.

import { describe, expect, it } from "vitest";
import { CopyablePlanner, PagePlanner } from "../../src/app/page-planner";
import { compiledModule, FoonPlanner, type KnowledgeBaseFile, type PlanRequest } from "../../src/planner/index";
import { initPlannerFromDisk, readEmbeddings, readKnowledgeBase, STARTER_KB_DIR } from "../../src/planner/node";
import type { LoadedKnowledgeBase, PlannerCopy } from "../../src/worker/protocol";
import { encode } from "./helpers";

initPlannerFromDisk();
const FILES = readKnowledgeBase(STARTER_KB_DIR);
const EMBEDDINGS = readEmbeddings();
const REQUEST: PlanRequest = { query: { type: "salad", ingredients: [{ object: "tomato", state: "diced" }, { object: "cool whip", state: "whole" }] } };

/** A worker stand-in: plans with its own planner in this thread and counts what it was asked. */
class FakeWorker implements CopyablePlanner {
  plans = 0;
  private planner = FoonPlanner.load(FILES, EMBEDDINGS);
  constructor(private copyOf: (module: WebAssembly.Module) => PlannerCopy | null = (module) => ({ module, files: FILES, embeddings: EMBEDDINGS, snapshot: this.planner.snapshot() })) {}

  private loaded(): Promise<LoadedKnowledgeBase> {
    return Promise.resolve({ name: "kb", stats: this.planner.stats(), vocabulary: this.planner.vocabulary(), warnings: [], embeddings: true, from: "files", phases: [] });
  }
  loadUrl(): Promise<LoadedKnowledgeBase> {
    return this.loaded();
  }
  loadFiles(files: KnowledgeBaseFile[]): Promise<LoadedKnowledgeBase> {
    this.planner = FoonPlanner.load(files, EMBEDDINGS);
    this.copyOf = (module) => ({ module, files, embeddings: EMBEDDINGS, snapshot: this.planner.snapshot() });
    return this.loaded();
  }
  prefetch(): void {}
  plan(request: PlanRequest): Promise<{ plan: ReturnType<FoonPlanner["plan"]>; ms: number }> {
    this.plans++;
    return Promise.resolve({ plan: this.planner.plan(request), ms: 0 });
  }
  exportPlan(): Promise<string> {
    return Promise.resolve("");
  }
  copy(): Promise<PlannerCopy | null> {
    return Promise.resolve(this.copyOf(compiledModule()!));
  }
  dispose(): void {}
}

describe("the page's planner", () => {
  it("makes re-plans with its own copy once the worker made a plan, and they are the worker's plans", async () => {
    const worker = new FakeWorker();
    const page = new PagePlanner(worker);
    const first = await page.plan(REQUEST);
    expect(worker.plans).toBe(1);
    await page.copied();
    expect(page.onPage).toBe(true);
    const again = await page.plan(REQUEST);
    expect(worker.plans).toBe(1);
    expect(JSON.stringify(again?.plan)).toBe(JSON.stringify(first?.plan));
  });

  it("drops its copy when another knowledge base is loaded, and copies that one after the worker's next plan", async () => {
    const worker = new FakeWorker();
    const page = new PagePlanner(worker);
    await page.plan(REQUEST);
    await page.copied();
    await page.loadFiles(FILES.filter((_, i) => i % 2 === 0));
    expect(page.onPage).toBe(false);
    const fromWorker = await page.plan(REQUEST);
    expect(worker.plans).toBe(2);
    await page.copied();
    expect(page.onPage).toBe(true);
    const fromCopy = await page.plan(REQUEST);
    expect(worker.plans).toBe(2);
    expect(JSON.stringify(fromCopy?.plan)).toBe(JSON.stringify(fromWorker?.plan));
  });

  it("loads its copy from the worker's snapshot, and from the files when the snapshot cannot be read", async () => {
    const bad = [{ name: "bad.txt", bytes: encode("S\tin\t[bowl\n") }];
    const snapshot = FoonPlanner.load(FILES, EMBEDDINGS).snapshot();
    const damaged = snapshot.slice();
    damaged[damaged.length >> 1]! ^= 0xff;
    const copies = [
      (module: WebAssembly.Module) => ({ module, files: bad, embeddings: EMBEDDINGS, snapshot }), // the files are not read
      (module: WebAssembly.Module) => ({ module, files: FILES, embeddings: EMBEDDINGS, snapshot: damaged }),
    ];
    for (const copyOf of copies) {
      const worker = new FakeWorker(copyOf);
      const page = new PagePlanner(worker);
      const fromWorker = await page.plan(REQUEST);
      await page.copied();
      expect(page.onPage).toBe(true);
      const fromCopy = await page.plan(REQUEST);
      expect(worker.plans).toBe(1);
      expect(JSON.stringify(fromCopy?.plan)).toBe(JSON.stringify(fromWorker?.plan));
    }
  });

  it("leaves every plan to the worker when the worker gives no copy or the copy cannot load", async () => {
    for (const copyOf of [() => null, (module: WebAssembly.Module) => ({ module, files: [{ name: "bad.txt", bytes: encode("S\tin\t[bowl\n") }], snapshot: null })]) {
      const worker = new FakeWorker(copyOf);
      const page = new PagePlanner(worker);
      await page.plan(REQUEST);
      await page.copied();
      expect(page.onPage).toBe(false);
      await page.plan(REQUEST);
      expect(worker.plans).toBe(2);
    }
  });

  it("gives a bad request's error as the worker would, and keeps its copy", async () => {
    const page = new PagePlanner(new FakeWorker());
    await page.plan(REQUEST);
    await page.copied();
    await expect(page.plan({ query: { type: "salad", ingredients: [] }, mode: "nonsense" } as unknown as PlanRequest)).rejects.toMatchObject({ code: "bad_query" });
    expect(page.onPage).toBe(true);
  });
});
