// Salad: leafy, layered, grain, pasta, fruit, bean and cooked-vegetable salads, and a composed salad.
import { Recipe, type Kitchen } from "../recipe";
import { written, type WrittenRecipe } from "../written";
import { boilingWater, boilNoodles, hardBoiledEgg, mincedGarlic, OLIVE_OIL, PEPPER, SALT, SUGAR, VEGETABLE_OIL } from "./common";

const VINEGAR = ["vinegar", "liquid", "in [bottle]"] as const;
const MUSTARD = ["mustard", "paste", "in [jar]"] as const;

/** Oil, vinegar, mustard, salt and pepper whisked in a small bowl. */
function vinaigrette(r: Recipe): Recipe {
  r.put("pour", OLIVE_OIL, "small bowl").put("pour", [...VINEGAR], "small bowl");
  r.put("scoop and pour", [...MUSTARD], "small bowl").putAll("sprinkle", [SALT, PEPPER], "small bowl");
  return r.mix("whisk", "small bowl", "vinaigrette", ["liquid", "mixed"], { with: ["whisk"] });
}

/** A lemon or lime halved and squeezed into a bowl. */
function squeezed(r: Recipe, fruit: "lemon" | "lime", into: string): Recipe {
  r.prep([fruit, "whole"], "cut in half:halved");
  return r.put("squeeze", fruit, into, { as: `${fruit} juice`, set: ["juice"], with: ["squeezer"] });
}

/** Each prepared ingredient into the salad bowl, then the dressing, then everything tossed into the salad. */
function dressAndToss(r: Recipe, items: string[], dressing: string, salad: string, bowl = "salad bowl"): Recipe {
  for (const i of items) r.put("sprinkle", i, bowl);
  r.put("pour", dressing, bowl);
  return r.mix("mix", bowl, salad, ["tossed", "mixed"], { with: ["tongs"] });
}

/** Produce rinsed in the colander, then cut on the board with the knife, one step per "motion:states". */
function rinseAndCut(r: Recipe, item: Kitchen, ...steps: string[]): Recipe {
  r.put("rinse", item, "colander", { plus: ["washed"] }).put("pick-and-place", item[0], "cutting board");
  for (const step of steps) {
    const [motion, states] = step.split(":");
    r.alter(motion!, item[0], { set: states!.split(","), with: ["knife"] });
  }
  return r;
}

/** Leaves rinsed in the colander and torn by hand. */
function tornLeaves(r: Recipe, leaf: string): Recipe {
  r.put("rinse", [leaf, "leaf"], "colander", { plus: ["washed"] });
  return r.alter("tear", leaf, { set: ["torn", "washed"] });
}

function gardenSalad(): WrittenRecipe {
  const r = new Recipe("s103-garden_salad", "Garden salad with vinaigrette", "salad");
  tornLeaves(r, "lettuce");
  r.prep(["cucumber", "whole"], "slice:sliced").prep(["tomato", "whole"], "cut:wedge");
  r.prep(["carrot", "whole", "unpeeled"], "peel:peeled,whole:peeler", "grate:grated");
  r.prep(["red onion", "whole", "unpeeled"], "peel:peeled,whole", "slice:ring shaped");
  vinaigrette(r);
  return written(dressAndToss(r, ["lettuce", "cucumber", "tomato", "carrot", "red onion"], "vinaigrette", "garden salad"), "garden salad");
}

/** Caprese: cherry tomatoes, mozzarella and torn basil tossed with olive oil and balsamic vinegar. */
function capreseSalad(): WrittenRecipe {
  const r = new Recipe("s104-caprese_salad", "Cherry tomato caprese salad", "salad");
  rinseAndCut(r, ["cherry tomato", "whole", "in [package]"], "cut in half:halved");
  r.prep(["mozzarella", "block", "in [package]"], "cut:cubed");
  tornLeaves(r, "basil");
  r.put("pour", OLIVE_OIL, "small bowl").put("pour", ["balsamic vinegar", "liquid", "in [bottle]"], "small bowl");
  r.putAll("sprinkle", [SALT, PEPPER], "small bowl");
  r.mix("whisk", "small bowl", "salad dressing", ["liquid", "mixed"], { with: ["whisk"] });
  return written(dressAndToss(r, ["cherry tomato", "mozzarella", "basil"], "salad dressing", "caprese salad", "serving bowl"), "caprese salad");
}

