// Omelette: folded French omelettes (plain, filled, egg-white, souffle), a baked frittata, eggs cooked in a
// sauce, a rolled omelette and scrambled eggs.
import { Recipe } from "../recipe";
import { written, type WrittenRecipe } from "../written";
import { BUTTER, choppedOnion, crackEggs, MILK, mincedGarlic, OLIVE_OIL, PEPPER, SALT, serve, SUGAR, VEGETABLE_OIL } from "./common";

/** Eggs (and milk) beaten with salt and pepper in a bowl: the egg mixture of most omelettes. */
function beatenEggs(r: Recipe, milk = true): Recipe {
  crackEggs(r, "bowl");
  if (milk) r.put("pour", MILK, "bowl");
  r.putAll("sprinkle", [SALT, PEPPER], "bowl");
  return r.mix("beat", "bowl", "egg mixture", ["beaten", "uncooked"], { with: ["fork"] });
}

/** Butter melted in a hot frying pan, the egg mixture poured in and cooked until just set. */
function cookInButter(r: Recipe, pan = "frying pan"): Recipe {
  r.put("pick-and-place", BUTTER, pan).heat(pan).alter("melt", "butter", { set: ["melted"] });
  r.put("pour", "egg mixture", pan);
  return r.mix("cook", pan, "omelette", ["partly cooked"], { with: ["spatula"] });
}

/** The omelette folded over its filling, cooked a minute more so the filling heats through, and slid onto a plate. */
function foldAndServe(r: Recipe): Recipe {
  r.alter("fold", "omelette", { set: ["folded", "partly cooked"], with: ["spatula"] });
  r.alter("cook", "omelette", { set: ["folded", "cooked"], with: ["spatula"] });
  return serve(r, "omelette");
}

/** A plain French omelette finished with chopped fresh herbs. */
function frenchHerbOmelette(): WrittenRecipe {
  const r = new Recipe("s85-french_herb_omelette", "French omelette with fines herbes", "omelette");
  beatenEggs(r, false);
  r.prep(["chive", "whole"], "chop:chopped").prep(["parsley", "leaf"], "chop:chopped");
  cookInButter(r);
  r.top("sprinkle", "chive", "omelette").top("sprinkle", "parsley", "omelette");
  return written(foldAndServe(r), "omelette");
}

function hamCheeseOmelette(): WrittenRecipe {
  const r = new Recipe("s86-ham_and_cheese_omelette", "Ham and cheese omelette", "omelette");
  beatenEggs(r);
  r.prep(["ham", "sliced", "in [package]"], "dice:diced").prep(["cheddar", "block", "in [package]"], "grate:grated");
  cookInButter(r);
  r.top("sprinkle", "ham", "omelette").top("sprinkle", "cheddar", "omelette");
  return written(foldAndServe(r), "omelette");
}

/** Egg whites only, with sauteed vegetables folded inside. */
function eggWhiteOmelette(): WrittenRecipe {
  const r = new Recipe("s87-egg_white_vegetable_omelette", "Egg-white omelette with spinach and tomato", "omelette");
  r.put("pour", ["egg white", "liquid", "in [carton]"], "bowl").putAll("sprinkle", [SALT, PEPPER], "bowl");
  r.mix("whisk", "bowl", "egg mixture", ["beaten", "uncooked"], { with: ["whisk"] });
  r.put("rinse", ["spinach", "leaf", "in [package]"], "colander", { plus: ["washed"] });
  r.prep(["mushroom", "whole"], "slice:sliced").prep(["tomato", "whole"], "cut:seeded", "dice:diced");
  r.put("pour", OLIVE_OIL, "skillet").heat("skillet").put("pour", "mushroom", "skillet");
  r.cookEach("cook and stir", "skillet", ["mushroom"], { plus: ["sauteed"], with: ["spatula"] });
  r.put("pick-and-place", "spinach", "skillet");
  r.cookEach("cook and stir", "skillet", ["spinach"], { set: ["wilted"], with: ["spatula"] });
  r.put("pour", "egg mixture", "skillet");
  r.mix("cook", "skillet", "omelette", ["partly cooked"], { with: ["spatula"] });
  r.top("sprinkle", "tomato", "omelette");
  return written(foldAndServe(r), "omelette");
}

/** Souffle omelette: whipped whites folded into the yolks, set in the pan and finished in the oven. */
function souffleOmelette(): WrittenRecipe {
  const r = new Recipe("s88-souffle_omelette_with_jam", "Sweet souffle omelette with strawberry jam", "omelette");
  r.preheat();
  r.put("pour", ["egg white", "liquid", "in [carton]"], "mixing bowl");
  r.alter("whisk", "egg white", { set: ["whipped"], with: ["hand mixer"] });
  crackEggs(r, "bowl").put("sprinkle", SUGAR, "bowl").put("pour", ["vanilla extract", "liquid", "in [bottle]"], "bowl");
  r.mix("beat", "bowl", "egg mixture", ["beaten", "uncooked"], { with: ["whisk"] });
  r.put("pour and scrape", "egg mixture", "mixing bowl", { with: ["spatula"] });
  r.mix("fold", "mixing bowl", "egg mixture", ["whipped", "uncooked"], { with: ["spatula"] });
  r.put("pick-and-place", BUTTER, "frying pan").heat("frying pan").alter("melt", "butter", { set: ["melted"] });
  r.put("pour and scrape", "egg mixture", "frying pan", { with: ["spatula"] });
  r.mix("cook", "frying pan", "omelette", ["partly cooked"]);
  r.alter("bake", "omelette", { set: ["baked", "cooked"], with: ["oven"] });
  r.top("spread", ["strawberry jam", "paste", "in [jar]"], "omelette", { with: ["spoon"] });
  r.alter("fold", "omelette", { set: ["folded", "baked", "cooked"], with: ["spatula"] });
  serve(r, "omelette");
  r.top("sprinkle", ["powdered sugar", "powder", "in [package]"], "omelette", { plus: ["garnished"], with: ["sieve"] });
  return written(r, "omelette");
}

