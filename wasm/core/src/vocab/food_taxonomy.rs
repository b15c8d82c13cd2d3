//! The project's food taxonomy (`data/food_taxonomy.tsv`: categories and groups of foods, keyed by word
//! stems) and its aliases (`data/food_aliases.tsv`). Substitution ranks by them (`similarity::ranking`);
//! the food knowledge and the planner read a food's category from them.

use crate::foon::label::normalize_label;
use crate::similarity::table::{is_stop_word, words};
use crate::vocab::taxonomy::data_lines;
use rust_stemmers::{Algorithm, Stemmer};
use rustc_hash::FxHashMap as HashMap;
use std::sync::{Arc, OnceLock};

const TAXONOMY_TSV: &str = include_str!("../../data/food_taxonomy.tsv");
const ALIASES_TSV: &str = include_str!("../../data/food_aliases.tsv");

/// Trailing words that name a form or a piece of an ingredient rather than the ingredient.
const FORM_WORDS: &[&str] = &[
    "half", "halves", "piece", "pieces", "leaf", "leaves", "stick", "blade", "flake", "clove",
    "slice", "chunk", "strip", "cube", "spear", "floret", "head", "sprig", "stalk", "stem",
    "wedge", "kernel", "segment", "bulb", "pod", "powder", "ground", "fillet", "filet", "round",
    "ring", "shred", "shaving", "crumb", "bit", "nib", "part", "portion", "topping", "cut",
];

/// One taxonomy category.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Category {
    pub name: String,
    pub group: String,
}

fn stemmer() -> &'static Stemmer {
    static STEMMER: OnceLock<Stemmer> = OnceLock::new();
    STEMMER.get_or_init(|| Stemmer::create(Algorithm::English))
}

/// Word stems of a phrase without stop words: the key names are compared on.
pub fn stem_key(phrase: &str) -> Vec<String> {
    words(phrase)
        .into_iter()
        .filter(|w| !is_stop_word(w))
        .map(|w| stemmer().stem(&w).into_owned())
        .collect()
}

/// The project's food taxonomy: categories and their member names keyed by word stems.
#[derive(Clone, Debug, Default)]
pub struct Taxonomy {
    pub categories: Vec<Category>,
    /// Stem key (words joined by a space) -> category index.
    by_key: HashMap<String, usize>,
    /// Member names as written, with their category (for category inference).
    pub members: Vec<(String, usize)>,
}

impl Taxonomy {
    pub fn parse(text: &str) -> Taxonomy {
        let mut t = Taxonomy::default();
        for line in data_lines(text) {
            let mut parts = line.split('\t');
            let (Some(name), Some(group), Some(list)) = (parts.next(), parts.next(), parts.next())
            else {
                continue;
            };
            let cat = Category {
                name: name.trim().to_string(),
                group: group.trim().to_string(),
            };
            let index = t.categories.iter().position(|c| *c == cat);
            let index = index.unwrap_or_else(|| {
                t.categories.push(cat);
                t.categories.len() - 1
            });
            for member in list.split(',').map(str::trim).filter(|m| !m.is_empty()) {
                t.list(member, index);
            }
        }
        t
    }

    /// Lists `member` in category `index`, unless its stem key is empty or listed already (the first
    /// listing wins: a name belongs to one category).
    fn list(&mut self, member: &str, index: usize) {
        let key = stem_key(member).join(" ");
        if !key.is_empty() && !self.by_key.contains_key(&key) {
            self.by_key.insert(key, index);
            self.members.push((member.to_string(), index));
        }
    }

    /// The built-in taxonomy of `data/food_taxonomy.tsv`.
    pub fn builtin() -> &'static Arc<Taxonomy> {
        static TAXONOMY: OnceLock<Arc<Taxonomy>> = OnceLock::new();
        TAXONOMY.get_or_init(|| Arc::new(Taxonomy::parse(TAXONOMY_TSV)))
    }

    /// A copy without the given names (compared on word stems): measures how the substitution does on
    /// names the taxonomy does not list.
    pub fn without(&self, names: &[&str]) -> Taxonomy {
        let drop: std::collections::HashSet<String> =
            names.iter().map(|n| stem_key(n).join(" ")).collect();
        let mut out = Taxonomy {
            categories: self.categories.clone(),
            ..Taxonomy::default()
        };
        for (name, c) in &self.members {
            if !drop.contains(&stem_key(name).join(" ")) {
                out.list(name, *c);
            }
        }
        out
    }

    /// The category of a phrase from its words alone: the longest listed ending, after trailing form
    /// words are dropped when needed. None when nothing is listed.
    pub fn lookup(&self, phrase: &str) -> Option<usize> {
        self.lookup_key(&stem_key(phrase))
    }

    /// `lookup` of a stem key.
    pub(crate) fn lookup_key(&self, key: &[String]) -> Option<usize> {
        let mut key = key.to_vec();
        loop {
            for start in 0..key.len() {
                if let Some(&c) = self.by_key.get(&key[start..].join(" ")) {
                    return Some(c);
                }
            }
            match key.last() {
                Some(last) if key.len() > 1 && is_form_stem(last) => {
                    key.pop();
                }
                _ => return None,
            }
        }
    }

    /// Whether this exact stem key is a listed name.
    pub fn lists(&self, key: &[String]) -> bool {
        self.by_key.contains_key(&key.join(" "))
    }

    pub fn category(&self, index: usize) -> &Category {
        &self.categories[index]
    }
}

pub(crate) fn is_form_stem(stem: &str) -> bool {
    // stemmed once: every profile asks this of several words
    static FORM_STEMS: OnceLock<Vec<String>> = OnceLock::new();
    FORM_STEMS
        .get_or_init(|| {
            FORM_WORDS
                .iter()
                .map(|w| stemmer().stem(w).into_owned())
                .collect()
        })
        .iter()
        .any(|f| f == stem)
}

/// The built-in alias list, keyed by normal form.
pub fn aliases() -> &'static Arc<HashMap<String, String>> {
    static ALIASES: OnceLock<Arc<HashMap<String, String>>> = OnceLock::new();
    ALIASES.get_or_init(|| {
        Arc::new(
            data_lines(ALIASES_TSV)
                .filter_map(|l| l.split_once('\t'))
                .map(|(a, b)| (normalize_label(a), normalize_label(b)))
                .filter(|(a, b)| !a.is_empty() && !b.is_empty())
                .collect(),
        )
    })
}