/** Tabbouleh: a parsley salad with bulgur cooked and cooled, dressed with lemon and olive oil. */
function tabbouleh(): WrittenRecipe {
  const r = new Recipe("s105-tabbouleh", "Tabbouleh", "salad");
  boilingWater(r, "saucepan");
  r.put("pour", ["bulgur", "dried", "in [package]"], "saucepan");
  r.cookEach("boil", "saucepan", ["bulgur"], { set: ["cooked"], with: ["wooden spoon"] });
  r.put("drain", "bulgur", "strainer").drop("water").alter("cool down", "bulgur", { plus: ["cooled"] });
  rinseAndCut(r, ["parsley", "leaf"], "chop:chopped");
  r.prep(["mint", "leaf"], "chop:chopped").prep(["tomato", "whole"], "dice:diced").prep(["cucumber", "whole"], "dice:diced");
  r.prep(["green onion", "whole"], "slice:sliced");
  r.put("pour", OLIVE_OIL, "small bowl");
  squeezed(r, "lemon", "small bowl").put("sprinkle", SALT, "small bowl");
  r.mix("whisk", "small bowl", "salad dressing", ["liquid", "mixed"], { with: ["whisk"] });
  return written(dressAndToss(r, ["bulgur", "parsley", "mint", "tomato", "cucumber", "green onion"], "salad dressing", "tabbouleh"), "tabbouleh");
}

function pastaSalad(): WrittenRecipe {
  const r = new Recipe("s106-italian_pasta_salad", "Italian pasta salad", "salad");
  boilNoodles(r, "penne").alter("rinse", "penne", { plus: ["chilled"] });
  r.prep(["cherry tomato", "whole"], "cut in half:halved").prep(["cucumber", "whole"], "dice:diced");
  r.prep(["red onion", "whole", "unpeeled"], "peel:peeled,whole", "slice:sliced");
  r.prep(["black olive", "whole", "in [can]"], "slice:sliced");
  r.prep(["feta cheese", "block", "in [package]"], "cut:crumbled:fork");
  r.put("pour", OLIVE_OIL, "small bowl").put("pour", [...VINEGAR], "small bowl");
  mincedGarlic(r).put("sprinkle", "garlic", "small bowl");
  r.putAll("sprinkle", [["oregano", "dried", "in [jar]"], SALT, PEPPER], "small bowl");
  r.mix("whisk", "small bowl", "salad dressing", ["liquid", "mixed"], { with: ["whisk"] });
  const items = ["penne", "cherry tomato", "cucumber", "red onion", "black olive", "feta cheese"];
  return written(dressAndToss(r, items, "salad dressing", "pasta salad"), "pasta salad");
}

/** Fruit salad: fruit washed and cut, dressed with honey and lime, and chilled. */
function fruitSalad(): WrittenRecipe {
  const r = new Recipe("s107-fruit_salad", "Fresh fruit salad with honey and lime", "salad");
  rinseAndCut(r, ["strawberry", "whole", "in [package]"], "cut:destemmed,washed", "cut in half:halved");
  r.put("rinse", ["blueberry", "whole", "in [package]"], "strainer", { plus: ["washed"] });
  r.prep(["apple", "whole"], "core:cored", "dice:diced");
  r.prep(["banana", "whole", "unpeeled"], "peel:peeled,whole:-", "slice:sliced");
  r.prep(["orange", "whole", "unpeeled"], "peel:peeled,whole:-", "cut:cut in pieces");
  r.put("pour", ["honey", "thick liquid", "in [jar]"], "small bowl");
  squeezed(r, "lime", "small bowl");
  r.mix("stir", "small bowl", "salad dressing", ["liquid", "mixed"], { with: ["spoon"] });
  dressAndToss(r, ["strawberry", "blueberry", "apple", "banana", "orange"], "salad dressing", "fruit salad", "serving bowl");
  return written(r.alter("chill", "fruit salad", { plus: ["chilled"], with: ["refrigerator"] }), "fruit salad");
}