/** A thick vegetable frittata set on the stove and baked through in the oven. */
function vegetableFrittata(): WrittenRecipe {
  const r = new Recipe("s89-zucchini_pepper_frittata", "Baked zucchini, pepper and feta frittata", "omelette");
  r.preheat();
  choppedOnion(r);
  r.prep(["zucchini", "whole"], "cut off ends:ends removed", "dice:diced");
  r.prep(["sweet pepper", "whole"], "cut:seeded", "dice:diced");
  r.prep(["feta cheese", "block", "in [package]"], "cut:crumbled:fork");
  beatenEggs(r);
  r.put("pour", OLIVE_OIL, "skillet").heat("skillet");
  for (const v of ["onion", "zucchini", "sweet pepper"]) r.put("pour", v, "skillet");
  r.cookEach("cook and stir", "skillet", ["onion", "zucchini", "sweet pepper"], { plus: ["sauteed"], with: ["wooden spoon"] });
  r.put("pour", "egg mixture", "skillet").put("sprinkle", "feta cheese", "skillet");
  r.mix("cook", "skillet", "frittata", ["partly cooked"], { with: ["spatula"] });
  r.alter("bake", "frittata", { set: ["baked"], with: ["oven"] });
  r.alter("cut", "frittata", { set: ["wedge", "baked"], with: ["knife"] });
  return written(serve(r, "frittata"), "frittata");
}

/** Shakshuka: eggs cooked in a spiced pepper and tomato sauce, covered, in the skillet. */
function shakshuka(): WrittenRecipe {
  const r = new Recipe("s90-shakshuka", "Shakshuka", "omelette");
  choppedOnion(r).prep(["sweet pepper", "whole"], "cut:seeded", "slice:sliced");
  mincedGarlic(r);
  r.put("pour", OLIVE_OIL, "skillet").heat("skillet");
  for (const v of ["onion", "sweet pepper", "garlic"]) r.put("pour", v, "skillet");
  r.mix("cook and stir", "skillet", "pepper mixture", ["sauteed", "mixed"], { with: ["wooden spoon"] });
  r.putAll("sprinkle", [["cumin", "ground", "in [jar]"], ["paprika", "ground", "in [jar]"], SALT], "skillet");
  r.put("pour", ["tomato sauce", "thick liquid", "in [can]"], "skillet");
  r.mix("simmer", "skillet", "sauce", ["thick liquid", "cooked"], { with: ["wooden spoon"] });
  crackEggs(r, "skillet");
  r.mix("cook", "skillet", "shakshuka", ["cooked", "covered"], { with: ["pot lid"] });
  r.prep(["cilantro", "leaf"], "chop:chopped").top("sprinkle", "cilantro", "shakshuka", { plus: ["garnished"] });
  return written(r, "shakshuka");
}

/** Japanese rolled omelette: sweetened egg cooked in a thin layer, rolled up and sliced. */
function rolledOmelette(): WrittenRecipe {
  const r = new Recipe("s91-tamagoyaki", "Japanese rolled omelette (tamagoyaki)", "omelette");
  crackEggs(r, "bowl").put("pour", ["soy sauce", "liquid", "in [bottle]"], "bowl");
  r.put("pour", ["mirin", "liquid", "in [bottle]"], "bowl").put("sprinkle", SUGAR, "bowl");
  r.mix("beat", "bowl", "egg mixture", ["beaten", "uncooked"], { with: ["chopstick"] });
  r.put("pour", VEGETABLE_OIL, "frying pan").heat("frying pan").put("pour", "egg mixture", "frying pan");
  r.mix("cook", "frying pan", "omelette", ["partly cooked"], { with: ["chopstick"] });
  r.alter("roll", "omelette", { set: ["rolled", "cooked"], with: ["spatula"] });
  r.put("pick-and-place", "omelette", "cutting board", { with: ["spatula"] });
  r.alter("slice", "omelette", { set: ["sliced", "rolled", "cooked"], with: ["knife"] });
  return written(r, "omelette");
}

function scrambledEggs(): WrittenRecipe {
  const r = new Recipe("s92-scrambled_eggs_with_chives", "Soft scrambled eggs with chives", "omelette");
  beatenEggs(r);
  r.put("pick-and-place", BUTTER, "skillet").heat("skillet").alter("melt", "butter", { set: ["melted"] });
  r.put("pour", "egg mixture", "skillet");
  r.mix("cook and stir", "skillet", "scrambled egg", ["scrambled", "cooked"], { with: ["spatula"] });
  r.prep(["chive", "whole"], "chop:chopped").top("sprinkle", "chive", "scrambled egg", { plus: ["garnished"] });
  return written(serve(r, "scrambled egg"), "scrambled egg");
}

export const omelette = (): WrittenRecipe[] => [
  frenchHerbOmelette(), hamCheeseOmelette(), eggWhiteOmelette(), souffleOmelette(), vegetableFrittata(), shakshuka(),
  rolledOmelette(), scrambledEggs(),
];
