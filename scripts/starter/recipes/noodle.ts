// Noodle: stir-fried, sauced, cold, in broth and baked noodle dishes.
import { Recipe } from "../recipe";
import { written, type WrittenRecipe } from "../written";
import { boilNoodles, BUTTER, choppedOnion, crackEggs, FLOUR, MILK, mincedGarlic, OLIVE_OIL, PEPPER, SALT, serve, SUGAR, VEGETABLE_OIL } from "./common";

const SOY = ["soy sauce", "liquid", "in [bottle]"] as const;
const SESAME = ["sesame oil", "liquid", "in [bottle]"] as const;
const PARMESAN = ["parmesan", "block", "in [package]"] as const;

/** A peeled, julienned carrot on the cutting board. */
function julienneCarrot(r: Recipe): Recipe {
  return r.prep(["carrot", "whole", "unpeeled"], "peel:peeled,whole:peeler", "slice:julienned");
}

function peeledGinger(r: Recipe): Recipe {
  return r.prep(["ginger", "whole", "unpeeled"], "peel:peeled,whole:peeler", "mince:minced");
}

function chickenLoMein(): WrittenRecipe {
  const r = new Recipe("s75-chicken_lo_mein", "Chicken lo mein", "noodle");
  boilNoodles(r, "egg noodle");
  r.prep(["chicken", "raw"], "slice:sliced");
  julienneCarrot(r).prep(["cabbage", "whole"], "slice:shredded");
  mincedGarlic(r);
  r.put("pour", [...VEGETABLE_OIL], "wok").heat("wok").put("pick-and-place", "chicken", "wok", { with: ["tongs"] });
  r.cookEach("cook and stir", "wok", ["chicken"], { set: ["sliced", "stir-fried", "cooked"], with: ["spatula"] });
  for (const v of ["garlic", "carrot", "cabbage"]) r.put("pour", v, "wok");
  r.cookEach("cook and stir", "wok", ["garlic", "carrot", "cabbage"], { plus: ["stir-fried"], with: ["spatula"] });
  r.put("pour", "egg noodle", "wok").put("pour", [...SOY], "wok").put("pour", [...SESAME], "wok").put("sprinkle", SUGAR, "wok");
  r.mix("cook and stir", "wok", "lo mein", ["stir-fried", "mixed"], { with: ["tongs"] });
  return written(serve(r, "lo mein", "serving bowl", "scoop and pour", "tongs"), "lo mein");
}

function sesameColdNoodles(): WrittenRecipe {
  const r = new Recipe("s76-sesame_cold_noodles", "Cold sesame noodles with cucumber", "noodle");
  boilNoodles(r, "soba noodle");
  r.put("rinse", "soba noodle", "strainer", { plus: ["chilled"] }).put("pick-and-place", "soba noodle", "serving bowl");
  r.put("scoop and pour", ["tahini", "paste", "in [jar]"], "small bowl").put("pour", [...SOY], "small bowl");
  r.put("pour", [...SESAME], "small bowl").put("pour", ["vinegar", "liquid", "in [bottle]"], "small bowl");
  r.put("sprinkle", SUGAR, "small bowl");
  r.mix("whisk", "small bowl", "sauce", ["liquid", "mixed"], { with: ["whisk"] });
  r.put("pour", "sauce", "serving bowl");
  r.prep(["cucumber", "whole"], "slice:julienned").put("sprinkle", "cucumber", "serving bowl");
  r.prep(["green onion", "whole"], "slice:sliced").put("sprinkle", "green onion", "serving bowl");
  r.mix("mix", "serving bowl", "soba noodle salad", ["tossed", "chilled"], { with: ["tongs"] });
  return written(r, "soba noodle salad");
}

