// `npm run bench`: speed and memory of the planner in WASM under Node, printed as figures (never asserted).
// FOON-111 (plain dialect) with the 320 dev queries, then synthetic universal FOONs of 10x and 100x its size,
// made by relabelling copies of FOON-111 (every label of copy k gets the suffix " k<k>"). BENCH_SCALES=1,10
// leaves out the 100x one (its load alone takes tens of seconds); BENCH_ROUNDS sets the plan rounds. Then the
// same plans natively (the WASM/native ratio of this run) and the page in headless Chromium (BENCH_BROWSER=0
// leaves it out; scripts/bench-browser.ts).

import { spawnSync } from "node:child_process";
import { existsSync } from "node:fs";
import { join } from "node:path";
import { FoonPlanner, wasmMemoryBytes } from "../src/planner/index";
import { initPlannerFromDisk, readEmbeddings, readKnowledgeBase, ROOT } from "../src/planner/node";
import type { KnowledgeBaseFile, Plan, PlanRequest } from "../src/planner/types";
import { readQueries } from "../src/cli/queries";

const SHARED = process.env.FOON_SHARED ?? join(ROOT, "../shared");
const ROUNDS = Number(process.env.BENCH_ROUNDS ?? 3);

const percentile = (sorted: number[], p: number): number => sorted[Math.min(sorted.length - 1, Math.floor(p * sorted.length))] ?? 0;
const ms = (x: number): string => `${x.toFixed(3)} ms`;
const mb = (bytes: number): string => `${(bytes / 2 ** 20).toFixed(1)} MiB`;

/** Copy k of a FOON file with every object, container and ingredient label suffixed. */
function relabel(text: string, k: number): string {
  const tag = (label: string): string => `${label.trim()} k${k}`;
  return text
    .split("\n")
    .map((line) => {
      const fields = line.split("\t");
      if (/^O\d*$/.test(fields[0] ?? "") && fields[1] !== undefined) fields[1] = tag(fields[1]);
      else if (/^S\d*$/.test(fields[0] ?? "") && fields[2] !== undefined) {
        fields[2] = fields[2]
          .replace(/\[([^\]]+)\]/, (_, c: string) => `[${tag(c)}]`)
          .replace(/\{([^}]*)\}/, (_, list: string) => `{${list.split(",").map(tag).join(",")}}`);
      }
      return fields.join("\t");
    })
    .join("\n");
}

function scaled(files: KnowledgeBaseFile[], factor: number): KnowledgeBaseFile[] {
  const decoder = new TextDecoder();
  const encoder = new TextEncoder();
  const out = [...files];
  for (let k = 1; k < factor; k++) {
    for (const f of files) out.push({ name: `k${k}-${f.name}`, bytes: encoder.encode(relabel(decoder.decode(f.bytes), k)) });
  }
  return out;
}

/** One plan call, timed; a typed error leaves `plan` undefined. */
function timedPlan(planner: FoonPlanner, request: PlanRequest): { took: number; plan?: Plan } {
  const started = performance.now();
  try {
    const plan = planner.plan(request);
    return { took: performance.now() - started, plan };
  } catch {
    return { took: performance.now() - started };
  }
}

/** "median …, p95 …, max …" of ascending times. */
const spread = (sorted: number[]): string =>
  `median ${ms(percentile(sorted, 0.5))}, p95 ${ms(percentile(sorted, 0.95))}, max ${ms(sorted[sorted.length - 1] ?? 0)}`;

