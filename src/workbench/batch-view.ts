// Batch mode: choose a knowledge base and recipe-query files (or a folder), plan them all in a worker
// with a progress bar (cancellable), and show the metrics table and the sortable list of recipes.

import { metricsTable, variantsOf } from "../eval/aggregate";
import { recipesCsv, summaryCsv, type EvalResults } from "../eval/format";
import { parseQuery, sortQueries } from "../eval/queries";
import { ratingItems } from "../eval/ratings";
import type { PlanEntry, StoredBatch } from "../eval/storage";
import type { LoadedQuery, Variant } from "../eval/types";
import type { KnowledgeBaseFile } from "../planner/types";
import { byId, download, el, timestamp } from "./dom";
import type { RunRequest, WorkerMessage } from "./protocol";
import type { Workbench } from "./state";
import { metricsTables, recipeRows, recipeTable, type SortState } from "./tables";

const BUNDLED_KB = "kb/default.foon";
const EMBEDDINGS = "data/food-embeddings.bin";
const VARIANTS: Variant[] = ["modified", "unmodified"];
/** Results are stored in groups of this many (and at the end). */
const SAVE_EVERY = 20;

async function readQueryFiles(files: readonly File[]): Promise<{ queries: LoadedQuery[]; problems: string[] }> {
  const queries: LoadedQuery[] = [];
  const problems: string[] = [];
  for (const file of files) {
    if (!file.name.toLowerCase().endsWith(".json")) continue;
    const source = file.webkitRelativePath !== "" ? file.webkitRelativePath : file.name;
    try {
      queries.push(parseQuery(source, await file.text()));
    } catch (e) {
      problems.push(e instanceof Error ? e.message : String(e));
    }
  }
  return { queries: sortQueries(queries), problems };
}

async function knowledgeBase(files: readonly File[]): Promise<{ name: string; files: KnowledgeBaseFile[] }> {
  const chosen = files.filter((f) => /\.(txt|foon)$/i.test(f.name));
  if (chosen.length > 0) {
    const sorted = [...chosen].sort((a, b) => a.name.localeCompare(b.name));
    return {
      name: chosen.length === 1 ? chosen[0]!.name : `${chosen.length} files`,
      files: await Promise.all(sorted.map(async (f) => ({ name: f.name, bytes: new Uint8Array(await f.arrayBuffer()) }))),
    };
  }
  const url = new URL(BUNDLED_KB, document.baseURI);
  const response = await fetch(url);
  if (!response.ok) throw new Error(`${url.pathname}: HTTP ${response.status}`);
  return { name: "default.foon (bundled)", files: [{ name: "default.foon", bytes: new Uint8Array(await response.arrayBuffer()) }] };
}

/** The embedding table the app ships; null (exact matching) if it cannot be fetched. */
async function embeddings(): Promise<Uint8Array | null> {
  try {
    const response = await fetch(new URL(EMBEDDINGS, document.baseURI));
    return response.ok ? new Uint8Array(await response.arrayBuffer()) : null;
  } catch {
    return null;
  }
}

export class BatchView {
  private worker: Worker | null = null;
  /** Plans received and not stored yet. */
  private pending: PlanEntry[] = [];
  private sort: SortState = { column: "type", descending: false };
  private kbFiles: File[] = [];
  private queryFiles: File[] = [];
  private readonly status = byId("batch-status", HTMLElement);
  private readonly progress = byId("batch-progress", HTMLProgressElement);
  private readonly run = byId("run-batch", HTMLButtonElement);
  private readonly cancel = byId("cancel-batch", HTMLButtonElement);

