//! One normal form for object labels, states and motions, used by the reader, the planner and the
//! similarity table alike, so that "Tomatoes ", "tomato" and "TOMATO" are the same object.

use std::borrow::Cow;

/// Words whose final "s" is not a plural ending (or whose plural is the everyday name of the food).
const KEEP_AS_IS: &str =
    "asparagus bass brussels citrus couscous fries greens grits hummus molasses oats \
    octopus scissors swiss tongs hibiscus series species news lens plus this";

/// Irregular plurals whose singular the suffix rules would get wrong.
const IRREGULAR: &[(&str, &str)] = &[
    ("leaves", "leaf"),
    ("halves", "half"),
    ("loaves", "loaf"),
    ("knives", "knife"),
    ("shelves", "shelf"),
    ("calves", "calf"),
    ("geese", "goose"),
    ("teeth", "tooth"),
    ("feet", "foot"),
    ("mice", "mouse"),
    ("children", "child"),
    ("people", "person"),
    ("dice", "dice"),
    ("cookies", "cookie"),
    ("pies", "pie"),
    ("brownies", "brownie"),
    ("smoothies", "smoothie"),
    ("veggies", "veggie"),
    ("calories", "calorie"),
    ("hoagies", "hoagie"),
    ("rotisseries", "rotisserie"),
    ("shoes", "shoe"),
    ("canoes", "canoe"),
    ("oboes", "oboe"),
    ("toes", "toe"),
    ("sprouts", "sprout"),
];

/// Lower case, trimmed, inner white space and underscores folded to single spaces.
pub fn fold(text: &str) -> String {
    let lowered = text.to_lowercase().replace('_', " ");
    lowered.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// Singular form of one English word; never invents a non-word for the exceptions above
/// (e.g. "glass" stays "glass", "molasses" stays "molasses").
pub fn singular(word: &str) -> String {
    singular_of(word).into_owned()
}

/// `singular`, borrowing the word when it is already singular (most words a reader sees).
fn singular_of(word: &str) -> Cow<'_, str> {
    if word.len() < 4 || !word.is_ascii() {
        return Cow::Borrowed(word);
    }
    if let Some((_, s)) = IRREGULAR.iter().find(|(p, _)| *p == word) {
        return Cow::Borrowed(s);
    }
    // every rule below removes a final "s"
    if !word.ends_with('s') || KEEP_AS_IS.split(' ').any(|w| w == word) {
        return Cow::Borrowed(word);
    }
    let ends = |suffix: &str| word.ends_with(suffix);
    let cut = |n: usize| &word[..word.len() - n];
    // recipe data singularised "lemongrass" and "watercress" once already ("lemongras", "watercres")
    if ends("ss") || ends("us") || ends("is") || ends("ous") || ends("gras") || ends("cres") {
        return Cow::Borrowed(word);
    }
    if ends("ies") {
        return Cow::Owned(format!("{}y", cut(3)));
    }
    if ends("oes") || ends("ches") || ends("shes") || ends("xes") || ends("sses") || ends("zzes") {
        return Cow::Borrowed(cut(2));
    }
    if !ends("'s") {
        return Cow::Borrowed(cut(1));
    }
    Cow::Borrowed(word)
}

/// The normal form of an object label: folded, with its head (last) word singular.
/// Modifiers are left alone ("brussels sprouts" -> "brussels sprout").
pub fn normalize_label(text: &str) -> String {
    let folded = fold(text);
    let (modifiers, head) = folded.split_at(folded.rfind(' ').map_or(0, |i| i + 1));
    format!("{modifiers}{}", singular_of(head))
}

/// States and motions are verbs/adjectives: folded only, never singularised.
pub fn normalize_word(text: &str) -> String {
    fold(text)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plurals_become_singular_without_mangling() {
        for (given, want) in [
            ("Tomatoes", "tomato"),
            ("cherries", "cherry"),
            ("peaches", "peach"),
            ("sesame seeds", "sesame seed"),
            ("glass", "glass"),
            ("drinking glass", "drinking glass"),
            ("molasses", "molasses"),
            ("asparagus", "asparagus"),
            ("watercress", "watercress"),
            ("lemongrass", "lemongrass"),
            ("lemongras", "lemongras"),
            ("watercres", "watercres"),
            ("grapes", "grape"),
            ("bananas", "banana"),
            ("cookies", "cookie"),
            ("leaves", "leaf"),
            ("olives", "olive"),
            ("salad greens", "salad greens"),
            ("  Sweet_potato   FRIES ", "sweet potato fries"),
            ("egg", "egg"),
            ("hummus", "hummus"),
            ("potatoes", "potato"),
            ("Red Dishes", "red dish"),
            ("geese", "goose"),
            ("baker's", "baker's"),
            ("chopped onion", "chopped onion"),
        ] {
            assert_eq!(normalize_label(given), want, "{given}");
        }
    }

    #[test]
    fn folding_leaves_folded_text_alone_and_folds_the_rest() {
        for (given, want) in [
            ("chopped onion", "chopped onion"),
            ("", ""),
            (" ", ""),
            ("a  b", "a b"),
            (" a", "a"),
            ("a ", "a"),
            ("a\tb", "a b"),
            // found by the reader's fuzzer: "in\u{b} [bowl]" was read as the state "in\u{b}", written
            // back as "in\u{b}\t[bowl]" and read again as "in"
            ("in\u{b}", "in"),
            ("a\u{b}b", "a b"),
            ("a_b", "a b"),
            ("Crème Brûlée", "crème brûlée"),
            ("off (ready)", "off (ready)"),
        ] {
            assert_eq!(fold(given), want, "{given:?}");
        }
    }

    #[test]
    fn states_are_folded_not_singularised() {
        assert_eq!(normalize_word(" Sliced  "), "sliced");
        assert_eq!(normalize_word("leaves"), "leaves");
        assert_eq!(normalize_word("off (ready)"), "off (ready)");
    }
}
