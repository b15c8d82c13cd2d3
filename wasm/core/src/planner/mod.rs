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
    DishClassRef, IngredientOutcome, Plan, PlanRequest, Query, QueryIngredient, RetrievalMode,
    FORMAT_VERSION,
};
use crate::error::{ErrorCode, FoonError, Result};
use crate::foon::kb::KnowledgeBase;
use crate::foon::label::{normalize_label, normalize_word};
use crate::foon::model::NodeId;
use crate::limits;
use crate::robot::{robot_view, Motions};
use crate::similarity::Similarity;
use crate::vocab::foods;
use crate::vocab::taxonomy::{dish_class_name, dish_class_of};
use rustc_hash::FxHashMap as HashMap;
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
    let readings = crate::vocab::foods::query_readings(&query);
    let setting = Setting {
        kb,
        index,
        similarity,
        scorer: &scorer,
        class,
        overrides: &overrides,
        readings: &readings,
        request,
        motions: motions.as_ref(),
    };
    let (chosen, made) = reference_for(&setting, &query, chosen, &trace, &mut notes);
    let Modified {
        tree,
        schedule: scheduled,
        outcomes,
        removed,
        notes: made_notes,
        ..
    } = made;
    notes.extend(made_notes);
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
        readings: &readings,
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
        alg2_retrieve::retrieve_explained(kb, index, scorer, root.0, root.1, |_| true, trace)
            .unwrap_or_default()
    });
    for &n in &reference.blocked {
        notes.push(format!(
            "every unit making '{}' needs it again (a cycle): taken as available",
            kb.nodes[n]
        ));
    }
    reference
}

/// What planning with one reference goal needs besides the goal: the knowledge base, the similarity,
/// the query's settings.
struct Setting<'a> {
    kb: &'a KnowledgeBase,
    index: &'a PlannerIndex,
    similarity: &'a dyn Similarity,
    scorer: &'a score::Scorer<'a>,
    class: Option<u32>,
    overrides: &'a BTreeMap<String, String>,
    readings: &'a HashMap<String, &'static str>,
    request: &'a PlanRequest,
    motions: Option<&'a Motions<'a>>,
}

/// A reference task tree (Alg. 2) modified for the query (Table I, pruning) and scheduled.
struct Modified<'kb> {
    tree: tree::Tree<'kb>,
    schedule: schedule::Schedule,
    outcomes: Vec<IngredientOutcome>,
    removed: Vec<String>,
    notes: Vec<String>,
    /// Units of the reference task tree, and how many of them the plan keeps.
    reference_units: usize,
    kept: usize,
}

impl Modified<'_> {
    /// Whether the plan keeps next to nothing of the reference task tree (at most two of its units, of
    /// many): the plan is then mostly the ingredients' own branches joined at the dish. `npm run eval`
    /// counts such plans the same way (`reference_units` in `src/eval/coverage.ts`).
    fn little_kept(&self) -> bool {
        self.kept <= 2 && self.reference_units >= 6
    }
}

/// The reference task tree of `chosen`, modified for the query when the request asks, and scheduled.
fn modified<'a>(
    s: &Setting<'a>,
    query: &Query,
    chosen: &alg1_goal::Chosen<'a>,
    trace: &'a explain::Recorder,
) -> Modified<'a> {
    let mut notes = Vec::new();
    let goal_subgraph = s.index.subgraph_id(&chosen.goal.subgraph);
    let root = (chosen.goal.node, goal_subgraph);
    let mode = s.request.robot.as_ref().map(|o| o.mode).zip(s.motions);
    let reference = reference_tree(s.kb, s.index, s.scorer, root, mode, trace, &mut notes);
    let mut tree = tree::Tree::from_retrieved(s.kb, &reference, chosen.goal.node);
    let ctx = modify::Context {
        kb: s.kb,
        index: s.index,
        sim: s.similarity,
        class: s.class,
        overrides: s.overrides,
        goal_subgraph,
        scorer: s.scorer,
        trace,
        readings: s.readings,
    };
    let modify = s.request.modify;
    let (mut outcomes, removed) = modify::modify(&ctx, &mut tree, query, modify, &mut notes);
    let (values, order) = tree.drop_redundant_units();
    let schedule = schedule::schedule(&mut tree, &values, order);
    if modify {
        schedule::confirm_planned(&tree, &schedule.order, &mut outcomes);
    }
    let mut made = Modified {
        kept: kept_units(&tree, &schedule.order),
        reference_units: reference.units.len(),
        tree,
        schedule,
        outcomes,
        removed,
        notes,
    };
    if modify && made.little_kept() {
        made.notes.push(format!(
            "little of the reference task tree fits this query: {} of its {} units kept ('{}'); the \
             rest are the ingredients' own branches. The knowledge base may have no recipe of this dish \
             type like it",
            made.kept, made.reference_units, chosen.goal.subgraph
        ));
    }
    made
}

