//! Attachment: where a new ingredient branch joins the tree (the unit it is added to).

use super::*;
use crate::planner::tree::add_item;

/// Motions that cannot take more ingredients (a robot cuts one item at a time; what goes into the oven
/// or under the grill is already assembled).
pub(super) const SINGLE_ITEM_WORDS: &[&str] = &[
    "slice",
    "cut",
    "chop",
    "dice",
    "mince",
    "peel",
    "crack",
    "grate",
    "grind",
    "mash",
    "crush",
    "julienne",
    "core",
    "squeeze",
    "wash",
    "rinse",
    "open",
    "turn",
    "preheat",
    "detach",
    "attach",
    "remove",
    "drain",
    "shave",
    "zest",
    "knead",
    "roll",
    "shape",
    "wrap",
    "unwrap",
    "throw",
    "take out",
    "tear",
    "flip",
    "cover",
    "bake",
    "roast",
    "grill",
    "toast",
    "broil",
    "put inside",
    "insert",
    "microwave",
];

pub(super) fn accepts_more(motion: &str) -> bool {
    !SINGLE_ITEM_WORDS.iter().any(|w| motion.contains(w))
}

/// How new ingredients join a dish of each class (first preferred): drinks are poured, salads mixed...
pub(super) fn dish_pattern(class: Option<u32>) -> &'static [&'static str] {
    match class.and_then(dish_class_name) {
        Some("drinks") => &["pour", "blend", "add", "stir", "mix", "shake"],
        Some("salad") => &["mix", "add", "pick-and-place", "pour", "sprinkle", "stir"],
        Some("soup") | Some("sauce") => &["pour", "add", "stir", "mix", "sprinkle"],
        Some("cake") | Some("muffin") | Some("cookie") | Some("bread") | Some("pie")
        | Some("dessert") => &["mix", "pour", "add", "stir", "beat", "sprinkle", "fold"],
        Some("omelette") => &["beat", "mix", "pour", "add", "sprinkle", "stir"],
        Some("rice") | Some("noodle") | Some("pasta") | Some("stir-fry") => {
            &["add", "stir", "pour", "mix", "sprinkle"]
        }
        _ => &["mix", "add", "pour", "stir", "sprinkle"],
    }
}

/// Whether a motion takes more ingredients, and its rank in the dish class's pattern (see
/// `attach_point`).
pub(super) fn motion_fit(class: Option<u32>, motion: &str) -> (bool, usize) {
    let pattern = dish_pattern(class);
    let rank = pattern
        .iter()
        .position(|m| motion.contains(m))
        .unwrap_or(pattern.len());
    (accepts_more(motion), rank)
}

/// Per slot, whether a unit that cooks `food` (`foods::cooks_food`) takes it or what it becomes on the
/// way on.
pub(super) fn cooked_later(tree: &Tree, order: &[TUnitId], food: &str) -> Vec<bool> {
    let mut cooked = vec![false; tree.slots.len()];
    // walked backwards, a unit's outputs are settled before its inputs
    for &v in order.iter().rev() {
        let unit = &tree.units[v];
        let cooks = unit_cooks(tree, v, food);
        for &(s, _) in &unit.inputs {
            cooked[s] |= cooks || unit.outputs.iter().any(|&(x, _)| x != s && cooked[x]);
        }
    }
    cooked
}

/// Whether unit `u` cooks `food`: one of its `cook_words` does (`foods::cooks_food`).
fn unit_cooks(tree: &Tree, u: TUnitId, food: &str) -> bool {
    cook_words(tree, u).any(|m| foods::cooks_food(food, m))
}

