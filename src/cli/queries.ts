// Recipe-query files on disk (the ../shared/recipes shape: <dir>/<type>/<id>.json), for batch, eval and bench.

import { readFileSync, readdirSync, statSync } from "node:fs";
import { join, relative } from "node:path";
import type { Query } from "../planner/types";

export interface QueryFile {
  /** Path relative to the queries folder, e.g. "salad/004628ff8d.json": batch output mirrors it. */
  path: string;
  query: Query;
}

function isQuery(value: unknown): value is Query {
  if (typeof value !== "object" || value === null) return false;
  const v = value as Record<string, unknown>;
  return (
    typeof v.type === "string" &&
    Array.isArray(v.ingredients) &&
    v.ingredients.every(
      (i: unknown) => typeof i === "object" && i !== null && typeof (i as Record<string, unknown>).object === "string",
    )
  );
}

/** Reads one query file; a file that is not a query is an error naming the file. */
export function readQuery(file: string): Query {
  let value: unknown;
  try {
    value = JSON.parse(readFileSync(file, "utf8"));
  } catch (e) {
    throw new Error(`${file}: not valid JSON (${e instanceof Error ? e.message : String(e)})`);
  }
  if (!isQuery(value)) throw new Error(`${file}: not a recipe query ({"type": string, "ingredients": [{"object", "state"}]})`);
  return value;
}

/** Every `.json` query below a folder, sorted by path (or the single file given). */
export function readQueries(dir: string): QueryFile[] {
  if (!statSync(dir).isDirectory()) return [{ path: relative(join(dir, ".."), dir), query: readQuery(dir) }];
  const out: QueryFile[] = [];
  const walk = (folder: string): void => {
    for (const name of readdirSync(folder).sort()) {
      const full = join(folder, name);
      if (statSync(full).isDirectory()) walk(full);
      else if (name.endsWith(".json")) out.push({ path: relative(dir, full), query: readQuery(full) });
    }
  };
  walk(dir);
  return out;
}
