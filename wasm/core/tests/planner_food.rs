//! The planner's food knowledge on small hand-made knowledge bases: raw meat cooked before it joins a
//! dish that does not cook it, flour joined before the dish is baked, produce named only by its category
//! prepared as a cook would, produce peeled before it is cut, a raw dish cooked last, progress lines that
//! reach the dish, and the cautions a plan reports.

mod common;
use common::hand::{outcome, plan_of, query, try_plan, BLACK_PEPPER};
use foon_core::planner::{cautions, CautionKind};
use foon_core::similarity::ExactMatch;
use foon_core::Plan;

/// A salad (class 15): lettuce chopped and mixed in a bowl.
const LETTUCE_SALAD: &str = "//
O\tsalad bowl\t0
S\tempty
O\tlettuce\t1
S\tchopped
M\tmix\t<Assumed>
O\tgreen salad\t1\t15
S\tmixed
S\tcontains\t{lettuce}
S\tin\t[salad bowl]
//
";

/// Elsewhere in FOON: chicken sliced raw, an onion chopped.
const PREPARED: &str = "//
O\tchicken breast\t1
S\traw
O\tknife\t1
S\tclean
M\tslice\t<Assumed>
O\tchicken breast\t1
S\tsliced
S\traw
//
O\tonion\t1
S\twhole
O\tknife\t1
S\tclean
M\tchop\t<Assumed>
O\tonion\t1
S\tchopped
//
";

fn kinds(p: &Plan) -> Vec<CautionKind> {
    cautions(p).into_iter().map(|c| c.kind).collect()
}

/// The motions of `food`'s progress line.
fn line_motions<'p>(p: &'p Plan, food: &str) -> Vec<&'p str> {
    let line = p
        .progress_lines
        .iter()
        .find(|l| l.ingredient == food)
        .unwrap_or_else(|| panic!("no line for {food}: {:#?}", p.progress_lines));
    line.motion.iter().map(|m| m.as_str()).collect()
}

#[test]
fn raw_chicken_is_cooked_before_it_joins_a_salad_that_does_not_cook_it() {
    let p = plan_of(
        &[("salad.txt", LETTUCE_SALAD), ("prep.txt", PREPARED)],
        &ExactMatch,
        &query(
            "salad",
            &[("lettuce", "chopped"), ("chicken breast", "sliced")],
        ),
    );
    let motions = line_motions(&p, "chicken breast");
    assert_eq!(motions, ["slice", "cook", "mix"], "{:#?}", p.units);
    let reason = outcome(&p, "chicken breast").reason.as_deref().unwrap();
    assert!(reason.contains("'cook' to make it cooked"), "{reason}");
    assert_eq!(kinds(&p), []);
}

#[test]
fn the_unmodified_tree_of_a_salad_with_raw_chicken_is_cautioned() {
    let salad = LETTUCE_SALAD.replace(
        "S\tchopped\nM",
        "S\tchopped\nO\tchicken breast\t1\nS\tsliced\nM",
    );
    let salad = salad.replace("{lettuce}", "{chicken breast,lettuce}");
    let mut request = query(
        "salad",
        &[("lettuce", "chopped"), ("chicken breast", "sliced")],
    );
    request = request.replace("}}", "}, \"modify\": false}");
    let p = try_plan(&[("salad.txt", &salad)], &ExactMatch, &request).unwrap();
    let found = cautions(&p);
    assert_eq!(found.len(), 1, "{found:#?}");
    assert_eq!(found[0].kind, CautionKind::Uncooked);
    assert_eq!(
        found[0].detail,
        "chicken breast reaches green salad uncooked"
    );
}

/// A cake (class 5): eggs beaten into a batter, baked, then syrup poured over the cake.
const SYRUP_CAKE: &str = "//
O\tbowl\t0
S\tempty
O\tegg\t1
S\tcracked
M\tbeat\t<Assumed>
O\tbatter\t1
S\tbeaten
S\tcontains\t{egg}
S\tin\t[bowl]
//
O\tbatter\t1
S\tbeaten
S\tcontains\t{egg}
S\tin\t[bowl]
O\toven\t0
S\ton
M\tbake\t<Assumed>
O\tsponge\t1
S\tbaked
S\tcontains\t{egg}
//
O\tsponge\t1
S\tbaked
S\tcontains\t{egg}
O\tsyrup\t1
S\tliquid
M\tpour\t<Assumed>
O\tsyrup cake\t1\t5
S\tcontains\t{egg,syrup}
//
";

/// Flour as bought, in a recipe of its own.
const FLOUR: &str = "//
O\tflour\t1
S\tpowder
S\tin\t[bag]
O\tmeasuring cup\t0
S\tempty
M\tpour\t<Assumed>
O\tflour\t1
S\tpowder
S\tin\t[measuring cup]
//
";

#[test]
fn flour_joins_the_cake_before_it_is_baked_not_with_the_syrup_after() {
    let p = plan_of(
        &[("cake.txt", SYRUP_CAKE), ("flour.txt", FLOUR)],
        &ExactMatch,
        &query(
            "cake",
            &[("egg", "cracked"), ("syrup", "liquid"), ("flour", "powder")],
        ),
    );
    let motions = line_motions(&p, "flour");
    assert!(motions.contains(&"bake"), "{motions:?}\n{:#?}", p.units);
    assert!(
        !motions.contains(&"cook"),
        "flour is not cooked on its own: {motions:?}"
    );
    assert_eq!(kinds(&p), []);
}

#[test]
fn an_onion_named_only_whole_veg_is_chopped_as_a_cook_would() {
    let p = plan_of(
        &[("salad.txt", LETTUCE_SALAD), ("prep.txt", PREPARED)],
        &ExactMatch,
        &query("salad", &[("lettuce", "chopped"), ("onion", "whole veg")]),
    );
    assert_eq!(
        line_motions(&p, "onion"),
        ["peel", "chop", "mix"],
        "{:#?}",
        p.units
    );
    let reason = outcome(&p, "onion").reason.as_deref().unwrap();
    assert!(
        reason.contains("'whole veg' names only what onion is: made 'chopped'"),
        "{reason}"
    );
    assert_eq!(kinds(&p), []);
}

#[test]
fn an_onion_asked_whole_in_the_tree_is_cautioned_as_left_whole() {
    let salad = LETTUCE_SALAD.replace("S\tchopped\nM", "S\tchopped\nO\tonion\t1\nS\twhole\nM");
    let salad = salad.replace("{lettuce}", "{lettuce,onion}");
    let p = plan_of(
        &[("salad.txt", &salad)],
        &ExactMatch,
        &query("salad", &[("lettuce", "chopped"), ("onion", "whole")]),
    );
    assert_eq!(kinds(&p), [CautionKind::LeftWhole]);
}

/// An omelette (class 23): the egg cracked into white and yolk, beaten back into egg, cooked in a pan.
const OMELETTE: &str = "//
O\tbowl\t0
S\tempty
O\tegg\t1
S\twhole
M\tcrack\t<Assumed>
O\tegg white\t1
S\tin\t[bowl]
O\tegg yolk\t1
S\tin\t[bowl]
//
O\tegg white\t1
S\tin\t[bowl]
O\tegg yolk\t1
S\tin\t[bowl]
O\twhisk\t1
M\tbeat\t<Assumed>
O\tegg\t1
S\tbeaten
S\tin\t[bowl]
//
O\tegg\t1
S\tbeaten
S\tin\t[bowl]
O\tpan\t0
S\thot
M\tcook\t<Assumed>
O\tomelette\t1\t23
S\tcooked
S\tcontains\t{egg}
//
";

#[test]
fn an_egg_beaten_back_into_egg_is_followed_on_into_the_omelette() {
    let p = plan_of(
        &[("omelette.txt", OMELETTE)],
        &ExactMatch,
        &query("omelette", &[("egg", "whole")]),
    );
    let line = &p.progress_lines[0];
    assert_eq!(line.end_product, "omelette", "{line:#?}");
    assert_eq!(line_motions(&p, "egg"), ["crack", "beat", "cook"]);
    assert_eq!(kinds(&p), []);
}

/// A soup (class 1): tomato poured into a pot, cooked into soup, simmered into tomato soup; FOON's pot
/// still lists the soup it no longer holds.
const TOMATO_SOUP: &str = "//
O\tpot\t0
S\tempty
O\ttomato\t1
S\tchopped
M\tpour\t<Assumed>
O\tpot\t0
S\tcontains\t{tomato}
O\tsoup\t1
S\tcontains\t{tomato}
S\tin\t[pot]
//
O\tpot\t0
S\tcontains\t{tomato}
O\tsoup\t1
S\tcontains\t{tomato}
S\tin\t[pot]
M\tsimmer\t<Assumed>
O\tpot\t0
S\tcontains\t{soup}
O\ttomato soup\t1\t1
S\tcooked
S\tcontains\t{tomato}
S\tin\t[pot]
//
";

#[test]
fn a_soup_simmered_into_another_is_followed_though_the_pot_still_lists_it() {
    let p = plan_of(
        &[("soup.txt", TOMATO_SOUP)],
        &ExactMatch,
        &query("soup", &[("tomato", "chopped")]),
    );
    let line = &p.progress_lines[0];
    assert_eq!(line.end_product, "tomato soup", "{line:#?}");
    assert_eq!(kinds(&p), []);
}

/// A soup FOON leaves "partly cooked" in the hot pot where the flour is whisked in, and calls "cooked"
/// only once it is ladled into the bowl.
const WHISKED_SOUP: &str = "//
O\tpot\t0
S\tcontains\t{broth}
S\thot
O\tflour\t1
S\tpowder
O\twhisk\t1
M\tpour and mix\t<Assumed>
O\tpot\t0
S\tcontains\t{broth,flour}
O\tpotato soup\t1
S\tcontains\t{broth,flour}
S\tpartly cooked
S\tin\t[pot]
//
O\tpotato soup\t1
S\tcontains\t{broth,flour}
S\tpartly cooked
S\tin\t[pot]
O\tbowl\t0
S\tempty
O\tladle\t1
M\tscoop and pour\t<Assumed>
O\tpotato soup\t1\t1
S\tcontains\t{broth,flour}
S\tcooked
S\tin\t[bowl]
//
";

#[test]
fn a_soup_left_partly_cooked_in_its_pot_is_cooked_there_before_it_is_ladled() {
    let p = plan_of(
        &[("soup.txt", WHISKED_SOUP)],
        &ExactMatch,
        &query("soup", &[("flour", "ground")]),
    );
    let motions: Vec<&str> = p.units.iter().map(|u| u.motion.as_str()).collect();
    assert_eq!(
        motions,
        ["pour and mix", "cook", "scoop and pour"],
        "{:#?}",
        p.units
    );
    assert_eq!(kinds(&p), [], "{:#?}", p.progress_lines);
}

/// A cake of lemon zest: the lemon grated beside its zest, which nothing takes but the zest it lists.
const ZESTED_CAKE: &str = "//
O\tlemon\t1
S\twhole
O\tgrater\t1
O\tbowl\t0
S\tempty
M\tgrate\t<Assumed>
O\tlemon\t1
S\tgrated
O\tlemon zest\t1
S\tcontains\t{lemon}
S\tin\t[bowl]
//
O\tlemon zest\t1
S\tcontains\t{lemon}
S\tin\t[bowl]
O\tflour\t1
S\tpowder
M\tmix\t<Assumed>
O\tlemon cake\t1\t5
S\tcontains\t{flour,lemon zest}
S\tin\t[bowl]
//
";

#[test]
fn a_food_grated_into_its_zest_is_followed_into_the_dish() {
    let p = plan_of(
        &[("cake.txt", ZESTED_CAKE)],
        &ExactMatch,
        &query("cake", &[("lemon", "whole"), ("flour", "ground")]),
    );
    assert_eq!(line_motions(&p, "lemon"), ["grate", "mix", "cook"]);
    assert_eq!(kinds(&p), [], "{:#?}", p.progress_lines);
}

/// Rice cooked with garlic in it, FOON's node of the cooked rice listing the garlic, then served.
const GARLIC_RICE: &str = "//
O\tpot\t0
S\tempty
O\tgarlic\t1
S\tminced
O\trice\t1
S\tuncooked
M\tcook\t<Assumed>
O\trice\t1
S\tcontains\t{garlic}
S\tcooked
S\tin\t[pot]
//
O\trice\t1
S\tcontains\t{garlic}
S\tcooked
S\tin\t[pot]
O\tplate\t0
S\tempty
M\tscoop and pour\t<Assumed>
O\tgarlic rice\t1\t19
S\tcontains\t{rice}
S\ton\t[plate]
//
";

#[test]
fn a_food_made_under_a_pruned_ingredients_name_stays_as_what_the_others_go_on_in() {
    let p = plan_of(
        &[("rice.txt", GARLIC_RICE)],
        &ExactMatch,
        &query("rice", &[("garlic", "minced")]),
    );
    assert_eq!(line_motions(&p, "garlic"), ["cook", "scoop and pour"]);
    assert_eq!(kinds(&p), [], "{:#?}", p.progress_lines);
    assert_eq!(p.removed, ["rice"]);
}

/// Banana bread: the banana mashed as FOON has it, with no peeling.
const BANANA_BREAD: &str = "//
O\tbanana\t1
S\twhole
O\tfork\t1
M\tmash\t<Assumed>
O\tbanana\t1
S\tmashed
//
O\tbanana\t1
S\tmashed
O\tflour\t1
S\tpowder
M\tmix\t<Assumed>
O\tbanana bread\t1\t0
S\tcontains\t{banana,flour}
S\tbaked
//
";

#[test]
fn a_banana_is_peeled_before_it_is_mashed() {
    let p = plan_of(
        &[("bread.txt", BANANA_BREAD)],
        &ExactMatch,
        &query("bread", &[("banana", "whole"), ("flour", "ground")]),
    );
    assert_eq!(line_motions(&p, "banana")[..2], ["peel", "mash"]);
}

