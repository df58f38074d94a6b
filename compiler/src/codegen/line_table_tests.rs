//! The line table (`docs/program-image.md` §11): one entry per line that starts a statement,
//! and the places the debugger halts at besides (`ELSIF` conditions, loop tests, SFC
//! transitions), while a fault still reports the line of the code that faulted.

use program_image::{Instr, Pou};

use crate::{SourceProject, compile_source};

/// The POU `Main` compiled from a program with `declarations` and `body`.
#[track_caller]
fn main_of(declarations: &str, body: &str) -> Pou {
    let source = format!("PROGRAM Main\nVAR\n{declarations}\nEND_VAR\n{body}\nEND_PROGRAM\n");
    let project = SourceProject::new(&source);
    let image = compile_source(&project, "test.st")
        .unwrap_or_else(|error| panic!("the source does not compile: {error}"));
    image
        .pous
        .into_iter()
        .find(|pou| pou.name == "Main")
        .unwrap_or_else(|| panic!("no Main"))
}

/// The line of instruction `index`: the entry at or before it, as a fault report finds it.
fn line_at(pou: &Pou, index: usize) -> u32 {
    let at = pou
        .lines
        .partition_point(|entry| entry.index as usize <= index);
    at.checked_sub(1).map_or(0, |at| pou.lines[at].line)
}

/// The lines of the entries, in order.
fn lines(pou: &Pou) -> Vec<u32> {
    pou.lines.iter().map(|entry| entry.line).collect()
}

/// Whether `index` is a statement start.
fn starts_statement(pou: &Pou, index: u32) -> bool {
    pou.lines.iter().any(|entry| entry.index == index)
}

/// The targets of the jumps that go backwards: the loops' back edges.
fn back_edges(pou: &Pou) -> Vec<u32> {
    pou.code
        .iter()
        .enumerate()
        .filter_map(|(at, instr)| match instr {
            Instr::Jump { target }
            | Instr::JumpIf { target, .. }
            | Instr::JumpIfNot { target, .. } => (*target as usize <= at).then_some(*target),
            _ => None,
        })
        .collect()
}

/// Entries are in ascending index order; a statement that starts with its first inner
/// statement (`REPEAT`) shares its index with it.
#[track_caller]
fn assert_ascending(pou: &Pou) {
    assert!(
        pou.lines
            .windows(2)
            .all(|pair| pair[0].index <= pair[1].index),
        "{:?}",
        pou.lines
    );
}

#[test]
fn every_elsif_condition_is_a_statement_start_of_its_line() {
    // Lines: 5 IF, 6 a := 1, 7 ELSIF, 8 a := 2, 9 ELSIF, 10 a := 3, 11 ELSE, 12 a := 4.
    let main = main_of(
        "a : INT; b : INT;",
        "IF b = 1 THEN\n    a := 1;\nELSIF b = 2 THEN\n    a := 2;\nELSIF 10 / b = 3 THEN\n    a := 3;\nELSE\n    a := 4;\nEND_IF;",
    );
    assert_eq!(lines(&main), [5, 6, 7, 8, 9, 10, 12]);
    assert_ascending(&main);
    // A fault in an ELSIF condition (a division by zero) is reported at the ELSIF's line,
    // not at the last statement of the branch before it.
    let division = main
        .code
        .iter()
        .position(|instr| {
            matches!(
                instr,
                Instr::Binary {
                    op: program_image::BinaryOp::Div,
                    ..
                }
            )
        })
        .unwrap_or_else(|| panic!("no division"));
    assert_eq!(line_at(&main, division), 9);
}

#[test]
fn a_for_loop_has_an_entry_where_it_starts_and_one_at_its_test() {
    // Lines: 5 FOR, 6 a := a + i, 7 END_FOR, 8 a := 0.
    let main = main_of(
        "a : INT; i : INT;",
        "FOR i := 1 TO 10 DO\n    a := a + i;\nEND_FOR;\na := 0;",
    );
    assert_eq!(lines(&main), [5, 5, 6, 8]);
    assert_ascending(&main);
    let edges = back_edges(&main);
    assert_eq!(edges.len(), 1, "{}", program_image::listing(&main.code));
    assert!(starts_statement(&main, edges[0]));
    assert_eq!(line_at(&main, edges[0] as usize), 5);
}

#[test]
fn a_for_loop_with_a_variable_step_tests_at_its_line_too() {
    let main = main_of(
        "a : INT; i : INT; s : INT := 2;",
        "FOR i := 1 TO 10 BY s DO\n    a := a + i;\nEND_FOR;",
    );
    for edge in back_edges(&main) {
        assert!(starts_statement(&main, edge));
        assert_eq!(line_at(&main, edge as usize), 5);
    }
}

#[test]
fn a_while_loop_jumps_back_to_its_test_which_starts_its_statement() {
    let main = main_of("a : INT;", "WHILE a < 10 DO\n    a := a + 1;\nEND_WHILE;");
    assert_eq!(lines(&main), [5, 6]);
    for edge in back_edges(&main) {
        assert!(starts_statement(&main, edge));
        assert_eq!(line_at(&main, edge as usize), 5);
    }
}

#[test]
fn a_repeat_loop_has_an_entry_at_its_until_test() {
    // Lines: 5 REPEAT, 6 a := a + 1, 7 UNTIL.
    let main = main_of(
        "a : INT;",
        "REPEAT\n    a := a + 1;\nUNTIL a > 10\nEND_REPEAT;",
    );
    assert_eq!(lines(&main), [5, 6, 7]);
    let test = main.lines[2].index as usize;
    assert!(
        matches!(main.code[test], Instr::Compare { .. }),
        "{}",
        program_image::listing(&main.code)
    );
}

#[test]
fn a_loop_whose_body_and_test_share_a_line_keeps_its_entries_in_order() {
    let main = main_of("a : INT;", "REPEAT a := a + 1; UNTIL a > 10 END_REPEAT;");
    assert_ascending(&main);
    let main = main_of("a : INT;", "REPEAT\n    ;\nUNTIL a > 10\nEND_REPEAT;");
    assert_ascending(&main);
    // The empty statement has no code: its instruction is the test's.
    assert_eq!(lines(&main), [5, 7]);
}

#[test]
fn every_sfc_step_and_transition_test_is_a_statement_start_of_its_line() {
    // Lines: 5 INITIAL_STEP, 6 END_STEP, 7 TRANSITION, 8 END_TRANSITION, 9 STEP Run, ...
    let main = main_of(
        "go : BOOL; done : BOOL;",
        "INITIAL_STEP Idle:\nEND_STEP\nTRANSITION FROM Idle TO Run := go;\nEND_TRANSITION\nSTEP Run:\nEND_STEP\nTRANSITION FROM Run TO Idle := done;\nEND_TRANSITION",
    );
    assert_ascending(&main);
    // Each step's active pass starts at its line, before the transitions are tested.
    assert_eq!(lines(&main), [5, 9, 7, 11]);
}
