//! Pruning (section III-C): what was not asked for leaves the tree, its names leave the lists of
//! contents.

use super::*;

/// Removes from every slot's lists of contents the items `drops` (slot, item) says go; units touching a
/// changed node are marked renamed.
pub(super) fn drop_contents(tree: &mut Tree, drops: &dyn Fn(SlotId, &str) -> bool) {
    let mut touched = vec![false; tree.slots.len()];
    for (x, (slot, touched)) in tree.slots.iter_mut().zip(touched.iter_mut()).enumerate() {
        if !slot.node.listed().any(|item| drops(x, item)) {
            continue;
        }
        retain_contents(&mut slot.node, &|item| !drops(x, item));
        *touched = true;
    }
    for u in tree.units.iter_mut() {
        if u.alive
            && u.origin == Origin::Reference
            && u.inputs
                .iter()
                .chain(u.outputs.iter())
                .any(|x| touched[x.0])
        {
            u.origin = Origin::Renamed;
        }
    }
}

/// Whether a unit with these inputs handles any ingredient: a non-utensil input or a listed content
/// (`gone` marks the slots pruned).
pub(super) fn handles_any(tree: &Tree, inputs: &[(SlotId, bool)], gone: &[bool]) -> bool {
    inputs.iter().any(|&(x, _)| handles(tree, x, gone))
}

/// Whether a slot is an ingredient or holds one (`gone` marks the slots pruned).
pub(super) fn handles(tree: &Tree, x: SlotId, gone: &[bool]) -> bool {
    let slot = &tree.slots[x];
    !gone[x] && (!slot.utensil || slot.node.holds_something())
}

/// The names a unit's outputs list in their contents that none of its inputs lists or is.
pub(super) fn made_in(
    tree: &Tree,
    inputs: &[(SlotId, bool)],
    outputs: &[(SlotId, bool)],
) -> Vec<String> {
    let known = |item: &str| {
        inputs.iter().any(|&(x, _)| {
            let node = &tree.slots[x].node;
            node.label == item || node.listed().any(|l| l == item)
        })
    };
    let mut made: Vec<String> = outputs
        .iter()
        .flat_map(|&(x, _)| tree.slots[x].node.listed())
        .filter(|item| !known(item))
        .map(str::to_string)
        .collect();
    made.sort_unstable();
    made.dedup();
    made
}

/// The slots of the ingredient the dish is named after (black beans cooked from black beans): those of
/// the goal's label no unit makes, taken only by units before the dish's side. The dish's side (marked in
/// the second vector) is the outputs of the first unit that makes the dish with something in it (the
/// beans cooked with onion), or else makes the goal, and of every unit after it.
pub(super) fn namesake(
    tree: &Tree,
    order: &[TUnitId],
    live: &[SlotId],
) -> (Vec<SlotId>, Vec<bool>) {
    let goal = tree.goal;
    let dish = tree.slots[goal].node.label.as_str();
    let makes_dish = |u: TUnitId| {
        tree.producer[goal] == Some(u)
            || tree.units[u].outputs.iter().any(|&(x, _)| {
                let node = &tree.slots[x].node;
                node.label == dish && node.holds_something()
            })
    };
    let from = order
        .iter()
        .position(|&u| makes_dish(u))
        .unwrap_or(order.len());
    let mut dish_side = vec![false; tree.slots.len()];
    // 1: taken before the dish's side; 2: taken by it
    let mut taken = vec![0u8; tree.slots.len()];
    for (k, &u) in order.iter().enumerate() {
        for &(x, _) in &tree.units[u].inputs {
            taken[x] |= if k < from { 1 } else { 2 };
        }
        if k >= from {
            for &(x, _) in &tree.units[u].outputs {
                dish_side[x] = true;
            }
        }
    }
    // a dish node whose link to the unit making it FOON lost (a brownie cut, not the one baked) is the
    // dish, not an ingredient
    let slots = live
        .iter()
        .copied()
        .filter(|&x| tree.slots[x].node.label == dish && !tree.produced(x) && taken[x] == 1)
        .collect();
    (slots, dish_side)
}

