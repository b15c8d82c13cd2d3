// Bread: yeast loaves, flatbreads and quick breads.
import { Recipe } from "../recipe";
import { written, type WrittenRecipe } from "../written";
import { BUTTER, crackEggs, FLOUR, kneadAndRise, MILK, mincedGarlic, OLIVE_OIL, SALT, SUGAR, VEGETABLE_OIL, WATER, yeastMixture } from "./common";

function garlicNaan(): WrittenRecipe {
  const r = new Recipe("s51-garlic_naan", "Garlic naan", "bread");
  yeastMixture(r);
  r.putAll("pour", [FLOUR], "mixing bowl").put("sprinkle", SALT, "mixing bowl");
  r.put("scoop and pour", ["yogurt", "creamy", "in [container]"], "mixing bowl");
  r.put("pour", "yeast mixture", "mixing bowl").put("pour", VEGETABLE_OIL, "mixing bowl");
  kneadAndRise(r);
  r.put("pick-and-place", "dough", "cutting board", { minus: ["covered"] });
  r.alter("roll", "dough", { set: ["risen", "flattened"], with: ["rolling pin"] });
  r.heat("skillet").put("pick-and-place", "dough", "skillet");
  r.alter("cook", "dough", { as: "naan", set: ["partly cooked"], with: ["turner"] });
  r.alter("flip", "naan", { set: ["flipped", "cooked"], with: ["turner"] });
  mincedGarlic(r).put("pick-and-place", BUTTER, "small bowl");
  r.alter("melt", "butter", { set: ["melted"], with: ["microwave"] }).put("sprinkle", "garlic", "small bowl");
  r.mix("stir", "small bowl", "butter mixture", ["liquid", "mixed"], { with: ["spoon"] });
  r.put("pick-and-place", "naan", "plate", { with: ["turner"] });
  r.top("spread", "butter mixture", "naan", { plus: ["coated"], with: ["brush"] });
  return written(r, "naan");
}

/** Banana bread: a quick bread raised by baking soda, baked in a loaf pan. */
function bananaBread(): WrittenRecipe {
  const r = new Recipe("s52-banana_walnut_bread", "Banana walnut bread", "bread");
  r.preheat().grease("loaf pan", BUTTER);
  r.put("pick-and-place", ["banana", "whole", "unpeeled"], "cutting board").alter("peel", "banana", { set: ["peeled", "whole"] });
  r.put("pick-and-place", "banana", "mixing bowl").alter("mash", "banana", { set: ["mashed"], with: ["fork"] });
  r.put("pick-and-place", BUTTER, "small bowl").alter("melt", "butter", { set: ["melted"], with: ["microwave"] });
  r.put("pour", "butter", "mixing bowl").put("sprinkle", ["brown sugar", "granulated", "in [package]"], "mixing bowl");
  crackEggs(r, "mixing bowl").put("pour", ["vanilla extract", "liquid", "in [bottle]"], "mixing bowl");
  r.mix("whisk", "mixing bowl", "banana mixture", ["mixed", "thick liquid"], { with: ["whisk"] });
  r.putAll("sprinkle", [FLOUR, ["baking soda", "powder", "in [box]"], SALT, ["cinnamon", "ground", "in [jar]"]], "mixing bowl");
  r.prep(["walnut", "shelled", "in [package]"], "chop:chopped").put("sprinkle", "walnut", "mixing bowl");
  r.mix("fold", "mixing bowl", "dough", ["mixed", "thick liquid"], { with: ["spatula"] });
  r.put("pour and scrape", "dough", "loaf pan", { with: ["spatula"] });
  r.alter("bake", "dough", { as: "banana bread", set: ["loaf", "baked"], with: ["oven"] });
  r.alter("cool down", "banana bread", { plus: ["cooled"], with: ["wire rack"] });
  r.put("flip", "banana bread", "cutting board");
  r.alter("slice", "banana bread", { set: ["sliced", "baked", "cooled"], with: ["knife"] });
  return written(r, "banana bread");
}

