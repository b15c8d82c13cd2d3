// The one module that owns the WASM planner: initialisation behind a single promise, typed calls,
// and errors as `PlannerError` with a stable code. Views and the CLI use only this module.

import initWasmModule, { initSync, KnowledgeBaseLoader, type Planner as WasmPlanner } from "../../wasm/pkg/foon_wasm.js";
import type { ExportFormat, FoonErrorData, KnowledgeBaseFile, Plan, PlanRequest, Stats, Vocabulary } from "./types";
import { scanVocabulary } from "./vocabulary";
import { PlannerError, toPlannerError } from "./errors";

export { describeError, PlannerError, toPlannerError } from "./errors";

export type * from "./types";

let ready: Promise<void> | null = null;
let initialised = false;

/** Initialises the WASM module once (browser: fetches it next to the glue code, or from `source`). */
export function initPlanner(source?: URL | string | Response | BufferSource): Promise<void> {
  ready ??= initWasmModule(source === undefined ? undefined : { module_or_path: source }).then(() => {
    initialised = true;
  });
  return ready;
}

/** Initialises the WASM module synchronously from its bytes (Node, Vitest, workers that hold the bytes). */
export function initPlannerSync(bytes: BufferSource): void {
  if (initialised) return;
  initSync({ module: bytes });
  initialised = true;
  ready = Promise.resolve();
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

/** A knowledge base loaded into the planner. Free it with `free()` when replaced. */
/** The planning calls of the WASM `Planner` (JSON in, JSON or text out), typed here once. */
interface WasmPlanningApi {
  plan(request: string): string;
  export(request: string, format: string): string;
}

export class FoonPlanner {
  private constructor(
    private readonly handle: WasmPlanner,
    private readonly vocab: Vocabulary,
  ) {}

  /** Parses and merges knowledge-base files; a malformed file throws a PlannerError naming file and line. */
  static load(files: readonly KnowledgeBaseFile[]): FoonPlanner {
    assertInitialised();
    const loader = new KnowledgeBaseLoader();
    try {
      for (const file of files) loader.addFile(file.name, file.bytes);
    } catch (thrown) {
      loader.free();
      throw toPlannerError(thrown);
    }
    try {
      const handle = loader.finish(); // finish() consumes the loader, even when it fails
      return new FoonPlanner(handle, scanVocabulary(files));
    } catch (thrown) {
      throw toPlannerError(thrown);
    }
  }

  stats(): Stats {
    return parseJson<Stats>(() => this.handle.stats());
  }

  /** Problems that did not stop the load (units skipped, with file and line). */
  warnings(): FoonErrorData[] {
    return parseJson<FoonErrorData[]>(() => this.handle.warnings());
  }

  /** Dish classes with their recipes, labels and states of the loaded files (for the query editor). */
  vocabulary(): Vocabulary {
    return this.vocab;
  }

  /** Whether this WASM build has the planning calls (plan, export). */
  canPlan(): boolean {
    const api = this.handle as unknown as Partial<WasmPlanningApi>;
    return typeof api.plan === "function" && typeof api.export === "function";
  }

  private planningApi(): WasmPlanningApi {
    if (!this.canPlan()) {
      throw new PlannerError({ code: "internal", message: "this WebAssembly build has no planner (plan/export): rebuild it with `npm run build:wasm`" });
    }
    return this.handle as unknown as WasmPlanningApi;
  }

  /** Plans a query: reference goal node, reference task tree, modification (docs/plan-format.md). */
  plan(request: PlanRequest): Plan {
    const api = this.planningApi();
    return parseJson<Plan>(() => api.plan(JSON.stringify(request)));
  }

  /** The plan of `request` as FOON text, JSON, PDDL or progress-line JSON. */
  export(request: PlanRequest, format: ExportFormat): string {
    const api = this.planningApi();
    try {
      return api.export(JSON.stringify(request), format);
    } catch (thrown) {
      throw toPlannerError(thrown);
    }
  }

  free(): void {
    this.handle.free();
  }
}
