//! The planner on small hand-made knowledge bases: one test per case of Table I, pruning, attachment,
//! cycles, unknown dish types, empty queries, duplicate ingredients, empty names, overrides, the
//! unmodified reference tree, and the exports.

mod common;
use common::hand::{goal_contents, outcome, plan_of, query, try_plan, units, BLACK_PEPPER};
use foon_core::contract::plan::{Origin, Status};
use foon_core::error::ErrorCode;
use foon_core::foon::read::parse_str;
use foon_core::similarity::{ExactMatch, Similarity};
use foon_core::{foon_text, pddl, progress_json, Plan};

/// A similarity given as a table of pairs (symmetric); 1 for a name with itself, 0 otherwise.
struct Pairs(&'static [(&'static str, &'static str, f32)]);

impl Similarity for Pairs {
    fn similarity(&self, a: &str, b: &str) -> f32 {
        if a == b {
            return 1.0;
        }
        self.0
            .iter()
            .find(|(x, y, _)| (*x == a && *y == b) || (*x == b && *y == a))
            .map_or(0.0, |p| p.2)
    }
}

/// A salad (dish class 15): a tomato sliced, and lettuce the recipe starts with chopped, mixed in a bowl.
const SALAD: &str = "//
O\tcutting board\t0
S\tempty
O\ttomato\t1
S\twhole
M\tpick-and-place\t<Assumed>
O\ttomato\t1
S\twhole
S\ton\t[cutting board]
//
O\ttomato\t1
S\twhole
S\ton\t[cutting board]
O\tknife\t1
S\tclean
M\tslice\t<Assumed>
O\ttomato\t1
S\tsliced
S\ton\t[cutting board]
//
O\tsalad bowl\t0
S\tempty
O\ttomato\t1
S\tsliced
S\ton\t[cutting board]
O\tlettuce\t1
S\tchopped
M\tmix\t<Assumed>
O\tgarden salad\t1\t15
S\tmixed
S\tcontains\t{lettuce,tomato}
S\tin\t[salad bowl]
//
";

/// Another recipe (a soup, class 1): cucumber sliced, lettuce chopped and shredded, boiled in a pot.
const SOUP: &str = "//
O\tcucumber\t1
S\twhole
O\tknife\t1
S\tclean
M\tslice\t<Assumed>
O\tcucumber\t1
S\tsliced
//
O\tlettuce\t1
S\twhole
O\tknife\t1
S\tclean
M\tchop\t<Assumed>
O\tlettuce\t1
S\tchopped
//
O\tlettuce\t1
S\twhole
O\tknife\t1
S\tclean
M\tshred\t<Assumed>
O\tlettuce\t1
S\tshredded
//
O\tpot\t0
S\tempty
O\tcucumber\t1
S\tsliced
O\tlettuce\t1
S\tshredded
M\tpour\t<Assumed>
O\tpot\t0
S\tcontains\t{cucumber,lettuce}
//
O\tpot\t0
S\tcontains\t{cucumber,lettuce}
M\tboil\t<Assumed>
O\tgreen soup\t1\t1
S\tcooked
S\tcontains\t{cucumber,lettuce}
S\tin\t[pot]
//
";

/// A sound plan for a salad of `items` against both recipes.
fn salad(items: &[(&str, &str)]) -> Plan {
    plan_of(BOTH, &SIM, &query("salad", items))
}

const BOTH: &[(&str, &str)] = &[("salad.txt", SALAD), ("soup.txt", SOUP)];
const SIM: Pairs = Pairs(&[
    ("cherry tomato", "tomato", 0.9),
    ("romaine", "lettuce", 0.85),
    ("zucchini", "cucumber", 0.8),
]);

/// Whether a unit with `motion` makes `label` in `state`.
fn makes(p: &Plan, motion: &str, label: &str, state: &str) -> bool {
    p.units.iter().any(|u| {
        u.motion == motion
            && u.outputs
                .iter()
                .any(|n| n.label == label && n.states.iter().any(|s| s == state))
    })
}

/// The labels every unit of the plan takes or makes.
fn labels(p: &Plan) -> std::collections::BTreeSet<&str> {
    p.units
        .iter()
        .flat_map(|u| u.inputs.iter().chain(u.outputs.iter()))
        .map(|n| n.label.as_str())
        .collect()
}

#[test]
fn case_1_object_and_state_in_the_tree_change_nothing() {
    let p = salad(&[("tomato", "sliced"), ("lettuce", "chopped")]);
    assert_eq!(p.goal.reference, "garden salad");
    for (object, state) in [("tomato", "sliced"), ("lettuce", "chopped")] {
        let o = outcome(&p, object);
        assert_eq!(o.case, Some(1), "{o:#?}");
        assert_eq!(o.status, Status::Planned);
        let m = o.matched.as_ref().unwrap();
        assert_eq!(
            (m.label.as_str(), m.state.as_str(), m.similarity),
            (object, state, 1.0)
        );
    }
    assert!(p.units.iter().all(|u| u.origin == Origin::Reference));
    assert_eq!(
        units(&p),
        [
            "pick-and-place: cutting board (empty) + tomato (whole) -> tomato (on [cutting board], whole)",
            "slice: knife (clean) + tomato (on [cutting board], whole) -> tomato (on [cutting board], sliced)",
            "mix: lettuce (chopped) + salad bowl (empty) + tomato (on [cutting board], sliced) -> garden salad (contains {lettuce,tomato}, in [salad bowl], mixed)",
        ]
    );
    assert!(p.removed.is_empty());
    assert_eq!(
        p.steps,
        [
            "Place the tomato onto the cutting board.",
            "Slice the tomato on the cutting board.",
            "Mix the lettuce and the tomato in the salad bowl.",
        ]
    );
}

#[test]
fn case_2_an_equivalent_in_the_same_state_is_renamed() {
    let p = salad(&[("cherry tomato", "sliced"), ("lettuce", "chopped")]);
    let o = outcome(&p, "cherry tomato");
    assert_eq!(o.case, Some(2));
    assert_eq!(o.status, Status::Planned);
    let m = o.matched.as_ref().unwrap();
    assert_eq!(
        (m.label.as_str(), m.state.as_str(), m.similarity),
        ("tomato", "sliced", 0.9)
    );
    // the tomato's whole branch now handles the cherry tomato, and the salad contains it
    assert!(!labels(&p).contains("tomato"), "{:#?}", units(&p));
    assert!(units(&p).contains(
        &"slice: cherry tomato (on [cutting board], whole) + knife (clean) -> cherry tomato (on [cutting board], sliced)".to_string()
    ));
    assert_eq!(goal_contents(&p), ["cherry tomato", "lettuce"]);
    assert_eq!(p.units.len(), 3);
}

#[test]
fn case_2_copies_the_branch_when_the_equivalent_is_asked_for_too() {
    let p = salad(&[
        ("tomato", "sliced"),
        ("cherry tomato", "sliced"),
        ("lettuce", "chopped"),
    ]);
    assert_eq!(outcome(&p, "tomato").case, Some(1));
    assert_eq!(outcome(&p, "cherry tomato").case, Some(2));
    for label in ["tomato", "cherry tomato"] {
        assert!(
            makes(&p, "slice", label, "sliced"),
            "{label}: {:#?}",
            units(&p)
        );
    }
    assert!(p.units.iter().any(|u| u.origin == Origin::Copied));
    assert_eq!(goal_contents(&p), ["cherry tomato", "lettuce", "tomato"]);
}

#[test]
fn case_3_grafts_the_units_that_make_the_trees_state_from_the_given_one() {
    // the salad starts from chopped lettuce; the user has a whole one, and the soup recipe chops it
    let p = salad(&[("tomato", "sliced"), ("lettuce", "whole")]);
    let o = outcome(&p, "lettuce");
    assert_eq!(o.case, Some(3));
    assert_eq!(o.status, Status::Planned);
    assert_eq!(o.matched.as_ref().unwrap().state, "chopped");
    let chop = p
        .units
        .iter()
        .position(|u| u.motion == "chop")
        .expect("a chop unit");
    assert_eq!(p.units[chop].origin, Origin::Grafted);
    assert_eq!(
        units(&p)[chop],
        "chop: knife (clean) + lettuce (whole) -> lettuce (chopped)"
    );
    // grafted onto the leaf: the chopped lettuce is made before the mix that takes it
    let mix = p.units.iter().position(|u| u.motion == "mix").unwrap();
    assert!(chop < mix);
    assert_eq!(p.steps[chop], "Chop the lettuce.");
}

#[test]
fn case_3_says_so_when_the_given_state_cannot_be_reached() {
    // the salad starts from chopped lettuce: lettuce cut coarser cannot be made from it
    let p = salad(&[("lettuce", "sliced")]);
    let o = outcome(&p, "lettuce");
    assert_eq!(o.case, Some(3));
    assert_eq!(o.status, Status::Planned);
    assert_eq!(
        o.reason.as_deref(),
        Some("state 'sliced' cannot be reached from the tree's 'chopped' (not reversible); kept 'chopped'")
    );
    assert!(makes(&p, "mix", "garden salad", "mixed"));
    assert!(!p.units.iter().any(|u| u.origin == Origin::Grafted));
}

#[test]
fn a_state_of_the_same_category_counts_as_matched() {
    // shredded and chopped are both finely cut: the tree's chopped lettuce serves, with a reason
    let p = salad(&[("lettuce", "shredded")]);
    let o = outcome(&p, "lettuce");
    assert_eq!(o.case, Some(1));
    assert_eq!(o.matched.as_ref().unwrap().state, "chopped");
    assert_eq!(
        o.reason.as_deref(),
        Some("state 'shredded' matched by category (finely cut)")
    );
}

/// A carrot soup (class 1) that grates one carrot and chops another.
const CARROTS: &str = "//
O\tcarrot\t1
S\twhole
O\tgrater\t1
M\tgrate\t<Assumed>
O\tcarrot\t1
S\tgrated
//
O\tcarrot\t1
S\twhole
O\tknife\t1
M\tchop\t<Assumed>
O\tcarrot\t1
S\tchopped
//
O\tpot\t0
S\tempty
O\tcarrot\t1
S\tgrated
O\tcarrot\t1
S\tchopped
M\tboil\t<Assumed>
O\tcarrot soup\t1\t1
S\tcooked
S\tcontains\t{carrot}
S\tin\t[pot]
//
";

#[test]
fn a_state_word_of_the_same_kind_is_preferred_to_others_of_its_category() {
    // chopped is the finely cut state salads use most, but shredded carrot is grated carrot
    let files = [("salad.txt", SALAD), ("carrots.txt", CARROTS)];
    let p = plan_of(
        &files,
        &SIM,
        &query("salad", &[("lettuce", "chopped"), ("carrot", "shredded")]),
    );
    let o = outcome(&p, "carrot");
    assert_eq!(o.matched.as_ref().unwrap().state, "grated", "{o:#?}");
    assert!(makes(&p, "grate", "carrot", "grated"), "{:#?}", units(&p));
    assert!(!makes(&p, "chop", "carrot", "chopped"), "{:#?}", units(&p));
    // in the tree: minced lettuce is the tree's chopped lettuce, and the reason says why
    let p = salad(&[("lettuce", "minced")]);
    let o = outcome(&p, "lettuce");
    assert_eq!(o.case, Some(1));
    assert_eq!(
        o.reason.as_deref(),
        Some("state 'minced' matched by 'chopped', a word for the same state")
    );
}

#[test]
fn case_4_renames_and_grafts_from_the_tree() {
    let p = salad(&[("tomato", "sliced"), ("romaine", "whole")]);
    let o = outcome(&p, "romaine");
    assert_eq!(o.case, Some(4));
    let m = o.matched.as_ref().unwrap();
    assert_eq!(
        (m.label.as_str(), m.state.as_str(), m.similarity),
        ("lettuce", "chopped", 0.85)
    );
    assert!(units(&p)
        .contains(&"chop: knife (clean) + romaine (whole) -> romaine (chopped)".to_string()));
    assert!(!labels(&p).contains("lettuce"));
    assert_eq!(goal_contents(&p), ["romaine", "tomato"]);
}

#[test]
fn case_4_takes_a_branch_from_elsewhere_in_foon_and_attaches_it_where_ingredients_mix() {
    // no zucchini anywhere: its equivalent, cucumber, is only in the soup recipe
    let p = salad(&[
        ("tomato", "sliced"),
        ("lettuce", "chopped"),
        ("zucchini", "sliced"),
    ]);
    let o = outcome(&p, "zucchini");
    assert_eq!(o.case, Some(4));
    assert_eq!(o.status, Status::Planned);
    let m = o.matched.as_ref().unwrap();
    assert_eq!((m.label.as_str(), m.state.as_str()), ("cucumber", "sliced"));
    let reason = o.reason.as_deref().unwrap();
    assert!(reason.contains("added at 'mix'"), "{o:#?}");
    // where the equivalent was found, and that it is not in the tree, said once each
    assert!(
        reason.starts_with("equivalent 'cucumber' found in the universal FOON; "),
        "{reason}"
    );
    assert_eq!(
        reason.matches("not in the reference tree").count(),
        1,
        "{reason}"
    );
    let all = units(&p);
    let slice = all
        .iter()
        .position(|u| u == "slice: knife (clean) + zucchini (whole) -> zucchini (sliced)")
        .unwrap_or_else(|| panic!("{all:#?}"));
    assert_eq!(p.units[slice].origin, Origin::Grafted);
    // attached to the mixing unit, never to a cutting one (a robot cuts one item at a time)
    let takes = |u: &foon_core::contract::plan::PlanUnit| {
        u.inputs
            .iter()
            .any(|n| n.label == "zucchini" && n.states.iter().any(|s| s == "sliced"))
    };
    let users: Vec<&str> = p
        .units
        .iter()
        .filter(|u| takes(u))
        .map(|u| u.motion.as_str())
        .collect();
    assert_eq!(users, ["mix"]);
    assert!(p
        .units
        .iter()
        .any(|u| u.motion == "mix" && u.origin == Origin::Attached));
    assert_eq!(goal_contents(&p), ["lettuce", "tomato", "zucchini"]);
    assert!(!labels(&p).contains("cucumber"));
}

#[test]
fn an_exact_foon_label_maps_to_itself_where_the_tree_has_no_variety_of_it() {
    // cucumber is a FOON label (in the soup): it is never replaced by the tree's tomato or lettuce
    let p = salad(&[("tomato", "sliced"), ("cucumber", "sliced")]);
    let o = outcome(&p, "cucumber");
    let m = o.matched.as_ref().unwrap();
    assert_eq!((m.label.as_str(), m.similarity), ("cucumber", 1.0));
    assert_eq!(goal_contents(&p), ["cucumber", "tomato"]);
}

#[test]
fn pruning_removes_what_was_not_asked_for_and_keeps_the_tree_connected() {
    let p = salad(&[("tomato", "sliced")]);
    assert_eq!(p.removed, ["lettuce"]);
    assert!(!labels(&p).contains("lettuce"));
    // the goal and the containers no longer list it
    assert_eq!(goal_contents(&p), ["tomato"]);
    assert!(p.units.iter().all(|u| !u.inputs.is_empty()));
    assert_eq!(p.steps.last().unwrap(), "Mix the tomato in the salad bowl.");
}

#[test]
fn an_ingredient_without_any_equivalent_is_unplannable_with_a_reason() {
    let p = salad(&[("tomato", "sliced"), ("plutonium", "whole")]);
    let o = outcome(&p, "plutonium");
    assert_eq!(o.status, Status::Unplannable);
    assert_eq!(o.case, None);
    assert!(o.matched.is_none());
    assert!(o
        .reason
        .as_deref()
        .unwrap()
        .contains("no equivalent of 'plutonium'"));
    assert!(!labels(&p).contains("plutonium"));
    assert_eq!(outcome(&p, "tomato").status, Status::Planned);
    // nothing is like it at all: no name is offered as an alternative or as the closest one
    assert_eq!(
        o.reason.as_deref(),
        Some("no equivalent of 'plutonium' in the knowledge base")
    );
    assert!(o.alternatives.is_empty(), "{:#?}", o.alternatives);
    // a name like some labels is offered those, and only those, besides its equivalent
    const KALE: Pairs = Pairs(&[("kale", "lettuce", 0.6), ("kale", "cucumber", 0.4)]);
    let p = plan_of(BOTH, &KALE, &query("salad", &[("kale", "chopped")]));
    let o = outcome(&p, "kale");
    assert_eq!(o.matched.as_ref().unwrap().label, "lettuce");
    let offered: Vec<(&str, f32)> = o
        .alternatives
        .iter()
        .map(|a| (a.label.as_str(), a.similarity))
        .collect();
    assert_eq!(offered, [("cucumber", 0.4)]);
}

/// A dessert whose butter is melted from solid and cooled back to solid in the same recipe: the only
/// unit making solid butter needs melted butter, which needs solid butter.
const CYCLE: &str = "//
O\tbutter\t1
S\tsolid
O\tpan\t0
S\thot
M\tmelt\t<Assumed>
O\tbutter\t1
S\tmelted
//
O\tbutter\t1
S\tmelted
M\tcool\t<Assumed>
O\tbutter\t1
S\tsolid
//
O\tbowl\t0
S\tempty
O\tbutter\t1
S\tmelted
O\tsugar\t1
S\tgranulated
M\tmix\t<Assumed>
O\tbutter cream\t1\t8
S\tmixed
S\tcontains\t{butter,sugar}
S\tin\t[bowl]
//
";

#[test]
fn retrieval_terminates_on_a_cycle() {
    let p = plan_of(
        &[("cycle.txt", CYCLE)],
        &ExactMatch,
        &query("dessert", &[("butter", "melted"), ("sugar", "granulated")]),
    );
    assert_eq!(p.goal.reference, "butter cream");
    // each unit once, in an order a robot can follow (checked by plan_of); the recipe had solid butter
    // from the start, so cooling it back is not part of the plan
    assert_eq!(
        units(&p),
        [
            "melt: butter (solid) + pan (hot) -> butter (melted)",
            "mix: bowl (empty) + butter (melted) + sugar (granulated) -> butter cream (contains {butter,sugar}, in [bowl], mixed)",
        ]
    );
}

#[test]
fn an_unknown_dish_type_searches_all_goals_and_says_so() {
    let p = plan_of(BOTH, &SIM, &query("spaceship", &[("tomato", "sliced")]));
    assert!(p.dish_class.is_none());
    assert!(
        p.notes
            .iter()
            .any(|n| n.contains("unknown dish type 'spaceship'")),
        "{:#?}",
        p.notes
    );
    assert_eq!(p.goal.reference, "garden salad");
    // a known type with no goal of its class in the knowledge base falls back too
    let p = plan_of(BOTH, &SIM, &query("pizza", &[("tomato", "sliced")]));
    assert_eq!(
        p.notes,
        ["no recipe of class 'pizza' in the knowledge base: searched all goal nodes"]
    );
}

#[test]
fn the_dish_type_picks_the_reference_goal() {
    let soup = plan_of(BOTH, &SIM, &query("soup", &[("lettuce", "chopped")]));
    assert_eq!(soup.goal.reference, "green soup");
    let salad = salad(&[("lettuce", "chopped")]);
    assert_eq!(salad.goal.reference, "garden salad");
}

/// A recipe (FOON lines) mixing `foods` in a bowl into `dish` of class `class`.
fn mixed_dish(foods: &[&str], dish: &str, class: u32) -> String {
    let inputs: String = foods
        .iter()
        .map(|f| format!("O\t{f}\t1\nS\tfresh\n"))
        .collect();
    format!(
        "//\nO\tbowl\t0\nS\tempty\n{inputs}M\tmix\t<Assumed>\nO\t{dish}\t1\t{class}\nS\tcontains\t{{{}}}\n//\n",
        foods.join(",")
    )
}

#[test]
fn a_dish_type_with_no_recipe_like_the_query_borrows_one_of_a_kin_type() {
    // bread (class 0) asked of flour, water and yeast: the only bread is a garlic toast; a pizza dough
    // (class 3, kin to bread) fits, and a soup (class 1, not kin) fits as well but is not taken
    let toast = mixed_dish(&["bread", "garlic", "butter"], "garlic toast", 0);
    let pizza = mixed_dish(&["flour", "water", "yeast", "cheese"], "cheese pizza", 3);
    let soup = mixed_dish(&["flour", "water", "yeast"], "yeast soup", 1);
    let files = [
        ("toast.txt", toast.as_str()),
        ("pizza.txt", &pizza),
        ("soup.txt", &soup),
    ];
    let items = [("flour", "fresh"), ("water", "fresh"), ("yeast", "fresh")];
    let p = plan_of(&files, &ExactMatch, &query("bread", &items));
    assert_eq!(p.goal.reference, "cheese pizza");
    assert!(
        p.notes
            .iter()
            .any(|n| n.contains("a dish made the same way")),
        "{:?}",
        p.notes
    );
    // the explain trace leads with the pizza, naming the kin type, then lists the bread type's goals
    let explained = query("bread", &items).replace("}}", r#"}, "explain": true}"#);
    let g = plan_of(&files, &ExactMatch, &explained)
        .trace
        .expect("a trace")
        .goal_selection;
    let labels: Vec<&str> = g.candidates.iter().map(|c| c.node.as_str()).collect();
    assert_eq!(
        labels[0].split(" (").next(),
        Some("cheese pizza"),
        "{labels:?}"
    );
    assert_eq!(labels.len(), 2, "{labels:?}");
    assert_eq!(g.tie_break.as_deref(), Some("kin_class"));
    assert!(g.kin_class.is_some());
    // a bread recipe that fits well is kept, though the pizza fits better still
    let loaf = mixed_dish(&["flour", "water", "yeast", "salt"], "loaf", 0);
    let files = [("loaf.txt", loaf.as_str()), ("pizza.txt", &pizza)];
    let p = plan_of(&files, &ExactMatch, &query("bread", &items));
    assert_eq!(p.goal.reference, "loaf");
}

#[test]
fn an_empty_query_is_a_typed_error() {
    let err = try_plan(
        BOTH,
        &SIM,
        r#"{"query": {"type": "salad", "ingredients": []}}"#,
    )
    .unwrap_err();
    assert_eq!(err.code, ErrorCode::BadQuery);
    assert!(err.message.contains("no ingredients"), "{err}");
}

#[test]
fn duplicate_ingredients_are_planned_once_with_a_note() {
    let p = salad(&[
        ("tomato", "sliced"),
        ("Tomato", " Sliced "),
        ("tomato", "sliced"),
    ]);
    assert_eq!(p.query.ingredients.len(), 1);
    assert_eq!(p.ingredients.len(), 1);
    // one note, however often it is listed
    assert_eq!(
        p.notes,
        ["duplicate ingredient 'tomato (sliced)' listed 3 times, planned once"]
    );
}

#[test]
fn an_empty_name_is_a_typed_error_naming_the_ingredient() {
    let err = try_plan(
        BOTH,
        &SIM,
        &query("salad", &[("tomato", "sliced"), ("  ", "whole")]),
    )
    .unwrap_err();
    assert_eq!(err.code, ErrorCode::BadQuery);
    assert!(
        err.message
            .contains("ingredient 2 has an empty object name"),
        "{err}"
    );
}

#[test]
fn an_override_replaces_the_equivalent_and_is_marked() {
    // the caller prefers lettuce for zucchini over the planner's cucumber
    let request = r#"{"query": {"type": "salad", "ingredients": [
        {"object": "tomato", "state": "sliced"}, {"object": "zucchini", "state": "chopped"}]},
        "overrides": {"zucchini": "lettuce"}}"#;
    let p = plan_of(BOTH, &SIM, request);
    let o = outcome(&p, "zucchini");
    assert!(o.overridden);
    let m = o.matched.as_ref().unwrap();
    assert_eq!((m.label.as_str(), m.state.as_str()), ("lettuce", "chopped"));
    assert_eq!(goal_contents(&p), ["tomato", "zucchini"]);
    // an override that is no ingredient of the knowledge base leaves the ingredient unplannable
    let request = request.replace(r#""zucchini": "lettuce""#, r#""zucchini": "spoon""#);
    let p = plan_of(BOTH, &SIM, &request);
    let o = outcome(&p, "zucchini");
    assert_eq!(o.status, Status::Unplannable);
    assert!(o.reason.as_deref().unwrap().contains("override 'spoon'"));
}

