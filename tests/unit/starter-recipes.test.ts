import { readdirSync, readFileSync } from "node:fs";
import { join } from "node:path";
import { describe, expect, it } from "vitest";
import { STARTER_KB_DIR } from "../../src/planner/node";
import { allRecipes } from "../../scripts/starter/recipes/index";

describe("the builder-made starter recipes", () => {
  const recipes = allRecipes();

  it("are the files in public/kb/starter (run `npm run build:starter` after changing a recipe)", () => {
    for (const r of recipes) expect(readFileSync(join(STARTER_KB_DIR, r.file), "utf8"), r.file).toBe(r.text);
  });

  it("each have a number of their own, hand-written files included", () => {
    const numbers = readdirSync(STARTER_KB_DIR).map((f) => f.split("-")[0]);
    expect(new Set(numbers).size).toBe(numbers.length);
    expect(numbers.length).toBeGreaterThan(recipes.length);
  });
});