function zucchiniBread(): WrittenRecipe {
  const r = new Recipe("s53-zucchini_bread", "Zucchini bread with cinnamon", "bread");
  r.preheat().grease("loaf pan", VEGETABLE_OIL);
  r.prep(["zucchini", "whole"], "cut off ends:ends removed", "grate:grated");
  crackEggs(r, "mixing bowl").put("pour", VEGETABLE_OIL, "mixing bowl").put("sprinkle", SUGAR, "mixing bowl");
  r.put("pour", ["vanilla extract", "liquid", "in [bottle]"], "mixing bowl");
  r.mix("whisk", "mixing bowl", "egg mixture", ["beaten", "uncooked"], { with: ["whisk"] });
  r.put("sprinkle", "zucchini", "mixing bowl");
  r.putAll("sprinkle", [FLOUR, ["baking soda", "powder", "in [box]"], ["baking powder", "powder", "in [box]"], SALT, ["cinnamon", "ground", "in [jar]"], ["nutmeg", "ground", "in [jar]"]], "mixing bowl");
  r.mix("fold", "mixing bowl", "dough", ["mixed", "thick liquid"], { with: ["spatula"] });
  r.put("pour and scrape", "dough", "loaf pan", { with: ["spatula"] });
  r.alter("bake", "dough", { as: "zucchini bread", set: ["loaf", "baked"], with: ["oven"] });
  r.alter("cool down", "zucchini bread", { plus: ["cooled"], with: ["wire rack"] });
  r.put("flip", "zucchini bread", "cutting board");
  r.alter("slice", "zucchini bread", { set: ["sliced", "baked", "cooled"], with: ["knife"] });
  return written(r, "zucchini bread");
}

/** Irish soda bread: no yeast, buttermilk and baking soda, shaped by hand and baked on a tray. */
function sodaBread(): WrittenRecipe {
  const r = new Recipe("s54-irish_soda_bread", "Irish soda bread", "bread");
  r.preheat();
  r.putAll("pour", [FLOUR], "mixing bowl");
  r.putAll("sprinkle", [["baking soda", "powder", "in [box]"], SALT], "mixing bowl");
  r.put("pour", ["buttermilk", "liquid", "in [carton]"], "mixing bowl");
  r.mix("mix", "mixing bowl", "dough", ["mixed", "lumpy"], { with: ["wooden spoon"] });
  r.put("scrape", "dough", "cutting board").alter("shape", "dough", { set: ["shaped", "loaf"] });
  r.put("pick-and-place", "dough", "baking tray");
  r.alter("cut", "dough", { plus: ["holed"], with: ["knife"] });
  r.alter("bake", "dough", { as: "soda bread", set: ["loaf", "baked"], with: ["oven"] });
  r.alter("cool down", "soda bread", { plus: ["cooled"], with: ["wire rack"] });
  return written(r, "soda bread");
}

function cornbread(): WrittenRecipe {
  const r = new Recipe("s55-skillet_cornbread", "Skillet cornbread", "bread");
  r.preheat().grease("skillet", BUTTER);
  r.putAll("pour", [["cornmeal", "powder", "in [package]"], FLOUR], "mixing bowl");
  r.putAll("sprinkle", [SUGAR, ["baking powder", "powder", "in [box]"], SALT], "mixing bowl");
  r.put("pick-and-place", BUTTER, "small bowl").alter("melt", "butter", { set: ["melted"], with: ["microwave"] });
  crackEggs(r, "bowl").put("pour", MILK, "bowl").put("pour", "butter", "bowl");
  r.mix("whisk", "bowl", "egg mixture", ["beaten", "uncooked"], { with: ["whisk"] });
  r.put("pour", "egg mixture", "mixing bowl");
  r.mix("stir", "mixing bowl", "cornbread batter", ["mixed", "thick liquid"], { with: ["spatula"] });
  r.put("pour and scrape", "cornbread batter", "skillet", { with: ["spatula"] });
  r.alter("bake", "cornbread batter", { as: "cornbread", set: ["baked"], with: ["oven"] });
  r.alter("cool down", "cornbread", { plus: ["cooled"], with: ["wire rack"] });
  r.alter("cut", "cornbread", { set: ["wedge", "baked", "cooled"], with: ["knife"] });
  return written(r, "cornbread");
}