/** Bean salad: canned beans drained and rinsed, with raw vegetables and a lime-cumin dressing. */
function blackBeanSalad(): WrittenRecipe {
  const r = new Recipe("s108-black_bean_chickpea_salad", "Black bean and chickpea salad", "salad");
  r.put("drain", ["black bean", "cooked", "in [can]"], "colander").alter("rinse", "black bean", { plus: ["washed"] });
  r.put("drain", ["chickpea", "cooked", "in [can]"], "strainer").alter("rinse", "chickpea", { plus: ["washed"] });
  r.prep(["sweet pepper", "whole"], "cut:seeded", "dice:diced");
  r.prep(["red onion", "whole", "unpeeled"], "peel:peeled,whole", "dice:diced");
  r.prep(["cherry tomato", "whole"], "cut in half:halved").prep(["cilantro", "leaf"], "chop:chopped");
  r.put("pour", OLIVE_OIL, "small bowl");
  squeezed(r, "lime", "small bowl").putAll("sprinkle", [["cumin", "ground", "in [jar]"], SALT, PEPPER], "small bowl");
  r.mix("whisk", "small bowl", "salad dressing", ["liquid", "mixed"], { with: ["whisk"] });
  const items = ["black bean", "chickpea", "sweet pepper", "red onion", "cherry tomato", "cilantro"];
  return written(dressAndToss(r, items, "salad dressing", "bean salad"), "bean salad");
}

/** Green beans blanched, cooled in cold water, dressed with mustard vinaigrette and toasted almonds. */
function greenBeanSalad(): WrittenRecipe {
  const r = new Recipe("s109-green_bean_almond_salad", "Green bean salad with toasted almonds", "salad");
  r.put("rinse", ["green bean", "whole"], "colander", { plus: ["washed"] });
  r.alter("cut off ends", "green bean", { set: ["ends removed", "washed"], with: ["knife"] });
  boilingWater(r);
  r.put("pour", "green bean", "pot").cookEach("boil", "pot", ["green bean"], { set: ["boiled", "cooked"], with: ["tongs"] });
  r.put("drain", "green bean", "strainer").drop("water").alter("rinse", "green bean", { plus: ["chilled"] });
  r.put("pour", ["almond", "sliced", "in [package]"], "frying pan").heat("frying pan");
  r.cookEach("toast", "frying pan", ["almond"], { set: ["sliced", "toasted"], with: ["spatula"] });
  r.prep(["shallot", "whole", "unpeeled"], "peel:peeled,whole", "mince:minced");
  vinaigrette(r);
  return written(dressAndToss(r, ["green bean", "almond", "shallot"], "vinaigrette", "green bean salad"), "green bean salad");
}

/** Cobb salad: lettuce under rows of chicken, bacon, egg, avocado, tomato and blue cheese. */
function cobbSalad(): WrittenRecipe {
  const r = new Recipe("s110-cobb_salad", "Cobb salad", "salad");
  hardBoiledEgg(r).alter("chop", "egg", { set: ["chopped", "boiled"], with: ["knife"] });
  r.put("pick-and-place", ["bacon", "raw", "in [package]"], "skillet").heat("skillet");
  r.cookEach("fry", "skillet", ["bacon"], { set: ["fried"], with: ["tongs"] });
  r.put("pick-and-place", "bacon", "paper towel", { with: ["tongs"] }).alter("chop", "bacon", { set: ["crumbled", "fried"], with: ["knife"] });
  r.put("pour", VEGETABLE_OIL, "frying pan").heat("frying pan").put("pick-and-place", ["chicken", "raw"], "frying pan", { with: ["tongs"] });
  r.cookEach("fry", "frying pan", ["chicken"], { set: ["fried", "cooked"], with: ["tongs"] });
  r.put("pick-and-place", "chicken", "cutting board", { with: ["tongs"] }).drop("vegetable oil").alter("dice", "chicken", { set: ["diced", "cooked"], with: ["knife"] });
  rinseAndCut(r, ["lettuce", "leaf"], "chop:chopped");
  r.prep(["avocado", "whole"], "cut in half:halved", "cut:seeded", "peel:peeled,halved", "dice:diced");
  r.prep(["tomato", "whole"], "dice:diced").prep(["blue cheese", "block", "in [package]"], "cut:crumbled:fork");
  r.prep(["chive", "whole"], "chop:chopped");
  vinaigrette(r);
  return written(dressAndToss(r, ["lettuce", "chicken", "bacon", "egg", "avocado", "tomato", "blue cheese", "chive"], "vinaigrette", "cobb salad"), "cobb salad");
}

