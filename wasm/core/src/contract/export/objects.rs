//! The objects of a plan for PDDL (`docs/pddl.md`). FOON names an object node by its label and states, so
//! two bowls of one recipe are the same label; PDDL needs each physical object once. Following the plan in
//! its order, each input is the object that is in that node now (the one put there last), or a new one
//! from the kitchen; each output continues an input object of its label, or is a new object. Each unit
//! then needs its input objects exactly as its nodes say (the facts of the node, and none of the other
//! facts the object ever has) and leaves its output objects exactly as theirs say, so a planner can
//! neither skip a unit nor take one before the units making its inputs.

use crate::contract::plan::{Plan, PlanNode, PlanUnit};
use crate::vocab::taxonomy::is_utensil;
use std::collections::{BTreeMap, BTreeSet};

/// A PDDL name: lower-case letters, digits and dashes, starting with a letter, never a reserved word.
pub(super) fn ident(text: &str) -> String {
    let mut out = String::new();
    for c in text.chars() {
        if c.is_ascii_alphanumeric() {
            out.push(c.to_ascii_lowercase());
        } else if !out.is_empty() && !out.ends_with('-') {
            out.push('-');
        }
    }
    while out.ends_with('-') {
        out.pop();
    }
    if !out.starts_with(|c: char| c.is_ascii_alphabetic()) || RESERVED.contains(&out.as_str()) {
        out.insert_str(0, "x-");
    }
    out
}

/// Words PDDL reserves; a name equal to one gets a prefix.
const RESERVED: &[&str] = &[
    "and", "at", "define", "domain", "either", "exists", "forall", "imply", "not", "object", "or",
    "problem", "when",
];

/// A ground fact about one object: `(available tomato)`, `(is-chopped tomato)`, `(in tomato bowl)`.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(super) struct Fact {
    pub predicate: String,
    pub object: String,
    /// The name of a relation's other end (`in [bowl]`, `contains {tomato}`): a label, not an object.
    pub other: Option<String>,
}

impl Fact {
    pub fn text(&self) -> String {
        match &self.other {
            Some(o) => format!("({} {} {o})", self.predicate, self.object),
            None => format!("({} {})", self.predicate, self.object),
        }
    }
}

/// The facts of `object` in node `n`: it is available, and each of its states, a relation to each name in
/// brackets or braces (`in [bowl]` -> `(in o bowl)`, `contains {a,b}` -> two facts) or else a property
/// (`chopped` -> `(is-chopped o)`).
pub(super) fn facts(object: &str, n: &PlanNode) -> BTreeSet<Fact> {
    let fact = |predicate: String, other: Option<String>| Fact {
        predicate,
        object: object.to_string(),
        other,
    };
    let mut out = BTreeSet::from([fact("available".into(), None)]);
    for s in &n.states {
        match relation(s) {
            Some((rel, names)) => {
                let predicate = ident(rel);
                out.extend(names.map(|o| fact(predicate.clone(), Some(ident(o)))));
            }
            None => {
                out.insert(fact(format!("is-{}", ident(s)), None));
            }
        }
    }
    out
}

/// `in [bowl]` -> ("in", ["bowl"]); `contains {a,b}` -> ("contains", ["a", "b"]); else None.
fn relation(state: &str) -> Option<(&str, impl Iterator<Item = &str>)> {
    let (open, close) = match state.chars().last()? {
        ']' => ('[', ']'),
        '}' => ('{', '}'),
        _ => return None,
    };
    let at = state.rfind(open)?;
    let rel = state[..at].trim();
    let inside = &state[at + 1..state.len() - close.len_utf8()];
    let names = inside.split(',').map(str::trim).filter(|s| !s.is_empty());
    (!rel.is_empty()).then_some((rel, names))
}

/// What a unit needs true (`pre`) and false (`pre_not`), makes true (`add`) and false (`del`).
#[derive(Default)]
pub(super) struct Action {
    pub pre: BTreeSet<Fact>,
    pub pre_not: BTreeSet<Fact>,
    pub add: BTreeSet<Fact>,
    pub del: BTreeSet<Fact>,
}

/// The plan as a PDDL task: objects, one action per unit, the kitchen and the goal.
pub(super) struct World {
    pub objects: Vec<String>,
    pub actions: Vec<Action>,
    pub init: BTreeSet<Fact>,
    /// The goal node's object exactly as the goal node says, and each object the plan touches as the plan
    /// leaves it (`States::goal`).
    pub goal: Action,
}