/// Pancakes: an egg cracked into the flour; elsewhere in FOON an egg is whipped.
const EGG_PANCAKE: &str = "//
O\tegg\t1
S\twhole
O\tbowl\t0
S\tcontains\t{flour}
O\tflour\t1
S\tpowder
S\tin\t[bowl]
M\tcrack\t<Assumed>
O\tpancake batter\t1
S\tcontains\t{egg,flour}
S\tin\t[bowl]
//
O\tpancake batter\t1
S\tcontains\t{egg,flour}
S\tin\t[bowl]
M\tfry\t<Assumed>
O\tpancake\t1\t5
S\tcontains\t{egg,flour}
S\tcooked
//
";
const WHIPPED_EGG: &str = "//
O\tegg\t1
S\tcracked
S\tin\t[bowl]
O\twhisk\t1
M\tbeat\t<Assumed>
O\tegg\t1
S\twhipped
S\tin\t[bowl]
//
";

#[test]
fn a_name_asked_whole_and_prepared_has_one_line_through_both() {
    let files = [("pancake.txt", EGG_PANCAKE), ("egg.txt", WHIPPED_EGG)];
    let asked = [
        ("egg", "whole raw"),
        ("egg", "whipped"),
        ("flour", "ground"),
    ];
    let p = plan_of(&files, &ExactMatch, &query("cake", &asked));
    assert!(
        line_motions(&p, "egg").contains(&"beat"),
        "{:#?}",
        p.progress_lines
    );
}

/// A cake: the batter mixed, poured into the baking tray, baked; elsewhere oil is poured from its bottle.
const TRAY_CAKE: &str = "//
O\tbowl\t0
S\tempty
O\tflour\t1
S\tpowder
M\tmix\t<Assumed>
O\tbatter\t1
S\tcontains\t{flour}
S\tin\t[bowl]
//
O\tbatter\t1
S\tcontains\t{flour}
S\tin\t[bowl]
O\tbaking tray\t0
S\tempty
M\tpour\t<Assumed>
O\tbaking tray\t0
S\tcontains\t{batter}
O\tbatter\t1
S\tcontains\t{flour}
S\tin\t[baking tray]
//
O\tbatter\t1
S\tcontains\t{flour}
S\tin\t[baking tray]
O\toven\t0
S\ton
M\tbake\t<Assumed>
O\tcake\t1\t5
S\tbaked
S\tcontains\t{flour}
S\tin\t[baking tray]
//
O\tvegetable oil\t1
S\tliquid
S\tin\t[bottle]
O\tpan\t0
S\tempty
M\tpour\t<Assumed>
O\tpan\t0
S\tcontains\t{vegetable oil}
//
";

#[test]
fn cooking_spray_greases_the_tray_the_cake_bakes_in_rather_than_joining_the_batter() {
    let asked = [("flour", "ground"), ("cooking spray", "liquid")];
    let request = query("cake", &asked).replacen(
        '{',
        r#"{"overrides": {"cooking spray": "vegetable oil"}, "#,
        1,
    );
    let p = plan_of(&[("cake.txt", TRAY_CAKE)], &ExactMatch, &request);
    assert_eq!(line_motions(&p, "cooking spray"), ["spray", "pour", "bake"]);
    let mix = p.units.iter().find(|u| u.motion == "mix").unwrap();
    assert!(mix.inputs.iter().all(|n| n.label != "cooking spray"));
    assert_eq!(kinds(&p), [], "{:#?}", p.progress_lines);
}

#[test]
fn a_raw_potato_is_cooked_before_it_is_mashed() {
    let potato_bread = BANANA_BREAD.replace("banana", "potato");
    let p = plan_of(
        &[("bread.txt", &potato_bread)],
        &ExactMatch,
        &query("bread", &[("potato", "whole"), ("flour", "ground")]),
    );
    let motions = line_motions(&p, "potato");
    assert!(foon_core::vocab::foods::cooks(motions[0]), "{motions:?}");
    assert_eq!(motions[1], "mash");
}

/// An omelette slid out of its pan, which FOON then has "empty" as it was before it was heated; elsewhere
/// cream is poured from its carton.
const SLID_OMELETTE: &str = "//
O\tcooking pan\t0
S\tempty
M\theat\t<Assumed>
O\tcooking pan\t0
S\thot
//
O\tegg\t1
S\tbeaten
S\tin\t[bowl]
O\tcooking pan\t0
S\thot
M\tpour\t<Assumed>
O\tcooking pan\t0
S\tcontains\t{egg}
S\thot
O\tegg\t1
S\tbeaten
S\tin\t[cooking pan]
//
O\tegg\t1
S\tbeaten
S\tin\t[cooking pan]
M\tcook\t<Assumed>
O\tomelette\t1
S\tcontains\t{egg}
S\tcooked
S\tin\t[cooking pan]
//
O\tomelette\t1
S\tcontains\t{egg}
S\tcooked
S\tin\t[cooking pan]
O\tcooking pan\t0
S\tcontains\t{egg}
S\thot
O\tplate\t0
S\tempty
M\tpour\t<Assumed>
O\tomelette\t1\t23
S\tcontains\t{egg}
S\tcooked
S\ton\t[plate]
O\tcooking pan\t0
S\tempty
//
O\tcream\t1
S\tcreamy
S\tin\t[carton]
O\tbowl\t0
S\tempty
M\tpour\t<Assumed>
O\tbowl\t0
S\tcontains\t{cream}
//
";

#[test]
fn cream_joins_the_eggs_before_they_cook_not_the_plated_omelette() {
    let asked = [("egg", "beaten"), ("cream", "creamy")];
    let p = plan_of(
        &[("omelette.txt", SLID_OMELETTE)],
        &ExactMatch,
        &query("omelette", &asked),
    );
    assert!(
        line_motions(&p, "cream").contains(&"cook"),
        "{:#?}",
        p.progress_lines
    );
}

#[test]
fn a_powder_squeezed_is_cautioned() {
    let squeezed = "//
O\tsugar\t1
S\tgranulated
O\tbowl\t0
S\tempty
M\tsqueeze\t<Assumed>
O\tsweet salad\t1\t15
S\tcontains\t{sugar}
S\tin\t[bowl]
//
";
    let p = plan_of(
        &[("salad.txt", squeezed)],
        &ExactMatch,
        &query("salad", &[("sugar", "granulated")]),
    );
    let found = cautions(&p);
    assert_eq!(found.len(), 1, "{found:#?}");
    assert_eq!(found[0].kind, CautionKind::MotionOnForm);
    assert_eq!(found[0].detail, "sugar cannot be 'squeeze'");
}

/// Fried rice (class 19): soy sauce mixed into a sauce, stirred into the rice in the pan; FOON's pan
/// lists the sauce, and the fried rice takes it in.
const FRIED_RICE: &str = "//
O\tfrying pan\t0
S\tempty
O\trice\t1
S\tcooked
M\tpour\t<Assumed>
O\tfrying pan\t0
S\tcontains\t{rice}
O\tfried rice\t1
S\tcontains\t{rice}
S\tin\t[frying pan]
//
O\tbowl\t0
S\tempty
O\tsoy sauce\t1
S\tliquid
M\tmix\t<Assumed>
O\tsauce\t1
S\tmixed
S\tcontains\t{soy sauce}
S\tin\t[bowl]
//
O\tfrying pan\t0
S\tcontains\t{rice}
O\tfried rice\t1
S\tcontains\t{rice}
S\tin\t[frying pan]
O\tsauce\t1
S\tmixed
S\tcontains\t{soy sauce}
S\tin\t[bowl]
M\tcook and stir\t<Assumed>
O\tfrying pan\t0
S\tcontains\t{fried rice,sauce}
O\tfried rice\t1
S\tcooked
S\tcontains\t{rice,soy sauce}
S\tin\t[frying pan]
//
O\tfried rice\t1
S\tcooked
S\tcontains\t{rice,soy sauce}
S\tin\t[frying pan]
O\tplate\t0
S\tempty
M\tpick-and-place\t<Assumed>
O\tegg fried rice\t1\t19
S\tcontains\t{rice,soy sauce}
S\ton\t[plate]
//
";

#[test]
fn a_sauce_stirred_into_the_rice_is_followed_into_the_dish() {
    let p = plan_of(
        &[("rice.txt", FRIED_RICE)],
        &ExactMatch,
        &query("rice", &[("rice", "cooked"), ("soy sauce", "liquid")]),
    );
    let line = p
        .progress_lines
        .iter()
        .find(|l| l.ingredient == "soy sauce")
        .unwrap();
    // the reference's "egg fried rice" holds no egg here: the dish is named for what it holds
    assert_eq!(line.end_product, "fried rice", "{line:#?}");
    assert_eq!(kinds(&p), []);
}

/// A salad (class 15) of lettuce poured into a bowl, croutons then placed on it.
const CROUTON_SALAD: &str = "//
O\tbowl\t0
S\tempty
O\tlettuce\t1
S\tchopped
M\tpour\t<Assumed>
O\tsalad base\t1
S\tcontains\t{lettuce}
S\tin\t[bowl]
//
O\tsalad base\t1
S\tcontains\t{lettuce}
S\tin\t[bowl]
O\tcrouton\t1
S\ttoasted
M\tpick-and-place\t<Assumed>
O\tcrouton salad\t1\t15
S\tcontains\t{crouton,lettuce}
S\tin\t[bowl]
//
";

/// Olive oil as bought, in a recipe of its own.
const OIL: &str = "//
O\tolive oil\t1
S\tliquid
S\tin\t[bottle]
O\tcup\t0
S\tempty
M\tpour\t<Assumed>
O\tolive oil\t1
S\tliquid
S\tin\t[cup]
//
";

#[test]
fn oil_is_poured_in_where_the_salad_takes_liquids_not_placed_with_the_croutons() {
    let p = plan_of(
        &[("salad.txt", CROUTON_SALAD), ("oil.txt", OIL)],
        &ExactMatch,
        &query(
            "salad",
            &[
                ("lettuce", "chopped"),
                ("crouton", "toasted"),
                ("olive oil", "liquid"),
            ],
        ),
    );
    let reason = outcome(&p, "olive oil").reason.as_deref().unwrap();
    assert!(reason.ends_with("added at 'pour'"), "{reason}");
}

/// An omelette (class 23) whose cracked egg FOON lists only as the bowl's egg white and yolk.
const CRACKED_INTO_BOWL: &str = "//
O\tbowl\t0
S\tempty
O\tegg\t1
S\twhole
M\tcrack\t<Assumed>
O\tbowl\t0
S\tcontains\t{egg white,egg yolk}
//
O\tbowl\t0
S\tcontains\t{egg white,egg yolk}
O\tfork\t1
M\tbeat\t<Assumed>
O\tegg\t1
S\tbeaten
S\tin\t[bowl]
//
O\tegg\t1
S\tbeaten
S\tin\t[bowl]
O\tpan\t0
S\thot
M\tfry\t<Assumed>
O\tplain omelette\t1\t23
S\tcooked
S\tcontains\t{egg}
//
";

#[test]
fn an_egg_the_bowl_lists_as_white_and_yolk_is_followed_into_the_omelette() {
    let p = plan_of(
        &[("omelette.txt", CRACKED_INTO_BOWL)],
        &ExactMatch,
        &query("omelette", &[("egg", "whole")]),
    );
    assert_eq!(line_motions(&p, "egg"), ["crack", "beat", "fry"]);
    assert_eq!(kinds(&p), []);
}

/// A soup (class 1): chicken put into a pot, the pot boiled, the soup poured out of it.
const CHICKEN_POT: &str = "//
O\tpot\t0
S\tempty
O\tchicken breast\t1
S\tsliced
M\tpick-and-place\t<Assumed>
O\tpot\t0
S\tcontains\t{chicken breast}
//
O\tpot\t0
S\tcontains\t{chicken breast}
O\tstove\t0
S\ton
M\tboil\t<Assumed>
O\tpot\t0
S\tcontains\t{chicken breast}
S\tcooked
//
O\tpot\t0
S\tcontains\t{chicken breast}
S\tcooked
O\tbowl\t0
S\tempty
M\tpour\t<Assumed>
O\tchicken soup\t1\t1
S\tcontains\t{chicken breast}
S\tin\t[bowl]
//
";

#[test]
fn food_cooked_in_its_pot_is_cooked_in_its_progress_line() {
    let p = plan_of(
        &[("soup.txt", CHICKEN_POT)],
        &ExactMatch,
        &query("soup", &[("chicken breast", "sliced")]),
    );
    let line = &p.progress_lines[0];
    let states: Vec<&str> = line
        .state
        .iter()
        .map(|s| s.physical_state.as_str())
        .collect();
    assert!(states.contains(&"sliced, cooked"), "{line:#?}");
    assert_eq!(
        line_motions(&p, "chicken breast"),
        ["pick-and-place", "boil", "pour"]
    );
    assert_eq!(kinds(&p), []);
}

/// A salad (class 15): tofu coated with flour ("floured {flour}"), fried, tossed with lettuce.
const FLOURED: &str = "//
O\tflour\t1
S\tpowder
O\ttofu\t1
S\tcubed
M\tcoat\t<Assumed>
O\ttofu\t1
S\tcubed
S\tfloured\t{flour}
//
O\ttofu\t1
S\tcubed
S\tfloured\t{flour}
O\tpan\t0
S\thot
M\tfry\t<Assumed>
O\ttofu\t1
S\tfried
//
O\ttofu\t1
S\tfried
O\tlettuce\t1
S\tchopped
M\tmix\t<Assumed>
O\ttofu salad\t1\t15
S\tcontains\t{lettuce,tofu}
//
";

#[test]
fn flour_coating_a_food_goes_on_with_that_food() {
    let p = plan_of(
        &[("salad.txt", FLOURED)],
        &ExactMatch,
        &query(
            "salad",
            &[
                ("flour", "powder"),
                ("tofu", "cubed"),
                ("lettuce", "chopped"),
            ],
        ),
    );
    assert_eq!(
        line_motions(&p, "flour"),
        ["coat", "fry", "mix"],
        "{:#?}",
        p.progress_lines
    );
    assert_eq!(kinds(&p), []);
}

#[test]
fn an_onion_asked_peeled_is_still_chopped_before_it_joins_the_salad() {
    let p = plan_of(
        &[("salad.txt", LETTUCE_SALAD), ("prep.txt", PREPARED)],
        &ExactMatch,
        &query("salad", &[("lettuce", "chopped"), ("onion", "peeled")]),
    );
    assert_eq!(
        line_motions(&p, "onion"),
        ["peel", "chop", "mix"],
        "{:#?}",
        p.units
    );
    let reason = outcome(&p, "onion").reason.as_deref().unwrap();
    assert!(
        reason.contains("'chop' to make it 'chopped', as a cook would"),
        "{reason}"
    );
    assert_eq!(kinds(&p), []);
}

