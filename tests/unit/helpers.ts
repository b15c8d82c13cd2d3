// Helpers for unit tests that load the real WASM build and the public data in ../shared.

import { existsSync } from "node:fs";
import { join, resolve } from "node:path";
import { initPlannerFromDisk, loadPlannerFromDisk, ROOT } from "../../src/planner/node";
import type { FoonPlanner, Query } from "../../src/planner/index";
import { readQueries } from "../../src/cli/queries";

/** ../shared beside the repository, or $FOON_SHARED. */
export const SHARED = resolve(process.env.FOON_SHARED ?? join(ROOT, "../shared"));

export function sharedPath(...parts: string[]): string {
  const path = join(SHARED, ...parts);
  if (!existsSync(path)) throw new Error(`${path} is missing: the tests read the shared data folder (set FOON_SHARED)`);
  return path;
}

export const encode = (text: string): Uint8Array => new TextEncoder().encode(text);

/** The WASM planner (initialised once) on FOON-111 from ../shared. */
export function foon111Planner(): FoonPlanner {
  initPlannerFromDisk();
  return loadPlannerFromDisk(sharedPath("foon/subgraphs-plain"));
}

/** Every `nth` dev query (of all dish types, in file order), as the CLI reads them. */
export function everyNthDevQuery(nth: number): Query[] {
  return readQueries(sharedPath("recipes/dev"))
    .filter((_, i) => i % nth === 0)
    .map((q) => q.query);
}
