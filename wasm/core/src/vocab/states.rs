//! The project's state taxonomy (`data/states.tsv`): twelve categories of states that can stand in for
//! each other, and which category can be reached from which (a chopped onion cannot be made whole again).

use crate::foon::label::normalize_word;
use crate::foon::model::ObjectNode;
use rustc_hash::FxHashMap as HashMap;
use smol_str::SmolStr;
use std::cell::RefCell;
use std::sync::OnceLock;

const STATES_TSV: &str = include_str!("../../data/states.tsv");

/// States things have in the kitchen before cooking starts: a node in only these, in nothing and holding
/// nothing, is available at the start even when some unit makes it (an empty bowl, a whole onion). The
/// evaluator's `START_STATES` (`src/eval/structure.ts`) is this list.
pub const START_STATES: &[&str] = &[
    "empty",
    "clean",
    "whole",
    "raw",
    "off",
    "off (ready)",
    "unopened",
    "closed",
    "dry",
];

/// Whether a state word says a thing is as the kitchen has it: a start state, or a food as bought
/// (`uncooked`, `fresh`). The knowledge base reads a node in only such states as a kitchen item.
pub fn is_start_state(word: &str) -> bool {
    START_STATES.contains(&word) || matches!(word, "uncooked" | "fresh")
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Category {
    Whole,
    Trimmed,
    Cut,
    FinelyCut,
    Ground,
    Liquid,
    Mixed,
    Cooked,
    Preserved,
    Shaped,
    Coated,
    Other,
}

/// Each category with its name in `states.tsv`.
const CATEGORY_NAMES: [(Category, &str); 12] = [
    (Category::Whole, "whole"),
    (Category::Trimmed, "trimmed"),
    (Category::Cut, "cut"),
    (Category::FinelyCut, "finely cut"),
    (Category::Ground, "ground"),
    (Category::Liquid, "liquid"),
    (Category::Mixed, "mixed"),
    (Category::Cooked, "cooked"),
    (Category::Preserved, "preserved"),
    (Category::Shaped, "shaped"),
    (Category::Coated, "coated"),
    (Category::Other, "other"),
];

impl Category {
    pub fn name(self) -> &'static str {
        CATEGORY_NAMES[self as usize].1
    }

    fn parse(text: &str) -> Option<Category> {
        CATEGORY_NAMES
            .iter()
            .find(|(_, n)| *n == text)
            .map(|(c, _)| *c)
    }

    /// A starting state: what an ingredient is like when it comes from the store.
    pub fn is_starting(self) -> bool {
        matches!(self, Category::Whole | Category::Preserved)
    }

    /// How far along the one-way path of separation a category is (whole → trimmed → cut → finely cut →
    /// ground → transformed). `None` for states that say nothing about the food.
    fn rank(self) -> Option<u8> {
        use Category::*;
        match self {
            Whole | Preserved => Some(0),
            Trimmed => Some(1),
            Cut => Some(2),
            FinelyCut => Some(3),
            Ground => Some(4),
            Liquid | Mixed | Cooked | Shaped | Coated => Some(5),
            Other => None,
        }
    }

    /// Whether food in category `self` can be brought into category `to` (states are not reversible:
    /// a liquid cannot be sliced, a minced clove cannot be made whole; but a solid that was cooked,
    /// shaped or coated can still be cut: a roast sliced, toasted nuts chopped).
    pub fn reaches(self, to: Category) -> bool {
        let solid = matches!(self, Category::Cooked | Category::Shaped | Category::Coated);
        match (self.rank(), to.rank()) {
            (Some(a), Some(b)) => a <= b || b == 5 || solid,
            _ => true,
        }
    }
}

/// A listed state word's category and kind (words of one kind say the same of the food).
#[derive(Clone, Copy)]
struct Entry {
    category: Category,
    kind: Option<&'static str>,
}

fn table() -> &'static HashMap<String, Entry> {
    static TABLE: OnceLock<HashMap<String, Entry>> = OnceLock::new();
    TABLE.get_or_init(|| {
        crate::vocab::taxonomy::data_lines(STATES_TSV)
            .filter_map(|l| {
                let mut columns = l.split('\t');
                let state = columns.next()?;
                let category = Category::parse(columns.next()?.trim())?;
                let kind = columns.next().map(str::trim);
                Some((normalize_word(state), Entry { category, kind }))
            })
            .collect()
    })
}

