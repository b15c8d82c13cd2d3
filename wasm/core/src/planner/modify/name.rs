//! Naming: after modification, the dish and the mixtures on the way to it are named for what they hold
//! and for the dish asked. A reference's "apple cake" made without apples for a bread is "bread"; its
//! "cake batter" is "batter"; an "egg mixture" the egg never joins is a "mixture". A motion FOON names
//! otherwise takes the cook's word for what it does (a stem "skimmed" peeled is peeled).

use super::*;
use crate::foon::label::singular;
use crate::vocab::taxonomy::kin_classes;

/// Renames the goal and the mixtures whose names claim a food they do not hold or a dish of another
/// class than the one asked (`ctx.class`); a note says what the dish is called and why.
pub(super) fn name_for_query(
    ctx: &Context,
    tree: &mut Tree,
    query: &Query,
    notes: &mut Vec<String>,
) {
    let asked: HashSet<&str> = query
        .ingredients
        .iter()
        .map(|i| i.object.as_str())
        .collect();
    let held = Held::of(tree);
    let goal = tree.slots[tree.goal].node.label.clone();
    let namer = Namer { class: ctx.class };
    let mut renames: Vec<(SmolStr, String)> = Vec::new();
    // the dish holds whatever the tree brings to it, listed or not
    let mut in_dish = held.words(&goal);
    in_dish.extend(tree.ingredient_labels().into_iter().flat_map(name_words));
    if let Some(to) = namer.dish(&goal, &in_dish) {
        for stage in earlier_stages(tree, &goal, &to, &asked) {
            renames.push((stage, to.clone()));
        }
        renames.push((goal.clone(), to));
    }
    let mut labels: Vec<&SmolStr> = tree
        .slots
        .iter()
        .filter(|s| !s.utensil && s.node.holds_something())
        .map(|s| &s.node.label)
        .filter(|l| **l != goal && !asked.contains(l.as_str()))
        .collect();
    labels.sort();
    labels.dedup();
    for label in labels {
        if let Some(to) = namer.mixture(label, &held.words(label)) {
            renames.push((label.clone(), to));
        }
    }
    // a name a food of the tree has (a food, or an ingredient as bought: the bread of a toast) would
    // merge the two: the dish is then a "... dish", a mixture keeps its name (an earlier stage of the
    // dish, the "soup" before it simmers, may share the dish's name)
    let taken: HashSet<&str> = tree
        .live_slots()
        .filter(|&s| !tree.slots[s].utensil)
        .map(|s| (tree.slots[s].node.label.as_str(), tree.produced(s)))
        .filter(|&(l, produced)| !produced || foods::kind(l).is_some())
        .map(|(l, _)| l)
        .collect();
    let renames: Vec<(SmolStr, String)> = renames
        .into_iter()
        .filter_map(|(from, to)| match taken.contains(to.as_str()) {
            false => Some((from, to)),
            true if from == goal => Some((from, format!("{to} dish"))),
            // the "dough" a "pizza dough" would merge with: the asked dish's ("bread dough")
            true => namer
                .for_class(&to)
                .filter(|n| !taken.contains(n.as_str()))
                .map(|n| (from, n)),
        })
        .collect();
    for (from, to) in &renames {
        tree.rename_everywhere(from, to);
        tree.rename_container(from, to);
        if *from == goal {
            notes.push(format!(
                "the dish is called '{to}': the reference task tree made '{from}', a name the asked \
                 dish and ingredients do not bear out"
            ));
        }
    }
}