#[test]
fn a_utensil_named_ingredient_is_planned_as_what_it_clearly_holds() {
    // FOON's cooking spray is a can holding oil: planned as the ingredient nearest to it
    let sim = Pairs(&[("cooking spray", "cucumber", 1.0)]);
    let asked = r#"{"query": {"type": "salad", "ingredients": [
        {"object": "tomato", "state": "sliced"}, {"object": "cooking spray", "state": "oily"}]}}"#;
    let p = plan_of(BOTH, &sim, asked);
    let o = outcome(&p, "cooking spray");
    assert_eq!(o.status, Status::Planned, "{:?}", o.reason);
    assert_eq!(o.matched.as_ref().unwrap().label, "cucumber");
    assert!(o.reason.as_deref().unwrap().contains("container in FOON"));
    assert_eq!(goal_contents(&p), ["cooking spray", "tomato"]);
}

#[test]
fn a_utensil_named_ingredient_offers_alternatives_and_is_planned_as_the_one_picked() {
    // nothing near enough: the user says which ingredient it is
    let sim = Pairs(&[("cooking spray", "lettuce", 0.6)]);
    let asked = r#"{"query": {"type": "salad", "ingredients": [
        {"object": "tomato", "state": "sliced"}, {"object": "cooking spray", "state": "oily"}]}}"#;
    let p = plan_of(BOTH, &sim, asked);
    let o = outcome(&p, "cooking spray");
    assert_eq!(o.status, Status::Unplannable);
    assert!(o
        .reason
        .as_deref()
        .unwrap()
        .contains("utensil or container"));
    let offered: Vec<&str> = o.alternatives.iter().map(|a| a.label.as_str()).collect();
    assert_eq!(offered, ["lettuce"]);
    let picked = asked.replace("]}}", r#"]}, "overrides": {"cooking spray": "lettuce"}}"#);
    let p = plan_of(BOTH, &sim, &picked);
    let o = outcome(&p, "cooking spray");
    assert_eq!(o.status, Status::Planned, "{:?}", o.reason);
    assert_eq!(goal_contents(&p), ["cooking spray", "tomato"]);
}