  constructor(
    private readonly bench: Workbench,
    private readonly openRecipe: (key: string) => void,
  ) {
    const pick = (id: string, set: (files: File[]) => void): void => {
      const input = byId(id, HTMLInputElement);
      input.addEventListener("change", () => {
        set([...(input.files ?? [])]);
        this.describeChoice();
      });
    };
    pick("query-files", (f) => (this.queryFiles = f));
    pick("query-folder", (f) => (this.queryFiles = f));
    pick("kb-files", (f) => (this.kbFiles = f));
    pick("kb-folder", (f) => (this.kbFiles = f));
    this.run.addEventListener("click", () => void this.start());
    this.cancel.addEventListener("click", () => void this.stop());
    byId("export-results-json", HTMLButtonElement).addEventListener("click", () => this.exportResults("json"));
    byId("export-summary-csv", HTMLButtonElement).addEventListener("click", () => this.exportResults("summary"));
    byId("export-recipes-csv", HTMLButtonElement).addEventListener("click", () => this.exportResults("recipes"));
    bench.onChange(() => this.render());
    this.describeChoice();
    this.render();
  }

  private describeChoice(): void {
    const queries = this.queryFiles.filter((f) => f.name.toLowerCase().endsWith(".json")).length;
    const kb = this.kbFiles.filter((f) => /\.(txt|foon)$/i.test(f.name)).length;
    byId("batch-choice", HTMLElement).textContent =
      `${queries} query file${queries === 1 ? "" : "s"} chosen; knowledge base: ${kb === 0 ? "the bundled one" : `${kb} file${kb === 1 ? "" : "s"}`}.`;
    this.run.disabled = queries === 0 || this.worker !== null;
  }

  private setStatus(text: string, state: "idle" | "running" | "done" | "cancelled" | "failed"): void {
    this.status.textContent = text;
    this.status.dataset.state = state;
  }

  private async start(): Promise<void> {
    if (this.worker !== null) return;
    const { queries, problems } = await readQueryFiles(this.queryFiles);
    byId("batch-problems", HTMLElement).replaceChildren(...problems.map((p) => el("li", { text: p })));
    if (queries.length === 0) {
      this.setStatus("No valid query files.", "failed");
      return;
    }
    let kb: { name: string; files: KnowledgeBaseFile[] };
    try {
      kb = await knowledgeBase(this.kbFiles);
    } catch (e) {
      this.setStatus(`Cannot read the knowledge base: ${e instanceof Error ? e.message : String(e)}`, "failed");
      return;
    }
    const table = await embeddings();
    const batch: StoredBatch = {
      id: `${timestamp()}-${Math.random().toString(36).slice(2, 8)}`,
      created: new Date().toISOString(),
      knowledge_base: table === null ? `${kb.name}, exact names (no embedding table)` : kb.name,
      variants: VARIANTS,
      queries,
      records: [],
      status: "running",
    };
    await this.bench.startBatch(batch);
    const total = queries.length * VARIANTS.length;
    this.progress.max = total;
    this.progress.value = 0;
    this.setStatus(`Loading the knowledge base (${kb.name})…`, "running");

    const worker = new Worker(new URL("./worker.ts", import.meta.url), { type: "module" });
    this.worker = worker;
    this.cancel.disabled = false;
    this.describeChoice();
    this.pending = [];
    const flush = (status: StoredBatch["status"]): Promise<void> => this.flush(status);
    worker.onmessage = (event: MessageEvent<WorkerMessage>) => {
      const message = event.data;
      switch (message.kind) {
        case "loaded":
          this.setStatus(`Planning ${queries.length} queries × ${VARIANTS.length} variants (${message.subgraphs} recipes in the knowledge base)…`, "running");
          break;
        case "result":
          batch.records.push(message.record);
          if (message.plan !== null) this.pending.push({ recipe: message.record.recipe, variant: message.record.variant, plan: message.plan });
          this.progress.value = message.done;
          this.status.textContent = `Planned ${message.done} of ${message.total}.`;
          if (message.done % SAVE_EVERY === 0) void flush("running");
          break;
        case "finished":
          this.finish();
          void flush("done").then(() => this.setStatus(`Done: ${batch.records.length} plans of ${queries.length} queries.`, "done"));
          break;
        case "failed":
          this.finish();
          void flush("failed").then(() => this.setStatus(`The batch failed: ${message.message}`, "failed"));
          break;
      }
    };
    worker.onerror = (event) => {
      this.finish();
      void flush("failed").then(() => this.setStatus(`The batch worker failed: ${event.message}`, "failed"));
    };
    const request: RunRequest = { kind: "run", knowledgeBase: kb.files, embeddings: table, queries, variants: VARIANTS };
    worker.postMessage(request, [...kb.files.map((f) => f.bytes.buffer), ...(table === null ? [] : [table.buffer])]);
  }

