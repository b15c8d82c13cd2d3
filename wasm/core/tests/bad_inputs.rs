//! The bad-input corpus (`tests/data/bad-inputs/`, manifest `expected.tsv`): every file is loaded as a
//! knowledge base on its own and must give exactly the error (code, file, line, column, message), the first
//! warning, or the load figures the manifest says. The Vitest suite (`tests/unit/errors-corpus.test.ts`)
//! feeds the same corpus through the WASM build, so both sides of the boundary agree.
//!
//! Manifest rows: `file  outcome  code  where  detail`, tab-separated, where `outcome` is `error`,
//! `warning` (the load succeeds and this is its first warning) or `ok`; `where` is `file:line:column`
//! (parts left out when the error has none, `-` for `ok`); `detail` is the exact message, or for `ok`
//! `units=N goals=N warnings=N`. Names starting with `@` are generated (see `generated`), so that no
//! multi-megabyte file is committed.

use foon_core::{limits, FoonError, KnowledgeBase};
use std::path::PathBuf;

fn corpus_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../tests/data/bad-inputs")
}

/// A good one-unit file of 9 lines, the prefix of several generated cases.
const GOOD: &str = "//\nO\ttomato\t1\nS\twhole\nO\tknife\t0\nS\tclean\nM\tslice\t<0:10,0:20>\nO\ttomato\t1\nS\tsliced\n//\n";

/// Bytes of a generated case (same recipes as `generatedCase` in tests/unit/errors-corpus.test.ts).
fn generated(name: &str) -> Vec<u8> {
    match name {
        // a 10 MB line after a good unit
        "@line-10mb" => format!("{GOOD}O\t{}\t1\n", "x".repeat(10 * 1024 * 1024)).into_bytes(),
        // one byte over the file limit
        "@file-over-limit" => vec![b'#'; limits::MAX_FILE_BYTES + 1],
        // a line one byte over the line limit
        "@line-over-limit" => {
            format!("O\t{}\n", "x".repeat(limits::MAX_LINE_BYTES - 1)).into_bytes()
        }
        // a line exactly at the line limit: not an error (the label is then too long)
        "@line-at-limit" => format!("O\t{}\n", "x".repeat(limits::MAX_LINE_BYTES - 2)).into_bytes(),
        // a label exactly at the label limit is fine
        "@label-at-limit" => format!(
            "O\t{}\t1\nM\tcut\nO\tb\t1\n",
            "x".repeat(limits::MAX_LABEL_CHARS)
        )
        .into_bytes(),
        // one unit over the unit limit
        "@units-over-limit" => "O\ta\nM\tc\nO\tb\n//\n"
            .repeat(limits::MAX_UNITS + 1)
            .into_bytes(),
        // two files in a bundle, each under the unit limit, together over it
        "@bundle-units-over-limit" => {
            let part = "O\ta\nM\tc\nO\tb\n//\n".repeat(limits::MAX_UNITS / 2 + 1);
            format!("#@file a.txt\n{part}#@file b.txt\n{part}").into_bytes()
        }
        // a line of 30,000 tab-separated fields (columns must be counted in linear time)
        "@many-fields" => format!("O\ta{}\n", "\tx".repeat(30_000)).into_bytes(),
        // one unit of 20,000 inputs and 20,000 outputs, then a second motion (recovery must be linear)
        "@wide-unit" => {
            let mut text = String::new();
            for i in 0..20_000 {
                text.push_str(&format!("O\tin{i}\t1\n"));
            }
            text.push_str("M\tmix\n");
            for i in 0..20_000 {
                text.push_str(&format!("O\tout{i}\t1\n"));
            }
            text.push_str("O\tout0\t1\nM\tserve\nO\tdish\t1\n");
            text.into_bytes()
        }
        other => panic!("unknown generated case {other}"),
    }
}

/// Generated cases of a million units or more: some seconds each in an optimised build, too slow for the
/// debug `cargo test`; `scripts/test.sh` runs this file with `--release`, and the WASM suite runs them too.
const HEAVY: &[&str] = &["@units-over-limit", "@bundle-units-over-limit"];

fn heavy_wanted() -> bool {
    std::env::var_os("FOON_HEAVY").is_some_and(|v| v == "1")
}

