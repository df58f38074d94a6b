//! Places against the line table of a small compiled program.

#![allow(clippy::unwrap_used, clippy::expect_used)] // A panic is a failed test.

use super::*;

/// Line numbers matter here: each statement's line is named in the tests.
const SOURCE: &str = "FUNCTION_BLOCK FB_Counter
VAR_INPUT step : INT; END_VAR
VAR count : INT; END_VAR
(* counts by step *)
count := count + step;
IF count > 100 THEN
    count := 0;
END_IF
END_FUNCTION_BLOCK

PROGRAM Main
VAR fbA : FB_Counter; fbB : FB_Counter; END_VAR
fbA(step := 1);
fbB(step := 2);
END_PROGRAM
";

fn image() -> ProgramImage {
    let source = compiler::SourceProject::new(SOURCE);
    compiler::compile_source(&source, "pous/counter.st").unwrap()
}

#[track_caller]
fn at(place: &str) -> Statement {
    statement_at(&image(), place).unwrap_or_else(|error| panic!("{place}: {error}"))
}

#[test]
fn a_file_line_names_the_statement_on_it_by_a_unique_end_of_the_path() {
    let statement = at("counter.st:5");
    assert_eq!(statement.pou_name, "FB_Counter");
    assert_eq!(
        (statement.file.as_str(), statement.line),
        ("pous/counter.st", 5)
    );
    assert_eq!(statement.to_string(), "pous/counter.st:5 (FB_Counter)");
    assert_eq!(at("pous/counter.st:13").pou_name, "Main");
}

#[test]
fn a_line_without_a_statement_names_the_next_statement_after_it() {
    // Line 4 is a comment: the statement on line 5 is meant.
    assert_eq!(at("counter.st:4"), at("counter.st:5"));
    // Line 12 declares Main's variables: its first statement is on line 13.
    let statement = at("counter.st:12");
    assert_eq!((statement.pou_name.as_str(), statement.line), ("Main", 13));
}

#[test]
fn a_pou_and_a_line_name_a_statement_of_that_pou() {
    assert_eq!(at("fb_counter:7"), at("counter.st:7"));
    assert_eq!(at("Main:1").line, 13);
}

#[test]
fn places_the_program_does_not_have_are_refused_saying_why() {
    let image = image();
    let error = statement_at(&image, "counter.st:40").unwrap_err();
    assert!(
        matches!(
            error,
            PlaceError::NoStatement {
                line: 40,
                last: 14,
                ..
            }
        ),
        "{error}"
    );
    assert!(error.to_string().contains("pous/counter.st:40"), "{error}");
    let error = statement_at(&image, "other.st:3").unwrap_err();
    assert!(error.to_string().contains("pous/counter.st"), "{error}");
    for wrong in ["counter.st", "counter.st:x", "counter.st:0", ":5"] {
        assert!(
            matches!(statement_at(&image, wrong), Err(PlaceError::Syntax(_))),
            "{wrong}"
        );
    }
}

#[test]
fn an_instruction_prints_as_the_statement_it_belongs_to() {
    let image = image();
    let statement = at("counter.st:7");
    let inside = statement_of(&image, statement.pou, statement.instruction + 1).unwrap();
    assert_eq!(inside.line, 7);
    assert_eq!(
        statement_of(&image, statement.pou, statement.instruction),
        Some(statement)
    );
    assert_eq!(statement_of(&image, 99, 0), None);
}

#[test]
fn an_fb_body_runs_on_its_own_instance_and_a_function_on_none() {
    let source = compiler::SourceProject::new(
        "FUNCTION Twice : INT VAR_INPUT x : INT; END_VAR Twice := x * 2; END_FUNCTION
PROGRAM Main VAR n : INT; END_VAR n := Twice(n); END_PROGRAM
",
    );
    let image = compiler::compile_source(&source, "f.st").unwrap();
    let twice = image.pous.iter().position(|p| p.name == "Twice").unwrap() as u32;
    let main = image.pous.iter().position(|p| p.name == "Main").unwrap() as u32;
    assert_eq!(instance_owner(&image, twice), None);
    assert_eq!(instance_owner(&image, main), Some("Main"));
}
