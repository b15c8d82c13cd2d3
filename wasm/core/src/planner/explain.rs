//! The recorder of the explain trace (`crate::trace`). Off, each hook is one `None` check and its
//! closure (where the texts are written) never runs, so that a plan costs what it did without it.

use super::modify::{food_states, Context};
use super::tree::Tree;
use crate::contract::plan::{IngredientOutcome, Status};
use crate::foon::kb::KnowledgeBase;
use crate::foon::model::{NodeId, UnitId};
use crate::trace::{
    Attachment, IngredientTrace, NameMatch, StateChoice, Trace, TraceUnit, TRACE_VERSION,
};
use std::cell::RefCell;

pub(crate) struct Recorder(Option<RefCell<Trace>>);

impl Recorder {
    pub const OFF: Recorder = Recorder(None);

    pub fn new(on: bool) -> Recorder {
        Recorder(on.then(|| {
            RefCell::new(Trace {
                trace_version: TRACE_VERSION,
                ..Trace::default()
            })
        }))
    }

    /// Runs `f` on the trace when recording.
    #[inline]
    pub fn record(&self, f: impl FnOnce(&mut Trace)) {
        if let Some(t) = &self.0 {
            f(&mut t.borrow_mut());
        }
    }

    /// Starts the trace again from Alg. 1's choice, which is now the candidate `node` of `subgraph`
    /// (the best goal's tree was kept next to nothing of): it leads the candidates, and what was
    /// recorded of the best goal's retrieval and modification is forgotten.
    pub fn restart_with_goal(&self, node: &str, subgraph: &str) {
        self.record(|t| {
            let g = &mut t.goal_selection;
            let at = (g.candidates.iter()).position(|c| c.node == node && c.subgraph == subgraph);
            if let Some(at) = at {
                g.candidates[..=at].rotate_right(1);
            }
            g.tie_break = Some("fuller_tree".to_string());
            *t = Trace {
                trace_version: t.trace_version,
                goal_selection: std::mem::take(&mut t.goal_selection),
                ..Trace::default()
            };
        });
    }

    pub fn finish(self) -> Option<Trace> {
        self.0.map(RefCell::into_inner)
    }
}

/// A knowledge-base unit as FOON texts.
pub(crate) fn kb_unit(kb: &KnowledgeBase, u: UnitId) -> TraceUnit {
    let unit = &kb.units[u];
    let text = |n: NodeId| kb.nodes[n].to_string();
    TraceUnit {
        inputs: unit.input_nodes().map(text).collect(),
        motion: unit.motion.clone(),
        outputs: unit.output_nodes().map(text).collect(),
    }
}

/// The tree's unit `u` as FOON texts.
fn tree_unit(tree: &Tree, u: usize) -> TraceUnit {
    let unit = &tree.units[u];
    let text = |x: &(usize, bool)| tree.slots[x.0].node.to_string();
    TraceUnit {
        inputs: unit.inputs.iter().map(text).collect(),
        motion: unit.motion.to_string(),
        outputs: unit.outputs.iter().map(text).collect(),
    }
}

fn name_match(m: Option<&(String, f32)>) -> Option<NameMatch> {
    m.map(|(label, similarity)| NameMatch {
        label: label.clone(),
        similarity: *similarity,
    })
}

impl Trace {
    /// The record of query ingredient `object` in `state` (`None`: any state), made on first use
    /// (modification visits an ingredient again when its branch comes from the universal FOON). A record
    /// made before its state was known takes the first state asked; one object in two states has two,
    /// with the same equivalents.
    fn ingredient(&mut self, object: &str, state: Option<&str>) -> &mut IngredientTrace {
        let same = |i: &IngredientTrace| i.object == object;
        let found = match state {
            None => self.ingredients.iter().position(same),
            Some(s) => (self.ingredients.iter())
                .position(|i| same(i) && i.state == s)
                .or_else(|| (self.ingredients.iter()).position(|i| same(i) && i.state.is_empty())),
        };
        let at = found.unwrap_or_else(|| {
            let matched = self.ingredients.iter().find(|i| same(i));
            let record = IngredientTrace {
                object: object.to_string(),
                tree_match: matched.and_then(|m| m.tree_match.clone()),
                foon_match: matched.and_then(|m| m.foon_match.clone()),
                ..IngredientTrace::default()
            };
            self.ingredients.push(record);
            self.ingredients.len() - 1
        });
        let record = &mut self.ingredients[at];
        if let Some(s) = state {
            record.state = s.to_string();
        }
        record
    }

