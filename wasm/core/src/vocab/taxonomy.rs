//! The project's own vocabularies: the 30 dish classes with their keywords, and the utensils,
//! containers and appliances that are never ingredients. Both are project files under `data/`.

use crate::foon::label::{fold, normalize_label};
use rustc_hash::FxHashSet as HashSet;
use std::sync::OnceLock;

const DISH_CLASSES_TSV: &str = include_str!("../../data/dish_classes.tsv");
const UTENSILS_TXT: &str = include_str!("../../data/utensils.txt");

/// One dish class: its index (the number on FOON goal lines), name and keywords.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct DishClass {
    pub index: u32,
    pub name: String,
    /// `name` in normal form, as dish types are compared with it.
    pub normal_name: String,
    pub keywords: Vec<String>,
    /// Classes made the same way, whose recipes may serve as reference when none of this one fits.
    pub kin: Vec<String>,
}

/// The rows of one of the project's data files: lines trimmed, without blank lines and `#` comments.
pub(crate) fn data_lines(text: &str) -> impl Iterator<Item = &str> {
    text.lines()
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.starts_with('#'))
}

/// The dish taxonomy, in index order.
pub fn dish_classes() -> &'static [DishClass] {
    static CLASSES: OnceLock<Vec<DishClass>> = OnceLock::new();
    CLASSES.get_or_init(|| {
        data_lines(DISH_CLASSES_TSV)
            .filter_map(|line| {
                let mut parts = line.split('\t');
                let index = parts.next()?.parse().ok()?;
                let name = parts.next()?.to_string();
                let mut list = || -> Vec<String> {
                    parts
                        .next()
                        .unwrap_or("")
                        .split(',')
                        .map(normalize_label)
                        .filter(|k| !k.is_empty() && k != "-")
                        .collect()
                };
                let keywords = list();
                let kin = list();
                Some(DishClass {
                    index,
                    normal_name: normalize_label(&name),
                    name,
                    keywords,
                    kin,
                })
            })
            .collect()
    })
}

fn dish_class(index: u32) -> Option<&'static DishClass> {
    dish_classes().iter().find(|c| c.index == index)
}

/// The indices of the classes kin to class `index` (`DishClass::kin`).
pub fn kin_classes(index: u32) -> impl Iterator<Item = u32> {
    let kin = dish_class(index).map_or(&[][..], |c| &c.kin[..]);
    kin.iter().filter_map(|k| {
        let class = dish_classes().iter().find(|c| &c.normal_name == k);
        class.map(|c| c.index)
    })
}

pub fn dish_class_name(index: u32) -> Option<&'static str> {
    dish_class(index).map(|c| c.name.as_str())
}

/// Maps a dish type or a dish title ("drinks", "Greek salads", "chicken noodle soup") to a class.
/// An exact class name or keyword wins; otherwise the keyword found last in the title (the head noun
/// of "chicken noodle soup" is "soup"), longest keyword first at the same place.
pub fn dish_class_of(text: &str) -> Option<u32> {
    let wanted = normalize_label(text);
    if wanted.is_empty() {
        return None;
    }
    let classes = dish_classes();
    if let Some(c) = classes.iter().find(|c| c.normal_name == wanted) {
        return Some(c.index);
    }
    if let Some(c) = classes.iter().find(|c| c.keywords.contains(&wanted)) {
        return Some(c.index);
    }
    let words: Vec<String> = fold(text)
        .split(' ')
        .map(crate::foon::label::singular)
        .collect();
    let joined = format!(" {} ", words.join(" "));
    // (end position, keyword length) of a keyword found in the title; ties to the first class
    let found = |k: &String| Some((joined.rfind(&format!(" {k} "))? + k.len(), k.len()));
    (classes.iter())
        .flat_map(|c| c.keywords.iter().map(move |k| (c.index, k)))
        .filter_map(|(c, k)| Some((found(k)?, c)))
        .reduce(|best, next| if next.0 > best.0 { next } else { best })
        .map(|(_, c)| c)
}

