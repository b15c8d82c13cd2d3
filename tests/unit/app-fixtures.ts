// A small plan in the shape of docs/plan-format.md, for the view adapters' tests: a whole tomato diced
// and poured into a bowl, a chili pepper substituted for jalapeno (case 2) and a grafted chopping unit.

import type { Plan, PlanNode } from "../../src/planner/types";

const node = (label: string, states: string[], container: string | null = null, ingredients: string[] = []): PlanNode => ({ label, states, ingredients, container });

export function fixturePlan(): Plan {
  return {
    format_version: 1,
    query: { type: "salad", ingredients: [{ object: "tomato", state: "whole" }, { object: "chili pepper", state: "chopped" }] },
    dish_class: { index: 15, name: "salad" },
    notes: [],
    modified: true,
    goal: { label: "salsa", reference: "salsa", states: ["contains {chili pepper,tomato}", "in [bowl]", "mixed"], ingredients: ["jalapeno", "tomato"], subgraph: "s48-pico_de_gallo.txt", score: 0.5, dish_class: 7 },
    units: [
      { inputs: [node("knife", ["clean"]), node("tomato", ["whole"])], motion: "dice", outputs: [node("tomato", ["diced"])], origin: "reference", sources: ["s48"] },
      { inputs: [node("knife", ["clean"]), node("chili pepper", ["whole"])], motion: "chop", outputs: [node("chili pepper", ["chopped"])], origin: "grafted", sources: [] },
      {
        inputs: [node("bowl", ["empty"]), node("tomato", ["diced"]), node("chili pepper", ["chopped"])],
        motion: "pour",
        outputs: [node("tomato", ["diced", "in [bowl]"], "bowl"), node("chili pepper", ["chopped", "in [bowl]"], "bowl")],
        origin: "renamed",
        sources: ["s48"],
      },
      {
        inputs: [node("spoon", ["clean"]), node("tomato", ["diced", "in [bowl]"], "bowl"), node("chili pepper", ["chopped", "in [bowl]"], "bowl")],
        motion: "mix",
        outputs: [node("salsa", ["contains {chili pepper,tomato}", "in [bowl]", "mixed"], "bowl", ["chili pepper", "tomato"])],
        origin: "reference",
        sources: ["s48"],
      },
    ],
    ingredients: [
      { object: "tomato", state: "whole", case: 1, match: { label: "tomato", state: "whole", similarity: 1 }, alternatives: [{ label: "cherry tomato", similarity: 0.8 }], low_confidence: false, overridden: false, status: "planned" },
      {
        object: "chili pepper",
        state: "chopped",
        case: 2,
        match: { label: "jalapeno", state: "chopped", similarity: 0.42 },
        alternatives: [{ label: "jalapeno", similarity: 0.42 }, { label: "sweet pepper", similarity: 0.4 }, { label: "green pepper", similarity: 0.38 }],
        low_confidence: true,
        overridden: false,
        status: "planned",
      },
    ],
    removed: ["onion", "cilantro"],
    progress_lines: [
      { ingredient: "tomato", state: [{ physical_state: "whole", location: "" }, { physical_state: "diced", location: "" }, { physical_state: "diced", location: "in bowl" }, { physical_state: "in salsa", location: "in bowl" }], motion: ["dice", "pour", "mix"], end_product: "salsa" },
      { ingredient: "chili pepper", state: [{ physical_state: "whole", location: "" }, { physical_state: "chopped", location: "" }, { physical_state: "chopped", location: "in bowl" }, { physical_state: "in salsa", location: "in bowl" }], motion: ["chop", "pour", "mix"], end_product: "salsa" },
    ],
    steps: ["Dice the tomato.", "Chop the chili pepper.", "Pour the tomato and the chili pepper into the bowl.", "Mix them."],
    cautions: [],
  };
}
