//! Branches: a copy of an ingredient's branch (case 2, when the original stays) and case 4 from the
//! universal FOON (the equivalent's branch, renamed, brought to the state and attached).

use super::*;

/// Case 2 with the equivalent also requested: copies the branch that prepares `eq` for `o` and feeds the
/// copy into the unit where `eq` joins the dish. Returns the copy's last node.
pub(super) fn copy_branch(tree: &mut Tree, eq: &str, o: &str) -> Option<SlotId> {
    let order = tree.order();
    // a unit gives back only `eq`, taking it with nothing made in the tree (the water it is washed in)
    let is_private = |u: TUnitId| {
        let unit = &tree.units[u];
        let mut ing_in = unit.inputs.iter().filter(|i| !tree.slots[i.0].utensil);
        let ing_out_ok = unit
            .outputs
            .iter()
            .map(|o| &tree.slots[o.0])
            .filter(|x| !x.utensil)
            .all(|x| x.node.label == eq);
        let takes_eq = ing_in.clone().any(|i| tree.slots[i.0].node.label == eq);
        takes_eq
            && ing_out_ok
            && ing_in.all(|i| tree.slots[i.0].node.label == eq || !tree.produced(i.0))
    };
    let branch: Vec<TUnitId> = order.iter().copied().filter(|&u| is_private(u)).collect();
    let entry = order.iter().copied().find(|&u| {
        !branch.contains(&u)
            && tree.units[u]
                .inputs
                .iter()
                .any(|i| tree.slots[i.0].node.label == eq)
    })?;
    let x = tree.units[entry]
        .inputs
        .iter()
        .map(|i| i.0)
        .find(|&i| tree.slots[i].node.label == eq)?;
    let produced_in_branch: HashSet<SlotId> = branch
        .iter()
        .flat_map(|&u| tree.units[u].outputs.iter().map(|o| o.0))
        .collect();
    let mut copy_of: HashMap<SlotId, SlotId> = HashMap::default();
    let copy = |tree: &mut Tree, s: SlotId, copy_of: &mut HashMap<SlotId, SlotId>| -> SlotId {
        if let Some(&c) = copy_of.get(&s) {
            return c;
        }
        let node = &tree.slots[s].node;
        if node.label != eq && !produced_in_branch.contains(&s) && !node.contents().any(|i| i == eq)
        {
            return s;
        }
        let mut renamed = map_contents(node, &mut |list| rename_item(list, eq, o));
        if renamed.label == eq {
            renamed.label = o.into();
        }
        let c = tree.add_slot(Cow::Owned(renamed));
        copy_of.insert(s, c);
        c
    };
    for &u in &branch {
        let unit = tree.units[u].clone();
        let inputs = unit
            .inputs
            .iter()
            .map(|&(s, m)| (copy(tree, s, &mut copy_of), m))
            .collect();
        let outputs = unit
            .outputs
            .iter()
            .map(|&(s, m)| (copy(tree, s, &mut copy_of), m))
            .collect();
        tree.add_unit(inputs, &unit.motion, outputs, Origin::Copied);
    }
    let new_x = copy(tree, x, &mut copy_of);
    tree.units[entry].inputs.push((new_x, true));
    let carries = tree.carriers(&order);
    tree.add_contents_downstream(entry, o, &order, &carries);
    tree.units[entry].origin = Origin::Attached;
    Some(new_x)
}

/// Whether a branch retrieved for `eq` handles `o` only as recipes handle foods of its form: every
/// unit on `eq` moves it or brings it into states the transition model has seen for that form.
pub(super) fn branch_fits(ctx: &Context, o: &str, eq: &str, branch: &Retrieved) -> bool {
    let model = &ctx.index.transitions;
    let food = known_as(ctx, o, eq);
    if eq == o || !model.judges(food) {
        return true;
    }
    branch.units.iter().all(|&u| {
        let unit = &ctx.kb.units[u];
        let takes_eq = unit.input_nodes().any(|n| ctx.kb.nodes[n].label == eq);
        let outs = unit.outputs.iter().map(|x| &ctx.kb.nodes[x.node]);
        !takes_eq
            || outs.filter(|n| n.label == eq).all(|n| {
                let gained: Vec<&str> = food_states(n)
                    .into_iter()
                    .filter(|st| {
                        !unit.input_nodes().any(|i| {
                            ctx.kb.nodes[i].label == eq
                                && ctx.kb.nodes[i].physical_states().any(|p| p == *st)
                        })
                    })
                    .collect();
                if gained.is_empty() {
                    return model.makes(food, &unit.motion, "") != Verdict::Unseen;
                }
                gained
                    .iter()
                    .all(|st| model.makes(food, &unit.motion, st) != Verdict::Unseen)
            })
    })
}

