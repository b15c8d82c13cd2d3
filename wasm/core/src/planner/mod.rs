//! Approximate task-tree retrieval (section III of Sakib, Paulius, Sun, RA-L 2022): a reference goal
//! node (Alg. 1), its task tree (Alg. 2), and the modification of that tree for the query's ingredients
//! (Table I), followed by pruning, progress lines and recipe-like steps.

mod alg1_goal;
mod alg2_retrieve;
mod cautions;
mod check;
mod explain;
mod index;
mod modify;
mod optimal;
mod output;
mod schedule;
mod score;
mod transitions;
mod tree;

pub use crate::contract::plan::{Caution, CautionKind};
pub use cautions::cautions;
pub use check::{available_at_start, violations};
pub use index::PlannerIndex;
pub use transitions::{Transitions, Verdict};

use crate::contract::plan::{
    DishClassRef, Plan, PlanRequest, Query, QueryIngredient, RetrievalMode, FORMAT_VERSION,
};
use crate::error::{ErrorCode, FoonError, Result};
use crate::foon::kb::KnowledgeBase;
use crate::foon::label::{normalize_label, normalize_word};
use crate::foon::model::NodeId;
use crate::limits;
use crate::robot::{robot_view, Motions};
use crate::similarity::Similarity;
use crate::vocab::taxonomy::{dish_class_name, dish_class_of};
use std::collections::BTreeMap;

/// Plans a query against a knowledge base. `index` must have been built from the same `kb`
/// (`PlannerIndex::new(kb)`, once). Never panics; a malformed request is `ErrorCode::BadQuery`, a knowledge
/// base without a usable goal node `ErrorCode::NoGoal`.
pub fn plan(
    kb: &KnowledgeBase,
    index: &PlannerIndex,
    similarity: &dyn Similarity,
    request: &PlanRequest,
) -> Result<Plan> {
    let mut notes = Vec::new();
    let query = prepare_query(&request.query, &mut notes)?;
    let overrides = prepare_overrides(&request.overrides)?;
    let class = dish_class_of(&query.dish_type);
    let mut labels: Vec<String> = Vec::new();
    for i in &query.ingredients {
        if !labels.contains(&i.object) {
            labels.push(i.object.clone());
        }
    }
    let motions = request.robot.as_ref().map(Motions::new).transpose()?;
    let scorer = score::Scorer::new(similarity, index, &labels);
    let trace = explain::Recorder::new(request.explain);
    let no_goal = "the knowledge base has no goal node with a functional unit that makes it";
    let chosen = alg1_goal::select(kb, index, &scorer, class, &mut notes, &query, &trace)
        .ok_or_else(|| FoonError::new(ErrorCode::NoGoal, no_goal))?;
    let goal_subgraph = index.subgraph_id(&chosen.goal.subgraph);
    let root = (chosen.goal.node, goal_subgraph);
    let mode = request.robot.as_ref().map(|o| o.mode).zip(motions.as_ref());
    let reference = reference_tree(kb, index, &scorer, root, mode, &trace, &mut notes);
    let mut tree = tree::Tree::from_retrieved(kb, &reference, chosen.goal.node);
    let ctx = modify::Context {
        kb,
        index,
        sim: similarity,
        class,
        overrides: &overrides,
        goal_subgraph,
        scorer: &scorer,
        trace: &trace,
        readings: crate::vocab::foods::query_readings(&query),
    };
    let (mut outcomes, removed) =
        modify::modify(&ctx, &mut tree, &query, request.modify, &mut notes);
    let (values, order) = tree.drop_redundant_units();
    let scheduled = schedule::schedule(&mut tree, &values, order);
    if request.modify {
        schedule::confirm_planned(&tree, &scheduled.order, &mut outcomes);
        note_little_kept(
            &tree,
            &scheduled.order,
            reference.units.len(),
            &chosen.goal.subgraph,
            &mut notes,
        );
    }
    trace.record(|t| t.outcomes(&outcomes, |o| index.is_label(o)));
    let dish_class = class.and_then(|index| {
        let name = dish_class_name(index)?.to_string();
        Some(DishClassRef { index, name })
    });
    let mut plan = output::build(output::Parts {
        kb,
        tree: &tree,
        order: &scheduled.order,
        nodes: &scheduled.nodes,
        query,
        dish_class,
        notes,
        modified: request.modify,
        goal: chosen.goal,
        score: chosen.score,
        outcomes,
        removed,
        format_version: FORMAT_VERSION,
        readings: &ctx.readings,
    });
    plan.cautions = cautions::cautions(&plan);
    plan.trace = trace.finish();
    plan.robot = request
        .robot
        .as_ref()
        .zip(motions.as_ref())
        .map(|(o, m)| robot_view(&plan, o, m));
    Ok(plan)
}

