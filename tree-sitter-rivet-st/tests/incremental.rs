//! Editing a tree and reparsing it gives the same tree as parsing the new text afresh, also
//! where the external scanner decides (comments, SFC steps, property accessors).

#![allow(clippy::unwrap_used, clippy::expect_used)] // Test helpers may panic: a panic is a failed test.

use tree_sitter::{InputEdit, Parser, Point, Tree};

const TEXT: &str = "\
FUNCTION_BLOCK FB
VAR x : INT; Step : INT; END_VAR
PROPERTY P : INT
GET
P := x;
END_GET
END_PROPERTY
Step := 1;
IF x > 0 THEN
    x := x - 1; (* count down *)
END_IF
CASE x OF
    1: x := 2;
    2: x := 3;
END_CASE
END_FUNCTION_BLOCK
";

fn parser() -> Parser {
    let mut parser = Parser::new();
    parser
        .set_language(&tree_sitter_rivet_st::language())
        .unwrap();
    parser
}

fn point_at(text: &str, byte: usize) -> Point {
    let before = &text[..byte];
    let row = before.matches('\n').count();
    let column = byte - before.rfind('\n').map_or(0, |newline| newline + 1);
    Point::new(row, column)
}

/// Replaces `old` (its first occurrence) with `new` in `text`, edits `tree` to match and
/// reparses incrementally; returns the new text and tree.
fn edit(parser: &mut Parser, text: &str, tree: &mut Tree, old: &str, new: &str) -> (String, Tree) {
    let start = text
        .find(old)
        .unwrap_or_else(|| panic!("{old:?} is in the text"));
    let edited = format!("{}{new}{}", &text[..start], &text[start + old.len()..]);
    tree.edit(&InputEdit {
        start_byte: start,
        old_end_byte: start + old.len(),
        new_end_byte: start + new.len(),
        start_position: point_at(text, start),
        old_end_position: point_at(text, start + old.len()),
        new_end_position: point_at(&edited, start + new.len()),
    });
    let reparsed = parser.parse(&edited, Some(tree)).unwrap();
    (edited, reparsed)
}

#[test]
fn incremental_reparses_match_fresh_parses() {
    let edits = [
        // Opening a comment swallows the rest; closing it again restores the code.
        ("IF x > 0", "(* IF x > 0"),
        ("(* IF x > 0", "(* IF *) x := 0; IF x > 0"),
        // A nested comment closes only at its own end.
        ("(* count down *)", "(* count (* down *)"),
        ("(* count (* down *)", "(* count (* down *) *)"),
        // A variable called Step becomes a step, and back.
        ("Step := 1;", "STEP S1: x := 1; END_STEP"),
        ("STEP S1: x := 1; END_STEP", "Step := 1;"),
        // GET stops being an accessor when it is assigned.
        ("GET\n", "GET := 1;\n"),
        ("GET := 1;\n", "GET\n"),
        // A case label turns into a statement and back.
        ("2: x := 3;", "y := 3;"),
        ("y := 3;", "2: x := 3;"),
    ];
    let mut parser = parser();
    let mut text = TEXT.to_owned();
    let mut tree = parser.parse(&text, None).unwrap();
    for (old, new) in edits {
        let (edited, reparsed) = edit(&mut parser, &text, &mut tree, old, new);
        let fresh = parser.parse(&edited, None).unwrap();
        assert_eq!(
            reparsed.root_node().to_sexp(),
            fresh.root_node().to_sexp(),
            "after replacing {old:?} with {new:?}"
        );
        text = edited;
        tree = reparsed;
    }
    assert!(
        !tree.root_node().has_error(),
        "{}",
        tree.root_node().to_sexp()
    );
}
