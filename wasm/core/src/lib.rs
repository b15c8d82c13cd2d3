//! foon-core: a FOON knowledge base (reader, universal FOON, indexes) and the approximate task-tree
//! retrieval of Sakib, Paulius and Sun (RA-L 2022). Plain Rust, no browser types: the `foon-wasm` crate
//! exposes it to JavaScript. `docs/architecture.md` maps the modules.

pub mod contract;
pub mod error;
pub mod foon;
pub mod limits;
mod memo;
pub mod planner;
pub mod robot;
pub mod similarity;
pub mod stats;
pub mod trace;
pub mod vocab;

pub use contract::export::{foon_text, pddl, progress_json, Pddl};
pub use contract::json::write_plan_json;
pub use contract::plan::{Plan, PlanRequest, Query, QueryIngredient};
pub use error::{ErrorCode, FoonError, Result};
pub use foon::bundle::load;
pub use foon::kb::{Goal, KnowledgeBase};
pub use foon::model::{FunctionalUnit, NodeId, ObjectNode, State, StateArg, UnitId, UnitObject};
pub use planner::{plan, PlannerIndex};
pub use similarity::ranking::{similar, EmbeddingSimilarity, SimilarResult};
pub use stats::{stats, Stats};
pub use vocab::listing::{vocabulary, Vocabulary};
