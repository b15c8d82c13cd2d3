//! Food knowledge the planner reasons with: the physical form of a food (by its category in the food
//! taxonomy), the motions a food of that form cannot take or join a dish by (`data/food_forms.tsv`),
//! which foods must be cooked and how a cook prepares one named only by its category
//! (`data/food_care.tsv`), the motions that cook (`data/heat_motions.txt`) and those that leave a food in
//! a state of their own (`data/motion_states.tsv`), the cook's word for a motion FOON names otherwise
//! (`data/motion_words.tsv`), and which food an ambiguous name means in a given state
//! (`data/food_readings.tsv`).

use crate::contract::plan::Query;
use crate::foon::label::{normalize_label, normalize_word};
use crate::vocab::food_taxonomy::Taxonomy;
use crate::vocab::states;
use rustc_hash::FxHashMap as HashMap;
use std::sync::OnceLock;

const FORMS_TSV: &str = include_str!("../../data/food_forms.tsv");
const CARE_TSV: &str = include_str!("../../data/food_care.tsv");
const HEAT_TXT: &str = include_str!("../../data/heat_motions.txt");
const READINGS_TSV: &str = include_str!("../../data/food_readings.tsv");
const MOTION_STATES_TSV: &str = include_str!("../../data/motion_states.tsv");
const MOTION_WORDS_TSV: &str = include_str!("../../data/motion_words.tsv");

/// A physical form and the motion words it cannot take.
#[derive(Debug)]
pub struct Form {
    pub name: String,
    cannot: Vec<String>,
    joins_not_by: Vec<String>,
    /// State words a food of this form is never in (a paste is not "whole").
    pub never_in: Vec<String>,
    /// The state a food of this form is shown in when it has none ("liquid").
    pub state_when_none: Option<String>,
    /// A food of this form looks cooked once cooked in a vessel (not salt in a pot of rice).
    pub shows_cooking: bool,
    /// The state a food of this form is in once heated, in place of its own ("melted" butter).
    pub heated: Option<String>,
    /// The state a food of this form joins a drink in ("blended" banana), if not as it is.
    pub in_drink: Option<String>,
}

struct Forms {
    forms: Vec<Form>,
    /// Taxonomy category name, or a food's own name, -> index into `forms`.
    by_name: HashMap<String, usize>,
}

fn split_list(list: &str) -> impl Iterator<Item = String> + '_ {
    list.split(',')
        .map(str::trim)
        .filter(|w| !w.is_empty())
        .map(str::to_string)
}

fn parse(text: &str) -> Forms {
    let mut forms = Vec::new();
    let mut by_name = HashMap::default();
    for line in crate::vocab::taxonomy::data_lines(text) {
        let mut parts = line.split('\t');
        let (Some(name), Some(categories), Some(cannot), Some(joins), Some(never), Some(none)) = (
            parts.next(),
            parts.next(),
            parts.next(),
            parts.next(),
            parts.next(),
            parts.next(),
        ) else {
            continue; // a test names the row
        };
        let (Some(shows), Some(heated)) =
            (parts.next().map(str::trim), parts.next().map(str::trim))
        else {
            continue; // a test names the row
        };
        let in_drink = parts.next().map(str::trim).filter(|w| *w != "-");
        for c in split_list(categories) {
            by_name.entry(c).or_insert(forms.len());
        }
        forms.push(Form {
            name: name.trim().to_string(),
            cannot: split_list(cannot).collect(),
            joins_not_by: split_list(joins).filter(|w| w != "-").collect(),
            never_in: split_list(never).filter(|w| w != "-").collect(),
            state_when_none: Some(none.trim()).filter(|w| *w != "-").map(str::to_string),
            shows_cooking: shows != "no",
            heated: Some(heated).filter(|w| *w != "-").map(str::to_string),
            in_drink: in_drink.map(str::to_string),
        });
    }
    Forms { forms, by_name }
}

fn forms() -> &'static Forms {
    static FORMS: OnceLock<Forms> = OnceLock::new();
    FORMS.get_or_init(|| parse(FORMS_TSV))
}

/// The form of a food named `food`: its own where the forms list it (cocoa is a powder, though a
/// chocolate), else its category's in the built-in taxonomy; None when neither is listed.
pub fn form_of(food: &str) -> Option<&'static Form> {
    let f = forms();
    if let Some(&i) = f.by_name.get(food) {
        return Some(&f.forms[i]);
    }
    let taxonomy = Taxonomy::builtin();
    let category = &taxonomy.category(taxonomy.lookup(food)?).name;
    f.by_name.get(category).map(|&i| &f.forms[i])
}