#[test]
fn without_modification_the_reference_tree_is_returned_as_retrieved() {
    let request = r#"{"query": {"type": "salad", "ingredients": [
        {"object": "zucchini", "state": "sliced"}, {"object": "tomato", "state": "sliced"}]},
        "modify": false}"#;
    let p = plan_of(BOTH, &SIM, request);
    assert!(!p.modified);
    assert!(p.units.iter().all(|u| u.origin == Origin::Reference));
    assert!(labels(&p).contains("lettuce") && !labels(&p).contains("zucchini"));
    assert!(p.removed.is_empty());
    assert_eq!(outcome(&p, "tomato").case, Some(1));
}

#[test]
fn progress_lines_follow_each_ingredient_to_the_dish() {
    let p = salad(&[("tomato", "sliced"), ("lettuce", "chopped")]);
    let line = p
        .progress_lines
        .iter()
        .find(|l| l.ingredient == "tomato")
        .unwrap();
    let states: Vec<(&str, &str)> = line
        .state
        .iter()
        .map(|s| (s.physical_state.as_str(), s.location.as_str()))
        .collect();
    assert_eq!(
        states,
        [
            ("whole", ""),
            ("whole", "on cutting board"),
            ("sliced", "on cutting board"),
            ("in garden salad", "in salad bowl"),
        ]
    );
    assert_eq!(line.motion, ["pick-and-place", "slice", "mix"]);
    assert_eq!(line.end_product, "garden salad");
    // the published visualiser's shape
    let json = progress_json(&p);
    let first = &json.as_array().expect("an array of lines")[0];
    for key in ["ingredient", "state", "motion", "end_product"] {
        assert!(first.get(key).is_some(), "{key} missing in {first}");
    }
}

#[test]
fn exports_read_back_and_have_one_action_per_unit() {
    let p = salad(&[("tomato", "sliced"), ("zucchini", "sliced")]);
    // FOON text in the plain dialect reads back as the same units
    let text = foon_text(&p);
    let parsed = parse_str("plan.txt", &text).unwrap_or_else(|e| panic!("{e}\n{text}"));
    assert_eq!(parsed.units.len(), p.units.len());
    // PDDL: one action per functional unit; the goal is the goal node
    let d = pddl(&p);
    assert_eq!(
        d.domain.matches("(:action").count(),
        p.units.len(),
        "{}",
        d.domain
    );
    assert!(d.problem.contains("(:goal"), "{}", d.problem);
}

#[test]
fn the_plan_does_not_depend_on_the_order_of_the_files() {
    let q = query(
        "salad",
        &[
            ("tomato", "sliced"),
            ("zucchini", "sliced"),
            ("lettuce", "whole"),
        ],
    );
    let forward = plan_of(BOTH, &SIM, &q);
    let backward = plan_of(&[("soup.txt", SOUP), ("salad.txt", SALAD)], &SIM, &q);
    assert_eq!(forward, backward);
}

