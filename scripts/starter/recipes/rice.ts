// Rice: plain steamed rice, fried rice, pilafs (toasted then simmered), risotto, coconut rice, porridge, a rice
// salad, and baked rice dishes.
import { Recipe } from "../recipe";
import { written, type WrittenRecipe } from "../written";
import { boilingWater, BUTTER, choppedOnion, crackEggs, MILK, mincedGarlic, OLIVE_OIL, PEPPER, SALT, serve, SUGAR, VEGETABLE_OIL, WATER } from "./common";

const RICE = ["rice", "uncooked", "in [package]"] as const;
const BROTH = ["chicken broth", "liquid", "in [carton]"] as const;
const SOY = ["soy sauce", "liquid", "in [bottle]"] as const;

/** Rice rinsed in a strainer until the water runs clear, then tipped into a pot. */
function rinsedRice(r: Recipe, pot: string): Recipe {
  return r.put("rinse", [...RICE], "strainer", { plus: ["washed"] }).put("pour", "rice", pot);
}

/** Rinsed rice simmered covered in salted water until it has taken up the water, then fluffed. */
function steamedRice(r: Recipe, pot = "saucepan"): Recipe {
  rinsedRice(r, pot).put("pour", WATER, pot).put("sprinkle", SALT, pot).heat(pot);
  r.mix("simmer", pot, "rice", ["cooked", "covered"], { with: ["pot lid"] });
  return r.alter("uncover", "rice", { set: ["cooked", "fluffed"], with: ["fork"] });
}

/** Rice stirred in the hot fat until the grains are toasted, before the liquid goes in (a pilaf). */
function toastRice(r: Recipe, pot: string): Recipe {
  rinsedRice(r, pot);
  return r.cookEach("cook and stir", pot, ["rice"], { plus: ["toasted"], with: ["wooden spoon"] });
}

function plainSteamedRice(): WrittenRecipe {
  const r = new Recipe("s93-steamed_white_rice", "Steamed white rice", "rice");
  steamedRice(r);
  return written(serve(r, "rice", "serving bowl", "scoop and pour", "spoon"), "rice");
}

function chickenFriedRice(): WrittenRecipe {
  const r = new Recipe("s94-chicken_fried_rice", "Chicken fried rice", "rice");
  steamedRice(r).put("pour", "rice", "baking tray").alter("cool down", "rice", { plus: ["cooled"] });
  r.prep(["chicken", "raw"], "dice:diced");
  r.prep(["carrot", "whole", "unpeeled"], "peel:peeled,whole:peeler", "dice:diced");
  r.prep(["green onion", "whole"], "slice:sliced");
  mincedGarlic(r);
  crackEggs(r, "bowl").mix("beat", "bowl", "egg mixture", ["beaten", "uncooked"], { with: ["fork"] });
  r.put("pour", VEGETABLE_OIL, "wok").heat("wok").put("pick-and-place", "chicken", "wok", { with: ["tongs"] });
  r.cookEach("cook and stir", "wok", ["chicken"], { set: ["diced", "stir-fried", "cooked"], with: ["spatula"] });
  r.put("pour", "egg mixture", "wok");
  r.cookEach("cook and stir", "wok", ["egg mixture"], { set: ["scrambled", "cooked"], with: ["spatula"] });
  for (const v of ["garlic", "carrot"]) r.put("pour", v, "wok");
  r.put("pour", ["green pea", "frozen", "in [package]"], "wok");
  r.cookEach("cook and stir", "wok", ["garlic", "carrot", "green pea"], { plus: ["stir-fried"], with: ["spatula"] });
  r.put("pour", "rice", "wok").put("pour", [...SOY], "wok").put("pour", ["sesame oil", "liquid", "in [bottle]"], "wok");
  r.put("sprinkle", "green onion", "wok");
  r.mix("cook and stir", "wok", "fried rice", ["stir-fried", "mixed"], { with: ["spatula"] });
  return written(serve(r, "fried rice", "serving bowl", "scoop and pour", "spatula"), "fried rice");
}

