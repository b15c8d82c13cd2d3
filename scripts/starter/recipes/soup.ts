// Soup: cold and blended soups, chunky meat and vegetable soups, legume soups, clear broths (with egg, with
// noodles, under a baked cheese crust) and a chowder.
import { Recipe } from "../recipe";
import { written, type WrittenRecipe } from "../written";
import { BUTTER, choppedOnion, crackEggs, FLOUR, MILK, mincedGarlic, OLIVE_OIL, PEPPER, SALT, WATER } from "./common";

const VEG_BROTH = ["vegetable broth", "liquid", "in [carton]"] as const;
const CHICKEN_BROTH = ["chicken broth", "liquid", "in [carton]"] as const;
const BAY = ["bay leaf", "dried", "in [jar]"] as const;
const THYME = ["thyme", "dried", "in [jar]"] as const;

/** A peeled carrot cut on the board (diced unless told). */
function carrot(r: Recipe, cut = "dice:diced"): Recipe {
  return r.prep(["carrot", "whole", "unpeeled"], "peel:peeled,whole:peeler", cut);
}

/** Oil (or melted butter) heated in the pot and the prepared vegetables sweated in it. */
function sweat(r: Recipe, pot: string, vegetables: string[], fat = OLIVE_OIL): Recipe {
  if (fat === BUTTER) r.put("pick-and-place", fat, pot).heat(pot).alter("melt", "butter", { set: ["melted"] });
  else r.put("pour", fat, pot).heat(pot);
  for (const v of vegetables) r.put("pour", v, pot);
  return r.cookEach("cook and stir", pot, vegetables, { plus: ["sauteed"], with: ["wooden spoon"] });
}

/** The soup ladled from its pot into a serving bowl. */
function ladle(r: Recipe, soup: string, bowl = "serving bowl"): Recipe {
  return r.put("pour", soup, bowl, { with: ["ladle"] });
}

/** Gazpacho: raw vegetables blended with oil and vinegar and served cold. */
function gazpacho(): WrittenRecipe {
  const r = new Recipe("s112-gazpacho", "Gazpacho", "soup");
  // cut in pieces, not chopped: the blender chops, and a plan borrowing a chopped vegetable gets no stray blender jar
  r.prep(["tomato", "whole"], "core:cored", "cut:cut in pieces").put("pick-and-place", "tomato", "blender jar");
  r.prep(["cucumber", "whole", "unpeeled"], "peel:peeled,whole:peeler", "cut:cut in pieces").put("pick-and-place", "cucumber", "blender jar");
  r.prep(["sweet pepper", "whole"], "cut:seeded", "cut:cut in pieces").put("pick-and-place", "sweet pepper", "blender jar");
  r.prep(["red onion", "whole", "unpeeled"], "peel:peeled,whole", "cut:cut in pieces").put("pick-and-place", "red onion", "blender jar");
  mincedGarlic(r).put("pick-and-place", "garlic", "blender jar");
  r.put("pour", OLIVE_OIL, "blender jar").put("pour", ["vinegar", "liquid", "in [bottle]"], "blender jar");
  r.putAll("sprinkle", [SALT, PEPPER], "blender jar");
  r.mix("blend", "blender jar", "gazpacho", ["blended", "liquid"], { with: ["blender"] });
  ladle(r, "gazpacho", "bowl").alter("chill", "gazpacho", { plus: ["chilled"], with: ["refrigerator"] });
  return written(r, "gazpacho");
}

/** Butternut squash soup: squash simmered soft in broth and blended smooth, finished with cream. */
function butternutSquashSoup(): WrittenRecipe {
  const r = new Recipe("s113-butternut_squash_soup", "Butternut squash soup", "soup");
  r.prep(["butternut squash", "whole"], "peel:peeled,whole:peeler", "cut:seeded", "cut:cubed");
  choppedOnion(r);
  sweat(r, "pot", ["onion"], BUTTER);
  r.put("pour", "butternut squash", "pot").put("pour", [...VEG_BROTH], "pot");
  r.putAll("sprinkle", [["nutmeg", "ground", "in [jar]"], SALT, PEPPER], "pot");
  // the cream simmers in the pot: what joins the soup last is cooked with it, not stirred raw into the bowl
  r.put("pour", ["heavy cream", "liquid", "in [carton]"], "pot");
  r.mix("simmer", "pot", "soup", ["liquid", "cooked"], { with: ["wooden spoon"] });
  r.put("pour", "soup", "blender jar", { with: ["ladle"] });
  r.mix("blend", "blender jar", "squash soup", ["blended", "creamy", "hot"], { with: ["blender"] });
  return written(r.put("pour", "squash soup", "serving bowl"), "squash soup");
}