pub fn motion_words(motion: &str) -> impl Iterator<Item = &str> {
    motion.split([' ', '*']).filter(|w| !w.is_empty())
}

/// Whether `food` can take `motion` while it is itself: no word of the motion ("squeeze and scrape")
/// is one its form cannot take. A food of unknown form takes any motion.
pub fn takes(food: &str, motion: &str) -> bool {
    let Some(form) = form_of(food) else {
        return true;
    };
    !motion_words(motion).any(|w| form.cannot.iter().any(|c| c == w))
}

/// Whether `food` can join a dish by `motion` (a liquid is poured in, not picked and placed): it can take
/// the motion and no word of it is one its form does not join by.
pub fn joins_by(food: &str, motion: &str) -> bool {
    takes(food, motion)
        && form_of(food)
            .is_none_or(|f| !motion_words(motion).any(|w| f.joins_not_by.iter().any(|c| c == w)))
}

/// How a food is cooked before it is eaten (`data/food_care.tsv`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Cooking {
    /// Cooked on its own when the dish does not cook it (chicken fried, pasta boiled).
    Alone,
    /// Only ever cooked as part of the dish: it joins before the dish is cooked (flour).
    InDish,
    /// Eaten as it is.
    No,
}

/// What `data/food_care.tsv` says of a food or a category.
struct Care {
    cooking: Option<Cooking>,
    prepared: Option<String>,
    /// The preparation comes before anything else is done to the food.
    first: bool,
    /// Cooked only with water (boiled, simmered, steamed, baked covered): rice is not cooked by
    /// stir-frying it raw.
    wet: bool,
    /// Joins a dish that is cooked before the cooking (stock, a bay leaf, onion).
    heat: bool,
    /// Joins the dish once it is cooked (croutons, grated cheese, chopped parsley, ketchup).
    top: bool,
    /// Joins the dish's mixture before it is cooked (milk beaten with the eggs), not the hot pan.
    mix: bool,
    /// Cooked on its own before it joins, even a dish that is cooked after (bacon fried before it goes
    /// into the eggs).
    brown: bool,
    /// Coats the vessel the dish is cooked in before the dish goes in (cooking spray).
    grease: bool,
    /// Never made into juice: its "juice" is the recipe data's word for a wet ingredient.
    unjuiced: bool,
    /// What a cook takes off it before it is used or cut (an onion's skin, a cherry's stone).
    trims: Vec<&'static Trim>,
}

fn cares() -> &'static HashMap<String, Care> {
    static CARES: OnceLock<HashMap<String, Care>> = OnceLock::new();
    CARES.get_or_init(|| {
        crate::vocab::taxonomy::data_lines(CARE_TSV)
            .filter_map(|line| {
                let mut parts = line.split('\t').map(str::trim);
                let (key, cook, prepared) = (parts.next()?, parts.next()?, parts.next()?);
                let cooking = match cook {
                    "alone" => Some(Cooking::Alone),
                    "in dish" => Some(Cooking::InDish),
                    "no" => Some(Cooking::No),
                    _ => None, // a test names the row
                };
                let flags: Vec<String> =
                    parts.next().map(split_list).into_iter().flatten().collect();
                let care = Care {
                    first: flags.iter().any(|f| f == "first"),
                    wet: flags.iter().any(|f| f == "wet"),
                    heat: flags.iter().any(|f| f == "heat"),
                    top: flags.iter().any(|f| f == "top"),
                    mix: flags.iter().any(|f| f == "mix"),
                    brown: flags.iter().any(|f| f == "brown"),
                    grease: flags.iter().any(|f| f == "grease"),
                    unjuiced: flags.iter().any(|f| f == "unjuiced"),
                    trims: TRIMS
                        .iter()
                        .filter(|t| flags.iter().any(|f| f == t.flag))
                        .collect(),
                    cooking,
                    prepared: (prepared != "-").then(|| prepared.to_string()),
                };
                Some((key.to_string(), care))
            })
            .collect()
    })
}

/// The food's own row, else its taxonomy category's.
fn care_of(food: &str) -> Option<&'static Care> {
    cares().get(food).or_else(|| category_care(food))
}

/// The row of the food's taxonomy category.
fn category_care(food: &str) -> Option<&'static Care> {
    let taxonomy = Taxonomy::builtin();
    cares().get(&taxonomy.category(taxonomy.lookup(food)?).name)
}