#[test]
fn a_state_change_comes_after_the_trees_cut_of_the_ingredient() {
    // the salad slices its tomato; the user wants it mashed: mashed after slicing, never sliced mash
    let p = salad(&[("tomato", "mashed")]);
    let o = outcome(&p, "tomato");
    assert_eq!(o.case, Some(3));
    assert_eq!(
        o.reason.as_deref(),
        Some("added 'mix' after 'slice' to make it 'mashed'")
    );
    let all = units(&p);
    let slice = all.iter().position(|u| u.starts_with("slice:")).unwrap();
    let mash = all
        .iter()
        .position(|u| u.ends_with("-> tomato (mashed, on [cutting board])"))
        .unwrap_or_else(|| panic!("{all:#?}"));
    assert!(slice < mash, "{all:#?}");
    assert_eq!(p.units[mash].origin, Origin::Grafted);
    // no node is both sliced and mashed, and the salad takes the mashed tomato
    for n in p
        .units
        .iter()
        .flat_map(|u| u.inputs.iter().chain(u.outputs.iter()))
    {
        let has = |s: &str| n.states.iter().any(|x| x == s);
        assert!(!(has("sliced") && has("mashed")), "{all:#?}");
    }
    assert_eq!(
        all.last().unwrap(),
        "mix: salad bowl (empty) + tomato (mashed, on [cutting board]) -> garden salad (contains {tomato}, in [salad bowl], mixed)"
    );
}

/// A salad dressed with vinegar poured from its bottle (the node says nothing of the vinegar's food
/// state), and a soup whose recipe starts the vinegar in the state `vinegar` (in none when `None`),
/// squeezes a lime, adds chili powder from its jar, and grinds peppercorns and slices a lime for garnish
/// (FOON's motions for 'ground' and 'sliced').
fn dressed(vinegar: Option<&str>) -> [(String, String); 2] {
    let vinegar = vinegar.map_or(String::new(), |s| format!("S\t{s}\n"));
    let salad = "//
O\tsalad bowl\t0
S\tempty
O\tlettuce\t1
S\tchopped
O\tvinegar\t1
S\tin\t[bottle]
M\tmix\t<Assumed>
O\tdressed salad\t1\t15
S\tmixed
S\tcontains\t{lettuce,vinegar}
S\tin\t[salad bowl]
//
";
    let soup = format!(
        "//
O\tpeppercorn\t1
S\twhole
M\tgrind\t<Assumed>
O\tpeppercorn\t1
S\tground
//
O\tlime\t1
S\twhole
M\tslice\t<Assumed>
O\tlime\t1
S\tsliced
//
O\tlime\t1
S\twhole
O\tsqueezer\t0
S\tclean
M\tsqueeze\t<Assumed>
O\tlime\t1
S\tjuice
//
O\tpot\t0
S\tempty
O\tlime\t1
S\tjuice
O\tvinegar\t1
{vinegar}S\tin\t[bottle]
O\tchili powder\t1
S\tin\t[jar]
M\tpour\t<Assumed>
O\tpot\t0
S\tcontains\t{{chili powder,lime,vinegar}}
//
O\tpot\t0
S\tcontains\t{{chili powder,lime,vinegar}}
M\tboil\t<Assumed>
O\tsour soup\t1\t1
S\tcooked
S\tcontains\t{{chili powder,lime,vinegar}}
S\tin\t[pot]
//
"
    );
    [
        ("salad.txt".to_string(), salad.to_string()),
        ("soup.txt".to_string(), soup),
    ]
}

fn dressed_salad(vinegar: Option<&str>, modify: bool) -> Plan {
    dressed_with(
        vinegar,
        modify,
        &[("lettuce", "chopped"), ("vinegar", "juice")],
    )
}