function honeyWheatLoaf(): WrittenRecipe {
  const r = new Recipe("s56-honey_wheat_loaf", "Honey whole wheat loaf", "bread");
  yeastMixture(r, false);
  r.put("pour", ["whole wheat flour", "powder", "in [package]"], "mixing bowl").put("pour", FLOUR, "mixing bowl");
  r.put("sprinkle", SALT, "mixing bowl").put("pour", ["honey", "thick liquid", "in [jar]"], "mixing bowl");
  r.put("pour", OLIVE_OIL, "mixing bowl").put("pour", "yeast mixture", "mixing bowl");
  kneadAndRise(r);
  r.preheat().grease("loaf pan", OLIVE_OIL);
  r.put("pick-and-place", "dough", "cutting board", { minus: ["covered"] }).alter("shape", "dough", { plus: ["shaped", "loaf"] });
  r.put("pick-and-place", "dough", "loaf pan").alter("ferment", "dough", { set: ["shaped", "loaf", "risen"] });
  r.alter("bake", "dough", { as: "bread", set: ["loaf", "baked"], with: ["oven"] });
  r.alter("cool down", "bread", { plus: ["cooled"], with: ["wire rack"] });
  r.put("flip", "bread", "cutting board").alter("slice", "bread", { set: ["sliced", "baked", "cooled"], with: ["knife"] });
  return written(r, "bread");
}

function pitaBread(): WrittenRecipe {
  const r = new Recipe("s57-pita_bread", "Pita bread", "bread");
  yeastMixture(r);
  r.put("pour", FLOUR, "mixing bowl").put("sprinkle", SALT, "mixing bowl").put("pour", OLIVE_OIL, "mixing bowl");
  r.put("pour", "yeast mixture", "mixing bowl");
  kneadAndRise(r);
  r.preheat();
  r.put("pick-and-place", "dough", "cutting board", { minus: ["covered"] });
  r.alter("cut", "dough", { set: ["risen", "pieces"], with: ["knife"] });
  r.alter("roll", "dough", { set: ["risen", "pieces", "flattened"], with: ["rolling pin"] });
  r.put("pick-and-place", "dough", "baking tray");
  r.alter("bake", "dough", { as: "pita bread", set: ["baked", "flattened"], with: ["oven"] });
  r.alter("cover", "pita bread", { plus: ["covered"], with: ["towel"] });
  return written(r, "pita bread");
}

function cinnamonRaisinBread(): WrittenRecipe {
  const r = new Recipe("s58-cinnamon_raisin_bread", "Cinnamon raisin bread", "bread");
  yeastMixture(r);
  r.put("pour", FLOUR, "mixing bowl").put("sprinkle", SALT, "mixing bowl");
  r.put("pick-and-place", BUTTER, "small bowl").alter("melt", "butter", { set: ["melted"], with: ["microwave"] });
  r.put("pour", "butter", "mixing bowl").put("pour", MILK, "mixing bowl");
  crackEggs(r, "mixing bowl").put("pour", "yeast mixture", "mixing bowl");
  r.put("sprinkle", ["raisin", "dried", "in [box]"], "mixing bowl");
  kneadAndRise(r);
  r.preheat().grease("loaf pan", BUTTER);
  r.put("pick-and-place", "dough", "cutting board", { minus: ["covered"] });
  r.alter("roll", "dough", { set: ["risen", "flattened"], with: ["rolling pin"] });
  r.top("sprinkle", ["cinnamon", "ground", "in [jar]"], "dough");
  r.top("sprinkle", ["brown sugar", "granulated", "in [package]"], "dough");
  r.alter("roll", "dough", { set: ["rolled", "shaped", "loaf"] });
  r.put("pick-and-place", "dough", "loaf pan").alter("ferment", "dough", { set: ["rolled", "loaf", "risen"] });
  r.alter("bake", "dough", { as: "raisin bread", set: ["loaf", "baked"], with: ["oven"] });
  r.alter("cool down", "raisin bread", { plus: ["cooled"], with: ["wire rack"] });
  r.put("flip", "raisin bread", "cutting board").alter("slice", "raisin bread", { set: ["sliced", "baked", "cooled"], with: ["knife"] });
  return written(r, "raisin bread");
}

