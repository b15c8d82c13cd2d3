import { describe, expect, it } from "vitest";
import { curvesToCsv, recipeScores, thresholdCurves } from "../../src/eval/curves";
import { variantOrder } from "../../src/eval/blind";
import { parseCsv } from "../../src/eval/csv";
import type { Rating } from "../../src/eval/ratings";

const r = (id: string, object: string, score: 0 | 1 | 2, variant: Rating["variant"] = "modified", rater = "ann", type = "salad"): Rating => ({
  rater, type, id, variant, object, state: "s", score, updated: "2026-01-01T00:00:00.000Z",
});

describe("threshold curves", () => {
  const ratings = [
    r("1", "a", 2), r("1", "b", 2), // score 100%
    r("2", "a", 2), r("2", "b", 1), // 75%
    r("3", "a", 0), r("3", "b", 1), // 25%
    r("1", "a", 0, "unmodified"), r("1", "b", 2, "unmodified"), // 50%
  ];

  it("scores a recipe as mean rating / 2", () => {
    expect(recipeScores(ratings).map((s) => [s.id, s.variant, s.score])).toEqual([
      ["1", "modified", 1], ["1", "unmodified", 0.5], ["2", "modified", 0.75], ["3", "modified", 0.25],
    ]);
  });

  it("share of recipes reaching each threshold, per type and variant", () => {
    const curves = thresholdCurves(ratings, { step: 25 });
    expect(curves.map((c) => [c.type, c.variant, c.recipes])).toEqual([["salad", "modified", 3], ["salad", "unmodified", 1]]);
    expect(curves[0]!.points).toEqual([
      { threshold: 0, share: 1 }, { threshold: 25, share: 1 }, { threshold: 50, share: 2 / 3 }, { threshold: 75, share: 2 / 3 }, { threshold: 100, share: 1 / 3 },
    ]);
    expect(thresholdCurves(ratings)[0]!.points).toHaveLength(101);
  });

  it("averages raters per ingredient, can pick raters, and leaves incomplete recipes out", () => {
    const two = [r("1", "a", 2), r("1", "a", 0, "modified", "bob"), r("1", "b", 2)];
    expect(recipeScores(two)[0]!.score).toBe(0.75);
    expect(recipeScores(two, { raters: new Set(["bob"]) })[0]!.score).toBe(0);
    expect(recipeScores(ratings, { expected: new Map([["salad/1", 3]]) }).map((s) => s.id)).toEqual(["2", "3"]);
  });

  it("exports CSV", () => {
    const rows = parseCsv(curvesToCsv(thresholdCurves(ratings, { step: 50 })));
    expect(rows[0]).toEqual(["type", "variant", "recipes", "threshold_percent", "share"]);
    expect(rows).toHaveLength(7);
  });
});

describe("blind order", () => {
  it("is stable per recipe and seed, and shuffles across recipes", () => {
    expect(variantOrder("salad/1", "seed", false)).toEqual(["modified", "unmodified"]);
    expect(variantOrder("salad/1", "seed", true)).toEqual(variantOrder("salad/1", "seed", true));
    const firsts = new Set(Array.from({ length: 20 }, (_, i) => variantOrder(`salad/${i}`, "seed", true)[0]));
    expect(firsts.size).toBe(2);
  });
});
