// Steps many starter recipes share, written once.
import type { Kitchen, Recipe } from "../recipe";

export const WATER: Kitchen = ["water", "liquid", "from [faucet]"];
export const SALT: Kitchen = ["salt", "granulated", "in [shaker]"];
export const PEPPER: Kitchen = ["black pepper", "ground", "in [shaker]"];
export const FLOUR: Kitchen = ["flour", "powder", "in [package]"];
export const SUGAR: Kitchen = ["sugar", "granulated", "in [package]"];
export const OLIVE_OIL: Kitchen = ["olive oil", "liquid", "in [bottle]"];
export const VEGETABLE_OIL: Kitchen = ["vegetable oil", "liquid", "in [bottle]"];
export const BUTTER: Kitchen = ["butter", "stick"];
export const MILK: Kitchen = ["milk", "liquid", "in [carton]"];

/** Warm water with yeast (and sugar) stirred in a measuring cup: the yeast mixture of a yeast dough. */
export function yeastMixture(r: Recipe, sugar = true): Recipe {
  r.put("pour", WATER, "measuring cup").alter("heat", "water", { plus: ["warm"], with: ["microwave"] });
  r.put("sprinkle", ["yeast", "powder", "in [package]"], "measuring cup");
  if (sugar) r.put("sprinkle", SUGAR, "measuring cup");
  return r.mix("stir", "measuring cup", "yeast mixture", ["liquid", "mixed"], { with: ["spoon"] });
}

/** A mixed dough kneaded on the board and left to rise, covered, in a bowl. */
export function kneadAndRise(r: Recipe, bowl = "mixing bowl"): Recipe {
  r.mix("mix", bowl, "dough", ["mixed", "lumpy"], { with: ["wooden spoon"] });
  r.put("scrape", "dough", "cutting board").alter("knead", "dough", { set: ["kneaded"] });
  r.put("pick-and-place", "dough", "bowl").alter("cover", "dough", { plus: ["covered"], with: ["towel"] });
  return r.alter("ferment", "dough", { set: ["kneaded", "risen"] });
}

/** Eggs cracked into a bowl, one step each. */
export function crackEggs(r: Recipe, into: string, label = "egg"): Recipe {
  return r.put("crack", [label, "whole"], into, { set: ["cracked", "uncooked"] });
}

/** A peeled, minced garlic clove on the cutting board. */
export function mincedGarlic(r: Recipe): Recipe {
  return r.prep(["garlic", "clove", "unpeeled"], "peel:peeled,clove", "mince:minced");
}

/** A peeled, chopped (or diced) onion on the cutting board. */
export function choppedOnion(r: Recipe, cut = "chop:chopped", label = "onion"): Recipe {
  return r.prep([label, "whole", "unpeeled"], "peel:peeled,whole", cut);
}

/** The dish moved onto a plate or into a serving bowl with a tool: the last step of most recipes. */
export function serve(r: Recipe, dish: string, to = "plate", motion = "pick-and-place", tool = "spatula"): Recipe {
  return r.put(motion, dish, to, { with: [tool] });
}

/** Tap water brought to the boil in a pot or saucepan on the stove. */
export function boilingWater(r: Recipe, pot = "pot"): Recipe {
  return r.put("pour", WATER, pot).heat(pot).alter("boil", "water", { plus: ["boiling"] });
}

/** An egg boiled in its shell, lifted onto the cutting board (the water stays behind) and peeled. */
export function hardBoiledEgg(r: Recipe): Recipe {
  boilingWater(r, "saucepan").put("pick-and-place", ["egg", "whole"], "saucepan", { with: ["spoon"] });
  r.cookEach("boil", "saucepan", ["egg"], { set: ["whole", "boiled"] });
  r.put("pick-and-place", "egg", "cutting board", { with: ["spoon"] }).drop("water");
  return r.alter("peel", "egg", { set: ["peeled", "boiled"] });
}

/** Noodles or pasta boiled in a pot of water and drained in a colander (the water stays behind). */
export function boilNoodles(r: Recipe, noodle: string, state = "dried"): Recipe {
  boilingWater(r);
  r.put("pour", [noodle, state, "in [package]"], "pot");
  r.cookEach("boil", "pot", [noodle], { set: ["cooked"], with: ["tongs"] });
  return r.put("drain", noodle, "colander").drop("water");
}