/// Elsewhere in FOON: an egg placed in a bowl as it is, a walnut cracked, milk blended thick.
const EGG_AND_MOTIONS: &str = "//
O\tbowl\t0
S\tempty
O\tegg\t1
S\tuncracked
M\tpick-and-place\t<Assumed>
O\tegg\t1
S\tuncracked
S\tin\t[bowl]
//
O\twalnut\t1
S\twhole
O\tnutcracker\t1
M\tcrack\t<Assumed>
O\twalnut\t1
S\tcracked
//
O\tmilk\t1
S\tliquid
O\tblender\t0
S\ton
M\tblend\t<Assumed>
O\tmilk\t1
S\tthick liquid
//
";

#[test]
fn an_egg_is_cracked_before_it_is_blended() {
    let p = plan_of(
        &[("salad.txt", LETTUCE_SALAD), ("egg.txt", EGG_AND_MOTIONS)],
        &ExactMatch,
        &query("salad", &[("lettuce", "chopped"), ("egg", "thick liquid")]),
    );
    let motions = line_motions(&p, "egg");
    let crack = motions.iter().position(|m| *m == "crack");
    let blend = motions.iter().position(|m| *m == "blend");
    assert!(
        crack.is_some() && crack < blend,
        "{motions:?}\n{:#?}",
        p.units
    );
}

/// A broth stirred in a pot, an egg cracked into it, noodles cooked in it and ladled with it into a
/// bowl as the ramen (class 14), the way FOON's ramen is made: the broth is a food of its own that the
/// pot holds, and the ladle leaves a second node of it in the bowl.
const BROTH_RAMEN: &str = "//
O\tpot\t0
S\ton\t[stove]
O\tgarlic\t1
S\tchopped
S\tin\t[bowl]
M\tpour\t<Assumed>
O\tpot\t0
S\tcontains\t{garlic}
S\ton\t[stove]
//
O\tpot\t0
S\tcontains\t{garlic}
S\ton\t[stove]
O\twater\t1
S\tin\t[measuring cup]
M\tpour\t<Assumed>
O\tpot\t0
S\tcontains\t{garlic,water}
S\ton\t[stove]
//
O\tpot\t0
S\tcontains\t{garlic,water}
S\ton\t[stove]
O\tspoon\t1
M\tstir\t<Assumed>
O\tpot\t0
S\tcontains\t{soup broth}
S\ton\t[stove]
O\tsoup broth\t0
S\tcontains\t{garlic,water}
S\tin\t[pot]
//
O\tpot\t0
S\tcontains\t{soup broth}
S\ton\t[stove]
O\tsoup broth\t0
S\tcontains\t{garlic,water}
S\tin\t[pot]
O\tegg\t1
S\tuncracked
M\tcrack\t<Assumed>
O\tpot\t0
S\tcontains\t{soup broth,egg white and yolk}
S\ton\t[stove]
//
O\tpot\t0
S\tcontains\t{soup broth,egg white and yolk}
S\ton\t[stove]
O\tnoodle\t1
S\tuncooked
M\tpick-and-place\t<Assumed>
O\tpot\t0
S\tcontains\t{soup broth,egg white and yolk,noodle}
S\ton\t[stove]
//
O\tpot\t0
S\tcontains\t{soup broth,egg white and yolk,noodle}
S\ton\t[stove]
M\tcook\t<Assumed>
O\tpot\t0
S\tcontains\t{soup broth,egg white and yolk,noodle}
S\tcooked
S\ton\t[stove]
//
O\tpot\t0
S\tcontains\t{soup broth,egg white and yolk,noodle}
S\tcooked
S\ton\t[stove]
O\tladle\t1
M\tscoop and pour\t<Assumed>
O\tramen\t1\t14
S\tcontains\t{soup broth,egg white and yolk,noodle}
S\tin\t[bowl]
O\tsoup broth\t1
S\tin\t[bowl]
//
";

#[test]
fn what_is_stirred_into_a_broth_reaches_the_ramen_and_an_egg_not_asked_leaves_no_crack() {
    let p = plan_of(
        &[("ramen.txt", BROTH_RAMEN)],
        &ExactMatch,
        &query(
            "noodle",
            &[
                ("garlic", "chopped"),
                ("water", "liquid"),
                ("noodle", "uncooked"),
            ],
        ),
    );
    for food in ["garlic", "water", "noodle"] {
        let line = p
            .progress_lines
            .iter()
            .find(|l| l.ingredient == food)
            .unwrap();
        let last = line.state.last().unwrap();
        assert_eq!(
            (line.end_product.as_str(), last.physical_state.as_str()),
            ("ramen", "in ramen"),
            "{food}: {line:#?}"
        );
        // cooked with the noodles in the broth's pot
        assert!(line.motion.iter().any(|m| m == "cook"), "{food}: {line:?}");
    }
    assert!(
        p.units.iter().all(|u| u.motion != "crack"),
        "{:#?}",
        p.units
    );
    assert!(
        p.units.iter().all(|u| u
            .outputs
            .iter()
            .chain(&u.inputs)
            .all(|n| n.label != "egg white and yolk"
                && n.states.iter().all(|s| !s.contains("egg white and yolk")))),
        "{:#?}",
        p.units
    );
    assert_eq!(kinds(&p), []);
}

/// Ground pepper from a shaker and a bell pepper sliced, as FOON has them.
const PEPPERS: &str = "//
O\tpepper\t1
S\tground
S\tin\t[shaker]
M\tsprinkle\t<Assumed>
O\tpepper\t1
S\tground
S\tin\t[salad bowl]
//
O\tbell pepper\t1
S\twhole
O\tknife\t1
M\tslice\t<Assumed>
O\tbell pepper\t1
S\tsliced
//
";

#[test]
fn a_pepper_asked_diced_is_a_fresh_pepper_and_one_asked_ground_is_the_shakers() {
    let files = [("salad.txt", LETTUCE_SALAD), ("peppers.txt", PEPPERS)];
    let diced = plan_of(
        &files,
        &ExactMatch,
        &query("salad", &[("lettuce", "chopped"), ("pepper", "diced")]),
    );
    let o = outcome(&diced, "pepper");
    assert_eq!(o.matched.as_ref().unwrap().label, "bell pepper", "{o:?}");
    assert!(
        o.reason
            .as_deref()
            .unwrap()
            .contains("read as 'bell pepper'"),
        "{o:?}"
    );
    assert!(
        line_motions(&diced, "pepper").contains(&"slice"),
        "{:#?}",
        diced.progress_lines
    );
    let ground = plan_of(
        &files,
        &ExactMatch,
        &query("salad", &[("lettuce", "chopped"), ("pepper", "ground")]),
    );
    let o = outcome(&ground, "pepper");
    assert_eq!(o.matched.as_ref().unwrap().label, "pepper", "{o:?}");
}

/// Elsewhere in FOON: a potato peeled (the motion for "peeled"), a lemon sliced.
const PEELING: &str = "//
O\tpotato\t1
S\twhole
O\tpeeler\t1
M\tpeel\t<Assumed>
O\tpotato\t1
S\tpeeled
//
O\tlemon\t1
S\twhole
O\tknife\t1
S\tclean
M\tslice\t<Assumed>
O\tlemon\t1
S\tsliced
//
";

#[test]
fn an_onion_is_peeled_before_it_is_chopped_and_a_lemon_is_sliced_in_its_rind() {
    let kb = [
        ("salad.txt", LETTUCE_SALAD),
        ("prep.txt", PREPARED),
        ("peel.txt", PEELING),
    ];
    let p = plan_of(
        &kb,
        &ExactMatch,
        &query(
            "salad",
            &[
                ("lettuce", "chopped"),
                ("onion", "whole veg"),
                ("lemon", "whole"),
            ],
        ),
    );
    assert_eq!(
        line_motions(&p, "onion"),
        ["peel", "chop", "mix"],
        "{:#?}",
        p.units
    );
    assert!(outcome(&p, "onion")
        .reason
        .as_deref()
        .unwrap()
        .contains("peeled before it is used"));
    assert_eq!(
        line_motions(&p, "lemon"),
        ["slice", "mix"],
        "{:#?}",
        p.units
    );
}

/// Fresh egg noodles (class 14): an egg and flour mixed into a dough, cut into noodles; `last` is the
/// motion that makes the noodles from the dough.
fn egg_noodles(last: &str) -> String {
    format!(
        "//
O\tbowl\t0
S\tempty
O\tegg\t1
S\tcracked
O\tflour\t1
S\tpowder
M\tmix\t<Assumed>
O\tbowl\t0
S\tcontains\t{{dough}}
O\tdough\t1
S\tcontains\t{{egg,flour}}
S\tin\t[bowl]
//
O\tdough\t1
S\tcontains\t{{egg,flour}}
S\tin\t[bowl]
O\tknife\t1
S\tclean
M\t{last}\t<Assumed>
O\tegg noodle\t1\t14
S\tcontains\t{{egg,flour}}
//
"
    )
}

#[test]
fn noodles_made_raw_from_egg_and_flour_are_cooked_last_and_boiled_ones_are_not() {
    let ask = query("noodle", &[("egg", "cracked"), ("flour", "powder")]);
    let p = plan_of(&[("noodles.txt", &egg_noodles("cut"))], &ExactMatch, &ask);
    let last = p.units.last().unwrap();
    assert_eq!(
        (last.motion.as_str(), last.inputs[0].label.as_str()),
        ("cook", "egg noodle"),
        "{:#?}",
        p.units
    );
    assert_eq!(p.goal.states, ["cooked"]);
    assert_eq!(
        line_motions(&p, "egg"),
        ["mix", "cut", "cook"],
        "{:#?}",
        p.progress_lines
    );
    assert!(
        p.notes
            .iter()
            .any(|n| n.contains("'egg noodle' is cooked last")),
        "{:?}",
        p.notes
    );
    assert_eq!(kinds(&p), []);
    // noodles the recipe cooks itself get no second cooking
    let p = plan_of(&[("noodles.txt", &egg_noodles("boil"))], &ExactMatch, &ask);
    assert_eq!(p.units.last().unwrap().motion, "boil", "{:#?}", p.units);
    assert!(
        p.notes.iter().all(|n| !n.contains("cooked last")),
        "{:?}",
        p.notes
    );
}

/// A noodle casserole (class 14) of bought noodles, cheese and milk.
const NOODLE_CASSEROLE: &str = "//
O\tbowl\t0
S\tempty
O\tnoodle\t1
S\tcooked
O\tcheese\t1
S\tgrated
O\tmilk\t1
S\tliquid
M\tmix\t<Assumed>
O\tbowl\t0
S\tcontains\t{noodle casserole}
O\tnoodle casserole\t1\t14
S\tcontains\t{cheese,milk,noodle}
S\tin\t[bowl]
//
";

#[test]
fn a_query_bringing_noodles_starts_from_a_dish_of_noodles_not_from_noodles_made_from_scratch() {
    let kb = [
        ("noodles.txt", egg_noodles("cut")),
        ("casserole.txt", NOODLE_CASSEROLE.to_string()),
    ];
    let kb: Vec<(&str, &str)> = kb.iter().map(|(n, t)| (*n, t.as_str())).collect();
    // egg noodles fit egg and flour better (nothing of theirs left unused), but make the noodles asked for
    let ask = query(
        "noodle",
        &[
            ("noodle", "cooked"),
            ("egg", "cracked"),
            ("flour", "powder"),
            ("cheese", "grated"),
        ],
    );
    assert_eq!(
        plan_of(&kb, &ExactMatch, &ask).goal.reference,
        "noodle casserole"
    );
    let ask = query(
        "noodle",
        &[
            ("egg", "cracked"),
            ("flour", "powder"),
            ("cheese", "grated"),
        ],
    );
    assert_eq!(plan_of(&kb, &ExactMatch, &ask).goal.reference, "egg noodle");
}

/// A salad of lettuce and ground sesame; elsewhere oil sold without a state word.
const SESAME_SALAD: &str = "//
O\tsalad bowl\t0
S\tempty
O\tlettuce\t1
S\tchopped
O\tsesame seed\t1
S\tground
S\tpowder
O\toil\t1
S\tin\t[bottle]
M\tmix\t<Assumed>
O\tsesame salad\t1\t15
S\tcontains\t{lettuce,oil,sesame seed}
S\tin\t[salad bowl]
//
";