/** Beef and vegetable soup: beef browned, then simmered with root vegetables in broth. */
function beefVegetableSoup(): WrittenRecipe {
  const r = new Recipe("s114-beef_vegetable_soup", "Beef and vegetable soup", "soup");
  r.prep(["beef", "raw", "in [package]"], "cut:cubed");
  choppedOnion(r);
  carrot(r).prep(["celery", "stalk"], "dice:diced");
  r.prep(["potato", "whole", "unpeeled"], "peel:peeled,whole:peeler", "cut:cubed");
  r.put("pour", OLIVE_OIL, "pot").heat("pot").put("pick-and-place", "beef", "pot", { with: ["tongs"] });
  r.cookEach("cook and stir", "pot", ["beef"], { set: ["cubed", "cooked"], with: ["wooden spoon"] });
  for (const v of ["onion", "carrot", "celery"]) r.put("pour", v, "pot");
  r.cookEach("cook and stir", "pot", ["onion", "carrot", "celery"], { plus: ["sauteed"], with: ["wooden spoon"] });
  r.put("pour", "potato", "pot").put("pour", ["tomato sauce", "thick liquid", "in [can]"], "pot");
  r.put("pour", ["beef broth", "liquid", "in [carton]"], "pot");
  r.put("pick-and-place", [...BAY], "pot").putAll("sprinkle", [[...THYME], SALT, PEPPER], "pot");
  r.mix("simmer", "pot", "beef soup", ["liquid", "cooked"], { with: ["wooden spoon"] });
  ladle(r, "beef soup");
  r.prep(["parsley", "leaf"], "chop:chopped").top("sprinkle", "parsley", "beef soup", { plus: ["garnished"] });
  return written(r, "beef soup");
}

/** Black bean soup: canned beans simmered with cumin and partly mashed to thicken. */
function blackBeanSoup(): WrittenRecipe {
  const r = new Recipe("s115-black_bean_soup", "Black bean soup", "soup");
  choppedOnion(r).prep(["sweet pepper", "whole"], "cut:seeded", "dice:diced");
  mincedGarlic(r);
  sweat(r, "pot", ["onion", "sweet pepper", "garlic"]);
  r.put("drain", ["black bean", "cooked", "in [can]"], "colander").alter("rinse", "black bean", { plus: ["washed"] });
  r.put("pour", "black bean", "pot").put("pour", [...VEG_BROTH], "pot");
  r.putAll("sprinkle", [["cumin", "ground", "in [jar]"], ["chili powder", "powder", "in [jar]"], SALT], "pot");
  r.mix("simmer", "pot", "black bean soup", ["thick liquid", "cooked"], { with: ["wooden spoon"] });
  r.alter("mash", "black bean soup", { set: ["thick liquid", "cooked", "lumpy"], with: ["masher"] });
  ladle(r, "black bean soup");
  r.top("pick-and-place", ["sour cream", "creamy", "in [container]"], "black bean soup", { with: ["spoon"] });
  r.prep(["cilantro", "leaf"], "chop:chopped").top("sprinkle", "cilantro", "black bean soup", { plus: ["garnished"] });
  return written(r, "black bean soup");
}

