//! The queries compile against the language and capture what the editor needs.

#![allow(clippy::unwrap_used, clippy::expect_used)] // Test helpers may panic: a panic is a failed test.

use std::collections::HashMap;

use tree_sitter::{Parser, Query, QueryCursor, StreamingIterator, Tree};
use tree_sitter_rivet_st::{FOLDS_QUERY, HIGHLIGHTS_QUERY, LOCALS_QUERY, language};

fn parse(text: &str) -> Tree {
    let mut parser = Parser::new();
    parser.set_language(&language()).unwrap();
    let tree = parser.parse(text, None).unwrap();
    assert!(
        !tree.root_node().has_error(),
        "the sample must parse cleanly: {}",
        tree.root_node().to_sexp()
    );
    tree
}

/// For every captured byte range, the capture name of the first pattern that captures it,
/// as tree-sitter-highlight decides.
fn winning_captures(query_source: &str, text: &str) -> HashMap<(usize, usize), String> {
    let query = Query::new(&language(), query_source).unwrap();
    let tree = parse(text);
    let mut cursor = QueryCursor::new();
    let mut best: HashMap<(usize, usize), (usize, String)> = HashMap::new();
    let mut matches = cursor.matches(&query, tree.root_node(), text.as_bytes());
    while let Some(found) = matches.next() {
        for capture in found.captures() {
            let range = (capture.node.start_byte(), capture.node.end_byte());
            let name = query.capture_names()[capture.index as usize].to_owned();
            let entry = best
                .entry(range)
                .or_insert((found.pattern_index, name.clone()));
            if found.pattern_index < entry.0 {
                *entry = (found.pattern_index, name);
            }
        }
    }
    best.into_iter()
        .map(|(range, (_, name))| (range, name))
        .collect()
}

/// The byte range of the `occurrence`-th (from 0) `needle` in `text`; a needle that starts or
/// ends with a letter only matches whole words, so `IN` is not found inside `INT`.
#[track_caller]
fn range_of(text: &str, needle: &str, occurrence: usize) -> (usize, usize) {
    let is_word = |c: char| c.is_alphanumeric() || c == '_';
    let start = text
        .match_indices(needle)
        .map(|(start, _)| start)
        .filter(|&start| {
            let before = text[..start].chars().next_back();
            let after = text[start + needle.len()..].chars().next();
            let joined_before = needle.starts_with(is_word) && before.is_some_and(is_word);
            let joined_after = needle.ends_with(is_word) && after.is_some_and(is_word);
            !joined_before && !joined_after
        })
        .nth(occurrence)
        .unwrap_or_else(|| panic!("{needle:?} occurs fewer than {} times", occurrence + 1));
    (start, start + needle.len())
}

#[test]
fn the_three_queries_compile_against_the_language() {
    for (name, source) in [
        ("highlights", HIGHLIGHTS_QUERY),
        ("folds", FOLDS_QUERY),
        ("locals", LOCALS_QUERY),
    ] {
        let query = Query::new(&language(), source);
        assert!(query.is_ok(), "{name}: {:?}", query.err());
        assert!(query.unwrap().pattern_count() > 0, "{name} has no pattern");
    }
}

const HIGHLIGHT_SAMPLE: &str = "\
FUNCTION_BLOCK FB_Demo
VAR
    nCount : INT := 16#FF; // counter
    sName : STRING(20) := 'abc';
    fbTimer : FB_Timer;
    aThings : ARRAY[1..2] OF Lib.T_Thing;
END_VAR
(* block (* nested *) *)
IF nCount > 0 AND xReady THEN
    fbTimer(IN := TRUE);
    nCount := fbTimer.ET + T#1s;
    fbAxis.Reset();
END_IF
END_FUNCTION_BLOCK
";