/// Whether the food's own row or its category's has a flag (`wet`, `heat`): a category's flag holds for
/// its foods with rows of their own (an onion is peeled, and like every allium cooked with the dish).
fn flagged(food: &str, flag: fn(&Care) -> bool) -> bool {
    cares().get(food).is_some_and(flag) || category_care(food).is_some_and(flag)
}

/// Whether the food knowledge knows `food` (its taxonomy category).
pub fn knows(food: &str) -> bool {
    Taxonomy::builtin().lookup(food).is_some()
}

/// How `food` is cooked before it is eaten; `No` for a food the data does not know.
pub fn cooking(food: &str) -> Cooking {
    care_of(food).and_then(|c| c.cooking).unwrap_or(Cooking::No)
}

/// The kind of food `name` is (its taxonomy category: "egg noodle" and "spaghetti" are pasta), leaving out
/// the names of whole dishes ("soup", "salad").
pub fn kind(name: &str) -> Option<&'static str> {
    let taxonomy = Taxonomy::builtin();
    let category = taxonomy.category(taxonomy.lookup(name)?);
    (category.group != "dish").then_some(category.name.as_str())
}

/// Whether `food` looks cooked once the vessel it is in is cooked: a food that must be cooked does, and
/// so does one of a form that shows cooking (a carrot in a soup; not salt or oil).
pub fn shows_cooking(food: &str) -> bool {
    must_cook(food) || form_of(food).is_none_or(|f| f.shows_cooking)
}

/// The state `food` is in once heated, in place of its own (butter in a hot pan is "melted").
pub fn state_once_heated(food: &str) -> Option<&'static str> {
    form_of(food)?.heated.as_deref()
}

/// Whether `food` is cooked in the dish's pan rather than stirred into a sauce mixed apart for it: a food
/// of a form that shows cooking (zucchini, beef), or of no form that must be cooked (egg); not soy sauce,
/// starch or oil.
pub fn cooks_in_pan(food: &str) -> bool {
    form_of(food).map_or_else(|| must_cook(food), |f| f.shows_cooking)
}

/// The state `food` joins a drink in where it is not in it yet: a fruit or vegetable blended, not in
/// pieces in the glass; none for a garnish (`top`: mint leaves, whipped cream).
pub fn state_in_drink(food: &str) -> Option<&'static str> {
    let form = form_of(food)?;
    form.in_drink.as_deref().filter(|_| !joins_served(food))
}

/// Whether `food` must be cooked before it is eaten (raw chicken, dry pasta, flour).
pub fn must_cook(food: &str) -> bool {
    cooking(food) != Cooking::No
}

/// Whether `food` is cooked on its own before it joins, even a dish that is cooked after (bacon, sausage).
pub fn cooked_first(food: &str) -> bool {
    flagged(food, |c| c.brown)
}

/// Whether `food` greases the vessel the dish is cooked in rather than joining the dish (cooking spray).
pub fn greases(food: &str) -> bool {
    flagged(food, |c| c.grease)
}

/// Whether `food` is never made into juice (a mushroom, a pepper): its "juice" in recipe data names a
/// wet ingredient, not a state a cook brings it to.
pub fn never_juiced(food: &str) -> bool {
    flagged(food, |c| c.unjuiced)
}

/// Whether `food` is never in `state`: a state its form is never in (a paste is not "whole"), or juice
/// of a food never juiced.
pub fn never_in(food: &str, state: &str) -> bool {
    form_of(food).is_some_and(|f| f.never_in.iter().any(|w| w == state))
        || (states::kind(state) == Some("juice") && never_juiced(food))
}

/// Whether `food` joins a dish that is cooked before the cooking, not after it (stock, wine, a bay leaf,
/// onion, carrot): it gives its taste or softens in the heat.
pub fn joins_before_heat(food: &str) -> bool {
    flagged(food, |c| c.heat)
}

/// Whether `food` joins a dish that is cooked only once it is cooked (croutons, grated cheese, chopped
/// parsley, avocado, ketchup, whipped cream): onto the served dish or stirred in after the cooking, never
/// beaten into the eggs or baked in the batter. It wins over its category's `heat` (chives, an allium).
pub fn joins_served(food: &str) -> bool {
    flagged(food, |c| c.top)
}

