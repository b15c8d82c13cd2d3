//! FOON's building blocks: object nodes (a label in a set of states), motion nodes, functional units.

use serde::Serialize;
use smol_str::{format_smolstr, SmolStr};

/// What a state says about its object beyond its name: where it is, or what it holds.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum StateArg {
    /// `in [bowl]`, `on [cutting board]`: the container or surface.
    Container(SmolStr),
    /// `contains {tomato,onion}`, `coated {flour}`: the ingredients involved, sorted, unique.
    Ingredients(Vec<SmolStr>),
}

/// One state of an object node, e.g. `sliced`, `in [bowl]`, `contains {egg,milk}`.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
pub struct State {
    /// The state word or relation word (`sliced`, `in`, `contains`, `coated`, ...).
    pub name: SmolStr,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub arg: Option<StateArg>,
}

impl State {
    pub fn plain(name: &str) -> State {
        State {
            name: name.into(),
            arg: None,
        }
    }

    /// FOON text for the state's argument, `[bowl]` or `{egg,milk}`.
    pub fn arg_text(&self) -> Option<String> {
        self.arg.as_ref().map(|arg| match arg {
            StateArg::Container(c) => format!("[{c}]"),
            StateArg::Ingredients(list) => format!("{{{}}}", list.join(",")),
        })
    }

    /// The state as FOON writes it, `in [bowl]` or `contains {egg,milk}`.
    pub fn text(&self) -> SmolStr {
        match self.arg {
            None => self.name.clone(),
            Some(_) => format_smolstr!("{self}"),
        }
    }
}

impl std::fmt::Display for State {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.name)?;
        match self.arg_text() {
            Some(arg) => write!(f, " {arg}"),
            None => Ok(()),
        }
    }
}

/// An object node: identity is the label together with the whole set of states.
/// States are kept sorted so that the same object annotated in another order is the same node.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
pub struct ObjectNode {
    pub label: SmolStr,
    pub states: Vec<State>,
}

impl ObjectNode {
    pub fn new(label: impl Into<SmolStr>, mut states: Vec<State>) -> ObjectNode {
        states.sort();
        states.dedup();
        ObjectNode {
            label: label.into(),
            states,
        }
    }

    /// Physical states (those without a container or ingredient argument), e.g. `sliced`, `whole`.
    pub fn physical_states(&self) -> impl Iterator<Item = &str> + Clone {
        self.states
            .iter()
            .filter(|s| s.arg.is_none())
            .map(|s| s.name.as_str())
    }

    /// The first container or surface the object is in or on.
    pub fn container(&self) -> Option<&str> {
        self.states.iter().find_map(|s| match &s.arg {
            Some(StateArg::Container(c)) => Some(c.as_str()),
            _ => None,
        })
    }

    /// Ingredients the object holds (`contains {…}`) as written (may repeat).
    pub fn contents(&self) -> impl Iterator<Item = &str> {
        self.lists(|s| s.name == "contains")
    }

    /// Every name in any of the object's lists (`contains {…}`, `greased {…}`, ...).
    pub fn listed(&self) -> impl Iterator<Item = &str> {
        self.lists(|_| true)
    }

    fn lists<'a>(&'a self, of: impl Fn(&State) -> bool + 'a) -> impl Iterator<Item = &'a str> {
        self.states
            .iter()
            .filter(move |s| of(s))
            .filter_map(|s| match &s.arg {
                Some(StateArg::Ingredients(list)) => Some(list.iter().map(SmolStr::as_str)),
                _ => None,
            })
            .flatten()
    }

    /// Whether the object holds any ingredient.
    pub fn holds_something(&self) -> bool {
        self.contents().next().is_some()
    }

    /// Ingredients the object holds (`contains {…}`), sorted and unique, as `String`s or the plan's
    /// `SmolStr`s.
    pub fn ingredients<'a, S: From<&'a str> + Ord>(&'a self) -> Vec<S> {
        let mut out: Vec<S> = self.contents().map(S::from).collect();
        out.sort_unstable();
        out.dedup();
        out
    }

    /// How many ingredients `ingredients` lists.
    pub fn ingredient_count(&self) -> usize {
        self.ingredients::<&str>().len()
    }
}

impl std::fmt::Display for ObjectNode {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.label)?;
        if self.states.is_empty() {
            return Ok(());
        }
        let states: Vec<String> = self.states.iter().map(State::to_string).collect();
        write!(f, " ({})", states.join(", "))
    }
}

/// Defines an id type: the position of one item in the knowledge base's list of such items, which
/// indexes any list kept in step with it (`kb.nodes[id]`, `kb.producers[id]`, `seen[id]`).
macro_rules! id_type {
    ($(#[$doc:meta])* $name:ident) => {
        $(#[$doc])*
        #[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
        #[serde(transparent)]
        pub struct $name(pub usize);

        impl $name {
            /// Every id of a list of `len` items.
            pub fn all(len: usize) -> impl DoubleEndedIterator<Item = $name> + Clone {
                (0..len).map($name)
            }
        }

        impl std::fmt::Display for $name {
            fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                self.0.fmt(f)
            }
        }

        impl<T> std::ops::Index<$name> for [T] {
            type Output = T;
            fn index(&self, id: $name) -> &T {
                &self[id.0]
            }
        }

        impl<T> std::ops::IndexMut<$name> for [T] {
            fn index_mut(&mut self, id: $name) -> &mut T {
                &mut self[id.0]
            }
        }

        impl<T> std::ops::Index<$name> for Vec<T> {
            type Output = T;
            fn index(&self, id: $name) -> &T {
                &self[id.0]
            }
        }

        impl<T> std::ops::IndexMut<$name> for Vec<T> {
            fn index_mut(&mut self, id: $name) -> &mut T {
                &mut self[id.0]
            }
        }
    };
}

id_type!(
    /// An object node of a knowledge base: its place in `KnowledgeBase::nodes`.
    NodeId
);
id_type!(
    /// A functional unit of a knowledge base: its place in `KnowledgeBase::units`.
    UnitId
);

/// An object node as used by one functional unit: `moves` is FOON's motion flag
/// (1 = the object is manipulated or changes, 0 = it is only present).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
pub struct UnitObject {
    pub node: NodeId,
    pub moves: bool,
}

/// A functional unit: input object nodes, one motion node, output object nodes.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct FunctionalUnit {
    pub inputs: Vec<UnitObject>,
    pub motion: String,
    pub outputs: Vec<UnitObject>,
}

impl FunctionalUnit {
    pub fn input_nodes(&self) -> impl Iterator<Item = NodeId> + '_ {
        self.inputs.iter().map(|o| o.node)
    }
    pub fn output_nodes(&self) -> impl Iterator<Item = NodeId> + '_ {
        self.outputs.iter().map(|o| o.node)
    }
}
