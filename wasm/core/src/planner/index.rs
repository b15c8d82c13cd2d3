//! Tables the planner derives once from a knowledge base: nodes per label, state frequencies per dish
//! class, the motion most used to reach each state, the utensil most used with each motion.

use super::transitions::Transitions;
use crate::foon::kb::KnowledgeBase;
use crate::foon::model::{FunctionalUnit, NodeId, StateArg, UnitId};
use crate::vocab::food_taxonomy::Taxonomy;
use crate::vocab::states::{category, has_food_state, is_food_state, node_category, Category};
use crate::vocab::taxonomy::{is_transfer_motion, is_utensil};
use rustc_hash::{FxHashMap as HashMap, FxHashSet as HashSet};
use smol_str::SmolStr;
use std::collections::{BTreeMap, BTreeSet};
use std::sync::atomic::{AtomicU64, Ordering};

/// Built once per knowledge base (`PlannerIndex::new`) and passed to every `plan` call.
#[derive(Clone, Debug, Default)]
pub struct PlannerIndex {
    /// Unique for the process: names this index's ingredient labels for `Similarity::rank_in_set`.
    pub(crate) id: u64,
    /// Unique for the process: names `label_names` for `Similarity::prepare`.
    pub(crate) label_set: u64,
    /// Object nodes per label (ids ascending).
    pub(crate) by_label: HashMap<SmolStr, Vec<NodeId>>,
    /// Distinct ingredient labels (not utensils), sorted.
    pub(crate) ingredient_labels: Vec<String>,
    /// label -> state -> dish class -> occurrences in units of recipes of that class; class `None`
    /// counts all. Nested so that a lookup borrows its words.
    label_state: HashMap<String, StateCounts>,
    /// state -> dish class -> occurrences; class `None` counts all.
    state_freq: StateCounts,
    /// State word -> the motion most used to bring an object into it.
    motion_for_state: HashMap<String, String>,
    /// Category -> the motion most used to bring an object into a state of it.
    motion_for_category: HashMap<Category, String>,
    /// Motion -> the utensil node most used as an input of it.
    utensil_for_motion: HashMap<String, NodeId>,
    /// Which motion brings a food of each form into which state, in this knowledge base.
    pub(crate) transitions: Transitions,
    /// Utensils some unit cooks in (`heated_vessels`): an ingredient is not bought in one.
    heated: HashSet<SmolStr>,
    /// Ingredients sold liquid or ground rather than whole (`sold_as`): a node of one without food
    /// states is in that category.
    sold_as: HashMap<String, Category>,
    /// Every name of an object or of a listed content, by id.
    label_names: Vec<String>,
    label_ids: HashMap<String, u32>,
    /// Per unit, the ids of the ingredients it handles: its non-utensil inputs and their contents.
    unit_ingredients: Vec<Vec<u32>>,
    /// The usable goals per dish class, for the classes that have some.
    class_goals: HashMap<u32, GoalClass>,
    /// Every usable goal: goal selection's choice when the query's class has none.
    all_goals: GoalClass,
    /// Subgraph names by id; ids follow name order, so sorted id lists are sorted name lists.
    subgraph_ids: HashMap<String, u32>,
    /// For each unit, the ids of the subgraphs it occurs in (sorted): `kb.provenance` without strings.
    unit_sources: Vec<Vec<u32>>,
    /// For each node, the ids of the subgraphs (sorted) in which some unit makes it (not merely passes
    /// it on).
    made_in: Vec<Vec<u32>>,
}

/// The goals goal selection may choose among (made by some unit, a dish rather than a container), with
/// their ingredients numbered within the group: the pairs a query's names make with them are remembered
/// from plan to plan by these numbers (`Similarity::memory`).
#[derive(Clone, Debug, Default)]
pub(crate) struct GoalClass {
    /// Unique for the process: names `labels` for `PairMemory`.
    pub set: u64,
    /// The label ids of the goals' ingredients, ascending: an ingredient's position here is its slot.
    pub labels: Vec<u32>,
    /// Each goal (index into `kb.goals`, in that order) with the slots of its ingredients that are not
    /// utensils, as listed.
    pub goals: Vec<(usize, Vec<u32>)>,
}

