import { describe, expect, it } from "vitest";
import { parseQuery, QueryFileError, recipeKey, sortQueries } from "../../src/eval/queries";
import { readQueries } from "../../src/cli/queries";
import { sharedPath } from "./helpers";

describe("recipe-query files", () => {
  it("validates the shape and names the file", () => {
    expect(parseQuery("d/x.json", '{"type":"soup","ingredients":[{"object":"leek","state":"sliced"}]}').query.id).toBe("x");
    expect(() => parseQuery("a.json", "[")).toThrow(QueryFileError);
    expect(() => parseQuery("a.json", '{"type":"","ingredients":[]}')).toThrow(/a.json: `type`/);
    expect(() => parseQuery("a.json", '{"type":"soup","ingredients":[{"object":1}]}')).toThrow(/ingredients\[0\]/);
  });

  it("sorts by type and id and drops repeated recipes", () => {
    const a = parseQuery("a", '{"id":"2","type":"soup","ingredients":[]}');
    const b = parseQuery("b", '{"id":"1","type":"soup","ingredients":[]}');
    const c = parseQuery("c", '{"id":"9","type":"cake","ingredients":[]}');
    expect(sortQueries([a, b, c, a]).map((q) => recipeKey(q.query))).toEqual(["cake/9", "soup/1", "soup/2"]);
  });

  it("reads the 320 dev queries from ../shared", () => {
    const queries = readQueries(sharedPath("recipes/dev"));
    expect(queries).toHaveLength(320);
    expect(new Set(queries.map((q) => q.query.type)).size).toBe(8);
  });
});
