//! Cases 3 and 4 within the tree: the units that bring an ingredient from the state the tree has to the
//! state asked for, from FOON or made from the most frequent motion.

use super::*;

pub(super) const SEPARATION: &[Category] = &[
    Category::Trimmed,
    Category::Cut,
    Category::FinelyCut,
    Category::Ground,
];

/// Live slots of `label` downstream of the given units (through units that pass the object on).
pub(super) fn downstream(
    tree: &Tree,
    start: Vec<TUnitId>,
    label: &str,
    order: &[TUnitId],
) -> Vec<SlotId> {
    let mut out = Vec::new();
    let mut seen_units: HashSet<TUnitId> = HashSet::default();
    let mut seen_slots: HashSet<SlotId> = HashSet::default();
    let mut work = start;
    while let Some(u) = work.pop() {
        if !seen_units.insert(u) {
            continue;
        }
        for &(x, _) in &tree.units[u].outputs {
            if tree.slots[x].node.label == label && seen_slots.insert(x) {
                out.push(x);
                work.extend(tree.consumers(x, order));
            }
        }
    }
    out
}

/// Replaces food states in a node (`old` → `new`; when `old` is empty, `new` is added).
pub(super) fn replace_states(node: &ObjectNode, old: &[String], new: &str) -> ObjectNode {
    with_state(node, |st| old.iter().any(|o| st == o.as_str()), new)
}

/// `node` in the state `new`, without the plain states `gone` picks (its places and lists stay).
pub(super) fn with_state(node: &ObjectNode, gone: impl Fn(&str) -> bool, new: &str) -> ObjectNode {
    let mut states: Vec<State> = node
        .states
        .iter()
        .filter(|st| st.arg.is_some() || !gone(&st.name))
        .cloned()
        .collect();
    states.push(State::plain(new));
    ObjectNode::new(node.label.clone(), states)
}

/// Cases 3 and 4: brings the ingredient `o` (already in the tree, in `slots`; `eq` in FOON) to the
/// state `s`.
pub(super) fn restate<'kb>(
    ctx: &Context<'kb>,
    tree: &mut Tree<'kb>,
    eq: &str,
    o: &str,
    s: &str,
    slots: &[SlotId],
) -> Result<String, String> {
    let order = tree.order();
    let Some(leaf) = starting_leaf(tree, &order, slots) else {
        return Err(format!(
            "'{o}' has no starting node in the tree; state kept"
        ));
    };
    let leaf_node = tree.slots[leaf].node.clone();
    let leaf_state = state_text(&leaf_node);
    let leaf_cat = food_category(ctx, &leaf_node);
    let c = category(s);
    if c.is_starting() {
        return made_from_raw(ctx, tree, eq, o, s, leaf);
    }
    if !leaf_cat.reaches(c) {
        // a node without food states is in the category its ingredient is sold in
        let kept = if leaf_state.is_empty() {
            leaf_cat.name().into()
        } else {
            leaf_state
        };
        return Err(format!(
            "state '{s}' cannot be reached from the tree's '{kept}' (not reversible); kept '{kept}'"
        ));
    }
    let motion = state_motion(ctx, o, eq, s)?;
    if let Some(why) = cannot_take(ctx, o, eq, &motion) {
        return Err(format!(
            "state '{s}' not given: {why}; kept the tree's state"
        ));
    }
    if SEPARATION.contains(&c) {
        let misfit = |m: &str| cannot_take(ctx, o, eq, m).is_some();
        if let Some(done) = swap_cut(tree, &order, (o, s, &motion), &misfit) {
            return Ok(done);
        }
    }
    // The unit bringing the ingredient to the wanted state comes after the tree's last cut of it (a
    // lime chopped, then squeezed), so that nothing cuts what is already juice or mashed; when the tree
    // does not cut it, or the cut piece goes on only as a container's contents through units pruning
    // may drop (a unit after the cut would then make nothing used), before its first use.
    let cut = order.iter().rev().find_map(|&u| {
        let (x, _) = cut_in(tree, u, o)?;
        let goes_on = tree.consumers(x, &order).any(|v| {
            tree.units[v]
                .outputs
                .iter()
                .any(|&(y, _)| y == tree.goal || tree.slots[y].node.label == o)
        });
        (goes_on && food_category(ctx, &tree.slots[x].node).reaches(c)).then_some((x, u))
    });
    let from = cut.map_or_else(|| past_handling(ctx, tree, &order, o, leaf), |(x, _)| x);
    if cut.is_none() && !SEPARATION.contains(&c) {
        opened_first(tree, &order, from, o, s)?;
    }
    add_state_step(ctx, tree, &order, from, cut.is_some(), o, s, &motion);
    Ok(match cut {
        Some((_, u)) => format!(
            "added '{motion}' after '{}' to make it '{s}'",
            tree.units[u].motion
        ),
        None => format!("added '{motion}' to make it '{s}'"),
    })
}

