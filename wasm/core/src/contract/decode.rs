//! Decoding what callers send as JSON (plan requests, name lists), with a size limit and errors that say
//! where the JSON is wrong: `ErrorCode::BadQuery` (or `TooLarge`) with the 1-based line and column of the
//! JSON text, never a panic. The bindings and the fuzz target `plan_request` use exactly these functions.

use crate::contract::plan::PlanRequest;
use crate::error::{ErrorCode, FoonError, Result};
use crate::limits;
use serde::de::DeserializeOwned;

fn decode<T: DeserializeOwned>(json: &str, what: &str) -> Result<T> {
    let (bytes, most) = (json.len(), limits::MAX_REQUEST_BYTES);
    if bytes > most {
        let message = format!("{what} is {bytes} bytes of JSON; the limit is {most} bytes");
        return Err(FoonError::new(ErrorCode::TooLarge, message));
    }
    serde_json::from_str(json).map_err(|e| {
        let mut error = FoonError::new(ErrorCode::BadQuery, format!("{what}: {e}"));
        if e.line() > 0 {
            error.line = Some(e.line());
            error.column = Some(e.column().max(1));
        }
        error
    })
}

/// A plan request: `{"query": {"type": …, "ingredients": [{"object": …, "state": …}]}, "modify"?, "overrides"?,
/// "explain"?, "robot"?}` (`docs/plan-format.md`).
pub fn plan_request(json: &str) -> Result<PlanRequest> {
    decode(json, "plan request")
}

/// A JSON array of names (strings), at most `limits::MAX_QUERY_INGREDIENTS` of them.
pub fn names(json: &str) -> Result<Vec<String>> {
    let names: Vec<String> = decode(json, "names (a JSON array of strings)")?;
    let (count, most) = (names.len(), limits::MAX_QUERY_INGREDIENTS);
    if count > most {
        let message = format!("{count} names; the limit is {most}");
        return Err(FoonError::new(ErrorCode::TooLarge, message));
    }
    Ok(names)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wrong_types_are_bad_queries_with_a_place() {
        for (json, message, line, column) in [
            (
                r#"{"query": {"type": "salad", "ingredients": "tomato"}}"#,
                "plan request: invalid type: string \"tomato\", expected a sequence at line 1 column 51",
                1,
                51,
            ),
            (
                "{\n\"query\": 7}",
                "plan request: invalid type: integer `7`, expected struct Query at line 2 column 10",
                2,
                10,
            ),
            (
                "",
                "plan request: EOF while parsing a value at line 1 column 0",
                1,
                1,
            ),
        ] {
            let e = plan_request(json).unwrap_err();
            assert_eq!(
                (e.code, e.message.as_str(), e.line, e.column),
                (ErrorCode::BadQuery, message, Some(line), Some(column)),
                "{json}"
            );
        }
    }

    #[test]
    fn oversized_requests_are_too_large() {
        let json = format!("\"{}\"", "x".repeat(limits::MAX_REQUEST_BYTES));
        assert_eq!(plan_request(&json).unwrap_err().code, ErrorCode::TooLarge);
        let many = serde_json::to_string(&vec!["a"; limits::MAX_QUERY_INGREDIENTS + 1]).unwrap();
        assert_eq!(names(&many).unwrap_err().code, ErrorCode::TooLarge);
        assert_eq!(names(r#"["a", 1]"#).unwrap_err().code, ErrorCode::BadQuery);
    }
}
