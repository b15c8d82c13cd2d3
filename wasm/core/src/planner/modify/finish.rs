//! What a cook does with the kept ingredients before they are used: whole produce prepared, trimmings
//! first, states fitted to the food's form, the dish cooked when nothing cooks it.

use super::*;

/// Produce still whole (asked "peeled", "washed") brought on to the state a cook gives it
/// (`foods::prepared_state`: a cucumber chopped, an egg cracked) by FOON's motion for that state.
/// Returns the slot the branch now ends in.
pub(super) fn prepare_whole<'kb>(
    ctx: &Context<'kb>,
    tree: &mut Tree<'kb>,
    eq: &str,
    o: &str,
    last: SlotId,
    how: &mut String,
) -> SlotId {
    let food = known_as(ctx, o, eq);
    let Some(p) = foods::prepared_state(food) else {
        return last;
    };
    let node = &tree.slots[last].node;
    let whole = node.physical_states().all(|st| {
        st != p
            && matches!(
                category(st),
                Category::Whole | Category::Trimmed | Category::Other
            )
    });
    let motion = ctx
        .index
        .motion_for(p)
        .filter(|m| cannot_take(ctx, o, eq, m).is_none());
    let (true, Some(motion)) = (whole, motion) else {
        return last;
    };
    let made = ObjectNode::new(eq, vec![State::plain(p)]);
    let _ = write!(how, ", then '{motion}' to make it '{p}', as a cook would");
    add_state_unit(ctx, tree, last, made, &motion)
}

/// The asked food `o` when the tree takes it to the dish in the piece it is bought as (a block of cheddar
/// poured into the omelette, asked "creamy"; a chicken baked whole for a salad): brought to the state a
/// cook gives it (`foods::prepared_state`: grated, chopped) as `restate` brings a food to an asked
/// state. Foods prepared before anything else (an egg cracked) are `prepare_first`'s. Returns the reason.
pub(super) fn prepare_kept<'kb>(
    ctx: &Context<'kb>,
    tree: &mut Tree<'kb>,
    o: &str,
    eq: &str,
) -> Option<String> {
    let food = known_as(ctx, o, eq);
    let p = foods::prepared_state(food).filter(|_| foods::prepared_first(food).is_none())?;
    let slots = tree.slots_with_label(o);
    let in_piece = slots.iter().all(|&x| {
        tree.slots[x].node.physical_states().all(|st| {
            matches!(
                category(st),
                Category::Whole | Category::Trimmed | Category::Cooked | Category::Other
            )
        })
    });
    // peppercorns ground into the soup are not kept whole
    if slots.is_empty() || !in_piece || shaped_as_it_joins(tree, &slots).is_some() {
        return None;
    }
    let how = restate(ctx, tree, eq, o, p, &slots).ok()?;
    Some(format!("kept whole by the tree: {how}, as a cook would"))
}

/// The preparation a food gets before anything else (`foods::prepared_first`: an egg cracked) where the
/// tree starts it past that point without it (a substitute's "egg white and yolk" in a bowl, an egg
/// bought beaten): a unit from the whole food comes first. Returns the reason.
pub(super) fn prepare_first<'kb>(
    ctx: &Context<'kb>,
    tree: &mut Tree<'kb>,
    o: &str,
    eq: &str,
) -> Option<String> {
    let food = known_as(ctx, o, eq);
    let p = foods::prepared_first(food)?;
    let motion = ctx
        .index
        .motion_for(p)
        .filter(|m| cannot_take(ctx, o, eq, m).is_none())?;
    let past: Vec<SlotId> = tree
        .slots_with_label(o)
        .into_iter()
        .filter(|&x| {
            !tree.produced(x)
                && tree.slots[x]
                    .node
                    .physical_states()
                    .all(|st| st != p && category(st) != Category::Whole)
        })
        .collect();
    for &x in &past {
        let whole = tree.add_slot(Cow::Owned(ObjectNode::new(o, vec![State::plain("whole")])));
        let node = &tree.slots[x].node;
        let mut states = node.states.clone();
        states.insert(0, State::plain(p));
        tree.slots[x].node = Cow::Owned(ObjectNode::new(node.label.clone(), states));
        add_motion_unit(ctx, tree, whole, &motion, x);
    }
    (!past.is_empty()).then(|| format!("'{motion}' first, as a cook would: the tree starts it {p}"))
}

