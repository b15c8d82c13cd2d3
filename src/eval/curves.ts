// Threshold curves (Fig. 6 of the paper): per dish type and variant, the share of recipes whose
// score reaches each correctness threshold. A recipe's score is the mean rating of its ingredients
// divided by 2 (1 = every progress line correct); with several raters, each ingredient's rating is
// first averaged over the raters. A recipe reaches threshold t when its score >= t.

import { toCsv } from "./csv";
import type { Rating } from "./ratings";
import type { Variant } from "./types";

export interface CurvePoint {
  /** Threshold, 0..100 (%). */
  threshold: number;
  /** Share of the recipes that reach it, 0..1. */
  share: number;
}

export interface Curve {
  type: string;
  variant: Variant;
  /** Recipes counted (fully rated). */
  recipes: number;
  points: CurvePoint[];
}

export interface RecipeScore {
  type: string;
  id: string;
  variant: Variant;
  score: number;
  rated: number;
}

export interface CurveOptions {
  /** Only these raters (default: all). */
  raters?: ReadonlySet<string>;
  /** Items to rate per recipe (`type/id` -> count): recipes with fewer rated items are left out. */
  expected?: ReadonlyMap<string, number>;
  /** Threshold step in % (default 1). */
  step?: number;
}

const EPSILON = 1e-9;

/** Per (recipe, variant) scores from ratings. */
export function recipeScores(ratings: readonly Rating[], options: CurveOptions = {}): RecipeScore[] {
  const items = new Map<string, { type: string; id: string; variant: Variant; perItem: Map<string, number[]> }>();
  for (const r of ratings) {
    if (options.raters !== undefined && !options.raters.has(r.rater)) continue;
    const key = JSON.stringify([r.type, r.id, r.variant]);
    let entry = items.get(key);
    if (entry === undefined) {
      entry = { type: r.type, id: r.id, variant: r.variant, perItem: new Map() };
      items.set(key, entry);
    }
    const item = JSON.stringify([r.object, r.state]);
    entry.perItem.set(item, [...(entry.perItem.get(item) ?? []), r.score]);
  }
  const scores: RecipeScore[] = [];
  for (const e of items.values()) {
    const expected = options.expected?.get(`${e.type}/${e.id}`);
    if (expected !== undefined && e.perItem.size < expected) continue;
    const means = [...e.perItem.values()].map((s) => s.reduce((a, b) => a + b, 0) / s.length);
    scores.push({ type: e.type, id: e.id, variant: e.variant, score: means.reduce((a, b) => a + b, 0) / means.length / 2, rated: e.perItem.size });
  }
  return scores.sort((a, b) => a.type.localeCompare(b.type) || a.id.localeCompare(b.id) || a.variant.localeCompare(b.variant));
}

export function thresholdCurves(ratings: readonly Rating[], options: CurveOptions = {}): Curve[] {
  const step = options.step ?? 1;
  const scores = recipeScores(ratings, options);
  const groups = new Map<string, RecipeScore[]>();
  for (const s of scores) {
    const key = JSON.stringify([s.type, s.variant]);
    groups.set(key, [...(groups.get(key) ?? []), s]);
  }
  const thresholds: number[] = [];
  for (let t = 0; t <= 100 + EPSILON; t += step) thresholds.push(Math.min(100, Math.round(t * 1000) / 1000));
  if (thresholds[thresholds.length - 1] !== 100) thresholds.push(100);
  const curves: Curve[] = [];
  for (const group of groups.values()) {
    const { type, variant } = group[0]!;
    curves.push({
      type,
      variant,
      recipes: group.length,
      points: thresholds.map((t) => ({ threshold: t, share: group.filter((s) => s.score + EPSILON >= t / 100).length / group.length })),
    });
  }
  return curves.sort((a, b) => a.type.localeCompare(b.type) || a.variant.localeCompare(b.variant));
}

export function curvesToCsv(curves: readonly Curve[]): string {
  return toCsv(
    ["type", "variant", "recipes", "threshold_percent", "share"],
    curves.flatMap((c) => c.points.map((p) => [c.type, c.variant, c.recipes, p.threshold, p.share])),
  );
}