/// Whether `food` is a liquid of the dish's mixture (milk, cream, water): in a dish that is cooked it
/// joins before the cooking, where the mixture is made (beaten with the eggs, mixed into the batter),
/// not poured into the hot pan beside it. A garnish of its category (sour cream) is not.
pub fn joins_mixed(food: &str) -> bool {
    flagged(food, |c| c.mix) && !joins_served(food)
}

/// The state a cook brings `food` to when a query names only its category ("whole veg" onion: chopped).
pub fn prepared_state(food: &str) -> Option<&'static str> {
    care_of(food)?.prepared.as_deref()
}

/// The preparation `food` gets before anything else is done to it (an egg: cracked), if any.
pub fn prepared_first(food: &str) -> Option<&'static str> {
    care_of(food).filter(|c| c.first)?.prepared.as_deref()
}

/// Something a cook takes off a food before using it: its skin, its stone, its hull, its core.
#[derive(Debug)]
pub struct Trim {
    /// The flag of `data/food_care.tsv`.
    pub flag: &'static str,
    /// The state it leaves the food in.
    pub state: &'static str,
    /// The motion, where FOON has none for the state.
    pub verb: &'static str,
    /// The state word it makes untrue ("unpeeled").
    pub undone: &'static str,
    /// Only before the food is cut (a lemon sliced in its rind is fine; a whole onion is not peeled to be
    /// roasted), else before any use but washing.
    pub before_cut: bool,
}

const TRIMS: &[Trim] = &[
    Trim {
        flag: "peel",
        state: "peeled",
        verb: "peel",
        undone: "unpeeled",
        before_cut: true,
    },
    Trim {
        flag: "core",
        state: "cored",
        verb: "core",
        undone: "uncored",
        before_cut: true,
    },
    Trim {
        flag: "pit",
        state: "pitted",
        verb: "pit",
        undone: "unpitted",
        before_cut: false,
    },
    Trim {
        flag: "hull",
        state: "hulled",
        verb: "hull",
        undone: "unhulled",
        before_cut: false,
    },
];

/// What a cook takes off `food` before it is used, in order (a mango peeled, then pitted).
pub fn trims(food: &str) -> &'static [&'static Trim] {
    care_of(food).map_or(&[], |c| c.trims.as_slice())
}

/// Motion words that cut a food into pieces (a peeled onion chopped, a mango sliced); not grating, which
/// takes an orange's zest from its skin.
const CUTS: &[&str] = &[
    "cut", "chop", "slice", "dice", "mince", "julienne", "cube", "quarter", "halve",
];

/// Motion words that take a food out of what it is bought in, leaving it as it was.
const UNWRAPS: &[&str] = &["unwrap", "unpack", "unbox", "open", "drain"];

/// Whether `motion` only takes a food out of its packaging ("unwrap").
pub fn unwraps(motion: &str) -> bool {
    let m = motion.trim_end_matches('*').trim();
    UNWRAPS.contains(&m)
}

/// Whether `motion` washes what it acts on ("wash", "rinse"), which a cook does before cutting it.
pub fn washes(motion: &str) -> bool {
    motion_words(motion).any(|w| matches!(w, "wash" | "rinse"))
}

/// Whether `motion` cuts what it acts on into pieces ("chop", "cut in half").
pub fn cuts(motion: &str) -> bool {
    motion_words(motion).any(|w| CUTS.contains(&w))
}

/// Motion words that break a food up without a knife: what is peeled before a cut is peeled before these.
const BREAKS_UP: &[&str] = &["mash", "blend", "puree", "grate", "shred", "crush", "grind"];

/// Whether `motion` cuts a food or breaks it up (a banana mashed, ginger grated): its skin comes off first.
pub fn breaks_up(motion: &str) -> bool {
    cuts(motion) || motion_words(motion).any(|w| BREAKS_UP.contains(&w))
}

