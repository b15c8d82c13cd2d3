// Loading knowledge bases through the real WASM build, as the app and the CLI do.
import { readFileSync } from "node:fs";
import { join } from "node:path";
import { beforeAll, describe, expect, it } from "vitest";
import { FoonPlanner, PlannerError } from "../../src/planner/index";
import { initPlannerFromDisk, readKnowledgeBase, ROOT } from "../../src/planner/node";
import { encode, sharedPath } from "./helpers";

beforeAll(() => initPlannerFromDisk());

function loadError(files: { name: string; text: string }[]): PlannerError {
  try {
    FoonPlanner.load(files.map((f) => ({ name: f.name, bytes: encode(f.text) })));
  } catch (e) {
    if (e instanceof PlannerError) return e;
    throw e;
  }
  throw new Error("expected the load to fail");
}

describe("knowledge base loading in WASM", () => {
  it("loads FOON-111 (plain dialect) and reports its statistics", () => {
    const planner = FoonPlanner.load(readKnowledgeBase(sharedPath("foon/subgraphs-plain")));
    const stats = planner.stats();
    expect(stats.subgraphs).toBe(111);
    expect(stats.units).toBeLessThan(stats.units_before_merge);
    expect(stats.recipes_per_class.salad).toBeGreaterThanOrEqual(5);
    // the three defects of FOON-111 are reported with file and line, not dropped silently
    const warnings = planner.warnings();
    expect(warnings.length).toBe(stats.warnings);
    expect(warnings.every((w) => w.file !== undefined && w.line !== undefined)).toBe(true);
    planner.free();
  });

  it("gives the same statistics for both dialects' file counts and any file order", () => {
    const files = readKnowledgeBase(sharedPath("foon/subgraphs-indexed"));
    const a = FoonPlanner.load(files);
    const b = FoonPlanner.load([...files].reverse());
    expect(b.stats()).toEqual(a.stats());
    expect(a.stats().subgraphs).toBe(111);
  });

  it("names file, line and column of a malformed file, with a stable code", () => {
    const e = loadError([
      { name: "good.txt", text: "O\ttomato\t1\nS\twhole\nM\tslice\nO\ttomato\t1\nS\tsliced\n" },
      { name: "bad.txt", text: "O\ttomato\t1\nS\tin\t[bowl\n" },
    ]);
    expect(e.code).toBe("bad_brackets");
    expect([e.file, e.line, e.column]).toEqual(["bad.txt", 2, 6]);
    expect(e.message).toContain("bad.txt:2:6:");
  });

  it("rejects non-UTF-8 bytes and empty knowledge bases with their own codes", () => {
    let caught: unknown;
    try {
      FoonPlanner.load([{ name: "latin1.txt", bytes: new Uint8Array([0x4f, 0x09, 0xe9, 0x0a]) }]);
    } catch (e) {
      caught = e;
    }
    expect((caught as PlannerError).code).toBe("invalid_utf8");
    expect(loadError([{ name: "empty.txt", text: "# nothing here\n" }]).code).toBe("empty_knowledge_base");
  });

  it("still works after an error (the module survives)", () => {
    loadError([{ name: "bad.txt", text: "X\n" }]);
    const planner = FoonPlanner.load([{ name: "ok.txt", bytes: encode("O\ta\t1\nM\tcut\nO\ta\t1\nS\tcut\n") }]);
    expect(planner.stats().units).toBe(1);
  });
});

describe("vocabulary of a knowledge base (what the query editor offers)", () => {
  it("lists dish classes with recipe titles, labels and plain states of the bundle", () => {
    const bytes = readFileSync(join(ROOT, "public/kb/default.foon"));
    const planner = FoonPlanner.load([{ name: "default.foon", bytes: new Uint8Array(bytes) }]);
    const vocab = planner.vocabulary();
    planner.free();
    const salad = vocab.dishes.find((d) => d.name === "salad");
    expect(salad?.recipes).toContain("Greek salad");
    expect(vocab.titles["s01-greek_salad.txt"]).toBe("Greek salad");
    expect(vocab.labels).toContain("tomato");
    expect(vocab.states).toEqual(expect.arrayContaining(["whole", "diced", "chopped"]));
    expect(vocab.states.some((s) => s.includes("[") || s.includes("{"))).toBe(false);
  });
  it("titles a recipe by its title line, else by its file name, and lists labels in the planner's normal form", () => {
    const toast = "# title: Toast\n//\nO\tbread\t1\nS\tsliced\nM\ttoast\t<Assumed>\nO\ttoast\t1\t0\nS\ttoasted\nS\ton\t[plate]\n";
    const rolls = "//\nO\tbread rolls\t1\nS\twhole\nM\tslice\t<Assumed>\nO\tbread rolls\t1\t0\nS\tsliced\n";
    const planner = FoonPlanner.load([
      { name: "toast.txt", bytes: encode(toast) },
      { name: "0097-bread_rolls-DONE.txt", bytes: encode(rolls) },
    ]);
    expect(planner.vocabulary()).toEqual({
      dishes: [{ name: "bread", recipes: ["bread rolls", "Toast"] }],
      labels: ["bread", "bread roll", "toast"],
      states: ["sliced", "toasted", "whole"],
      titles: { "0097-bread_rolls-DONE.txt": "bread rolls", "toast.txt": "Toast" },
    });
    planner.free();
  });
});
