//! Food knowledge the planner reasons with: the physical form of a food (by its category in the food
//! taxonomy) and the motions a food of that form cannot take (`data/food_forms.tsv`).

use crate::substitute::Taxonomy;
use rustc_hash::FxHashMap as HashMap;
use std::sync::OnceLock;

const FORMS_TSV: &str = include_str!("../data/food_forms.tsv");

/// A physical form and the motion words it cannot take.
#[derive(Debug)]
pub struct Form {
    pub name: String,
    cannot: Vec<String>,
}

struct Forms {
    forms: Vec<Form>,
    /// Taxonomy category name -> index into `forms`.
    of_category: HashMap<String, usize>,
}

fn split_list(list: &str) -> impl Iterator<Item = String> + '_ {
    list.split(',')
        .map(str::trim)
        .filter(|w| !w.is_empty())
        .map(str::to_string)
}

fn parse(text: &str) -> Forms {
    let mut forms = Vec::new();
    let mut of_category = HashMap::default();
    for line in crate::taxonomy::data_lines(text) {
        let mut parts = line.split('\t');
        let (Some(name), Some(categories), Some(cannot)) =
            (parts.next(), parts.next(), parts.next())
        else {
            continue;
        };
        for c in split_list(categories) {
            of_category.entry(c).or_insert(forms.len());
        }
        forms.push(Form {
            name: name.trim().to_string(),
            cannot: split_list(cannot).collect(),
        });
    }
    Forms { forms, of_category }
}

fn forms() -> &'static Forms {
    static FORMS: OnceLock<Forms> = OnceLock::new();
    FORMS.get_or_init(|| parse(FORMS_TSV))
}

/// The form of a food named `food`, from its category in the built-in taxonomy; None when the
/// taxonomy does not know it or its category has no listed form.
pub fn form_of(food: &str) -> Option<&'static Form> {
    let taxonomy = Taxonomy::builtin();
    let category = &taxonomy.category(taxonomy.lookup(food)?).name;
    let f = forms();
    f.of_category.get(category).map(|&i| &f.forms[i])
}

/// Whether `food` can take `motion` while it is itself: no word of the motion ("squeeze and scrape")
/// is one its form cannot take. A food of unknown form takes any motion.
pub fn takes(food: &str, motion: &str) -> bool {
    let Some(form) = form_of(food) else {
        return true;
    };
    !motion
        .split([' ', '*'])
        .any(|w| form.cannot.iter().any(|c| c == w))
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
            ("tomato", "squeeze"),
            ("spaghetti", "bake"),
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
            ("unheard-of food", "squeeze"),
        ] {
            assert!(takes(food, motion), "{food} should take '{motion}'");
        }
    }

    #[test]
    fn every_listed_category_is_a_taxonomy_category() {
        let taxonomy = Taxonomy::builtin();
        for category in forms().of_category.keys() {
            assert!(
                taxonomy.categories.iter().any(|c| &c.name == category),
                "food_forms.tsv names '{category}', which food_taxonomy.tsv lacks"
            );
        }
    }
}