/// The heat motion words of `data/heat_motions.txt`, each flagged when it cooks in water.
fn heat_words() -> &'static [(&'static str, bool)] {
    static HEAT: OnceLock<Vec<(&'static str, bool)>> = OnceLock::new();
    HEAT.get_or_init(|| {
        crate::vocab::taxonomy::data_lines(HEAT_TXT)
            .filter_map(|l| {
                let mut parts = l.split('\t').map(str::trim);
                Some((parts.next()?, parts.next() == Some("wet")))
            })
            .collect()
    })
}

/// Whether `motion` cooks what it acts on ("bake", "deep fry", "cook and stir").
pub fn cooks(motion: &str) -> bool {
    motion_words(motion).any(|w| heat_words().iter().any(|(h, _)| *h == w))
}

/// Whether `motion` cooks `food`: any heat does, but a food cooked only with water (rice, dry pasta) is
/// cooked by a motion with water or by a plain "cook" (FOON's pot of rice), not fried raw.
pub fn cooks_food(food: &str, motion: &str) -> bool {
    if !flagged(food, |c| c.wet) {
        return cooks(motion);
    }
    motion.trim_end_matches('*').trim() == "cook"
        || motion_words(motion).any(|w| heat_words().iter().any(|&(h, wet)| wet && h == w))
}

/// The state `motion` leaves a food in whatever piece it was (`data/motion_states.tsv`: "spread" for
/// butter spread), if it is one that does.
pub fn leaves_in(motion: &str) -> Option<&'static str> {
    static LEAVES: OnceLock<HashMap<&'static str, &'static str>> = OnceLock::new();
    let table = LEAVES.get_or_init(|| {
        crate::vocab::taxonomy::data_lines(MOTION_STATES_TSV)
            .filter_map(|l| l.split_once('\t'))
            .map(|(m, s)| (m.trim(), s.trim()))
            .collect()
    });
    table.get(motion.trim_end_matches('*').trim()).copied()
}

/// The cook's word for `motion` where it gives a food the state `state` (`data/motion_words.tsv`: a
/// broccoli stem peeled by FOON's "skim" is peeled), if FOON names that motion otherwise.
pub fn cooks_word(motion: &str, state: &str) -> Option<&'static str> {
    static WORDS: OnceLock<HashMap<(&'static str, &'static str), &'static str>> = OnceLock::new();
    let table = WORDS.get_or_init(|| {
        crate::vocab::taxonomy::data_lines(MOTION_WORDS_TSV)
            .filter_map(|l| {
                let mut parts = l.split('\t').map(str::trim);
                Some(((parts.next()?, parts.next()?), parts.next()?))
            })
            .collect()
    });
    table.get(&(motion, state)).copied()
}

/// (name, asked state) -> the food meant, in normal form.
fn readings() -> &'static HashMap<(String, String), String> {
    static READINGS: OnceLock<HashMap<(String, String), String>> = OnceLock::new();
    READINGS.get_or_init(|| {
        let mut map = HashMap::default();
        for line in crate::vocab::taxonomy::data_lines(READINGS_TSV) {
            let mut parts = line.split('\t').map(str::trim);
            let (Some(name), Some(states), Some(reading)) =
                (parts.next(), parts.next(), parts.next())
            else {
                continue; // a test names the row
            };
            for state in split_list(states) {
                let key = (normalize_label(name), normalize_word(&state));
                map.entry(key).or_insert_with(|| normalize_label(reading));
            }
        }
        map
    })
}

/// The food an ambiguous name means in the asked state ("pepper", "diced": bell pepper), if the data
/// lists it; both arguments in normal form.
pub fn reading(food: &str, state: &str) -> Option<&'static str> {
    readings()
        .get(&(food.to_string(), state.to_string()))
        .map(String::as_str)
}

