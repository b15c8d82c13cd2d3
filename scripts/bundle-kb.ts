// Bundles the knowledge base the app ships into public/kb/default.foon (one text file: every subgraph
// behind a "#@file <name>" line), after checking that it loads, and its snapshot into public/kb/default.kb
// (the parsed and merged knowledge base, for the module in wasm/pkg: the page's planner reads it instead of
// downloading and parsing the text; src/worker/kb-cache.ts). Which knowledge base:
//   default                         the project's starter knowledge base (public/kb/starter)
//   FOON_DIR=<dir-or-file>[:...]    those instead (e.g. FOON_DIR=../shared/foon/subgraphs-plain)
//   FOON_MERGE=1 with FOON_DIR      those merged with the starter knowledge base

import { mkdirSync, readFileSync, writeFileSync } from "node:fs";
import { join, resolve } from "node:path";
import { describeError, FoonPlanner } from "../src/planner/index";
import { initPlannerFromDisk, readKnowledgeBase, ROOT, STARTER_KB_DIR, WASM_PATH } from "../src/planner/node";
import { buildDigest, shippedSnapshot } from "../src/worker/kb-cache";
import { bundleText } from "../src/planner/bundle";

const OUT = join(ROOT, "public/kb/default.foon");
const OUT_SNAPSHOT = join(ROOT, "public/kb/default.kb");

function sources(): string[] {
  const custom = process.env.FOON_DIR?.split(":").filter((p) => p !== "").map((p) => resolve(p));
  if (custom === undefined || custom.length === 0) return [STARTER_KB_DIR];
  return process.env.FOON_MERGE === "1" ? [STARTER_KB_DIR, ...custom] : custom;
}

const files = sources().flatMap((dir) => readKnowledgeBase(dir));
initPlannerFromDisk();
const planner = FoonPlanner.load(files); // throws with file and line when a file is malformed
for (const w of planner.warnings()) console.warn(`warning: ${describeError(w)}`);
const stats = planner.stats();
planner.free();
const text = bundleText(files);
// the snapshot of the bundle itself, as the page would parse it
const bundled = FoonPlanner.load([{ name: "default.foon", bytes: new TextEncoder().encode(text) }]);
const build = await buildDigest(readFileSync(WASM_PATH));
if (build === null) throw new Error("no WebCrypto in this Node: cannot write the knowledge base's snapshot");
const snapshot = shippedSnapshot(build, bundled.snapshot());
bundled.free();
mkdirSync(join(ROOT, "public/kb"), { recursive: true });
writeFileSync(OUT, text);
writeFileSync(OUT_SNAPSHOT, snapshot);
console.log(`bundled ${files.length} files (${stats.units} units, ${stats.goal_nodes} goal nodes) from ${sources().join(", ")} into ${OUT} (snapshot: ${OUT_SNAPSHOT}, ${snapshot.byteLength} bytes)`);
