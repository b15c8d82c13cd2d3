//! What a query editor offers for a knowledge base: its dish classes with their recipes, its object
//! labels and its plain states, as the planner knows them (normal forms, units the reader skipped left
//! out).

use crate::foon::kb::KnowledgeBase;
use crate::vocab::taxonomy::dish_class_name;
use serde::Serialize;
use std::collections::{BTreeMap, BTreeSet};

#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Vocabulary {
    /// Dish classes that have at least one goal node, with the titles of their recipes.
    pub dishes: Vec<Dish>,
    /// Object labels.
    pub labels: Vec<String>,
    /// State names without an argument ("in [bowl]" and "contains {…}" are not states one asks for).
    pub states: Vec<String>,
    /// Recipe title of each subgraph file.
    pub titles: BTreeMap<String, String>,
}

#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Dish {
    pub name: String,
    pub recipes: Vec<String>,
}

/// Sorted as a reader expects: case-insensitively, then as written.
fn sorted<S: AsRef<str>>(set: BTreeSet<S>) -> Vec<String> {
    let mut v: Vec<String> = set.into_iter().map(|s| s.as_ref().to_string()).collect();
    v.sort_by_cached_key(|s| (s.to_lowercase(), s.clone()));
    v
}

pub fn vocabulary(kb: &KnowledgeBase) -> Vocabulary {
    let titles: BTreeMap<String, String> = kb
        .subgraphs
        .iter()
        .map(|g| (g.name.clone(), g.title.clone()))
        .collect();
    let mut dishes: BTreeMap<&str, BTreeSet<String>> = BTreeMap::new();
    for g in &kb.goals {
        if let (Some(class), Some(title)) = (
            g.dish_class.and_then(dish_class_name),
            titles.get(&g.subgraph),
        ) {
            dishes.entry(class).or_default().insert(title.clone());
        }
    }
    let mut labels = BTreeSet::new();
    let mut states = BTreeSet::new();
    for node in &kb.nodes {
        labels.insert(node.label.as_str());
        states.extend(
            node.states
                .iter()
                .filter(|s| s.arg.is_none())
                .map(|s| s.name.as_str()),
        );
    }
    Vocabulary {
        dishes: dishes
            .into_iter()
            .map(|(name, recipes)| Dish {
                name: name.to_string(),
                recipes: sorted(recipes),
            })
            .collect(),
        labels: sorted(labels),
        states: sorted(states),
        titles,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::foon::kb::title_from_name;
    use crate::foon::read::parse_str;

    #[test]
    fn titles_come_from_the_title_line_else_the_file_name() {
        assert_eq!(title_from_name("0001-whipped_cream.txt"), "whipped cream");
        assert_eq!(title_from_name("s01-greek_salad.txt"), "greek salad");
        assert_eq!(title_from_name("0097-miso_soup-DONE.txt"), "miso soup");
        assert_eq!(
            title_from_name("recipes/0097-miso_soup-DONE.txt"),
            "miso soup"
        );
        assert_eq!(title_from_name("12.txt"), "12");
        assert_eq!(title_from_name(".txt"), ".txt");
        let text = "# title: Toast\n//\nO\tbread\t1\nS\tsliced\nM\ttoast\t<Assumed>\nO\ttoast\t1\t0\nS\ttoasted\nS\ton\t[plate]\n";
        let kb = KnowledgeBase::merge(&[
            parse_str("toast.txt", text).unwrap(),
            parse_str(
                "0002-rye_toast.txt",
                &text.replace("# title: Toast\n", "# a comment\n"),
            )
            .unwrap(),
        ])
        .unwrap();
        let v = vocabulary(&kb);
        assert_eq!(v.titles["toast.txt"], "Toast");
        assert_eq!(v.titles["0002-rye_toast.txt"], "rye toast");
        assert_eq!(
            v.dishes,
            vec![Dish {
                name: "bread".into(),
                recipes: vec!["rye toast".into(), "Toast".into()]
            }]
        );
        assert_eq!(v.labels, ["bread", "toast"]);
        assert_eq!(v.states, ["sliced", "toasted"]);
    }
}
