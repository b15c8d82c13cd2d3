//! One plain sentence per unit (`Plan::steps`), from its motion, objects and places.

use super::*;

/// Two steps that read the same ("Cut the dough on the cutting board", to halve it and then to cut it
/// into strips) each say what their food becomes: "… until it is halved."; when nothing tells them apart,
/// the later says "again". A plan has a few dozen steps: pairs are compared directly.
pub(super) fn tell_apart(tree: &Tree, order: &[TUnitId], steps: &mut [String]) {
    let repeated: Vec<usize> = (0..steps.len())
        .filter(|&i| (0..steps.len()).any(|j| j != i && steps[j] == steps[i]))
        .collect();
    for i in repeated {
        let unit = &tree.units[order[i]];
        // the food's new plain states: in an output, not in the input of the same name
        let made = unit.outputs.iter().find_map(|&(o, _)| {
            if tree.slots[o].utensil {
                return None;
            }
            let out = &tree.slots[o].node;
            let before = unit
                .inputs
                .iter()
                .map(|&(x, _)| &tree.slots[x].node)
                .find(|n| n.label == out.label)?;
            let new: Vec<&str> = out
                .physical_states()
                .filter(|s| !before.physical_states().any(|b| b == *s))
                .collect();
            (!new.is_empty()).then_some(new)
        });
        if let Some(new) = made {
            let step = &mut steps[i];
            step.pop();
            step.push_str(&format!(" until it is {}.", new.join(" and ")));
        }
    }
    // what still reads the same is the same action once more (a second spoonful of soy sauce)
    for i in 1..steps.len() {
        let times = steps[..i].iter().filter(|s| **s == steps[i]).count();
        if times > 0 {
            let step = &mut steps[i];
            step.pop();
            step.push_str(match times {
                1 => " again.",
                _ => " once more.",
            });
        }
    }
}

/// FOON motions whose words go around the object in English: ("cut in half", "Cut", " in half") makes "Cut
/// the tomato in half", ("make slits", "Make slits in", "") "Make slits in the mango". ("Break apart the
/// chip" reads well as it is.)
pub(super) const VERB_FRAMES: &[(&str, &str, &str)] = &[
    ("pick-and-place", "Place", ""),
    ("put inside", "Put", ""),
    ("cut in half", "Cut", " in half"),
    ("make slits", "Make slits in", ""),
    ("cut with slits", "Cut slits in", ""),
    ("cut off ends", "Cut the ends off", ""),
    ("cut off skin", "Cut the skin off", ""),
    ("tuck ends", "Tuck in the ends of", ""),
];

/// The motion as the sentence's capitalised verb, written onto `out`; returns what follows the object.
pub(super) fn push_verb(out: &mut String, motion: &str) -> &'static str {
    let m = motion.trim_end_matches('*').trim();
    if let Some(&(_, verb, after)) = VERB_FRAMES.iter().find(|f| f.0 == m) {
        out.push_str(verb);
        return after;
    }
    let mut c = m.chars();
    if let Some(f) = c.next() {
        out.extend(f.to_uppercase());
        out.push_str(c.as_str());
    }
    ""
}

/// "the a, the b and the c", written onto `out`.
pub(super) fn push_list(out: &mut String, items: &[&str]) {
    for (k, item) in items.iter().enumerate() {
        if k > 0 {
            out.push_str(if k + 1 == items.len() { " and " } else { ", " });
        }
        out.push_str("the ");
        out.push_str(item);
    }
}

/// Motions that open or close a container.
pub(super) const CLOSES: &[&str] = &["open", "close", "cover", "uncover"];

/// Other motions that handle a container itself rather than what it holds.
pub(super) const HANDLES: &[&str] = &[
    "remove", "attach", "detach", "take out", "turn on", "turn off",
];

/// Whether a motion moves things into a place ("pour into the bowl", "tear and place onto the tray").
pub(super) fn moves_into(motion: &str) -> bool {
    motion.contains("pour")
        || motion.contains("place")
        || PUT_MOTIONS.contains(&motion)
        || motion == "add"
}

/// Where a node is (`in [bowl]` as ("in", "bowl"), `attached to [mixer]` as ("to", "mixer")), unless
/// that is one of the `objects` moved. A lid it is covered with, or a tool it is with, is not a place.
pub(super) fn container_of<'n>(n: &'n ObjectNode, objects: &[&str]) -> Option<(&'n str, &'n str)> {
    n.states.iter().find_map(|s| {
        let Some(StateArg::Container(c)) = &s.arg else {
            return None;
        };
        let rel = match s.name.as_str() {
            "attached to" => "to",
            rel @ ("in" | "on" | "over" | "under") => rel,
            _ => return None,
        };
        (!objects.contains(&c.as_str())).then_some((rel, c.as_str()))
    })
}

