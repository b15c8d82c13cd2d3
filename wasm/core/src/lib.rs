//! foon-core: a FOON knowledge base (reader, universal FOON, indexes) and the approximate task-tree
//! retrieval of Sakib, Paulius and Sun (RA-L 2022). Plain Rust, no browser types: the `foon-wasm` crate
//! exposes it to JavaScript.

pub mod bundle;
mod cones;
pub mod decode;
pub mod embedding;
pub mod error;
pub mod export;
pub mod foods;
pub mod kb;
pub mod label;
pub mod limits;
mod memo;
pub mod model;
pub mod parse;
pub mod plan;
pub mod plan_json;
pub mod planner;
pub mod robot;
pub mod similarity;
pub mod stats;
pub mod substitute;
pub mod taxonomy;
pub mod trace;
pub mod vocabulary;
pub mod write;

pub use bundle::load;
pub use error::{ErrorCode, FoonError, Result};
pub use export::{foon_text, pddl, progress_json, Pddl};
pub use kb::{Goal, KnowledgeBase};
pub use model::{FunctionalUnit, NodeId, ObjectNode, State, StateArg, UnitId, UnitObject};
pub use plan::{Plan, PlanRequest, Query, QueryIngredient};
pub use plan_json::write_plan_json;
pub use planner::{plan, PlannerIndex};
pub use stats::{stats, Stats};
pub use substitute::{similar, EmbeddingSimilarity, SimilarResult};
pub use vocabulary::{vocabulary, Vocabulary};
