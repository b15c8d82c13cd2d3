// Recipe-query files on disk (the ../shared/recipes shape: <dir>/<type>/<id>.json), for batch, eval and
// bench. Validation is the workbench's own (src/eval/queries.ts), so CLI and browser accept the same files.

import { readFileSync, readdirSync, statSync } from "node:fs";
import { basename, join, relative } from "node:path";
import { parseQuery, sortQueries } from "../eval/queries";
import type { LoadedQuery } from "../eval/types";
import type { Query } from "../planner/types";

/** Reads one query file; a file that is not a query is an error naming the file and what is wrong. */
export function readQuery(file: string): Query {
  return parseQuery(file, readFileSync(file, "utf8")).query;
}

/**
 * Every `.json` query below a folder (or the single file given), ordered by dish type and id. `source` is
 * the path relative to the folder, e.g. "salad/004628ff8d.json": batch output mirrors it.
 */
export function readQueries(path: string): LoadedQuery[] {
  if (!statSync(path).isDirectory()) return [parseQuery(basename(path), readFileSync(path, "utf8"))];
  const files: string[] = [];
  const walk = (p: string): void => {
    if (statSync(p).isDirectory()) for (const name of readdirSync(p).sort()) walk(join(p, name));
    else if (p.endsWith(".json")) files.push(p);
  };
  walk(path);
  if (files.length === 0) throw new Error(`${path}: no .json query files`);
  return sortQueries(files.map((f) => parseQuery(relative(path, f), readFileSync(f, "utf8"))));
}