impl GoalClass {
    /// `goals` (with their ingredients' label ids) numbered as a group.
    fn new(goals: Vec<(usize, &Vec<u32>)>) -> GoalClass {
        let mut labels: Vec<u32> = goals
            .iter()
            .flat_map(|(_, ids)| ids.iter().copied())
            .collect();
        labels.sort_unstable();
        labels.dedup();
        let slot = |id: &u32| labels.binary_search(id).unwrap_or_default() as u32;
        GoalClass {
            set: NEXT_ID.fetch_add(1, Ordering::Relaxed),
            goals: goals
                .into_iter()
                .map(|(g, ids)| (g, ids.iter().map(slot).collect()))
                .collect(),
            labels,
        }
    }

    /// The slot of label `id`, when an ingredient of these goals has it.
    pub fn slot(&self, id: u32) -> Option<u32> {
        self.labels.binary_search(&id).ok().map(|s| s as u32)
    }
}

static NEXT_ID: AtomicU64 = AtomicU64::new(1);

/// Occurrences per dish class (`None`: all classes).
type ClassCounts = HashMap<Option<u32>, u32>;
/// Occurrences of each state word per dish class.
type StateCounts = HashMap<String, ClassCounts>;

/// The key with the highest count; ties to the smallest key, whatever the order counts came in.
fn best<K: Ord + Clone>(counts: &BTreeMap<K, u32>) -> Option<K> {
    let ranked = counts.iter().max_by(|a, b| a.1.cmp(b.1).then(b.0.cmp(a.0)));
    ranked.map(|(k, _)| k.clone())
}

/// Per key, the value counted most (`best`).
fn most_counted<K: Eq + std::hash::Hash, V: Ord + Clone>(
    counts: BTreeMap<K, BTreeMap<V, u32>>,
) -> HashMap<K, V> {
    (counts.into_iter())
        .filter_map(|(k, c)| Some((k, best(&c)?)))
        .collect()
}

/// Counts per (word, class) counted on borrowed words, as owned word -> class -> count.
fn by_word(flat: HashMap<(&str, Option<u32>), u32>) -> StateCounts {
    let mut out = StateCounts::default();
    for ((word, class), n) in flat {
        out.entry(word.to_string()).or_default().insert(class, n);
    }
    out
}

/// Subgraph names numbered in name order, and each unit's subgraphs by number (sorted).
fn subgraph_ids(kb: &KnowledgeBase) -> (HashMap<String, u32>, Vec<Vec<u32>>) {
    let names: BTreeSet<&String> = kb.provenance.iter().flat_map(|s| s.iter()).collect();
    let subgraph_ids: HashMap<String, u32> = names
        .into_iter()
        .enumerate()
        .map(|(i, n)| (n.clone(), i as u32))
        .collect();
    let unit_sources = kb
        .provenance
        .iter()
        .map(|p| {
            let mut ids: Vec<u32> = p.iter().map(|s| subgraph_ids[s]).collect();
            ids.sort_unstable();
            ids.dedup();
            ids
        })
        .collect();
    (subgraph_ids, unit_sources)
}

/// Per node, the subgraphs (sorted) in which some unit makes it rather than passing it on.
fn made_in(kb: &KnowledgeBase, unit_sources: &[Vec<u32>]) -> Vec<Vec<u32>> {
    let mut made_in: Vec<Vec<u32>> = vec![Vec::new(); kb.nodes.len()];
    for (uid, u) in kb.each_unit() {
        for o in u.output_nodes() {
            if !u.input_nodes().any(|i| i == o) {
                made_in[o].extend_from_slice(&unit_sources[uid]);
            }
        }
    }
    for ids in &mut made_in {
        ids.sort_unstable();
        ids.dedup();
    }
    made_in
}

