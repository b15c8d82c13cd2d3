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
    tree_labels: &[SmolStr],
    w: &mut Work,
) -> Option<(String, f32)> {
    let ranked = ctx
        .sim
        .rank_in_set(name, ctx.index.id, &ctx.index.ingredient_labels, 6);
    // a name with no likeness at all (similarity 0, as exact matching gives every other name) is no
    // alternative and no closest name
    let alternatives = |eq: &str| -> Vec<Alternative> {
        ranked
            .iter()
            .filter(|(l, s)| l != eq && l != o && *s > 0.0)
            .take(5)
            .map(|(l, s)| Alternative {
                label: l.as_str().into(),
                similarity: *s,
            })
            .collect()
    };
    if let Some(v) = ctx.overrides.get(o) {
        w.overridden = true;
        if !ctx.index.is_label(v) || is_utensil(v) {
            w.alternatives = alternatives("");
            w.reasons.push(format!(
                "override '{v}' is not an ingredient of the knowledge base"
            ));
            return None;
        }
        let sim = if v == o {
            1.0
        } else {
            ctx.sim.similarity(o, v)
        };
        w.alternatives = alternatives(v);
        return Some((v.clone(), sim));
    }
    // a name FOON gives a utensil or container (a cooking spray holds the oil) is planned as the
    // ingredient it clearly holds, else only as the one the user picks from the alternatives offered
    if is_utensil(o) {
        let held = ranked
            .first()
            .filter(|(l, s)| ctx.sim.accepts(*s) && !ctx.sim.low_confidence(name, l, *s));
        if let Some((label, sim)) = held {
            w.alternatives = alternatives(label);
            w.reasons.push(format!(
                "'{o}' is a container in FOON: planned as the ingredient it holds, '{label}'"
            ));
            return Some((label.clone(), *sim));
        }
        w.alternatives = alternatives("");
        w.reasons.push(format!(
            "'{o}' is a utensil or container in FOON, not an ingredient: pick the ingredient it stands for (an override) to plan it"
        ));
        return None;
    }
    if ctx.index.is_label(name) {
        // (a reading is the food itself, named more exactly)
        w.alternatives = alternatives(name);
        return Some((name.to_string(), 1.0));
    }
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
    match pick {
        Some((label, sim)) => {
            w.alternatives = alternatives(&label);
            if !tree_labels.iter().any(|l| *l == label) {
                w.reasons
                    .push(format!("equivalent '{label}' found in the universal FOON"));
            }
            Some((label, sim))
        }
        None => {
            w.alternatives = alternatives("");
            w.reasons.push(format!(
                "no equivalent of '{name}' in the knowledge base{}",
                ranked
                    .first()
                    .filter(|(_, s)| *s > 0.0)
                    .map(|(l, s)| format!(" (closest: '{l}', {s:.2})"))
                    .unwrap_or_default()
            ));
            None
        }
    }
}
