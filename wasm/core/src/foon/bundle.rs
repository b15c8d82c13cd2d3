//! Loading a knowledge base from files, and the bundle form the build ships: all subgraph files in one
//! text file, each introduced by a line `#@file <name>` (a FOON comment, so a bundle is also valid FOON).

use crate::error::Result;
use crate::foon::kb::KnowledgeBase;
use crate::foon::read::{parse_bytes, Subgraph};

pub const FILE_MARK: &str = "#@file ";

/// Splits bundle bytes into (file name, bytes) pairs, without requiring the whole bundle to be UTF-8,
/// so that a damaged file inside a bundle is reported by its own name. Empty when `bytes` is not a bundle.
pub fn split_bundle_bytes(bytes: &[u8]) -> Vec<(String, &[u8])> {
    if !bytes.starts_with(FILE_MARK.as_bytes()) {
        return Vec::new();
    }
    let mut out = Vec::new();
    let mut current: Option<(String, usize)> = None;
    let mut offset = 0;
    for line in bytes.split_inclusive(|&b| b == b'\n') {
        if let Some(name) = line.strip_prefix(FILE_MARK.as_bytes()) {
            if let Some((n, start)) = current.take() {
                out.push((n, &bytes[start..offset]));
            }
            current = Some((
                String::from_utf8_lossy(name).trim().to_string(),
                offset + line.len(),
            ));
        }
        offset += line.len();
    }
    if let Some((n, start)) = current {
        out.push((n, &bytes[start..]));
    }
    out
}

/// Joins files into bundle text, each ended by a line end.
pub fn join_bundle<'a>(files: impl IntoIterator<Item = (&'a str, &'a str)>) -> String {
    let mut out = String::new();
    for (name, text) in files {
        let end = if text.ends_with('\n') { "" } else { "\n" };
        out.push_str(&format!("{FILE_MARK}{name}\n{text}{end}"));
    }
    out
}

/// Parses every file (a bundle file is expanded into its parts) and merges them.
/// The first malformed file stops the load with its error; nothing is half-loaded.
pub fn load(files: &[(String, Vec<u8>)]) -> Result<KnowledgeBase> {
    let mut graphs: Vec<Subgraph> = Vec::new();
    for (name, bytes) in files {
        let parts = split_bundle_bytes(bytes);
        if parts.is_empty() {
            graphs.push(parse_bytes(name, bytes)?);
        }
        for (part, body) in parts {
            graphs.push(parse_bytes(&part, body)?);
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
        let parts = split_bundle_bytes(text.as_bytes());
        let expected: Vec<(String, &[u8])> = vec![
            ("a.txt".into(), b"O\ta\t1\n"),
            ("b.txt".into(), b"# x\nO\tb\t0\n"),
        ];
        assert_eq!(parts, expected);
        assert!(split_bundle_bytes(b"O\ta\t1\n").is_empty());
    }
}