/// Unit `u`'s motion, and the cook's word for it where it gives a food a state (`foods::cooks_word`:
/// FOON's "flip and stack" that leaves the slices "toasted" toasts them, and the egg they were dipped in).
pub(super) fn cook_words<'t>(tree: &'t Tree, u: TUnitId) -> impl Iterator<Item = &'t str> {
    let unit = &tree.units[u];
    let renamed = unit.outputs.iter().flat_map(move |x| {
        tree.slots[x.0]
            .node
            .physical_states()
            .filter_map(|s| foods::cooks_word(&unit.motion, s))
    });
    std::iter::once(unit.motion.as_ref()).chain(renamed)
}

/// Whether `food` joining unit `u` is cooked there or later (`cooked`: `cooked_later` for it): what the
/// unit puts things into (the bowl a ladle fills, not the pot it empties, which may go back on the
/// stove), else any of its outputs.
pub(super) fn cooks_what_joins(tree: &Tree, cooked: &[bool], u: TUnitId, food: &str) -> bool {
    let unit = &tree.units[u];
    let contents = |x: SlotId| tree.slots[x].node.contents().count();
    let filled: Vec<SlotId> = unit
        .outputs
        .iter()
        .map(|o| o.0)
        .filter(|&x| {
            let label = &tree.slots[x].node.label;
            let had = unit
                .inputs
                .iter()
                .filter(|i| tree.slots[i.0].node.label == *label)
                .map(|i| contents(i.0))
                .max();
            had.is_some_and(|n| contents(x) > n)
        })
        .collect();
    let cooked_later = |x: &SlotId| cooked[*x];
    // not a vessel the unit empties (the pan the eggs are slid out of, FOON's node of it before it was
    // heated): what joins there goes where the food goes
    let takes_in = |x: &SlotId| !tree.slots[*x].utensil || tree.slots[*x].node.holds_something();
    unit_cooks(tree, u, food)
        || if filled.is_empty() {
            unit.outputs
                .iter()
                .map(|o| o.0)
                .filter(takes_in)
                .any(|x| cooked_later(&x))
        } else {
            filled.iter().any(cooked_later)
        }
}

/// The unit a new ingredient joins: one that can take more ingredients, into an output whose contents
/// reach the goal (`carries`: the tree's `carriers`), by a motion the food can join by (milk poured, not
/// placed), before a unit that cooks it when it must be cooked (`cooked`: `cooked_later`), where
/// ingredients of the same kind go in (salt where the pepper is sprinkled), else with the dish's usual
/// motion, closest to the goal. A food that joins the served dish (`foods::joins_served`) takes the unit
/// closest to the goal that nothing cooks after; where there is none, `top_dish` follows.
#[allow(clippy::too_many_arguments)]
pub(super) fn attach_point(
    ctx: &Context,
    tree: &Tree,
    order: &[TUnitId],
    carries: &[bool],
    cooked: &[bool],
    o: &str,
    c: Category,
) -> Option<TUnitId> {
    let goal_label = tree.slots[tree.goal].node.label.as_str();
    let food = known_as(ctx, o, o);
    // a garnish of a dish that is cooked or heated goes in as late as it can; in a dish nothing heats (a
    // salad, a drink) it joins where the others do
    let cooked_dish = order.iter().any(|&u| heats(tree, u));
    let served = foods::joins_served(food) && cooked_dish;
    // a stir-fry's zucchini and beef go into its pan, not into the sauce mixed apart for it
    let out_of_sauce = cooked_dish && foods::cooks_in_pan(food);
    // closest to the goal first: a unit further from it must do strictly better, so its kin
    // ingredients are worked out only when they could make it
    let mut best: Option<(TUnitId, AttachKey)> = None;
    for &u in order.iter().rev() {
        let unit = &tree.units[u];
        let mut holding = unit
            .outputs
            .iter()
            .filter(|x| tree.slots[x.0].node.holds_something())
            .peekable();
        if holding.peek().is_none() {
            continue;
        }
        let reaches =
            holding.any(|x| carries[x.0]) || unit.outputs.iter().any(|x| x.0 == tree.goal);
        // a unit that adds an ingredient, not one that only moves the dish itself
        let adds = unit.inputs.iter().any(|i| {
            let x = &tree.slots[i.0];
            i.1 && !x.utensil && x.node.label != goal_label
        });
        let fits = foods::joins_by(o, &unit.motion) && !(out_of_sauce && mixes_sauce(tree, u));
        let (safe, cool) = timing(tree, cooked, u, o, food);
        let beats = |kin: bool, pref: usize| {
            let key = (reaches, fits, safe, cool, adds, kin, usize::MAX - pref);
            best.as_ref().is_none_or(|(_, b)| key > *b).then_some(key)
        };
        // not even with kin ingredients and the dish's first motion: its motion is not looked up
        if beats(true, 0).is_none() {
            continue;
        }
        let (more, pref) = motion_fit(ctx.class, &unit.motion);
        if !more || beats(true, pref).is_none() {
            continue;
        }
        if served && reaches && fits && safe {
            // as late as it can: onto the served dish rather than into the hot pot after the cooking
            best = Some((u, (true, true, true, cool, adds, false, usize::MAX - pref)));
            break;
        }
        if let Some(key) = beats(kin_join(ctx, tree, u, o, c), pref) {
            best = Some((u, key));
            // a unit adding ingredients of the same kind with the dish's first motion into the dish: none
            // beats it
            if key == (true, true, true, true, true, true, usize::MAX) {
                break;
            }
        }
    }
    // nothing that takes more reaches the dish: the unit that makes it takes the food, so its
    // progress line ends in the dish
    best.filter(|(_, key)| key.0)
        .map(|b| b.0)
        .or_else(|| tree.producer.get(tree.goal).copied().flatten())
}