/// What a cook takes off the asked food before using it (`foods::trims`: an onion's skin before it is
/// cut, a cherry's stone before it joins anything), where the tree has it still on: a unit doing so
/// (FOON's motion for the state, else the trim's own verb) comes at that point of the food's own chain
/// (after it is moved and washed; a peach's stone after it is halved). Returns the states given.
pub(super) fn trim_first<'kb>(
    ctx: &Context<'kb>,
    tree: &mut Tree<'kb>,
    o: &str,
    eq: &str,
) -> Vec<&'static str> {
    let food = known_as(ctx, o, eq);
    let mut given = Vec::new();
    for trim in foods::trims(food) {
        // FOON's motion for the very state ("peel"), else the trim's own verb (not another trim's)
        let motion = ctx
            .index
            .motion_making(trim.state)
            .unwrap_or(trim.verb)
            .to_string();
        if cannot_take(ctx, o, eq, &motion).is_some() {
            continue;
        }
        let starts: Vec<SlotId> = tree
            .slots_with_label(o)
            .into_iter()
            .filter(|&x| !tree.produced(x))
            .collect();
        for x in starts {
            // with the trims given so far, so that a chain shared by two starts is trimmed once
            let order = tree.order();
            let Some((at, u)) = trim_point(tree, &order, o, x, trim) else {
                continue;
            };
            let whole = |st: &str| category(st) == Category::Whole;
            let trimmed = with_state(&tree.slots[at].node, whole, trim.state);
            let made = add_state_unit_before(ctx, tree, (at, u), trimmed, &motion);
            // what it becomes no longer has what was taken off ("halved, unpeeled"), and is
            // trimmed while it is still whole (the pitted cherries poured into the blender cup)
            let order = tree.order();
            for (y, _) in own_chain(tree, &order, o, made).into_iter().skip(1) {
                let n = &tree.slots[y].node;
                let node = if food_states(n).into_iter().all(whole) {
                    with_state(n, |st| whole(st) || st == trim.undone, trim.state)
                } else {
                    let kept = n.states.iter().filter(|st| st.name != trim.undone).cloned();
                    ObjectNode::new(n.label.clone(), kept.collect())
                };
                tree.slots[y].node = Cow::Owned(node);
            }
            if !given.contains(&trim.state) {
                given.push(trim.state);
            }
        }
    }
    given
}

/// The slots of food `o` from `x` on while it stays itself (moved, washed, cut), each with the unit
/// taking it next.
pub(super) fn own_chain(
    tree: &Tree,
    order: &[TUnitId],
    o: &str,
    x: SlotId,
) -> Vec<(SlotId, TUnitId)> {
    let mut chain = Vec::new();
    let mut at = Some(x);
    while let Some(x) = at.filter(|x| chain.iter().all(|&(y, _)| y != *x)) {
        let Some(u) = tree.consumers(x, order).next() else {
            break;
        };
        chain.push((x, u));
        at = tree.units[u]
            .outputs
            .iter()
            .map(|o| o.0)
            .find(|&y| tree.slots[y].node.label == o);
    }
    chain
}

/// Where on `o`'s own chain from `x` the trim comes: before its first cut (a peel, a hull), once it is
/// halved (a stone), else before the unit it leaves the chain at (it joins a batter, a blender); None when
/// the chain has it done already, or a peel finds it cut or joined first, or it was bought preserved.
pub(super) fn trim_point(
    tree: &Tree,
    order: &[TUnitId],
    o: &str,
    x: SlotId,
    trim: &foods::Trim,
) -> Option<(SlotId, TUnitId)> {
    let chain = own_chain(tree, order, o, x);
    let done = |&(y, _): &(SlotId, TUnitId)| {
        tree.slots[y]
            .node
            .physical_states()
            .any(|st| st == trim.state)
    };
    // frozen or dried fruit was bought with its stone and hull taken out, cut fruit too (an avocado
    // bought chopped has no stone left)
    let bought_ready = tree.slots[x].node.physical_states().any(|st| {
        matches!(
            category(st),
            Category::Preserved
                | Category::Cut
                | Category::FinelyCut
                | Category::Ground
                | Category::Liquid
                | Category::Mixed
        )
    });
    if bought_ready || chain.iter().any(done) {
        return None;
    }
    let whole = |y: SlotId| {
        tree.slots[y]
            .node
            .physical_states()
            .all(|st| matches!(category(st), Category::Whole | Category::Other))
    };
    let first_cut = || {
        chain
            .iter()
            .copied()
            .find(|&(_, u)| foods::breaks_up(&tree.units[u].motion))
    };
    if trim.before_cut {
        return first_cut().filter(|&(y, _)| whole(y));
    }
    // a stone comes out once the fruit is halved, else before it is cut at all (a cherry pitted
    // whole, not in slices); a hull before the first cut...
    let halved = chain.iter().copied().find(|&(y, _)| {
        tree.slots[y]
            .node
            .physical_states()
            .any(|st| st == "halved")
    });
    // ... and before it meets other foods (cherries poured into the blender cup beside the banana)
    let cut_or_met = || {
        chain
            .iter()
            .copied()
            .find(|&(_, u)| foods::breaks_up(&tree.units[u].motion) || meets_others(tree, u, o))
    };
    if let Some(point) = halved.or_else(cut_or_met) {
        return Some(point);
    }
    let &(y, u) = chain.last()?;
    let joins = !tree.units[u]
        .outputs
        .iter()
        .any(|o2| tree.slots[o2.0].node.label == o);
    joins.then_some((y, u))
}