function spaghettiBolognese(): WrittenRecipe {
  const r = new Recipe("s77-spaghetti_bolognese", "Spaghetti bolognese", "noodle");
  choppedOnion(r, "dice:diced");
  r.prep(["carrot", "whole", "unpeeled"], "peel:peeled,whole:peeler", "dice:diced");
  r.prep(["celery", "stalk"], "dice:diced");
  mincedGarlic(r);
  r.put("pour", OLIVE_OIL, "saucepan").heat("saucepan");
  for (const v of ["onion", "carrot", "celery", "garlic"]) r.put("pour", v, "saucepan");
  r.mix("cook and stir", "saucepan", "vegetable mixture", ["sauteed", "mixed"], { with: ["wooden spoon"] });
  r.put("pick-and-place", ["ground beef", "raw", "in [package]"], "saucepan");
  r.cookEach("cook and stir", "saucepan", ["ground beef"], { set: ["crumbled", "cooked"], with: ["wooden spoon"] });
  r.put("pour", ["tomato sauce", "thick liquid", "in [can]"], "saucepan");
  r.putAll("sprinkle", [["oregano", "dried", "in [jar]"], SALT, PEPPER], "saucepan");
  r.mix("simmer", "saucepan", "sauce", ["thick liquid", "cooked"], { with: ["wooden spoon"] });
  boilNoodles(r, "spaghetti");
  r.put("pick-and-place", "spaghetti", "plate", { with: ["tongs"] });
  r.top("scoop and pour", "sauce", "spaghetti", { plus: ["coated"], with: ["ladle"] });
  r.prep([...PARMESAN], "grate:grated").top("sprinkle", "parmesan", "spaghetti", { plus: ["garnished"] });
  return written(r, "spaghetti");
}

function fettuccineAlfredo(): WrittenRecipe {
  const r = new Recipe("s78-fettuccine_alfredo", "Fettuccine alfredo", "noodle");
  boilNoodles(r, "fettuccine");
  mincedGarlic(r);
  r.put("pick-and-place", BUTTER, "skillet").heat("skillet").alter("melt", "butter", { set: ["melted"] });
  r.put("pour", "garlic", "skillet").cookEach("cook and stir", "skillet", ["garlic"], { plus: ["sauteed"], with: ["wooden spoon"] });
  r.put("pour", ["heavy cream", "liquid", "in [carton]"], "skillet");
  r.prep([...PARMESAN], "grate:grated").put("sprinkle", "parmesan", "skillet");
  r.putAll("sprinkle", [SALT, PEPPER, ["nutmeg", "ground", "in [jar]"]], "skillet");
  r.mix("simmer", "skillet", "white sauce", ["thick liquid", "cooked"], { with: ["whisk"] });
  r.put("pour", "fettuccine", "skillet");
  r.mix("cook and stir", "skillet", "fettuccine alfredo", ["coated", "cooked"], { with: ["tongs"] });
  r.prep(["parsley", "leaf"], "chop:chopped").top("sprinkle", "parsley", "fettuccine alfredo", { plus: ["garnished"] });
  return written(serve(r, "fettuccine alfredo", "plate", "pick-and-place", "tongs"), "fettuccine alfredo");
}

function mushroomUdon(): WrittenRecipe {
  const r = new Recipe("s79-mushroom_udon_stir_fry", "Stir-fried udon with mushrooms", "noodle");
  boilNoodles(r, "udon noodle", "frozen");
  r.prep(["mushroom", "whole"], "slice:sliced").prep(["sweet pepper", "whole"], "cut:seeded", "slice:sliced");
  peeledGinger(r).prep(["green onion", "whole"], "slice:sliced");
  r.put("pour", [...VEGETABLE_OIL], "wok").heat("wok");
  for (const v of ["ginger", "mushroom", "sweet pepper"]) r.put("pour", v, "wok");
  r.cookEach("cook and stir", "wok", ["ginger", "mushroom", "sweet pepper"], { plus: ["stir-fried"], with: ["spatula"] });
  r.put("pour", "udon noodle", "wok").put("pour", [...SOY], "wok");
  r.put("pour", ["oyster sauce", "thick liquid", "in [bottle]"], "wok").put("pour", "green onion", "wok");
  r.mix("cook and stir", "wok", "udon", ["stir-fried", "mixed"], { with: ["tongs"] });
  return written(serve(r, "udon", "serving bowl", "scoop and pour", "tongs"), "udon");
}

