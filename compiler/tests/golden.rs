//! Golden parser trees: each `tests/golden/*.st` is parsed and its tree and errors compared
//! with the `.tree` file beside it. Run with `UPDATE_GOLDEN=1` to rewrite the `.tree` files
//! after a deliberate change to the parser, and review the diff.

#![allow(clippy::unwrap_used, clippy::expect_used)] // Test helpers may panic: a panic is a failed test.

use std::path::Path;

#[test]
fn parser_trees_match_their_golden_files() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/golden");
    let update = std::env::var_os("UPDATE_GOLDEN").is_some();
    let mut sources: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|entry| entry.unwrap().path())
        .filter(|path| path.extension().is_some_and(|e| e == "st"))
        .collect();
    sources.sort();
    assert!(sources.len() >= 4);
    let mut stale = Vec::new();
    for source in &sources {
        let text = std::fs::read_to_string(source).unwrap();
        let tree = compiler::syntax::parse(&text).debug_tree();
        let golden = source.with_extension("tree");
        if update {
            std::fs::write(&golden, &tree).unwrap();
            continue;
        }
        let expected = std::fs::read_to_string(&golden).unwrap_or_default();
        if expected != tree {
            stale.push(golden.display().to_string());
        }
    }
    assert!(
        stale.is_empty(),
        "these trees changed (run with UPDATE_GOLDEN=1 and review the diff): {stale:?}"
    );
}