/// Whether unit `u` puts `o` into a vessel with another food.
fn meets_others(tree: &Tree, u: TUnitId, o: &str) -> bool {
    tree.units[u].outputs.iter().any(|&(x, _)| {
        let vessel = &tree.slots[x].node;
        vessel.contents().any(|c| c == o) && vessel.contents().any(|c| c != o)
    })
}

/// The states of the asked food `o` made to fit its form (`foods::Form`): a state it is never in, taken
/// over from a substitute (tahini "ground, powder" like the sesame it replaced), goes; a food left with no
/// state as it starts is shown in its form's ("liquid" oil), else as it was asked (`as_bought`), never blank.
pub(super) fn fit_states_to_form(ctx: &Context, tree: &mut Tree, o: &str, asked: &str) {
    let food = known_as(ctx, o, o);
    let form = foods::form_of(food);
    let never_in = |w: &str| foods::never_in(food, w);
    let misfit = |st: &State| st.arg.is_none() && never_in(&st.name);
    let when_none = form
        .and_then(|f| f.state_when_none.as_deref())
        .or_else(|| as_bought(asked).filter(|s| !never_in(s)));
    for x in tree.slots_with_label(o) {
        let starts = !tree.produced(x);
        let node = &tree.slots[x].node;
        let mut states: Vec<State> = node
            .states
            .iter()
            .filter(|st| !misfit(st))
            .cloned()
            .collect();
        let bare = !states.iter().any(|st| st.arg.is_none());
        let shown = when_none.filter(|_| starts && bare);
        if states.len() == node.states.len() && shown.is_none() {
            continue;
        }
        states.extend(shown.map(State::plain));
        tree.slots[x].node = Cow::Owned(ObjectNode::new(node.label.clone(), states));
    }
}

/// The asked state as a food bought so is shown (chips "pieces", "crushed"; a liquid's coarse words,
/// "juice" or "thick liquid", as "liquid"); none for a state a cook makes (mixed, cooked) or one the
/// state taxonomy does not know.
fn as_bought(asked: &str) -> Option<&str> {
    match category(asked) {
        Category::Liquid => Some(Category::Liquid.name()),
        Category::Mixed | Category::Cooked | Category::Other => None,
        _ => Some(asked).filter(|s| !s.is_empty()),
    }
}

/// A fruit or vegetable joining a drink that blends nothing (`foods::state_in_drink`): a unit blends it
/// first, so the banana or mango is in the drink, not in pieces at the bottom of the glass. A drink
/// with a blender takes it there. Returns the slot the branch now ends in.
pub(super) fn blend_for_drink<'kb>(
    ctx: &Context<'kb>,
    tree: &mut Tree<'kb>,
    (o, eq): (&str, &str),
    last: SlotId,
    how: &mut String,
) -> SlotId {
    let drink = ctx.class.and_then(dish_class_name) == Some("drinks");
    let Some(state) = foods::state_in_drink(known_as(ctx, o, eq)).filter(|_| drink) else {
        return last;
    };
    // the drink's own blender, not one blending another ingredient for it
    let blender = tree
        .alive_units()
        .any(|(_, u)| u.motion.contains("blend") && u.origin != Origin::Grafted);
    let poured = tree.slots[last]
        .node
        .physical_states()
        .any(|st| matches!(category(st), Category::Liquid | Category::Mixed));
    if blender || poured {
        return last;
    }
    let (made, motion) = bring_to(ctx, tree, (o, state, "blend"), last);
    let _ = write!(how, ", then '{motion}' to make it '{state}' for the drink");
    made
}