/// How often each label is in each state, and each state occurs, in units of recipes of each dish class
/// (class `None` counts all).
fn state_counts(kb: &KnowledgeBase) -> (HashMap<String, StateCounts>, StateCounts) {
    let mut subgraph_class: HashMap<&str, Option<u32>> = HashMap::default();
    for g in &kb.goals {
        subgraph_class.entry(&g.subgraph).or_insert(g.dish_class);
    }
    let mut label_state: HashMap<&str, HashMap<(&str, Option<u32>), u32>> = HashMap::default();
    let mut state_freq: HashMap<(&str, Option<u32>), u32> = HashMap::default();
    for (uid, u) in kb.each_unit() {
        let classes: BTreeSet<Option<u32>> = kb.provenance[uid]
            .iter()
            .map(|s| subgraph_class.get(s.as_str()).copied().flatten())
            .collect();
        for o in u.inputs.iter().chain(u.outputs.iter()) {
            let node = &kb.nodes[o.node];
            if is_utensil(&node.label) {
                continue;
            }
            let of_label = label_state.entry(&node.label).or_default();
            for s in node.physical_states() {
                for c in classes.iter().copied().chain([None]) {
                    *of_label.entry((s, c)).or_insert(0) += 1;
                    *state_freq.entry((s, c)).or_insert(0) += 1;
                }
            }
        }
    }
    let label_state = label_state
        .into_iter()
        .map(|(label, states)| (label.to_string(), by_word(states)))
        .collect();
    (label_state, by_word(state_freq))
}

/// The motions the knowledge base uses most: to bring a food into each state and each category, and
/// with each utensil.
struct MotionTables {
    for_state: HashMap<String, String>,
    for_category: HashMap<Category, String>,
    utensil: HashMap<String, NodeId>,
}

impl MotionTables {
    fn count(kb: &KnowledgeBase) -> MotionTables {
        let mut motion_state: BTreeMap<String, BTreeMap<String, u32>> = BTreeMap::new();
        let mut motion_cat: BTreeMap<Category, BTreeMap<String, u32>> = BTreeMap::new();
        let mut motion_utensil: BTreeMap<String, BTreeMap<NodeId, u32>> = BTreeMap::new();
        for u in &kb.units {
            for s in gained_states(kb, u) {
                let count =
                    |m: &mut BTreeMap<String, u32>| *m.entry(u.motion.clone()).or_insert(0) += 1;
                count(motion_state.entry(s.to_string()).or_default());
                count(motion_cat.entry(category(s)).or_default());
            }
            for i in &u.inputs {
                let n = &kb.nodes[i.node];
                if is_utensil(&n.label) && n.states.is_empty() {
                    *motion_utensil
                        .entry(u.motion.clone())
                        .or_default()
                        .entry(i.node)
                        .or_insert(0) += 1;
                }
            }
        }
        MotionTables {
            for_state: most_counted(motion_state),
            for_category: most_counted(motion_cat),
            utensil: most_counted(motion_utensil),
        }
    }
}

/// Food states an output of unit `u` gains over the input of the same label: the motion reaches them
/// (not a pour or a scoop: a sauce poured into a bowl, written "sauce" only there, was not made so).
fn gained_states<'k>(kb: &'k KnowledgeBase, u: &'k FunctionalUnit) -> Vec<&'k str> {
    if is_transfer_motion(&u.motion) {
        return Vec::new();
    }
    let mut gained = Vec::new();
    for o in &u.outputs {
        let out = &kb.nodes[o.node];
        if is_utensil(&out.label) {
            continue;
        }
        let before: BTreeSet<&str> = u
            .inputs
            .iter()
            .map(|i| &kb.nodes[i.node])
            .filter(|n| n.label == out.label)
            .flat_map(|n| n.physical_states())
            .collect();
        gained.extend(
            out.physical_states()
                .filter(|s| !before.contains(s) && is_food_state(s)),
        );
    }
    gained
}