/// Of `o`'s slots, the node nothing in the tree makes that is used first.
fn starting_leaf(tree: &Tree, order: &[TUnitId], slots: &[SlotId]) -> Option<SlotId> {
    let first_use = |x: SlotId| {
        order
            .iter()
            .position(|&u| tree.units[u].inputs.iter().any(|i| i.0 == x))
            .unwrap_or(usize::MAX)
    };
    slots
        .iter()
        .copied()
        .filter(|&x| !tree.produced(x))
        .min_by_key(|&x| (first_use(x), x))
}

/// Table I, case 3: the tree starts from a processed leaf; adds the units making it from raw.
fn made_from_raw<'kb>(
    ctx: &Context<'kb>,
    tree: &mut Tree<'kb>,
    eq: &str,
    o: &str,
    s: &str,
    leaf: SlotId,
) -> Result<String, String> {
    let leaf_node = &tree.slots[leaf].node;
    let Some(kb_node) = tree.slots[leaf].kb else {
        return Err(format!(
            "no way to make '{leaf_node}' from '{s}' is known; taken as it is"
        ));
    };
    let leaf_state = state_text(leaf_node);
    let r = retrieve(ctx.kb, ctx.index, ctx.scorer, kb_node, ctx.goal_subgraph);
    if r.units.is_empty() {
        return Err(format!(
            "FOON has no way to make '{leaf_state}' {o} from '{s}'; it is taken as it is"
        ));
    }
    let mut slot_of: HashMap<NodeId, SlotId> = [(kb_node, leaf)].into_iter().collect();
    let before = tree.slots.len();
    tree.add_retrieved(ctx.kb, &r, &mut slot_of, Origin::Grafted);
    if eq != o {
        tree.rename_in(before..tree.slots.len(), eq, o);
    }
    Ok(format!(
        "added {} unit(s) making the tree's '{leaf_state}' {o} from '{s}'",
        r.units.len()
    ))
}

/// Swaps the tree's own cutting step of `o` for one reaching the wanted cut `s` by `motion`, if it has
/// one: a cut into pieces for pieces, a trim for a trim (a cherry tomato taken off its stem stays
/// destemmed when it is asked chopped; its quartering becomes the chopping), or a step the food cannot
/// take (`misfit`: canned fruit cocktail is not peeled like the orange it replaced).
fn swap_cut(
    tree: &mut Tree,
    order: &[TUnitId],
    (o, s, motion): (&str, &str, &str),
    misfit: &dyn Fn(&str) -> bool,
) -> Option<String> {
    let into_pieces = |st: &str| category(st) != Category::Trimmed;
    let fits = |u: TUnitId, old: &[String]| match old {
        // a cut FOON leaves unsaid is into pieces
        [] => into_pieces(s),
        _ => {
            misfit(&tree.units[u].motion) || old.iter().all(|st| into_pieces(st) == into_pieces(s))
        }
    };
    let (u, old) = order.iter().find_map(|&u| {
        cut_in(tree, u, o)
            .filter(|(_, old)| fits(u, old))
            .map(|(_, old)| (u, old))
    })?;
    for x in downstream(tree, vec![u], o, order) {
        let node = replace_states(&tree.slots[x].node, &old, s);
        tree.slots[x].node = Cow::Owned(node);
    }
    let unit = &mut tree.units[u];
    let before = std::mem::replace(&mut unit.motion, Cow::Owned(motion.to_string()));
    if unit.origin == Origin::Reference {
        unit.origin = Origin::Renamed;
    }
    Some(format!(
        "'{}' ({before}) changed to '{s}' ({motion})",
        old.join(", ")
    ))
}