/** Egg salad: boiled eggs chopped into a mayonnaise and mustard dressing with celery and chives. */
function eggSalad(): WrittenRecipe {
  const r = new Recipe("s111-egg_salad", "Egg salad", "salad");
  hardBoiledEgg(r).alter("chop", "egg", { set: ["chopped", "boiled"], with: ["knife"] });
  r.prep(["celery", "stalk"], "dice:diced").prep(["chive", "whole"], "chop:chopped");
  r.put("scoop and pour", ["mayonnaise", "creamy", "in [jar]"], "mixing bowl").put("scoop and pour", [...MUSTARD], "mixing bowl");
  r.putAll("sprinkle", [["paprika", "ground", "in [jar]"], SALT, PEPPER], "mixing bowl");
  r.mix("stir", "mixing bowl", "salad dressing", ["creamy", "mixed"], { with: ["spoon"] });
  for (const i of ["egg", "celery", "chive"]) r.put("sprinkle", i, "mixing bowl");
  return written(r.mix("fold", "mixing bowl", "egg salad", ["mixed", "coated"], { with: ["spatula"] }), "egg salad");
}

/** Macaroni salad: cooled elbow macaroni in a sweet-sharp mayonnaise dressing with crisp vegetables. */
function macaroniSalad(): WrittenRecipe {
  const r = new Recipe("s125-macaroni_salad", "Macaroni salad", "salad");
  boilNoodles(r, "macaroni").alter("rinse", "macaroni", { plus: ["chilled"] });
  r.prep(["celery", "stalk"], "dice:diced").prep(["sweet pepper", "whole"], "cut:seeded", "dice:diced");
  r.prep(["red onion", "whole", "unpeeled"], "peel:peeled,whole", "mince:minced");
  r.prep(["carrot", "whole", "unpeeled"], "peel:peeled,whole:peeler", "grate:grated");
  r.put("scoop and pour", ["mayonnaise", "creamy", "in [jar]"], "mixing bowl").put("scoop and pour", [...MUSTARD], "mixing bowl");
  r.put("pour", [...VINEGAR], "mixing bowl").putAll("sprinkle", [SUGAR, SALT, PEPPER], "mixing bowl");
  r.mix("whisk", "mixing bowl", "salad dressing", ["creamy", "mixed"], { with: ["whisk"] });
  for (const i of ["macaroni", "celery", "sweet pepper", "red onion", "carrot"]) r.put("sprinkle", i, "mixing bowl");
  r.mix("fold", "mixing bowl", "macaroni salad", ["mixed", "coated"], { with: ["spatula"] });
  return written(r.alter("chill", "macaroni salad", { plus: ["chilled"], with: ["refrigerator"] }), "macaroni salad");
}

/** Chicken salad: poached chicken breast diced into a lemony mayonnaise with celery and grapes. */
function chickenSalad(): WrittenRecipe {
  const r = new Recipe("s126-chicken_salad", "Chicken salad with celery and grapes", "salad");
  boilingWater(r, "saucepan");
  r.put("pick-and-place", ["chicken", "raw"], "saucepan", { with: ["tongs"] });
  r.cookEach("simmer", "saucepan", ["chicken"], { set: ["boiled", "cooked"], with: ["pot lid"] });
  r.put("pick-and-place", "chicken", "cutting board", { with: ["tongs"] }).drop("water");
  r.alter("cool down", "chicken", { plus: ["cooled"] }).alter("dice", "chicken", { set: ["diced", "cooked"], with: ["knife"] });
  r.prep(["celery", "stalk"], "dice:diced").prep(["red onion", "whole", "unpeeled"], "peel:peeled,whole", "mince:minced");
  rinseAndCut(r, ["grape", "whole"], "cut in half:halved");
  r.put("scoop and pour", ["mayonnaise", "creamy", "in [jar]"], "mixing bowl");
  squeezed(r, "lemon", "mixing bowl").putAll("sprinkle", [SALT, PEPPER], "mixing bowl");
  r.mix("stir", "mixing bowl", "salad dressing", ["creamy", "mixed"], { with: ["spoon"] });
  for (const i of ["chicken", "celery", "red onion", "grape"]) r.put("sprinkle", i, "mixing bowl");
  return written(r.mix("fold", "mixing bowl", "chicken salad", ["mixed", "coated"], { with: ["spatula"] }), "chicken salad");
}

export const salad = (): WrittenRecipe[] => [
  gardenSalad(), capreseSalad(), tabbouleh(), pastaSalad(), fruitSalad(), blackBeanSalad(), greenBeanSalad(), cobbSalad(),
  eggSalad(), macaroniSalad(), chickenSalad(),
];