/// The labels pruning removes before any unit goes: those of the tree's starting nodes (not utensils, not
/// made by a unit), and the names only the lists of starting nodes give, unless kept or asked for.
fn starting_labels(
    tree: &Tree,
    live: &[SlotId],
    keep: &BTreeSet<String>,
    requested: &HashSet<&str>,
) -> BTreeSet<String> {
    // what a unit gives out is made, whether or not it is the unit chosen to make it (the broth FOON's
    // ladle leaves in the bowl beside the ramen is not a starting ingredient)
    let mut made = vec![false; tree.slots.len()];
    for (_, u) in tree.alive_units() {
        for &(x, _) in &u.outputs {
            made[x] = true;
        }
    }
    let mut starting: Vec<&str> = live
        .iter()
        .filter(|&&x| !made[x] && !tree.slots[x].utensil)
        .map(|&x| tree.slots[x].node.label.as_str())
        .collect();
    // names that only the lists of starting nodes give are ingredients too (FOON's "contain {butter}"
    // makes no node of the butter a skillet holds, and the french toast made in it lists butter): not
    // asked for, they go. A name a unit's output lists first is made there (the egg white a crack
    // leaves in the bowl).
    let named = |item: &str| live.iter().any(|&x| tree.slots[x].node.label == item);
    for &x in live.iter().filter(|&&x| !made[x]) {
        let unnamed =
            |item: &&str| !requested.contains(item) && !keep.contains(*item) && !named(item);
        starting.extend(tree.slots[x].node.listed().filter(unnamed));
    }
    starting.sort_unstable();
    starting.dedup();
    starting
        .into_iter()
        .filter(|&l| !keep.contains(l))
        .map(str::to_string)
        .collect()
}

/// The outputs of a removed unit: one its inputs have (the same node, else the same label) stands for
/// that input from now on (`alias`); any other is gone, and its label (unless a utensil's) is returned.
fn outputs_of_removed(
    tree: &Tree,
    inputs: &[(SlotId, bool)],
    outputs: &[(SlotId, bool)],
    alias: &mut HashMap<SlotId, SlotId>,
    gone: &mut [bool],
) -> Vec<String> {
    let mut labels = Vec::new();
    for &(x, _) in outputs {
        let node = &tree.slots[x].node;
        let same = inputs
            .iter()
            .find(|i| tree.slots[i.0].node == *node)
            .or_else(|| {
                inputs
                    .iter()
                    .find(|i| tree.slots[i.0].node.label == node.label)
            });
        match same {
            Some(&(i, _)) if i != x => {
                alias.insert(x, i);
            }
            Some(_) => {}
            None => {
                gone[x] = true;
                if !tree.slots[x].utensil {
                    labels.push(node.label.to_string());
                }
            }
        }
    }
    labels
}

/// Per unit, before pruning: whether it handled an ingredient, and whether something it moved did.
fn handled_before(tree: &Tree, order: &[TUnitId]) -> Vec<(bool, bool)> {
    let none_gone = vec![false; tree.slots.len()];
    let mut before = vec![(false, false); tree.units.len()];
    for &u in order {
        let inputs = &tree.units[u].inputs;
        before[u] = (
            handles_any(tree, inputs, &none_gone),
            inputs
                .iter()
                .any(|&(x, m)| m && handles(tree, x, &none_gone)),
        );
    }
    before
}

/// The inputs and outputs of unit `u` as they are now: slots that stand for others (`alias`) replaced,
/// slots `gone` left out.
fn uses_now(tree: &Tree, u: TUnitId, alias: &HashMap<SlotId, SlotId>, gone: &[bool]) -> Uses {
    let resolve = |mut s: SlotId| {
        for _ in 0..10_000 {
            match alias.get(&s) {
                Some(&t) => s = t,
                None => break,
            }
        }
        s
    };
    let unit = &tree.units[u];
    let inputs = unit.inputs.iter().map(|&(x, m)| (resolve(x), m));
    let outputs = unit.outputs.iter().copied();
    (
        inputs.filter(|i| !gone[i.0]).collect(),
        outputs.filter(|o| !gone[o.0]).collect(),
    )
}

/// A unit's inputs and outputs.
type Uses = (Vec<(SlotId, bool)>, Vec<(SlotId, bool)>);

/// Whether a unit, with its uses as they are after pruning (`inputs`, `outputs`) and what it handled
/// before (`handled_before`), is left doing nothing.
fn does_nothing(
    tree: &Tree,
    (had_food, moved_food): (bool, bool),
    inputs: &[(SlotId, bool)],
    outputs: &[(SlotId, bool)],
    gone: &[bool],
) -> bool {
    let lost_all = had_food && !handles_any(tree, inputs, gone);
    // nothing new comes out: every output is one of the inputs as they are now
    let no_op = outputs.iter().all(|o| {
        inputs
            .iter()
            .any(|i| i.0 == o.0 || tree.slots[i.0].node == tree.slots[o.0].node)
    });
    // a unit whose moved things all lost their food (an empty bowl poured into the pot, the egg
    // cracked into the broth) acts on nothing, and gives back only things of the names it took
    let label = |x: SlotId| tree.slots[x].node.label.as_str();
    let moves_nothing = moved_food
        && !inputs.iter().any(|&(x, m)| m && handles(tree, x, gone))
        && outputs
            .iter()
            .all(|o| inputs.iter().any(|i| label(i.0) == label(o.0)));
    lost_all || no_op || moves_nothing || outputs.is_empty()
}