/// Every name of an object or of a listed content, numbered (units' ingredients first, then goals',
/// then every node's label), with each unit's and each goal's ingredients by number.
struct Labels {
    names: Vec<String>,
    ids: HashMap<String, u32>,
    unit_ingredients: Vec<Vec<u32>>,
    goal_ingredients: Vec<Vec<u32>>,
}

impl Labels {
    fn number(kb: &KnowledgeBase) -> Labels {
        let mut names: Vec<String> = Vec::new();
        let mut ids: HashMap<String, u32> = HashMap::default();
        let mut intern = |l: &str| -> u32 {
            *ids.entry(l.to_string()).or_insert_with(|| {
                names.push(l.to_string());
                names.len() as u32 - 1
            })
        };
        let unit_ingredients = kb
            .units
            .iter()
            .map(|unit| {
                let mut ids: Vec<u32> = Vec::new();
                for n in unit.input_nodes() {
                    let node = &kb.nodes[n];
                    if !is_utensil(&node.label) {
                        ids.push(intern(&node.label));
                    }
                    // every listed content (contains, greased, garnished...), as g(u) always had it
                    for st in &node.states {
                        if let Some(StateArg::Ingredients(list)) = &st.arg {
                            ids.extend(list.iter().map(|l| intern(l)));
                        }
                    }
                }
                ids.sort_unstable();
                ids.dedup();
                ids
            })
            .collect();
        let goal_ingredients = kb
            .goals
            .iter()
            .map(|g| {
                g.ingredients
                    .iter()
                    .filter(|l| !is_utensil(l))
                    .map(|l| intern(l))
                    .collect()
            })
            .collect();
        for n in &kb.nodes {
            intern(&n.label);
        }
        Labels {
            names,
            ids,
            unit_ingredients,
            goal_ingredients,
        }
    }
}

/// The usable goals (with their ingredients' label ids, `kb.goals` order) per dish class, and all of them.
fn goal_classes(
    kb: &KnowledgeBase,
    ingredients: &[Vec<u32>],
) -> (HashMap<u32, GoalClass>, GoalClass) {
    let usable: Vec<(usize, &Vec<u32>)> = kb
        .goals
        .iter()
        .zip(ingredients)
        .enumerate()
        .filter(|(_, (g, _))| {
            kb.producers.get(g.node.0).is_some_and(|p| !p.is_empty())
                && !is_utensil(&kb.nodes[g.node].label)
        })
        .map(|(i, (_, ids))| (i, ids))
        .collect();
    let mut by_class: BTreeMap<u32, Vec<(usize, &Vec<u32>)>> = BTreeMap::new();
    for &(i, ids) in &usable {
        if let Some(c) = kb.goals[i].dish_class {
            by_class.entry(c).or_default().push((i, ids));
        }
    }
    let classes = by_class
        .into_iter()
        .map(|(c, goals)| (c, GoalClass::new(goals)))
        .collect();
    (classes, GoalClass::new(usable))
}

/// Food taxonomy categories (`data/food_taxonomy.tsv`) of ingredients sold as liquids (flavorings are
/// extracts and essences, but for the rare vanilla bean) or ground.
const SOLD_LIQUID: &str =
    "beverage, beer, dressing, flavoring, juice, milk, oil, plant milk, sauce, \
    spirit, stock, syrup, vinegar, wine";
const SOLD_GROUND: &str = "flour, leavener, spice blend, starch";