/** Risotto: toasted rice given hot broth a ladle at a time and stirred creamy, finished with parmesan. */
function mushroomRisotto(): WrittenRecipe {
  const r = new Recipe("s95-mushroom_risotto", "Mushroom risotto", "rice");
  r.put("pour", [...BROTH], "saucepan").heat("saucepan").alter("heat", "chicken broth", { plus: ["hot"] });
  r.prep(["shallot", "whole", "unpeeled"], "peel:peeled,whole", "mince:minced");
  r.prep(["mushroom", "whole"], "slice:sliced");
  r.put("pour", OLIVE_OIL, "pot").heat("pot");
  r.put("pour", "shallot", "pot").put("pour", "mushroom", "pot");
  r.cookEach("cook and stir", "pot", ["shallot", "mushroom"], { plus: ["sauteed"], with: ["wooden spoon"] });
  r.put("pour", ["rice", "uncooked", "in [package]"], "pot");
  r.cookEach("cook and stir", "pot", ["rice"], { plus: ["toasted"], with: ["wooden spoon"] });
  r.put("pour", ["white wine", "liquid", "in [bottle]"], "pot").put("pour", "chicken broth", "pot", { with: ["ladle"] });
  r.mix("cook and stir", "pot", "risotto", ["creamy", "cooked"], { with: ["wooden spoon"] });
  r.top("pick-and-place", BUTTER, "risotto");
  r.prep(["parmesan", "block", "in [package]"], "grate:grated").top("sprinkle", "parmesan", "risotto", { plus: ["mixed"] });
  return written(serve(r, "risotto", "serving bowl", "scoop and pour", "ladle"), "risotto");
}

/** Mexican red rice: toasted rice simmered in broth with tomato, onion and garlic. */
function mexicanRice(): WrittenRecipe {
  const r = new Recipe("s96-mexican_red_rice", "Mexican red rice", "rice");
  choppedOnion(r, "dice:diced");
  mincedGarlic(r);
  r.put("pour", VEGETABLE_OIL, "saucepan").heat("saucepan");
  toastRice(r, "saucepan");
  r.put("pour", "onion", "saucepan").put("pour", "garlic", "saucepan");
  r.cookEach("cook and stir", "saucepan", ["onion", "garlic"], { plus: ["sauteed"], with: ["wooden spoon"] });
  r.put("pour", ["tomato sauce", "thick liquid", "in [can]"], "saucepan").put("pour", [...BROTH], "saucepan");
  r.putAll("sprinkle", [["cumin", "ground", "in [jar]"], SALT], "saucepan");
  r.mix("simmer", "saucepan", "rice", ["cooked", "covered"], { with: ["pot lid"] });
  r.alter("uncover", "rice", { set: ["cooked", "fluffed"], with: ["fork"] });
  r.prep(["cilantro", "leaf"], "chop:chopped").top("sprinkle", "cilantro", "rice", { plus: ["garnished"] });
  return written(r, "rice");
}

function coconutRice(): WrittenRecipe {
  const r = new Recipe("s97-coconut_rice", "Coconut rice", "rice");
  rinsedRice(r, "saucepan").put("pour", ["coconut milk", "liquid", "in [can]"], "saucepan").put("pour", WATER, "saucepan");
  r.putAll("sprinkle", [SUGAR, SALT], "saucepan").heat("saucepan");
  r.mix("simmer", "saucepan", "coconut rice", ["cooked", "covered"], { with: ["pot lid"] });
  r.alter("uncover", "coconut rice", { set: ["cooked", "fluffed"], with: ["fork"] });
  return written(serve(r, "coconut rice", "serving bowl", "scoop and pour", "spoon"), "coconut rice");
}

/** Cumin rice: whole cumin sizzled in butter, then a pilaf of basmati. */
function cuminRice(): WrittenRecipe {
  const r = new Recipe("s98-cumin_rice_pilaf", "Cumin rice (jeera rice)", "rice");
  r.put("pick-and-place", BUTTER, "saucepan").heat("saucepan").alter("melt", "butter", { set: ["melted"] });
  r.put("sprinkle", ["cumin", "whole", "in [jar]"], "saucepan");
  r.cookEach("fry", "saucepan", ["cumin"], { set: ["whole", "toasted"], with: ["wooden spoon"] });
  r.put("pick-and-place", ["bay leaf", "dried", "in [jar]"], "saucepan");
  toastRice(r, "saucepan").put("pour", WATER, "saucepan").put("sprinkle", SALT, "saucepan");
  r.mix("simmer", "saucepan", "rice", ["cooked", "covered"], { with: ["pot lid"] });
  r.alter("uncover", "rice", { set: ["cooked", "fluffed"], with: ["fork"] });
  r.prep(["cilantro", "leaf"], "chop:chopped").top("sprinkle", "cilantro", "rice", { plus: ["garnished"] });
  return written(r, "rice");
}