/// The kind a state word is listed with (shredded and grated are of the kind "grated"), if any.
pub(crate) fn kind(state: &str) -> Option<&'static str> {
    let t = table();
    t.get(state)
        .or_else(|| t.get(&normalize_word(state)))
        .and_then(|e| e.kind)
}

/// Whether two state words say the same of the food: equal, or of one kind (shredded and grated).
pub(crate) fn akin(a: &str, b: &str) -> bool {
    a == b || kind(a).is_some_and(|k| kind(b) == Some(k))
}

/// The category of a state word (normalised or not). Unlisted words are classified by their parts
/// ("thinly sliced" → cut, "whole wheat" → whole); anything else is `Other`.
pub fn category(state: &str) -> Category {
    // planning asks for the same few dozen states thousands of times per plan
    thread_local! {
        static SEEN: RefCell<HashMap<String, Category>> = RefCell::new(HashMap::default());
    }
    if let Some(e) = table().get(state) {
        return e.category;
    }
    if let Some(c) = SEEN.with(|m| m.borrow().get(state).copied()) {
        return c;
    }
    let c = classify(state);
    if state.len() <= MAX_REMEMBERED_STATE {
        SEEN.with(|m| {
            let mut m = m.borrow_mut();
            if m.len() >= MAX_REMEMBERED_STATES {
                m.clear();
            }
            m.insert(state.to_string(), c);
        });
    }
    c
}

/// Bounds of the memo of `category` (a hostile knowledge base may have any number of states).
const MAX_REMEMBERED_STATES: usize = 4096;
const MAX_REMEMBERED_STATE: usize = 64;

fn classify(state: &str) -> Category {
    let word = normalize_word(state);
    if let Some(e) = table().get(&word) {
        return e.category;
    }
    // the last listed word decides ("finely chopped", "cooked and sliced")
    let last = word
        .rsplit([' ', '-', ','])
        .find_map(|part| table().get(part));
    last.map_or(Category::Other, |e| e.category)
}

/// The category a node's food states put it in (the furthest along; whole when it has none).
pub(crate) fn node_category(node: &ObjectNode) -> Category {
    food_state_category(node).unwrap_or(Category::Whole)
}

/// `node_category`, `None` for a node without food states.
pub(crate) fn food_state_category(node: &ObjectNode) -> Option<Category> {
    node.physical_states()
        .map(category)
        .filter(|&c| c != Category::Other)
        .max_by_key(|c| if c.is_starting() { 0 } else { 1 + *c as u8 })
}

/// Whether a node says anything of its food (has a food state), without listing its states.
pub(crate) fn has_food_state(node: &ObjectNode) -> bool {
    node.physical_states().any(is_food_state)
}

/// States that describe the food itself (not its place or contents, not an appliance's condition).
pub fn is_food_state(state: &str) -> bool {
    category(state) != Category::Other
}

/// A node's state as a plan reports it (its match and its progress lines): its food states, else its
/// physical states, comma-separated.
pub(crate) fn state_text(node: &ObjectNode) -> SmolStr {
    let current = |s: &&str| !undone(node, s);
    let mut food = node
        .physical_states()
        .filter(|s| is_food_state(s))
        .filter(current)
        .peekable();
    if food.peek().is_some() {
        comma_separated(food)
    } else {
        comma_separated(node.physical_states().filter(current))
    }
}

/// Whether `state` says a food is cooked through: a cooked state, but not one of the way there ("partly
/// cooked", "partly toasted") or the heat of a pot ("hot").
pub fn done_cooking(state: &str) -> bool {
    category(state) == Category::Cooked && !state.starts_with("partly ") && state != "hot"
}