/** Flour tortillas: an unleavened flatbread cooked in a dry skillet. */
function flourTortilla(): WrittenRecipe {
  const r = new Recipe("s59-flour_tortilla", "Flour tortillas", "bread");
  r.put("pour", FLOUR, "mixing bowl").putAll("sprinkle", [["baking powder", "powder", "in [box]"], SALT], "mixing bowl");
  r.put("pour", VEGETABLE_OIL, "mixing bowl").put("pour", WATER, "measuring cup");
  r.alter("heat", "water", { plus: ["warm"], with: ["microwave"] }).put("pour", "water", "mixing bowl");
  r.mix("mix", "mixing bowl", "dough", ["mixed", "lumpy"], { with: ["wooden spoon"] });
  r.put("scrape", "dough", "cutting board").alter("knead", "dough", { set: ["kneaded"] });
  r.alter("cut", "dough", { set: ["kneaded", "pieces"], with: ["knife"] });
  r.alter("roll", "dough", { set: ["pieces", "flattened"], with: ["rolling pin"] });
  r.heat("skillet").put("pick-and-place", "dough", "skillet");
  r.alter("cook", "dough", { as: "tortilla", set: ["flattened", "partly cooked"], with: ["turner"] });
  r.alter("flip", "tortilla", { set: ["flattened", "flipped", "cooked"], with: ["turner"] });
  r.put("pick-and-place", "tortilla", "plate", { with: ["turner"] });
  r.alter("cover", "tortilla", { plus: ["covered"], with: ["towel"] });
  return written(r, "tortilla");
}

function dinnerRolls(): WrittenRecipe {
  const r = new Recipe("s60-soft_dinner_rolls", "Soft dinner rolls", "bread");
  yeastMixture(r);
  r.put("pour", FLOUR, "mixing bowl").put("sprinkle", SALT, "mixing bowl");
  r.put("pick-and-place", BUTTER, "small bowl").alter("melt", "butter", { set: ["melted"], with: ["microwave"] });
  r.put("pour", "butter", "mixing bowl").put("pour", MILK, "mixing bowl");
  crackEggs(r, "mixing bowl").put("pour", "yeast mixture", "mixing bowl");
  kneadAndRise(r);
  r.preheat().grease("baking dish", BUTTER);
  r.put("pick-and-place", "dough", "cutting board", { minus: ["covered"] });
  r.alter("cut", "dough", { set: ["risen", "pieces"], with: ["knife"] });
  r.alter("shape", "dough", { set: ["pieces", "shaped"] });
  r.put("pick-and-place", "dough", "baking dish").alter("ferment", "dough", { set: ["pieces", "shaped", "risen"] });
  r.alter("bake", "dough", { as: "bread roll", set: ["baked"], with: ["oven"] });
  r.alter("cool down", "bread roll", { plus: ["cooled"], with: ["wire rack"] });
  return written(r, "bread roll");
}

export const bread = (): WrittenRecipe[] => [
  garlicNaan(), bananaBread(), zucchiniBread(), sodaBread(), cornbread(), honeyWheatLoaf(), pitaBread(),
  cinnamonRaisinBread(), flourTortilla(), dinnerRolls(),
];
