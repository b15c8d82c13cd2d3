import { describe, expect, it } from "vitest";
import {
  EXAMPLES,
  ingredientPhrase,
  isPlannable,
  parseIngredientList,
  queryFromSearch,
  queryToSearch,
  splitIngredient,
  toPlanRequest,
  type AppQuery,
} from "../../src/app/query";
import { loadPlannerFromDisk } from "../../src/planner/node";

const STATES = ["chopped", "whole", "diced", "cut in pieces", "sliced"];

describe("ingredient phrases", () => {
  it("splits the longest known state off the front", () => {
    expect(splitIngredient("Chopped  Chili Pepper", STATES)).toEqual({ object: "chili pepper", state: "chopped" });
    expect(splitIngredient("cut in pieces tomato", STATES)).toEqual({ object: "tomato", state: "cut in pieces" });
  });
  it("keeps unknown words as the object (free text for unseen ingredients)", () => {
    expect(splitIngredient("cool whip", STATES)).toEqual({ object: "cool whip", state: "" });
    expect(splitIngredient("whole", STATES)).toEqual({ object: "whole", state: "" });
  });
  it("parses comma-, semicolon- and line-separated lists with bullets", () => {
    expect(parseIngredientList("chopped chili pepper, whole tomato, cool whip", STATES)).toEqual([
      { object: "chili pepper", state: "chopped" },
      { object: "tomato", state: "whole" },
      { object: "cool whip", state: "" },
    ]);
    expect(parseIngredientList("- sliced cucumber\n2. diced tomato;\n\n", STATES)).toEqual([
      { object: "cucumber", state: "sliced" },
      { object: "tomato", state: "diced" },
    ]);
  });
  it("says a row the way recipes do", () => {
    expect(ingredientPhrase({ object: "tomato", state: "diced" })).toBe("diced tomato");
    expect(ingredientPhrase({ object: "cool whip", state: "" })).toBe("cool whip");
  });
});

describe("plan requests", () => {
  it("drops empty rows and overrides of objects no longer asked for", () => {
    const q: AppQuery = {
      dish: " Salad ",
      ingredients: [{ object: " Tomato", state: "Whole " }, { object: "  ", state: "diced" }],
      overrides: { tomato: "cherry tomato", onion: "shallot" },
    };
    expect(toPlanRequest(q)).toEqual({ query: { type: "salad", ingredients: [{ object: "tomato", state: "whole" }] }, overrides: { tomato: "cherry tomato" } });
    expect(isPlannable(q)).toBe(true);
    expect(isPlannable({ dish: "salad", ingredients: [{ object: "", state: "" }], overrides: {} })).toBe(false);
  });
  it("asks for a retrieval mode only when it is not the paper's heuristic", () => {
    const q: AppQuery = { dish: "salad", ingredients: [{ object: "tomato", state: "" }], overrides: {} };
    expect(toPlanRequest({ ...q, mode: "most_reliable" }).robot).toEqual({ mode: "most_reliable" });
    expect(toPlanRequest({ ...q, mode: "heuristic" })).toEqual(toPlanRequest(q));
    expect("robot" in toPlanRequest(q)).toBe(false);
  });
});

describe("the query in the URL", () => {
  it("round-trips dish, ingredients and substitutes", () => {
    const q: AppQuery = {
      dish: "salad",
      ingredients: [{ object: "chili pepper", state: "chopped" }, { object: "cool whip", state: "" }],
      overrides: { "chili pepper": "jalapeno" },
    };
    const search = queryToSearch(q);
    expect(search).toBe("?dish=salad&i=chili+pepper~chopped&i=cool+whip&sub=chili+pepper~jalapeno");
    expect(queryFromSearch(search)).toEqual(q);
  });
  it("round-trips the retrieval mode and ignores an unknown one", () => {
    const q: AppQuery = { dish: "soup", ingredients: [{ object: "onion", state: "" }], overrides: {}, mode: "lowest_cost" };
    expect(queryToSearch(q)).toBe("?dish=soup&i=onion&mode=lowest_cost");
    expect(queryFromSearch(queryToSearch(q))).toEqual(q);
    expect(queryFromSearch("?dish=soup&i=onion&mode=fastest")).toEqual({ ...q, mode: undefined });
  });
  it("encodes characters that would break the URL", () => {
    const q: AppQuery = { dish: "", ingredients: [{ object: "mac & cheese", state: "50% done" }], overrides: {} };
    expect(queryFromSearch(queryToSearch(q))).toEqual(q);
  });
  it("is null without a query, so the saved state stays", () => {
    expect(queryFromSearch("")).toBeNull();
    expect(queryFromSearch("?theme=dark")).toBeNull();
  });
  it("has example queries that each plan a task tree of their dish type, with every ingredient, on the bundled knowledge base", () => {
    const planner = loadPlannerFromDisk();
    for (const e of EXAMPLES) {
      const plan = planner.plan(toPlanRequest(e.query));
      expect(plan.dish_class?.name, e.title).toBe(e.query.dish);
      expect(plan.units.length, e.title).toBeGreaterThan(0);
      expect(plan.ingredients.map((i) => `${i.object}: ${i.status}`), e.title).toEqual(e.query.ingredients.map((i) => `${i.object}: planned`));
    }
    planner.free();
  });
});
