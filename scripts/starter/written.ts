// The starter recipes written with the builder, as the files they become in public/kb/starter/.
import type { DishType, Recipe } from "./recipe";

export interface WrittenRecipe {
  file: string;
  dish: DishType;
  text: string;
}

export function written(recipe: Recipe, goal: string): WrittenRecipe {
  return { file: `${recipe.file}.txt`, dish: recipe.dish, text: recipe.text(goal) };
}
