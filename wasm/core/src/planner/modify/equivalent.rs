//! The equivalent of an asked object: an override, itself, or the most similar label of the reference
//! tree or of the universal FOON (section III-C).

use super::*;

/// The food an ambiguous name is looked up as, by its state (pepper diced: bell pepper), when the
/// knowledge base has it or something like it and the user has not overridden the name.
pub(super) fn read_as(ctx: &Context, o: &str, s: &str) -> Option<&'static str> {
    let r = foods::reading(o, s).filter(|&r| r != o && !ctx.overrides.contains_key(o))?;
    let known = ctx.index.is_label(r)
        || ctx
            .sim
            .rank_in_set(r, ctx.index.id, &ctx.index.ingredient_labels, 1)
            .first()
            .is_some_and(|(_, sim)| ctx.sim.accepts(*sim));
    known.then_some(r)
}

/// The equivalent of `o` (looked up as `name`, the food it is read as): an override, itself when it is a
/// FOON label, else the most similar label of the reference tree, else of the whole knowledge base. Fills
/// the alternatives; `None` when unplannable.
pub(super) fn equivalent(
    ctx: &Context,
    o: &str,
    name: &str,
    reference: &ReferenceLabels,
    w: &mut Work,
) -> Option<(String, f32)> {
    let ranked = ctx
        .sim
        .rank_in_set(name, ctx.index.id, &ctx.index.ingredient_labels, 6);
    let found = match ctx.overrides.get(o) {
        Some(v) => {
            w.overridden = true;
            overridden(ctx, o, v, &mut w.reasons)
        }
        None if is_utensil(o) => held_in(ctx, o, name, &ranked, &mut w.reasons),
        // (a reading is the food itself, named more exactly)
        None if ctx.index.is_label(name) => Some(
            kin_in_tree(ctx, name, reference, &mut w.reasons)
                .unwrap_or_else(|| (name.to_string(), 1.0)),
        ),
        None => most_similar(ctx, name, &reference.all, &ranked, &mut w.reasons),
    };
    // a name with no likeness at all (similarity 0, as exact matching gives every other name) is no
    // alternative
    let eq = found.as_ref().map_or("", |(label, _)| label.as_str());
    w.alternatives = ranked
        .iter()
        .filter(|(l, s)| l != eq && l != o && *s > 0.0)
        .take(5)
        .map(|(l, s)| Alternative {
            label: l.as_str().into(),
            similarity: *s,
        })
        .collect();
    found
}

/// A variety of `name` in the reference tree (its "vegetable oil" for the oil asked, its "egg white and
/// yolk" for the egg: a label of the same kind of food that names it), when `name` itself is not there:
/// taking its place keeps the tree's own handling of it, where a branch from elsewhere in FOON would
/// only join the dish at some unit.
fn kin_in_tree(
    ctx: &Context,
    name: &str,
    reference: &ReferenceLabels,
    reasons: &mut Vec<String>,
) -> Option<(String, f32)> {
    if reference.all.iter().any(|l| l == name) {
        return None;
    }
    let kind = foods::kind(name)?;
    // a variety puts words before the name ("olive oil"); a name followed by more is a part of the food
    // ("egg yolk", "lime zest"), unless the rest names the food by all of its parts ("egg white and yolk")
    let names_it = |label: &str| {
        label.strip_suffix(name).is_some_and(|m| m.ends_with(' '))
            || label
                .strip_prefix(name)
                .is_some_and(|rest| rest.starts_with(' ') && rest.contains(" and "))
    };
    // (a label whose food FOON leaves short of the dish would leave the asked food there too)
    let kin: Vec<&str> = reference
        .reaching
        .iter()
        .map(SmolStr::as_str)
        .filter(|l| names_it(l) && foods::kind(l) == Some(kind) && same_care(name, l))
        .collect();
    let (label, sim) = ctx.sim.rank(name, &kin, 1).into_iter().next()?;
    reasons.push(format!(
        "'{name}' is not in the reference tree: its '{label}', a {kind} of that name, takes its place"
    ));
    Some((label, sim))
}