    /// The best equivalents of `object` in the reference tree and in the universal FOON.
    pub(crate) fn equivalents(
        &mut self,
        object: &str,
        tree: Option<&(String, f32)>,
        foon: Option<&(String, f32)>,
    ) {
        let i = self.ingredient(object, None);
        i.tree_match = name_match(tree);
        i.foon_match = name_match(foon);
    }

    /// The node the state taxonomy chose for a branch from the universal FOON (`None`: as bought), for
    /// the query's `asked` state; `state` is the one searched for (a whole cucumber: sliced).
    pub(crate) fn state_choice(
        &mut self,
        ctx: &Context,
        (object, asked): (&str, &str),
        eq: &str,
        state: &str,
        node: Option<(NodeId, bool)>,
    ) {
        let kb = ctx.kb;
        let food: Vec<&str> = node.map_or_else(Vec::new, |(n, _)| food_states(&kb.nodes[n]));
        let frequency = ctx.index.state_frequency(ctx.class, eq, &food);
        self.ingredient(object, Some(asked)).state_choice = Some(StateChoice {
            node: node.map(|(n, _)| kb.nodes[n].to_string()),
            category: crate::vocab::states::category(state).name().to_string(),
            in_state: node.is_some_and(|(_, s)| s),
            frequency_in_class: frequency.0,
            frequency_overall: frequency.1,
        });
    }

    /// The unit a branch from the universal FOON joins, and the dish-type pattern that chose it.
    pub(crate) fn attached(&mut self, object: &str, state: &str, motion: &str, pattern: &[&str]) {
        self.ingredient(object, Some(state)).attached = Some(Attachment {
            motion: motion.to_string(),
            pattern: pattern.iter().map(|m| m.to_string()).collect(),
            rank: pattern.iter().position(|m| motion.contains(m)),
        });
    }

    /// The tree's live units before pruning (`pruned_from` keeps the ones that went).
    pub(crate) fn before_pruning(&mut self, tree: &Tree) {
        let alive = tree.alive_units().map(|(u, _)| (u, tree_unit(tree, u)));
        self.pruning.alive_before = alive.collect();
    }

    /// The units, of those alive before pruning, that pruning removed, as they were.
    pub(crate) fn pruned_from(&mut self, tree: &Tree, removed: &[String]) {
        let before = std::mem::take(&mut self.pruning.alive_before);
        self.pruning.units = before
            .into_iter()
            .filter(|(u, _)| !tree.units[*u].alive)
            .map(|(_, unit)| unit)
            .collect();
        self.pruning.removed = removed.to_vec();
    }

    /// Fills each ingredient's case, status, reason and route from its outcome, in query order.
    pub(crate) fn outcomes(
        &mut self,
        outcomes: &[IngredientOutcome],
        is_label: impl Fn(&str) -> bool,
    ) {
        let ordered = outcomes.iter().map(|o| {
            let mut i = self.ingredient(&o.object, Some(&o.state)).clone();
            i.case = o.case;
            i.planned = o.status == Status::Planned;
            i.reason = o.reason.clone();
            i.route = route(o, &i, is_label(&o.object)).to_string();
            i
        });
        self.ingredients = ordered.collect();
    }
}

/// How the equivalent of an ingredient was found (see `IngredientTrace`).
fn route(o: &IngredientOutcome, i: &IngredientTrace, is_label: bool) -> &'static str {
    let Some(m) = &o.matched else {
        return "none";
    };
    if o.overridden {
        "override"
    } else if is_label {
        "exact"
    } else if i.tree_match.as_ref().is_some_and(|t| t.label == m.label) {
        "tree"
    } else {
        "foon"
    }
}