/// A whole food its first use opens into other foods (an egg cracked into white and yolk) is not
/// blended or cooked before: those foods are what go on.
fn opened_first(
    tree: &Tree,
    order: &[TUnitId],
    from: SlotId,
    o: &str,
    s: &str,
) -> Result<(), String> {
    for v in tree.consumers(from, order) {
        let outputs = tree.units[v].outputs.iter().map(|&(y, _)| &tree.slots[y]);
        if outputs
            .clone()
            .any(|x| x.node.label == o || x.node.contents().any(|i| i == o))
        {
            continue;
        }
        let foods: Vec<&str> = outputs
            .filter(|x| !x.utensil && !x.node.holds_something())
            .map(|x| x.node.label.as_str())
            .collect();
        if !foods.is_empty() {
            return Err(format!(
                "state '{s}' not given: '{}' makes the {o} into {} first, which the tree takes on",
                tree.units[v].motion,
                foods.join(" and ")
            ));
        }
    }
    Ok(())
}

/// Adds the unit `motion` bringing `o` from slot `from` to state `s`; its users take the new node, and
/// the nodes of `o` after it are in `s`.
#[allow(clippy::too_many_arguments)]
fn add_state_step<'kb>(
    ctx: &Context<'kb>,
    tree: &mut Tree<'kb>,
    order: &[TUnitId],
    from: SlotId,
    after_cut: bool,
    o: &str,
    s: &str,
    motion: &str,
) {
    let from_node = tree.slots[from].node.clone();
    let old: Vec<String> = food_states(&from_node)
        .into_iter()
        .map(str::to_string)
        .collect();
    // after a cut the ingredient stays where it was cut
    let made = if after_cut {
        replace_states(&from_node, &old, s)
    } else {
        ObjectNode::new(o, vec![State::plain(s)])
    };
    let consumers: Vec<TUnitId> = tree.consumers(from, order).collect();
    let new_slot = add_state_unit(ctx, tree, from, made, motion);
    for &v in &consumers {
        for i in tree.units[v].inputs.iter_mut() {
            if i.0 == from {
                i.0 = new_slot;
            }
        }
    }
    for x in downstream(tree, consumers, o, order) {
        let node = replace_states(&tree.slots[x].node, &old, s);
        tree.slots[x].node = Cow::Owned(node);
    }
}

/// Where on `o`'s own chain from `leaf` a change of state can come: past the units that unwrap it, wash
/// it or give it the preparation that comes before anything else (an egg is cracked before it is beaten;
/// cheese is unwrapped before it is grated; berries are washed, then sliced), so that nothing is done to
/// it in its shell or packet; never past the unit it leaves its chain at.
pub(super) fn past_handling(
    ctx: &Context,
    tree: &Tree,
    order: &[TUnitId],
    o: &str,
    leaf: SlotId,
) -> SlotId {
    let first = foods::prepared_first(known_as(ctx, o, o));
    let handling = |motion: &str| {
        foods::unwraps(motion)
            || foods::washes(motion)
            || first.is_some_and(|p| p.starts_with(motion))
    };
    let chain = own_chain(tree, order, o, leaf);
    let mut past = leaf;
    // the last unit of the chain takes it on: a change of state comes before it at the latest; moves
    // between handlings (into the bowl it is washed in) are passed over
    for &(_, u) in chain.iter().take(chain.len().saturating_sub(1)) {
        let motion = &tree.units[u].motion;
        if !handling(motion) && !is_transfer_motion(motion) {
            break;
        }
        let Some(&(next, _)) = tree.units[u]
            .outputs
            .iter()
            .find(|&&(y, _)| tree.slots[y].node.label == o)
        else {
            break;
        };
        if handling(motion) {
            past = next;
        }
    }
    past
}

/// The motion bringing `o` (`eq` in FOON) into state `s`: the one FOON uses most for the state, if
/// some recipe uses it on a food of the form of `o`, else the one recipes use most on foods of that form
/// (butter is softened as FOON softens butter, not blended as it softens vegetables).
pub(super) fn state_motion(ctx: &Context, o: &str, eq: &str, s: &str) -> Result<String, String> {
    let motion = motion_to_state(ctx, o, eq, s)?;
    // a state its form is never in names only what it is sold as (beans "juice": canned in liquid); a
    // motion its form cannot take is the caller's to explain
    let food = known_as(ctx, o, eq);
    if foods::never_in(food, s) && foods::takes(food, &motion) {
        return Err(format!(
            "a food like '{o}' is never '{s}'; kept the tree's state"
        ));
    }
    Ok(motion)
}