/// The ingredients sold liquid or ground rather than whole (water, oil, flour, a spice blend), with that
/// category: a node of one without food states is in it. Decided by the label's starting nodes (those no
/// unit makes) with food states, when FOON has some; else by a state word of the name ("turmeric
/// powder", "lemon juice"); else by the food taxonomy.
fn sold_as(kb: &KnowledgeBase, ingredient_labels: &[String]) -> HashMap<String, Category> {
    // label -> (starting nodes in a liquid state, in a ground one, in another food state)
    let mut votes: HashMap<&str, [u32; 3]> = HashMap::default();
    for (node, _) in kb
        .nodes
        .iter()
        .zip(&kb.producers)
        .filter(|(n, made_by)| made_by.is_empty() && !is_utensil(&n.label) && has_food_state(n))
    {
        let v = votes.entry(node.label.as_str()).or_default();
        match node_category(node) {
            Category::Liquid => v[0] += 1,
            Category::Ground => v[1] += 1,
            _ => v[2] += 1,
        }
    }
    let taxonomy = Taxonomy::builtin();
    let sold = |label: &str| -> Option<Category> {
        if let Some(&[liquid, ground, other]) = votes.get(label) {
            return if 2 * liquid > liquid + ground + other {
                Some(Category::Liquid)
            } else if 2 * ground > liquid + ground + other {
                Some(Category::Ground)
            } else {
                None
            };
        }
        // the last state word of the name decides, as in `category`
        let named = label
            .rsplit(' ')
            .map(category)
            .find(|&c| matches!(c, Category::Liquid | Category::Ground));
        named.or_else(|| {
            let name = &taxonomy.category(taxonomy.lookup(label)?).name;
            let sold = |c, names: &str| names.split(", ").any(|n| n == name).then_some(c);
            sold(Category::Liquid, SOLD_LIQUID).or_else(|| sold(Category::Ground, SOLD_GROUND))
        })
    };
    ingredient_labels
        .iter()
        .filter_map(|label| Some((label.clone(), sold(label)?)))
        .collect()
}

/// The utensils that units whose motion cooks take in (the pot simmered, the pan fried in): the
/// knowledge base's own cooking vessels.
fn heated_vessels(kb: &KnowledgeBase) -> HashSet<SmolStr> {
    kb.units
        .iter()
        .filter(|u| crate::vocab::foods::cooks(&u.motion))
        .flat_map(|u| u.input_nodes())
        .map(|n| &kb.nodes[n].label)
        .filter(|l| is_utensil(l))
        .cloned()
        .collect()
}

impl PlannerIndex {
    pub fn new(kb: &KnowledgeBase) -> PlannerIndex {
        let mut by_label: HashMap<SmolStr, Vec<NodeId>> = HashMap::default();
        for (id, n) in kb.each_node() {
            by_label.entry(n.label.clone()).or_default().push(id);
        }
        let ingredient_labels: Vec<String> = kb
            .ingredient_labels()
            .into_iter()
            .map(str::to_string)
            .collect();
        let (subgraph_ids, unit_sources) = subgraph_ids(kb);
        let (label_state, state_freq) = state_counts(kb);
        let motions = MotionTables::count(kb);
        let labels = Labels::number(kb);
        let (class_goals, all_goals) = goal_classes(kb, &labels.goal_ingredients);
        PlannerIndex {
            class_goals,
            all_goals,
            label_names: labels.names,
            label_ids: labels.ids,
            unit_ingredients: labels.unit_ingredients,
            id: NEXT_ID.fetch_add(1, Ordering::Relaxed),
            label_set: NEXT_ID.fetch_add(1, Ordering::Relaxed),
            by_label,
            sold_as: sold_as(kb, &ingredient_labels),
            ingredient_labels,
            label_state,
            state_freq,
            motion_for_state: motions.for_state,
            motion_for_category: motions.for_category,
            transitions: Transitions::mine(kb),
            heated: heated_vessels(kb),
            utensil_for_motion: motions.utensil,
            made_in: made_in(kb, &unit_sources),
            subgraph_ids,
            unit_sources,
        }
    }

    /// Whether some unit of the knowledge base cooks in utensil `label` (a pot, a frying pan).
    pub(crate) fn is_heated(&self, label: &str) -> bool {
        self.heated.contains(label)
    }