/// Whether ingredients of the kind of `o` (asked in category `c`) join unit `u`: a food in the same
/// state category (salt where the pepper is sprinkled), or one similar to it.
fn kin_join(ctx: &Context, tree: &Tree, u: TUnitId, o: &str, c: Category) -> bool {
    tree.units[u].inputs.iter().any(|i| {
        let x = &tree.slots[i.0];
        let n = &x.node;
        !x.utensil
            && n.label != o
            && ((!matches!(c, Category::Whole | Category::Other) && food_category(ctx, n) == c)
                || {
                    let sim = ctx.scorer.pair(o, &n.label);
                    ctx.sim.accepts(sim) && sim < 1.0
                })
    })
}

/// Whether unit `u` mixes a sauce apart, cold (the soy sauce and starch a stir-fry is tossed in).
fn mixes_sauce(tree: &Tree, u: TUnitId) -> bool {
    let makes_sauce = tree.units[u]
        .outputs
        .iter()
        .any(|x| foods::kind(&tree.slots[x.0].node.label) == Some("sauce"));
    makes_sauce && !heats(tree, u)
}

/// How `attach_point` ranks a unit: reaches the goal, the food joins by its motion, it meets the dish's
/// cooking as it should and goes in cool if it must (`timing`), the unit adds an ingredient, kin
/// ingredients join there, the dish's motion rank.
pub(super) type AttachKey = (bool, bool, bool, bool, bool, bool, usize);

/// Whether `food` (asked as `o`) joining unit `u` meets the dish's cooking as it should, and whether it
/// goes in cool as it must: a garnish (`top`) after the last cooking; a food that must be cooked, gives its
/// taste in the heat (`heat`) or is a liquid of the mixture (`mix`) before a cooking; a liquid of the
/// mixture where the dish is mixed before a cooking (milk beaten with the eggs), not into the hot pan.
fn timing(tree: &Tree, cooked: &[bool], u: TUnitId, o: &str, food: &str) -> (bool, bool) {
    let cooked_after = || cooks_what_joins(tree, cooked, u, food);
    if foods::joins_served(food) {
        return (!cooked_after(), true);
    }
    let mixed = foods::joins_mixed(food);
    let wants_heat = mixed || foods::must_cook(o) || foods::joins_before_heat(food);
    let safe = !wants_heat || cooked_after();
    // where nothing cooks it after, the pan's heat is not what decides (the soup's hot pot, not the bowl)
    (safe, !(mixed && safe && heats(tree, u)))
}

