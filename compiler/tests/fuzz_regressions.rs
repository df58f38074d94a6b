//! Inputs the fuzzer found (crashes, hangs, slow cases), kept so they stay fixed.

#![allow(clippy::unwrap_used, clippy::expect_used)] // Test helpers may panic: a panic is a failed test.

use std::path::Path;

#[test]
fn every_fuzz_finding_parses_losslessly_and_checks() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fuzz_regressions");
    let mut count = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        let bytes = std::fs::read(&path).unwrap();
        let text = String::from_utf8_lossy(&bytes);
        for parse in [
            compiler::syntax::parse(&text),
            compiler::syntax::parse_statements(&text),
            compiler::syntax::parse_declaration_part(&text),
        ] {
            assert_eq!(parse.syntax().to_string(), text, "{}", path.display());
            for error in parse.errors() {
                assert!(error.range.end <= text.len());
                error.render("fuzz.st", &text);
            }
        }
        // The checker, on the file as a project of its own: every finding it maps back must
        // point inside the text.
        let source = compiler::source_project::SourceProject::new(&text);
        for found in compiler::sema::check_project(&source.project) {
            if let Some(range) = source.locate(&found) {
                assert!(
                    range.start <= range.end && range.end <= text.len(),
                    "{}: {found:?} maps to {range:?}",
                    path.display()
                );
            }
        }
        count += 1;
    }
    assert!(count > 0);
}