/// The foods made on the way that bear the goal's head word ("pizza" before the "cheese pizza" is
/// baked) where the dish is renamed to another class: a bread made through a pizza's tree is never
/// called a pizza on the way.
fn earlier_stages(tree: &Tree, goal: &str, to: &str, asked: &HashSet<&str>) -> Vec<SmolStr> {
    if dish_class_of(goal) == dish_class_of(to) {
        return Vec::new();
    }
    let mut stages: Vec<SmolStr> = tree
        .live_slots()
        .filter(|&s| !tree.slots[s].utensil && tree.produced(s))
        .map(|s| tree.slots[s].node.label.clone())
        .filter(|l| l != goal && !asked.contains(l.as_str()) && head_word(l) == head_word(goal))
        .collect();
    stages.sort();
    stages.dedup();
    stages
}

/// The last word of a name, the food it names ("pizza" of "cheese pizza").
fn head_word(label: &str) -> &str {
    label.rsplit(' ').next().unwrap_or(label)
}

/// Gives a unit the cook's word for its motion (`foods::cooks_word`) where it gives a food the state
/// that word is for.
pub(super) fn name_motions(tree: &mut Tree) {
    for u in 0..tree.units.len() {
        let unit = &tree.units[u];
        let had = |label: &str, state: &str| {
            unit.inputs.iter().any(|i| {
                let n = &tree.slots[i.0].node;
                n.label == label && n.physical_states().any(|s| s == state)
            })
        };
        let word = unit.outputs.iter().find_map(|o| {
            let n = &tree.slots[o.0].node;
            n.physical_states()
                .filter(|s| !had(&n.label, s))
                .find_map(|s| foods::cooks_word(&unit.motion, s))
        });
        if let Some(word) = word {
            tree.units[u].motion = Cow::Borrowed(word);
        }
    }
}

/// The words of an ingredient's name that say what it is: none for a mixture, whose name claims
/// nothing ("corn mixture" of sugar holds no corn).
fn name_words(item: &str) -> Vec<&str> {
    let mixture = item.rsplit(' ').next().and_then(foods::kind) == Some("mixture");
    if mixture {
        Vec::new()
    } else {
        item.split([' ', '-']).collect()
    }
}

/// What each mixture holds, as the words of its ingredients, through the mixtures it holds (a batter
/// holding an "egg mixture" holds its egg).
struct Held<'t> {
    lists: HashMap<&'t str, Vec<&'t str>>,
}

impl<'t> Held<'t> {
    fn of(tree: &'t Tree) -> Held<'t> {
        let mut lists: HashMap<&str, Vec<&str>> = HashMap::default();
        for s in tree.slots.iter().filter(|s| !s.utensil) {
            lists
                .entry(s.node.label.as_str())
                .or_default()
                .extend(s.node.contents());
        }
        Held { lists }
    }

    fn words(&self, label: &str) -> HashSet<&'t str> {
        let mut seen: HashSet<&str> = HashSet::default();
        let mut words = HashSet::default();
        let mut todo: Vec<&str> = self.lists.get(label).cloned().unwrap_or_default();
        while let Some(item) = todo.pop() {
            if seen.insert(item) {
                words.extend(name_words(item));
                todo.extend(self.lists.get(item).into_iter().flatten().copied());
            }
        }
        words
    }
}

/// A word naming a food ("apple", "egg", "bean"; not "cake", a mixture's "batter", or the "fried",
/// "creamed" and "ground" the taxonomy's stems would read as foods).
fn is_food_word(word: &str) -> bool {
    // "bean" is also a state (coffee bought as beans), a starting one: a food still
    let made = is_food_state(word) && !category(word).is_starting();
    let participle = made || (word.ends_with("ed") && !word.ends_with("eed"));
    !participle && foods::kind(word).is_some_and(|k| k != "mixture")
}

struct Namer {
    /// The asked dish class.
    class: Option<u32>,
}

impl Namer {
    fn names_class(&self, text: &str) -> bool {
        self.class.is_some() && dish_class_of(text) == self.class
    }

    /// `name` as the asked class's ("dough": "bread dough").
    fn for_class(&self, name: &str) -> Option<String> {
        let class = singular(dish_class_name(self.class?)?);
        (!name.starts_with(&class)).then(|| format!("{class} {name}"))
    }

