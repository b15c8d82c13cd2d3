// Hand-made plans of the documented shape (docs/plan-format.md) for the evaluation unit tests.

import type { IngredientOutcome, Plan, PlanNode, PlanUnit, Query } from "../../src/planner/types";

export function node(label: string, states: string[] = [], ingredients: string[] = [], container: string | null = null): PlanNode {
  return { label, states, ingredients, container };
}

export function unit(inputs: PlanNode[], motion: string, outputs: PlanNode[]): PlanUnit {
  return { inputs, motion, outputs, origin: "reference", sources: ["test.txt"] };
}

export function outcome(object: string, state: string, extra: Partial<IngredientOutcome> = {}): IngredientOutcome {
  return { object, state, case: 1, match: { label: object, state, similarity: 1 }, alternatives: [], low_confidence: false, overridden: false, status: "planned", ...extra };
}

const board = node("cutting board", ["empty"]);
const knife = node("knife", ["clean"]);
const bowl = node("bowl", ["empty"]);
const tomatoWhole = node("tomato", ["whole"]);
const tomatoOnBoard = node("tomato", ["whole", "on [cutting board]"], [], "cutting board");
const tomatoDiced = node("tomato", ["diced", "on [cutting board]"], [], "cutting board");
const bowlWithTomato = node("bowl", ["contains {tomato}"], ["tomato"]);
const saltWhole = node("salt", ["ground"]);
export const salad = node("salad", ["mixed", "in [bowl]"], ["salt", "tomato"], "bowl");

/** A correct small plan: dice a tomato, put it in a bowl, add salt and mix into a salad. */
export function cleanUnits(): PlanUnit[] {
  return [
    unit([board, tomatoWhole], "pick-and-place", [tomatoOnBoard]),
    unit([tomatoOnBoard, knife], "dice", [tomatoDiced, knife]),
    unit([bowl, tomatoDiced], "pour", [bowlWithTomato]),
    unit([bowlWithTomato, saltWhole], "mix", [salad]),
  ];
}

export function plan(units: PlanUnit[] = cleanUnits(), query: Partial<Query> = {}, ingredients?: IngredientOutcome[]): Plan {
  const q: Query = { id: "r1", type: "salad", ingredients: [{ object: "tomato", state: "diced" }, { object: "salt", state: "ground" }], ...query };
  return {
    format_version: 1,
    query: q,
    dish_class: { index: 0, name: q.type },
    notes: [],
    modified: true,
    goal: { label: "salad", reference: "salad", states: ["in [bowl]", "mixed"], ingredients: ["salt", "tomato"], subgraph: "test.txt", score: 1, dish_class: 0 },
    units,
    ingredients: ingredients ?? q.ingredients.map((i) => outcome(i.object, i.state)),
    removed: [],
    progress_lines: q.ingredients.map((i) => ({ ingredient: i.object, state: [{ physical_state: "whole", location: "" }, { physical_state: i.state, location: "bowl" }], motion: ["dice"], end_product: "salad" })),
    steps: units.map((u) => u.motion),
    cautions: [],
  };
}