/// How things are put in each container, found once per container: a plan asks about a few
/// containers many times, and each answer looks through every slot.
pub(super) struct Relations<'t> {
    pub(super) tree: &'t Tree<'t>,
    pub(super) known: Vec<(&'t str, &'t str)>,
}

impl<'t> Relations<'t> {
    pub(super) fn to(&mut self, container: &'t str) -> &'t str {
        if let Some(&(_, rel)) = self.known.iter().find(|k| k.0 == container) {
            return rel;
        }
        let rel = relation_to(self.tree, container);
        self.known.push((container, rel));
        rel
    }
}

/// How things are put in `container`, as the tree's nodes say ("on" a plate, "in" a bowl), else "in".
/// Food says it first: a lid is on the blender jar, the food in it (a pot says it is on the stove).
pub(super) fn relation_to<'t>(tree: &'t Tree, container: &str) -> &'t str {
    let said_by = |food: bool| {
        tree.slots
            .iter()
            .filter(move |slot| slot.utensil != food)
            .flat_map(|slot| &slot.node.states)
            .filter(|s| matches!(&s.arg, Some(StateArg::Container(c)) if c == container))
            .find(|s| s.name == "in" || s.name == "on")
            .map(|s| s.name.as_str())
    };
    said_by(true).or_else(|| said_by(false)).unwrap_or("in")
}

/// What a unit's motion does, by its words.
struct MotionKind {
    /// It puts things into a place ("pour", "place", "add").
    puts: bool,
    /// It opens or closes a container.
    closes: bool,
    /// It handles a container itself rather than what it holds.
    handles: bool,
}

impl MotionKind {
    fn of(motion: &str) -> MotionKind {
        MotionKind {
            puts: moves_into(motion),
            closes: CLOSES.contains(&motion),
            handles: PUT_MOTIONS.contains(&motion)
                || HANDLES.contains(&motion)
                || motion.ends_with(" open"),
        }
    }
}

/// How a sentence's objects were found, which decides its place and the tools it names.
#[derive(Default)]
struct Found<'t> {
    /// The container worked on, as (relation, label), when it is the place ("… in the bowl").
    holder: Option<(&'t str, &'t str)>,
    /// A container opened or closed where it stands.
    closed: bool,
    /// What is put somewhere was taken out of a vessel other than the products'.
    from_elsewhere: bool,
    /// The objects are what moved, the tools it moved with aside.
    with_tools: bool,
}

/// The unit `u` and its tree, as a sentence is made of them.
struct Said<'t> {
    tree: &'t Tree<'t>,
    unit: &'t TUnit<'t>,
}

impl<'t> Said<'t> {
    fn node(&self, x: SlotId) -> &'t ObjectNode {
        &self.tree.slots[x].node
    }

    fn utensil(&self, x: SlotId) -> bool {
        self.tree.slots[x].utensil
    }

    fn tool(&self, x: SlotId) -> bool {
        self.utensil(x) && self.node(x).states.is_empty()
    }

    /// The labels of the inputs `which` accepts (by slot and whether it moves), into `objects`.
    fn push_inputs(&self, objects: &mut Vec<&'t str>, which: impl Fn(SlotId, bool) -> bool) {
        for &(x, _) in self.unit.inputs.iter().filter(|&&(x, m)| which(x, m)) {
            push(objects, &self.node(x).label);
        }
    }
}

fn push<'n>(objects: &mut Vec<&'n str>, l: &'n str) {
    if !objects.contains(&l) {
        objects.push(l);
    }
}

/// One plain sentence for a unit: "Slice the tomato on the cutting board."
pub(super) fn sentence<'t>(tree: &'t Tree, u: TUnitId, relations: &mut Relations<'t>) -> String {
    let said = Said {
        tree,
        unit: &tree.units[u],
    };
    let unit = said.unit;
    let motion = unit.motion.trim_end_matches('*');
    let kind = MotionKind::of(motion);
    // the sentence's objects, then its tools after them
    let mut objects = Vec::new();
    let found = said.objects(motion, &kind, &mut objects, relations);
    let place = found.holder.or_else(|| {
        (!found.closed)
            .then(|| said.place(&objects, relations))
            .flatten()
    });
    let settled = said.settled(
        &mut objects,
        place.filter(|_| found.holder.is_none() && kind.puts),
    );
    let moved = objects.len();
    said.tools(&mut objects, &found, place);
    let (objects, tools) = objects.split_at(moved);
    write(&unit.motion, objects, place, kind.puts, &settled, tools)
}