  private async flush(status: StoredBatch["status"]): Promise<void> {
    const entries = this.pending;
    this.pending = [];
    await this.bench.addResults(entries, status);
  }

  private finish(): void {
    this.worker?.terminate();
    this.worker = null;
    this.cancel.disabled = true;
    this.describeChoice();
  }

  private async stop(): Promise<void> {
    if (this.worker === null) return;
    this.finish();
    const batch = this.bench.batch;
    await this.flush("cancelled");
    this.setStatus(`Cancelled after ${batch?.records.length ?? 0} of ${this.progress.max} plans.`, "cancelled");
  }

  private exportResults(kind: "json" | "summary" | "recipes"): void {
    const batch = this.bench.batch;
    if (batch === null) return;
    const variants = variantsOf(batch.records);
    const table = variants.flatMap((v) => metricsTable(batch.records, v));
    if (kind === "json") {
      const results: EvalResults = { format: "foon-planner-eval", version: 1, knowledge_base: batch.knowledge_base, variants, table, records: batch.records };
      download(`eval-${batch.id}.json`, JSON.stringify(results, null, 2) + "\n", "application/json");
    } else if (kind === "summary") download(`eval-${batch.id}-summary.csv`, summaryCsv(table), "text/csv");
    else download(`eval-${batch.id}-recipes.csv`, recipesCsv(batch.records), "text/csv");
  }

  private lastRender = 0;
  private renderTimer: ReturnType<typeof setTimeout> | null = null;

  /** Renders now, or at most once a second while a batch runs. */
  render(): void {
    if (this.worker !== null) {
      const wait = this.lastRender + 1000 - performance.now();
      if (wait > 0) {
        this.renderTimer ??= setTimeout(() => {
          this.renderTimer = null;
          this.render();
        }, wait);
        return;
      }
    }
    this.lastRender = performance.now();
    this.renderNow();
  }

  private renderNow(): void {
    const batch = this.bench.batch;
    const blind = this.bench.settings.blind;
    const metrics = byId("metrics", HTMLElement);
    const list = byId("recipe-list", HTMLElement);
    for (const id of ["export-results-json", "export-summary-csv", "export-recipes-csv"]) byId(id, HTMLButtonElement).disabled = batch === null || blind;
    if (batch === null) {
      metrics.replaceChildren(el("p", { text: "No batch yet." }));
      list.replaceChildren();
      return;
    }
    if (this.worker === null && this.status.dataset.state === undefined) {
      this.setStatus(`Batch of ${batch.created.slice(0, 16).replace("T", " ")}: ${batch.records.length} plans of ${batch.queries.length} queries (${batch.status}), knowledge base ${batch.knowledge_base}.`, "idle");
    }
    const tables = metricsTables(batch.records);
    metrics.replaceChildren(
      ...(blind ? [el("p", { text: "Metrics are hidden in blind mode (they tell which plan was modified)." })] : tables.length === 0 ? [el("p", { text: "No plans yet." })] : tables),
    );
    const rater = this.bench.settings.rater;
    const rated = (q: LoadedQuery): number =>
      VARIANTS.reduce((n, variant) => n + ratingItems(q.query.ingredients).filter((i) => this.bench.rating({ rater, type: q.query.type, id: q.query.id, variant, ...i }) !== undefined).length, 0);
    const rows = recipeRows(batch.queries, batch.records, rated);
    list.replaceChildren(
      recipeTable(
        rows,
        this.sort,
        blind,
        (column) => {
          this.sort = { column, descending: this.sort.column === column ? !this.sort.descending : false };
          this.render();
        },
        (key) => this.openRecipe(key),
      ),
    );
  }
}