/** Split pea soup: dried peas simmered soft with ham and aromatic vegetables. */
function splitPeaSoup(): WrittenRecipe {
  const r = new Recipe("s116-split_pea_soup", "Split pea soup with ham", "soup");
  r.put("rinse", ["split pea", "dried", "in [package]"], "strainer", { plus: ["washed"] });
  choppedOnion(r);
  carrot(r).prep(["celery", "stalk"], "dice:diced");
  r.prep(["ham", "sliced", "in [package]"], "dice:diced");
  sweat(r, "pot", ["onion", "carrot", "celery"]);
  r.put("pour", "split pea", "pot").put("pour", "ham", "pot").put("pour", WATER, "pot");
  r.put("pick-and-place", [...BAY], "pot").putAll("sprinkle", [SALT, PEPPER], "pot");
  r.mix("simmer", "pot", "split pea soup", ["thick liquid", "cooked"], { with: ["wooden spoon"] });
  return written(ladle(r, "split pea soup"), "split pea soup");
}

/** French onion soup: onions slowly browned, simmered in broth, under toasted bread and melted cheese. */
function frenchOnionSoup(): WrittenRecipe {
  const r = new Recipe("s117-french_onion_soup", "French onion soup", "soup");
  r.preheat();
  choppedOnion(r, "slice:sliced");
  sweat(r, "pot", ["onion"], BUTTER);
  r.put("sprinkle", FLOUR, "pot").put("pour", ["beef broth", "liquid", "in [carton]"], "pot");
  r.putAll("sprinkle", [[...THYME], SALT, PEPPER], "pot");
  r.mix("simmer", "pot", "onion soup", ["liquid", "cooked"], { with: ["wooden spoon"] });
  ladle(r, "onion soup", "heatproof bowl");
  r.prep(["bread", "loaf"], "slice:sliced").put("pick-and-place", "bread", "baking tray");
  r.alter("toast", "bread", { set: ["sliced", "toasted"], with: ["oven"] });
  r.top("pick-and-place", "bread", "onion soup");
  r.prep(["gruyere", "block", "in [package]"], "grate:grated").top("sprinkle", "gruyere", "onion soup");
  r.alter("bake", "onion soup", { set: ["baked", "hot"], with: ["oven"] });
  return written(r, "onion soup");
}

/** Egg drop soup: beaten egg poured in threads into simmering, lightly thickened broth. */
function eggDropSoup(): WrittenRecipe {
  const r = new Recipe("s118-egg_drop_soup", "Egg drop soup", "soup");
  r.put("sprinkle", ["cornstarch", "powder", "in [box]"], "small bowl").put("pour", WATER, "small bowl");
  r.mix("stir", "small bowl", "cornstarch mixture", ["liquid", "mixed"], { with: ["spoon"] });
  r.put("pour", [...CHICKEN_BROTH], "pot").heat("pot");
  r.prep(["ginger", "whole", "unpeeled"], "peel:peeled,whole:peeler", "grate:grated").put("sprinkle", "ginger", "pot");
  r.put("pour", ["soy sauce", "liquid", "in [bottle]"], "pot").put("pour", "cornstarch mixture", "pot");
  r.mix("simmer", "pot", "broth", ["liquid", "cooked"], { with: ["wooden spoon"] });
  crackEggs(r, "bowl").mix("beat", "bowl", "egg mixture", ["beaten", "uncooked"], { with: ["fork"] });
  r.put("pour", "egg mixture", "pot");
  r.mix("simmer", "pot", "egg drop soup", ["liquid", "cooked"], { with: ["fork"] });
  ladle(r, "egg drop soup");
  r.prep(["green onion", "whole"], "slice:sliced").top("sprinkle", "green onion", "egg drop soup", { plus: ["garnished"] });
  return written(r, "egg drop soup");
}

/** Vegetable noodle soup: a vegetable broth with egg noodles cooked in it. */
function vegetableNoodleSoup(): WrittenRecipe {
  const r = new Recipe("s119-vegetable_noodle_soup", "Vegetable noodle soup", "soup");
  choppedOnion(r);
  carrot(r, "slice:sliced").prep(["celery", "stalk"], "slice:sliced");
  mincedGarlic(r);
  sweat(r, "pot", ["onion", "carrot", "celery", "garlic"]);
  r.put("pour", [...VEG_BROTH], "pot").putAll("sprinkle", [[...THYME], SALT, PEPPER], "pot");
  r.prep(["zucchini", "whole"], "cut off ends:ends removed", "dice:diced").put("pour", "zucchini", "pot");
  r.put("pour", ["egg noodle", "dried", "in [package]"], "pot");
  r.mix("simmer", "pot", "noodle soup", ["liquid", "cooked"], { with: ["wooden spoon"] });
  ladle(r, "noodle soup");
  r.prep(["parsley", "leaf"], "chop:chopped").top("sprinkle", "parsley", "noodle soup", { plus: ["garnished"] });
  return written(r, "noodle soup");
}

