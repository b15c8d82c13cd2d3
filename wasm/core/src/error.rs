//! Typed errors: every failure of the core is one of these, never a panic.
//! `code` is stable (the bindings and the app match on it); `message` is for people.

use serde::{Deserialize, Serialize};

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ErrorCode {
    /// The bytes of a file are not UTF-8.
    InvalidUtf8,
    /// A file, line, label or collection is over a documented limit.
    TooLarge,
    /// A line starts with something that is not `O`, `S`, `M`, `#` or `//`.
    UnknownLine,
    /// A line lacks a field it needs (a label, a flag, a state name, a motion).
    MissingField,
    /// An object flag that is not 0 or 1, or a dish class that is not a number, not a known class, or
    /// not the same on two goal marks of one node.
    BadNumber,
    /// An empty or white-space-only label, state or motion.
    EmptyLabel,
    /// A state argument with unbalanced or unknown brackets.
    BadBrackets,
    /// A state line with no object before it in its unit.
    StateWithoutObject,
    /// A unit with objects but no motion line, or with two motion lines, or a separating motion that
    /// turns one food into another.
    BadMotion,
    /// A motion line with no input object before it.
    MotionWithoutInputs,
    /// A motion line with no output object after it.
    UnitWithoutOutputs,
    /// No subgraph files, or files with no functional units at all.
    EmptyKnowledgeBase,
    /// A plan request that is not well-formed (wrong types, empty names, too many ingredients).
    BadQuery,
    /// The embedding table is damaged or of another version.
    BadEmbeddings,
    /// The knowledge base has no goal node the planner could use.
    NoGoal,
}

impl ErrorCode {
    pub fn as_str(self) -> &'static str {
        match self {
            ErrorCode::InvalidUtf8 => "invalid_utf8",
            ErrorCode::TooLarge => "too_large",
            ErrorCode::UnknownLine => "unknown_line",
            ErrorCode::MissingField => "missing_field",
            ErrorCode::BadNumber => "bad_number",
            ErrorCode::EmptyLabel => "empty_label",
            ErrorCode::BadBrackets => "bad_brackets",
            ErrorCode::StateWithoutObject => "state_without_object",
            ErrorCode::BadMotion => "bad_motion",
            ErrorCode::MotionWithoutInputs => "motion_without_inputs",
            ErrorCode::UnitWithoutOutputs => "unit_without_outputs",
            ErrorCode::EmptyKnowledgeBase => "empty_knowledge_base",
            ErrorCode::BadQuery => "bad_query",
            ErrorCode::BadEmbeddings => "bad_embeddings",
            ErrorCode::NoGoal => "no_goal",
        }
    }
}

/// An error with an optional place: file, 1-based line and 1-based column (in characters).
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct FoonError {
    pub code: ErrorCode,
    pub message: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub file: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub line: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub column: Option<usize>,
}

impl FoonError {
    pub fn new(code: ErrorCode, message: impl Into<String>) -> FoonError {
        FoonError {
            code,
            message: message.into(),
            file: None,
            line: None,
            column: None,
        }
    }

    /// A request that is not well-formed (`ErrorCode::BadQuery`).
    pub(crate) fn bad_query(message: impl Into<String>) -> FoonError {
        FoonError::new(ErrorCode::BadQuery, message)
    }

    pub fn at(
        code: ErrorCode,
        file: &str,
        line: usize,
        column: usize,
        message: impl Into<String>,
    ) -> FoonError {
        FoonError {
            file: Some(file.to_string()),
            line: Some(line),
            column: Some(column),
            ..FoonError::new(code, message)
        }
    }
}

impl std::fmt::Display for FoonError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match (&self.file, self.line, self.column) {
            (Some(file), Some(line), Some(col)) => write!(f, "{file}:{line}:{col}: ")?,
            (Some(file), Some(line), None) => write!(f, "{file}:{line}: ")?,
            (Some(file), None, _) => write!(f, "{file}: ")?,
            _ => {}
        }
        write!(f, "{} ({})", self.message, self.code.as_str())
    }
}

impl std::error::Error for FoonError {}

pub type Result<T> = std::result::Result<T, FoonError>;