#[test]
fn a_paste_in_for_a_ground_seed_is_not_called_a_powder_and_oil_is_shown_liquid() {
    let ask = query(
        "salad",
        &[("lettuce", "chopped"), ("tahini", ""), ("oil", "")],
    )
    .replace("]}}", r#"]}, "overrides": {"tahini": "sesame seed"}}"#);
    let p = plan_of(&[("salad.txt", SESAME_SALAD)], &ExactMatch, &ask);
    let first = |food: &str| {
        let line = p
            .progress_lines
            .iter()
            .find(|l| l.ingredient == food)
            .unwrap();
        line.state[0].physical_state.clone()
    };
    assert_eq!(first("tahini"), "paste", "{:#?}", p.progress_lines);
    assert_eq!(first("oil"), "liquid");
    assert_eq!(first("lettuce"), "chopped");
}

#[test]
fn whole_spices_are_not_chopped_and_an_orange_keeps_its_skin_to_be_grated() {
    assert!(!foon_core::vocab::foods::takes("nutmeg", "chop"));
    assert!(foon_core::vocab::foods::takes("nutmeg", "grate"));
    assert!(!foon_core::vocab::foods::cuts("grate") && foon_core::vocab::foods::cuts("slice"));
}

/// Fried rice (class 19): an egg fried in a pan with oil; elsewhere in FOON rice is boiled.
const EGG_FRIED_RICE: &str = "//
O\tfrying pan\t0
S\tempty
O\toil\t1
S\tliquid
O\tegg\t1
S\tcracked
M\tcook and stir\t<Assumed>
O\tfrying pan\t0
S\tcontains\t{fried rice}
O\tfried rice\t1\t19
S\tcontains\t{egg,oil}
S\tin\t[frying pan]
//
O\trice\t1
S\tuncooked
O\tpot\t0
S\tcontains\t{water}
M\tboil\t<Assumed>
O\trice\t1
S\tcooked
S\tin\t[pot]
//
";

#[test]
fn rice_asked_in_a_cooked_word_no_recipe_makes_is_cooked_before_it_is_fried() {
    // the recipe data's "baked" rice is cooked rice: boiled, then stir-fried, never fried raw
    let p = plan_of(
        &[("fried_rice.txt", EGG_FRIED_RICE)],
        &ExactMatch,
        &query(
            "rice",
            &[("egg", "cracked"), ("oil", "liquid"), ("rice", "baked")],
        ),
    );
    let motions = line_motions(&p, "rice");
    assert_eq!(motions.first(), Some(&"boil"), "{:#?}", p.progress_lines);
    assert!(motions.contains(&"cook and stir"), "{motions:?}");
    assert_eq!(outcome(&p, "rice").state, "baked");
}

#[test]
fn cherries_are_pitted_after_they_are_washed_and_before_they_join_the_salad() {
    let washed = "//
O\tcherry\t1
S\twhole
O\tsink\t0
S\ton
M\twash\t<Assumed>
O\tcherry\t1
S\twashed
S\twhole
//
";
    let p = plan_of(
        &[("salad.txt", LETTUCE_SALAD), ("wash.txt", washed)],
        &ExactMatch,
        &query("salad", &[("lettuce", "chopped"), ("cherry", "washed")]),
    );
    assert_eq!(
        line_motions(&p, "cherry"),
        ["wash", "pit", "mix"],
        "{:#?}",
        p.units
    );
    let line = p
        .progress_lines
        .iter()
        .find(|l| l.ingredient == "cherry")
        .unwrap();
    assert_eq!(line.state[2].physical_state, "pitted");
}

#[test]
fn a_peach_is_pitted_once_halved_and_frozen_strawberries_are_not_hulled() {
    let shake = "//
O\tpeach\t1
S\twhole
O\tcutting board\t0
S\tempty
M\tpick-and-place\t<Assumed>
O\tpeach\t1
S\twhole
S\ton\t[cutting board]
//
O\tpeach\t1
S\twhole
S\ton\t[cutting board]
O\tknife\t1
M\tslice\t<Assumed>
O\tpeach\t1
S\thalved
S\ton\t[cutting board]
//
O\tpeach\t1
S\thalved
S\ton\t[cutting board]
O\tstrawberry\t1
S\tfrozen
O\tblender\t0
S\ton
M\tblend\t<Assumed>
O\tpeach shake\t1\t9
S\tcontains\t{peach,strawberry}
//
";
    let ask = query("drinks", &[("peach", "halved"), ("strawberry", "frozen")]);
    let p = plan_of(&[("shake.txt", shake)], &ExactMatch, &ask);
    assert_eq!(
        line_motions(&p, "peach"),
        ["pick-and-place", "slice", "pit", "blend"],
        "{:#?}",
        p.units
    );
    assert_eq!(line_motions(&p, "strawberry"), ["blend"]);
}

/// The states of `food`'s progress line, as the plan shows them.
fn line_states<'p>(p: &'p Plan, food: &str) -> Vec<&'p str> {
    let line = p
        .progress_lines
        .iter()
        .find(|l| l.ingredient == food)
        .unwrap_or_else(|| panic!("no line for {food}: {:#?}", p.progress_lines));
    line.state
        .iter()
        .map(|s| s.physical_state.as_str())
        .collect()
}

#[test]
fn a_stone_comes_out_once_the_fruit_is_halved_not_after_it_is_sliced() {
    // a peach halved, then sliced, into a shake: pitted between the two cuts; cherries sliced whole
    // are pitted before the knife touches them
    let shake = "//
O\tpeach\t1
S\twhole
O\tknife\t1
M\tslice\t<Assumed>
O\tpeach\t1
S\thalved
//
O\tpeach\t1
S\thalved
O\tknife\t1
M\tslice\t<Assumed>
O\tpeach\t1
S\tsliced
//
O\tcherry\t1
S\twhole
O\tknife\t1
M\tslice\t<Assumed>
O\tcherry\t1
S\tsliced
//
O\tpeach\t1
S\tsliced
O\tcherry\t1
S\tsliced
O\tblender\t0
S\ton
M\tblend\t<Assumed>
O\tpeach shake\t1\t9
S\tcontains\t{cherry,peach}
//
";
    let ask = query("drinks", &[("peach", "sliced"), ("cherry", "sliced")]);
    let p = plan_of(&[("shake.txt", shake)], &ExactMatch, &ask);
    assert_eq!(
        line_motions(&p, "peach"),
        ["slice", "pit", "slice", "blend"],
        "{:#?}",
        p.units
    );
    assert_eq!(line_motions(&p, "cherry"), ["pit", "slice", "blend"]);
    assert_eq!(kinds(&p), []);
}

#[test]
fn an_egg_cracked_into_white_and_yolk_is_shown_cracked_not_in_its_white() {
    let p = plan_of(
        &[("omelette.txt", CRACKED_INTO_BOWL)],
        &ExactMatch,
        &query("omelette", &[("egg", "whole")]),
    );
    let states = line_states(&p, "egg");
    assert_eq!(states[1], "cracked", "{states:?}");
    assert!(
        states.iter().all(|s| !s.contains("egg white")),
        "{states:?}"
    );
}

#[test]
fn a_block_of_cheese_the_tree_pours_in_whole_is_grated_first() {
    // asked in the recipe data's coarse word "creamy": the cook grates the block before it goes in
    let omelette = "//
O\tegg\t1
S\tbeaten
O\tcheddar\t1
S\tblock
O\tfrying pan\t0
S\thot
M\tcook\t<Assumed>
O\tomelette\t1\t17
S\tcontains\t{cheddar,egg}
S\tin\t[frying pan]
//
O\tcheddar\t1
S\tblock
O\tgrater\t0
M\tgrate\t<Assumed>
O\tcheddar\t1
S\tgrated
//
";
    let ask = query("omelette", &[("egg", "beaten"), ("cheddar", "creamy")]);
    let p = plan_of(&[("omelette.txt", omelette)], &ExactMatch, &ask);
    assert_eq!(
        line_motions(&p, "cheddar"),
        ["grate", "cook"],
        "{:#?}",
        p.units
    );
    assert_eq!(line_states(&p, "cheddar")[1], "grated");
}

#[test]
fn uncooked_rice_joining_a_stir_fry_is_boiled_first_for_frying_does_not_cook_it() {
    let p = plan_of(
        &[("fried_rice.txt", EGG_FRIED_RICE)],
        &ExactMatch,
        &query(
            "rice",
            &[("egg", "cracked"), ("oil", "liquid"), ("rice", "grain")],
        ),
    );
    let motions = line_motions(&p, "rice");
    let boiled = motions.iter().position(|m| *m == "boil");
    let fried = motions.iter().position(|m| *m == "cook and stir");
    assert!(
        boiled.is_some() && boiled < fried,
        "{motions:?} {:#?}",
        p.units
    );
    assert_eq!(kinds(&p), []);
}

#[test]
fn an_ingredient_starts_from_its_shaker_not_from_the_pan_a_recipe_had_it_in() {
    // FOON has ground pepper both in a frying pan it was sprinkled into and in its shaker
    let elsewhere = "//
O\tblack pepper\t1
S\tground
S\tin\t[frying pan]
O\tegg\t1
S\tbeaten
S\tin\t[frying pan]
O\tfrying pan\t0
S\thot
M\tcook\t<Assumed>
O\tscrambled egg\t1\t17
S\tcontains\t{black pepper,egg}
//
O\tblack pepper\t1
S\tground
S\tin\t[shaker]
O\tsteak\t1
S\tcooked
M\tsprinkle\t<Assumed>
O\tsteak\t1
S\tcooked
S\tpeppered
//
";
    let p = plan_of(
        &[("salad.txt", LETTUCE_SALAD), ("other.txt", elsewhere)],
        &ExactMatch,
        &query(
            "salad",
            &[("lettuce", "chopped"), ("black pepper", "ground")],
        ),
    );
    let line = p
        .progress_lines
        .iter()
        .find(|l| l.ingredient == "black pepper")
        .unwrap();
    assert_eq!(line.state[0].location, "in shaker", "{line:?}");
}

#[test]
fn an_egg_is_cracked_before_it_is_beaten_and_cheese_unwrapped_before_it_is_grated() {
    // the trees crack the egg and unwrap the cheese first: the asked state comes after that, not in the
    // shell or the packet
    let kb = "//
O\tegg\t1
S\twhole
O\tbowl\t0
S\tempty
M\tcrack\t<Assumed>
O\tegg\t1
S\tcracked
S\tin\t[bowl]
//
O\tcheese\t1
S\tsliced
S\tin\t[packet]
M\tunwrap\t<Assumed>
O\tcheese\t1
S\tsliced
S\ton\t[plate]
//
O\tegg\t1
S\tcracked
S\tin\t[bowl]
O\tcheese\t1
S\tsliced
S\ton\t[plate]
O\tfrying pan\t0
S\thot
M\tcook\t<Assumed>
O\tomelette\t1\t23
S\tcontains\t{cheese,egg}
S\tin\t[frying pan]
//
O\tcream\t1
S\tliquid
O\twhisk\t0
M\tbeat\t<Assumed>
O\tcream\t1
S\twhipped
//
O\tcarrot\t1
S\twhole
O\tgrater\t0
M\tgrate\t<Assumed>
O\tcarrot\t1
S\tgrated
//
";
    let ask = query("omelette", &[("egg", "whipped"), ("cheese", "grated")]);
    let p = plan_of(&[("omelette.txt", kb)], &ExactMatch, &ask);
    assert_eq!(
        line_motions(&p, "egg"),
        ["crack", "beat", "cook"],
        "{:#?}",
        p.units
    );
    assert_eq!(line_motions(&p, "cheese"), ["unwrap", "grate", "cook"]);
}

#[test]
fn fruit_bought_cut_is_not_pitted() {
    let salad = "//
O\tavocado\t1
S\tchopped
S\tin\t[bowl]
O\tlettuce\t1
S\tchopped
O\tsalad bowl\t0
S\tempty
M\tmix\t<Assumed>
O\tgreen salad\t1\t15
S\tcontains\t{avocado,lettuce}
S\tin\t[salad bowl]
//
";
    let ask = query("salad", &[("avocado", "chopped"), ("lettuce", "chopped")]);
    let p = plan_of(&[("salad.txt", salad)], &ExactMatch, &ask);
    assert_eq!(line_motions(&p, "avocado"), ["mix"], "{:#?}", p.units);
}

#[test]
fn fruit_asked_dried_is_bought_dried_and_not_pitted() {
    let elsewhere = "//
O\tapricot\t1
S\twhole
O\tknife\t1
M\tslice\t<Assumed>
O\tapricot\t1
S\tsliced
//
";
    let ask = query("salad", &[("lettuce", "chopped"), ("apricot", "dried")]);
    let p = plan_of(
        &[("salad.txt", LETTUCE_SALAD), ("other.txt", elsewhere)],
        &ExactMatch,
        &ask,
    );
    assert_eq!(line_motions(&p, "apricot"), ["mix"], "{:#?}", p.units);
    assert_eq!(line_states(&p, "apricot")[0], "dried");
}

#[test]
fn a_name_asked_twice_keeps_the_state_it_was_first_planned_in() {
    // lettuce asked chopped (as the tree has it) and again sliced: its one line stays right for the first
    let ask = r#"{"query": {"type": "salad", "ingredients": [
        {"object": "lettuce", "state": "chopped"}, {"object": "lettuce", "state": "sliced"}]}}"#;
    let p = plan_of(&[("salad.txt", LETTUCE_SALAD)], &ExactMatch, ask);
    assert_eq!(line_motions(&p, "lettuce"), ["mix"], "{:#?}", p.units);
    let second = p
        .ingredients
        .iter()
        .find(|i| i.state == "sliced")
        .and_then(|i| i.reason.as_deref())
        .unwrap();
    assert!(second.contains("kept in the state 'chopped'"), "{second}");
}

#[test]
fn a_name_brought_from_elsewhere_and_asked_again_keeps_its_first_state() {
    // onion is not in the salad: the first ask brings it chopped from FOON; asked again sliced, its
    // line is not cut again into a mix of both
    let ask = r#"{"query": {"type": "salad", "ingredients": [{"object": "lettuce", "state": "chopped"},
        {"object": "onion", "state": "chopped"}, {"object": "onion", "state": "sliced"}]}}"#;
    let p = plan_of(
        &[("salad.txt", LETTUCE_SALAD), ("other.txt", PREPARED)],
        &ExactMatch,
        ask,
    );
    assert_eq!(
        line_motions(&p, "onion"),
        ["peel", "chop", "mix"],
        "{:#?}",
        p.units
    );
    let second = p
        .ingredients
        .iter()
        .find(|i| i.state == "sliced")
        .and_then(|i| i.reason.as_deref())
        .unwrap();
    assert!(second.contains("kept in the state 'chopped'"), "{second}");
}

#[test]
fn cheese_asked_creamy_is_cream_cheese_shown_creamy_not_the_block_foon_sells() {
    let elsewhere = "//
O\tcream cheese\t1
S\tblock
S\tin\t[packet]
O\tmixing bowl\t0
M\tpick-and-place\t<Assumed>
O\tcream cheese\t1
S\tblock
S\tin\t[mixing bowl]
//
O\tbutter\t1
S\tsoftened
M\tmix\t<Assumed>
O\tbutter\t1
S\tcreamy
//
";
    let ask = query("salad", &[("lettuce", "chopped"), ("cheese", "creamy")]);
    let p = plan_of(
        &[("salad.txt", LETTUCE_SALAD), ("other.txt", elsewhere)],
        &ExactMatch,
        &ask,
    );
    let states = line_states(&p, "cheese");
    assert_eq!(states[0], "creamy", "{:#?}", p.progress_lines);
    assert!(
        !states.iter().any(|&s| s == "block" || s == "grated"),
        "{states:?}"
    );
    // no unit of its own just to call it creamy
    assert_eq!(line_motions(&p, "cheese"), ["mix"], "{:#?}", p.units);
}

