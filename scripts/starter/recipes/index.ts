// Every builder-made starter recipe, by dish type.
import type { WrittenRecipe } from "../written";
import { bread } from "./bread";
import { breadDishes } from "./bread-dishes";
import { cake } from "./cake";
import { drinks } from "./drinks";
import { noodle } from "./noodle";
import { omelette } from "./omelette";
import { rice } from "./rice";
import { salad } from "./salad";
import { soup } from "./soup";

export function allRecipes(): WrittenRecipe[] {
  return [...bread(), ...breadDishes(), ...cake(), ...drinks(), ...noodle(), ...omelette(), ...rice(), ...salad(), ...soup()];
}