    /// Whether a word may stay in a name: no food, or one held, or the asked dish ("custard").
    fn keeps(&self, word: &str, held: &HashSet<&str>) -> bool {
        !is_food_word(word) || held.contains(word) || self.names_class(word)
    }

    /// A modifier (its hyphened parts each) without the foods not held; `None` when nothing is left.
    fn kept_part(&self, modifier: &str, held: &HashSet<&str>) -> Option<String> {
        let parts: Vec<&str> = modifier
            .split('-')
            .filter(|p| self.keeps(p, held))
            .collect();
        (!parts.is_empty()).then(|| parts.join("-"))
    }

    /// The goal's name: food words it does not hold are dropped; a name whose head food is gone, or
    /// that names a dish of a kin class rather than the asked one, becomes the asked class's name after
    /// the foods it holds ("blueberry muffin" asked as a cake: "blueberry cake"). `None`: it stays.
    fn dish(&self, label: &str, held: &HashSet<&str>) -> Option<String> {
        let words: Vec<&str> = label.split(' ').collect();
        let held = &with_compounds(&words, held);
        let (head, modifiers) = words.split_last()?;
        // "butter cream" holding butter keeps its name; "black bean" holding no bean does not, even
        // beside black pepper ("black" names no food)
        let head_gone =
            !self.keeps(head, held) && !words.iter().any(|w| is_food_word(w) && held.contains(w));
        let kept: Vec<String> = modifiers
            .iter()
            .filter_map(|m| self.kept_part(m, held))
            .collect();
        let named = join_words(&kept, head);
        // "macaroni and cheese" without one of them is no longer that dish
        let joined = words.iter().any(|w| matches!(*w, "and" | "with")) && named != label;
        let kin = |name: &str| {
            let (Some(asked), Some(made)) = (self.class, dish_class_of(name)) else {
                return false;
            };
            made != asked && kin_classes(asked).any(|k| k == made)
        };
        let to = if head_gone || joined || kin(label) || kin(&named) {
            let foods: Vec<String> = words
                .iter()
                .filter(|w| w.split('-').all(is_food_word))
                .filter_map(|w| self.kept_part(w, held))
                .collect();
            join_words(&foods, &singular(dish_class_name(self.class?)?))
        } else {
            named
        };
        (to != label).then_some(to)
    }

    /// A mixture's name ("cake batter", "egg mixture") without the foods it does not hold or the
    /// dishes of another class than the one asked; only names whose head is a mixture's word change.
    fn mixture(&self, label: &str, held: &HashSet<&str>) -> Option<String> {
        let words: Vec<&str> = label.split(' ').collect();
        let (head, modifiers) = words.split_last()?;
        if modifiers.is_empty() || foods::kind(head) != Some("mixture") {
            return None;
        }
        let other_dish =
            |m: &str| !is_food_word(m) && dish_class_of(m).is_some() && !self.names_class(m);
        let kept: Vec<String> = modifiers
            .iter()
            .filter(|m| !other_dish(m))
            .filter_map(|m| self.kept_part(m, held))
            .collect();
        let to = join_words(&kept, head);
        (to != label).then_some(to)
    }
}

/// `held` and the other word of a two-word food the name holds one word of: a cake of "chip" (as
/// recipe data shortens chocolate chips) keeps its "chocolate chip".
fn with_compounds<'a>(words: &[&'a str], held: &HashSet<&'a str>) -> HashSet<&'a str> {
    let mut with = held.clone();
    for pair in words.windows(2) {
        if pair.iter().any(|w| held.contains(w) && is_food_word(w))
            && foods::kind(&pair.join(" ")).is_some()
        {
            with.extend(pair.iter().copied());
        }
    }
    with
}

fn join_words(modifiers: &[String], head: &str) -> String {
    [modifiers.join(" "), head.to_string()]
        .join(" ")
        .trim()
        .to_string()
}