/// Whether the state `s` of `node` was undone by another of its states (a node keeps the states it was
/// given on the way): "unpeeled" beside "peeled", "uncooked", "raw" or "partly cooked" beside a cooked
/// state, "softened" beside "melted", the piece it was bought as ("whole", "block", "clove") once it is
/// cut, what was trimmed off ("peeled") once it is grated, ground, juiced or mixed.
fn undone(node: &ObjectNode, s: &str) -> bool {
    use Category::*;
    let any = |f: &dyn Fn(&str) -> bool| node.physical_states().any(f);
    let un = s.strip_prefix("un").is_some_and(|done| any(&|t| t == done));
    un || match s {
        "uncooked" | "raw" => any(&|t| category(t) == Cooked),
        // canned beans "cooked" are not also "partly cooked" by the pot they sit in
        "partly cooked" => any(&|t| t != s && category(t) == Cooked),
        "softened" => any(&|t| t == "melted"),
        _ => match category(s) {
            Whole => any(&|t| matches!(category(t), Cut | FinelyCut | Ground | Liquid | Mixed)),
            Trimmed => any(&|t| matches!(category(t), FinelyCut | Ground | Liquid | Mixed)),
            _ => false,
        },
    }
}

fn comma_separated<'a>(states: impl Iterator<Item = &'a str>) -> SmolStr {
    states.collect::<Vec<_>>().join(", ").into()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::foon::model::State;

    #[test]
    fn a_state_undone_on_the_way_is_not_shown() {
        let node = |states: &[&str]| {
            ObjectNode::new("rice", states.iter().map(|s| State::plain(s)).collect())
        };
        assert_eq!(state_text(&node(&["uncooked", "cooked"])), "cooked");
        assert_eq!(
            state_text(&node(&["cooked", "partly cooked", "soaked"])),
            "cooked, soaked"
        );
        assert_eq!(
            state_text(&node(&["partly cooked", "soaked"])),
            "partly cooked, soaked"
        );
        assert_eq!(
            state_text(&node(&["halved", "peeled", "unpeeled"])),
            "halved, peeled"
        );
        assert_eq!(state_text(&node(&["unpeeled", "whole"])), "unpeeled, whole");
        assert_eq!(state_text(&node(&["raw"])), "raw");
        // the piece it was bought as, once cut; what was trimmed off, once grated; softened, once melted
        assert_eq!(state_text(&node(&["block", "diced"])), "diced");
        assert_eq!(
            state_text(&node(&["peppercorn", "whole", "ground"])),
            "ground"
        );
        assert_eq!(state_text(&node(&["grated", "peeled"])), "grated");
        assert_eq!(state_text(&node(&["sliced", "peeled"])), "peeled, sliced");
        assert_eq!(
            state_text(&node(&["chopped", "uncooked"])),
            "chopped, uncooked"
        );
        assert_eq!(
            state_text(&node(&["liquid", "melted", "softened"])),
            "liquid, melted"
        );
    }

    #[test]
    fn groups_similar_states() {
        assert_eq!(category("sliced"), category("diced"));
        assert_eq!(category("juice"), category("liquid"));
        assert_eq!(category("ground"), category("granulated"));
        assert_eq!(category("whole raw"), Category::Whole);
        assert_eq!(category("Thinly Sliced"), Category::Cut);
        assert_eq!(category("in"), Category::Other);
        assert_eq!(category("spaceship"), Category::Other);
    }

    #[test]
    fn separation_is_one_way() {
        assert!(Category::Whole.reaches(Category::FinelyCut));
        assert!(Category::Cut.reaches(Category::FinelyCut));
        assert!(!Category::FinelyCut.reaches(Category::Cut));
        assert!(!Category::Liquid.reaches(Category::Cut));
        assert!(Category::Cut.reaches(Category::Cooked));
        assert!(Category::Liquid.reaches(Category::Mixed));
        assert!(Category::Cooked.reaches(Category::Cut));
        assert!(!Category::Mixed.reaches(Category::Cut));
        assert!(!Category::Ground.reaches(Category::FinelyCut));
    }

    #[test]
    fn states_of_one_kind_are_akin_and_others_of_their_category_are_not() {
        assert!(akin("shredded", "grated"));
        assert!(akin("minced", "chopped"));
        assert!(akin("sliced", "sliced"));
        assert!(!akin("shredded", "chopped"));
        assert_eq!(category("shredded"), category("chopped"));
        assert!(!akin("whole", "raw"));
        assert!(!akin("spaceship", "grated"));
    }

    #[test]
    fn every_listed_category_parses() {
        assert!(table().len() > 150);
    }
}