/// The units of the reference task tree a plan keeps (as they were, renamed, or with an ingredient
/// attached).
fn kept_units(tree: &tree::Tree, order: &[tree::TUnitId]) -> usize {
    use crate::contract::plan::Origin::{Attached, Reference, Renamed};
    let kept =
        |&&u: &&tree::TUnitId| matches!(tree.units[u].origin, Reference | Renamed | Attached);
    order.iter().filter(kept).count()
}

/// The tree of Alg. 1's best goal `chosen` modified for the query, or, where the query keeps next to
/// nothing of it, that of the runner-up whose tree it keeps more of (`fuller_reference`), with a note;
/// the trace then starts again from the runner-up.
fn reference_for<'a>(
    s: &Setting<'a>,
    query: &Query,
    chosen: alg1_goal::Chosen<'a>,
    trace: &'a explain::Recorder,
    notes: &mut Vec<String>,
) -> (alg1_goal::Chosen<'a>, Modified<'a>) {
    let made = modified(s, query, &chosen, trace);
    let Some(fuller) = fuller_reference(s, query, &chosen, &made) else {
        return (chosen, made);
    };
    notes.push(format!(
        "Alg. 1's best goal ('{}') keeps {} of its {} units for this query: started from '{}' \
         (similarity {:.2}), the next candidate whose tree the query uses",
        chosen.goal.subgraph, made.kept, made.reference_units, fuller.goal.subgraph, fuller.score
    ));
    trace.restart_with_goal(
        &s.kb.nodes[fuller.goal.node].to_string(),
        &fuller.goal.subgraph,
    );
    let made = modified(s, query, &fuller, trace);
    (fuller, made)
}

/// Where the query keeps next to nothing of the tree of Alg. 1's best goal (`Modified::little_kept`),
/// the first of the next candidates (at most `RUNNERS_UP`, scoring at most `FULLER_WITHIN` less) whose
/// tree it keeps more of. Planned without the trace.
fn fuller_reference<'kb>(
    s: &Setting<'kb>,
    query: &Query,
    chosen: &alg1_goal::Chosen<'kb>,
    made: &Modified,
) -> Option<alg1_goal::Chosen<'kb>> {
    if !s.request.modify || !made.little_kept() {
        return None;
    }
    let runners = alg1_goal::runners_up(s.kb, s.index, s.scorer, s.class, query, chosen);
    runners
        .into_iter()
        .filter(|c| c.score >= chosen.score - FULLER_WITHIN)
        .take(RUNNERS_UP)
        .find(|c| {
            let off = explain::Recorder::OFF;
            !modified(s, query, c, &off).little_kept()
        })
}

/// How many runners-up of Alg. 1 are tried when its best goal's tree is kept next to nothing of.
const RUNNERS_UP: usize = 3;
/// How much less than Alg. 1's best goal a runner-up tried instead may score.
const FULLER_WITHIN: f32 = 0.1;

/// `what` is written only for the error (every ingredient is checked; its name is a `format!`).
fn check_length(text: &str, what: impl FnOnce() -> String) -> Result<()> {
    let most = limits::MAX_LABEL_CHARS;
    if text.chars().count() > most {
        let message = format!("{} is longer than {most} characters", what());
        return Err(FoonError::bad_query(message));
    }
    Ok(())
}