/// The food each asked name stands for where its state says (`foods::reading`). A planned query names
/// one food by one name (a name asked as two foods is split before planning), so its entries agree.
pub fn query_readings(query: &Query) -> HashMap<String, &'static str> {
    query
        .ingredients
        .iter()
        .filter_map(|ing| Some((ing.object.clone(), reading(&ing.object, &ing.state)?)))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn foods_cannot_take_motions_their_form_rules_out() {
        for (food, motion) in [
            ("flour", "squeeze"),
            ("granulated sugar", "squeeze and scrape"),
            ("butter", "grind"),
            ("margarine", "squeeze"),
            ("vodka", "bake"),
            ("tomato", "crack"),
            ("spaghetti", "bake"),
            ("caper", "squeeze"),
            ("kalamata olive", "peel"),
        ] {
            assert!(!takes(food, motion), "{food} should not take '{motion}'");
        }
        for (food, motion) in [
            ("lemon", "squeeze"),
            ("onion", "chop"),
            ("butter", "melt"),
            ("nutmeg", "grind"),
            ("cheddar", "grate"),
            ("flour", "sift"),
            ("milk", "pour"),
            // a garlic press, a salt mill, a squeeze bottle
            ("garlic", "squeeze"),
            ("salt", "grind"),
            ("mustard", "squeeze"),
            ("unheard-of food", "squeeze"),
        ] {
            assert!(takes(food, motion), "{food} should take '{motion}'");
        }
    }

    #[test]
    fn liquids_and_powders_join_a_dish_poured_or_mixed_not_placed() {
        for (food, motion) in [
            ("milk", "pick-and-place"),
            ("flour", "spread"),
            ("salt", "pick-and-place"),
        ] {
            assert!(
                !joins_by(food, motion),
                "{food} should not join by '{motion}'"
            );
        }
        for (food, motion) in [
            ("milk", "pour"),
            ("flour", "mix"),
            ("salt", "sprinkle"),
            ("onion", "pick-and-place"),
        ] {
            assert!(joins_by(food, motion), "{food} should join by '{motion}'");
        }
    }

    #[test]
    fn raw_meat_grains_and_eggs_must_be_cooked_and_produce_need_not() {
        for food in [
            "chicken breast",
            "ground beef",
            "bacon",
            "rice",
            "spaghetti",
            "egg",
            "flour",
            "potato",
        ] {
            assert!(must_cook(food), "{food} must be cooked");
        }
        for food in [
            "ham",
            "lettuce",
            "tomato",
            "cheddar",
            "salt",
            "unheard-of food",
        ] {
            assert!(!must_cook(food), "{food} need not be cooked");
        }
        assert_eq!(cooking("chicken breast"), Cooking::Alone);
        assert_eq!(cooking("flour"), Cooking::InDish);
        assert!(cooks("deep fry") && cooks("cook and stir") && cooks("bake"));
        assert!(!cooks("mix") && !cooks("pick-and-place"));
    }

    #[test]
    fn a_food_named_by_its_category_is_prepared_as_a_cook_does() {
        assert_eq!(prepared_state("onion"), Some("chopped"));
        assert_eq!(prepared_state("egg"), Some("cracked"));
        assert_eq!(prepared_state("mango"), Some("sliced"));
        assert_eq!(prepared_state("ham"), Some("sliced"));
        assert_eq!(prepared_state("salt"), None);
        assert_eq!(prepared_state("blueberry"), None);
        assert_eq!(prepared_first("egg"), Some("cracked"));
        assert_eq!(prepared_first("onion"), None);
        let flags = |food: &str| trims(food).iter().map(|t| t.flag).collect::<Vec<_>>();
        assert_eq!(
            (flags("red onion"), flags("mango")),
            (vec!["peel"], vec!["peel", "pit"])
        );
        assert_eq!(
            (flags("cherry"), flags("strawberry")),
            (vec!["pit"], vec!["hull"])
        );
        assert!(flags("lemon").is_empty() && flags("leek").is_empty() && flags("egg").is_empty());
    }

    #[test]
    fn every_care_row_is_a_taxonomy_category_or_food() {
        let taxonomy = Taxonomy::builtin();
        for (key, care) in cares() {
            assert!(
                care.cooking.is_some(),
                "food_care.tsv: '{key}' has no cooking of alone, in dish, no"
            );
            let known = taxonomy.categories.iter().any(|c| &c.name == key)
                || taxonomy.lookup(key).is_some();
            assert!(
                known,
                "food_care.tsv names '{key}', which food_taxonomy.tsv lacks"
            );
        }
    }

    #[test]
    fn every_form_row_has_its_eight_columns_and_every_care_flag_is_known() {
        let rows = crate::vocab::taxonomy::data_lines(FORMS_TSV).count();
        assert_eq!(
            forms().forms.len(),
            rows,
            "food_forms.tsv: a row lacks a column"
        );
        for line in crate::vocab::taxonomy::data_lines(CARE_TSV) {
            for flag in line
                .split('\t')
                .nth(3)
                .map(split_list)
                .into_iter()
                .flatten()
            {
                assert!(
                    matches!(
                        flag.as_str(),
                        "first" | "wet" | "heat" | "top" | "mix" | "brown" | "grease" | "unjuiced"
                    ) || TRIMS.iter().any(|t| t.flag == flag),
                    "food_care.tsv: flag '{flag}' in {line}"
                );
            }
        }
        let paste = form_of("tahini").unwrap();
        assert!(paste.never_in.iter().any(|s| s == "powder"));
        assert_eq!(paste.state_when_none.as_deref(), Some("paste"));
        assert_eq!(form_of("cheddar").unwrap().state_when_none, None);
        assert_eq!(cooks_word("skim", "peeled"), Some("peel"));
        assert_eq!(cooks_word("skim", "skimmed"), None);
        assert_eq!(cooks_word("flip", "partly cooked"), Some("cook and flip"));
        assert_eq!(cooks_word("flip", "cooked"), Some("cook"));
        assert_eq!(cooks_word("flip", "flipped"), None);
        // the milk and ice of a glass stirred are not "sprinkled" in
        assert_eq!(cooks_word("sprinkle", "mixed"), Some("stir"));
        assert_eq!(cooks_word("sprinkle", "sprinkled"), None);
        assert!(!shows_cooking("salt") && !shows_cooking("olive oil"));
        assert_eq!(state_once_heated("butter"), Some("melted"));
        assert_eq!(state_once_heated("olive oil"), None);
        assert!(cooked_first("bacon") && cooked_first("italian sausage"));
        assert!(greases("cooking spray") && !greases("olive oil"));
        assert!(joins_served("jelly") && !joins_served("cherry pie filling"));
        assert!(joins_before_heat("thyme") && joins_before_heat("cumin"));
        // a mushroom or a pepper asked "juice" is not blended to one; an orange or a tomato is juiced
        assert!(never_juiced("mushroom") && never_juiced("pimento") && never_juiced("onion"));
        assert!(!never_juiced("orange") && !never_juiced("tomato") && !never_juiced("apple"));
        // sugar and a curry powder dissolve in a broth that cooks, not on the served ramen
        assert!(joins_before_heat("curry powder") && joins_before_heat("sugar"));
        // vegetables a cooked dish cooks (the ramen's cauliflower into the broth), not the raw cucumber
        assert!(joins_before_heat("cauliflower") && joins_before_heat("mushroom"));
        assert!(joins_served("cucumber") && !joins_served("zucchini"));
        assert!(joins_before_heat("dried basil") && !joins_before_heat("basil"));
        assert!(!cooked_first("chicken breast") && !cooked_first("ground beef"));
        assert!(shows_cooking("carrot") && shows_cooking("flour") && shows_cooking("rice"));
        // a garnish joins the served dish; its flag wins over its category's heat (chives, an allium)
        assert!(joins_served("cheddar") && joins_served("feta") && joins_served("chive"));
        assert!(
            joins_served("glaze") && joins_served("frosting") && joins_served("powdered sugar")
        );
        assert!(!joins_served("sugar") && !joins_served("brown sugar"));
        assert!(!joins_served("cream cheese") && !joins_served("onion") && !joins_served("thyme"));
        assert!(joins_mixed("half and half") && joins_mixed("heavy cream") && joins_mixed("water"));
        assert!(
            !joins_mixed("sour cream") && !joins_mixed("ice cream") && !joins_mixed("olive oil")
        );
    }

    #[test]
    fn every_listed_category_or_food_is_in_the_taxonomy() {
        let taxonomy = Taxonomy::builtin();
        for name in forms().by_name.keys() {
            assert!(
                taxonomy.categories.iter().any(|c| &c.name == name)
                    || taxonomy.lookup(name).is_some(),
                "food_forms.tsv names '{name}', which food_taxonomy.tsv lacks"
            );
        }
    }

    #[test]
    fn a_food_listed_by_name_has_its_own_form_not_its_categorys() {
        assert_eq!(form_of("cocoa").map(|f| f.name.as_str()), Some("powder"));
        assert_eq!(
            form_of("cocoa powder").map(|f| f.name.as_str()),
            Some("powder")
        );
        assert_eq!(
            form_of("dark chocolate").map(|f| f.name.as_str()),
            Some("dry")
        );
        assert!(!takes("cocoa", "chop"));
        // a brand of cream cheese is a soft cheese, never grated
        assert!(!takes("philadelphia", "grate"));
    }

    #[test]
    fn fruit_and_vegetables_join_a_drink_blended_not_a_powder_or_a_garnish() {
        for food in ["banana", "mango", "pumpkin", "spinach", "strawberry"] {
            assert_eq!(state_in_drink(food), Some("blended"), "{food}");
        }
        for food in ["milk", "sugar", "ice", "whipped cream", "cinnamon"] {
            assert_eq!(state_in_drink(food), None, "{food}");
        }
    }

    #[test]
    fn foods_that_cook_in_the_pan_are_not_stirred_into_a_sauce_apart() {
        for food in ["zucchini", "beef", "egg", "cabbage", "shrimp"] {
            assert!(cooks_in_pan(food), "{food}");
        }
        for food in ["soy sauce", "cornstarch", "oil", "salt", "honey"] {
            assert!(!cooks_in_pan(food), "{food}");
        }
    }

    #[test]
    fn a_query_reads_its_names_by_their_states() {
        let query: Query = serde_json::from_str(
            r#"{"type": "soup", "ingredients": [{"object": "basil", "state": "dried"},
               {"object": "coriander", "state": "leaves"}, {"object": "onion", "state": "chopped"}]}"#,
        )
        .unwrap();
        let r = query_readings(&query);
        assert_eq!(
            (r.get("basil"), r.get("coriander")),
            (Some(&"dried basil"), Some(&"cilantro"))
        );
        assert_eq!(r.get("onion"), None);
        let twice: Query = serde_json::from_str(
            r#"{"type": "soup", "ingredients": [{"object": "pepper", "state": "ground"},
               {"object": "pepper", "state": "cracked"}]}"#,
        )
        .unwrap();
        assert_eq!(query_readings(&twice).get("pepper"), Some(&"black pepper"));
        assert!(!takes("dried basil", "chop") && !takes("coriander seed", "chop"));
    }

    #[test]
    fn an_ambiguous_name_is_read_by_its_state() {
        assert_eq!(reading("pepper", "diced"), Some("bell pepper"));
        assert_eq!(reading("pepper", "whole veg"), Some("bell pepper"));
        assert_eq!(reading("pepper", "whole"), Some("bell pepper"));
        assert_eq!(reading("pepper", "sauce"), Some("hot sauce"));
        assert_eq!(reading("cheese", "creamy"), Some("cream cheese"));
        assert_eq!(reading("pepper", "ground"), Some("black pepper"));
        assert_eq!(reading("pepper", "flakes"), Some("red pepper flake"));
        assert_eq!(reading("garlic", "ground"), Some("garlic powder"));
        assert_eq!(reading("lemon", "juice"), Some("lemon juice"));
        assert_eq!(reading("garlic", "minced"), None);
        assert_eq!(reading("onion", "chopped"), None);
        assert_eq!(reading("rib", "chopped"), Some("celery"));
        assert_eq!(reading("rib", "meat"), None);
    }

    #[test]
    fn every_reading_row_is_complete_and_names_a_taxonomy_food() {
        let taxonomy = Taxonomy::builtin();
        for line in crate::vocab::taxonomy::data_lines(READINGS_TSV) {
            let parts: Vec<&str> = line.split('\t').map(str::trim).collect();
            assert_eq!(
                parts.len(),
                3,
                "food_readings.tsv: '{line}' needs 3 columns"
            );
            for food in [parts[0], parts[2]] {
                assert!(
                    taxonomy.lookup(&normalize_label(food)).is_some(),
                    "food_readings.tsv names '{food}', which food_taxonomy.tsv lacks"
                );
            }
        }
    }

    #[test]
    fn a_motion_that_reshapes_a_food_names_a_state_of_the_taxonomy() {
        use crate::vocab::states::{category, Category};
        assert_eq!(leaves_in("spread"), Some("spread"));
        assert_eq!(leaves_in("grind*"), Some("ground"));
        assert_eq!(leaves_in("pour"), None);
        for line in crate::vocab::taxonomy::data_lines(MOTION_STATES_TSV) {
            let (_, state) = line
                .split_once('\t')
                .expect("motion_states.tsv: two columns");
            assert_ne!(
                category(state.trim()),
                Category::Other,
                "motion_states.tsv: '{state}' is not in states.tsv"
            );
        }
    }

    #[test]
    fn rice_and_dry_pasta_are_cooked_only_in_water() {
        assert!(!cooks_food("rice", "cook and stir"));
        assert!(!cooks_food("spaghetti", "fry"));
        assert!(cooks_food("rice", "boil") && cooks_food("rice", "cook"));
        assert!(cooks_food("chicken", "cook and stir"));
    }

    #[test]
    fn a_sauce_or_powder_word_reads_the_name_as_that_product() {
        assert_eq!(reading("fish", "sauce"), Some("fish sauce"));
        assert_eq!(reading("oyster", "thick sauce"), Some("oyster sauce"));
        assert_eq!(reading("curry", "ground"), Some("curry powder"));
        assert_eq!(reading("sprout", "bean"), Some("bean sprout"));
        assert_eq!(reading("cake", "ground"), Some("cake mix"));
        assert_eq!(reading("fish", "fillet"), None);
    }
}
