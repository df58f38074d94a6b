//! Every diagnostic code has a doc page under `docs/diagnostics/`, and every page a code.

#![allow(clippy::unwrap_used, clippy::expect_used)] // Test helpers may panic: a panic is a failed test.

use std::collections::BTreeSet;
use std::path::Path;

use compiler::{Code, Severity};

#[test]
fn codes_and_doc_pages_match_one_to_one() {
    let docs = Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/diagnostics");
    let pages: BTreeSet<String> = std::fs::read_dir(&docs)
        .unwrap()
        .map(|entry| entry.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|name| name != "README.md")
        .collect();
    let codes: BTreeSet<String> = Code::ALL
        .iter()
        .map(|code| format!("{}.md", code.id()))
        .collect();
    assert_eq!(
        pages, codes,
        "add a page for each new code, and a code for each page"
    );

    let index = std::fs::read_to_string(docs.join("README.md")).unwrap();
    for code in Code::ALL {
        let page = std::fs::read_to_string(docs.join(format!("{}.md", code.id()))).unwrap();
        let heading = format!("# {}: {}", code.id(), code.title());
        assert!(
            page.starts_with(&heading),
            "{} must start with '{heading}'",
            code.id()
        );
        let severity = match code.severity() {
            Severity::Error => "Severity: error.",
            Severity::Warning => "Severity: warning.",
        };
        assert!(
            page.contains(severity),
            "{} must say '{severity}'",
            code.id()
        );
        assert!(
            page.contains("## Example") && page.contains("## Fix"),
            "{} needs an example and a fix",
            code.id()
        );
        assert!(
            index.contains(&format!("[{0}]({0}.md)", code.id())),
            "{} missing from the index",
            code.id()
        );
    }
}

#[test]
fn code_identifiers_are_unique() {
    let ids: BTreeSet<&str> = Code::ALL.iter().map(|code| code.id()).collect();
    assert_eq!(ids.len(), Code::ALL.len());
}