/// `state_motion` before the food's form is asked whether it is ever in `s`.
fn motion_to_state(ctx: &Context, o: &str, eq: &str, s: &str) -> Result<String, String> {
    let model = &ctx.index.transitions;
    let food = known_as(ctx, o, eq);
    let usual = ctx.index.motion_for(s);
    if !model.judges(food) {
        return usual
            .ok_or_else(|| format!("no motion in FOON reaches '{s}'; kept the tree's state"));
    }
    if let Some(m) = usual
        .as_ref()
        .filter(|m| model.makes(food, m, s) == Verdict::Seen)
    {
        return Ok(m.clone());
    }
    model
        .motion_for(food, s)
        // moving a food does not change it (FOON may list ground cumin poured from a leaf)
        .filter(|m| !is_transfer_motion(m))
        .map(str::to_string)
        // a cut the food's form takes, though no recipe here cuts such a food so (cheese diced)
        .or_else(|| usual.filter(|m| foods::cuts(m) && foods::takes(food, m)))
        .ok_or_else(|| {
            format!("no recipe in FOON brings a food like '{o}' to '{s}'; kept the tree's state")
        })
}

/// The state to plan the asked food for: a cooked state of the recipe data that no recipe brings a
/// food like it to ("baked" rice: cooked, in the source's coarse words) is planned as "cooked".
pub(super) fn planned_state<'s>(ctx: &Context, o: &str, eq: &str, s: &'s str) -> &'s str {
    let coarse = category(s) == Category::Cooked && s != "cooked";
    if coarse && state_motion(ctx, o, eq, s).is_err() && state_motion(ctx, o, eq, "cooked").is_ok()
    {
        "cooked"
    } else {
        s
    }
}

/// The output of unit `u` in which `o` gains a cut (a separation state none of its inputs `o` has),
/// with the states gained.
pub(super) fn cut_in(tree: &Tree, u: TUnitId, o: &str) -> Option<(SlotId, Vec<String>)> {
    let unit = &tree.units[u];
    unit.outputs.iter().find_map(|&(x, _)| {
        let out = &tree.slots[x].node;
        if out.label != o {
            return None;
        }
        let before: BTreeSet<&str> = unit
            .inputs
            .iter()
            .map(|i| &tree.slots[i.0].node)
            .filter(|n| n.label == o)
            .flat_map(|n| n.physical_states())
            .collect();
        if before.is_empty() && !unit.inputs.iter().any(|i| tree.slots[i.0].node.label == o) {
            return None;
        }
        let g: Vec<String> = food_states(out)
            .into_iter()
            .filter(|st| !before.contains(st) && SEPARATION.contains(&category(st)))
            .map(str::to_string)
            .collect();
        // FOON may leave the state out ("ginger in pot" once grated): the motion says the food is cut
        let in_pieces = |st: &str| {
            matches!(
                category(st),
                Category::Cut | Category::FinelyCut | Category::Ground
            )
        };
        let cut_unsaid = g.is_empty()
            && !food_states(out).into_iter().any(in_pieces)
            && foods::leaves_in(&unit.motion).is_some_and(in_pieces);
        (!g.is_empty() || cut_unsaid).then_some((x, g))
    })
}

/// Adds a unit making `made` (the ingredient in a new state) from slot `from` by `motion`, with the
/// utensil FOON uses most for it; returns the new slot.
pub(super) fn add_state_unit<'kb>(
    ctx: &Context<'kb>,
    tree: &mut Tree<'kb>,
    from: SlotId,
    made: ObjectNode,
    motion: &str,
) -> SlotId {
    let made = tree.add_slot(Cow::Owned(made));
    add_motion_unit(ctx, tree, from, motion, made);
    made
}

/// `add_state_unit` between slot `at` and unit `u`, which takes the new slot instead.
pub(super) fn add_state_unit_before<'kb>(
    ctx: &Context<'kb>,
    tree: &mut Tree<'kb>,
    (at, u): (SlotId, TUnitId),
    made: ObjectNode,
    motion: &str,
) -> SlotId {
    let made = add_state_unit(ctx, tree, at, made, motion);
    for input in tree.units[u].inputs.iter_mut().filter(|i| i.0 == at) {
        input.0 = made;
    }
    made
}

/// A grafted unit taking the food `from` (with the utensil FOON uses for `motion`) to the node `to`.
pub(super) fn add_motion_unit<'kb>(
    ctx: &Context<'kb>,
    tree: &mut Tree<'kb>,
    from: SlotId,
    motion: &str,
    to: SlotId,
) {
    let mut inputs = vec![(from, true)];
    if let Some(t) = ctx.index.utensil_for(motion) {
        inputs.push((utensil_slot(ctx.kb, tree, t), false));
    }
    tree.add_unit(inputs, motion, vec![(to, true)], Origin::Grafted);
}

