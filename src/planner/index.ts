// The one module that owns the WASM planner: initialisation behind a single promise, typed calls,
// and errors as `PlannerError` with a stable code. Views and the CLI use only this module.

import initWasmModule, { initSync, KnowledgeBaseLoader, Planner as WasmPlanner } from "../../wasm/pkg/foon_wasm.js";
import type { ExportFormat, FoonErrorData, KnowledgeBaseFile, Plan, PlanNode, PlanRequest, PlanUnit, SimilarResult, Stats, Vocabulary } from "./types";
import { PlannerError, toPlannerError } from "./errors";

// The error class lives in errors.ts so that the page can use it without the WASM glue (the worker owns it).
export { describeError, PlannerError, toPlannerError } from "./errors";

export type * from "./types";

let ready: Promise<void> | null = null;
let initialised = false;
let memory: WebAssembly.Memory | null = null;

// The smallest module with a SIMD instruction (a function returning `v128.const 0`): the planner is built
// with WebAssembly SIMD, and an engine without it would fail to compile the planner with a cryptic error.
const SIMD_PROBE = new Uint8Array([
  0x00, 0x61, 0x73, 0x6d, 0x01, 0x00, 0x00, 0x00, // magic, version
  0x01, 0x05, 0x01, 0x60, 0x00, 0x01, 0x7b, // type section: () -> v128
  0x03, 0x02, 0x01, 0x00, // function section
  0x0a, 0x16, 0x01, 0x14, 0x00, 0xfd, 0x0c, ...new Array<number>(16).fill(0), 0x0b, // code: v128.const 0
]);

/** Fails with a clear `unsupported` error where WebAssembly SIMD is missing (browsers before 2021–2023). */
function assertSimd(): void {
  if (!WebAssembly.validate(SIMD_PROBE)) {
    throw new PlannerError({
      code: "unsupported",
      message: "this browser's WebAssembly has no SIMD, which the planner needs: use Chrome or Edge 91, Firefox 89, Safari 16.4 or later",
    });
  }
}

/** The compiled module once initialised: another thread (the page, for re-plans) instantiates it without compiling it again. */
let compiled: WebAssembly.Module | null = null;

/**
 * Initialises the WASM module once (browser: fetches it next to the glue code, or from `source`; a compiled
 * `WebAssembly.Module`, such as the worker's `compiledModule()`, is only instantiated).
 */
export function initPlanner(source?: URL | string | Response | BufferSource | WebAssembly.Module): Promise<void> {
  try {
    assertSimd();
  } catch (e) {
    return Promise.reject(e);
  }
  if (ready === null) {
    if (source instanceof WebAssembly.Module) compiled = source;
    ready = initWasmModule(source === undefined ? undefined : { module_or_path: source }).then((exports) => {
      memory = exports.memory;
      initialised = true;
    });
  }
  return ready;
}

/** The compiled module this thread was given (`initPlanner(module)`, `initPlannerSync`), else null. */
export function compiledModule(): WebAssembly.Module | null {
  return compiled;
}

/** Initialises the WASM module synchronously from its bytes (Node, Vitest, workers that hold the bytes). */
export function initPlannerSync(bytes: BufferSource): void {
  if (initialised) return;
  assertSimd();
  compiled = new WebAssembly.Module(bytes);
  memory = initSync({ module: compiled }).memory;
  initialised = true;
  ready = Promise.resolve();
}

/** Size of the WASM linear memory in bytes (it only grows, so this is also its peak). */
export function wasmMemoryBytes(): number {
  return memory?.buffer.byteLength ?? 0;
}

function assertInitialised(): void {
  if (!initialised) {
    throw new PlannerError({
      code: "not_initialised",
      message: "the planner's WebAssembly module is not initialised: await initPlanner() (browser) or call initPlannerSync(bytes) (Node) first",
    });
  }
}

function parseJson<T>(call: () => string): T {
  let text: string;
  try {
    text = call();
  } catch (thrown) {
    throw toPlannerError(thrown);
  }
  return JSON.parse(text) as T;
}

/** A unit as the WASM module writes it: a node written in full in an earlier place comes as its number. */
interface WireUnit extends Omit<PlanUnit, "inputs" | "outputs"> {
  inputs: (PlanNode | number)[];
  outputs: (PlanNode | number)[];
}

type WirePlan = Omit<Plan, "units"> & { units: WireUnit[] };

/**
 * Puts each node number back as the node it stands for: number k is the k-th node written in full
 * (`wasm/core/src/plan_json.rs`). A node that several units share becomes one object, as in the planner.
 */