/** Rice salad: rice cooked, cooled, and tossed with raw vegetables in a lemon dressing. */
function riceSalad(): WrittenRecipe {
  const r = new Recipe("s99-lemon_rice_salad", "Rice salad with vegetables and lemon dressing", "rice");
  steamedRice(r).put("pour", "rice", "baking tray").alter("cool down", "rice", { plus: ["cooled"] });
  r.put("pour", "rice", "salad bowl");
  r.prep(["cucumber", "whole"], "dice:diced").prep(["sweet pepper", "whole"], "cut:seeded", "dice:diced");
  r.prep(["red onion", "whole", "unpeeled"], "peel:peeled,whole", "mince:minced");
  r.prep(["parsley", "leaf"], "chop:chopped");
  for (const v of ["cucumber", "sweet pepper", "red onion", "parsley"]) r.put("sprinkle", v, "salad bowl");
  r.put("pour", OLIVE_OIL, "small bowl");
  r.prep(["lemon", "whole"], "cut in half:halved").put("squeeze", "lemon", "small bowl", { as: "lemon juice", set: ["juice"], with: ["squeezer"] });
  r.putAll("sprinkle", [SALT, PEPPER], "small bowl");
  r.mix("whisk", "small bowl", "salad dressing", ["liquid", "mixed"], { with: ["whisk"] });
  r.put("pour", "salad dressing", "salad bowl");
  r.mix("mix", "salad bowl", "rice salad", ["tossed", "chilled"], { with: ["spoon"] });
  return written(r, "rice salad");
}

/** Chicken and rice baked in one dish: the rice cooks in the broth around the chicken. */
function bakedChickenRice(): WrittenRecipe {
  const r = new Recipe("s100-baked_chicken_and_rice", "Oven-baked chicken and rice", "rice");
  r.preheat();
  choppedOnion(r).prep(["carrot", "whole", "unpeeled"], "peel:peeled,whole:peeler", "slice:sliced");
  mincedGarlic(r);
  rinsedRice(r, "baking dish");
  for (const v of ["onion", "carrot", "garlic"]) r.put("sprinkle", v, "baking dish");
  r.put("pour", [...BROTH], "baking dish").putAll("sprinkle", [["paprika", "ground", "in [jar]"], SALT, PEPPER], "baking dish");
  r.mix("stir", "baking dish", "rice mixture", ["mixed", "uncooked"], { with: ["spoon"] });
  r.top("pick-and-place", ["chicken", "raw"], "rice mixture", { with: ["tongs"] }).top("pour", OLIVE_OIL, "rice mixture");
  r.alter("cover", "rice mixture", { plus: ["covered"], with: ["aluminum foil"] });
  r.alter("bake", "rice mixture", { as: "chicken and rice", set: ["baked", "cooked"], with: ["oven"] });
  r.prep(["parsley", "leaf"], "chop:chopped").top("sprinkle", "parsley", "chicken and rice", { plus: ["garnished"] });
  return written(r, "chicken and rice");
}

/** Baked rice pudding: raw rice slowly baked in sweetened milk until thick and creamy. */
function bakedRicePudding(): WrittenRecipe {
  const r = new Recipe("s101-baked_rice_pudding", "Baked rice pudding", "rice");
  r.preheat().grease("baking dish", BUTTER);
  rinsedRice(r, "baking dish").put("pour", MILK, "baking dish").put("sprinkle", SUGAR, "baking dish");
  r.put("pour", ["vanilla extract", "liquid", "in [bottle]"], "baking dish");
  r.mix("stir", "baking dish", "rice mixture", ["mixed", "uncooked"], { with: ["spoon"] });
  r.top("sprinkle", ["nutmeg", "ground", "in [jar]"], "rice mixture");
  r.alter("bake", "rice mixture", { as: "rice pudding", set: ["baked", "creamy"], with: ["oven"] });
  r.alter("cool down", "rice pudding", { plus: ["warm"] });
  return written(r, "rice pudding");
}

/** Congee: rice simmered long in broth until it breaks down, with chicken and ginger. */
function chickenCongee(): WrittenRecipe {
  const r = new Recipe("s102-chicken_congee", "Chicken and ginger congee", "rice");
  rinsedRice(r, "pot").put("pour", [...BROTH], "pot").put("pour", WATER, "pot");
  r.prep(["ginger", "whole", "unpeeled"], "peel:peeled,whole:peeler", "slice:julienned").put("sprinkle", "ginger", "pot");
  r.prep(["chicken", "raw"], "slice:sliced").put("pick-and-place", "chicken", "pot", { with: ["tongs"] });
  r.put("sprinkle", SALT, "pot").heat("pot");
  // seasoned in the pot, not poured on the bowl: what joins the congee last simmers with it
  r.put("pour", [...SOY], "pot").put("pour", ["sesame oil", "liquid", "in [bottle]"], "pot");
  r.mix("simmer", "pot", "congee", ["thick liquid", "cooked"], { with: ["wooden spoon"] });
  r.put("pour", "congee", "serving bowl", { with: ["ladle"] });
  r.prep(["green onion", "whole"], "slice:sliced").top("sprinkle", "green onion", "congee", { plus: ["garnished"] });
  return written(r, "congee");
}

