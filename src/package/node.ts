// The npm package's Node entry (`import … from "foon-planner"` in Node): the planner API, with the WASM
// module, the bundled knowledge base and the embedding table read from the package's own files.

import { readFileSync } from "node:fs";
import { fileURLToPath } from "node:url";
import { FoonPlanner, initPlannerSync } from "../planner/index";
import type { KnowledgeBaseFile } from "../planner/types";

export * from "../planner/index";
export { readKnowledgeBase } from "../planner/node";

// Paths in the package as built (lib/node.js beside lib/foon_wasm_bg.wasm, the web build in dist/).
const packageFile = (path: string): string => fileURLToPath(new URL(path, import.meta.url));

/** Initialises the WASM module from the package's copy (once; later calls do nothing). */
export function initPlannerNode(): void {
  initPlannerSync(new Uint8Array(readFileSync(packageFile("./foon_wasm_bg.wasm"))));
}

/** The package's starter knowledge base, as one bundle file. */
export function bundledKnowledgeBase(): KnowledgeBaseFile[] {
  return [{ name: "default.foon", bytes: new Uint8Array(readFileSync(packageFile("../dist/kb/default.foon"))) }];
}

/** The package's food embedding table (finds substitutes by meaning). */
export function bundledEmbeddings(): Uint8Array {
  return new Uint8Array(readFileSync(packageFile("../dist/data/food-embeddings.bin")));
}

/**
 * A planner ready to plan: the WASM module initialised, `files` loaded (default: the bundled knowledge base)
 * with the embedding table, unless `exact` asks for exact name matching.
 */
export function loadPlanner(files: readonly KnowledgeBaseFile[] = bundledKnowledgeBase(), options: { exact?: boolean } = {}): FoonPlanner {
  initPlannerNode();
  return FoonPlanner.load(files, options.exact === true ? undefined : bundledEmbeddings());
}
