// Every builder-made starter recipe, by dish type.
import type { WrittenRecipe } from "../written";
import { bread } from "./bread";
import { cake } from "./cake";
import { drinks } from "./drinks";
import { noodle } from "./noodle";

export function allRecipes(): WrittenRecipe[] {
  return [...bread(), ...cake(), ...drinks(), ...noodle()];
}