/// A slot for a utensil node: the tree's own when it is a starting item there, else a new one.
pub(super) fn utensil_slot<'kb>(kb: &'kb KnowledgeBase, tree: &mut Tree<'kb>, n: NodeId) -> SlotId {
    let node = &kb.nodes[n];
    if let Some(x) = tree
        .slots_with_label(&node.label)
        .into_iter()
        .find(|&x| *tree.slots[x].node == *node && !tree.produced(x))
    {
        return x;
    }
    tree.add_slot(Cow::Borrowed(node))
}

/// Knowledge-base nodes of `eq` for state `s`, best first: same state, else one of its kind (grated for
/// shredded), else same category, preferring one not in a vessel food is cooked in, then one without
/// a place (ties: the state most frequent in recipes of the dish class, then overall).
/// The flag says whether the node is in the wanted state (else it is the ingredient as bought).
pub(super) fn rank_nodes(ctx: &Context, eq: &str, s: &str) -> Vec<(NodeId, bool)> {
    let c = category(s);
    type Key = (
        bool,
        bool,
        bool,
        bool,
        bool,
        bool,
        u32,
        u32,
        usize,
        std::cmp::Reverse<NodeId>,
    );
    let mut ranked: Vec<(Key, NodeId)> = Vec::new();
    for &n in ctx.index.nodes_of(eq) {
        let node = &ctx.kb.nodes[n];
        // the node's food states and their categories
        let (food, cats): (Vec<&str>, Vec<Category>) = node
            .physical_states()
            .map(|state| (state, category(state)))
            .filter(|&(_, k)| k != Category::Other)
            .unzip();
        let exact = food.contains(&s);
        let kin = food.iter().any(|f| akin(f, s));
        let cat = c != Category::Other && cats.contains(&c);
        // a node saying nothing of its food is as bought: whole, unless its ingredient is sold otherwise
        let raw = c.is_starting()
            && ctx.kb.kitchen[n]
            && cats.iter().all(|k| k.is_starting())
            && (!cats.is_empty() || ctx.index.sold_as(eq).is_none());
        if !(exact || cat || raw) {
            continue;
        }
        let (in_class, overall) = ctx.index.state_frequency(ctx.class, eq, &food);
        let bare = node.container().is_none() && !node.holds_something();
        // an ingredient comes from a packet, a shaker, a bowl: not from the pan it was cooked in
        let stored = !node.container().is_some_and(|c| ctx.index.is_heated(c));
        let key = (
            exact,
            kin,
            cat,
            stored,
            !node.holds_something(),
            bare,
            in_class,
            overall,
            usize::MAX - node.states.len(),
            std::cmp::Reverse(n),
        );
        ranked.push((key, n));
    }
    ranked.sort_by_key(|r| std::cmp::Reverse(r.0));
    let mut out: Vec<(NodeId, bool)> = ranked.into_iter().map(|(_, n)| (n, true)).collect();
    // the ingredient as it comes from the kitchen, fresh unless asked preserved (a grape halved is not a
    // raisin), fewest states first
    let preserved = |n: NodeId| {
        c != Category::Preserved
            && ctx.kb.nodes[n]
                .physical_states()
                .any(|st| category(st) == Category::Preserved)
    };
    if let Some(n) = ctx
        .index
        .nodes_of(eq)
        .iter()
        .copied()
        .filter(|&n| ctx.kb.kitchen[n] && !ctx.kb.nodes[n].holds_something())
        .min_by_key(|&n| (preserved(n), ctx.kb.nodes[n].states.len(), n))
        .or_else(|| ctx.index.nodes_of(eq).first().copied())
    {
        out.push((n, false));
    }
    out
}

/// Why the asked food `o` (else its equivalent `eq`, when the food knowledge does not know `o`) cannot
/// take `motion` ("a powder is not squeezed"), or None when it can: a query's state word that only such a
/// motion makes is a coarse category of the recipe data (butter "ground", oil "juice").
pub(super) fn cannot_take(ctx: &Context, o: &str, eq: &str, motion: &str) -> Option<String> {
    // the asked food's knowledge decides when it has any: horseradish is not handled as the cayenne it
    // replaced
    let food = known_as(ctx, o, eq);
    let form = foods::form_of(food)?;
    (!foods::takes(food, motion)).then(|| format!("{o} ({}) is not '{motion}'", form.name))
}

/// A node without food states given the starting state `s`.
pub(super) fn map_states(node: &ObjectNode, s: &str) -> ObjectNode {
    let mut states = node.states.clone();
    states.push(State::plain(s));
    ObjectNode::new(node.label.clone(), states)
}