/** Broccoli cheddar rice: cooked rice and broccoli baked in a white sauce under cheddar. */
function broccoliCheddarRice(): WrittenRecipe {
  const r = new Recipe("s128-broccoli_cheddar_rice_bake", "Broccoli cheddar rice bake", "rice");
  r.preheat();
  steamedRice(r).put("pour", "rice", "baking dish");
  r.put("rinse", ["broccoli", "whole"], "colander", { plus: ["washed"] }).put("pick-and-place", "broccoli", "cutting board");
  r.alter("cut", "broccoli", { set: ["cut in pieces"], with: ["knife"] });
  boilingWater(r);
  r.put("pour", "broccoli", "pot").cookEach("boil", "pot", ["broccoli"], { set: ["cut in pieces", "boiled"] });
  r.put("drain", "broccoli", "strainer").drop("water").put("pour", "broccoli", "baking dish");
  r.prep(["cheddar", "block", "in [package]"], "grate:shredded");
  r.put("pick-and-place", BUTTER, "skillet").heat("skillet").alter("melt", "butter", { set: ["melted"] });
  r.put("sprinkle", ["flour", "powder", "in [package]"], "skillet").put("pour", MILK, "skillet");
  r.putAll("sprinkle", [SALT, PEPPER], "skillet");
  r.mix("whisk", "skillet", "white sauce", ["thick liquid", "cooked"], { with: ["whisk"] });
  r.put("pour", "white sauce", "baking dish");
  r.mix("mix", "baking dish", "rice mixture", ["mixed", "coated"], { with: ["spoon"] });
  r.top("sprinkle", "cheddar", "rice mixture");
  r.alter("bake", "rice mixture", { as: "rice casserole", set: ["baked", "hot"], with: ["oven"] });
  return written(r, "rice casserole");
}

/** A one-pan beef and rice dinner: rice simmered in tomato and broth with browned beef, melted cheddar on top. */
function beefRiceSkillet(): WrittenRecipe {
  const r = new Recipe("s129-cheesy_beef_and_rice_skillet", "Cheesy beef and rice skillet", "rice");
  choppedOnion(r).prep(["sweet pepper", "whole"], "cut:seeded", "dice:diced");
  mincedGarlic(r);
  r.put("pour", OLIVE_OIL, "skillet").heat("skillet").put("pick-and-place", ["ground beef", "raw", "in [package]"], "skillet");
  r.cookEach("cook and stir", "skillet", ["ground beef"], { set: ["crumbled", "cooked"], with: ["wooden spoon"] });
  for (const v of ["onion", "sweet pepper", "garlic"]) r.put("pour", v, "skillet");
  r.cookEach("cook and stir", "skillet", ["onion", "sweet pepper", "garlic"], { plus: ["sauteed"], with: ["wooden spoon"] });
  rinsedRice(r, "skillet").put("pour", ["tomato sauce", "thick liquid", "in [can]"], "skillet").put("pour", [...BROTH], "skillet");
  r.putAll("sprinkle", [["chili powder", "powder", "in [jar]"], ["cumin", "ground", "in [jar]"], SALT], "skillet");
  r.mix("simmer", "skillet", "beef and rice", ["cooked", "covered"], { with: ["pot lid"] });
  r.prep(["cheddar", "block", "in [package]"], "grate:shredded").top("sprinkle", "cheddar", "beef and rice");
  r.alter("cook", "beef and rice", { set: ["cooked", "covered", "melted"], with: ["pot lid"] });
  r.prep(["green onion", "whole"], "slice:sliced").top("sprinkle", "green onion", "beef and rice", { plus: ["garnished"] });
  return written(r, "beef and rice");
}

export const rice = (): WrittenRecipe[] => [
  plainSteamedRice(), chickenFriedRice(), mushroomRisotto(), mexicanRice(), coconutRice(), cuminRice(), riceSalad(),
  bakedChickenRice(), bakedRicePudding(), chickenCongee(), broccoliCheddarRice(), beefRiceSkillet(),
];
