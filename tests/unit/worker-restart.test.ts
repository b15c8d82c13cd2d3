// No lost work when the planner worker crashes: the client starts a new worker, loads the last knowledge
// base into it again and resends the calls that were waiting, once. Driven with a scripted fake worker.
import { describe, expect, it } from "vitest";
import { WorkerPlanner } from "../../src/worker/client";
import type { WorkerRequest, WorkerResponse } from "../../src/worker/protocol";
import type { Plan } from "../../src/planner/types";

type Script = (message: WorkerRequest, worker: FakeWorker) => void;

/** A worker that answers as the real one would, and can be told to crash on a message. */
class FakeWorker {
  onmessage: ((event: MessageEvent<WorkerResponse>) => void) | null = null;
  onerror: ((event: ErrorEvent) => void) | null = null;
  readonly received: WorkerRequest[] = [];
  terminated = false;
  constructor(private readonly script: Script) {}
  postMessage(message: WorkerRequest): void {
    this.received.push(message);
    queueMicrotask(() => {
      if (!this.terminated) this.script(message, this);
    });
  }
  terminate(): void {
    this.terminated = true;
  }
  answer(response: WorkerResponse): void {
    this.onmessage?.({ data: response } as MessageEvent<WorkerResponse>);
  }
  crash(message = "RuntimeError: unreachable"): void {
    this.onerror?.({ message, preventDefault: () => undefined } as unknown as ErrorEvent);
  }
}

const KB = { name: "kb", stats: {} as never, vocabulary: {} as never, warnings: [], embeddings: false, from: "files" as const, phases: [] };
const PLAN = { units: [] } as unknown as Plan;
const REQUEST = { query: { type: "salad", ingredients: [{ object: "tomato", state: "" }] } };

/** Answers loads and plans; `crashOn(n, message)` decides whether the n-th worker crashes on a message. */
function setup(crashOn: (workerIndex: number, message: WorkerRequest) => "throw" | "trap" | null) {
  const workers: FakeWorker[] = [];
  const restarts: string[] = [];
  const client = new WorkerPlanner({
    createWorker: () => {
      const index = workers.length;
      const w = new FakeWorker((message, self) => {
        const crash = crashOn(index, message);
        if (crash === "throw") return self.crash();
        if (crash === "trap") return self.answer({ type: "error", id: message.id, error: { code: "internal", message: "planner failure: unreachable" } });
        if (message.type === "load") self.answer({ type: "loaded", id: message.id, kb: KB });
        else if (message.type === "plan") self.answer({ type: "planned", id: message.id, plan: PLAN, ms: 1 });
        else self.answer({ type: "error", id: message.id, error: { code: "bad_query", message: "unknown export format" } });
      });
      workers.push(w);
      return w as unknown as Worker;
    },
    onRestart: (reason) => restarts.push(reason),
  });
  return { client, workers, restarts };
}

describe("a crashed planner worker", () => {
  it("is restarted with the last knowledge base, and the waiting plan is resumed", async () => {
    const { client, workers, restarts } = setup((index, m) => (index === 0 && m.type === "plan" ? "throw" : null));
    await client.loadFiles([{ name: "mine.txt", bytes: new Uint8Array([1]) }]);
    const result = await client.plan(REQUEST);
    expect(result?.plan).toBe(PLAN);
    expect(workers.length).toBe(2);
    expect(workers[0].terminated).toBe(true);
    // the new worker got the user's files again, then the plan
    expect(workers[1].received.map((m) => m.type)).toEqual(["load", "plan"]);
    const reload = workers[1].received[0];
    expect(reload.type === "load" && reload.source.kind === "files" && reload.source.files[0].name).toBe("mine.txt");
    expect(restarts).toEqual(["planner worker failed: RuntimeError: unreachable"]);
  });

  it("holds calls made after a crash until the new worker has the knowledge base again", async () => {
    const { client, workers } = setup(() => null);
    await client.loadFiles([{ name: "mine.txt", bytes: new Uint8Array([1]) }]);
    workers[0].crash(); // between calls
    expect((await client.plan(REQUEST))?.plan).toBe(PLAN);
    expect(workers[1].received.map((m) => m.type)).toEqual(["load", "plan"]);
  });

  it("is restarted when its WASM module traps (an internal 'planner failure' answer)", async () => {
    const { client, workers } = setup((index, m) => (index === 0 && m.type === "plan" ? "trap" : null));
    await client.loadUrl("kb/default.foon");
    expect((await client.plan(REQUEST))?.plan).toBe(PLAN);
    expect(workers.length).toBe(2);
  });

  it("reports a request that crashes the new worker too, and keeps working for the next one", async () => {
    let poisoned = true;
    const { client, workers } = setup((_index, m) => (poisoned && m.type === "plan" ? "throw" : null));
    await client.loadUrl("kb/default.foon");
    await expect(client.plan(REQUEST)).rejects.toMatchObject({ code: "internal", message: expect.stringContaining("twice on this request") });
    poisoned = false;
    expect((await client.plan(REQUEST))?.plan).toBe(PLAN);
    expect(workers.length).toBe(3);
  });

  it("stops restarting after three crashes in a minute", async () => {
    const { client, workers } = setup((_index, m) => (m.type === "plan" ? "throw" : null));
    await client.loadUrl("kb/default.foon");
    await expect(client.plan(REQUEST)).rejects.toMatchObject({ code: "internal" });
    await expect(client.plan(REQUEST)).rejects.toMatchObject({ code: "internal", message: expect.stringContaining("3 times in a minute") });
    expect(workers.length).toBeLessThanOrEqual(5);
  });

  it("reports a worker whose script cannot be loaded, and does not keep starting new ones", async () => {
    const workers: FakeWorker[] = [];
    const client = new WorkerPlanner({
      createWorker: () => {
        // a module worker's failed script load: an error event without a message, soon after it is made
        const w = new FakeWorker(() => undefined);
        queueMicrotask(() => w.crash(""));
        workers.push(w);
        return w as unknown as Worker;
      },
    });
    await expect(client.loadUrl("kb/default.foon")).rejects.toMatchObject({ message: expect.stringContaining("Access-Control-Allow-Origin") });
    const started = workers.length;
    // the client and the fake worker run on microtasks only (no timers): once these have all run, as they
    // have when the next macrotask starts, nothing more can start a worker
    await new Promise((resolve) => setImmediate(resolve));
    expect(workers.length).toBe(started);
    expect(started).toBeLessThanOrEqual(5);
    expect(workers.every((w) => w.terminated)).toBe(true);
  });

  it("does not restart on ordinary errors (a bad request is the caller's)", async () => {
    const { client, workers } = setup(() => null);
    await client.loadUrl("kb/default.foon");
    await expect(client.exportPlan(REQUEST, "json")).rejects.toMatchObject({ code: "bad_query" });
    expect(workers.length).toBe(1);
  });
});