/// Whether a unit handles `eq` alone (with utensils): a branch with a unit that mixes other ingredients
/// would bring another recipe's dish along.
pub(super) fn private_unit(kb: &KnowledgeBase, u: UnitId, eq: &str) -> bool {
    kb.units[u].input_nodes().all(|n| {
        let node = &kb.nodes[n];
        (is_utensil(&node.label) || node.label == eq) && node.contents().all(|i| i == eq)
    })
}

/// The node of `eq` a case-4 branch starts from, whether it is in state `s`, and the units making it:
/// the best few ranked in the state, and always the ingredient as it comes from the kitchen (last). A
/// branch handling the food as no recipe handles one of its form is kept only as a last resort (tahini
/// is not ground as the seed it was matched with).
fn pick_branch(ctx: &Context, o: &str, eq: &str, s: &str) -> Option<(NodeId, bool, Retrieved)> {
    let candidates = rank_nodes(ctx, eq, s);
    let count = candidates.len();
    let tried = candidates
        .iter()
        .copied()
        .enumerate()
        .filter(|(i, _)| *i < 8 || *i + 1 == count)
        .map(|x| x.1);
    let mut misfit = None;
    for (n, in_state) in tried {
        if ctx.kb.kitchen[n] {
            return Some((n, in_state, Default::default()));
        }
        let private = |u| private_unit(ctx.kb, u, eq);
        if let Some(r) = retrieve_within(ctx.kb, ctx.index, ctx.scorer, n, None, private) {
            if branch_fits(ctx, o, eq, &r) {
                return Some((n, in_state, r));
            }
            misfit.get_or_insert((n, in_state, r));
        }
    }
    misfit
}

/// Case 4 from the universal FOON: the equivalent's branch for the state, renamed and attached.
/// Returns the chosen state text and a reason.
pub(super) fn add_branch<'kb>(
    ctx: &Context<'kb>,
    tree: &mut Tree<'kb>,
    eq: &str,
    o: &str,
    asked: &str,
) -> Result<(SmolStr, String), String> {
    let prepared = prepared_state(ctx, o, eq, asked);
    let s = prepared.unwrap_or(asked);
    let picked = pick_branch(ctx, o, eq, s);
    let node = picked.as_ref().map(|p| (p.0, p.1));
    ctx.trace
        .record(|t| t.state_choice(ctx, (o, asked), eq, s, node));
    let before = tree.slots.len();
    // the reason, written into one string as the branch is made (sized for nearly every reason: it
    // does not grow step by step)
    let mut how = String::new();
    how.push_str("not in the reference tree: ");
    if eq != o {
        let _ = write!(how, "'{eq}' substituted with '{o}': ");
    }
    if prepared.is_some() {
        let _ = write!(
            how,
            "'{asked}' names only what {o} is: made '{s}', as a cook would; "
        );
    }
    let Some((n, in_state, r)) = picked else {
        // FOON only makes it together with other ingredients (a prepared product such as taco
        // seasoning, whose recipe would bring another dish along): it is bought ready
        let bare = tree.add_slot(Cow::Owned(ObjectNode::new(eq, Vec::new())));
        let _ = write!(
            how,
            "'{eq}' taken as bought (FOON makes it only together with other ingredients)"
        );
        return finish_branch(
            ctx,
            tree,
            eq,
            o,
            s,
            before,
            bare,
            SmolStr::default(),
            false,
            how,
        );
    };
    // most branches are a kitchen item alone: only units retrieved for one share the tree's utensils
    let (added, made) = if ctx.kb.kitchen[n] || r.units.is_empty() {
        (0, None)
    } else {
        let mut slot_of = starting_utensils(tree);
        tree.add_retrieved(ctx.kb, &r, &mut slot_of, Origin::Grafted);
        (r.units.len(), slot_of.get(&n).copied())
    };
    let last = made.unwrap_or_else(|| tree.add_slot(Cow::Borrowed(&ctx.kb.nodes[n])));
    let _ = write!(how, "'{}' taken from FOON", ctx.kb.nodes[n]);
    if added > 0 {
        let _ = write!(how, " with {added} unit(s) making it");
    }
    let state = state_text(&ctx.kb.nodes[n]);
    finish_branch(ctx, tree, eq, o, s, before, last, state, in_state, how)
}