/** Chicken ramen: noodles in a ginger-soy broth with a soft-boiled egg. */
function chickenRamen(): WrittenRecipe {
  const r = new Recipe("s80-chicken_ramen", "Chicken ramen with soft egg", "noodle");
  r.put("pour", ["chicken broth", "liquid", "in [carton]"], "pot").heat("pot");
  peeledGinger(r).put("pour", "ginger", "pot");
  mincedGarlic(r).put("pour", "garlic", "pot").put("pour", [...SOY], "pot");
  r.prep(["chicken", "raw"], "slice:sliced").put("pick-and-place", "chicken", "pot");
  r.prep(["mushroom", "whole"], "slice:sliced").put("pour", "mushroom", "pot");
  r.mix("simmer", "pot", "broth", ["liquid", "cooked"], { with: ["ladle"] });
  r.put("pour", ["water", "liquid", "from [faucet]"], "saucepan").heat("saucepan").alter("boil", "water", { plus: ["boiling"] });
  r.put("pick-and-place", ["egg", "whole"], "saucepan", { with: ["spoon"] });
  r.cookEach("boil", "saucepan", ["egg"], { set: ["whole", "boiled"] });
  r.put("pick-and-place", "egg", "bowl", { with: ["spoon"] }).drop("water");
  r.alter("peel", "egg", { set: ["peeled", "boiled"] }).alter("cut in half", "egg", { set: ["halved", "boiled"], with: ["knife"] });
  // the noodles cook in the simmering broth, so what joins the ramen last is cooked too
  r.put("pour", ["ramen noodle", "dried", "in [package]"], "pot");
  r.mix("simmer", "pot", "ramen", ["liquid", "cooked"], { with: ["chopstick"] });
  r.put("pour", "ramen", "serving bowl", { with: ["ladle"] });
  r.top("pick-and-place", "egg", "ramen", { with: ["spoon"] });
  r.prep(["green onion", "whole"], "slice:sliced").top("sprinkle", "green onion", "ramen", { plus: ["garnished"] });
  return written(r, "ramen");
}

/** Tuna noodle casserole: egg noodles and tuna in a white sauce, topped with cheese and baked. */
function tunaNoodleCasserole(): WrittenRecipe {
  const r = new Recipe("s81-tuna_noodle_casserole", "Tuna noodle casserole", "noodle");
  r.preheat();
  boilNoodles(r, "egg noodle").put("pour", "egg noodle", "baking dish");
  choppedOnion(r).prep(["celery", "stalk"], "dice:diced");
  r.put("pick-and-place", BUTTER, "saucepan").heat("saucepan").alter("melt", "butter", { set: ["melted"] });
  r.put("pour", "onion", "saucepan").put("pour", "celery", "saucepan");
  r.cookEach("cook and stir", "saucepan", ["onion", "celery"], { plus: ["sauteed"], with: ["wooden spoon"] });
  r.put("sprinkle", FLOUR, "saucepan").put("pour", MILK, "saucepan").putAll("sprinkle", [SALT, PEPPER], "saucepan");
  r.mix("whisk", "saucepan", "white sauce", ["thick liquid", "cooked"], { with: ["whisk"] });
  r.put("pour", "white sauce", "baking dish");
  r.put("drain", ["tuna", "flakes", "in [can]"], "strainer").put("pour", "tuna", "baking dish");
  r.put("pour", ["green pea", "frozen", "in [package]"], "baking dish");
  r.mix("mix", "baking dish", "casserole", ["mixed"], { with: ["spoon"] });
  r.prep(["cheddar", "block", "in [package]"], "grate:shredded").top("sprinkle", "cheddar", "casserole");
  r.alter("bake", "casserole", { as: "tuna noodle casserole", set: ["baked", "hot"], with: ["oven"] });
  return written(r, "tuna noodle casserole");
}

