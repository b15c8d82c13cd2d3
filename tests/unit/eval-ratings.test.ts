import { describe, expect, it } from "vitest";
import { mergeRatings, parseRatingsFile, ratingItems, ratingsToCsv, ratingsToJson, RatingsFormatError, type Rating } from "../../src/eval/ratings";

const r = (rater: string, id: string, object: string, score: 0 | 1 | 2, updated = "2026-01-01T00:00:00.000Z", variant: Rating["variant"] = "modified"): Rating => ({
  rater, type: "salad", id, variant, object, state: "diced", score, updated,
});

describe("ratings", () => {
  it("rates each distinct (object, state) of a query once", () => {
    expect(ratingItems([{ object: "oil", state: "juice" }, { object: "oil", state: "juice" }, { object: "oil", state: "hot" }])).toEqual([
      { object: "oil", state: "juice" },
      { object: "oil", state: "hot" },
    ]);
  });

  it("merging keeps each rater's ratings and the most recent per item", () => {
    const ann = [r("ann", "1", "tomato", 2), r("ann", "1", "salt", 1)];
    const bob = [r("bob", "1", "tomato", 0)];
    const annLater = [r("ann", "1", "salt", 2, "2026-02-01T00:00:00.000Z"), r("ann", "1", "tomato", 0, "2025-01-01T00:00:00.000Z")];
    const once = mergeRatings(ann, bob);
    expect(once).toMatchObject({ added: 1, updated: 0, unchanged: 0 });
    const twice = mergeRatings(once.ratings, annLater);
    expect(twice).toMatchObject({ added: 0, updated: 1, unchanged: 1 });
    expect(twice.ratings.find((x) => x.rater === "ann" && x.object === "salt")?.score).toBe(2);
    expect(twice.ratings.find((x) => x.rater === "ann" && x.object === "tomato")?.score).toBe(2);
    expect(twice.ratings).toHaveLength(3);
  });

  it("round-trips JSON and CSV, hostile labels included", () => {
    const ratings = [r("ann", "1", 'to,"mato"\n<b>', 2), r("bob", "2", "=cmd()", 0, "2026-01-02T00:00:00.000Z", "unmodified")];
    expect(parseRatingsFile("x.json", ratingsToJson(ratings, new Date(0)))).toEqual(mergeRatings([], ratings).ratings);
    expect(parseRatingsFile("x.csv", ratingsToCsv(ratings))).toEqual(mergeRatings([], ratings).ratings);
  });

  it("accepts a bare JSON array and an empty state", () => {
    const text = JSON.stringify([{ ...r("ann", "1", "tomato", 1), state: "" }]);
    expect(parseRatingsFile("a.json", text)[0]!.state).toBe("");
  });

  it("rejects bad files naming the file and the row", () => {
    expect(() => parseRatingsFile("a.json", "{")).toThrow(RatingsFormatError);
    expect(() => parseRatingsFile("a.json", JSON.stringify({ ratings: [{ ...r("ann", "1", "t", 2), score: 3 }] }))).toThrow(/a.json: ratings\[0\]: `score`/);
    expect(() => parseRatingsFile("a.json", JSON.stringify({ format: "other", ratings: [] }))).toThrow(/not a ratings file/);
    expect(() => parseRatingsFile("a.json", JSON.stringify({ format: "foon-planner-ratings", version: 9, ratings: [] }))).toThrow(/newer/);
    expect(() => parseRatingsFile("b.csv", "rater,type\nann,salad\n")).toThrow(/b.csv: line 1: missing column/);
    const csv = ratingsToCsv([r("ann", "1", "t", 2)]).replace(",modified,", ",maybe,");
    expect(() => parseRatingsFile("c.csv", csv)).toThrow(/c.csv: row 2: `variant`/);
  });
});