/// Labels that are utensils, containers or appliances rather than ingredients (Fx hashing: the planner
/// asks this of nearly every node it touches).
pub fn utensils() -> &'static HashSet<String> {
    static UTENSILS: OnceLock<HashSet<String>> = OnceLock::new();
    UTENSILS.get_or_init(|| data_lines(UTENSILS_TXT).map(normalize_label).collect())
}

pub fn is_utensil(label: &str) -> bool {
    utensils().contains(label)
}

/// Motions that only take a food apart or off: what comes out is still that food (chopped onion is
/// onion). Cuts that may name their pieces (a cake cut into slices, dough cut into noodles) are not here.
const SEPARATING_MOTIONS: &[&str] = &["chop", "dice", "julienne", "mince", "peel"];

pub fn is_separating_motion(motion: &str) -> bool {
    SEPARATING_MOTIONS.contains(&motion)
}

/// Motions that put their object somewhere.
pub const PUT_MOTIONS: &[&str] = &["pick-and-place", "place", "put inside", "insert"];

/// With `PUT_MOTIONS`, the motions that only move food from one place to another.
const OTHER_TRANSFER_MOTIONS: &[&str] = &[
    "add",
    "fill",
    "measure",
    "pour",
    "put",
    "remove",
    "scoop",
    "scrape",
    "sprinkle",
    "take out",
    "throw away",
    "transfer",
];

/// Whether a motion only moves food; with `and`, every part does (`scoop and pour`; `pour and stir`
/// stirs). Such a motion never changes what state a food is in, whatever a file records.
pub fn is_transfer_motion(motion: &str) -> bool {
    motion.split(" and ").all(|part| {
        let part = part.trim_end_matches('*');
        PUT_MOTIONS.contains(&part) || OTHER_TRANSFER_MOTIONS.contains(&part)
    })
}

/// Motions that work on everything a vessel holds at once (a blend, a whisk, a stir).
const MIXING_MOTIONS: &[&str] = &[
    "mix", "blend", "beat", "whisk", "stir", "fold", "mash", "combine",
];

/// Whether some part of a motion mixes (`cook and stir`, `mix and mash`).
pub fn is_mixing_motion(motion: &str) -> bool {
    motion
        .split(" and ")
        .any(|part| MIXING_MOTIONS.contains(&part.trim_end_matches('*')))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_kin_class_is_a_class() {
        for c in dish_classes() {
            assert_eq!(
                kin_classes(c.index).count(),
                c.kin.len(),
                "dish_classes.tsv: a kin class of '{}' is not a class: {:?}",
                c.name,
                c.kin
            );
        }
        let bread = dish_class_of("bread").unwrap();
        assert!(kin_classes(bread).any(|k| dish_class_name(k) == Some("pizza")));
    }

    #[test]
    fn has_thirty_classes_in_order() {
        let classes = dish_classes();
        assert_eq!(classes.len(), 30);
        assert!(classes
            .iter()
            .enumerate()
            .all(|(i, c)| c.index as usize == i));
        assert_eq!(dish_class_name(15), Some("salad"));
    }

    #[test]
    fn maps_types_and_titles_to_classes() {
        assert_eq!(dish_class_of("salad"), Some(15));
        assert_eq!(dish_class_of("Drinks"), Some(9));
        assert_eq!(dish_class_of("smoothies"), Some(9));
        assert_eq!(dish_class_of("omelette"), Some(23));
        assert_eq!(dish_class_of("chicken noodle soup"), Some(1));
        assert_eq!(dish_class_of("blood orange salad"), Some(15));
        assert_eq!(dish_class_of("garlic bread"), Some(0));
        assert_eq!(dish_class_of("spaceship"), None);
        assert_eq!(dish_class_of("  "), None);
    }

    #[test]
    fn utensils_are_not_ingredients() {
        assert!(is_utensil("cutting board"));
        assert!(is_utensil("glass"));
        assert!(!is_utensil("tomato"));
    }

    #[test]
    fn a_motion_mixes_when_one_of_its_parts_does() {
        assert!(is_mixing_motion("blend"));
        assert!(is_mixing_motion("mix*"));
        assert!(is_mixing_motion("cook and stir"));
        assert!(!is_mixing_motion("pour"));
        assert!(!is_mixing_motion("stir fry"));
    }
}
