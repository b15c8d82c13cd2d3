// Helpers for unit tests that load the real WASM build and the public data in ../shared.

import { existsSync } from "node:fs";
import { join, resolve } from "node:path";
import { ROOT } from "../../src/planner/node";

/** ../shared beside the repository, or $FOON_SHARED. */
export const SHARED = resolve(process.env.FOON_SHARED ?? join(ROOT, "../shared"));

export function sharedPath(...parts: string[]): string {
  const path = join(SHARED, ...parts);
  if (!existsSync(path)) throw new Error(`${path} is missing: the tests read the shared data folder (set FOON_SHARED)`);
  return path;
}

export const encode = (text: string): Uint8Array => new TextEncoder().encode(text);