#[test]
fn berries_are_washed_before_they_are_hulled_and_sliced() {
    let smoothie = "//
O\tstrawberry\t1
S\twhole
S\tin\t[container]
O\tbowl\t0
M\tpick-and-place\t<Assumed>
O\tstrawberry\t1
S\twhole
S\tin\t[bowl]
//
O\tstrawberry\t1
S\twhole
S\tin\t[bowl]
M\twash\t<Assumed>
O\tstrawberry\t1
S\twashed
S\tin\t[bowl]
//
O\tstrawberry\t1
S\twashed
S\tin\t[bowl]
O\tmilk\t1
S\tliquid
M\tblend\t<Assumed>
O\tsmoothie\t1\t9
S\tblended
S\tcontains\t{strawberry,milk}
//
O\tapple\t1
S\twhole
M\tslice\t<Assumed>
O\tapple\t1
S\tsliced
//
";
    let ask = query("drinks", &[("strawberry", "sliced"), ("milk", "liquid")]);
    let p = plan_of(&[("smoothie.txt", smoothie)], &ExactMatch, &ask);
    assert_eq!(
        line_motions(&p, "strawberry"),
        ["pick-and-place", "wash", "hull", "slice", "blend"],
        "{:#?}",
        p.progress_lines
    );
}

#[test]
fn onion_joins_a_soup_before_it_is_boiled_not_as_it_is_served() {
    // parsley is scattered over the soup as it is served: a unit that adds a food, closer to the dish
    let soup = CHICKEN_POT.replace(
        "O\tbowl\t0\nS\tempty\nM\tpour",
        "O\tbowl\t0\nS\tempty\nO\tparsley\t1\nS\tchopped\nM\tpour",
    );
    assert_ne!(soup, CHICKEN_POT);
    let ask = query(
        "soup",
        &[
            ("chicken breast", "sliced"),
            ("parsley", "chopped"),
            ("onion", "chopped"),
        ],
    );
    let p = plan_of(
        &[("soup.txt", &soup), ("other.txt", PREPARED)],
        &ExactMatch,
        &ask,
    );
    assert!(
        line_motions(&p, "onion").contains(&"boil"),
        "{:#?}",
        p.progress_lines
    );
}

#[test]
fn a_new_ingredient_does_not_join_where_pepper_is_ground() {
    let salad = "//
O\tlettuce\t1
S\tchopped
O\tsalad bowl\t0
S\tempty
M\ttoss\t<Assumed>
O\tsalad bowl\t0
S\tcontains\t{lettuce}
//
O\tsalad bowl\t0
S\tcontains\t{lettuce}
O\tblack pepper\t1
S\tpeppercorn
M\tgrind\t<Assumed>
O\tsalad bowl\t0
S\tcontains\t{lettuce,black pepper}
//
O\tsalad bowl\t0
S\tcontains\t{lettuce,black pepper}
M\tmix\t<Assumed>
O\tgreen salad\t1\t15
S\tmixed
S\tcontains\t{lettuce,black pepper}
//
O\tcucumber\t1
S\twhole
O\tknife\t1
M\tslice\t<Assumed>
O\tcucumber\t1
S\tsliced
//
";
    let ask = query(
        "salad",
        &[
            ("lettuce", "chopped"),
            ("black pepper", "ground"),
            ("cucumber", "sliced"),
        ],
    );
    let p = plan_of(&[("salad.txt", salad)], &ExactMatch, &ask);
    let motions = line_motions(&p, "cucumber");
    assert!(!motions.contains(&"grind"), "{motions:?}");
    assert!(motions.contains(&"toss"), "{:#?}", p.progress_lines);
}

#[test]
fn ginger_asked_chopped_is_chopped_where_foon_grates_it_not_cut_twice() {
    // FOON grates the ginger into the pot and leaves "grated" out of the node it makes
    let soup = "//
O\tginger\t1
S\tpeeled
O\tpot\t0
S\tcontains\t{broth}
O\tgrater\t1
M\tgrate\t<Assumed>
O\tginger\t1
S\tpeeled
S\tin\t[pot]
O\tpot\t0
S\tcontains\t{broth,ginger}
//
O\tpot\t0
S\tcontains\t{broth,ginger}
O\tstove\t0
S\ton
M\tboil\t<Assumed>
O\tginger soup\t1\t1
S\tcooked
S\tcontains\t{broth,ginger}
S\tin\t[pot]
//
";
    let ask = query("soup", &[("ginger", "chopped")]);
    let p = plan_of(
        &[("soup.txt", soup), ("other.txt", PREPARED)],
        &ExactMatch,
        &ask,
    );
    let motions = line_motions(&p, "ginger");
    assert_eq!(motions.first(), Some(&"chop"), "{:#?}", p.progress_lines);
    assert!(!motions.contains(&"grate"), "{motions:?}");
}

#[test]
fn salt_in_a_pot_that_is_boiled_is_not_called_cooked_but_the_chicken_is() {
    let pot = CHICKEN_POT
        .replacen(
            "O\tchicken breast\t1\nS\tsliced\nM\tpick-and-place",
            "O\tchicken breast\t1\nS\tsliced\nO\tsalt\t1\nS\tgranulated\nM\tpick-and-place",
            1,
        )
        .replace("{chicken breast}", "{chicken breast,salt}");
    let ask = query(
        "soup",
        &[("chicken breast", "sliced"), ("salt", "granulated")],
    );
    let p = plan_of(&[("soup.txt", &pot)], &ExactMatch, &ask);
    let cooked = |food: &str| {
        line_states(&p, food)
            .iter()
            .any(|s| !s.starts_with("in ") && s.contains("cooked"))
    };
    assert!(cooked("chicken breast"), "{:#?}", p.progress_lines);
    assert!(!cooked("salt"), "{:#?}", p.progress_lines);
}

/// A broccoli salad (class 15): FOON's "skim" runs a knife under the stem's skin, then the stem is
/// chopped and tossed in a bowl.
const BROCCOLI_SALAD: &str = "//
O\tbroccoli\t1
S\tuncooked
S\twhole
S\ton\t[cutting board]
O\tknife\t1
M\tskim\t<Assumed>
O\tbroccoli\t0
S\tuncooked
S\twhole
S\tpeeled
S\ton\t[cutting board]
//
O\tbroccoli\t0
S\tuncooked
S\twhole
S\tpeeled
S\ton\t[cutting board]
O\tknife\t1
M\tchop\t<Assumed>
O\tbroccoli\t0
S\tchopped
S\ton\t[cutting board]
//
O\tbroccoli\t0
S\tchopped
S\ton\t[cutting board]
O\tbowl\t0
S\tempty
M\tpick-and-place\t<Assumed>
O\tsalad\t1\t15
S\tcontains\t{broccoli}
S\tin\t[bowl]
//
";

#[test]
fn a_motion_foon_names_otherwise_takes_the_cooks_word() {
    let files = [("broccoli.txt", BROCCOLI_SALAD)];
    let p = plan_of(
        &files,
        &ExactMatch,
        &query("salad", &[("broccoli", "chopped")]),
    );
    // the stem is peeled, as a cook says, not "skimmed"
    assert_eq!(
        line_motions(&p, "broccoli"),
        ["peel", "chop", "pick-and-place"]
    );
    assert!(
        p.steps.iter().any(|s| s.starts_with("Peel the broccoli")),
        "{:?}",
        p.steps
    );
}

/// Rice (class 4) boiled in a pot with ground pepper sprinkled in.
const PEPPER_RICE: &str = "//
O\trice\t1
S\tuncooked
S\tin\t[bowl]
O\tpot\t0
S\tempty
M\tpour\t<Assumed>
O\tpot\t0
S\tcontains\t{rice}
O\trice\t1
S\tuncooked
S\tin\t[pot]
//
O\tpot\t0
S\tcontains\t{rice}
O\tpepper\t1
S\tground
S\tin\t[shaker]
M\tsprinkle\t<Assumed>
O\tpot\t0
S\tcontains\t{pepper,rice}
O\tpepper\t1
S\tground
S\tin\t[pot]
//
O\tpot\t0
S\tcontains\t{pepper,rice}
O\tstove\t0
S\ton
M\tboil\t<Assumed>
O\tpot\t0
S\tcontains\t{pepper,rice}
S\tcooked
//
O\tpot\t0
S\tcontains\t{pepper,rice}
S\tcooked
O\tbowl\t0
S\tempty
M\tpour\t<Assumed>
O\trice\t1\t4
S\tcontains\t{pepper}
S\tin\t[bowl]
//
";

#[test]
fn a_name_read_as_a_spice_does_not_show_the_pots_cooking() {
    let files = [("rice.txt", PEPPER_RICE)];
    let q = query("rice", &[("rice", "uncooked"), ("pepper", "ground")]);
    let p = plan_of(&files, &ExactMatch, &q);
    let states = |food: &str| -> Vec<String> {
        let line = p
            .progress_lines
            .iter()
            .find(|l| l.ingredient == food)
            .unwrap();
        line.state
            .iter()
            .map(|s| s.physical_state.to_string())
            .collect()
    };
    // "pepper — ground" is black pepper: ground, never "partly cooked" in the boiling pot
    assert!(
        states("pepper").iter().all(|s| !s.contains("cooked")),
        "{:?}",
        states("pepper")
    );
    assert!(
        states("rice")
            .iter()
            .any(|s| s.contains("cooked") && !s.contains("uncooked")),
        "{:?}",
        states("rice")
    );
}

/// Ramen (class 14): noodles into the broth, an egg cracked into the pot and poached beside them, all
/// ladled into a bowl.
const POACHED_EGG_RAMEN: &str = "//
O\tpot\t0
S\tcontains\t{broth}
S\ton\t[stove]
O\tnoodle\t1
S\tuncooked
S\tin\t[packet]
M\tpour\t<Assumed>
O\tpot\t0
S\tcontains\t{broth,noodle}
S\ton\t[stove]
//
O\tpot\t0
S\tcontains\t{broth,noodle}
S\ton\t[stove]
O\tegg\t1
S\tuncracked
M\tcrack\t<Assumed>
O\tpot\t0
S\tcontains\t{broth,egg white and yolk,noodle}
S\ton\t[stove]
//
O\tpot\t0
S\tcontains\t{broth,egg white and yolk,noodle}
S\ton\t[stove]
M\tcook\t<Assumed>
O\tegg white and yolk\t1
S\tboiled
S\tin\t[pot]
O\tpot\t0
S\tcontains\t{broth,egg white and yolk,noodle}
S\tcooked
S\ton\t[stove]
//
O\tpot\t0
S\tcontains\t{broth,egg white and yolk,noodle}
S\tcooked
S\ton\t[stove]
O\tbowl\t0
S\tempty
M\tscoop and pour\t<Assumed>
O\tramen\t1\t14
S\tcontains\t{broth,egg white and yolk,noodle}
S\tin\t[bowl]
//
";

#[test]
fn a_food_poached_beside_the_ingredient_does_not_take_it_in() {
    let files = [("ramen.txt", POACHED_EGG_RAMEN)];
    let q = query("noodle", &[("noodle", "uncooked"), ("egg", "whole")]);
    let p = plan_of(&files, &ExactMatch, &q);
    let line = p
        .progress_lines
        .iter()
        .find(|l| l.ingredient == "noodle")
        .unwrap();
    // the noodles stay in the pot while the egg poaches beside them, then go into the ramen
    assert!(
        line.state.iter().all(|s| !s.physical_state.contains("egg")),
        "{line:#?}"
    );
    assert_eq!(line.end_product, "ramen", "{line:#?}");
}

/// Elsewhere in FOON: parsley chopped, mushrooms sliced, a block of cheddar grated.
const TOPPINGS: &str = "//
O\tparsley\t1
S\twhole
O\tknife\t1
S\tclean
M\tchop\t<Assumed>
O\tparsley\t1
S\tchopped
//
O\tmushroom\t1
S\twhole
O\tknife\t1
S\tclean
M\tslice\t<Assumed>
O\tmushroom\t1
S\tsliced
//
O\tcheddar\t1
S\tblock
O\tgrater\t1
M\tgrate\t<Assumed>
O\tcheddar\t1
S\tgrated
//
";

#[test]
fn parsley_joins_the_soup_as_it_is_served_and_the_mushrooms_are_boiled_in_it() {
    // the chicken is boiled in the pot; parsley is scattered over the served bowl
    let ask = query(
        "soup",
        &[
            ("parsley", "chopped"),
            ("mushroom", "sliced"),
            ("chicken breast", "sliced"),
        ],
    );
    let p = plan_of(
        &[("soup.txt", CHICKEN_POT), ("other.txt", TOPPINGS)],
        &ExactMatch,
        &ask,
    );
    let parsley = line_motions(&p, "parsley");
    assert!(!parsley.contains(&"boil"), "{:#?}", p.progress_lines);
    assert_eq!(parsley.last(), Some(&"pour"), "{parsley:?}");
    assert!(
        line_motions(&p, "mushroom").contains(&"boil"),
        "{:#?}",
        p.progress_lines
    );
}

#[test]
fn cheddar_goes_onto_the_baked_cake_not_into_its_batter() {
    // the cake is baked last: no unit after the baking takes more, so one is added onto the dish
    let (baked_last, _syrup) = SYRUP_CAKE
        .rsplit_once("O\tsponge\t1\nS\tbaked\nS\tcontains\t{egg}\nO\tsyrup")
        .unwrap();
    let baked_last = baked_last.replacen("O\tsponge\t1\n", "O\tsponge\t1\t5\n", 1);
    let ask = query(
        "cake",
        &[
            ("egg", "cracked"),
            ("cheddar", "grated"),
            ("flour", "powder"),
        ],
    );
    let p = plan_of(
        &[
            ("cake.txt", &baked_last),
            ("flour.txt", FLOUR),
            ("other.txt", TOPPINGS),
        ],
        &ExactMatch,
        &ask,
    );
    let cheddar = line_motions(&p, "cheddar");
    assert!(!cheddar.contains(&"bake"), "{:#?}", p.progress_lines);
    assert!(line_motions(&p, "flour").contains(&"bake"));
    let line = p
        .progress_lines
        .iter()
        .find(|l| l.ingredient == "cheddar")
        .unwrap();
    assert_eq!(line.end_product, p.goal.label, "{line:#?}");
    assert_eq!(cheddar.last(), Some(&"sprinkle"), "{cheddar:?}");
    assert_eq!(kinds(&p), []);
}