/// A unit bringing the branch of `o` that ends at `last` to `state` by the motion FOON's recipes use for
/// it (`fallback` where they have none). Returns the slot it makes and the motion.
fn bring_to<'kb>(
    ctx: &Context<'kb>,
    tree: &mut Tree<'kb>,
    (o, state, fallback): (&str, &str, &str),
    last: SlotId,
) -> (SlotId, String) {
    let motion = ctx
        .index
        .motion_for(state)
        .unwrap_or_else(|| fallback.into());
    let made = ObjectNode::new(o, vec![State::plain(state)]);
    (add_state_unit(ctx, tree, last, made, &motion), motion)
}

/// The dish itself cooked last when what is in it must be cooked (the egg of fresh egg noodles, the flour
/// of a batter) and nothing FOON's recipes do on the way cooks it: the reference recipe ends at the raw dish, and the query asks for one to eat.
/// The motion is the one FOON's recipes use to cook foods of its kind.
pub(super) fn cook_dish<'kb>(ctx: &Context<'kb>, tree: &mut Tree<'kb>, notes: &mut Vec<String>) {
    let node = &tree.slots[tree.goal].node;
    let label = node.label.clone();
    // a soup left "partly cooked" or "hot" by the pot it was mixed in is not done
    let raw = !node.physical_states().any(done_cooking);
    // what is in it must be cooked: flour, or an egg that was not cooked before it joined (each judged
    // as the food its asked state says it is: fish asked as sauce is fish sauce)
    let must_cook = node
        .contents()
        .any(|c| match foods::cooking(known_as(ctx, c, c)) {
            foods::Cooking::InDish => true,
            foods::Cooking::Alone => !cooked_somewhere(tree, c),
            foods::Cooking::No => false,
        });
    if !raw || !must_cook || body_cooked(tree) {
        return;
    }
    let motion = state_motion(ctx, &label, &label, "cooked").unwrap_or_else(|_| "cook".into());
    let made = ObjectNode::new(label.clone(), vec![State::plain("cooked")]);
    tree.goal = add_state_unit(ctx, tree, tree.goal, made, &motion);
    notes.push(format!(
        "'{label}' is cooked last ('{motion}'): the reference task tree makes it raw"
    ));
}

/// A dish left "partly cooked" or "hot" in its pot by the unit that mixed it (flour whisked into the hot
/// soup), that no unit after cooks, is cooked there before it leaves the pot (FOON often just calls the
/// served bowl "cooked"): a unit to "cooked" after its last node in that pot, and the nodes after it say so.
pub(super) fn finish_in_pot<'kb>(
    ctx: &Context<'kb>,
    tree: &mut Tree<'kb>,
    notes: &mut Vec<String>,
) {
    let dish = tree.slots[tree.goal].node.label.clone();
    let order = tree.order();
    let underdone = |x: SlotId| {
        let node = &tree.slots[x].node;
        node.physical_states()
            .any(|st| category(st) == Category::Cooked)
            && !node.physical_states().any(done_cooking)
    };
    let Some(first) = order
        .iter()
        .flat_map(|&u| tree.units[u].outputs.iter().map(|o| o.0))
        .find(|&x| tree.slots[x].node.label == dish && underdone(x))
    else {
        return;
    };
    let chain = own_chain(tree, &order, &dish, first);
    let pot = tree.slots[first].node.container();
    // cooked on the way, or done in the pot by its heat (the omelette folded "cooked" in the pan)
    let done_in_pot = tree.slots_with_label(&dish).into_iter().any(|x| {
        let node = &tree.slots[x].node;
        node.container() == pot && node.physical_states().any(done_cooking)
    });
    if done_in_pot
        || chain
            .iter()
            .any(|&(_, u)| cook_words(tree, u).any(foods::cooks))
    {
        return;
    }
    let Some(&(at, _)) = chain
        .iter()
        .take_while(|&&(x, _)| tree.slots[x].node.container() == pot)
        .last()
    else {
        return;
    };
    let motion = cooking_motion(ctx, (&dish, &dish), "cook");
    let made = add_state_unit(ctx, tree, at, cooked(&tree.slots[at].node), &motion);
    // the units that took the dish from `at` take it cooked (not the new unit, the last one)
    let new_unit = tree.units.len() - 1;
    for unit in tree.units[..new_unit].iter_mut().filter(|u| u.alive) {
        for input in unit.inputs.iter_mut().filter(|i| i.0 == at) {
            input.0 = made;
        }
    }
    let order = tree.order();
    let later: Vec<SlotId> = own_chain(tree, &order, &dish, made)
        .into_iter()
        .map(|(x, _)| x)
        .skip(1)
        .chain(std::iter::once(tree.goal))
        .collect();
    for x in later {
        tree.slots[x].node = Cow::Owned(cooked(&tree.slots[x].node));
    }
    notes.push(format!(
        "'{dish}' is cooked ('{motion}') before it leaves the pot: the reference task tree leaves it \
         partly cooked there"
    ));
}

