//! Culinary plausibility of a finished plan, from its units and progress lines alone (not from what
//! modification meant to do), by the food knowledge of `foods`: what a cook would stop at.

use crate::contract::plan::{Caution, CautionKind, Plan, ProgressLine, Status};
use crate::vocab::foods;
use crate::vocab::states::{category, Category};
use crate::vocab::taxonomy::is_utensil;

/// What a cook would stop at in `plan`; empty when nothing.
pub fn cautions(plan: &Plan) -> Vec<Caution> {
    let readings = foods::query_readings(&plan.query);
    // the food knowledge judges a name by the food its state says it is (coriander asked as leaves)
    let meant = |food: &str| -> String { readings.get(food).map_or(food, |r| r).to_string() };
    let mut out = motions_on_forms(plan, &meant);
    for line in asked_lines(plan) {
        out.extend(line_caution(plan, line, &meant(&line.ingredient)));
    }
    out
}

/// Units giving a food a motion its form cannot take, once per food and motion. In a unit of several
/// foods the motion is the one of those that take it (the avocado mashed with the salt, the pastry cut
/// with its filling), so a food is named only when no other food of the unit takes it either.
fn motions_on_forms(plan: &Plan, meant: &dyn Fn(&str) -> String) -> Vec<Caution> {
    let mut out: Vec<Caution> = Vec::new();
    for unit in &plan.units {
        let mut food = unit
            .inputs
            .iter()
            .map(|n| n.label.as_str())
            .filter(|l| !is_utensil(l));
        if food.clone().any(|f| foods::takes(&meant(f), &unit.motion)) {
            continue;
        }
        for food in food.by_ref() {
            let detail = format!("{food} cannot be '{}'", unit.motion);
            if !out.iter().any(|c| c.detail == detail) {
                out.push(Caution {
                    kind: CautionKind::MotionOnForm,
                    food: food.to_string(),
                    detail,
                });
            }
        }
    }
    out
}

/// The progress lines of the planned query ingredients.
fn asked_lines(plan: &Plan) -> impl Iterator<Item = &ProgressLine> {
    plan.progress_lines.iter().filter(|l| {
        plan.ingredients
            .iter()
            .any(|o| o.status == Status::Planned && o.object == l.ingredient)
    })
}

/// The first of: the line ends short of the dish, a must-cook food is never cooked, produce is never
/// prepared.
fn line_caution(plan: &Plan, line: &ProgressLine, meant: &str) -> Option<Caution> {
    let food = line.ingredient.to_string();
    let caution = |kind, detail| {
        Some(Caution {
            kind,
            food: food.clone(),
            detail,
        })
    };
    if line.motion.is_empty() {
        let detail = format!("{food} is never used on the way to {}", plan.goal.label);
        return caution(CautionKind::ShortOfDish, detail);
    }
    if !super::output::reaches_dish(line, &plan.goal.label) {
        let last = line.state.last().map_or("", |s| s.physical_state.as_str());
        let detail = format!(
            "{food} ends in {} ({last}), not in {}",
            line.end_product, plan.goal.label
        );
        return caution(CautionKind::ShortOfDish, detail);
    }
    let cooked = reaches(line, Category::Cooked)
        || line.motion.iter().any(|m| foods::cooks_food(meant, m))
        || dish_cooked(plan, meant);
    if foods::must_cook(meant) && !cooked && !reaches(line, Category::Preserved) {
        return caution(
            CautionKind::Uncooked,
            format!("{food} reaches {} uncooked", plan.goal.label),
        );
    }
    let prepared = foods::prepared_state(meant);
    if prepared.is_some_and(|p| !cooked && !changed(line, p)) {
        let detail = format!("{food} goes into {} whole", plan.goal.label);
        return caution(CautionKind::LeftWhole, detail);
    }
    None
}

/// Whether a unit cooks the dish itself once it is made (the pancake flipped, then cooked): `food` in it
/// is cooked with it, if that motion cooks such a food.
fn dish_cooked(plan: &Plan, food: &str) -> bool {
    plan.units.iter().any(|u| {
        foods::cooks_food(food, &u.motion) && u.inputs.iter().any(|n| n.label == plan.goal.label)
    })
}

/// The words of the line's physical states ("in batter, baked" is "in batter" and "baked").
fn state_words(line: &ProgressLine) -> impl Iterator<Item = &str> {
    line.state
        .iter()
        .flat_map(|s| s.physical_state.split(", "))
        .filter(|w| !w.is_empty())
}

fn reaches(line: &ProgressLine, c: Category) -> bool {
    state_words(line).any(|w| category(w) == c)
}

/// Motion words that break down a food and what it is in (a banana blended into the smoothie).
const BREAKING_DOWN: &[&str] = &["blend", "mash", "puree", "purée", "process", "crush"];

/// Motion words that cut a food itself (ginger grated into the pot, an egg cracked into the bowl).
const CUTTING: &[&str] = &[
    "cut", "chop", "slice", "dice", "mince", "grate", "shred", "julienne", "zest", "tear", "crack",
    "squeeze", "juice",
];

/// Whether the food was prepared along the line: its own states (before it joins anything) cut,
/// ground, juiced, mashed, shaped or dried, or brought to `prepared` (an egg cracked), or a motion cut it
/// while it was itself or broke it down later.
fn changed(line: &ProgressLine, prepared: &str) -> bool {
    let own = line
        .state
        .iter()
        .map(|s| s.physical_state.as_str())
        .filter(|s| !s.starts_with("in "))
        .flat_map(|s| s.split(", "));
    let prepared_itself = own.clone().any(|w| {
        use Category::*;
        w == prepared
            || matches!(
                category(w),
                Cut | FinelyCut | Ground | Liquid | Mixed | Shaped | Preserved
            )
    });
    // motion i leads from state i, which is the food itself until it is "in" something
    let cut = line.motion.iter().zip(&line.state).any(|(m, s)| {
        !s.physical_state.starts_with("in ") && foods::motion_words(m).any(|w| CUTTING.contains(&w))
    });
    let broken = line
        .motion
        .iter()
        .any(|m| foods::motion_words(m).any(|w| BREAKING_DOWN.contains(&w)));
    prepared_itself || cut || broken
}
