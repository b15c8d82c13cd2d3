//! The state-transition model, mined from the knowledge base's own functional units: for each physical
//! form of food (`foods::form_of`: powder, liquid, fat, produce, ...), which motion brings a food of that
//! form into which state. The planner gives a food only transitions some recipe makes for a food of its
//! form: butter is softened the way FOON softens butter, not blended because a blender softens
//! vegetables; a substitute's branch is demoted when it handles the asked food in a way no recipe
//! handles a food of that form.

use crate::foon::kb::KnowledgeBase;
use crate::foon::model::ObjectNode;
use crate::vocab::foods;
use crate::vocab::taxonomy::is_utensil;
use rustc_hash::FxHashMap as HashMap;

use crate::vocab::states::{akin, is_food_state};

/// Below this many transitions of a form the model says nothing of it (too few recipes to tell).
const MIN_EVIDENCE: u32 = 20;

/// What the model says of a transition.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verdict {
    /// Some recipe makes it for a food of this form.
    Seen,
    /// The knowledge base knows foods of this form well, and none is handled so.
    Unseen,
    /// The food's form is unknown, or too rare in the knowledge base to tell.
    Unknown,
}

#[derive(Clone, Debug, Default)]
pub struct Transitions {
    /// (form, motion, state reached) -> occurrences; "" as the state when the motion only moves it.
    reached: HashMap<(&'static str, String, String), u32>,
    /// (form, motion) -> occurrences.
    handled: HashMap<(&'static str, String), u32>,
    /// form -> transitions seen of it.
    evidence: HashMap<&'static str, u32>,
}

impl Transitions {
    /// Every unit's input food and its output of the same label: the motion, and each food state the
    /// output gains (or none: it was moved).
    pub fn mine(kb: &KnowledgeBase) -> Transitions {
        let mut t = Transitions::default();
        for u in &kb.units {
            for i in &u.inputs {
                let before = &kb.nodes[i.node];
                let Some(form) = food_form(before) else {
                    continue;
                };
                let after = u
                    .outputs
                    .iter()
                    .map(|o| &kb.nodes[o.node])
                    .filter(|o| o.label == before.label);
                for out in after {
                    let gained = out
                        .physical_states()
                        .filter(|s| is_food_state(s) && !before.physical_states().any(|b| b == *s));
                    t.record(form, &u.motion, gained);
                }
            }
        }
        t
    }

    fn record<'s>(
        &mut self,
        form: &'static str,
        motion: &str,
        gained: impl Iterator<Item = &'s str>,
    ) {
        *self.handled.entry((form, motion.to_string())).or_insert(0) += 1;
        *self.evidence.entry(form).or_insert(0) += 1;
        let mut gained: Vec<String> = gained.map(str::to_string).collect();
        if gained.is_empty() {
            gained.push(String::new()); // moved only
        }
        for s in gained {
            *self
                .reached
                .entry((form, motion.to_string(), s))
                .or_insert(0) += 1;
        }
    }

    /// The form the model judges `food` by, when it knows enough of it.
    fn known_form(&self, food: &str) -> Option<&'static str> {
        let form = foods::form_of(food)?.name.as_str();
        (self.evidence.get(form).copied().unwrap_or(0) >= MIN_EVIDENCE).then_some(form)
    }

    /// Whether some recipe brings a food of `food`'s form into `state` by `motion` ("" as the state:
    /// handles it by `motion` at all).
    pub fn makes(&self, food: &str, motion: &str, state: &str) -> Verdict {
        let Some(form) = self.known_form(food) else {
            return Verdict::Unknown;
        };
        let seen = if state.is_empty() {
            self.handled.contains_key(&(form, motion.to_string()))
        } else {
            self.reached
                .contains_key(&(form, motion.to_string(), state.to_string()))
        };
        if seen {
            Verdict::Seen
        } else {
            Verdict::Unseen
        }
    }

    /// The motion most used to bring a food of `food`'s form into `state`, else into a state that says
    /// the same of it (cheese is grated, not shredded, in FOON); `None` when the form is unknown or no
    /// recipe does either.
    pub fn motion_for(&self, food: &str, state: &str) -> Option<&str> {
        let form = self.known_form(food)?;
        let most_used = |same: &dyn Fn(&str) -> bool| {
            self.reached
                .iter()
                .filter(|((f, _, s), _)| *f == form && same(s))
                .max_by(|a, b| a.1.cmp(b.1).then_with(|| b.0 .1.cmp(&a.0 .1)))
                .map(|((_, m, _), _)| m.as_str())
        };
        most_used(&|s| s == state).or_else(|| most_used(&|s| !s.is_empty() && akin(s, state)))
    }

    /// Whether the model knows `food`'s form well enough to judge it.
    pub fn judges(&self, food: &str) -> bool {
        self.known_form(food).is_some()
    }
}

/// The form of a node's food; `None` for utensils and foods of unknown form.
fn food_form(node: &ObjectNode) -> Option<&'static str> {
    if is_utensil(&node.label) {
        return None;
    }
    foods::form_of(&node.label).map(|f| f.name.as_str())
}