/// FOON's usual motion to "cooked" for `o` (`eq` in FOON) when it cooks, else `fallback`: a knowledge base
/// whose only unit to "cooked" pours does not make pouring a way to cook.
fn cooking_motion(ctx: &Context, (o, eq): (&str, &str), fallback: &str) -> String {
    state_motion(ctx, o, eq, "cooked")
        .ok()
        .filter(|m| foods::cooks(m))
        .unwrap_or_else(|| fallback.into())
}

/// `node` cooked through: its cooked states ("partly cooked", "hot") give way to "cooked".
fn cooked(node: &ObjectNode) -> ObjectNode {
    with_state(node, |st| category(st) == Category::Cooked, "cooked")
}

/// A food that must be cooked on its own (a potato, a pumpkin) and that its chain mashes raw is cooked
/// first: a raw potato is not mashed.
pub(super) fn cook_before_mash<'kb>(
    ctx: &Context<'kb>,
    tree: &mut Tree<'kb>,
    o: &str,
    eq: &str,
) -> Option<String> {
    if foods::cooking(known_as(ctx, o, eq)) != foods::Cooking::Alone {
        return None;
    }
    let order = tree.order();
    let raw = |x: SlotId| !tree.slots[x].node.physical_states().any(done_cooking);
    let start = tree
        .slots_with_label(o)
        .into_iter()
        .find(|&x| !tree.produced(x))?;
    let (at, u) = own_chain(tree, &order, o, start)
        .into_iter()
        .find(|&(x, u)| {
            raw(x) && foods::motion_words(&tree.units[u].motion).any(|w| w == "mash")
        })?;
    let motion = cooking_motion(ctx, (o, eq), "boil");
    add_state_unit_before(ctx, tree, (at, u), cooked(&tree.slots[at].node), &motion);
    Some(format!("'{motion}' before it is mashed, as a cook would"))
}

/// Whether some node of `food` in the tree is cooked (the chicken baked before it joined the salad).
pub(super) fn cooked_somewhere(tree: &Tree, food: &str) -> bool {
    tree.slots_with_label(food).into_iter().any(|x| {
        tree.slots[x]
            .node
            .physical_states()
            .any(|st| category(st) == Category::Cooked)
    })
}

/// Whether a unit the tree kept from FOON cooks anything: the dish is then cooked on the way (ramen's
/// broth simmered, pancakes fried), whereas the units modification added cook an ingredient alone (noodles
/// boiled before they join a raw dough).
pub(super) fn body_cooked(tree: &Tree) -> bool {
    tree.alive_units()
        .any(|(v, u)| u.origin != Origin::Grafted && cook_words(tree, v).any(foods::cooks))
}

/// A food that must be cooked on its own (`foods::Cooking::Alone`) and is still raw at `last`, cooked
/// before it joins a dish that does not cook it, or that it must not join raw (`why` says which).
/// Returns the slot the branch now ends in.
pub(super) fn cook_alone<'kb>(
    ctx: &Context<'kb>,
    tree: &mut Tree<'kb>,
    (o, why): (&str, &str),
    last: SlotId,
    how: &mut String,
) -> SlotId {
    let raw = !tree.slots[last]
        .node
        .physical_states()
        .any(|st| category(st) == Category::Cooked);
    if !raw || foods::cooking(known_as(ctx, o, o)) != foods::Cooking::Alone {
        return last;
    }
    let (made, motion) = bring_to(ctx, tree, (o, "cooked", "cook"), last);
    let _ = write!(how, ", '{motion}' to make it cooked ({why})");
    made
}