/// Normal forms of names and states; identical ingredients removed with a note.
fn prepare_query(q: &Query, notes: &mut Vec<String>) -> Result<Query> {
    check_length(&q.dish_type, || "the dish type".into())?;
    if q.ingredients.is_empty() {
        return Err(FoonError::bad_query("the query has no ingredients"));
    }
    let (count, most) = (q.ingredients.len(), limits::MAX_QUERY_INGREDIENTS);
    if count > most {
        let message = format!("the query has {count} ingredients; the limit is {most}");
        return Err(FoonError::new(ErrorCode::TooLarge, message));
    }
    // each distinct ingredient with how often it is listed
    let mut listed: Vec<(QueryIngredient, usize)> = Vec::with_capacity(count);
    for (i, ing) in q.ingredients.iter().enumerate() {
        let item = prepare_ingredient(i + 1, ing)?;
        match listed.iter_mut().find(|(o, _)| *o == item) {
            Some((_, n)) => *n += 1,
            None => listed.push((item, 1)),
        }
    }
    name_each_food(&mut listed, notes);
    // one note per ingredient listed more than once, however often
    for (item, n) in listed.iter().filter(|(_, n)| *n > 1) {
        let (object, state) = (&item.object, &item.state);
        notes.push(format!(
            "duplicate ingredient '{object} ({state})' listed {n} times, planned once"
        ));
    }
    Ok(Query {
        id: q.id.clone(),
        dish_type: normalize_word(&q.dish_type),
        ingredients: listed.into_iter().map(|(item, _)| item).collect(),
    })
}

/// A name asked in states read as different foods (pepper "diced", a bell pepper, and "ground", black
/// pepper) names two foods, and each gets its own line: the plain food (read as nothing else) keeps the
/// name, else its first entry does; every other entry takes the name of the food its state reads as.
fn name_each_food(listed: &mut [(QueryIngredient, usize)], notes: &mut Vec<String>) {
    let read = |i: &QueryIngredient| foods::reading(&i.object, &i.state);
    for k in 0..listed.len() {
        let item = &listed[k].0;
        let Some(food) = read(item) else { continue };
        let same_name = || listed.iter().filter(|(i, _)| i.object == item.object);
        let keeper = same_name()
            .find(|(i, _)| read(i).is_none())
            .or_else(|| same_name().next())
            .map(|(i, _)| read(i));
        if keeper.is_some_and(|r| r != Some(food)) {
            notes.push(format!(
                "'{}' is asked as more than one food: '{}' ({}) is planned as '{food}'",
                item.object, item.object, item.state
            ));
            listed[k].0.object = food.to_string();
        }
    }
}

/// Characters a FOON label or state cannot hold.
const NOT_IN_FOON: [char; 7] = ['{', '}', '[', ']', ',', '\t', '\n'];

/// Query ingredient number `n` in normal form.
fn prepare_ingredient(n: usize, ing: &QueryIngredient) -> Result<QueryIngredient> {
    check_length(&ing.object, || format!("ingredient {n} object"))?;
    check_length(&ing.state, || format!("ingredient {n} state"))?;
    let object = normalize_label(&ing.object);
    let state = normalize_word(&ing.state);
    let why = if object.is_empty() {
        format!("ingredient {n} has an empty object name")
    } else if object.contains(NOT_IN_FOON) {
        format!("ingredient {n} ('{object}') has a character not allowed in a FOON label")
    } else if state.contains(NOT_IN_FOON) {
        format!("ingredient {n} state ('{state}') has a character not allowed in a FOON state")
    } else {
        return Ok(QueryIngredient { object, state });
    };
    Err(FoonError::bad_query(why))
}

fn prepare_overrides(o: &BTreeMap<String, String>) -> Result<BTreeMap<String, String>> {
    let mut out = BTreeMap::new();
    for (k, v) in o {
        check_length(k, || "an override".into())?;
        check_length(v, || "an override".into())?;
        let (k, v) = (normalize_label(k), normalize_label(v));
        if k.is_empty() || v.is_empty() {
            return Err(FoonError::bad_query("an override has an empty name"));
        }
        out.insert(k, v);
    }
    Ok(out)
}
