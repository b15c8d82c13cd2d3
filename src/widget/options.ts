// The widget's options and how its attributes read into them (pure, unit-tested).

import type { QueryIngredient, RetrievalMode } from "../planner/types";
import type { ViewName } from "../app/app";
import type { ThemeChoice } from "../app/prefs";
import { normalizeName, parseIngredientList } from "../app/query";

export type WidgetView = "tree" | "progress" | "steps" | "explain" | "all";

export interface WidgetOptions {
  /** Dish type, e.g. "salad". */
  dishType?: string;
  /** "chopped chili pepper, whole tomato" (states read with the knowledge base's states), or rows. */
  ingredients?: string | QueryIngredient[];
  view?: WidgetView;
  theme?: ThemeChoice;
  /** Knowledge base URL (relative to the page); default: the bundled one. */
  kbUrl?: string;
  /** Retrieval mode (docs/robot.md); default the paper's heuristic. */
  mode?: RetrievalMode;
}

export const WIDGET_VIEWS: Record<WidgetView, ViewName[]> = {
  tree: ["tree"],
  progress: ["progress"],
  steps: ["steps"],
  explain: ["explain"],
  all: ["tree", "progress", "steps", "substitutions"],
};

export function parseView(value: string | null | undefined): WidgetView {
  return value === "tree" || value === "progress" || value === "steps" || value === "explain" || value === "all" ? value : "all";
}

export function parseTheme(value: string | null | undefined): ThemeChoice {
  return value === "light" || value === "dark" ? value : "system";
}

/**
 * Ingredient rows of the `ingredients` option. "object~state" items are taken as written; other items are
 * split into state and object with the knowledge base's states ("chopped chili pepper").
 */
export function widgetIngredients(value: WidgetOptions["ingredients"], knownStates: readonly string[]): QueryIngredient[] {
  if (value === undefined) return [];
  if (typeof value !== "string") return value.map((i) => ({ object: normalizeName(i.object), state: normalizeName(i.state) }));
  return value
    .split(/[,;\n]+/)
    .map((item) => item.trim())
    .filter((item) => item !== "")
    .flatMap((item) => {
      const at = item.indexOf("~");
      if (at >= 0) return [{ object: normalizeName(item.slice(0, at)), state: normalizeName(item.slice(at + 1)) }];
      return parseIngredientList(item, knownStates);
    });
}
