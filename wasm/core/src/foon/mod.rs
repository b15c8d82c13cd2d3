//! FOON itself: the object, motion and functional-unit model, labels, the subgraph reader and writer,
//! bundles of subgraph files, and the universal FOON (the knowledge base) with its kitchen items.

pub mod bundle;
pub mod kb;
pub mod label;
pub mod model;
pub mod read;
pub mod snapshot;
pub mod write;