/// Alg. 2's reference task tree of the goal `root` (node, subgraph), or the tree of a robot's retrieval
/// mode; a note for each node taken as available to break a cycle.
fn reference_tree(
    kb: &KnowledgeBase,
    index: &PlannerIndex,
    scorer: &score::Scorer,
    root: (NodeId, Option<u32>),
    mode: Option<(RetrievalMode, &Motions)>,
    trace: &explain::Recorder,
    notes: &mut Vec<String>,
) -> alg2_retrieve::Retrieved {
    let in_mode = mode.and_then(|(mode, m)| {
        optimal::retrieve_in_mode(kb, index, scorer, root, mode, m, trace, notes)
    });
    let reference = in_mode.unwrap_or_else(|| {
        alg2_retrieve::retrieve_explained(kb, index, scorer, root.0, root.1, trace)
    });
    for &n in &reference.blocked {
        notes.push(format!(
            "every unit making '{}' needs it again (a cycle): taken as available",
            kb.nodes[n]
        ));
    }
    reference
}

/// Says so when the plan keeps next to nothing of the reference task tree (at most two of its units,
/// of many): the knowledge base then has no recipe of the dish type like the query, and the plan is mostly
/// the ingredients' own branches joined at the dish. `npm run eval` counts such plans the same way
/// (`reference_units` in `src/eval/coverage.ts`).
fn note_little_kept(
    tree: &tree::Tree,
    order: &[tree::TUnitId],
    reference_units: usize,
    subgraph: &str,
    notes: &mut Vec<String>,
) {
    use crate::contract::plan::Origin;
    let kept = order
        .iter()
        .filter(|&&u| {
            let origin = tree.units[u].origin;
            matches!(
                origin,
                Origin::Reference | Origin::Renamed | Origin::Attached
            )
        })
        .count();
    if kept <= 2 && reference_units >= 6 {
        notes.push(format!(
            "little of the reference task tree fits this query: {kept} of its {reference_units} units \
             kept ('{subgraph}'); the rest are the ingredients' own branches. The knowledge base may \
             have no recipe of this dish type like it"
        ));
    }
}

fn bad(message: String) -> FoonError {
    FoonError::new(ErrorCode::BadQuery, message)
}

/// `what` is written only for the error (every ingredient is checked; its name is a `format!`).
fn check_length(text: &str, what: impl FnOnce() -> String) -> Result<()> {
    if text.chars().count() > limits::MAX_LABEL_CHARS {
        return Err(bad(format!(
            "{} is longer than {} characters",
            what(),
            limits::MAX_LABEL_CHARS
        )));
    }
    Ok(())
}

/// Normal forms of names and states; identical ingredients removed with a note.
fn prepare_query(q: &Query, notes: &mut Vec<String>) -> Result<Query> {
    check_length(&q.dish_type, || "the dish type".into())?;
    if q.ingredients.is_empty() {
        return Err(bad("the query has no ingredients".into()));
    }
    if q.ingredients.len() > limits::MAX_QUERY_INGREDIENTS {
        return Err(FoonError::new(
            ErrorCode::TooLarge,
            format!(
                "the query has {} ingredients; the limit is {}",
                q.ingredients.len(),
                limits::MAX_QUERY_INGREDIENTS
            ),
        ));
    }
    let mut out: Vec<QueryIngredient> = Vec::with_capacity(q.ingredients.len());
    // how often each of `out` is listed
    let mut listed: Vec<usize> = Vec::with_capacity(q.ingredients.len());
    for (i, ing) in q.ingredients.iter().enumerate() {
        check_length(&ing.object, || format!("ingredient {} object", i + 1))?;
        check_length(&ing.state, || format!("ingredient {} state", i + 1))?;
        let object = normalize_label(&ing.object);
        if object.is_empty() {
            return Err(bad(format!(
                "ingredient {} has an empty object name",
                i + 1
            )));
        }
        if object.contains(['{', '}', '[', ']', ',', '\t', '\n']) {
            return Err(bad(format!(
                "ingredient {} ('{object}') has a character not allowed in a FOON label",
                i + 1
            )));
        }
        let state = normalize_word(&ing.state);
        if state.contains(['{', '}', '[', ']', ',', '\t', '\n']) {
            return Err(bad(format!(
                "ingredient {} state ('{state}') has a character not allowed in a FOON state",
                i + 1
            )));
        }
        let item = QueryIngredient { object, state };
        match out.iter().position(|o| *o == item) {
            Some(k) => listed[k] += 1,
            None => {
                out.push(item);
                listed.push(1);
            }
        }
    }
    // one note per ingredient listed more than once, however often
    for (item, &n) in out.iter().zip(&listed).filter(|(_, &n)| n > 1) {
        notes.push(format!(
            "duplicate ingredient '{} ({})' listed {n} times, planned once",
            item.object, item.state
        ));
    }
    Ok(Query {
        id: q.id.clone(),
        dish_type: normalize_word(&q.dish_type),
        ingredients: out,
    })
}

fn prepare_overrides(o: &BTreeMap<String, String>) -> Result<BTreeMap<String, String>> {
    let mut out = BTreeMap::new();
    for (k, v) in o {
        check_length(k, || "an override".into())?;
        check_length(v, || "an override".into())?;
        let (k, v) = (normalize_label(k), normalize_label(v));
        if k.is_empty() || v.is_empty() {
            return Err(bad("an override has an empty name".into()));
        }
        out.insert(k, v);
    }
    Ok(out)
}
