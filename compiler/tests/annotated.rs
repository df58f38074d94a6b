//! Annotated diagnostic tests: each `tests/annotated/*.st` file is a whole source file whose
//! expected diagnostics are written under the line they are about:
//!
//! ```text
//! x := y + TRUE;
//! //   ^^^^^^^^ E0105
//! ```
//!
//! The carets give the exact span; the test fails on any diagnostic that is missing, extra, or
//! at another span, so the spans of messages are tested as well as their codes.
//!
//! A file whose first line contains `dialect: iec-strict` is checked in that dialect; the
//! others in the default (CODESYS) one.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::print_stdout)] // Test helpers may panic: a panic is a failed test.

use std::collections::BTreeSet;
use std::path::Path;

use compiler::sema::check_project;
use compiler::source_project::SourceProject;

/// (line, first column, end column, code), lines and columns from 1.
type Expectation = (usize, usize, usize, String);

fn expected(text: &str) -> BTreeSet<Expectation> {
    let mut found = BTreeSet::new();
    let mut subject_line = 0;
    for (index, line) in text.lines().enumerate() {
        let trimmed = line.trim_start();
        let is_marker = trimmed.starts_with("//") && trimmed[2..].trim_start().starts_with('^');
        if !is_marker {
            subject_line = index + 1;
            continue;
        }
        let start = line.find('^').unwrap();
        let end = start + line[start..].chars().take_while(|c| *c == '^').count();
        let code = line[end..].trim().to_owned();
        assert!(
            code.len() == 5,
            "line {}: a marker ends with a code such as E0104",
            index + 1
        );
        found.insert((subject_line, start + 1, end + 1, code));
    }
    found
}

fn actual(text: &str) -> (BTreeSet<Expectation>, Vec<String>) {
    let mut source = SourceProject::new(text);
    if text
        .lines()
        .next()
        .is_some_and(|line| line.contains("dialect: iec-strict"))
    {
        source.project.dialect = project_model::Dialect::IecStrict;
    }
    let mut ranges = Vec::new();
    for error in source.parse.errors().iter().chain(&source.diagnostics) {
        ranges.push((error.range.clone(), error.code.id(), error.message.clone()));
    }
    for finding in check_project(&source.project) {
        let Some(range) = source.locate(&finding) else {
            continue;
        };
        ranges.push((
            range,
            finding.diagnostic.code.id(),
            finding.diagnostic.message.clone(),
        ));
    }
    let mut found = BTreeSet::new();
    let mut messages = Vec::new();
    for (range, code, message) in ranges {
        let line = text[..range.start].matches('\n').count() + 1;
        let line_start = text[..range.start].rfind('\n').map_or(0, |at| at + 1);
        let start = range.start - line_start + 1;
        // A span that runs past the line (or is empty) is marked up to the line's end.
        let line_end = text[range.start..]
            .find('\n')
            .map_or(text.len(), |at| range.start + at);
        let end = range.end.min(line_end).max(range.start + 1) - line_start + 1;
        messages.push(format!("{line}:{start}-{end} {code}: {message}"));
        found.insert((line, start, end, code.to_owned()));
    }
    (found, messages)
}

#[test]
fn annotated_files_report_exactly_their_markers() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/annotated");
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|entry| entry.unwrap().path())
        .filter(|path| path.extension().is_some_and(|e| e == "st"))
        .collect();
    files.sort();
    assert!(!files.is_empty(), "the annotated cases are missing");
    let mut failures = Vec::new();
    for path in &files {
        let text = std::fs::read_to_string(path).unwrap();
        let want = expected(&text);
        let (got, messages) = actual(&text);
        if want != got {
            let name = path.file_name().unwrap().to_string_lossy();
            let missing: Vec<_> = want.difference(&got).collect();
            let extra: Vec<_> = got.difference(&want).collect();
            failures.push(format!(
                "{name}\n  missing: {missing:?}\n  unexpected: {extra:?}\n  all reported:\n    {}",
                messages.join("\n    ")
            ));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
}
