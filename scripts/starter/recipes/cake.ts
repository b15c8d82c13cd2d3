// Cake: baked sponges and butter cakes, a microwave cake, and no-bake cakes set in the refrigerator.
import { Recipe } from "../recipe";
import { written, type WrittenRecipe } from "../written";
import { BUTTER, crackEggs, FLOUR, MILK, SALT, SUGAR, VEGETABLE_OIL } from "./common";

const BAKING_POWDER = ["baking powder", "powder", "in [box]"] as const;
const VANILLA = ["vanilla extract", "liquid", "in [bottle]"] as const;

/** Butter and sugar beaten creamy, eggs and vanilla beaten in: the start of a butter cake. */
function creamedButter(r: Recipe, bowl = "mixing bowl"): Recipe {
  r.put("pick-and-place", BUTTER, bowl).put("pour", SUGAR, bowl);
  r.mix("beat", bowl, "butter mixture", ["creamy", "mixed"], { with: ["hand mixer"] });
  crackEggs(r, bowl).put("pour", VANILLA, bowl);
  return r.mix("beat", bowl, "cake batter", ["creamy", "mixed"], { with: ["hand mixer"] });
}

/** Pour the batter into the greased pan, bake, cool on a rack and turn out. */
function bakeInPan(r: Recipe, pan: string, cake: string): Recipe {
  r.put("pour and scrape", "cake batter", pan, { with: ["spatula"] });
  r.alter("bake", "cake batter", { as: cake, set: ["baked"], with: ["oven"] });
  r.alter("cool down", cake, { plus: ["cooled"], with: ["wire rack"] });
  return r.put("flip", cake, "plate");
}

function lemonDrizzleCake(): WrittenRecipe {
  const r = new Recipe("s61-lemon_drizzle_cake", "Lemon drizzle loaf cake", "cake");
  r.preheat().grease("loaf pan", BUTTER);
  creamedButter(r);
  r.putAll("sprinkle", [FLOUR, [...BAKING_POWDER], SALT], "mixing bowl").put("pour", MILK, "mixing bowl");
  r.mix("fold", "mixing bowl", "cake batter", ["mixed", "thick liquid"], { with: ["spatula"] });
  bakeInPan(r, "loaf pan", "lemon cake");
  r.prep(["lemon", "whole"], "cut in half:halved").put("squeeze", "lemon", "small bowl", { as: "lemon juice", set: ["juice"], with: ["squeezer"] });
  r.put("sprinkle", ["powdered sugar", "powder", "in [package]"], "small bowl");
  r.mix("stir", "small bowl", "frosting", ["liquid", "mixed"], { with: ["spoon"] });
  r.top("pour and spread", "frosting", "lemon cake", { plus: ["coated"], with: ["spoon"] });
  return written(r, "lemon cake");
}

/** No-bake cheesecake: a pressed crumb base and a whipped cream-cheese filling set in the refrigerator. */
function noBakeCheesecake(): WrittenRecipe {
  const r = new Recipe("s62-no_bake_cheesecake", "No-bake lemon cheesecake", "cake");
  r.put("pour", ["graham cracker", "crumbs", "in [package]"], "bowl");
  r.put("pick-and-place", BUTTER, "small bowl").alter("melt", "butter", { set: ["melted"], with: ["microwave"] });
  r.put("pour", "butter", "bowl").mix("mix", "bowl", "crust", ["mixed", "crumbs"], { with: ["spoon"] });
  r.put("pour", "crust", "cake pan").alter("press", "crust", { set: ["flattened"], with: ["spoon"] });
  r.put("pick-and-place", ["cream cheese", "block", "in [package]"], "mixing bowl");
  r.put("pour", ["powdered sugar", "powder", "in [package]"], "mixing bowl");
  r.prep(["lemon", "whole"], "cut in half:halved").put("squeeze", "lemon", "mixing bowl", { as: "lemon juice", set: ["juice"], with: ["squeezer"] });
  r.put("pour", VANILLA, "mixing bowl").put("pour", ["heavy cream", "liquid", "in [carton]"], "mixing bowl");
  r.mix("beat", "mixing bowl", "cream mixture", ["whipped", "creamy"], { with: ["hand mixer"] });
  r.top("pour and spread", "cream mixture", "crust", { as: "cheesecake", set: ["coated", "flattened"], with: ["spatula"] });
  r.alter("chill", "cheesecake", { plus: ["chilled"], with: ["refrigerator"] });
  r.alter("cut", "cheesecake", { set: ["wedge", "chilled"], with: ["knife"] });
  return written(r, "cheesecake");
}