/** Prints the figures of one knowledge base; returns the median plan time over all rounds. */
function bench(name: string, files: KnowledgeBaseFile[], embeddings: Uint8Array, requests: PlanRequest[], rounds = ROUNDS): number {
  const loads: number[] = [];
  let planner: FoonPlanner | undefined;
  const loadRounds = files.length > 5000 ? 1 : 5;
  for (let i = 0; i < loadRounds; i++) {
    planner?.free();
    const started = performance.now();
    planner = FoonPlanner.load(files, embeddings);
    loads.push(performance.now() - started);
  }
  if (planner === undefined) return NaN;
  const stats = planner.stats();
  const times: number[] = [];
  // each query's fastest round: a shared machine only ever adds time, so the best of a few rounds is
  // the figure that repeats from one run to the next (all rounds are reported too)
  const best = requests.map(() => Infinity);
  const texts: string[] = [];
  let errors = 0;
  for (let round = 0; round < rounds; round++) {
    for (const [i, request] of requests.entries()) {
      const { took, plan } = timedPlan(planner, request);
      if (plan === undefined) errors++;
      times.push(took);
      best[i] = Math.min(best[i]!, took);
      // the bench's own record of the plan, outside the timed call
      if (round === 0 && plan !== undefined) texts.push(JSON.stringify(plan));
    }
  }
  times.sort((a, b) => a - b);
  best.sort((a, b) => a - b);
  // what JavaScript spends turning a plan's JSON text into objects: measured on the plan as printed; the
  // WASM module sends it with shared nodes by number (docs/plan-format.md), a sixth shorter and faster
  const parses = texts.map((text) => {
    let fastest = Infinity;
    for (let round = 0; round < rounds; round++) {
      const started = performance.now();
      JSON.parse(text);
      fastest = Math.min(fastest, performance.now() - started);
    }
    return fastest;
  });
  parses.sort((a, b) => a - b);
  const bytes = texts.map((t) => t.length).sort((a, b) => a - b);
  loads.sort((a, b) => a - b);
  console.log(`\n${name}: ${stats.subgraphs} subgraphs, ${stats.units} units, ${stats.object_nodes} object nodes`);
  console.log(`  knowledge-base load (parse + merge + index + embeddings): median ${ms(percentile(loads, 0.5))} over ${loads.length}`);
  console.log(`  plan (${requests.length} dev queries x ${rounds} rounds, JSON in/out): ${spread(times)}, typed errors ${errors / rounds}`);
  if (rounds > 1) console.log(`  plan, each query's best of ${rounds} rounds: ${spread(best)}`);
  console.log(`  JSON.parse of the plan as printed (median ${(percentile(bytes, 0.5) / 1024).toFixed(1)} kB): median ${ms(percentile(parses, 0.5))}, p95 ${ms(percentile(parses, 0.95))}`);
  console.log(`  memory: WASM linear memory ${mb(wasmMemoryBytes())}, process peak RSS ${mb(process.resourceUsage().maxRSS * 1024)}`);
  planner.free();
  return percentile(times, 0.5);
}

/**
 * The same dev plans natively (`plan_timing`, plan and JSON written, no WASM boundary) in this run, as the
 * ratio that one machine's figures can be compared by. Skipped, saying so, where cargo is not installed.
 */
function benchNative(wasmMedian: number): void {
  const run = spawnSync("cargo", ["run", "-q", "--release", "--example", "plan_timing", "--", String(ROUNDS)], { cwd: join(ROOT, "wasm"), encoding: "utf8" });
  const median = /plan \+ JSON .*?median ([\d.]+) ms/.exec(run.stdout ?? "")?.[1];
  if (run.status !== 0 || median === undefined) {
    console.log(`  native (cargo plan_timing): not run (${run.error?.message ?? (run.stderr.trim().split("\n").pop() || "no figure printed")})`);
    return;
  }
  console.log(`  native (cargo plan_timing, plan + JSON): median ${ms(Number(median))}; WASM under Node / native ${(wasmMedian / Number(median)).toFixed(2)}x`);
}