/// Whether a cook treats the two foods alike: cooked or not, joining the dish at the same time, prepared
/// the same way (sour cream, a topping, is not the cream beaten into the eggs; green onion is not onion).
fn same_care(a: &str, b: &str) -> bool {
    let care = |f: &str| {
        (
            foods::must_cook(f),
            foods::joins_served(f),
            foods::joins_mixed(f),
            foods::joins_before_heat(f),
            foods::prepared_state(f),
            foods::trims(f).iter().map(|t| t.flag).collect::<Vec<_>>(),
        )
    };
    care(a) == care(b)
}

/// The label `v` the user gave for `o`, when it is an ingredient of the knowledge base.
fn overridden(ctx: &Context, o: &str, v: &str, reasons: &mut Vec<String>) -> Option<(String, f32)> {
    if !ctx.index.is_label(v) || is_utensil(v) {
        reasons.push(format!(
            "override '{v}' is not an ingredient of the knowledge base"
        ));
        return None;
    }
    let sim = if v == o {
        1.0
    } else {
        ctx.sim.similarity(o, v)
    };
    Some((v.to_string(), sim))
}

/// A name FOON gives a utensil or container (a cooking spray holds the oil) is planned as the ingredient
/// it clearly holds, else only as the one the user picks from the alternatives offered.
fn held_in(
    ctx: &Context,
    o: &str,
    name: &str,
    ranked: &[(String, f32)],
    reasons: &mut Vec<String>,
) -> Option<(String, f32)> {
    let held = ranked
        .first()
        .filter(|(l, s)| ctx.sim.accepts(*s) && !ctx.sim.low_confidence(name, l, *s));
    match held {
        Some((label, sim)) => {
            reasons.push(format!(
                "'{o}' is a container in FOON: planned as the ingredient it holds, '{label}'"
            ));
            Some((label.clone(), *sim))
        }
        None => {
            reasons.push(format!(
                "'{o}' is a utensil or container in FOON, not an ingredient: pick the ingredient it stands for (an override) to plan it"
            ));
            None
        }
    }
}

/// The most similar label of the reference tree (`tree_labels`), else of the knowledge base (`ranked`).
fn most_similar(
    ctx: &Context,
    name: &str,
    tree_labels: &[SmolStr],
    ranked: &[(String, f32)],
    reasons: &mut Vec<String>,
) -> Option<(String, f32)> {
    let tree_refs: Vec<&str> = tree_labels.iter().map(SmolStr::as_str).collect();
    let in_tree = ctx.sim.rank(name, &tree_refs, 1).into_iter().next();
    let in_kb = ranked.first().cloned();
    ctx.trace
        .record(|t| t.equivalents(name, in_tree.as_ref(), in_kb.as_ref()));
    let pick = match (in_tree, in_kb) {
        (Some(t), k) if ctx.sim.accepts(t.1) && !ctx.sim.low_confidence(name, &t.0, t.1) => {
            Some(t).or(k)
        }
        (t, Some(k)) if ctx.sim.accepts(k.1) && t.as_ref().is_none_or(|t| k.1 > t.1) => Some(k),
        (Some(t), _) if ctx.sim.accepts(t.1) => Some(t),
        _ => None,
    };
    match &pick {
        Some((label, _)) if !tree_labels.iter().any(|l| l == label) => {
            reasons.push(format!("equivalent '{label}' found in the universal FOON"));
        }
        Some(_) => {}
        None => reasons.push(format!(
            "no equivalent of '{name}' in the knowledge base{}",
            ranked
                .first()
                .filter(|(_, s)| *s > 0.0)
                .map(|(l, s)| format!(" (closest: '{l}', {s:.2})"))
                .unwrap_or_default()
        )),
    }
    pick
}