function withSharedNodes(wire: WirePlan): Plan {
  const written: PlanNode[] = [];
  const resolve = (list: (PlanNode | number)[]): void => {
    for (let i = 0; i < list.length; i++) {
      const item = list[i];
      if (typeof item !== "number") {
        if (item !== undefined) written.push(item);
        continue;
      }
      const node = written[item];
      if (node === undefined) throw new PlannerError({ code: "internal", message: `planner failure: plan refers to node ${item}, of ${written.length} written` });
      list[i] = node;
    }
  };
  // in place: the parsed objects are the plan's own, and copying them costs a tenth of the parse
  for (const unit of wire.units) {
    resolve(unit.inputs);
    resolve(unit.outputs);
  }
  // every number was replaced by its node just above
  return wire as Plan;
}

/** JSON text of a request; a value JSON cannot represent (undefined, a cycle, a BigInt) is a bad query. */
function requestJson(value: unknown, what: string): string {
  let text: string | undefined;
  try {
    text = JSON.stringify(value);
  } catch (thrown) {
    const reason = `${what}: ${thrown instanceof Error ? thrown.message : String(thrown)}`;
    throw new PlannerError({ code: "bad_query", message: `${reason} (bad_query)`, reason });
  }
  if (text === undefined) {
    const reason = `${what}: not a JSON value`;
    throw new PlannerError({ code: "bad_query", message: `${reason} (bad_query)`, reason });
  }
  return text;
}

/** A knowledge base loaded into the planner. Free it with `free()` when replaced. */
export class FoonPlanner {
  private constructor(private readonly handle: WasmPlanner) {}

  /**
   * Parses and merges knowledge-base files; a malformed file throws a PlannerError naming file and line.
   * `embeddings` is the food embedding table (public/data/food-embeddings.bin); without it the planner
   * matches ingredient names exactly.
   */
  static load(files: readonly KnowledgeBaseFile[], embeddings?: Uint8Array): FoonPlanner {
    assertInitialised();
    const loader = new KnowledgeBaseLoader();
    try {
      for (const file of files) loader.addFile(file.name, file.bytes);
    } catch (thrown) {
      loader.free();
      throw toPlannerError(thrown);
    }
    try {
      const handle = loader.finish(embeddings); // finish() consumes the loader, even when it fails
      return new FoonPlanner(handle);
    } catch (thrown) {
      throw toPlannerError(thrown);
    }
  }

  /**
   * The planner of a knowledge base saved with `snapshot()`, without parsing and merging its files again; null
   * when the bytes are damaged or were written by another version of the module (load the files then).
   */
  static fromSnapshot(snapshot: Uint8Array, embeddings?: Uint8Array): FoonPlanner | null {
    assertInitialised();
    try {
      const handle = WasmPlanner.fromSnapshot(snapshot, embeddings);
      return handle === undefined ? null : new FoonPlanner(handle);
    } catch (thrown) {
      throw toPlannerError(thrown);
    }
  }

  /** The loaded (parsed and merged) knowledge base as bytes, for `fromSnapshot`. */
  snapshot(): Uint8Array {
    return this.handle.snapshot();
  }

  /** Dish classes with their recipes, labels and states of the loaded files (for the query editor). */
  vocabulary(): Vocabulary {
    return parseJson<Vocabulary>(() => this.handle.vocabulary());
  }

  stats(): Stats {
    return parseJson<Stats>(() => this.handle.stats());
  }

  /** Plans a query: reference goal, reference task tree, modification (unless `modify: false`). */
  plan(request: PlanRequest): Plan {
    const json = requestJson(request, "plan request");
    return withSharedNodes(parseJson<WirePlan>(() => this.handle.plan(json)));
  }

  /** Plans a query and renders it: plan JSON, FOON text (plain dialect), PDDL, or progress-line JSON. */
  exportPlan(request: PlanRequest, format: ExportFormat): string {
    const json = requestJson(request, "plan request");
    try {
      return this.handle.export(json, String(format));
    } catch (thrown) {
      throw toPlannerError(thrown);
    }
  }

  /** The knowledge-base ingredients most similar to each name, best first, as the planner ranks them. */
  similar(names: readonly string[], top = 5): SimilarResult[] {
    const json = requestJson(names, "names (a JSON array of strings)");
    return parseJson<SimilarResult[]>(() => this.handle.similar(json, top));
  }

  /** Problems that did not stop the load (units skipped, with file and line). */
  warnings(): FoonErrorData[] {
    return parseJson<FoonErrorData[]>(() => this.handle.warnings());
  }

  free(): void {
    this.handle.free();
  }
}
