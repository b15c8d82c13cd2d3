// Every builder-made starter recipe, by dish type.
import type { WrittenRecipe } from "../written";
import { bread } from "./bread";

export function allRecipes(): WrittenRecipe[] {
  return [...bread()];
}
