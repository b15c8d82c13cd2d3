//! What the planner promises its callers: the plan request and plan types (`plan`), decoding requests
//! (`decode`), the plan JSON (`json`) and the exports (`export`).

pub mod decode;
pub mod export;
pub mod json;
pub mod plan;
