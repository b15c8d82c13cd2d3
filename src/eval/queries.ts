// Recipe-query files (the ../shared/recipes shape), validated at the boundary.

import type { Query } from "../planner/types";
import type { LoadedQuery } from "./types";

export class QueryFileError extends Error {
  constructor(
    readonly source: string,
    reason: string,
  ) {
    super(`${source}: ${reason}`);
    this.name = "QueryFileError";
  }
}

const isRecord = (v: unknown): v is Record<string, unknown> => typeof v === "object" && v !== null && !Array.isArray(v);

/** The file name without folders and `.json`: the query id when the file has none. */
function stem(source: string): string {
  const base = source.split(/[\\/]/).pop() ?? source;
  return base.replace(/\.json$/i, "");
}

/** Parses one query file; throws QueryFileError naming the file and what is wrong. */
export function parseQuery(source: string, text: string): LoadedQuery {
  let value: unknown;
  try {
    value = JSON.parse(text);
  } catch (e) {
    throw new QueryFileError(source, `not JSON (${e instanceof Error ? e.message : String(e)})`);
  }
  if (!isRecord(value)) throw new QueryFileError(source, "not a JSON object");
  const { id, type, ingredients } = value;
  if (typeof type !== "string" || type.trim() === "") throw new QueryFileError(source, "`type` must be a non-empty string");
  if (id !== undefined && typeof id !== "string") throw new QueryFileError(source, "`id` must be a string");
  if (!Array.isArray(ingredients)) throw new QueryFileError(source, "`ingredients` must be an array");
  const parsed: Query["ingredients"] = ingredients.map((item: unknown, i) => {
    if (!isRecord(item) || typeof item.object !== "string" || typeof item.state !== "string") {
      throw new QueryFileError(source, `ingredients[${i}] must be {object: string, state: string}`);
    }
    return { object: item.object, state: item.state };
  });
  return { source, query: { id: id ?? stem(source), type, ingredients: parsed } };
}

/** Orders queries by dish type, then id; drops exact repeats of (type, id), keeping the first. */
export function sortQueries(queries: readonly LoadedQuery[]): LoadedQuery[] {
  const seen = new Set<string>();
  return [...queries]
    .sort((a, b) => a.query.type.localeCompare(b.query.type) || a.query.id.localeCompare(b.query.id))
    .filter((q) => {
      const key = recipeKey(q.query);
      if (seen.has(key)) return false;
      seen.add(key);
      return true;
    });
}

/** Stable identity of a recipe across runs and raters: `<type>/<id>`. */
export function recipeKey(r: { type: string; id: string }): string {
  return `${r.type}/${r.id}`;
}