/** Corn chowder: bacon, potato and corn in a milk broth thickened with flour. */
function cornChowder(): WrittenRecipe {
  const r = new Recipe("s120-corn_chowder", "Corn and potato chowder", "soup");
  r.prep(["bacon", "raw", "in [package]"], "chop:chopped");
  r.heat("pot").put("pick-and-place", "bacon", "pot");
  r.cookEach("fry", "pot", ["bacon"], { set: ["chopped", "fried"], with: ["wooden spoon"] });
  choppedOnion(r).prep(["celery", "stalk"], "dice:diced");
  r.prep(["potato", "whole", "unpeeled"], "peel:peeled,whole:peeler", "dice:diced");
  r.put("pour", "onion", "pot").put("pour", "celery", "pot");
  r.cookEach("cook and stir", "pot", ["onion", "celery"], { plus: ["sauteed"], with: ["wooden spoon"] });
  r.put("sprinkle", FLOUR, "pot").put("pour", [...CHICKEN_BROTH], "pot").put("pour", "potato", "pot");
  r.put("pour", ["corn", "frozen", "in [package]"], "pot").put("pour", MILK, "pot");
  r.putAll("sprinkle", [SALT, PEPPER], "pot");
  r.mix("simmer", "pot", "chowder", ["thick liquid", "cooked"], { with: ["wooden spoon"] });
  ladle(r, "chowder");
  r.prep(["chive", "whole"], "chop:chopped").top("sprinkle", "chive", "chowder", { plus: ["garnished"] });
  return written(r, "chowder");
}

/** Chili con carne: browned beef simmered with beans, tomato and chili spices, topped with cheddar. */
function chiliConCarne(): WrittenRecipe {
  const r = new Recipe("s127-chili_con_carne", "Chili con carne", "soup");
  choppedOnion(r).prep(["sweet pepper", "whole"], "cut:seeded", "dice:diced");
  mincedGarlic(r);
  r.put("pour", OLIVE_OIL, "pot").heat("pot").put("pick-and-place", ["ground beef", "raw", "in [package]"], "pot");
  r.cookEach("cook and stir", "pot", ["ground beef"], { set: ["crumbled", "cooked"], with: ["wooden spoon"] });
  for (const v of ["onion", "sweet pepper", "garlic"]) r.put("pour", v, "pot");
  r.cookEach("cook and stir", "pot", ["onion", "sweet pepper", "garlic"], { plus: ["sauteed"], with: ["wooden spoon"] });
  r.putAll("sprinkle", [["chili powder", "powder", "in [jar]"], ["cumin", "ground", "in [jar]"], SALT], "pot");
  r.put("drain", ["kidney bean", "cooked", "in [can]"], "colander").alter("rinse", "kidney bean", { plus: ["washed"] });
  r.put("pour", "kidney bean", "pot").put("pour", ["tomato sauce", "thick liquid", "in [can]"], "pot");
  r.put("pour", ["beef broth", "liquid", "in [carton]"], "pot");
  r.mix("simmer", "pot", "chili", ["thick liquid", "cooked"], { with: ["wooden spoon"] });
  ladle(r, "chili");
  r.prep(["cheddar", "block", "in [package]"], "grate:shredded").top("sprinkle", "cheddar", "chili", { plus: ["garnished"] });
  return written(r, "chili");
}

export const soup = (): WrittenRecipe[] => [
  gazpacho(), butternutSquashSoup(), beefVegetableSoup(), blackBeanSoup(), splitPeaSoup(), frenchOnionSoup(),
  eggDropSoup(), vegetableNoodleSoup(), cornChowder(), chiliConCarne(),
];
