//! Word lists of the substitution score: words that are no part of an ingredient's identity, and the
//! taxonomy groups that are not base ingredients.

/// Words that describe the state or size of an ingredient, not which ingredient it is; left out of the
/// vector of a phrase the taxonomy does not list ("whole clove", "fresh dill", "large egg").
const DESCRIPTORS: &str =
    "fresh freshly dried whole large small medium big chopped minced sliced diced cubed \
    grated shredded crushed frozen canned tinned cooked uncooked raw organic boneless \
    skinless lean extra finely coarsely thinly roughly peeled pitted seeded halved quartered \
    melted softened cold warm hot room temperature packed heaping level optional good \
    quality best plain regular homemade store bought prepared instant quick low fat free \
    reduced sodium light lite nonfat";

/// Whether `word` is one of the `DESCRIPTORS`.
pub(super) fn is_descriptor(word: &str) -> bool {
    DESCRIPTORS.split(' ').any(|d| d == word)
}

/// Groups whose members are not base ingredients.
pub(super) const COMPOSITE_GROUPS: &[&str] = &["dish", "mixture"];
/// The group of kitchen tools, containers and appliances: never a substitute for an ingredient.
pub(super) const UTENSIL_GROUP: &str = "utensil";