fn dressed_with(vinegar: Option<&str>, modify: bool, items: &[(&str, &str)]) -> Plan {
    let files = dressed(vinegar);
    let files: Vec<(&str, &str)> = files
        .iter()
        .map(|(n, t)| (n.as_str(), t.as_str()))
        .collect();
    let mut request = query("salad", items);
    if !modify {
        request = request.replacen('{', r#"{"modify": false, "#, 1);
    }
    plan_of(&files, &ExactMatch, &request)
}

#[test]
fn an_ingredient_foon_starts_as_a_liquid_is_not_squeezed_to_be_one() {
    // FOON's recipes start vinegar liquid: the salad's bottled vinegar is the 'juice' asked for
    let p = dressed_salad(Some("liquid"), true);
    let o = outcome(&p, "vinegar");
    assert_eq!(o.case, Some(1), "{o:#?}");
    assert_eq!(
        o.reason.as_deref(),
        Some("state 'juice' matched by category (liquid): 'vinegar' comes as a liquid")
    );
    assert_eq!(
        units(&p),
        ["mix: lettuce (chopped) + salad bowl (empty) + vinegar (in [bottle], liquid) -> dressed salad (contains {lettuce,vinegar}, in [salad bowl], mixed)"]
    );
    assert_eq!(
        dressed_salad(Some("liquid"), false).ingredients[1].case,
        Some(1)
    );
    // had FOON's recipes started it whole, FOON's motion for juice would squeeze it: a liquid is not
    // squeezed (food_forms.tsv), so the vinegar is taken as it is
    let p = dressed_salad(Some("whole"), true);
    let o = outcome(&p, "vinegar");
    assert_eq!(o.case, Some(3), "{o:#?}");
    assert_eq!(
        o.reason.as_deref(),
        Some("state 'juice' not given: vinegar (liquid) is not 'squeeze'; kept the tree's state")
    );
    assert!(
        !makes(&p, "squeeze", "vinegar", "juice"),
        "{:#?}",
        units(&p)
    );
    assert_eq!(
        dressed_salad(Some("whole"), false).ingredients[1].case,
        Some(3)
    );
    // had FOON's recipes never said, the food taxonomy would: vinegar is sold as a liquid
    let o = outcome(&dressed_salad(None, true), "vinegar").clone();
    assert_eq!(o.case, Some(1), "{o:#?}");
}

#[test]
fn an_ingredient_sold_ground_is_not_ground_again_and_a_liquid_is_never_sliced() {
    // chili powder, named so, comes ground: the soup's branch brings it as it is
    let p = dressed_with(
        Some("liquid"),
        true,
        &[("lettuce", "chopped"), ("chili powder", "ground")],
    );
    let o = outcome(&p, "chili powder");
    assert_eq!(o.case, Some(4), "{o:#?}");
    assert_eq!(o.status, Status::Planned);
    assert!(
        !p.units.iter().any(|u| u.motion == "grind"),
        "{:#?}",
        units(&p)
    );
    assert!(
        goal_contents(&p).contains(&"chili powder"),
        "{:#?}",
        units(&p)
    );
    // where the name says nothing, the recipe's whole peppercorn is ground
    let p = dressed_with(
        Some("liquid"),
        true,
        &[("lettuce", "chopped"), ("peppercorn", "ground")],
    );
    assert!(
        makes(&p, "grind", "peppercorn", "ground"),
        "{:#?}",
        units(&p)
    );
    // nothing makes liquid vinegar or ground chili powder sliced, from the tree or from FOON
    let p = dressed_with(
        Some("liquid"),
        true,
        &[
            ("lettuce", "chopped"),
            ("vinegar", "sliced"),
            ("chili powder", "sliced"),
        ],
    );
    assert_eq!(
        outcome(&p, "vinegar").reason.as_deref(),
        Some("state 'sliced' cannot be reached from the tree's 'liquid' (not reversible); kept 'liquid'")
    );
    let reason = outcome(&p, "chili powder").reason.clone().unwrap();
    assert!(
        reason.contains("state 'sliced' cannot be reached from ground (not reversible)"),
        "{reason}"
    );
    assert!(
        !p.units.iter().any(|u| u.motion == "slice"),
        "{:#?}",
        units(&p)
    );
    // nor made whole again
    let p = dressed_with(
        Some("liquid"),
        true,
        &[("lettuce", "chopped"), ("chili powder", "whole")],
    );
    let reason = outcome(&p, "chili powder").reason.clone().unwrap();
    assert!(
        reason.contains("state 'whole' cannot be reached from ground (not reversible)"),
        "{reason}"
    );
}

/// A custard (class 8): egg and milk poured into a bowl and whisked, the batter poured into a pot, which
/// is covered and cooked.
const CUSTARD: &str = "//
O\tbowl\t0
S\tempty
O\tegg\t1
S\tcracked
O\tmilk\t1
S\tliquid
M\tpour\t<Assumed>
O\tbowl\t0
S\tcontains\t{egg,milk}
//
O\tbowl\t0
S\tcontains\t{egg,milk}
O\twhisk\t1
M\tmix\t<Assumed>
O\tbowl\t0
S\tcontains\t{custard batter}
O\tcustard batter\t1
S\tmixed
S\tcontains\t{egg,milk}
S\tin\t[bowl]
//
O\tpot\t0
S\tempty
O\tcustard batter\t1
S\tmixed
S\tcontains\t{egg,milk}
S\tin\t[bowl]
M\tpour\t<Assumed>
O\tpot\t0
S\tcontains\t{custard batter}
//
O\tpot\t0
S\tcontains\t{custard batter}
O\tpot lid\t1
M\tcover\t<Assumed>
O\tpot\t0
S\tcontains\t{custard batter}
S\tcovered\t[pot lid]
//
O\tpot\t0
S\tcontains\t{custard batter}
S\tcovered\t[pot lid]
M\tcook\t<Assumed>
O\tcustard\t1\t8
S\tcooked
S\tcontains\t{egg,milk}
S\tin\t[pot]
//
";

#[test]
fn a_step_names_the_food_a_tool_works_on_the_container_it_closes_and_where_food_goes() {
    let p = plan_of(
        &[("custard.txt", CUSTARD)],
        &ExactMatch,
        &query("dessert", &[("egg", "cracked"), ("milk", "liquid")]),
    );
    assert_eq!(
        p.steps,
        [
            // the moved food says nothing of where it goes: the bowl that now lists it does
            "Pour the egg and the milk into the bowl.",
            "Mix the egg and the milk in the bowl with the whisk.",
            "Pour the custard batter into the pot.",
            "Cover the pot with the pot lid.",
            // the pot is cooked with what it holds: the step names what it holds
            "Cook the custard batter in the pot.",
        ],
        "{:#?}",
        units(&p)
    );
}

/// A salad (class 15) of buttered bread: the bread goes into a pan, is mixed with butter there, and only
/// the bread goes on to be toasted; the pan, listing everything, is left behind. With `buttered`, the
/// mixing also lists the butter on the bread; without, only the pan holds anything after it.
fn toast_salad(buttered: bool) -> String {
    let bread_after = if buttered {
        "O\tbread\t1\nS\tcontains\t{butter}\nS\tin\t[pan]\n"
    } else {
        "O\tbread\t1\nS\tin\t[pan]\nS\tsoftened\n"
    };
    format!(
        "//
O\tpan\t0
S\tempty
O\tbread\t1
S\tsliced
M\tpick-and-place\t<Assumed>
O\tpan\t0
S\tcontains\t{{bread}}
O\tbread\t1
S\tsliced
S\tin\t[pan]
//
O\tpan\t0
S\tcontains\t{{bread}}
O\tbread\t1
S\tsliced
S\tin\t[pan]
O\tbutter\t1
S\tsoftened
M\tmix\t<Assumed>
O\tpan\t0
S\tcontains\t{{bread,butter}}
{bread_after}//
{bread_after}M\ttoast\t<Assumed>
O\ttoast salad\t1\t15
S\ttoasted
S\tcontains\t{{bread,butter}}
//
"
    )
}

/// Salt, in the kitchen as bought, in a recipe of its own.
const SALTED: &str = "//
O\tpot\t0
S\tempty
O\tsalt\t1
S\tgranulated
M\tsprinkle\t<Assumed>
O\tpot\t0
S\tcontains\t{salt}
//
";

/// The salad of buttered bread with salt added.
fn salted_toast(buttered: bool) -> Plan {
    let recipe = toast_salad(buttered);
    plan_of(
        &[("toast.txt", &recipe), ("salt.txt", SALTED)],
        &ExactMatch,
        &query(
            "salad",
            &[
                ("bread", "sliced"),
                ("butter", "softened"),
                ("salt", "granulated"),
            ],
        ),
    )
}

/// The salad of buttered bread with salt added: the salt joins the unit of `motion`, and the dish lists it.
fn assert_salt_joins(buttered: bool, motion: &str) {
    let p = salted_toast(buttered);
    let salt = outcome(&p, "salt");
    assert_eq!((salt.case, salt.status), (Some(4), Status::Planned));
    let reason = salt.reason.as_deref().unwrap();
    assert!(
        reason.ends_with(&format!("added at '{motion}'")),
        "{salt:#?}"
    );
    let contents = goal_contents(&p);
    assert_eq!(contents, ["bread", "butter", "salt"], "{:#?}", units(&p));
}

#[test]
fn an_added_ingredient_goes_with_what_reaches_the_dish_not_the_pan_left_behind() {
    // the mixing unit is where salads take ingredients: the salt joins it, and goes onto the bread,
    // which the toasting takes on, rather than into the pan, which holds more but goes nowhere
    assert_salt_joins(true, "mix");
    // where nothing the mixing makes goes on to the dish, the salt joins the toasting instead
    assert_salt_joins(false, "toast");
}

/// A recipe that puts sliced bread onto an empty plate, the plate then listing `holds`, and goes on with
/// `rest` (FOON lines).
fn bread_onto_plate(holds: &str, rest: &str) -> String {
    format!(
        "//\nO\tplate\t0\nS\tempty\nO\tbread\t1\nS\tsliced\nM\tpick-and-place\t<Assumed>\n\
         O\tplate\t0\nS\tcontains\t{{{holds}}}\n{rest}//\n"
    )
}

#[test]
fn a_dish_listing_nothing_takes_the_added_ingredient_rather_than_the_plate() {
    // the dish is plated and lists no contents; the plate lists the dish
    let plated = bread_onto_plate(
        "toast salad",
        "O\ttoast salad\t1\t15\nS\tempty\nS\ton\t[plate]\n",
    );
    let p = plan_of(
        &[("plated.txt", &plated), ("salt.txt", SALTED)],
        &ExactMatch,
        &query("salad", &[("bread", "sliced"), ("salt", "granulated")]),
    );
    assert_eq!(goal_contents(&p), ["salt"], "{:#?}", units(&p));
    let goal = &p.units.last().unwrap().outputs;
    let dish = goal.iter().find(|n| n.label == p.goal.label).unwrap();
    assert_eq!(dish.states, ["contains {salt}", "on [plate]"]);
}

#[test]
fn a_step_puts_food_on_what_the_recipe_puts_things_on() {
    // the bread's node says nothing of where it goes; the plate that lists it does, and the recipe
    // puts things on a plate rather than in it
    let served = bread_onto_plate(
        "bread",
        "//\nO\tplate\t0\nS\tcontains\t{bread}\nO\tfork\t1\nM\tarrange\t<Assumed>\n\
         O\tbread salad\t1\t15\nS\tcontains\t{bread}\nS\ton\t[plate]\n",
    );
    let p = plan_of(
        &[("served.txt", &served)],
        &ExactMatch,
        &query("salad", &[("bread", "sliced")]),
    );
    assert_eq!(
        p.steps[0], "Place the bread onto the plate.",
        "{:#?}",
        p.steps
    );
}

#[test]
fn a_step_uncovers_the_pot_not_the_lid_and_attaches_a_bowl_to_its_machine() {
    let soup = "//
O\tblender\t0
S\toff
O\tblender jar\t1
S\tempty
M\tattach\t<Assumed>
O\tblender jar\t1
S\tattached to\t[blender]
S\tempty
//
O\tblender jar\t1
S\tattached to\t[blender]
S\tempty
O\ttomato\t1
S\tchopped
M\tpour\t<Assumed>
O\tblender jar\t1
S\tattached to\t[blender]
S\tcontains\t{tomato}
//
O\tblender jar\t0
S\tattached to\t[blender]
S\tcontains\t{tomato}
O\tblender lid\t1
M\tcover\t<Assumed>
O\tblender jar\t0
S\tattached to\t[blender]
S\tcontains\t{tomato}
S\tcovered\t[blender lid]
O\tblender lid\t1
S\ton\t[blender jar]
//
O\tblender jar\t1
S\tattached to\t[blender]
S\tcontains\t{tomato}
S\tcovered\t[blender lid]
O\tblender lid\t1
S\ton\t[blender jar]
M\tuncover\t<Assumed>
O\ttomato soup\t1\t1
S\tcontains\t{tomato}
S\tin\t[blender jar]
//
";
    assert_steps(
        soup,
        "soup",
        &[
            "Attach the blender jar to the blender.",
            "Pour the tomato into the blender jar.",
            "Cover the blender jar with the blender lid.",
            "Uncover the blender jar.",
        ],
    );
}

#[test]
fn a_step_stirs_the_food_not_the_empty_spoon() {
    let stirred = "//
O\tbowl\t0
S\tempty
O\ttomato\t1
S\tchopped
M\tpour\t<Assumed>
O\tbowl\t0
S\tcontains\t{tomato}
//
O\tbowl\t0
S\tcontains\t{tomato}
O\tspoon\t1
S\tempty
M\tstir\t<Assumed>
O\ttomato salad\t1\t15
S\tcontains\t{tomato}
S\tin\t[bowl]
//
";
    assert_steps(
        stirred,
        "salad",
        &[
            "Pour the tomato into the bowl.",
            "Stir the tomato in the bowl.",
        ],
    );
}

/// FOON lists what a bowl already holds among the inputs of the next thing put in it, and moves an olive
/// along with the oil poured over it.
const BOWL_FILLED: &str = "//
O\ttomato\t1
S\tchopped
O\tbowl\t0
S\tempty
M\tpour\t<Assumed>
O\tbowl\t0
S\tcontains\t{tomato}
//
O\tonion\t1
S\tchopped
O\ttomato\t1
S\tchopped
S\tin\t[bowl]
O\tbowl\t0
S\tcontains\t{tomato}
M\tpour\t<Assumed>
O\tbowl\t0
S\tcontains\t{onion,tomato}
//
O\tolive\t1
S\twhole
S\tin\t[jar]
O\toil\t1
S\tin\t[bottle]
O\tbowl\t0
S\tcontains\t{onion,tomato}
M\tpour\t<Assumed>
O\tolive\t1
S\twhole
S\tin\t[bowl]
O\tbowl\t0
S\tcontains\t{oil,olive,onion,tomato}
//
O\tbowl\t0
S\tcontains\t{oil,olive,onion,tomato}
O\tspoon\t1
M\tmix\t<Assumed>
O\ttomato salad\t1\t15
S\tcontains\t{oil,olive,onion,tomato}
S\tin\t[bowl]
//
";

#[test]
fn food_already_in_the_bowl_is_not_put_there_again() {
    let items = [
        ("tomato", "chopped"),
        ("onion", "chopped"),
        ("olive", "whole"),
        ("oil", ""),
    ];
    let p = recipe_plan(BOWL_FILLED, "salad", &items);
    assert_eq!(
        p.steps[..3],
        [
            "Pour the tomato into the bowl.",
            "Pour the onion into the tomato in the bowl.",
            "Pour the oil and the olive into the bowl.",
        ],
        "{:#?}",
        units(&p)
    );
    let line = |ingredient: &str| {
        let l = p
            .progress_lines
            .iter()
            .find(|l| l.ingredient == ingredient)
            .unwrap();
        let states: Vec<String> = l
            .state
            .iter()
            .map(|s| format!("{} @ {}", s.physical_state, s.location))
            .collect();
        (states, l.motion.clone(), l.end_product.clone())
    };
    // the tomato stays in the bowl while the onion joins it: no step of its own
    let (states, motions, dish) = line("tomato");
    assert_eq!(
        states,
        [
            "chopped @ ",
            "chopped @ in bowl",
            "in tomato salad @ in bowl"
        ]
    );
    assert_eq!(motions, ["pour", "mix"]);
    assert_eq!(dish, "tomato salad");
    // the oil goes into the bowl, not into the olive poured with it
    let (states, motions, dish) = line("oil");
    assert_eq!(
        states,
        [
            "liquid @ in bottle",
            "liquid @ in bowl",
            "in tomato salad @ in bowl"
        ]
    );
    assert_eq!(motions, ["pour", "mix"]);
    assert_eq!(dish, "tomato salad");
}

#[test]
fn a_ladle_scoops_out_of_the_pot_into_the_bowl() {
    let ladled = "//
O\tpot\t0
S\tempty
O\tnoodle\t1
S\tcooked
M\tpour\t<Assumed>
O\tpot\t0
S\tcontains\t{noodle}
//
O\tbowl\t0
S\tempty
O\tladle\t1
O\tpot\t0
S\tcontains\t{noodle}
M\tscoop and pour\t<Assumed>
O\tbowl\t0
S\tcontains\t{noodle soup}
O\tnoodle soup\t1\t14
S\tcontains\t{noodle}
S\tin\t[bowl]
//
";
    let p = recipe_plan(ladled, "noodle", &[("noodle", "cooked")]);
    assert_eq!(
        p.steps,
        [
            "Pour the noodle into the pot.",
            "Scoop and pour the noodle into the bowl with the ladle."
        ],
        "{:#?}",
        units(&p)
    );
}

#[test]
fn a_blend_names_all_the_cup_holds_not_only_what_foon_moves() {
    let smoothie = "//
O\tblender cup\t0
S\tempty
O\tbanana\t1
S\tsliced
O\tmilk\t1
S\tliquid
M\tpour\t<Assumed>
O\tblender cup\t0
S\tcontains\t{banana,milk}
//
O\tblender cup\t0
S\tcontains\t{banana,milk}
O\thoney\t1
S\tliquid
M\tpour\t<Assumed>
O\tblender cup\t0
S\tcontains\t{banana,honey,milk}
O\thoney\t1
S\tliquid
S\tin\t[blender cup]
//
O\tblender cup\t0
S\tcontains\t{banana,honey,milk}
O\thoney\t1
S\tliquid
S\tin\t[blender cup]
O\tblender\t0
M\tblend\t<Assumed>
O\tsmoothie\t1\t9
S\tblended
S\tcontains\t{banana,honey,milk}
S\tin\t[blender cup]
//
";
    let items = [
        ("banana", "sliced"),
        ("milk", "liquid"),
        ("honey", "liquid"),
    ];
    let p = recipe_plan(smoothie, "drinks", &items);
    assert_eq!(
        p.steps.last().map(String::as_str),
        Some("Blend the honey, the banana and the milk in the blender cup with the blender."),
        "{:#?}",
        units(&p)
    );
}

/// The steps of a dish of chopped tomato planned on one recipe.
/// A sound plan from one hand-made recipe, names matched exactly.
fn recipe_plan(recipe: &str, dish: &str, items: &[(&str, &str)]) -> Plan {
    plan_of(&[("recipe.txt", recipe)], &ExactMatch, &query(dish, items))
}

fn assert_steps(recipe: &str, dish: &str, steps: &[&str]) {
    let p = recipe_plan(recipe, dish, &[("tomato", "chopped")]);
    assert_eq!(p.steps, steps, "{:#?}", units(&p));
}

/// FOON text of a tomato on the cutting board cut in turn (`cuts`: state before, motion, state after), then
/// poured into a bowl: a tomato salad.
fn cut_in_turn(cuts: &[(&str, &str, &str)]) -> String {
    let on_board = |state: &str| format!("O\ttomato\t1\nS\t{state}\nS\ton\t[cutting board]\n");
    let mut text = String::from("//\n");
    for (before, motion, after) in cuts {
        text += &on_board(before);
        text += &format!("O\tknife\t1\nM\t{motion}\t<Assumed>\n");
        text += &on_board(after);
        text += "//\n";
    }
    text += &on_board(cuts.last().map_or("whole", |c| c.2));
    text += "O\tbowl\t0\nS\tempty\nM\tpour\t<Assumed>\n";
    text + "O\ttomato salad\t1\t15\nS\tcontains\t{tomato}\nS\tin\t[bowl]\n//\n"
}

#[test]
fn two_steps_that_read_the_same_say_what_each_makes() {
    let cut_twice = cut_in_turn(&[("chopped", "cut", "halved"), ("halved", "cut", "stripped")]);
    assert_steps(
        &cut_twice,
        "salad",
        &[
            "Cut the tomato on the cutting board until it is halved.",
            "Cut the tomato on the cutting board until it is stripped.",
            "Pour the tomato into the bowl.",
        ],
    );
}

#[test]
fn a_step_puts_the_food_where_a_phrasal_motion_needs_it() {
    let slit = cut_in_turn(&[
        ("whole", "make slits", "slit"),
        ("slit", "cut off skin", "peeled"),
        ("peeled", "cut in half", "halved"),
    ]);
    assert_steps(
        &slit,
        "salad",
        &[
            "Make slits in the tomato on the cutting board.",
            "Cut the skin off the tomato on the cutting board.",
            "Cut the tomato in half on the cutting board.",
            "Pour the tomato into the bowl.",
        ],
    );
}

#[test]
fn a_step_says_where_the_food_it_makes_is() {
    // the cracked egg becomes the bowl's egg white and yolk; the blended tomato is poured as "mixture" and
    // becomes the soup in the bowl: no output names either, nor lists them
    let cracked_and_blended = "//
O\tbowl\t0
S\tempty
O\tegg\t1
S\twhole
M\tcrack\t<Assumed>
O\tegg white and yolk\t1
S\tin\t[bowl]
//
O\tblender jar\t0
S\tempty
O\ttomato\t1
S\tchopped
M\tblend\t<Assumed>
O\tmixture\t1
S\tblended
S\tin\t[blender jar]
//
O\tmixture\t1
S\tblended
S\tin\t[blender jar]
O\tegg white and yolk\t0
S\tin\t[bowl]
M\tpour\t<Assumed>
O\tsoup\t1\t1
S\tin\t[bowl]
//
";
    let p = recipe_plan(
        cracked_and_blended,
        "soup",
        &[("egg", "whole"), ("tomato", "chopped")],
    );
    assert_eq!(
        p.steps,
        [
            "Crack the egg in the bowl.",
            "Blend the tomato in the blender jar.",
            "Pour the mixture into the bowl.",
        ],
        "{:#?}",
        units(&p)
    );
}

#[test]
fn an_emptied_jar_is_not_put_into_the_pot() {
    // the bay leaf goes from its jar into the pot, making the soup; with the bay leaf pruned, only the
    // empty jar moves, and the soup in the pot is not where it goes
    let jarred = "//
O\tpot\t0
S\tempty
O\tonion\t1
S\tchopped
M\tpour\t<Assumed>
O\tpot\t0
S\tcontains\t{onion}
//
O\tpot\t0
S\tcontains\t{onion}
O\tjar\t1
S\tcontains\t{bay leaf}
O\tbay leaf\t1
S\tin\t[jar]
M\tput inside\t<Assumed>
O\tonion soup\t1\t1
S\tin\t[pot]
S\tcontains\t{bay leaf,onion}
//
";
    let p = recipe_plan(jarred, "soup", &[("onion", "chopped")]);
    assert_eq!(p.removed, ["bay leaf"]);
    assert!(
        p.steps.iter().all(|s| !s.contains("jar into")),
        "{:#?}\n{:#?}",
        p.steps,
        units(&p)
    );
}

#[test]
fn food_goes_into_a_jar_a_lid_goes_on() {
    // the lid's "on [blender jar]" (before any food's "in" among the tree's nodes) does not say how food
    // is put in the jar: the tomato is scooped into it
    let covered_jar = "//
O\tblender jar\t0
S\tempty
O\tblender cover\t1
M\tcover\t<Assumed>
O\tblender jar\t0
S\tcovered\t[blender cover]
O\tblender cover\t1
S\ton\t[blender jar]
//
O\tblender jar\t0
S\tcovered\t[blender cover]
O\tblender cover\t1
S\ton\t[blender jar]
M\tuncover\t<Assumed>
O\tblender jar\t0
S\tuncovered
O\tblender cover\t1
//
O\tblender jar\t0
S\tuncovered
O\tbowl\t0
S\tcontains\t{tomato}
O\ttomato\t1
S\tchopped
S\tin\t[bowl]
O\tspoon\t1
M\tscoop and pour\t<Assumed>
O\tblender jar\t0
S\tcontains\t{tomato}
O\tbowl\t0
S\tempty
//
O\tblender jar\t0
S\tcontains\t{tomato}
M\tblend\t<Assumed>
O\ttomato soup\t1
S\tblended
S\tin\t[blender jar]
//
O\ttomato soup\t1
S\tblended
S\tin\t[blender jar]
O\tbowl\t0
S\tempty
M\tpour\t<Assumed>
O\ttomato soup\t1\t1
S\tblended
S\tin\t[bowl]
//
";
    let p = recipe_plan(covered_jar, "soup", &[("tomato", "chopped")]);
    assert_eq!(
        p.steps,
        [
            "Cover the blender jar with the blender cover.",
            "Uncover the blender jar.",
            "Scoop and pour the tomato into the blender jar.",
            "Blend the tomato in the blender jar.",
            "Pour the tomato soup into the bowl.",
        ],
        "{:#?}",
        units(&p)
    );
}

#[test]
fn a_pot_is_covered_once_nothing_more_is_done_in_it_open() {
    // the stir gives the open pot back as it took it, and the cover changes it: the stir comes first,
    // whatever order the tree lists them in
    let covered_late = "//
O\tpot\t0
S\tempty
O\trice\t1
S\tuncooked
M\tpour\t<Assumed>
O\tpot\t0
S\tcontains\t{rice}
O\trice\t1
S\tuncooked
S\tin\t[pot]
//
O\tpot\t0
S\tcontains\t{rice}
O\tpot lid\t1
M\tcover\t<Assumed>
O\tpot\t0
S\tcontains\t{rice}
S\tcovered
O\tpot lid\t1
S\ton\t[pot]
//
O\tpot\t0
S\tcontains\t{rice}
O\trice\t1
S\tuncooked
S\tin\t[pot]
O\tspoon\t1
M\tstir\t<Assumed>
O\tpot\t0
S\tcontains\t{rice}
O\trice\t1
S\ttoasted
S\tin\t[pot]
//
O\tpot\t0
S\tcontains\t{rice}
S\tcovered
O\trice\t1
S\ttoasted
S\tin\t[pot]
M\tsimmer\t<Assumed>
O\trice soup\t1\t1
S\tcooked
S\tin\t[pot]
//
";
    let p = recipe_plan(covered_late, "soup", &[("rice", "uncooked")]);
    assert_eq!(
        p.steps,
        [
            "Pour the rice into the pot.",
            "Stir the rice in the pot.",
            "Cover the pot with the pot lid.",
            "Simmer the rice in the pot.",
        ],
        "{:#?}",
        units(&p)
    );
}

#[test]
fn butter_only_a_list_names_goes_and_the_pot_is_not_opened_before_it_is_used() {
    // FOON's "contain {butter}" makes no node of the butter: it is an ingredient all the same, and not
    // asked for, it leaves every list. The pot of rice it told apart is then made twice, poured and
    // uncovered again: the stir needs it as poured, the serving as uncovered.
    let buttered = "//
O\tpot\t0
S\tcontain\t{butter}
O\trice\t1
S\tuncooked
M\tpour\t<Assumed>
O\tpot\t0
S\tcontains\t{butter,rice}
O\trice\t1
S\tuncooked
S\tin\t[pot]
//
O\tpot\t0
S\tcontains\t{butter,rice}
O\trice\t1
S\tuncooked
S\tin\t[pot]
O\tspoon\t1
M\tstir\t<Assumed>
O\tpot\t0
S\tcontains\t{butter,rice}
O\trice\t1
S\ttoasted
S\tin\t[pot]
//
O\tpot\t0
S\tcontains\t{butter,rice}
O\tpot lid\t1
M\tcover\t<Assumed>
O\tpot\t0
S\tcontains\t{butter,rice}
S\tcovered
O\tpot lid\t1
S\ton\t[pot]
//
O\tpot\t0
S\tcontains\t{butter,rice}
S\tcovered
O\trice\t1
S\ttoasted
S\tin\t[pot]
M\tsimmer\t<Assumed>
O\tpot\t0
S\tcontains\t{rice}
S\tcovered
O\trice\t1
S\tcooked
S\tin\t[pot]
//
O\tpot\t0
S\tcontains\t{rice}
S\tcovered
O\tpot lid\t1
S\ton\t[pot]
M\tuncover\t<Assumed>
O\tpot\t0
S\tcontains\t{rice}
O\tpot lid\t1
//
O\tpot\t0
S\tcontains\t{rice}
O\trice\t1
S\tcooked
S\tin\t[pot]
O\tbowl\t0
S\tempty
M\tscoop and pour\t<Assumed>
O\trice soup\t1\t1
S\tcontains\t{butter,rice}
S\tin\t[bowl]
//
";
    let p = recipe_plan(buttered, "soup", &[("rice", "uncooked")]);
    assert_eq!(
        p.steps,
        [
            "Pour the rice into the pot.",
            "Stir the rice in the pot.",
            "Cover the pot with the pot lid.",
            "Simmer the rice in the pot.",
            "Uncover the pot.",
            "Scoop and pour the rice into the bowl.",
        ],
        "{:#?}",
        units(&p)
    );
    assert_eq!(p.removed, ["butter"]);
    assert_eq!(goal_contents(&p), ["rice"]);
}

#[test]
fn a_bowl_emptied_by_pruning_is_not_poured() {
    // the salt is not asked for: its bowl, empty, pours nothing into the pot, and the pour goes (though
    // FOON's pot is no longer hot after it)
    let salted = "//
O\tpot\t0
S\tempty
O\tonion\t1
S\tchopped
M\tpour\t<Assumed>
O\tpot\t0
S\tcontains\t{onion}
S\thot
//
O\tbowl\t1
S\tcontains\t{salt}
O\tsalt\t1
S\tin\t[bowl]
O\tpot\t0
S\tcontains\t{onion}
S\thot
M\tpour\t<Assumed>
O\tbowl\t1
S\tempty
O\tpot\t0
S\tcontains\t{onion,salt}
//
O\tpot\t0
S\tcontains\t{onion,salt}
M\tboil\t<Assumed>
O\tonion soup\t1\t1
S\tcooked
S\tcontains\t{onion,salt}
S\tin\t[pot]
//
";
    let p = recipe_plan(salted, "soup", &[("onion", "chopped")]);
    assert_eq!(p.removed, ["salt"]);
    assert_eq!(
        p.steps,
        ["Pour the onion into the pot.", "Boil the onion in the pot."],
        "{:#?}",
        units(&p)
    );
}

/// Sauces poured from their bottles (recorded as "sauce" only once poured) and a tomato blended into one.
const SAUCES: &str = "//
O\tketchup\t1
S\tin\t[bottle]
M\tpour\t<Assumed>
O\tketchup\t1
S\tsauce
S\tin\t[bowl]
//
O\tmustard\t1
S\tin\t[bottle]
M\tpour\t<Assumed>
O\tmustard\t1
S\tsauce
S\tin\t[bowl]
//
O\ttomato\t1
S\twhole
O\tblender\t0
M\tblend\t<Assumed>
O\ttomato\t1
S\tsauce
//
O\tpepper\t1
S\twhole
O\tknife\t0
M\tslice\t<Assumed>
O\tpepper\t1
S\tsliced
//
";

/// A salad of six units made of cucumber alone.
const CUCUMBER_SALAD: &str = "//
O\tcucumber\t1
S\tdirty
M\twash\t<Assumed>
O\tcucumber\t1
S\twashed
//
O\tcucumber\t1
S\twashed
O\tpeeler\t1
M\tpeel\t<Assumed>
O\tcucumber\t1
S\tpeeled
//
O\tcutting board\t0
S\tempty
O\tcucumber\t1
S\tpeeled
M\tpick-and-place\t<Assumed>
O\tcucumber\t1
S\tpeeled
S\ton\t[cutting board]
//
O\tcucumber\t1
S\tpeeled
S\ton\t[cutting board]
O\tknife\t1
M\tslice\t<Assumed>
O\tcucumber\t1
S\tsliced
S\ton\t[cutting board]
//
O\tbowl\t0
S\tempty
O\tcucumber\t1
S\tsliced
S\ton\t[cutting board]
M\tpour\t<Assumed>
O\tbowl\t0
S\tcontains\t{cucumber}
//
O\tbowl\t0
S\tcontains\t{cucumber}
O\tspoon\t1
M\tmix\t<Assumed>
O\tcucumber salad\t1\t15
S\tcontains\t{cucumber}
S\tin\t[bowl]
//
";

#[test]
fn a_plan_keeping_next_to_nothing_of_its_reference_says_so() {
    let files = [("salad.txt", CUCUMBER_SALAD), ("sauces.txt", SAUCES)];
    let little = |p: &Plan| {
        p.notes
            .iter()
            .any(|n| n.starts_with("little of the reference task tree"))
    };
    // nothing of the cucumber's six units is asked for: only the dish's last unit is left
    let p = plan_of(&files, &ExactMatch, &query("salad", &[("tomato", "sauce")]));
    assert!(little(&p), "{:?}\n{:#?}", p.notes, units(&p));
    assert!(
        p.notes
            .iter()
            .any(|n| n.contains("1 of its 6 units kept ('salad.txt')")),
        "{:?}",
        p.notes
    );
    // asked for, the cucumber keeps its units, and nothing is said
    let p = plan_of(
        &files,
        &ExactMatch,
        &query("salad", &[("tomato", "sauce"), ("cucumber", "sliced")]),
    );
    assert!(!little(&p), "{:?}", p.notes);
}

#[test]
fn a_state_is_made_by_a_motion_that_makes_it_never_by_a_pour() {
    // FOON pours two sauces and blends one: pouring moves a sauce, the blender makes one (a carrot: a
    // pepper asked "sauce" is hot sauce, bought so)
    let sauces = SAUCES.replace("pepper", "carrot");
    let files = [("salad.txt", SALAD), ("sauces.txt", sauces.as_str())];
    let p = plan_of(
        &files,
        &SIM,
        &query("salad", &[("lettuce", "chopped"), ("carrot", "sauce")]),
    );
    let o = outcome(&p, "carrot");
    assert!(makes(&p, "blend", "carrot", "sauce"), "{:#?}", units(&p));
    assert!(!makes(&p, "pour", "carrot", "sauce"), "{:#?}", units(&p));
    assert!(
        o.reason
            .as_deref()
            .is_some_and(|r| r.contains("then 'blend' to make it 'sauce'")),
        "{o:#?}"
    );
}

/// A dish named after its main ingredient (class 1, soup): black beans poured from their bowl into a
/// pot, then cooked with chopped onion into the dish, also called black bean.
const BLACK_BEANS: &str = "//
O\tbowl\t0
S\tcontains\t{black bean}
O\tblack bean\t1
S\tin\t[bowl]
O\tpot\t0
S\tempty
M\tpour\t<Assumed>
O\tpot\t0
S\tcontains\t{black bean}
O\tblack bean\t1
S\tin\t[pot]
//
O\tpot\t0
S\tcontains\t{black bean}
O\tblack bean\t1
S\tin\t[pot]
O\tonion\t1
S\tchopped
M\tcook and stir\t<Assumed>
O\tblack bean\t1\t1
S\tcooked
S\tcontains\t{onion}
S\tin\t[pot]
//
";

#[test]
fn the_ingredient_a_dish_is_named_after_is_pruned_when_not_asked_for_and_the_dish_stays() {
    let files = [("black_beans.txt", BLACK_BEANS)];
    let p = plan_of(&files, &SIM, &query("soup", &[("onion", "chopped")]));
    assert_eq!(p.goal.reference, "black bean");
    // a soup without beans is not called after them
    assert_eq!(p.goal.label, "soup");
    assert_eq!(p.removed, ["black bean"]);
    // nor is it when black pepper seasons it ("black" names no food of the dish)
    let peppered = query("soup", &[("onion", "chopped"), ("black pepper", "ground")]);
    let with_pepper = [
        ("black_beans.txt", BLACK_BEANS),
        ("pepper.txt", BLACK_PEPPER),
    ];
    let seasoned = plan_of(&with_pepper, &SIM, &peppered);
    assert_eq!(seasoned.removed, ["black bean"]);
    assert_eq!(seasoned.goal.label, "soup");
    // the dish is cooked from the onion alone: no bean is poured, none goes into the pot
    assert_eq!(
        units(&p),
        ["cook and stir: onion (chopped) + pot (empty) -> soup (contains {onion}, cooked, in [pot])"]
    );
    // asked for, the beans stay
    let p = plan_of(
        &files,
        &SIM,
        &query("soup", &[("onion", "chopped"), ("black bean", "whole")]),
    );
    assert!(p.removed.is_empty(), "{:?}", p.removed);
    assert!(
        makes(&p, "pour", "black bean", "in [pot]"),
        "{:#?}",
        units(&p)
    );
}

/// A soup blended in a jar, in whose recipe the jar full of tomato is also covered and uncovered again:
/// FOON names the uncovered jar by its values, so the node the pour makes is also made by the uncover,
/// from a covered jar that only the cover makes from it.
const COVERED_AND_UNCOVERED: &str = "//
O\ttomato\t1
S\twhole
O\tknife\t1
M\tchop\t<Assumed>
O\ttomato\t1
S\tchopped
//
O\tonion\t1
S\twhole
O\tknife\t1
M\tchop\t<Assumed>
O\tonion\t1
S\tchopped
//
O\tgarlic\t1
S\twhole
O\tknife\t1
M\tchop\t<Assumed>
O\tgarlic\t1
S\tchopped
//
O\tblender jar\t0
S\tempty
O\ttomato\t1
S\tchopped
O\tonion\t1
S\tchopped
O\tgarlic\t1
S\tchopped
M\tpour\t<Assumed>
O\tblender jar\t0
S\tcontains\t{garlic,onion,tomato}
//
O\tblender jar\t0
S\tcontains\t{garlic,onion,tomato}
O\tblender cover\t1
M\tcover\t<Assumed>
O\tblender jar\t0
S\tcontains\t{garlic,onion,tomato}
S\tcovered\t[blender cover]
O\tblender cover\t1
S\ton\t[blender jar]
//
O\tblender jar\t0
S\tcontains\t{garlic,onion,tomato}
S\tcovered\t[blender cover]
O\tblender cover\t1
S\ton\t[blender jar]
M\tuncover\t<Assumed>
O\tblender jar\t0
S\tcontains\t{garlic,onion,tomato}
O\tblender cover\t1
//
O\tblender jar\t0
S\tcontains\t{garlic,onion,tomato}
M\tblend\t<Assumed>
O\ttomato soup\t1\t1
S\tblended
S\tin\t[blender jar]
//
";

#[test]
fn a_node_is_made_the_way_that_starts_from_what_exists_not_by_undoing_a_change_made_from_it() {
    // the uncover needs fewer inputs made than the pour, but the covered jar it needs is made only from
    // the jar full of tomato it would make: chosen, the plan would uncover a jar nothing has covered
    let p = recipe_plan(
        COVERED_AND_UNCOVERED,
        "soup",
        &[("tomato", "whole"), ("onion", "whole"), ("garlic", "whole")],
    );
    let motions: Vec<&str> = p.units.iter().map(|u| u.motion.as_str()).collect();
    assert!(motions.contains(&"pour"), "{:#?}", units(&p));
    assert!(
        !motions.iter().any(|m| *m == "cover" || *m == "uncover"),
        "{:#?}",
        units(&p)
    );
}

#[test]
fn a_tool_that_opens_a_container_is_what_it_is_opened_with() {
    // FOON moves the packet and the scissors, and no food: the packet is cut open, not the scissors
    let packet = "//
O\tpacket\t1
S\tsealed
S\tcontains\t{bacon}
O\tscissors\t1
M\tcut open\t<Assumed>
O\tpacket\t1
S\topened
S\tcontains\t{bacon}
//
O\tpacket\t1
S\topened
S\tcontains\t{bacon}
O\tbacon\t1
S\tin\t[packet]
O\tpan\t0
S\tempty
M\tpick-and-place\t<Assumed>
O\tpan\t0
S\tcontains\t{bacon}
//
O\tpan\t0
S\tcontains\t{bacon}
O\tonion\t1
S\tchopped
M\tfry\t<Assumed>
O\tbacon soup\t1\t1
S\tfried
S\tin\t[pan]
//
";
    let p = recipe_plan(packet, "soup", &[("onion", "chopped"), ("bacon", "whole")]);
    assert_eq!(
        p.steps.first().map(String::as_str),
        Some("Cut open the packet with the scissors."),
        "{:#?}",
        units(&p)
    );
}

#[test]
fn an_egg_is_not_blended_before_it_is_cracked() {
    // the omelette cracks the egg into white and yolk and beats those: an egg asked for as a thick liquid
    // cannot be blended whole first
    let omelette = "//
O\tegg\t1
S\twhole
O\tbowl\t0
S\tempty
M\tcrack\t<Assumed>
O\tegg white\t1
S\tin\t[bowl]
O\tegg yolk\t1
S\tin\t[bowl]
O\tbowl\t0
S\tcontains\t{egg white,egg yolk}
//
O\tbowl\t0
S\tcontains\t{egg white,egg yolk}
O\tegg white\t1
S\tin\t[bowl]
O\tegg yolk\t1
S\tin\t[bowl]
O\twhisk\t1
M\tbeat\t<Assumed>
O\tomelette\t1\t3
S\tbeaten
S\tin\t[bowl]
//
O\tegg\t1
S\twhole
O\tblender\t0
M\tblend\t<Assumed>
O\tegg\t1
S\tliquid
//
";
    let p = recipe_plan(omelette, "omelette", &[("egg", "thick liquid")]);
    assert!(
        p.units.iter().all(|u| u.motion != "blend"),
        "{:#?}",
        units(&p)
    );
    assert_eq!(p.steps.len(), 2, "{:#?}", p.steps);
    assert_eq!(
        outcome(&p, "egg").reason.as_deref(),
        Some("state 'thick liquid' not given: 'crack' makes the egg into egg white and egg yolk first, which the tree takes on")
    );
}

#[test]
fn a_progress_line_follows_the_food_an_ingredient_went_into_to_the_dish() {
    // the flour goes into the batter; the batter is poured into the pan and baked into the muffin. A unit
    // that takes the bowl and gives nothing of it back (a mixer turned on) does not end the line.
    let muffin = "//
O\tflour\t1
S\tin\t[bowl]
O\tbowl\t0
S\tcontains\t{flour}
O\tsugar\t1
S\tgranulated
M\tpour\t<Assumed>
O\tbowl\t0
S\tcontains\t{flour,sugar}
//
O\tbowl\t0
S\tcontains\t{flour,sugar}
O\tmixer\t0
S\toff
M\tturn on\t<Assumed>
O\tmixer\t0
S\ton
//
O\tbowl\t0
S\tcontains\t{flour,sugar}
O\tmixer\t0
S\ton
M\tmix\t<Assumed>
O\tmuffin batter\t1
S\tcontains\t{flour,sugar}
S\tin\t[bowl]
//
O\tmuffin batter\t1
S\tcontains\t{flour,sugar}
S\tin\t[bowl]
O\tmuffin pan\t0
S\tempty
M\tpour\t<Assumed>
O\tmuffin batter\t1
S\tcontains\t{flour,sugar}
S\tin\t[muffin pan]
//
O\tmuffin batter\t1
S\tcontains\t{flour,sugar}
S\tin\t[muffin pan]
O\toven\t0
S\ton
M\tbake\t<Assumed>
O\tmuffin\t1\t3
S\tcontains\t{flour,sugar}
S\tbaked
S\tin\t[muffin pan]
//
";
    let p = recipe_plan(muffin, "cake", &[("flour", "ground"), ("sugar", "ground")]);
    let line = p
        .progress_lines
        .iter()
        .find(|l| l.ingredient == "flour")
        .unwrap();
    assert_eq!(line.motion, ["mix", "pour", "bake"], "{line:#?}");
    // the muffin recipe serves a cake: the dish is named for the cake asked, its batter no muffin's
    assert_eq!(line.end_product, "cake");
    assert!(
        line.state.iter().any(|s| s.physical_state == "in batter")
            && !line
                .state
                .iter()
                .any(|s| s.physical_state.contains("muffin")),
        "{line:#?}"
    );
    assert!(
        p.notes
            .iter()
            .any(|n| n.contains("the dish is called 'cake'")),
        "{:?}",
        p.notes
    );
    let last = line.state.last().unwrap();
    assert_eq!(
        (last.physical_state.as_str(), last.location.as_str()),
        ("in cake", "in muffin pan")
    );
}

#[test]
fn a_state_only_a_motion_the_food_cannot_take_makes_is_not_given() {
    // FOON grinds peppercorns; butter asked "ground" (a coarse word of the recipe data) is not ground
    let recipe = "//
O\tpeppercorn\t1
S\twhole
O\tgrinder\t0
M\tgrind\t<Assumed>
O\tpeppercorn\t1
S\tground
//
O\tbutter\t1
S\tin\t[bowl]
O\tbowl\t0
S\tcontains\t{butter}
O\tsugar\t1
S\tgranulated
M\tmix\t<Assumed>
O\tbatter\t1\t3
S\tcontains\t{butter,sugar}
S\tin\t[bowl]
//
";
    let p = recipe_plan(
        recipe,
        "cake",
        &[("butter", "ground"), ("sugar", "granulated")],
    );
    assert!(
        p.units.iter().all(|u| u.motion != "grind"),
        "{:#?}",
        units(&p)
    );
    let reason = outcome(&p, "butter").reason.clone().unwrap_or_default();
    assert!(reason.contains("butter (fat) is not 'grind'"), "{reason}");
}
