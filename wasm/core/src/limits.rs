//! Limits on input sizes, so that a hostile or mistaken file gets a clear error instead of exhausting
//! the WASM module's memory.

/// Largest subgraph file (bytes).
pub const MAX_FILE_BYTES: usize = 32 * 1024 * 1024;
/// Longest line in a subgraph file (bytes).
pub const MAX_LINE_BYTES: usize = 64 * 1024;
/// Longest label, state or motion (characters).
pub const MAX_LABEL_CHARS: usize = 200;
/// Most functional units in one file, and in a whole knowledge base before duplicates are merged.
pub const MAX_UNITS: usize = 1_000_000;
/// Most ingredients in one plan request.
pub const MAX_QUERY_INGREDIENTS: usize = 200;
/// Largest plan request or name list, as JSON text (bytes).
pub const MAX_REQUEST_BYTES: usize = 1024 * 1024;
