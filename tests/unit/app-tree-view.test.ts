// The task-tree view keeps Cytoscape's elements across re-plans: after any sequence of plans the graph
// drawn must be exactly the latest plan's (nothing stale left, nothing missing, marks and places current).
import cytoscape, { type Core } from "cytoscape";
import { describe, expect, it } from "vitest";
import { planToGraph } from "../../src/app/model/tree";
import { elements, showGraph } from "../../src/app/views/tree-view";
import type { Plan } from "../../src/planner/types";
import { fixturePlan } from "./app-fixtures";

/** What the user sees of each element: id, place, caption, marks (classes), ends of edges. */
function drawn(cy: Core): string[] {
  return cy
    .elements()
    .map((e) => (e.isNode() ? `${e.id()} @${e.position("x")},${e.position("y")} ${JSON.stringify(e.data("caption"))} [${e.classes().sort().join(" ")}]` : `${e.id()} ${e.source().id()}>${e.target().id()}`))
    .sort();
}

/** The same elements drawn on an empty canvas. */
function fresh(plan: Plan): string[] {
  const cy = cytoscape({ headless: true });
  cy.add(elements(planToGraph(plan)));
  return drawn(cy);
}

/** The fixture with the tomato chopped instead of diced and the grafted unit taken from the reference. */
function edited(): Plan {
  const plan = fixturePlan();
  const rename = (n: { states: string[] }): void => {
    n.states = n.states.map((s) => (s === "diced" ? "chopped" : s));
  };
  for (const u of plan.units) [...u.inputs, ...u.outputs].forEach(rename);
  plan.units[0]!.motion = "chop";
  plan.units[1]!.origin = "reference";
  return plan;
}

describe("task tree view, re-plans", () => {
  it("draws each plan exactly as on an empty canvas, whatever was drawn before", () => {
    const cy = cytoscape({ headless: true });
    const short: Plan = { ...fixturePlan(), units: fixturePlan().units.slice(0, 2) };
    for (const plan of [fixturePlan(), edited(), short, fixturePlan(), edited()]) {
      showGraph(cy, planToGraph(plan));
      expect(drawn(cy)).toEqual(fresh(plan));
    }
  });
  it("keeps the elements both plans share (so Cytoscape restyles only what changed)", () => {
    const cy = cytoscape({ headless: true });
    showGraph(cy, planToGraph(fixturePlan()));
    const knife = cy.getElementById("o:knife|clean");
    showGraph(cy, planToGraph(edited()));
    expect(cy.getElementById("o:knife|clean").same(knife)).toBe(true);
    expect(cy.getElementById("o:tomato|diced").empty()).toBe(true);
  });
});
