// Bread dishes made from a bought loaf (dish class bread, as FOON files them): French toast, garlic bread,
// bruschetta and a baked bread pudding.
import { Recipe } from "../recipe";
import { written, type WrittenRecipe } from "../written";
import { BUTTER, crackEggs, MILK, mincedGarlic, OLIVE_OIL, PEPPER, SALT, serve, SUGAR } from "./common";

const LOAF = ["bread", "loaf"] as const;
const CINNAMON = ["cinnamon", "ground", "in [jar]"] as const;
const VANILLA = ["vanilla extract", "liquid", "in [bottle]"] as const;

/** Bread slices soaked in a sweet egg custard and fried in butter. */
function frenchToast(): WrittenRecipe {
  const r = new Recipe("s121-french_toast", "Cinnamon French toast", "bread");
  crackEggs(r, "baking dish").put("pour", MILK, "baking dish").put("sprinkle", SUGAR, "baking dish");
  r.put("sprinkle", [...CINNAMON], "baking dish").put("pour", [...VANILLA], "baking dish");
  r.mix("whisk", "baking dish", "egg mixture", ["beaten", "uncooked"], { with: ["whisk"] });
  r.prep([...LOAF], "slice:sliced").put("dip", "bread", "baking dish");
  r.mix("soak", "baking dish", "bread", ["sliced", "soaked", "uncooked"], { with: ["fork"] });
  r.put("pick-and-place", BUTTER, "frying pan").heat("frying pan").alter("melt", "butter", { set: ["melted"] });
  r.put("pick-and-place", "bread", "frying pan", { with: ["fork"] });
  r.mix("fry", "frying pan", "french toast", ["fried", "partly cooked"], { with: ["turner"] });
  r.alter("flip", "french toast", { set: ["flipped", "fried", "cooked"], with: ["turner"] });
  serve(r, "french toast", "plate", "pick-and-place", "turner");
  r.top("pour", ["maple syrup", "thick liquid", "in [bottle]"], "french toast", { plus: ["coated"] });
  return written(r, "french toast");
}

/** Garlic bread: a split loaf spread with garlic-parsley butter and baked. */
function garlicBread(): WrittenRecipe {
  const r = new Recipe("s122-garlic_bread", "Garlic bread", "bread");
  r.preheat();
  r.put("pick-and-place", BUTTER, "bowl").alter("melt", "butter", { set: ["softened"], with: ["microwave"] });
  mincedGarlic(r).put("sprinkle", "garlic", "bowl");
  r.prep(["parsley", "leaf"], "chop:chopped").put("sprinkle", "parsley", "bowl").put("sprinkle", SALT, "bowl");
  r.mix("mix", "bowl", "butter mixture", ["creamy", "mixed"], { with: ["spoon"] });
  r.prep([...LOAF], "cut in half:halved").put("pick-and-place", "bread", "baking tray");
  r.put("scoop and pour", "butter mixture", "baking tray", { with: ["spoon"] });
  r.prep(["parmesan", "block", "in [package]"], "grate:grated").put("sprinkle", "parmesan", "baking tray");
  r.mix("spread", "baking tray", "garlic bread", ["halved", "coated"], { with: ["knife"] });
  r.alter("bake", "garlic bread", { set: ["halved", "coated", "baked"], with: ["oven"] });
  r.put("pick-and-place", "garlic bread", "cutting board", { with: ["spatula"] });
  r.alter("slice", "garlic bread", { set: ["sliced", "baked"], with: ["knife"] });
  return written(r, "garlic bread");
}

/** Bruschetta: toasted bread rubbed with garlic and topped with a fresh tomato and basil mix. */
function bruschetta(): WrittenRecipe {
  const r = new Recipe("s123-tomato_bruschetta", "Tomato and basil bruschetta", "bread");
  r.preheat();
  r.prep(["tomato", "whole"], "core:cored", "dice:diced").put("pour", "tomato", "bowl");
  r.put("rinse", ["basil", "leaf"], "colander", { plus: ["washed"] }).put("pick-and-place", "basil", "cutting board");
  r.alter("chop", "basil", { set: ["chopped"], with: ["knife"] }).put("sprinkle", "basil", "bowl");
  mincedGarlic(r).put("sprinkle", "garlic", "bowl");
  r.put("pour", OLIVE_OIL, "bowl").put("pour", ["balsamic vinegar", "liquid", "in [bottle]"], "bowl");
  r.putAll("sprinkle", [SALT, PEPPER], "bowl");
  r.mix("mix", "bowl", "tomato mixture", ["mixed", "chopped"], { with: ["spoon"] });
  r.prep([...LOAF], "slice:sliced").put("pick-and-place", "bread", "baking tray");
  r.alter("toast", "bread", { set: ["sliced", "toasted"], with: ["oven"] });
  r.put("pick-and-place", "bread", "plate", { with: ["tongs"] });
  r.put("scoop and pour", "tomato mixture", "plate", { with: ["spoon"] });
  r.mix("spread", "plate", "bruschetta", ["sliced", "toasted", "garnished"], { with: ["spoon"] });
  return written(r, "bruschetta");
}

/** Bread pudding: cubes of day-old bread soaked in custard with raisins and baked. */
function breadPudding(): WrittenRecipe {
  const r = new Recipe("s124-bread_pudding", "Baked bread pudding with raisins", "bread");
  r.preheat().grease("baking dish", BUTTER);
  r.prep([...LOAF], "cut:cubed").put("pick-and-place", "bread", "baking dish");
  r.put("sprinkle", ["raisin", "dried", "in [package]"], "baking dish");
  crackEggs(r, "mixing bowl").put("pour", MILK, "mixing bowl").put("sprinkle", SUGAR, "mixing bowl");
  r.put("sprinkle", [...CINNAMON], "mixing bowl").put("pour", [...VANILLA], "mixing bowl");
  r.mix("whisk", "mixing bowl", "egg mixture", ["beaten", "uncooked"], { with: ["whisk"] });
  r.put("pour", "egg mixture", "baking dish");
  r.mix("soak", "baking dish", "bread mixture", ["soaked", "uncooked"]);
  r.alter("bake", "bread mixture", { as: "bread pudding", set: ["baked"], with: ["oven"] });
  r.alter("cool down", "bread pudding", { plus: ["warm"], with: ["wire rack"] });
  return written(r, "bread pudding");
}

export const breadDishes = (): WrittenRecipe[] => [frenchToast(), garlicBread(), bruschetta(), breadPudding()];