/** The page's load phases and download from headless Chromium (`npm run bench:browser`), when dist/ is built. */
function benchBrowser(): void {
  if (!existsSync(join(ROOT, "dist/index.html"))) {
    console.log("\nbrowser: not run (dist/ is not built: npm run build)");
    return;
  }
  console.log("");
  const run = spawnSync("npx", ["--no-install", "tsx", "scripts/bench-browser.ts"], { cwd: ROOT, encoding: "utf8", env: { ...process.env, BENCH_ROUNDS: process.env.BENCH_BROWSER_ROUNDS ?? "3" } });
  process.stdout.write(run.stdout);
  if (run.status !== 0) console.log(`browser: failed (${run.stderr.trim().split("\n").pop() ?? ""})`);
}

/**
 * What the explain trace costs (the Algorithm view's `explain: true`): each query's best of the rounds with
 * it off and on, interleaved query by query so that the machine's changing speed falls on both alike.
 */
function benchExplain(files: KnowledgeBaseFile[], embeddings: Uint8Array, requests: PlanRequest[], rounds = ROUNDS): void {
  const planner = FoonPlanner.load(files, embeddings);
  const off = requests.map(() => Infinity);
  const on = requests.map(() => Infinity);
  const sizes: number[] = [];
  for (let round = 0; round < rounds; round++) {
    for (const [i, request] of requests.entries()) {
      off[i] = Math.min(off[i]!, timedPlan(planner, request).took);
      const explained = timedPlan(planner, { ...request, explain: true });
      on[i] = Math.min(on[i]!, explained.took);
      if (round === 0 && explained.plan?.trace !== undefined) sizes.push(JSON.stringify(explained.plan.trace).length);
    }
  }
  planner.free();
  const ratios = off.map((t, i) => on[i]! / t).sort((a, b) => a - b);
  for (const list of [off, on, sizes]) list.sort((a, b) => a - b);
  console.log(`  explain (each query's best of ${rounds} rounds, off and on interleaved): off median ${ms(percentile(off, 0.5))}, on median ${ms(percentile(on, 0.5))}, p95 ${ms(percentile(on, 0.95))}; on/off per query median ${percentile(ratios, 0.5).toFixed(2)}x; trace JSON median ${(percentile(sizes, 0.5) / 1024).toFixed(1)} kB, max ${((sizes.at(-1) ?? 0) / 1024).toFixed(1)} kB`);
}

/**
 * V8 runs WebAssembly first from a quick baseline compile and optimises each function once it has run a
 * while. One round of the dev queries on a planner of its own takes the plan code through that, so that the
 * figures below are the planner's (each measured planner still starts with nothing remembered); what a
 * page's very first plans cost is printed here.
 */
function warmUpEngine(files: KnowledgeBaseFile[], embeddings: Uint8Array, requests: PlanRequest[]): void {
  const planner = FoonPlanner.load(files, embeddings);
  // typed errors are counted by the bench proper
  const times = requests.map((request) => timedPlan(planner, request).took);
  planner.free();
  times.sort((a, b) => a - b);
  console.log(`engine warm-up (FOON-111, a planner of its own, not counted below): first round ${spread(times)}`);
}

initPlannerFromDisk();
const embeddings = readEmbeddings();
const foon111 = readKnowledgeBase(join(SHARED, "foon/subgraphs-plain"));
const requests: PlanRequest[] = readQueries(join(SHARED, "recipes/dev")).map((q) => ({ query: q.query }));
console.log(`foon-planner bench (Node ${process.version}, ${requests.length} dev queries)`);
warmUpEngine(foon111, embeddings, requests);
// BENCH_SCALES=1,10,100 (the default) picks which of the three knowledge bases to measure
const scales = new Set((process.env.BENCH_SCALES ?? "1,10,100").split(",").map((s) => s.trim()));
if (scales.has("1")) {
  benchNative(bench("FOON-111 (plain)", foon111, embeddings, requests));
  benchExplain(foon111, embeddings, requests);
}
if (scales.has("10")) bench("synthetic 10x FOON-111", scaled(foon111, 10), embeddings, requests);
if (scales.has("100")) bench("synthetic 100x FOON-111", scaled(foon111, 100), embeddings, requests, 1);
if (process.env.BENCH_BROWSER !== "0") benchBrowser();