impl<'t> Said<'t> {
    /// The objects the unit works on, into `objects`.
    fn objects(
        &self,
        motion: &str,
        kind: &MotionKind,
        objects: &mut Vec<&'t str>,
        relations: &mut Relations<'t>,
    ) -> Found<'t> {
        let unit = self.unit;
        self.push_inputs(objects, |x, m| m && !self.utensil(x));
        if objects.is_empty() {
            self.push_inputs(objects, |x, _| !self.utensil(x));
        }
        let MotionKind {
            puts,
            closes,
            handles,
        } = *kind;
        let mut found = Found::default();
        // food already in a vessel, mixed there into something new, is mixed with all the vessel
        // holds: the blender blends the whole cup, not the honey FOON moves ("Blend the honey, the
        // blueberry and the milk")
        if !objects.is_empty() && !puts && !handles && !closes && is_mixing_motion(motion) {
            let label_of = |x: SlotId| self.node(x).label.as_str();
            let makes_new = unit.outputs.iter().any(|&(o, _)| {
                !self.utensil(o) && !unit.inputs.iter().any(|&(i, _)| label_of(i) == label_of(o))
            });
            let inside = |v: &ObjectNode, l: &str| {
                unit.inputs.iter().any(|&(i, _)| {
                    label_of(i) == l && self.node(i).container() == Some(v.label.as_str())
                })
            };
            let vessel = unit
                .inputs
                .iter()
                .map(|&(i, _)| self.node(i))
                .find(|v| v.holds_something() && objects.iter().all(|l| inside(v, l)));
            if let Some(v) = vessel.filter(|_| makes_new) {
                for l in v.contents() {
                    push(objects, l);
                }
            }
        }
        if objects.is_empty() && !handles {
            self.worked_on(kind, objects, &mut found, relations);
        }
        // what moved, the tools it moved with aside ("Cut open the packet with the scissors")
        if objects.is_empty() {
            self.push_inputs(objects, |x, m| m && !self.tool(x));
            found.with_tools = !objects.is_empty();
        }
        if objects.is_empty() {
            self.push_inputs(objects, |_, m| m);
        }
        if objects.is_empty() {
            if let Some(&(x, _)) = unit.inputs.first() {
                push(objects, &self.node(x).label);
            }
        }
        found
    }

    /// No food among the inputs: the unit works on what a container holds ("Mix the egg and the milk in
    /// the bowl with the whisk", "Cook the egg in the pot", "Pour the flour and the salt into the
    /// bowl"), not on a tool or the container ("Mix the whisk", "Cook the pot", "Pour the bowl"),
    /// unless it handles the container itself: "Place the pot onto the stove", "Cover the pot with the
    /// pot lid" (only tools move: the lid) but "Cover the pot" when the pot moves.
    fn worked_on(
        &self,
        kind: &MotionKind,
        objects: &mut Vec<&'t str>,
        out: &mut Found<'t>,
        relations: &mut Relations<'t>,
    ) {
        let unit = self.unit;
        let MotionKind { puts, closes, .. } = *kind;
        let tools_only = unit.inputs.iter().any(|&(x, m)| m && self.tool(x))
            && unit.inputs.iter().all(|&(x, m)| !m || self.tool(x))
            && !PUT_MOTIONS.contains(&unit.motion.trim_end_matches('*'));
        let vessel = |i: &&(SlotId, bool)| self.node(i.0).holds_something();
        // a lid is put on or taken off what the unit covers or uncovers, before or after
        let covered = closes
            .then(|| {
                let mut nodes = unit.inputs.iter().chain(&unit.outputs);
                nodes.find(|i| self.node(i.0).states.iter().any(|s| s.name == "covered"))
            })
            .flatten();
        // a moved tool (a spoon, even an empty or clean one), or a machine holding a vessel (a mixer with
        // its bowl), is not what is worked on; nor is a lid
        let machine = |x: SlotId| {
            let n = self.node(x);
            let bare_tool =
                self.utensil(x) && !n.holds_something() && n.states.iter().all(|s| s.arg.is_none());
            bare_tool || n.states.iter().any(|s| s.name == "with")
        };
        let moved = unit.inputs.iter().filter(|i| i.1);
        // what a motion puts somewhere comes out of a vessel other than the one the products are in (a
        // ladle scoops the noodles out of the pot into the bowl)
        let source = |i: &&(SlotId, bool)| {
            vessel(i)
                && !(puts
                    && unit
                        .outputs
                        .iter()
                        .any(|o| self.node(o.0).container() == Some(&self.node(i.0).label)))
        };
        let worked = covered.or_else(|| moved.clone().find(vessel)).or_else(|| {
            (closes || moved.clone().all(|i| machine(i.0)))
                .then(|| {
                    let found = unit.inputs.iter().find(source);
                    out.from_elsewhere = puts && found.is_some();
                    found.or_else(|| unit.inputs.iter().find(vessel))
                })
                .flatten()
        });
        if let Some(&(x, _)) = worked {
            let n = self.node(x);
            if closes {
                push(objects, &n.label);
                out.closed = true;
            } else {
                for l in n.contents() {
                    push(objects, l);
                }
                // poured out of it (with more than tools moving): where it goes is the place
                if (tools_only || !puts) && !out.from_elsewhere {
                    out.holder = Some((relations.to(&n.label), n.label.as_str()));
                }
            }
        }
    }

    /// Where the moved objects end up.
    fn place(
        &self,
        objects: &[&'t str],
        relations: &mut Relations<'t>,
    ) -> Option<(&'t str, &'t str)> {
        let unit = self.unit;
        unit.outputs
            .iter()
            .find_map(|&(x, _)| {
                let n = self.node(x);
                if !objects.contains(&n.label.as_str()) {
                    return None;
                }
                container_of(n, objects)
            })
            // no moved object says where it is (ingredients that joined the unit, whose lists alone
            // record them): where what now holds one of them is, or that container itself
            .or_else(|| {
                unit.outputs.iter().find_map(|&(x, _)| {
                    let n = self.node(x);
                    if objects.contains(&n.label.as_str())
                        || !n.contents().any(|c| objects.contains(&c))
                    {
                        return None;
                    }
                    if self.utensil(x) {
                        return Some((relations.to(&n.label), n.label.as_str()));
                    }
                    container_of(n, objects)
                })
            })
            // nothing the unit makes lists them: the food it makes of them is where they went ("Pour the
            // mixture into the pot", the pot's soup made of it). An emptied jar alone (its food pruned)
            // goes nowhere.
            .or_else(|| {
                let food = |&(x, _): &(SlotId, bool)| {
                    !self.utensil(x) && objects.contains(&self.node(x).label.as_str())
                };
                if !unit.inputs.iter().any(food) {
                    return None;
                }
                unit.outputs.iter().find_map(|&(x, _)| {
                    let n = self.node(x);
                    (!self.utensil(x) && !objects.contains(&n.label.as_str()))
                        .then(|| container_of(n, objects))
                        .flatten()
                })
            })
    }

    /// What is already where the others are put is not put there again (FOON lists what a bowl holds
    /// among the inputs of the next thing added to it): the others go onto it ("Pour the maple syrup onto
    /// the french toast on the plate"); a bowl of the same name that does not hold it is another bowl.
    /// Returns those, taken out of `objects`.
    fn settled(&self, objects: &mut Vec<&'t str>, put_into: Option<(&str, &str)>) -> Vec<&'t str> {
        let unit = self.unit;
        let mut settled = Vec::new();
        if let Some((_, c)) = put_into {
            let mut vessels = unit
                .inputs
                .iter()
                .map(|i| self.node(i.0))
                .filter(|n| n.label == c);
            if let Some(first) = vessels.next() {
                let holds = |n: &ObjectNode, l: &str| n.contents().any(|i| i == l);
                let there = |l: &str| holds(first, l) && vessels.clone().all(|n| holds(n, l));
                let count = objects.iter().filter(|l| there(l)).count();
                if count > 0 && count < objects.len() {
                    settled.extend(objects.iter().copied().filter(|l| there(l)));
                    objects.retain(|l| !there(l));
                }
            }
        }
        settled
    }

    /// The tools the sentence names after its objects, into `objects`.
    fn tools(&self, objects: &mut Vec<&'t str>, found: &Found, place: Option<(&str, &str)>) {
        let unit = self.unit;
        let moved = objects.len();
        for &(x, m) in &unit.inputs {
            let n = self.node(x);
            if (!m
                || found.holder.is_some()
                || found.closed
                || found.from_elsewhere
                || found.with_tools)
                && self.utensil(x)
                && n.states.is_empty()
                && !objects[..moved].contains(&n.label.as_str())
                && place.is_none_or(|p| p.1 != n.label)
            {
                objects.push(&n.label);
            }
        }
    }
}

/// The sentence: verb, objects, place (with what is settled there) and tools.
fn write(
    motion: &str,
    objects: &[&str],
    place: Option<(&str, &str)>,
    puts: bool,
    settled: &[&str],
    tools: &[&str],
) -> String {
    let mut text = String::new();
    let after = push_verb(&mut text, motion);
    text.push(' ');
    push_list(&mut text, objects);
    text.push_str(after);
    if let Some((rel, c)) = place {
        let (into, rel) = match (rel, puts) {
            ("in", true) => ("into", "in"),
            ("on", true) => ("onto", "on"),
            (r, _) => (r, r),
        };
        text.push_str(&format!(" {into}"));
        // a long list of what is there already says less than the container's name
        if (1..=2).contains(&settled.len()) {
            text.push(' ');
            push_list(&mut text, settled);
            text.push_str(&format!(" {rel}"));
        }
        text.push_str(&format!(" the {c}"));
    }
    if !tools.is_empty() {
        text.push_str(" with ");
        push_list(&mut text, tools);
    }
    text.push('.');
    text
}