#[derive(Debug)]
struct Row {
    file: String,
    outcome: String,
    code: String,
    place: String,
    detail: String,
}

fn manifest() -> Vec<Row> {
    let text = std::fs::read_to_string(corpus_dir().join("expected.tsv")).unwrap();
    text.lines()
        .filter(|l| !l.trim().is_empty() && !l.starts_with('#'))
        .map(|l| {
            let f: Vec<&str> = l.split('\t').collect();
            assert_eq!(f.len(), 5, "manifest row needs 5 fields: {l:?}");
            Row {
                file: f[0].into(),
                outcome: f[1].into(),
                code: f[2].into(),
                place: f[3].into(),
                detail: f[4].into(),
            }
        })
        .collect()
}

fn place(e: &FoonError) -> String {
    let mut parts = vec![e.file.clone().unwrap_or_default()];
    parts.extend(e.line.map(|l| l.to_string()));
    parts.extend(e.column.map(|c| c.to_string()));
    match parts.join(":") {
        p if p.is_empty() => "-".into(),
        p => p,
    }
}

fn outcome(kb: &std::result::Result<KnowledgeBase, FoonError>) -> (String, String, String, String) {
    match kb {
        Err(e) => (
            "error".into(),
            e.code.as_str().into(),
            place(e),
            e.message.clone(),
        ),
        Ok(kb) => match kb.warnings.first() {
            Some(w) => (
                "warning".into(),
                w.code.as_str().into(),
                place(w),
                w.message.clone(),
            ),
            None => (
                "ok".into(),
                "-".into(),
                "-".into(),
                format!(
                    "units={} goals={} warnings=0",
                    kb.units.len(),
                    kb.goals.len()
                ),
            ),
        },
    }
}

#[test]
fn every_bad_input_gives_its_expected_error_and_place() {
    let rows = manifest();
    let mut failures = Vec::new();
    for row in &rows {
        if HEAVY.contains(&row.file.as_str()) && cfg!(debug_assertions) && !heavy_wanted() {
            eprintln!(
                "{}: skipped in a debug build (FOON_HEAVY=1 or --release runs it)",
                row.file
            );
            continue;
        }
        let bytes = if row.file.starts_with('@') {
            generated(&row.file)
        } else {
            std::fs::read(corpus_dir().join(&row.file))
                .unwrap_or_else(|e| panic!("{}: {e}", row.file))
        };
        let got = outcome(&foon_core::load(&[(row.file.clone(), bytes)]));
        let want = (
            row.outcome.clone(),
            row.code.clone(),
            row.place.clone(),
            row.detail.clone(),
        );
        if got != want {
            failures.push(format!(
                "{}\n   want {want:?}\n   got  {got:?}\n   row  {}\t{}\t{}\t{}\t{}",
                row.file, row.file, got.0, got.1, got.2, got.3
            ));
        }
    }
    assert!(
        failures.is_empty(),
        "{} of {} corpus rows differ:\n{}",
        failures.len(),
        rows.len(),
        failures.join("\n")
    );
}

#[test]
fn every_corpus_file_is_in_the_manifest() {
    let listed: std::collections::BTreeSet<String> =
        manifest().into_iter().map(|r| r.file).collect();
    for entry in std::fs::read_dir(corpus_dir()).unwrap() {
        let name = entry.unwrap().file_name().to_string_lossy().into_owned();
        if name != "expected.tsv" && name != "README.md" && !name.starts_with('.') {
            assert!(listed.contains(&name), "{name} has no row in expected.tsv");
        }
    }
}

#[test]
fn the_corpus_covers_every_reader_error_code() {
    use foon_core::ErrorCode::*;
    let rows = manifest();
    for code in [
        InvalidUtf8,
        TooLarge,
        UnknownLine,
        MissingField,
        BadNumber,
        EmptyLabel,
        BadBrackets,
        StateWithoutObject,
        BadMotion,
        MotionWithoutInputs,
        UnitWithoutOutputs,
        EmptyKnowledgeBase,
    ] {
        assert!(
            rows.iter().any(|r| r.code == code.as_str()),
            "no corpus file gives {}",
            code.as_str()
        );
    }
}
