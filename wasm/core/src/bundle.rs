//! Loading a knowledge base from files, and the bundle form the build ships: all subgraph files in one
//! text file, each introduced by a line `#@file <name>` (a FOON comment, so a bundle is also valid FOON).

use crate::error::{FoonError, Result};
use crate::kb::KnowledgeBase;
use crate::parse::{parse_bytes, Subgraph};

pub const FILE_MARK: &str = "#@file ";

/// Splits bundle text into (file name, text) pairs; text before the first mark is ignored.
pub fn split_bundle(text: &str) -> Vec<(&str, &str)> {
    let mut out = Vec::new();
    let mut current: Option<(&str, usize)> = None;
    let mut offset = 0;
    for line in text.split_inclusive('\n') {
        if let Some(name) = line.strip_prefix(FILE_MARK) {
            if let Some((n, start)) = current.take() {
                out.push((n, &text[start..offset]));
            }
            current = Some((name.trim(), offset + line.len()));
        }
        offset += line.len();
    }
    if let Some((n, start)) = current {
        out.push((n, &text[start..]));
    }
    out
}

/// Joins files into bundle text.
pub fn join_bundle<'a>(files: impl IntoIterator<Item = (&'a str, &'a str)>) -> String {
    let mut out = String::new();
    for (name, text) in files {
        out.push_str(FILE_MARK);
        out.push_str(name);
        out.push('\n');
        out.push_str(text);
        if !text.ends_with('\n') {
            out.push('\n');
        }
    }
    out
}

/// Parses every file (a bundle file is expanded into its parts) and merges them.
/// The first malformed file stops the load with its error; nothing is half-loaded.
pub fn load(files: &[(String, Vec<u8>)]) -> Result<KnowledgeBase> {
    let mut graphs: Vec<Subgraph> = Vec::new();
    for (name, bytes) in files {
        if bytes.starts_with(FILE_MARK.as_bytes()) {
            let Ok(text) = std::str::from_utf8(bytes) else {
                return Err(parse_bytes(name, bytes).err().unwrap_or_else(|| {
                    FoonError::new(crate::error::ErrorCode::InvalidUtf8, "bundle is not UTF-8")
                }));
            };
            for (part, body) in split_bundle(text) {
                graphs.push(parse_bytes(part, body.as_bytes())?);
            }
        } else {
            graphs.push(parse_bytes(name, bytes)?);
        }
    }
    KnowledgeBase::merge(&graphs)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bundles_round_trip() {
        let files = [("a.txt", "O\ta\t1\n"), ("b.txt", "# x\nO\tb\t0")];
        let text = join_bundle(files);
        assert_eq!(
            split_bundle(&text),
            vec![("a.txt", "O\ta\t1\n"), ("b.txt", "# x\nO\tb\t0\n")]
        );
    }

    #[test]
    fn errors_in_a_bundle_name_the_inner_file_and_line() {
        let text = join_bundle([
            ("good.txt", "O\ta\t1\nM\tm\nO\tb\t1\n"),
            ("bad.txt", "O\ta\t1\nS\tin\t[bowl\n"),
        ]);
        let e = load(&[("kb.foon".into(), text.into_bytes())]).unwrap_err();
        assert_eq!((e.file.as_deref(), e.line), (Some("bad.txt"), Some(2)));
    }
}