/// An omelette (class 23): eggs beaten in a bowl, poured into a hot pan with oil, cooked.
const OIL_PAN_OMELETTE: &str = "//
O\tbowl\t0
S\tempty
O\tegg\t1
S\tcracked
M\tbeat\t<Assumed>
O\tbowl\t0
S\tcontains\t{egg}
//
O\tfrying pan\t0
S\thot
O\tolive oil\t1
S\tliquid
M\tpour\t<Assumed>
O\tfrying pan\t0
S\thot
S\tcontains\t{olive oil}
//
O\tbowl\t0
S\tcontains\t{egg}
O\tfrying pan\t0
S\thot
S\tcontains\t{olive oil}
M\tpour\t<Assumed>
O\tfrying pan\t0
S\thot
S\tcontains\t{egg,olive oil}
//
O\tfrying pan\t0
S\thot
S\tcontains\t{egg,olive oil}
O\tstove\t0
S\ton
M\tcook\t<Assumed>
O\tomelette\t1\t23
S\tcooked
S\tcontains\t{egg,olive oil}
S\tin\t[frying pan]
//
";

/// Milk as bought, in a recipe of its own.
const MILK: &str = "//
O\tmilk\t1
S\tliquid
S\tin\t[carton]
O\tcup\t0
S\tempty
M\tpour\t<Assumed>
O\tmilk\t1
S\tliquid
S\tin\t[cup]
//
";

#[test]
fn milk_is_beaten_with_the_eggs_not_poured_into_the_hot_pan_with_the_oil() {
    let ask = query(
        "omelette",
        &[
            ("egg", "cracked"),
            ("olive oil", "liquid"),
            ("milk", "liquid"),
        ],
    );
    let p = plan_of(
        &[("omelette.txt", OIL_PAN_OMELETTE), ("milk.txt", MILK)],
        &ExactMatch,
        &ask,
    );
    let milk = line_motions(&p, "milk");
    assert!(milk.contains(&"beat"), "{:#?}", p.progress_lines);
    assert!(milk.contains(&"cook"), "{milk:?}");
}

/// Scrambled egg (class 23): eggs beaten, poured into the hot pan, cooked, poured onto a plate, soy
/// sauce poured over them.
const SCRAMBLED_EGG: &str = "//
O\tbowl\t0
S\tempty
O\tegg\t1
S\tcracked
M\tbeat\t<Assumed>
O\tbowl\t0
S\tcontains\t{egg}
//
O\tbowl\t0
S\tcontains\t{egg}
O\tfrying pan\t0
S\thot
M\tpour\t<Assumed>
O\tfrying pan\t0
S\thot
S\tcontains\t{egg}
//
O\tfrying pan\t0
S\thot
S\tcontains\t{egg}
O\tstove\t0
S\ton
M\tcook\t<Assumed>
O\tfrying pan\t0
S\tcontains\t{scrambled egg}
O\tscrambled egg\t1
S\tcooked
S\tcontains\t{egg}
S\tin\t[frying pan]
//
O\tfrying pan\t0
S\tcontains\t{scrambled egg}
O\tscrambled egg\t1
S\tcooked
S\tcontains\t{egg}
S\tin\t[frying pan]
O\tplate\t0
S\tempty
M\tpour\t<Assumed>
O\tscrambled egg\t1
S\tcooked
S\tcontains\t{egg}
S\ton\t[plate]
//
O\tscrambled egg\t1
S\tcooked
S\tcontains\t{egg}
S\ton\t[plate]
O\tsoy sauce\t1
S\tliquid
M\tpour\t<Assumed>
O\tscrambled egg\t1\t23
S\tcooked
S\tcontains\t{egg,soy sauce}
S\ton\t[plate]
//
";

#[test]
fn oil_goes_into_the_pan_before_the_eggs_cook_not_onto_the_plated_eggs() {
    let ask = query(
        "omelette",
        &[
            ("egg", "cracked"),
            ("olive oil", "liquid"),
            ("soy sauce", "liquid"),
        ],
    );
    let p = plan_of(
        &[("eggs.txt", SCRAMBLED_EGG), ("oil.txt", OIL)],
        &ExactMatch,
        &ask,
    );
    let oil = line_motions(&p, "olive oil");
    assert!(oil.contains(&"cook"), "{:#?}", p.progress_lines);
}

/// A cake (class 5) whose tree has its own varieties of the foods a query may ask: vegetable oil and
/// "egg white and yolk" (an egg cracked) mixed with flour into a batter that is baked; green onion and
/// lime zest stirred in; olive oil poured into a pan that the stove heats without it (a dead end).
const VARIETY_CAKE: &str = "//
O\tbowl\t0
S\tempty
O\tflour\t1
S\tpowder
O\tvegetable oil\t1
S\tliquid
O\tegg white and yolk\t1
S\tin\t[bowl]
O\tgreen onion\t1
S\tchopped
O\tlime zest\t1
S\tgrated
M\tmix\t<Assumed>
O\tcake batter\t1
S\tcontains\t{flour,vegetable oil,egg white and yolk,green onion,lime zest}
S\tin\t[bowl]
//
O\tpan\t0
S\tempty
O\tolive oil\t1
S\tliquid
M\tpour\t<Assumed>
O\tpan\t0
S\tcontains\t{olive oil}
O\tolive oil\t1
S\tin\t[pan]
//
O\tpan\t0
S\tcontains\t{olive oil}
O\tstove\t0
S\ton
M\theat\t<Assumed>
O\tpan\t0
S\thot
//
O\tpan\t0
S\thot
O\tcake batter\t1
S\tcontains\t{flour,vegetable oil,egg white and yolk,green onion,lime zest}
S\tin\t[bowl]
M\tbake\t<Assumed>
O\tcake\t1\t5
S\tcontains\t{flour,vegetable oil,egg white and yolk,green onion,lime zest}
S\tin\t[pan]
//
";

/// Elsewhere in FOON: the foods a query may ask by their own names (so that each is a FOON label).
const PLAIN_FOODS: &str = "//
O\tegg\t1
S\twhole
O\tbowl\t0
S\tempty
M\tcrack\t<Assumed>
O\tegg\t1
S\tcracked
S\tin\t[bowl]
//
O\toil\t1
S\tliquid
O\tpot\t0
S\tempty
M\tpour\t<Assumed>
O\toil\t1
S\tin\t[pot]
//
O\tonion\t1
S\twhole
O\tknife\t1
S\tclean
M\tchop\t<Assumed>
O\tonion\t1
S\tchopped
//
O\tlime\t1
S\twhole
O\tknife\t1
S\tclean
M\tslice\t<Assumed>
O\tlime\t1
S\tsliced
//
";

fn variety_cake(items: &[(&str, &str)]) -> Plan {
    plan_of(
        &[("cake.txt", VARIETY_CAKE), ("foods.txt", PLAIN_FOODS)],
        &ExactMatch,
        &query("cake", items),
    )
}

#[test]
fn an_asked_food_takes_the_place_of_its_variety_in_the_reference_tree() {
    let p = variety_cake(&[("flour", "powder"), ("oil", "liquid")]);
    let oil = outcome(&p, "oil");
    assert_eq!(
        oil.matched.as_ref().map(|m| m.label.as_str()),
        Some("vegetable oil")
    );
    assert_eq!(line_motions(&p, "oil"), ["mix", "bake"]);
    assert_eq!(kinds(&p), []);
}

#[test]
fn an_egg_taking_the_place_of_white_and_yolk_is_cracked_first() {
    let p = variety_cake(&[("flour", "powder"), ("egg", "whole")]);
    assert_eq!(
        outcome(&p, "egg")
            .matched
            .as_ref()
            .map(|m| m.label.as_str()),
        Some("egg white and yolk")
    );
    assert_eq!(line_motions(&p, "egg"), ["crack", "mix", "bake"]);
    let line = p
        .progress_lines
        .iter()
        .find(|l| l.ingredient == "egg")
        .unwrap();
    assert_eq!(line.state[0].physical_state, "whole");
    assert_eq!(kinds(&p), []);
}

#[test]
fn a_food_does_not_take_the_place_of_a_part_another_food_or_a_dead_end() {
    // green onion is handled otherwise than onion (no skin to peel), lime zest is a part of the lime,
    // and the tree's olive oil never reaches the cake: each asked food comes from elsewhere in FOON
    let p = variety_cake(&[
        ("flour", "powder"),
        ("onion", "chopped"),
        ("lime", "sliced"),
    ]);
    for food in ["onion", "lime"] {
        assert_eq!(
            outcome(&p, food).matched.as_ref().map(|m| m.label.as_str()),
            Some(food),
            "{:#?}",
            p.ingredients
        );
    }
    let cake = VARIETY_CAKE.replace("vegetable oil", "sunflower seed");
    let p = plan_of(
        &[("cake.txt", &cake), ("foods.txt", PLAIN_FOODS)],
        &ExactMatch,
        &query("cake", &[("flour", "powder"), ("oil", "liquid")]),
    );
    assert_eq!(
        outcome(&p, "oil")
            .matched
            .as_ref()
            .map(|m| m.label.as_str()),
        Some("oil")
    );
}

/// Elsewhere in FOON: raisins poured into a bowl, a cabbage chopped into shreds.
const RAISIN_AND_SHREDS: &str = "//
O\traisin\t1
S\twhole
O\tbowl\t0
S\tempty
M\tpour\t<Assumed>
O\traisin\t1
S\twhole
S\tin\t[bowl]
//
O\tcabbage\t1
S\twhole
O\tknife\t1
S\tclean
M\tchop\t<Assumed>
O\tcabbage\t1
S\tshredded
//
";

/// "shredded coconut" is like a raisin (a dried fruit); nothing else is alike.
struct DriedFruit;

impl foon_core::similarity::Similarity for DriedFruit {
    fn similarity(&self, a: &str, b: &str) -> f32 {
        match (a, b) {
            _ if a == b => 1.0,
            ("shredded coconut", "raisin") | ("raisin", "shredded coconut") => 0.6,
            _ => 0.0,
        }
    }
}

#[test]
fn a_food_read_as_a_product_of_its_state_is_bought_so_not_made_from_its_substitute() {
    // coconut "shredded" is shredded coconut, bought so: not a whole raisin chopped into shreds
    let p = plan_of(
        &[
            ("salad.txt", LETTUCE_SALAD),
            ("foods.txt", RAISIN_AND_SHREDS),
        ],
        &DriedFruit,
        &query("salad", &[("lettuce", "chopped"), ("coconut", "shredded")]),
    );
    assert_eq!(line_motions(&p, "coconut"), ["mix"], "{:#?}", p.units);
    let line = p
        .progress_lines
        .iter()
        .find(|l| l.ingredient == "coconut")
        .unwrap();
    assert_eq!(line.state[0].physical_state, "shredded");
    // "flakes" reads so too, by a state word of the same kind as the product's
    let p = plan_of(
        &[
            ("salad.txt", LETTUCE_SALAD),
            ("foods.txt", RAISIN_AND_SHREDS),
        ],
        &DriedFruit,
        &query("salad", &[("lettuce", "chopped"), ("coconut", "flakes")]),
    );
    assert_eq!(line_motions(&p, "coconut"), ["mix"], "{:#?}", p.units);
}

/// A bread (class 0): flour from one packet sprinkled on a board and poured into a bowl, where it is
/// mixed with water into a dough that is kneaded on the floured board and baked. The board's flour
/// comes first in the plan.
const FLOURED_BOARD: &str = "//
O\tflour\t1
S\tpowder
S\tin\t[packet]
O\tboard\t0
S\tempty
M\tsprinkle\t<Assumed>
O\tflour\t1
S\tpowder
S\ton\t[board]
O\tboard\t0
S\tcontains\t{flour}
//
O\tflour\t1
S\tpowder
S\tin\t[packet]
O\tbowl\t0
S\tempty
M\tpour\t<Assumed>
O\tflour\t1
S\tpowder
S\tin\t[bowl]
O\tbowl\t0
S\tcontains\t{flour}
//
O\tbowl\t0
S\tcontains\t{flour}
O\tflour\t1
S\tpowder
S\tin\t[bowl]
O\twater\t1
S\tliquid
M\tmix\t<Assumed>
O\tdough\t1
S\tcontains\t{flour,water}
S\tin\t[bowl]
//
O\tboard\t0
S\tcontains\t{flour}
O\tdough\t1
S\tcontains\t{flour,water}
S\tin\t[bowl]
M\tknead\t<Assumed>
O\tdough\t1
S\tkneaded
S\tcontains\t{flour,water}
S\ton\t[board]
//
O\tdough\t1
S\tkneaded
S\tcontains\t{flour,water}
S\ton\t[board]
M\tbake\t<Assumed>
O\tbread\t1\t0
S\tcontains\t{flour,water}
S\tbaked
//
";

#[test]
fn flour_is_followed_into_the_dough_not_onto_the_board_it_is_kneaded_on() {
    let p = plan_of(
        &[("bread.txt", FLOURED_BOARD)],
        &ExactMatch,
        &query("bread", &[("flour", "powder"), ("water", "liquid")]),
    );
    assert_eq!(
        line_motions(&p, "flour"),
        ["pour", "mix", "knead", "bake"],
        "{:#?}",
        p.units
    );
}

/// A brownie (class 5): flour and sugar mixed into a batter, baked, placed on a board and cut there. As
/// in FOON, the brownie the cut takes is another node than the one placed on the board, which lists it.
const BOARD_BROWNIE: &str = "//
O\tbowl\t0
S\tempty
O\tflour\t1
S\tpowder
O\tsugar\t1
S\tgranulated
M\tmix\t<Assumed>
O\tbatter\t1
S\tcontains\t{flour,sugar}
S\tin\t[bowl]
//
O\tbatter\t1
S\tcontains\t{flour,sugar}
S\tin\t[bowl]
O\toven\t0
S\ton
M\tbake\t<Assumed>
O\tbrownie\t1
S\tbaked
S\tcontains\t{flour,sugar}
S\tin\t[baking tray]
//
O\tbrownie\t1
S\tbaked
S\tcontains\t{flour,sugar}
S\tin\t[baking tray]
O\tcutting board\t0
S\tempty
M\tpick-and-place\t<Assumed>
O\tbrownie\t1
S\tbaked
S\tcontains\t{flour,sugar}
S\ton\t[cutting board]
O\tcutting board\t0
S\tcontains\t{brownie}
//
O\tbrownie\t1
S\tbaked
S\ton\t[cutting board]
O\tcutting board\t0
S\tcontains\t{brownie}
O\tknife\t0
S\tclean
M\tcut\t<Assumed>
O\tbrownie\t1\t5
S\tdivided
S\tcontains\t{flour,sugar}
S\ton\t[cutting board]
//
";

