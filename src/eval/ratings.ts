// Ratings of progress lines (section IV-B of the paper): each ingredient of each recipe's plan, in
// each variant, rated 0 = incorrect, 1 = partially incorrect, 2 = correct, by a named rater.
// Import/export as JSON or CSV; merging several raters' files keeps each rater's own ratings and,
// for the same rater and item, the most recent one.

import { parseCsvRecords, toCsv } from "./csv";
import type { Variant } from "./types";

export type Score = 0 | 1 | 2;

export interface Rating {
  rater: string;
  type: string;
  id: string;
  variant: Variant;
  /** The query ingredient rated (its progress line). */
  object: string;
  state: string;
  score: Score;
  /** ISO 8601 time of the rating. */
  updated: string;
}

/** One rating per (rater, recipe, variant, ingredient). */
export function ratingKey(r: Pick<Rating, "rater" | "type" | "id" | "variant" | "object" | "state">): string {
  return JSON.stringify([r.rater, r.type, r.id, r.variant, r.object, r.state]);
}

/** Distinct (object, state) pairs of a query, in order: the items a rater rates. */
export function ratingItems(ingredients: readonly { object: string; state: string }[]): { object: string; state: string }[] {
  const seen = new Set<string>();
  return ingredients.filter((i) => {
    const key = JSON.stringify([i.object, i.state]);
    if (seen.has(key)) return false;
    seen.add(key);
    return true;
  });
}

export class RatingsFormatError extends Error {
  constructor(message: string) {
    super(message);
    this.name = "RatingsFormatError";
  }
}

const isRecord = (v: unknown): v is Record<string, unknown> => typeof v === "object" && v !== null && !Array.isArray(v);

/** Validates one rating from untrusted data (a file); `where` names it in errors. */
export function toRating(value: unknown, where: string): Rating {
  if (!isRecord(value)) throw new RatingsFormatError(`${where}: not an object`);
  const text = (name: string, allowEmpty = false): string => {
    const v = value[name];
    if (typeof v !== "string" || (!allowEmpty && v === "")) throw new RatingsFormatError(`${where}: \`${name}\` must be a non-empty string`);
    return v;
  };
  const variant = text("variant");
  if (variant !== "modified" && variant !== "unmodified") throw new RatingsFormatError(`${where}: \`variant\` must be modified or unmodified`);
  const rawScore = value.score;
  const score = typeof rawScore === "string" ? Number(rawScore) : rawScore;
  if (score !== 0 && score !== 1 && score !== 2) throw new RatingsFormatError(`${where}: \`score\` must be 0, 1 or 2`);
  const updated = text("updated");
  if (Number.isNaN(Date.parse(updated))) throw new RatingsFormatError(`${where}: \`updated\` is not a date`);
  return { rater: text("rater"), type: text("type"), id: text("id"), variant, object: text("object"), state: text("state", true), score, updated };
}

export interface MergeReport {
  ratings: Rating[];
  added: number;
  updated: number;
  unchanged: number;
}

/** Merges ratings into a base set: per key, the most recent `updated` wins (ties keep the base). */
export function mergeRatings(base: readonly Rating[], incoming: readonly Rating[]): MergeReport {
  const byKey = new Map(base.map((r) => [ratingKey(r), r]));
  let added = 0;
  let updated = 0;
  let unchanged = 0;
  for (const r of incoming) {
    const key = ratingKey(r);
    const old = byKey.get(key);
    if (old === undefined) {
      added += 1;
      byKey.set(key, r);
    } else if (Date.parse(r.updated) > Date.parse(old.updated)) {
      updated += 1;
      byKey.set(key, r);
    } else unchanged += 1;
  }
  return { ratings: sortRatings([...byKey.values()]), added, updated, unchanged };
}

export function sortRatings(ratings: Rating[]): Rating[] {
  return ratings.sort((a, b) => ratingKey(a).localeCompare(ratingKey(b)));
}

export interface RatingsFile {
  format: "foon-planner-ratings";
  version: 1;
  exported: string;
  ratings: Rating[];
}

export function ratingsToJson(ratings: readonly Rating[], exported: Date): string {
  const file: RatingsFile = { format: "foon-planner-ratings", version: 1, exported: exported.toISOString(), ratings: sortRatings([...ratings]) };
  return JSON.stringify(file, null, 2) + "\n";
}

const CSV_COLUMNS = ["rater", "type", "id", "variant", "object", "state", "score", "updated"] as const;

export function ratingsToCsv(ratings: readonly Rating[]): string {
  return toCsv(CSV_COLUMNS, sortRatings([...ratings]).map((r) => CSV_COLUMNS.map((c) => r[c])));
}

/** Reads a ratings file of either format (JSON when it starts with `{` or `[`, else CSV). */
export function parseRatingsFile(name: string, text: string): Rating[] {
  const trimmed = text.replace(/^\uFEFF/, "").trimStart();
  if (trimmed.startsWith("{") || trimmed.startsWith("[")) {
    let value: unknown;
    try {
      value = JSON.parse(trimmed);
    } catch (e) {
      throw new RatingsFormatError(`${name}: not JSON (${e instanceof Error ? e.message : String(e)})`);
    }
    const list = Array.isArray(value) ? value : isRecord(value) ? value.ratings : undefined;
    if (isRecord(value) && value.format !== undefined && value.format !== "foon-planner-ratings") throw new RatingsFormatError(`${name}: not a ratings file`);
    if (isRecord(value) && typeof value.version === "number" && value.version > 1) throw new RatingsFormatError(`${name}: ratings format version ${value.version} is newer than this workbench`);
    if (!Array.isArray(list)) throw new RatingsFormatError(`${name}: no \`ratings\` array`);
    return list.map((r: unknown, i) => toRating(r, `${name}: ratings[${i}]`));
  }
  try {
    return parseCsvRecords(text, CSV_COLUMNS).map((r, i) => toRating(r, `${name}: row ${i + 2}`));
  } catch (e) {
    if (e instanceof RatingsFormatError) throw e;
    throw new RatingsFormatError(`${name}: ${e instanceof Error ? e.message : String(e)}`);
  }
}
