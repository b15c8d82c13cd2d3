// View adapters: the plan as graph data, progress rows, selection sync, substitution rows, SVG export.
import { describe, expect, it } from "vitest";
import { graphToSvg, escapeXml } from "../../src/app/export/svg";
import { COLUMN_GAP, layoutTree, ROW_GAP } from "../../src/app/model/layout";
import { columnCount, progressRows } from "../../src/app/model/progress";
import { caseText, substituteChoices } from "../../src/app/model/substitutions";
import { describeUnit, motionKey, objectKey, planToGraph, selectNode, selectProgressMotion, selectUnit, unitsOfIngredient } from "../../src/app/model/tree";
import type { GraphColors } from "../../src/app/theme-colors";
import { fixturePlan } from "./app-fixtures";

const COLORS: GraphColors = { text: "#000", background: "#fff", object: "green", motion: "red", edge: "#777", mark: "blue", select: "orange", line: "orange" };

describe("task tree graph", () => {
  const plan = fixturePlan();
  const graph = planToGraph(plan);
  it("has one motion node per unit and one object node per distinct label + states", () => {
    expect(graph.nodes.filter((n) => n.kind === "motion")).toHaveLength(4);
    // knife (shared), tomato whole/diced/in bowl, chili whole/chopped/in bowl, bowl, spoon, salsa
    expect(graph.nodes.filter((n) => n.kind === "object")).toHaveLength(10);
    expect(graph.edges.every((e) => graph.nodes.some((n) => n.id === e.source) && graph.nodes.some((n) => n.id === e.target))).toBe(true);
  });
  it("runs edges input -> motion -> output", () => {
    const dice = motionKey(0);
    expect(graph.edges).toContainEqual({ id: `e:${objectKey({ label: "tomato", states: ["whole"], ingredients: [], container: null })}>${dice}`, source: "o:tomato|whole", target: dice });
    expect(graph.edges.some((e) => e.source === dice && e.target === "o:tomato|diced")).toBe(true);
  });
  it("marks what modification touched and the goal node", () => {
    const byId = new Map(graph.nodes.map((n) => [n.id, n]));
    expect(byId.get(motionKey(1))?.mark).toBe("grafted");
    expect(byId.get(motionKey(2))?.mark).toBe("renamed");
    expect(byId.get(motionKey(0))?.mark).toBeNull();
    expect(byId.get("o:chili pepper|chopped")?.mark).toBe("substituted"); // case 2
    expect(byId.get("o:tomato|diced")?.mark).toBeNull();
    expect(graph.nodes.filter((n) => n.goal).map((n) => n.label)).toEqual(["salsa"]);
  });
  it("selects the same unit and progress line from every view", () => {
    expect(selectNode(graph, "o:tomato|diced")).toEqual({ unit: 0, ingredient: "tomato", node: "o:tomato|diced" });
    expect(selectUnit(plan, 1)).toEqual({ unit: 1, ingredient: "chili pepper", node: motionKey(1) });
    expect(unitsOfIngredient(plan, "chili pepper")).toEqual([1, 2, 3]);
    expect(selectProgressMotion(plan, "chili pepper", 1)).toEqual({ unit: 2, ingredient: "chili pepper", node: motionKey(2) });
    expect(selectUnit(plan, 99).unit).toBeNull();
    expect(describeUnit(plan, 0)).toBe("dice: knife (clean), tomato (whole) → tomato (diced)");
  });
});

describe("task tree layout", () => {
  const graph = planToGraph(fixturePlan());
  const at = layoutTree(graph);
  it("places every node, each edge running left to right, the goal node last", () => {
    expect([...at.keys()].sort()).toEqual(graph.nodes.map((n) => n.id).sort());
    for (const e of graph.edges) expect(at.get(e.source)!.x, e.id).toBeLessThan(at.get(e.target)!.x);
    const goal = graph.nodes.find((n) => n.goal)!;
    expect(at.get(goal.id)!.x).toBe(Math.max(...[...at.values()].map((p) => p.x)));
  });
  it("never puts two nodes of a column closer than a row", () => {
    const points = [...at.values()];
    for (const p of points) for (const q of points) if (p !== q && p.x === q.x) expect(Math.abs(p.y - q.y)).toBeGreaterThanOrEqual(ROW_GAP);
  });
  it("puts an ingredient one column before its first use, and a chain on one row", () => {
    // the spoon joins at the last unit, not in the first column
    expect(at.get("o:spoon|clean")!.x).toBe(at.get(motionKey(3))!.x - COLUMN_GAP);
    const node = graph.nodes[0]!;
    const chain = { nodes: ["a", "m", "b"].map((id) => ({ ...node, id })), edges: [{ id: "1", source: "a", target: "m" }, { id: "2", source: "m", target: "b" }] };
    const placed = layoutTree(chain);
    expect(["a", "m", "b"].map((id) => placed.get(id))).toEqual([0, 1, 2].map((c) => ({ x: c * COLUMN_GAP, y: 0 })));
  });
  it("lays out a graph with a cycle without hanging", () => {
    const cyclic = { nodes: ["a", "b", "c"].map((id) => ({ ...graph.nodes[0]!, id })), edges: [{ id: "1", source: "a", target: "b" }, { id: "2", source: "b", target: "c" }, { id: "3", source: "c", target: "a" }] };
    expect(layoutTree(cyclic).size).toBe(3);
  });
});

describe("progress lines", () => {
  it("alternates states and motions and ends with the product", () => {
    const rows = progressRows(fixturePlan());
    expect(rows.map((r) => r.ingredient)).toEqual(["tomato", "chili pepper"]);
    expect(rows[0]!.cells.map((c) => c.kind)).toEqual(["state", "motion", "state", "motion", "state", "motion", "state", "product"]);
    expect(rows[1]!.cells[1]).toEqual({ kind: "motion", text: "chop", index: 0, unit: 1 });
    expect(columnCount(rows)).toBe(8);
  });
});

describe("substitutions", () => {
  it("names the case in words and lists the equivalent first without repeats", () => {
    const [tomato, chili] = fixturePlan().ingredients;
    expect(caseText(tomato!)).toBe("Case 1: exact match: used as it is");
    expect(caseText(chili!)).toBe("Case 2: object substituted, same state");
    expect(substituteChoices(chili!).map((c) => c.label)).toEqual(["jalapeno", "sweet pepper", "green pepper"]);
    expect(caseText({ ...chili!, case: null, status: "unplannable" })).toBe("not plannable");
  });
});

describe("SVG export", () => {
  it("escapes hostile labels", () => {
    expect(escapeXml(`<img src=x onerror="alert(1)">`)).not.toMatch(/[<>"]/);
    const svg = graphToSvg(
      [{ id: "a", kind: "object", label: "<img src=x onerror=alert(1)>", detail: "whole", mark: null, goal: false, x: 0, y: 0, size: 26 }],
      [],
      COLORS,
      "t",
    );
    expect(svg).not.toContain("<img");
    expect(svg).toContain("&#60;img");
  });
  it("draws circles for objects, squares for motions, and arrows between them", () => {
    const graph = planToGraph(fixturePlan());
    const placed = graph.nodes.map((n, i) => ({ ...n, x: i * 50, y: (i % 3) * 40, size: 26 }));
    const svg = graphToSvg(placed, graph.edges, COLORS, "Task tree");
    expect(svg.match(/<circle /g)).toHaveLength(10);
    expect(svg.match(/<rect x=/g)?.length).toBeGreaterThanOrEqual(4);
    expect(svg.match(/<line /g)).toHaveLength(graph.edges.length);
    expect(svg).toContain('data-mark="grafted"');
  });
});
