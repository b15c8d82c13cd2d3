// Node entry of the planner module (CLI, Vitest, benchmarks): loads the WASM bytes and knowledge-base
// files from disk. Browser code must not import this file.

import { readFileSync, readdirSync, statSync } from "node:fs";
import { basename, join, resolve } from "node:path";
import { fileURLToPath } from "node:url";
import { FoonPlanner, initPlannerSync } from "./index";
import type { KnowledgeBaseFile } from "./types";

export const ROOT = resolve(fileURLToPath(new URL("../..", import.meta.url)));
export const WASM_PATH = join(ROOT, "wasm/pkg/foon_wasm_bg.wasm");
/** The project's own starter knowledge base: the default everywhere. */
export const STARTER_KB_DIR = join(ROOT, "public/kb/starter");
/** The compressed food embedding table shipped with the app (built by scripts/build_embeddings.py). */
export const EMBEDDINGS_PATH = join(ROOT, "public/data/food-embeddings.bin");

export function initPlannerFromDisk(): void {
  let bytes: Buffer;
  try {
    bytes = readFileSync(WASM_PATH);
  } catch {
    throw new Error(`${WASM_PATH} is missing: run "npm run build:wasm" (or "npm run setup") first`);
  }
  initPlannerSync(new Uint8Array(bytes));
}

/** FOON files of a folder (every `.txt` and `.foon`, sorted by name), or a single file. */
export function readKnowledgeBase(path: string): KnowledgeBaseFile[] {
  const stat = statSync(path);
  if (!stat.isDirectory()) return [{ name: basename(path), bytes: readFileSync(path) }];
  return readdirSync(path)
    .filter((name) => name.endsWith(".txt") || name.endsWith(".foon"))
    .sort()
    .map((name) => ({ name, bytes: readFileSync(join(path, name)) }));
}

export function readEmbeddings(): Uint8Array {
  return new Uint8Array(readFileSync(EMBEDDINGS_PATH));
}

/**
 * Loads a knowledge base from disk (default: the starter KB) into an initialised planner, with the
 * embedding table unless `exact` is set (exact name matching only).
 */
export function loadPlannerFromDisk(kbPath: string = STARTER_KB_DIR, options: { exact?: boolean } = {}): FoonPlanner {
  initPlannerFromDisk();
  return FoonPlanner.load(readKnowledgeBase(kbPath), options.exact === true ? undefined : readEmbeddings());
}