/// Baking soda as bought, in a recipe of its own.
const BAKING_SODA: &str = "//
O\tbaking soda\t1
S\tpowder
S\tin\t[box]
O\tbowl\t0
S\tempty
M\tpour\t<Assumed>
O\tbaking soda\t1
S\tpowder
S\tin\t[bowl]
//
";

#[test]
fn baking_soda_joins_the_batter_though_the_board_passes_the_brownie_to_the_cut() {
    let ask = query(
        "cake",
        &[
            ("flour", "powder"),
            ("sugar", "granulated"),
            ("baking soda", "powder"),
        ],
    );
    let p = plan_of(
        &[("brownie.txt", BOARD_BROWNIE), ("soda.txt", BAKING_SODA)],
        &ExactMatch,
        &ask,
    );
    let soda = line_motions(&p, "baking soda");
    assert!(soda.contains(&"bake"), "{soda:?}\n{:#?}", p.units);
    assert!(!soda.contains(&"cut"), "{soda:?}");
    assert_eq!(kinds(&p), []);
}

/// An omelette (class 23): eggs cooked in a hot pan, cheese placed on them in the pan, then flipped
/// onto a plate.
const FLIPPED_OMELETTE: &str = "//
O\tegg\t1
S\tbeaten
S\tin\t[frying pan]
O\tstove\t0
S\ton
M\tcook\t<Assumed>
O\tomelette\t1
S\tcooked
S\tcontains\t{egg}
S\tin\t[frying pan]
O\tfrying pan\t0
S\tcontains\t{omelette}
S\thot
//
O\tfrying pan\t0
S\tcontains\t{omelette}
S\thot
O\tcheese\t1
S\tsliced
M\tplace\t<Assumed>
O\tfrying pan\t0
S\tcontains\t{cheese,omelette}
S\thot
//
O\tfrying pan\t0
S\tcontains\t{cheese,omelette}
S\thot
O\tplate\t0
S\tempty
M\tflip and place\t<Assumed>
O\tomelette\t1\t23
S\tcontains\t{cheese,egg}
S\ton\t[plate]
//
";

#[test]
fn parsley_goes_onto_the_plated_omelette_not_into_its_hot_pan() {
    let ask = query(
        "omelette",
        &[
            ("egg", "beaten"),
            ("cheese", "sliced"),
            ("parsley", "chopped"),
        ],
    );
    let p = plan_of(
        &[("omelette.txt", FLIPPED_OMELETTE), ("other.txt", TOPPINGS)],
        &ExactMatch,
        &ask,
    );
    let parsley = line_motions(&p, "parsley");
    assert_eq!(parsley.last(), Some(&"sprinkle"), "{:#?}", p.progress_lines);
    assert!(!parsley.contains(&"place"), "{parsley:?}");
}

/// An omelette (class 23): butter cubed into a pan heated on the stove, eggs poured in and cooked.
const BUTTER_PAN_OMELETTE: &str = "//
O\tbutter\t1
S\tcubed
O\tfrying pan\t0
S\tempty
M\tpour\t<Assumed>
O\tfrying pan\t0
S\tcontains\t{butter}
//
O\tfrying pan\t0
S\tcontains\t{butter}
O\tstove\t0
S\ton
M\theat\t<Assumed>
O\tfrying pan\t0
S\tcontains\t{butter}
S\thot
//
O\tfrying pan\t0
S\tcontains\t{butter}
S\thot
O\tegg\t1
S\tbeaten
M\tcook\t<Assumed>
O\tomelette\t1\t23
S\tcontains\t{butter,egg}
S\tin\t[frying pan]
//
";

#[test]
fn butter_heated_in_the_pan_is_melted_not_cubed_and_hot() {
    let p = plan_of(
        &[("omelette.txt", BUTTER_PAN_OMELETTE)],
        &ExactMatch,
        &query("omelette", &[("butter", "cubed"), ("egg", "beaten")]),
    );
    let butter = line_states(&p, "butter");
    assert!(butter.contains(&"melted, hot"), "{butter:?}");
    assert!(
        !butter.iter().any(|s| s.contains("cubed, hot")),
        "{butter:?}"
    );
    assert_eq!(butter.first(), Some(&"cubed"), "{butter:?}");
}

/// Bacon sliced raw, in a recipe of its own.
const BACON: &str = "//
O\tbacon\t1
S\traw
O\tknife\t0
S\tclean
M\tslice\t<Assumed>
O\tbacon\t1
S\tsliced
S\traw
//
";

#[test]
fn bacon_is_cooked_before_it_joins_the_omelette_and_the_pan_does_not_reheat_it() {
    let p = plan_of(
        &[("omelette.txt", OIL_PAN_OMELETTE), ("bacon.txt", BACON)],
        &ExactMatch,
        &query(
            "omelette",
            &[
                ("egg", "cracked"),
                ("olive oil", "liquid"),
                ("bacon", "sliced"),
            ],
        ),
    );
    let motions = line_motions(&p, "bacon");
    let cooked = motions.iter().position(|m| *m == "cook");
    assert!(
        cooked.is_some_and(|i| i <= 1),
        "{motions:?}\n{:#?}",
        p.units
    );
    let reason = outcome(&p, "bacon").reason.as_deref().unwrap();
    assert!(
        reason.contains("to make it cooked (before it joins)"),
        "{reason}"
    );
    let states = line_states(&p, "bacon");
    assert!(!states.iter().any(|s| s.contains("hot")), "{states:?}");
    assert_eq!(kinds(&p), []);
}

/// Toast (class 0): slices soaked in milk in the pan, then toasted there by FOON's "flip and stack".
const PAN_TOAST: &str = "//
O\tbread\t1
S\tsliced
S\ton\t[cooking pan]
O\tmilk\t1
S\tliquid
M\tpour\t<Assumed>
O\tbread\t1
S\tsliced
S\tcontains\t{milk}
S\ton\t[cooking pan]
//
O\tbread\t1
S\tsliced
S\tcontains\t{milk}
S\ton\t[cooking pan]
O\tstove\t0
S\ton
M\tflip and stack\t<Assumed>
O\tbread\t1
S\tsliced
S\ttoasted
S\tcontains\t{milk}
S\ton\t[cooking pan]
//
O\tbread\t1
S\tsliced
S\ttoasted
S\tcontains\t{milk}
S\ton\t[cooking pan]
O\tplate\t0
S\tempty
M\tpick-and-place\t<Assumed>
O\tbread toast\t1\t0
S\tcontains\t{bread,milk}
S\ton\t[plate]
//
O\tegg\t1
S\tuncracked
M\tcrack\t<Assumed>
O\tegg\t1
S\tcracked
//
";

#[test]
fn an_egg_soaks_the_slices_that_the_pan_toasts_not_cooked_apart_and_poured_on() {
    let p = plan_of(
        &[("toast.txt", PAN_TOAST), ("extract.txt", EXTRACT)],
        &ExactMatch,
        &query(
            "bread",
            &[
                ("bread", "sliced"),
                ("milk", "liquid"),
                ("egg", "cracked"),
                ("vanilla extract", "liquid"),
            ],
        ),
    );
    let egg = line_motions(&p, "egg");
    assert!(egg.contains(&"toast and stack"), "{egg:?}\n{:#?}", p.units);
    assert!(!egg.contains(&"cook"), "{egg:?}");
    let vanilla = line_motions(&p, "vanilla extract");
    assert!(vanilla.contains(&"toast and stack"), "{vanilla:?}");
    assert_eq!(kinds(&p), []);
}

/// Vanilla extract as bought.
const EXTRACT: &str = "//
O\tvanilla extract\t1
S\tliquid
S\tin\t[bottle]
O\tspoon\t0
S\tempty
M\tpour\t<Assumed>
O\tvanilla extract\t1
S\tliquid
S\tin\t[spoon]
//
";

/// Elsewhere in FOON: canned kidney beans poured into a bowl, black beans blended, a bar of chocolate
/// chopped.
const BEANS_AND_CHOCOLATE: &str = "//
O\tkidney bean\t1
S\tcooked
S\tin\t[can]
O\tbowl\t0
S\tempty
M\tpour\t<Assumed>
O\tkidney bean\t1
S\tcooked
S\tin\t[bowl]
//
O\tblack bean\t1
S\tcooked
O\tblender\t0
S\ton
M\tblend\t<Assumed>
O\tblack bean\t1
S\tjuice
//
O\tchocolate\t1
S\tbar
O\tknife\t0
S\tclean
M\tchop\t<Assumed>
O\tchocolate\t1
S\tchopped
//
";

#[test]
fn beans_asked_juice_are_not_blended_into_a_salad() {
    let p = plan_of(
        &[
            ("salad.txt", LETTUCE_SALAD),
            ("other.txt", BEANS_AND_CHOCOLATE),
        ],
        &ExactMatch,
        &query("salad", &[("lettuce", "chopped"), ("kidney bean", "juice")]),
    );
    let beans = line_motions(&p, "kidney bean");
    assert!(!beans.contains(&"blend"), "{beans:?}\n{:#?}", p.units);
}

#[test]
fn chocolate_asked_solid_is_chopped_before_it_joins_the_batter() {
    let p = plan_of(
        &[("cake.txt", SYRUP_CAKE), ("other.txt", BEANS_AND_CHOCOLATE)],
        &ExactMatch,
        &query("cake", &[("egg", "cracked"), ("chocolate", "solid")]),
    );
    let chocolate = line_motions(&p, "chocolate");
    assert_eq!(
        chocolate.first(),
        Some(&"chop"),
        "{chocolate:?}\n{:#?}",
        p.units
    );
}

/// A pizza (class 3): dough kneaded into "pizza dough", shaped into a raw "pizza", baked.
const PIZZA: &str = "//
O\tflour\t1
S\tpowder
O\twater\t1
S\tliquid
O\tbowl\t0
S\tempty
M\tmix\t<Assumed>
O\tdough\t1
S\tmixed
S\tcontains\t{flour,water}
S\tin\t[bowl]
//
O\tdough\t1
S\tmixed
S\tcontains\t{flour,water}
S\tin\t[bowl]
M\tknead\t<Assumed>
O\tpizza dough\t1
S\tkneaded
S\tcontains\t{flour,water}
S\tin\t[bowl]
//
O\tpizza dough\t1
S\tkneaded
S\tcontains\t{flour,water}
S\tin\t[bowl]
O\tpizza pan\t0
S\tempty
M\tpick-and-place\t<Assumed>
O\tpizza\t1
S\tuncooked
S\tcontains\t{flour,water}
S\tin\t[pizza pan]
//
O\tpizza\t1
S\tuncooked
S\tcontains\t{flour,water}
S\tin\t[pizza pan]
O\toven\t0
S\ton
M\tbake\t<Assumed>
O\tcheese pizza\t1\t3
S\tbaked
S\tcontains\t{flour,water}
S\tin\t[pizza pan]
//
";

#[test]
fn a_bread_made_through_a_pizzas_tree_is_never_called_a_pizza_on_the_way() {
    let p = plan_of(
        &[("pizza.txt", PIZZA)],
        &ExactMatch,
        &query("bread", &[("flour", "powder"), ("water", "liquid")]),
    );
    assert_eq!(p.goal.label, "bread");
    let states = line_states(&p, "flour");
    assert!(
        states.iter().any(|s| s.contains("in bread dough")),
        "{states:?}"
    );
    assert!(states.iter().all(|s| !s.contains("pizza")), "{states:?}");
    // the pizza's own tree keeps its names
    let pizza = plan_of(
        &[("pizza.txt", PIZZA)],
        &ExactMatch,
        &query("pizza", &[("flour", "powder"), ("water", "liquid")]),
    );
    assert!(line_states(&pizza, "flour")
        .iter()
        .any(|s| s.contains("in pizza dough")));
}

/// Elsewhere in FOON: a zucchini chopped.
const ZUCCHINI: &str = "//
O\tzucchini\t1
S\twhole
O\tknife\t1
M\tchop\t<Assumed>
O\tzucchini\t1
S\tchopped
//
";

#[test]
fn a_stir_frys_vegetables_go_into_its_pan_not_into_the_sauce_mixed_apart() {
    // minced garlic in the sauce would draw the chopped zucchini to it as a food of its kind
    let rice = FRIED_RICE.replace(
        "O\tsoy sauce\t1\nS\tliquid\nM\tmix",
        "O\tsoy sauce\t1\nS\tliquid\nO\tgarlic\t1\nS\tminced\nM\tmix",
    );
    let p = plan_of(
        &[("rice.txt", &rice), ("zucchini.txt", ZUCCHINI)],
        &ExactMatch,
        &query(
            "rice",
            &[
                ("rice", "cooked"),
                ("soy sauce", "liquid"),
                ("garlic", "minced"),
                ("zucchini", "chopped"),
            ],
        ),
    );
    let states = line_states(&p, "zucchini");
    assert!(states.iter().all(|s| !s.contains("sauce")), "{states:?}");
    assert!(
        states.last().unwrap().contains("in fried rice"),
        "{states:?}"
    );
    // the soy sauce still goes into the sauce
    assert!(line_states(&p, "soy sauce")
        .iter()
        .any(|s| s.contains("in sauce")));
}

/// A soup (class 1): broth in a pot, peppercorns ground from the mill into it; elsewhere in FOON cumin is
/// ground on its own (what makes "ground").
const PEPPERED_SOUP: &str = "//
O\tbroth\t1
S\tliquid
S\tin\t[pot]
O\tpepper\t1
S\tpeppercorn
S\tin\t[pepper mill]
M\tgrind\t<Assumed>
O\tsoup\t1\t1
S\tcontains\t{broth,pepper}
S\tin\t[pot]
//
O\tcumin\t1
S\twhole
O\tmortar\t0
M\tgrind\t<Assumed>
O\tcumin\t1
S\tground
//
";

#[test]
fn peppercorns_ground_into_the_soup_are_ground_as_they_join_not_ground_twice() {
    let files = [("soup.txt", PEPPERED_SOUP)];
    let p = plan_of(
        &files,
        &ExactMatch,
        &query("soup", &[("broth", "liquid"), ("pepper", "ground")]),
    );
    assert_eq!(line_motions(&p, "pepper"), ["grind"], "{:#?}", p.units);
    let reason = outcome(&p, "pepper").reason.as_deref().unwrap();
    assert!(
        reason.contains("given as it joins the dish: 'grind'"),
        "{reason}"
    );
    // a diced (fresh) pepper asked too shares the one line: it is not chopped into the ground one
    let both = plan_of(
        &files,
        &ExactMatch,
        &query(
            "soup",
            &[
                ("broth", "liquid"),
                ("pepper", "diced"),
                ("pepper", "ground"),
            ],
        ),
    );
    assert_eq!(
        line_motions(&both, "pepper"),
        ["grind"],
        "{:#?}",
        both.units
    );
}