/// One physical object: its name and the node it is in now (None once used up).
struct Object<'p> {
    name: String,
    node: Option<&'p PlanNode>,
    /// The unit (1-based; 0 = the kitchen) that put it in `node`.
    since: usize,
}

/// Each unit's input and output objects, by index into the objects.
struct Step<'p> {
    inputs: Vec<(usize, &'p PlanNode)>,
    outputs: Vec<(usize, &'p PlanNode)>,
    used_up: Vec<usize>,
}

pub(super) fn world(plan: &Plan) -> World {
    let mut objects: Vec<Object> = Vec::new();
    let mut kitchen: Vec<(usize, &PlanNode)> = Vec::new();
    let mut steps: Vec<Step> = Vec::with_capacity(plan.units.len());
    for (j, u) in plan.units.iter().enumerate() {
        let step = follow(&mut objects, &mut kitchen, &mut steps, j + 1, u);
        steps.push(step);
    }
    let states = States::new(&objects, &kitchen, &steps);
    let actions = steps.iter().map(|s| states.action(s)).collect();
    let init = kitchen
        .iter()
        .flat_map(|&(k, n)| states.facts(k, n))
        .collect();
    let goal = states.goal(plan);
    World {
        objects: objects.into_iter().map(|o| o.name).collect(),
        actions,
        init,
        goal,
    }
}

impl Action {
    /// Needs what `other` needs too.
    fn require(&mut self, other: Action) {
        self.pre.extend(other.pre);
        self.pre_not.extend(other.pre_not);
    }
}

/// The objects' facts: in a node, and every fact each object ever has (for the exact states).
struct States<'w, 'p> {
    objects: &'w [Object<'p>],
    ever: BTreeMap<usize, BTreeSet<Fact>>,
}

impl<'w, 'p> States<'w, 'p> {
    fn new(objects: &'w [Object<'p>], kitchen: &[(usize, &PlanNode)], steps: &[Step]) -> Self {
        let mut ever: BTreeMap<usize, BTreeSet<Fact>> = BTreeMap::new();
        for &(k, n) in kitchen.iter().chain(steps.iter().flat_map(|s| &s.outputs)) {
            ever.entry(k)
                .or_default()
                .extend(facts(&objects[k].name, n));
        }
        States { objects, ever }
    }

    fn facts(&self, k: usize, n: &PlanNode) -> BTreeSet<Fact> {
        facts(&self.objects[k].name, n)
    }

    /// Object `k` exactly in node `n` (`None`: used up): its facts, and none of the others it ever has.
    fn exactly(&self, k: usize, n: Option<&PlanNode>) -> Action {
        let pre = n.map(|n| self.facts(k, n)).unwrap_or_default();
        let pre_not = self.ever[&k].difference(&pre).cloned().collect();
        Action {
            pre,
            pre_not,
            ..Action::default()
        }
    }

    /// A step's action: its inputs exactly; its outputs' facts added, and the facts an object left
    /// deleted; a used-up input's facts deleted.
    fn action(&self, s: &Step) -> Action {
        let mut a = Action::default();
        for &(k, n) in &s.inputs {
            a.require(self.exactly(k, Some(n)));
        }
        for &(k, o) in &s.outputs {
            let after = self.facts(k, o);
            if let Some(&(_, before)) = s.inputs.iter().find(|(i, _)| *i == k) {
                a.del
                    .extend(self.facts(k, before).difference(&after).cloned());
            }
            a.add.extend(after);
        }
        for &(k, n) in s.inputs.iter().filter(|(k, _)| s.used_up.contains(k)) {
            a.del.extend(self.facts(k, n));
        }
        a
    }

    /// The goal node's object exactly in the goal node, and every object a unit touched as the plan
    /// leaves it (a unit is in the plan for a reason).
    fn goal(&self, plan: &Plan) -> Action {
        let mut goal = Action::default();
        if let Some((k, n)) = goal_object(self.objects, plan) {
            goal.require(self.exactly(k, Some(n)));
        }
        for (k, o) in self.objects.iter().enumerate().filter(|(_, o)| o.since > 0) {
            goal.require(self.exactly(k, o.node));
        }
        goal
    }
}