#[test]
fn highlights_capture_keywords_types_literals_comments_calls_variables_and_operators() {
    let captures = winning_captures(HIGHLIGHTS_QUERY, HIGHLIGHT_SAMPLE);
    let expected = [
        ("FUNCTION_BLOCK", 0, "keyword"),
        ("END_VAR", 0, "keyword"),
        ("IF", 0, "keyword.conditional"),
        ("AND", 0, "keyword.operator"),
        ("FB_Demo", 0, "type"),
        ("INT", 0, "type.builtin"),
        ("FB_Timer", 0, "type"),
        ("Lib", 0, "type"),
        ("T_Thing", 0, "type"),
        ("STRING", 0, "type.builtin"),
        ("16#FF", 0, "number"),
        ("20", 0, "number"),
        ("T#1s", 0, "number"),
        ("'abc'", 0, "string"),
        ("TRUE", 0, "constant.builtin"),
        ("// counter", 0, "comment"),
        ("(* block (* nested *) *)", 0, "comment"),
        ("fbTimer", 0, "variable"),
        ("fbTimer", 1, "function.call"),
        ("Reset", 0, "function.method.call"),
        ("IN", 0, "variable.parameter"),
        ("nCount", 0, "variable"),
        ("nCount", 1, "variable"),
        ("xReady", 0, "variable"),
        ("fbTimer", 2, "variable"),
        ("ET", 0, "property"),
        (":=", 0, "operator"),
        (">", 0, "operator"),
        ("+", 0, "operator"),
        (";", 0, "punctuation.delimiter"),
        ("(", 3, "punctuation.bracket"),
    ];
    let mut wrong = Vec::new();
    for (needle, occurrence, capture) in expected {
        let found = captures.get(&range_of(HIGHLIGHT_SAMPLE, needle, occurrence));
        if found.map(String::as_str) != Some(capture) {
            wrong.push(format!(
                "{needle:?} #{occurrence}: expected @{capture}, found {found:?}"
            ));
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

#[test]
fn folds_cover_pous_variable_blocks_and_control_statements() {
    let text = "\
PROGRAM Main
VAR
    i : INT;
END_VAR
IF i > 0 THEN
    i := 0;
END_IF
CASE i OF
    1:
        i := 2;
END_CASE
FOR i := 1 TO 10 DO
    ;
END_FOR
WHILE FALSE DO
END_WHILE
METHOD Reset
END_METHOD
END_PROGRAM
";
    let query = Query::new(&language(), FOLDS_QUERY).unwrap();
    let tree = parse(text);
    let mut cursor = QueryCursor::new();
    let mut folds = Vec::new();
    let mut captures = cursor.captures(&query, tree.root_node(), text.as_bytes());
    while let Some((found, index)) = captures.next() {
        let node = found.captures()[*index].node;
        folds.push((
            node.kind().to_owned(),
            node.start_position().row + 1,
            node.end_position().row + 1,
        ));
    }
    for expected in [
        ("program_declaration", 1, 19),
        ("var_block", 2, 4),
        ("if_statement", 5, 7),
        ("case_statement", 8, 11),
        ("case_branch", 9, 10),
        ("for_statement", 12, 14),
        ("while_statement", 15, 16),
        ("method_declaration", 17, 18),
    ] {
        let expected = (expected.0.to_owned(), expected.1, expected.2);
        assert!(folds.contains(&expected), "{expected:?} not in {folds:?}");
    }
}

#[test]
fn locals_define_declared_variables_inside_their_pou() {
    let text = "FUNCTION F : INT\nVAR_INPUT a : INT; END_VAR\nF := a;\nEND_FUNCTION\n";
    let captures = winning_captures(LOCALS_QUERY, text);
    assert_eq!(
        captures.get(&range_of(text, "a", 0)).map(String::as_str),
        Some("local.definition")
    );
    assert_eq!(
        captures.get(&range_of(text, "a", 1)).map(String::as_str),
        Some("local.reference")
    );
    assert_eq!(
        captures.get(&(0, text.len() - 1)).map(String::as_str),
        Some("local.scope")
    );
}