/// The state a cook brings the food to when the asked state `s` is only a category word of the recipe
/// data ("whole veg" onion: chopped; "whole" egg: cracked), from `foods::prepared_state` of the asked food
/// (else its equivalent); None when `s` is a real state or the food is used as it is.
pub(super) fn prepared_state(ctx: &Context, o: &str, eq: &str, s: &str) -> Option<&'static str> {
    if category(s) != Category::Whole || matches!(s, "washed" | "clean") {
        return None;
    }
    let food = known_as(ctx, o, eq);
    foods::prepared_state(food)
}

/// The utensils the tree starts with, by knowledge-base node: a branch shares them rather than
/// duplicating them.
pub(super) fn starting_utensils(tree: &Tree) -> HashMap<NodeId, SlotId> {
    let mut slot_of = HashMap::default();
    for x in tree.live_slots() {
        if let Some(k) = tree.slots[x].kb {
            if tree.slots[x].utensil && !tree.produced(x) {
                slot_of.entry(k).or_insert(x);
            }
        }
    }
    slot_of
}

/// Whether the asked food is read as a product its asked state names, in that word or one of its state
/// category (coconut "shredded" or "flakes": shredded coconut; beef "ground": ground beef; garlic
/// "ground": garlic powder), or as a dried product (thyme "ground" is dried thyme, crumbled in its jar),
/// which a cook buys so rather than makes; not pepper "diced", a bell pepper.
fn bought_as_read(ctx: &Context, o: &str, s: &str) -> bool {
    let Some(r) = ctx.readings.get(o) else {
        return false;
    };
    let names = |w: &str, x: &str| {
        let c = category(w);
        x == w || (category(x) == c && !matches!(c, Category::Other | Category::Whole))
    };
    r.split(' ').any(|x| kind(x) == Some("dried"))
        || s.split([' ', ','])
            .any(|w| !w.is_empty() && r.split(' ').any(|x| names(w, x)))
}