/// Whether unit `u` cooks, or what it makes is in a hot pan.
pub(super) fn heats(tree: &Tree, u: TUnitId) -> bool {
    let unit = &tree.units[u];
    cook_words(tree, u).any(foods::cooks)
        || unit
            .outputs
            .iter()
            .any(|x| tree.slots[x.0].node.physical_states().any(|st| st == "hot"))
}

/// How a food that joins the served dish goes onto it, first the one its form joins by: grated cheese
/// sprinkled, ketchup poured, whipped cream spread.
const TOPPING_MOTIONS: &[&str] = &["sprinkle", "pour", "spread"];

/// A food that joins the served dish (`foods::joins_served`: croutons, parsley) where every unit that
/// takes more is cooked after: a unit after the goal puts it onto the dish as it is served (the cheese
/// sprinkled on the baked bread, not baked in its batter). Returns the unit.
pub(super) fn top_dish(tree: &mut Tree, food: &str, o: &str, last: SlotId) -> TUnitId {
    let motion = TOPPING_MOTIONS
        .iter()
        .copied()
        .find(|m| foods::joins_by(food, m))
        .unwrap_or("add");
    let dish = map_contents(&tree.slots[tree.goal].node, &mut |list| add_item(list, o));
    let made = tree.add_slot(Cow::Owned(dish));
    let inputs = vec![(tree.goal, true), (last, true)];
    let u = tree.add_unit(inputs, motion, vec![(made, true)], Origin::Attached);
    tree.goal = made;
    u
}

/// Where a food that greases (`foods::greases`: cooking spray) coats the vessel the dish is cooked in: the
/// first unit that puts food into that vessel (the batter poured into the tray, the eggs into the pan),
/// and the empty vessel it takes.
pub(super) fn greased_vessel(tree: &Tree, order: &[TUnitId]) -> Option<(TUnitId, SlotId)> {
    let vessel = order.iter().find_map(|&u| {
        if !cook_words(tree, u).any(foods::cooks) {
            return None;
        }
        tree.units[u]
            .inputs
            .iter()
            .filter(|i| !tree.slots[i.0].utensil)
            .find_map(|i| tree.slots[i.0].node.container())
    })?;
    let holds = |x: SlotId| tree.slots[x].node.holds_something();
    order.iter().find_map(|&u| {
        let unit = &tree.units[u];
        let empty =
            unit.inputs.iter().map(|i| i.0).find(|&x| {
                tree.slots[x].utensil && tree.slots[x].node.label == vessel && !holds(x)
            })?;
        let filled = unit
            .outputs
            .iter()
            .any(|o| tree.slots[o.0].node.label == vessel && holds(o.0));
        filled.then_some((u, empty))
    })
}

/// Food `o` (its branch ending in `last`) greases the empty vessel `x` before unit `m` fills it: a unit
/// sprays it on, and the vessel `m` takes is the greased one.
pub(super) fn grease(tree: &mut Tree, o: &str, last: SlotId, (m, x): (TUnitId, SlotId)) {
    let vessel = &tree.slots[x].node;
    let mut states = vessel.states.clone();
    states.push(State {
        name: "greased".into(),
        arg: Some(StateArg::Ingredients(vec![o.into()])),
    });
    let greased = ObjectNode::new(vessel.label.clone(), states);
    let greased = tree.add_slot(Cow::Owned(greased));
    tree.add_unit(
        vec![(last, true), (x, false)],
        "spray",
        vec![(greased, false)],
        Origin::Grafted,
    );
    for input in tree.units[m].inputs.iter_mut().filter(|i| i.0 == x) {
        input.0 = greased;
    }
}
