// Drinks: blended smoothies and lassi, hot milk drinks, spiced tea, a fruit cooler.
import { Recipe } from "../recipe";
import { written, type WrittenRecipe } from "../written";
import { MILK, SUGAR, WATER } from "./common";

const ICE = ["ice", "frozen", "cube", "in [freezer]"] as const;
const YOGURT = ["yogurt", "creamy", "in [container]"] as const;
const HONEY = ["honey", "thick liquid", "in [jar]"] as const;

/** A peeled, sliced banana on the cutting board. */
function slicedBanana(r: Recipe): Recipe {
  return r.prep(["banana", "whole", "unpeeled"], "peel:peeled,whole:-", "slice:sliced");
}

/** Blend what is in the blender jar and pour it into a glass. */
function blendAndPour(r: Recipe, drink: string, states = ["blended", "thick liquid"]): Recipe {
  r.mix("blend", "blender jar", drink, states, { with: ["blender"] });
  return r.put("pour", drink, "drinking glass");
}

function blueberryBananaSmoothie(): WrittenRecipe {
  const r = new Recipe("s68-blueberry_banana_smoothie", "Blueberry banana smoothie", "drinks");
  r.put("rinse", ["blueberry", "whole", "in [package]"], "colander", { plus: ["washed"] });
  r.put("pour", "blueberry", "blender jar");
  slicedBanana(r).put("pick-and-place", "banana", "blender jar");
  r.put("scoop and pour", [...YOGURT], "blender jar").put("pour", MILK, "blender jar");
  r.put("pour", [...HONEY], "blender jar").put("pick-and-place", [...ICE], "blender jar");
  return written(blendAndPour(r, "smoothie"), "smoothie");
}

function greenSmoothie(): WrittenRecipe {
  const r = new Recipe("s69-green_spinach_smoothie", "Green spinach and apple smoothie", "drinks");
  r.put("rinse", ["spinach", "leaf", "in [package]"], "colander", { plus: ["washed"] });
  r.put("pick-and-place", "spinach", "blender jar");
  r.prep(["apple", "whole"], "core:cored", "cut:cut in pieces").put("pick-and-place", "apple", "blender jar");
  slicedBanana(r).put("pick-and-place", "banana", "blender jar");
  r.put("pour", MILK, "blender jar").put("pour", [...HONEY], "blender jar").put("pick-and-place", [...ICE], "blender jar");
  return written(blendAndPour(r, "smoothie"), "smoothie");
}

function mangoLassi(): WrittenRecipe {
  const r = new Recipe("s70-mango_lassi", "Mango lassi", "drinks");
  r.prep(["mango", "whole"], "peel:peeled,whole:peeler", "cut:cut in pieces"); // cut off the stone; the blender does the rest
  r.put("pick-and-place", "mango", "blender jar").put("scoop and pour", [...YOGURT], "blender jar");
  r.put("pour", MILK, "blender jar").put("pour", SUGAR, "blender jar");
  r.put("sprinkle", ["cardamom", "ground", "in [jar]"], "blender jar").put("pick-and-place", [...ICE], "blender jar");
  return written(blendAndPour(r, "lassi"), "lassi");
}

function hotChocolate(): WrittenRecipe {
  const r = new Recipe("s71-hot_chocolate", "Hot chocolate", "drinks");
  r.put("pour", MILK, "saucepan").heat("saucepan");
  r.putAll("sprinkle", [["cocoa powder", "powder", "in [box]"], SUGAR], "saucepan");
  r.put("pour", ["vanilla extract", "liquid", "in [bottle]"], "saucepan");
  r.mix("whisk", "saucepan", "hot chocolate", ["liquid", "hot", "mixed"], { with: ["whisk"] });
  r.put("pour", "hot chocolate", "mug");
  r.put("pour", ["heavy cream", "liquid", "in [carton]"], "bowl").mix("whisk", "bowl", "whipped cream", ["whipped", "creamy"], { with: ["whisk"] });
  r.top("scoop and pour", "whipped cream", "hot chocolate", { plus: ["garnished"], with: ["spoon"] });
  return written(r, "hot chocolate");
}

/** Spiced milk tea: water, ginger and cinnamon simmered, tea steeped in it, milk and sugar, strained. */
function masalaChai(): WrittenRecipe {
  const r = new Recipe("s72-masala_chai", "Masala chai", "drinks");
  r.put("pour", WATER, "saucepan").heat("saucepan").alter("boil", "water", { plus: ["boiling"] });
  r.prep(["ginger", "whole", "unpeeled"], "peel:peeled,whole:peeler", "slice:sliced").put("pick-and-place", "ginger", "saucepan");
  r.put("pick-and-place", ["cinnamon", "stick", "in [jar]"], "saucepan");
  r.put("pick-and-place", ["tea bag", "dried", "in [box]"], "saucepan");
  r.put("pour", MILK, "saucepan").put("sprinkle", SUGAR, "saucepan");
  r.mix("simmer", "saucepan", "tea", ["liquid", "hot"], { with: ["spoon"] });
  r.put("pour and strain", "tea", "mug", { plus: ["strained"], with: ["sieve"] });
  return written(r, "tea");
}

function watermelonCooler(): WrittenRecipe {
  const r = new Recipe("s73-watermelon_mint_cooler", "Watermelon mint cooler", "drinks");
  r.prep(["watermelon", "whole"], "cut:wedge", "peel:peeled,wedge:knife", "cut:cubed").put("pick-and-place", "watermelon", "blender jar");
  r.prep(["lime", "whole"], "cut in half:halved").put("squeeze", "lime", "blender jar", { as: "lime juice", set: ["juice"], with: ["squeezer"] });
  r.put("rinse", ["mint", "leaf", "in [package]"], "colander", { plus: ["washed"] }).put("pick-and-place", "mint", "blender jar");
  r.put("pour", [...HONEY], "blender jar");
  r.mix("blend", "blender jar", "juice", ["blended", "liquid"], { with: ["blender"] });
  r.put("pour and strain", "juice", "pitcher", { plus: ["strained"], with: ["sieve"] });
  r.put("pick-and-place", [...ICE], "highball glass");
  r.put("pour", "juice", "highball glass");
  r.mix("stir", "highball glass", "juice", ["liquid", "chilled"], { with: ["spoon"] });
  return written(r, "juice");
}

function peanutButterBananaShake(): WrittenRecipe {
  const r = new Recipe("s74-peanut_butter_banana_shake", "Peanut butter banana oat shake", "drinks");
  slicedBanana(r).put("pick-and-place", "banana", "blender jar");
  r.put("scoop and pour", ["peanut butter", "paste", "in [jar]"], "blender jar");
  r.put("pour", ["oat", "flakes", "in [package]"], "blender jar").put("pour", MILK, "blender jar");
  r.put("sprinkle", ["cinnamon", "ground", "in [jar]"], "blender jar").put("pour", [...HONEY], "blender jar");
  r.put("pick-and-place", [...ICE], "blender jar");
  return written(blendAndPour(r, "milkshake"), "milkshake");
}

export const drinks = (): WrittenRecipe[] => [
  blueberryBananaSmoothie(), greenSmoothie(), mangoLassi(), hotChocolate(), masalaChai(), watermelonCooler(),
  peanutButterBananaShake(),
];
