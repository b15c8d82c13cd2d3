// Bundles the knowledge base the app ships into public/kb/default.foon (one text file: every subgraph
// behind a "#@file <name>" line), after checking that it loads. Which knowledge base:
//   default                         the project's starter knowledge base (public/kb/starter)
//   FOON_DIR=<dir-or-file>[:...]    those instead (e.g. FOON_DIR=../shared/foon/subgraphs-plain)
//   FOON_MERGE=1 with FOON_DIR      those merged with the starter knowledge base

import { mkdirSync, writeFileSync } from "node:fs";
import { join, resolve } from "node:path";
import { describeError, FoonPlanner } from "../src/planner/index";
import { initPlannerFromDisk, readKnowledgeBase, ROOT, STARTER_KB_DIR } from "../src/planner/node";
import { bundleText } from "../src/planner/bundle";

const OUT = join(ROOT, "public/kb/default.foon");

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
mkdirSync(join(ROOT, "public/kb"), { recursive: true });
writeFileSync(OUT, bundleText(files));
console.log(`bundled ${files.length} files (${stats.units} units, ${stats.goal_nodes} goal nodes) from ${sources().join(", ")} into ${OUT}`);