/// A food made on the way under the name of an ingredient that goes, but holding others that stay (the
/// "rice" FOON cooks with the garlic and oil in it, where noodles are asked), is what those go on in: it
/// stays, as a mixture (`name_for_query` names it for what it holds).
fn keep_mixtures(tree: &mut Tree, live: &[SlotId], gone: &mut [bool]) {
    for &x in live {
        let slot = &tree.slots[x];
        if gone[x] && !slot.utensil && tree.produced(x) && slot.node.holds_something() {
            gone[x] = false;
            let node = &tree.slots[x].node;
            let label = format!("{} mixture", node.label);
            tree.slots[x].node = Cow::Owned(ObjectNode::new(label, node.states.clone()));
        }
    }
}

/// Removes every starting ingredient not asked for (`keep`: planned so far; `requested`: the query's
/// names, some still to be brought in), with the units that only served it; containers that held it
/// pass on unchanged, and it leaves every `contains {…}` list. Returns the removed labels.
/// A dish named after one of its ingredients (black beans cooked from black beans) keeps its name: from
/// the unit that makes it on, the name means the dish, and nodes and lists there stay.
pub(super) fn prune(
    tree: &mut Tree,
    keep: &BTreeSet<String>,
    requested: &HashSet<&str>,
) -> Vec<String> {
    let order = tree.order();
    let live: Vec<SlotId> = tree.live_slots().collect();
    let mut pruned = starting_labels(tree, &live, keep, requested);
    let goal = tree.goal;
    let dish = tree.slots[goal].node.label.clone();
    let (namesake_slots, dish_side) = if pruned.remove(dish.as_str()) {
        namesake(tree, &order, &live)
    } else {
        Default::default()
    };
    let namesake = !namesake_slots.is_empty();
    if pruned.is_empty() && !namesake {
        return Vec::new();
    }
    let going: HashSet<&str> = pruned.iter().map(String::as_str).collect();
    let before = handled_before(tree, &order);
    // per slot, whether it is pruned
    let mut gone = vec![false; tree.slots.len()];
    // the dish's own name stays in the lists of its side, where it means the dish
    drop_contents(tree, &|x, item| {
        going.contains(item) || (namesake && item == dish && !dish_side[x])
    });
    for &x in &live {
        gone[x] = going.contains(tree.slots[x].node.label.as_str());
    }
    keep_mixtures(tree, &live, &mut gone);
    for &x in &namesake_slots {
        gone[x] = true;
    }
    // labels that go with the units removed below, beyond those already dropped from the contents
    let mut with_units: BTreeSet<String> = BTreeSet::new();
    let mut alias: HashMap<SlotId, SlotId> = HashMap::default();
    for &u in &order {
        let (mut inputs, outputs) = uses_now(tree, u, &alias, &gone);
        let makes_goal = outputs.iter().any(|o| o.0 == goal);
        if !makes_goal && does_nothing(tree, before[u], &inputs, &outputs, &gone) {
            tree.units[u].alive = false;
            let gone_with = outputs_of_removed(tree, &inputs, &outputs, &mut alias, &mut gone);
            let unlisted = |l: &String| !keep.contains(l.as_str()) && !going.contains(l.as_str());
            with_units.extend(gone_with.into_iter().filter(unlisted));
            // what only it put into a container (the egg white and yolk a crack leaves in the pot) goes
            // with it, from the units after it as well
            let made_here = made_in(tree, &inputs, &outputs);
            let stays = |l: &String| {
                keep.contains(l.as_str()) || requested.contains(l.as_str()) || *l == dish
            };
            for item in made_here.into_iter().filter(|l| !stays(l)) {
                for &x in &live {
                    gone[x] |= tree.slots[x].node.label == item;
                }
                with_units.insert(item);
            }
            continue;
        }
        dedup_slots(&mut inputs);
        let unit = &mut tree.units[u];
        unit.inputs = inputs;
        unit.outputs = outputs;
    }
    // labels made only by removed units leave the lists of contents as well
    with_units.retain(|l| {
        !tree
            .live_slots()
            .any(|x| !gone[x] && tree.slots[x].node.label == *l)
    });
    if !with_units.is_empty() {
        drop_contents(tree, &|_, item| with_units.contains(item));
        pruned.extend(with_units);
    }
    if namesake {
        pruned.insert(dish.to_string());
    }
    pruned.into_iter().collect()
}
