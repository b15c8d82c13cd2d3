// The user's query as the app holds it (dish type, ingredient rows, chosen substitutes), its URL form,
// and the parsing of pasted ingredient lists. Pure functions: unit-tested without a browser.

import { RETRIEVAL_MODES, type PlanRequest, type QueryIngredient, type RetrievalMode } from "../planner/types";

export interface AppQuery {
  /** Dish type: a dish class name ("salad") or free text. */
  dish: string;
  ingredients: QueryIngredient[];
  /** Query object -> the equivalent label the user chose in the substitutions panel. */
  overrides: Record<string, string>;
  /** How the reference task tree is retrieved (docs/robot.md); absent: the paper's heuristic. */
  mode?: RetrievalMode;
}

export const EMPTY_QUERY: AppQuery = { dish: "", ingredients: [], overrides: {} };

/** Lower case, single spaces: how the knowledge base spells names. */
export function normalizeName(text: string): string {
  return text.trim().toLowerCase().replace(/\s+/g, " ");
}

/** The plan request of a query; empty rows are left out, overrides only for objects still asked for. */
export function toPlanRequest(query: AppQuery): PlanRequest {
  const ingredients = query.ingredients
    .map((i) => ({ object: normalizeName(i.object), state: normalizeName(i.state) }))
    .filter((i) => i.object !== "");
  const asked = new Set(ingredients.map((i) => i.object));
  const overrides: Record<string, string> = {};
  for (const [object, label] of Object.entries(query.overrides)) {
    if (asked.has(object) && label !== "") overrides[object] = label;
  }
  const request: PlanRequest = { query: { type: normalizeName(query.dish), ingredients }, overrides };
  // the paper's heuristic sends no robot options: the plan is the default one
  if (query.mode !== undefined && query.mode !== "heuristic") request.robot = { mode: query.mode };
  return request;
}

/** A retrieval mode named in text (a URL, an attribute), or undefined for anything else. */
export function parseMode(value: string | null | undefined): RetrievalMode | undefined {
  return RETRIEVAL_MODES.find((m) => m === value);
}

/** Whether a query has enough to plan: a dish type or at least one ingredient. */
export function isPlannable(query: AppQuery): boolean {
  return toPlanRequest(query).query.ingredients.length > 0;
}

// ---- URL form: ?dish=salad&i=chili%20pepper~chopped&i=tomato~whole&sub=cool%20whip~whipped%20cream ----
// `~` separates object and state (encodeURIComponent keeps it readable); labels never contain it.

const SEP = "~";

function encode(text: string): string {
  return encodeURIComponent(text).replace(/%20/g, "+");
}

export function queryToSearch(query: AppQuery): string {
  const parts: string[] = [];
  const request = toPlanRequest(query);
  if (request.query.type !== "") parts.push(`dish=${encode(request.query.type)}`);
  for (const i of request.query.ingredients) parts.push(`i=${encode(i.state === "" ? i.object : `${i.object}${SEP}${i.state}`)}`);
  for (const [object, label] of Object.entries(request.overrides ?? {}).sort(([a], [b]) => a.localeCompare(b))) {
    parts.push(`sub=${encode(`${object}${SEP}${label}`)}`);
  }
  if (request.robot?.mode !== undefined) parts.push(`mode=${request.robot.mode}`);
  return parts.length === 0 ? "" : `?${parts.join("&")}`;
}

function splitPair(value: string): [string, string] {
  const at = value.indexOf(SEP);
  return at < 0 ? [normalizeName(value), ""] : [normalizeName(value.slice(0, at)), normalizeName(value.slice(at + 1))];
}

/** The query of a URL's search part; `null` when the URL carries none (then keep the saved one). */
export function queryFromSearch(search: string): AppQuery | null {
  const params = new URLSearchParams(search);
  if (!params.has("dish") && !params.has("i")) return null;
  const ingredients = params
    .getAll("i")
    .map(splitPair)
    .filter(([object]) => object !== "")
    .map(([object, state]) => ({ object, state }));
  const overrides: Record<string, string> = {};
  for (const value of params.getAll("sub")) {
    const [object, label] = splitPair(value);
    if (object !== "" && label !== "") overrides[object] = label;
  }
  const mode = parseMode(params.get("mode"));
  return { dish: normalizeName(params.get("dish") ?? ""), ingredients, overrides, ...(mode === undefined ? {} : { mode }) };
}

// ---- Pasted lists: "chopped chili pepper, whole tomato, cool whip" ----

/**
 * Splits "chopped chili pepper" into object and state, using the knowledge base's states: the longest known
 * state at the start ("cut in pieces tomato") or after a comma at the end ("tomato, diced") is the state.
 * Anything else is an object without a state (free text stays allowed for unseen ingredients).
 */
export function splitIngredient(text: string, knownStates: readonly string[]): QueryIngredient {
  const phrase = normalizeName(text);
  const byLength = [...knownStates].map(normalizeName).sort((a, b) => b.length - a.length);
  for (const state of byLength) {
    if (state !== "" && phrase.startsWith(`${state} `) && phrase.length > state.length + 1) {
      return { object: phrase.slice(state.length + 1).trim(), state };
    }
  }
  return { object: phrase, state: "" };
}

/** A pasted comma- or line-separated list as ingredient rows. */
export function parseIngredientList(text: string, knownStates: readonly string[]): QueryIngredient[] {
  return text
    .split(/[,;\n\r]+/)
    .map((part) => part.replace(/^\s*[-*•\d.)]+\s+/, "")) // list bullets and numbering
    .map((part) => part.trim())
    .filter((part) => part !== "")
    .map((part) => splitIngredient(part, knownStates));
}

/** "chopped chili pepper" (state first, as recipes say it). */
export function ingredientPhrase(i: QueryIngredient): string {
  return i.state === "" ? i.object : `${i.state} ${i.object}`;
}

/** Example queries, one click away. */
export const EXAMPLES: readonly { title: string; query: AppQuery }[] = [
  {
    title: "Salad: chopped chili pepper, whole tomato, cool whip",
    query: {
      dish: "salad",
      ingredients: [
        { object: "chili pepper", state: "chopped" },
        { object: "tomato", state: "whole" },
        { object: "cool whip", state: "" },
      ],
      overrides: {},
    },
  },
  {
    title: "Greek salad with what is in the fridge",
    query: {
      dish: "salad",
      ingredients: [
        { object: "tomato", state: "diced" },
        { object: "cucumber", state: "sliced" },
        { object: "red onion", state: "whole" },
        { object: "feta cheese", state: "crumbled" },
        { object: "olive oil", state: "" },
      ],
      overrides: {},
    },
  },
  {
    title: "Soup: carrot, ginger, onion",
    query: {
      dish: "soup",
      ingredients: [
        { object: "carrot", state: "chopped" },
        { object: "ginger", state: "minced" },
        { object: "onion", state: "diced" },
        { object: "vegetable broth", state: "" },
      ],
      overrides: {},
    },
  },
  {
    title: "Omelette: egg, spinach, shallot",
    query: {
      dish: "omelette",
      ingredients: [
        { object: "egg", state: "whole" },
        { object: "spinach", state: "chopped" },
        { object: "shallot", state: "minced" },
        { object: "cheddar", state: "grated" },
      ],
      overrides: {},
    },
  },
];