function butteredNoodles(): WrittenRecipe {
  const r = new Recipe("s82-buttered_egg_noodles", "Buttered egg noodles with parsley", "noodle");
  boilNoodles(r, "egg noodle").put("pour", "egg noodle", "serving bowl");
  r.put("pick-and-place", BUTTER, "serving bowl");
  r.prep(["parsley", "leaf"], "chop:chopped").put("sprinkle", "parsley", "serving bowl");
  r.putAll("sprinkle", [SALT, PEPPER], "serving bowl");
  r.mix("mix", "serving bowl", "buttered noodle", ["coated", "mixed"], { with: ["tongs"] });
  return written(r, "buttered noodle");
}

/** Carbonara: the hot spaghetti cooks the egg and cheese into a sauce off the heat. */
function spaghettiCarbonara(): WrittenRecipe {
  const r = new Recipe("s83-spaghetti_carbonara", "Spaghetti carbonara", "noodle");
  r.prep(["bacon", "raw", "in [package]"], "chop:chopped");
  r.heat("skillet").put("pick-and-place", "bacon", "skillet");
  r.cookEach("fry", "skillet", ["bacon"], { set: ["chopped", "fried"], with: ["spatula"] });
  crackEggs(r, "bowl").prep([...PARMESAN], "grate:grated").put("sprinkle", "parmesan", "bowl").put("sprinkle", PEPPER, "bowl");
  r.mix("whisk", "bowl", "egg mixture", ["beaten", "uncooked"], { with: ["whisk"] });
  boilNoodles(r, "spaghetti").put("pour", "spaghetti", "skillet");
  r.put("pour", "egg mixture", "skillet");
  r.mix("stir", "skillet", "spaghetti carbonara", ["coated", "cooked"], { with: ["tongs"] });
  return written(serve(r, "spaghetti carbonara", "plate", "pick-and-place", "tongs"), "spaghetti carbonara");
}

function peanutRiceNoodles(): WrittenRecipe {
  const r = new Recipe("s84-peanut_rice_noodles", "Peanut rice noodles with vegetables", "noodle");
  r.put("pour", ["water", "liquid", "from [faucet]"], "kettle").alter("boil", "water", { plus: ["boiling"], vessel: true });
  r.put("pick-and-place", ["rice noodle", "dried", "in [package]"], "heatproof bowl").put("pour", "water", "heatproof bowl");
  r.cookEach("soak", "heatproof bowl", ["rice noodle"], { set: ["soaked", "cooked"] });
  r.put("drain", "rice noodle", "colander").drop("water").put("pour", "rice noodle", "serving bowl");
  r.put("scoop and pour", ["peanut butter", "paste", "in [jar]"], "small bowl").put("pour", [...SOY], "small bowl");
  r.prep(["lime", "whole"], "cut in half:halved").put("squeeze", "lime", "small bowl", { as: "lime juice", set: ["juice"], with: ["squeezer"] });
  r.put("pour", ["honey", "thick liquid", "in [jar]"], "small bowl");
  r.mix("whisk", "small bowl", "sauce", ["thick liquid", "mixed"], { with: ["whisk"] });
  r.put("pour", "sauce", "serving bowl");
  julienneCarrot(r).put("sprinkle", "carrot", "serving bowl");
  r.prep(["sweet pepper", "whole"], "cut:seeded", "slice:julienned").put("sprinkle", "sweet pepper", "serving bowl");
  r.prep(["cilantro", "leaf"], "chop:chopped").put("sprinkle", "cilantro", "serving bowl");
  r.mix("mix", "serving bowl", "peanut noodle", ["tossed", "coated"], { with: ["tongs"] });
  r.prep(["peanut", "shelled", "in [package]"], "chop:chopped").top("sprinkle", "peanut", "peanut noodle", { plus: ["garnished"] });
  return written(r, "peanut noodle");
}

export const noodle = (): WrittenRecipe[] => [
  chickenLoMein(), sesameColdNoodles(), spaghettiBolognese(), fettuccineAlfredo(), mushroomUdon(), chickenRamen(),
  tunaNoodleCasserole(), butteredNoodles(), spaghettiCarbonara(), peanutRiceNoodles(),
];