/// Unit `u` (number `j`, 1-based) on the objects: which it takes, which it leaves in its outputs.
fn follow<'p>(
    objects: &mut Vec<Object<'p>>,
    kitchen: &mut Vec<(usize, &'p PlanNode)>,
    before: &mut [Step<'p>],
    j: usize,
    u: &'p PlanUnit,
) -> Step<'p> {
    let mut inputs: Vec<(usize, &PlanNode)> = Vec::new();
    for n in &u.inputs {
        let free = |k: &usize| !inputs.iter().any(|i| i.0 == *k);
        // the object in this node now (the one put there last)
        let now = (0..objects.len())
            .filter(|&k| objects[k].node.is_some_and(|m| same(m, n)))
            .filter(free)
            .max_by_key(|&k| objects[k].since);
        if let Some(k) = now {
            inputs.push((k, n));
            continue;
        }
        // else a unit made this node, but its object has moved on since (FOON takes a node once made
        // as there for every unit that needs it): that unit makes a second object in the node; else it
        // comes from the kitchen
        let maker = before.iter().rposition(|s| makes(s, n));
        let k = new_object(objects, &n.label, Some(n), maker.map_or(0, |p| p + 1));
        match maker {
            Some(p) => before[p].outputs.push((k, n)),
            None => kitchen.push((k, n)),
        }
        inputs.push((k, n));
    }
    let mut continued = vec![false; inputs.len()];
    let mut outputs = Vec::new();
    for o in &u.outputs {
        // the input object of the same label most like it, else a new object
        let like = (0..inputs.len())
            .filter(|&p| !continued[p] && inputs[p].1.label == o.label)
            .max_by_key(|&p| (likeness(inputs[p].1, o), std::cmp::Reverse(p)));
        let k = match like {
            Some(p) => {
                continued[p] = true;
                inputs[p].0
            }
            None => new_object(objects, &o.label, None, j),
        };
        outputs.push((k, &**o));
    }
    // a food not among the outputs went into them, unless it is listed in what an output holds (FOON
    // lists a bowl's contents again as inputs of the next thing added to it); a utensil stays as it was
    let held = |label: &str| {
        u.outputs
            .iter()
            .any(|o| o.ingredients.iter().any(|i| i == label))
    };
    let used_up: Vec<usize> = (0..inputs.len())
        .filter(|&p| !continued[p])
        .filter(|&p| !is_utensil(&inputs[p].1.label) && !held(&inputs[p].1.label))
        .map(|p| inputs[p].0)
        .collect();
    for &(k, o) in &outputs {
        objects[k].node = Some(o);
        objects[k].since = j;
    }
    for &k in &used_up {
        objects[k].node = None;
        objects[k].since = j;
    }
    Step {
        inputs,
        outputs,
        used_up,
    }
}

/// Whether two nodes are one: the same label in the same set of states.
fn same(a: &PlanNode, b: &PlanNode) -> bool {
    a.is(&b.label, &b.states)
}

/// Whether a step makes node `n` (not only passes it on).
fn makes(s: &Step, n: &PlanNode) -> bool {
    let has = |list: &[(usize, &PlanNode)]| list.iter().any(|(_, m)| same(m, n));
    has(&s.outputs) && !has(&s.inputs)
}

/// How many states two nodes share.
fn likeness(a: &PlanNode, b: &PlanNode) -> usize {
    a.states.iter().filter(|s| b.states.contains(s)).count()
}

/// A new object of `label`: named after it, with a number from the second on (`bowl`, `bowl-2`).
fn new_object<'p>(
    objects: &mut Vec<Object<'p>>,
    label: &str,
    node: Option<&'p PlanNode>,
    since: usize,
) -> usize {
    let base = ident(label);
    let mut name = base.clone();
    let mut k = 1;
    while objects.iter().any(|o| o.name == name) {
        k += 1;
        name = format!("{base}-{k}");
    }
    objects.push(Object { name, node, since });
    objects.len() - 1
}

/// The object in the goal node at the end, else the last unit's output of the goal's label.
fn goal_object<'p>(objects: &[Object<'p>], plan: &'p Plan) -> Option<(usize, &'p PlanNode)> {
    let goal = &plan.goal;
    let last = plan.units.last()?;
    let output = last
        .outputs
        .iter()
        .find(|o| o.is(&goal.label, &goal.states))
        .or_else(|| last.outputs.iter().find(|o| o.label == goal.label))?;
    let k = (0..objects.len()).find(|&k| objects[k].node.is_some_and(|m| same(m, output)))?;
    Some((k, &**output))
}