    /// Whether node `n` is a starting item of one of the recipes unit `u` comes from (that recipe
    /// never makes it): retrieval takes it from the kitchen there, as the recipe did.
    pub(crate) fn starts_in_recipe_of(&self, u: UnitId, n: NodeId) -> bool {
        let made = self.made_in.get(n.0).map_or(&[][..], Vec::as_slice);
        self.sources(u)
            .iter()
            .any(|s| made.binary_search(s).is_err())
    }

    /// The ids of the subgraphs unit `u` occurs in, sorted.
    pub(crate) fn sources(&self, u: UnitId) -> &[u32] {
        self.unit_sources.get(u.0).map_or(&[], Vec::as_slice)
    }

    /// Whether units `u` and `v` occur in a common subgraph.
    pub(crate) fn share_recipe(&self, u: UnitId, v: UnitId) -> bool {
        let theirs = self.sources(v);
        self.sources(u)
            .iter()
            .any(|s| theirs.binary_search(s).is_ok())
    }

    pub(crate) fn subgraph_id(&self, name: &str) -> Option<u32> {
        self.subgraph_ids.get(name).copied()
    }

    pub(crate) fn label_id(&self, label: &str) -> Option<u32> {
        self.label_ids.get(label).copied()
    }

    /// Every label name, by id.
    pub(crate) fn label_names(&self) -> &[String] {
        &self.label_names
    }

    pub(crate) fn unit_ingredients(&self, u: UnitId) -> &[u32] {
        self.unit_ingredients.get(u.0).map_or(&[], Vec::as_slice)
    }

    /// The usable goals of dish class `class`, when it has some.
    pub(crate) fn goals_of_class(&self, class: u32) -> Option<&GoalClass> {
        self.class_goals.get(&class)
    }

    /// Every usable goal.
    pub(crate) fn all_goals(&self) -> &GoalClass {
        &self.all_goals
    }

    pub(crate) fn nodes_of(&self, label: &str) -> &[NodeId] {
        self.by_label.get(label).map_or(&[], Vec::as_slice)
    }

    pub(crate) fn is_label(&self, label: &str) -> bool {
        self.by_label.contains_key(label)
    }

    /// The category `label` is sold in when not whole (see `sold_as`).
    pub(crate) fn sold_as(&self, label: &str) -> Option<Category> {
        self.sold_as.get(label).copied()
    }

    /// How common the states are for `label`: summed over `states`, how often `label` is in the state
    /// plus how often anything is, in recipes of the class and in all recipes.
    pub(crate) fn state_frequency(
        &self,
        class: Option<u32>,
        label: &str,
        states: &[&str],
    ) -> (u32, u32) {
        let of_label = self.label_state.get(label);
        let count = |counts: Option<&ClassCounts>, c: Option<u32>| {
            counts.and_then(|m| m.get(&c)).copied().unwrap_or(0)
        };
        states.iter().fold((0, 0), |(in_class, overall), &s| {
            let labelled = of_label.and_then(|m| m.get(s));
            let any = self.state_freq.get(s);
            (
                in_class + count(labelled, class) + count(any, class),
                overall + count(labelled, None) + count(any, None),
            )
        })
    }

    /// The motion most used to bring an object into exactly the state word `state`, if any unit does.
    pub(crate) fn motion_making(&self, state: &str) -> Option<&str> {
        self.motion_for_state.get(state).map(String::as_str)
    }

    /// The motion most used to reach `state` (or a state of its category); `None` for starting states.
    pub(crate) fn motion_for(&self, state: &str) -> Option<String> {
        let cat = category(state);
        if cat.is_starting() || cat == Category::Other {
            return None;
        }
        self.motion_for_state
            .get(state)
            .or_else(|| self.motion_for_category.get(&cat))
            .cloned()
    }

    pub(crate) fn utensil_for(&self, motion: &str) -> Option<NodeId> {
        self.utensil_for_motion.get(motion).copied()
    }
}

/// Plans may run on several threads against one index.
const _: fn() = || {
    fn send_sync<T: Send + Sync>() {}
    send_sync::<PlannerIndex>();
};