function appleCinnamonCake(): WrittenRecipe {
  const r = new Recipe("s63-apple_cinnamon_cake", "Apple cinnamon cake", "cake");
  r.preheat().grease("cake pan", BUTTER);
  r.prep(["apple", "whole"], "peel:peeled,whole:peeler", "core:cored", "dice:diced");
  crackEggs(r, "mixing bowl").put("pour", SUGAR, "mixing bowl").put("pour", VEGETABLE_OIL, "mixing bowl");
  r.put("pour", MILK, "mixing bowl").mix("whisk", "mixing bowl", "egg mixture", ["beaten", "uncooked"], { with: ["whisk"] });
  r.putAll("sprinkle", [FLOUR, [...BAKING_POWDER], ["cinnamon", "ground", "in [jar]"], SALT], "mixing bowl");
  r.mix("whisk", "mixing bowl", "cake batter", ["mixed", "thick liquid"], { with: ["whisk"] });
  r.put("sprinkle", "apple", "mixing bowl");
  r.mix("fold", "mixing bowl", "cake batter", ["mixed", "lumpy"], { with: ["spatula"] });
  bakeInPan(r, "cake pan", "apple cake");
  r.top("sprinkle", ["powdered sugar", "powder", "in [package]"], "apple cake", { plus: ["garnished"], with: ["sieve"] });
  return written(r, "apple cake");
}

function poundCake(): WrittenRecipe {
  const r = new Recipe("s64-butter_pound_cake", "Butter pound cake", "cake");
  r.preheat().grease("loaf pan", BUTTER);
  creamedButter(r);
  r.putAll("sprinkle", [FLOUR, SALT], "mixing bowl");
  r.mix("fold", "mixing bowl", "cake batter", ["mixed", "thick liquid"], { with: ["spatula"] });
  bakeInPan(r, "loaf pan", "pound cake");
  r.put("pick-and-place", "pound cake", "cutting board");
  r.alter("slice", "pound cake", { set: ["sliced", "baked", "cooled"], with: ["knife"] });
  return written(r, "pound cake");
}

/** A chocolate cake cooked in a mug in the microwave. */
function mugCake(): WrittenRecipe {
  const r = new Recipe("s65-chocolate_mug_cake", "Chocolate mug cake", "cake");
  r.putAll("sprinkle", [FLOUR, SUGAR, ["cocoa powder", "powder", "in [box]"], [...BAKING_POWDER], SALT], "mug");
  r.put("pour", MILK, "mug").put("pour", VEGETABLE_OIL, "mug").put("pour", VANILLA, "mug");
  r.mix("whisk", "mug", "cake batter", ["mixed", "thick liquid"], { with: ["fork"] });
  r.put("sprinkle", ["chocolate chip", "chunk", "in [package]"], "mug");
  r.mix("stir", "mug", "cake batter", ["mixed", "lumpy"], { with: ["spoon"] });
  r.alter("cook", "cake batter", { as: "chocolate cake", set: ["cooked", "hot"], with: ["microwave"] });
  return written(r, "chocolate cake");
}

/** Victoria sponge: whisked sponge layers sandwiched with jam and whipped cream. */
function victoriaSponge(): WrittenRecipe {
  const r = new Recipe("s66-victoria_sponge", "Victoria sponge with jam and cream", "cake");
  r.preheat().grease("cake pan", BUTTER);
  creamedButter(r);
  r.putAll("sprinkle", [FLOUR, [...BAKING_POWDER]], "mixing bowl").put("pour", MILK, "mixing bowl");
  r.mix("fold", "mixing bowl", "cake batter", ["mixed", "thick liquid"], { with: ["spatula"] });
  bakeInPan(r, "cake pan", "sponge cake");
  r.alter("slice", "sponge cake", { set: ["halved", "baked", "cooled"], with: ["knife"] });
  r.put("pour", ["heavy cream", "liquid", "in [carton]"], "bowl").put("sprinkle", ["powdered sugar", "powder", "in [package]"], "bowl");
  r.mix("whisk", "bowl", "whipped cream", ["whipped", "creamy"], { with: ["whisk"] });
  r.top("spread", ["strawberry jam", "paste", "in [jar]"], "sponge cake", { plus: ["coated"], with: ["spoon"] });
  r.top("spread", "whipped cream", "sponge cake", { set: ["coated", "stacked", "baked", "cooled"], with: ["spatula"] });
  return written(r, "sponge cake");
}

/** Icebox cake: no oven; biscuits soften between layers of whipped cream overnight. */
function iceboxCake(): WrittenRecipe {
  const r = new Recipe("s67-chocolate_icebox_cake", "Chocolate icebox cake", "cake");
  r.put("pour", ["heavy cream", "liquid", "in [carton]"], "mixing bowl");
  r.putAll("sprinkle", [["powdered sugar", "powder", "in [package]"], ["cocoa powder", "powder", "in [box]"]], "mixing bowl");
  r.put("pour", VANILLA, "mixing bowl");
  r.mix("whisk", "mixing bowl", "whipped cream", ["whipped", "creamy"], { with: ["hand mixer"] });
  r.put("pick-and-place", ["chocolate wafer", "whole", "in [package]"], "baking dish");
  r.top("spread", "whipped cream", "chocolate wafer", { as: "icebox cake", set: ["coated", "stacked"], with: ["spatula"] });
  r.alter("chill", "icebox cake", { plus: ["chilled", "softened"], with: ["refrigerator"] });
  r.prep(["dark chocolate", "bar", "in [package]"], "grate:grated");
  r.top("sprinkle", "dark chocolate", "icebox cake", { plus: ["garnished"] });
  return written(r, "icebox cake");
}

export const cake = (): WrittenRecipe[] => [
  lemonDrizzleCake(), noBakeCheesecake(), appleCinnamonCake(), poundCake(), mugCake(), victoriaSponge(), iceboxCake(),
];