/// Elsewhere in FOON: chips poured from their packet, no state said of them.
const CHIPS: &str = "//
O\tchip\t1
S\tin\t[packet]
O\tbowl\t0
S\tempty
M\tpour\t<Assumed>
O\tchip\t1
S\tin\t[bowl]
//
";

#[test]
fn a_food_foon_says_no_state_of_starts_as_it_was_asked_not_blank() {
    let p = plan_of(
        &[("salad.txt", LETTUCE_SALAD), ("chips.txt", CHIPS)],
        &ExactMatch,
        &query("salad", &[("lettuce", "chopped"), ("chip", "pieces")]),
    );
    assert_eq!(
        line_states(&p, "chip").first(),
        Some(&"pieces"),
        "{:#?}",
        p.units
    );
    // a liquid's coarse word is shown as the liquid it is
    let p = plan_of(
        &[
            ("salad.txt", LETTUCE_SALAD),
            ("chips.txt", &CHIPS.replace("chip", "fat")),
        ],
        &ExactMatch,
        &query("salad", &[("lettuce", "chopped"), ("fat", "juice")]),
    );
    assert_eq!(
        line_states(&p, "fat").first(),
        Some(&"liquid"),
        "{:#?}",
        p.units
    );
}

/// A drink (class 9) of milk poured into a glass: no blender; elsewhere in FOON a banana is chopped and
/// a smoothie blended.
const MILK_DRINK: &str = "//
O\tmilk\t1
S\tliquid
S\tin\t[carton]
O\tglass\t0
S\tempty
M\tpour\t<Assumed>
O\tmilk drink\t1\t9
S\tliquid
S\tcontains\t{milk}
S\tin\t[glass]
//
";
const BANANA: &str = "//
O\tbanana\t1
S\twhole
O\tknife\t1
M\tchop\t<Assumed>
O\tbanana\t1
S\tchopped
//
O\tbanana\t1
S\tchopped
O\tblender\t0
M\tblend\t<Assumed>
O\tsmoothie\t1
S\tblended
S\tcontains\t{banana}
//
";

#[test]
fn a_banana_joins_a_drink_without_a_blender_blended_not_in_pieces() {
    let p = plan_of(
        &[("drink.txt", MILK_DRINK), ("banana.txt", BANANA)],
        &ExactMatch,
        &query("drinks", &[("milk", "liquid"), ("banana", "chopped")]),
    );
    assert_eq!(
        line_motions(&p, "banana"),
        ["peel", "chop", "blend", "pour"],
        "{:#?}",
        p.units
    );
    assert!(line_states(&p, "banana").contains(&"blended"));
}

/// Elsewhere in FOON: a thyme sprig laid on a board.
const THYME_SPRIG: &str = "//
O\tthyme\t1
S\tsprig
O\tcutting board\t0
S\tempty
M\tpick-and-place\t<Assumed>
O\tthyme\t1
S\tsprig
S\ton\t[cutting board]
//
";

/// "dried thyme" is like thyme; nothing else is alike.
struct DriedHerb;

impl foon_core::similarity::Similarity for DriedHerb {
    fn similarity(&self, a: &str, b: &str) -> f32 {
        match (a, b) {
            _ if a == b => 1.0,
            ("dried thyme", "thyme") | ("thyme", "dried thyme") => 0.9,
            _ => 0.0,
        }
    }
}

#[test]
fn a_herb_read_as_dried_is_bought_crumbled_not_a_fresh_sprig() {
    // thyme "ground" is dried thyme from a jar: no woody sprig goes into the salad
    let p = plan_of(
        &[("salad.txt", LETTUCE_SALAD), ("foods.txt", THYME_SPRIG)],
        &DriedHerb,
        &query("salad", &[("lettuce", "chopped"), ("thyme", "ground")]),
    );
    let line = p
        .progress_lines
        .iter()
        .find(|l| l.ingredient == "thyme")
        .unwrap();
    assert_eq!(line.state[0].physical_state, "ground", "{line:#?}");
    assert!(
        line.state
            .iter()
            .all(|s| !s.physical_state.contains("sprig")),
        "{line:#?}"
    );
}

/// Elsewhere in FOON: a bell pepper diced.
const BELL_PEPPER: &str = "//
O\tbell pepper\t1
S\twhole
O\tknife\t1
S\tclean
M\tdice\t<Assumed>
O\tbell pepper\t1
S\tdiced
//
";

#[test]
fn a_name_asked_as_two_foods_plans_both() {
    // "pepper" diced is a bell pepper, "pepper" ground black pepper: two foods, two lines
    let p = plan_of(
        &[
            ("salad.txt", LETTUCE_SALAD),
            ("foods.txt", BELL_PEPPER),
            ("pepper.txt", BLACK_PEPPER),
        ],
        &ExactMatch,
        &query(
            "salad",
            &[
                ("lettuce", "chopped"),
                ("pepper", "diced"),
                ("pepper", "ground"),
            ],
        ),
    );
    let line = |name: &str| {
        p.progress_lines
            .iter()
            .find(|l| l.ingredient == name)
            .unwrap_or_else(|| panic!("no line for {name}: {:#?}", p.progress_lines))
    };
    let pepper = line("pepper");
    assert!(
        pepper.state.iter().any(|s| s.physical_state == "diced"),
        "{pepper:#?}"
    );
    assert!(pepper.state.iter().all(|s| s.physical_state != "ground"));
    let black = line("black pepper");
    assert_eq!(black.state[0].physical_state, "ground", "{black:#?}");
    assert!(black.end_product.contains("salad"), "{black:#?}");
    assert!(
        p.notes.iter().any(|n| n.contains("more than one food")),
        "{:?}",
        p.notes
    );
}

/// A salad (class 15): cherry tomatoes taken off their stems into a strainer, washed there, quartered,
/// and mixed with chopped lettuce.
const QUARTERED_TOMATOES: &str = "//
O\tcherry tomato\t1
S\twhole
S\tin\t[packet]
O\tstrainer\t0
S\tempty
M\tpick-and-place\t<Assumed>
O\tcherry tomato\t1
S\tdestemmed
S\tin\t[strainer]
O\tstrainer\t0
S\tcontains\t{cherry tomato}
//
O\tcherry tomato\t1
S\tdestemmed
S\tin\t[strainer]
O\tfaucet\t0
S\ton
M\twash\t<Assumed>
O\tcherry tomato\t1
S\tdestemmed
S\twashed
S\tin\t[strainer]
//
O\tcherry tomato\t1
S\tdestemmed
S\twashed
S\tin\t[strainer]
O\tknife\t1
M\tcut\t<Assumed>
O\tcherry tomato\t1
S\tquartered
//
O\tsalad bowl\t0
S\tempty
O\tcherry tomato\t1
S\tquartered
O\tlettuce\t1
S\tchopped
M\tmix\t<Assumed>
O\tgreen salad\t1\t15
S\tmixed
S\tcontains\t{cherry tomato,lettuce}
S\tin\t[salad bowl]
//
";

#[test]
fn a_cut_asked_replaces_the_trees_cut_not_its_trim() {
    // asked chopped, the tomatoes are still taken off their stems and washed whole; the quartering
    // becomes the chopping (not a chop before the wash)
    let p = plan_of(
        &[("salad.txt", QUARTERED_TOMATOES), ("foods.txt", PREPARED)],
        &ExactMatch,
        &query(
            "salad",
            &[("lettuce", "chopped"), ("cherry tomato", "chopped")],
        ),
    );
    let line = p
        .progress_lines
        .iter()
        .find(|l| l.ingredient == "cherry tomato")
        .unwrap();
    let states: Vec<&str> = line
        .state
        .iter()
        .map(|s| s.physical_state.as_str())
        .collect();
    assert_eq!(
        states,
        [
            "whole",
            "destemmed",
            "destemmed, washed",
            "chopped",
            "in salad"
        ],
        "{line:#?}"
    );
}

/// A drink (class 9): cherries washed in their bowl, poured into the blender cup that holds the sliced
/// banana, and blended with it.
const CHERRY_SHAKE: &str = "//
O\tcherry\t1
S\twhole
S\tin\t[bowl]
O\tfaucet\t0
S\ton
M\twash\t<Assumed>
O\tcherry\t1
S\twashed
S\tin\t[bowl]
//
O\tblender cup\t0
S\tcontains\t{banana}
O\tcherry\t1
S\twashed
S\tin\t[bowl]
M\tpour\t<Assumed>
O\tblender cup\t0
S\tcontains\t{banana,cherry}
O\tcherry\t1
S\twashed
S\tin\t[blender cup]
//
O\tblender cup\t0
S\tcontains\t{banana,cherry}
O\tcherry\t1
S\twashed
S\tin\t[blender cup]
O\tbanana\t1
S\tsliced
S\tin\t[blender cup]
M\tblend\t<Assumed>
O\tsmoothie\t1\t9
S\tblended
S\tcontains\t{banana,cherry}
S\tin\t[blender cup]
//
";

#[test]
fn a_stone_comes_out_before_the_fruit_meets_the_other_foods() {
    // the cherries are pitted in their bowl, not in the blender cup beside the banana
    let p = plan_of(
        &[("drink.txt", CHERRY_SHAKE)],
        &ExactMatch,
        &query("drinks", &[("cherry", "whole"), ("banana", "sliced")]),
    );
    let line = p
        .progress_lines
        .iter()
        .find(|l| l.ingredient == "cherry")
        .unwrap();
    let pit = line.motion.iter().position(|m| m == "pit");
    let pour = line.motion.iter().position(|m| m == "pour");
    assert!(pit.is_some() && pit < pour, "{line:#?}");
    // and they stay pitted in the cup
    assert_eq!(
        line.state[line.state.len() - 2].physical_state,
        "pitted",
        "{line:#?}"
    );
}

/// A drink (class 9): strawberries washed in their bowl under the faucet's water, then poured into the
/// blender cup with the milk and blended.
const WASHED_BERRY_SHAKE: &str = "//
O\tfaucet\t1
S\ton
O\twater\t0
S\tliquid
S\tfrom\t[faucet]
O\tbowl\t0
S\tcontains\t{strawberry}
O\tstrawberry\t1
S\twhole
S\tin\t[bowl]
M\twash\t<Assumed>
O\tstrawberry\t1
S\twhole
S\twashed
S\tin\t[bowl]
//
O\tblender cup\t0
S\tcontains\t{milk}
O\tstrawberry\t1
S\twhole
S\twashed
S\tin\t[bowl]
M\tpour\t<Assumed>
O\tblender cup\t0
S\tcontains\t{milk,strawberry}
O\tstrawberry\t1
S\twashed
S\tin\t[blender cup]
//
O\tblender cup\t0
S\tcontains\t{milk,strawberry}
O\tstrawberry\t1
S\twashed
S\tin\t[blender cup]
O\tmilk\t1
S\tliquid
S\tin\t[blender cup]
M\tblend\t<Assumed>
O\tsmoothie\t1\t9
S\tblended
S\tcontains\t{milk,strawberry}
S\tin\t[blender cup]
//
";

/// A cherry is like a strawberry; nothing else is alike.
struct BerryLike;

impl foon_core::similarity::Similarity for BerryLike {
    fn similarity(&self, a: &str, b: &str) -> f32 {
        match (a, b) {
            _ if a == b => 1.0,
            ("cherry", "strawberry") | ("strawberry", "cherry") => 0.8,
            _ => 0.0,
        }
    }
}

#[test]
fn a_copied_branch_takes_the_wash_along_and_joins_where_the_original_does() {
    // the cherries get the strawberries' handling (washed in the faucet's water) and go into the
    // blender cup with them, not into the strawberries' wash, which gives back only strawberries
    let p = plan_of(
        &[("drink.txt", WASHED_BERRY_SHAKE)],
        &BerryLike,
        &query(
            "drinks",
            &[
                ("strawberry", "whole"),
                ("cherry", "whole"),
                ("milk", "liquid"),
            ],
        ),
    );
    let line = p
        .progress_lines
        .iter()
        .find(|l| l.ingredient == "cherry")
        .unwrap();
    assert!(line.motion.iter().any(|m| m == "wash"), "{line:#?}");
    let last = &line.state[line.state.len() - 1];
    assert_eq!(last.physical_state, "in smoothie", "{line:#?}");
}

/// Elsewhere in FOON: an orange squeezed into juice, a mushroom as bought, a dressing stirred.
const JUICED_ORANGE: &str = "//
O\tsalad dressing\t1
S\tliquid
O\tspoon\t1
M\tstir\t<Assumed>
O\tsalad dressing\t1
S\tmixed
//
O\torange\t1
S\twhole
O\tjuicer\t1
M\tsqueeze\t<Assumed>
O\torange\t1
S\tjuice
//
O\tmushroom\t1
S\twhole
O\tcutting board\t0
S\tempty
M\tpick-and-place\t<Assumed>
O\tmushroom\t1
S\twhole
S\ton\t[cutting board]
//
";

#[test]
fn a_coarse_word_of_the_recipe_data_is_not_made_by_a_motion() {
    // a mushroom "juice" is a wet ingredient, not squeezed into juice; it is sliced as a cook would
    let p = plan_of(
        &[("salad.txt", LETTUCE_SALAD), ("foods.txt", JUICED_ORANGE)],
        &ExactMatch,
        &query("salad", &[("lettuce", "chopped"), ("mushroom", "juice")]),
    );
    let line = p
        .progress_lines
        .iter()
        .find(|l| l.ingredient == "mushroom")
        .unwrap();
    assert!(
        line.state.iter().all(|s| s.physical_state != "juice"),
        "{line:#?}"
    );
    // mixed berries are a bag of them: cherries "mixed" are not stirred on their own
    let p = plan_of(
        &[("drink.txt", CHERRY_SHAKE), ("foods.txt", JUICED_ORANGE)],
        &ExactMatch,
        &query("drinks", &[("cherry", "mixed"), ("banana", "sliced")]),
    );
    assert!(
        !line_motions(&p, "cherry").contains(&"stir"),
        "{:#?}",
        p.progress_lines
    );
}