/// The rest of a case-4 branch whose last node is `last`: a unit bringing it to the state `s` when it is
/// not in it (the motion FOON uses most for that state), the renaming to the query's name, and the
/// attachment where the dish takes such ingredients.
#[allow(clippy::too_many_arguments)]
pub(super) fn finish_branch<'kb>(
    ctx: &Context<'kb>,
    tree: &mut Tree<'kb>,
    eq: &str,
    o: &str,
    s: &str,
    before: SlotId,
    mut last: SlotId,
    mut chosen_state: SmolStr,
    mut in_state: bool,
    mut how: String,
) -> Result<(SmolStr, String), String> {
    if foods::prepared_first(known_as(ctx, o, eq)).is_some() && !in_state {
        // an egg is cracked before it is beaten or blended
        last = prepare_whole(ctx, tree, eq, o, last, &mut how);
    }
    let c = category(s);
    // milk taken in a cup is liquid milk already; liquid milk cannot be sliced, diced pineapple not made
    // whole (of the starting states only 'whole' speaks of the cut: dried fruit may well be diced)
    let node = &tree.slots[last].node;
    let from = food_category(ctx, node);
    let bought_preserved = matches!(kind(s), Some("dried" | "frozen"));
    let bought_made = bought_as_read(ctx, o, s);
    if (bought_preserved || bought_made) && from == Category::Whole {
        // asked dried or frozen (dried apricots), or read as a product made so (coconut "shredded" is
        // shredded coconut), bought so: not made from the whole food, no stone or skin to take off then
        let whole: Vec<String> = food_states(node)
            .into_iter()
            .filter(|st| category(st) == Category::Whole)
            .map(str::to_string)
            .collect();
        tree.slots[last].node = Cow::Owned(replace_states(node, &whole, s));
        let _ = write!(how, ", bought '{s}'");
        chosen_state = s.into();
        in_state |= bought_made;
    }
    let node = &tree.slots[last].node;
    let as_sold = ctx.index.sold_as(eq) == Some(c) && !has_food_state(node);
    let shown = shown_by_form(tree, known_as(ctx, o, eq), s, &[last]);
    if !(in_state || as_sold || shown || c == Category::Other) {
        if !from.reaches(c) && (c == Category::Whole || !c.is_starting()) {
            let _ = write!(
                how,
                ", state '{s}' cannot be reached from {} (not reversible)",
                from.name()
            );
        } else if c.is_starting() {
            if chosen_state.is_empty() && !s.is_empty() && from.reaches(c) {
                // an ingredient as bought is in the starting state asked for
                let node = map_states(node, s);
                tree.slots[last].node = Cow::Owned(node);
                chosen_state = s.into();
            }
        } else {
            match state_motion(ctx, o, eq, s) {
                Err(why) => {
                    let _ = write!(how, ", {}", why.trim_end_matches("; kept the tree's state"));
                }
                Ok(m) => match cannot_take(ctx, o, eq, &m) {
                    Some(why) => {
                        let _ = write!(how, ", state '{s}' not given: {why}");
                    }
                    None => {
                        let made = ObjectNode::new(eq, vec![State::plain(s)]);
                        last = add_state_unit(ctx, tree, last, made, &m);
                        let _ = write!(how, ", then '{m}' to make it '{s}'");
                        chosen_state = s.into();
                    }
                },
            }
        }
    }
    last = prepare_whole(ctx, tree, eq, o, last, &mut how);
    if eq != o {
        tree.rename_in(before..tree.slots.len(), eq, o);
    }
    join_branch(ctx, tree, (o, eq, s), last, &mut how)?;
    Ok((chosen_state, how))
}

/// Attachment of a branch ending in `last` for the asked food `o` (equivalent `eq`, state `s`): at the
/// unit `attach_point` picks, cooked alone first where nothing cooks it after, or onto the served dish
/// (`top_dish`) when it is a topping.
fn join_branch<'kb>(
    ctx: &Context<'kb>,
    tree: &mut Tree<'kb>,
    (o, eq, s): (&str, &str, &str),
    mut last: SlotId,
    how: &mut String,
) -> Result<(), String> {
    let order = tree.order();
    let carries = tree.carriers(&order);
    let food = known_as(ctx, o, eq);
    if let Some(point) = foods::greases(food)
        .then(|| greased_vessel(tree, &order))
        .flatten()
    {
        grease(tree, o, last, point);
        tree.add_contents_downstream(point.0, o, &order, &carries);
        let _ = write!(
            how,
            "; sprayed on the {} the dish is cooked in",
            tree.slots[point.1].node.label
        );
        return Ok(());
    }
    let cooked = cooked_later(tree, &order, food);
    let at = attach_point(ctx, tree, &order, &carries, &cooked, o, category(s));
    let Some(m) = at else {
        return Err(format!("no unit of the tree can take '{o}'"));
    };
    let cooked_there = cooks_what_joins(tree, &cooked, m, food);
    // a garnish goes onto the served dish, not into the hot pan before it is plated
    let m = if foods::joins_served(food) && (cooked_there || heats(tree, m)) {
        top_dish(tree, food, o, last)
    } else {
        if !cooked_there {
            last = cook_alone(ctx, tree, (o, "the dish does not cook it"), last, how);
        } else if foods::cooked_first(food) {
            last = cook_alone(ctx, tree, (o, "before it joins"), last, how);
        }
        last = blend_for_drink(ctx, tree, (o, eq), last, how);
        tree.units[m].inputs.push((last, true));
        tree.add_contents_downstream(m, o, &order, &carries);
        tree.units[m].origin = Origin::Attached;
        m
    };
    ctx.trace
        .record(|t| t.attached(o, s, &tree.units[m].motion, dish_pattern(ctx.class)));
    let _ = write!(how, "; added at '{}'", tree.units[m].motion);
    Ok(())
}
