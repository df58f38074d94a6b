use super::*;
use crate::{SourceProject, compile_project};

const SOURCE: &str = "FUNCTION_BLOCK FB_Counter
VAR_INPUT
    step : INT;
END_VAR
VAR_OUTPUT
    count : DINT;
END_VAR
VAR
    name : STRING(20);
END_VAR
count := count + step;
name := 'counting';
END_FUNCTION_BLOCK

FUNCTION Twice : DINT
VAR_INPUT
    x : DINT;
END_VAR
VAR
    t : DINT;
END_VAR
t := x * 2;
Twice := t;
END_FUNCTION

PROGRAM Main
VAR
    fbA : FB_Counter;
    a : ARRAY[1..5] OF INT;
    i : INT := 1;
    big : DINT;
END_VAR
fbA(step := 1);
a[i] := 2;
big := Twice(fbA.count);
END_PROGRAM
";

fn project() -> Project {
    let source = SourceProject::new(SOURCE);
    assert!(
        source.parse.errors().is_empty(),
        "{:?}",
        source.parse.errors()
    );
    source.project
}

#[track_caller]
fn compiled(pou: &str, expression: &str) -> CompiledCondition {
    match compile_condition(&project(), pou, expression) {
        Ok(compiled) => compiled,
        Err(error) => panic!("'{expression}' in {pou} does not compile: {error}"),
    }
}

#[track_caller]
fn refused(pou: &str, expression: &str) -> ConditionCompileError {
    match compile_condition(&project(), pou, expression) {
        Ok(compiled) => panic!("'{expression}' in {pou} compiled: {compiled:?}"),
        Err(error) => error,
    }
}

fn image() -> program_image::ProgramImage {
    match compile_project(&project()) {
        Ok(image) => image,
        Err(CompileError::Diagnostics(found)) => {
            let errors: Vec<&str> = found
                .iter()
                .map(|d| d.diagnostic.message.as_str())
                .collect();
            panic!("the source does not check: {errors:#?}")
        }
        Err(error) => panic!("the source does not compile: {error}"),
    }
}

#[test]
fn a_comparison_of_an_instance_variable_compiles_for_the_image_the_project_compiles_to() {
    let image = image();
    let compiled = compiled("FB_Counter", "count > 100");
    let pou = &image.pous[compiled.pou as usize];
    assert_eq!(pou.name, "FB_Counter");
    assert_eq!(
        compiled.image,
        image.identity(),
        "the build is left as it was"
    );
    assert_eq!(
        image.verify_condition(compiled.pou, &compiled.condition),
        Ok(())
    );
    let condition = &compiled.condition;
    assert!(condition.result >= pou.frame_size);
    assert!(condition.result < pou.frame_size + condition.scratch_bytes);
    let listing = program_image::listing(&condition.code);
    assert!(listing.contains("gt DINT"), "{listing}");
}

#[test]
fn a_constant_the_image_does_not_have_lives_in_the_scratch_area() {
    let compiled = compiled("FB_Counter", "count = 123456789");
    let bytes = 123_456_789_i32.to_le_bytes();
    assert!(
        compiled.condition.init.windows(4).any(|w| w == bytes),
        "{:?}",
        compiled.condition
    );
    assert_eq!(compiled.image, image().identity());
}

#[test]
fn a_function_condition_sees_its_parameters_and_locals_and_an_array_element_its_index() {
    compiled("Twice", "x = 3 AND t < 10");
    // The element is read without a pointer, into the condition's scratch area.
    let element = compiled("Main", "a[i] = 0 OR fbA.count > big");
    let listing = program_image::listing(&element.condition.code);
    assert!(listing.contains("loadelement INT"), "{listing}");
    assert_eq!(
        image().verify_condition(element.pou, &element.condition),
        Ok(())
    );
    compiled("FB_Counter", "name = 'conveyor'");
}

#[test]
fn a_condition_may_read_the_clock_and_the_verifier_lets_it() {
    let image = image();
    let compiled = compiled("Main", "LTIME() > LTIME#1s AND TIME() < T#1h");
    assert_eq!(
        image.verify_condition(compiled.pou, &compiled.condition),
        Ok(())
    );
    let listing = program_image::listing(&compiled.condition.code);
    let operations: Vec<&str> = listing
        .lines()
        .filter_map(|line| line.split_whitespace().nth(1))
        .collect();
    assert!(
        operations.contains(&"ltime") && operations.contains(&"time"),
        "{listing}"
    );
}

#[test]
fn an_unknown_name_is_reported_at_its_place_in_the_expression() {
    let ConditionCompileError::Diagnostics(found) = refused("Main", "i > 0 AND nope") else {
        panic!("expected the checker's errors");
    };
    assert!(
        found
            .iter()
            .any(|d| d.range == (10..14) && d.message.contains("nope")),
        "{found:?}"
    );
}

#[test]
fn a_condition_that_is_not_bool_is_refused_with_its_type() {
    let error = refused("FB_Counter", "count + 1");
    assert!(
        matches!(&error, ConditionCompileError::NotBool { found, .. } if found == "DINT"),
        "{error:?}"
    );
    assert!(error.to_string().contains("not BOOL"));
}

#[test]
fn text_that_is_not_one_expression_is_refused() {
    for text in [
        "",
        "   ",
        "i > 1 THEN i := 0; END_IF; IF TRUE",
        "i > 1 THEN ELSE i := 0",
    ] {
        let error = refused("Main", text);
        assert!(
            matches!(
                error,
                ConditionCompileError::NotAnExpression(_) | ConditionCompileError::Diagnostics(_)
            ),
            "'{text}': {error:?}"
        );
    }
}

#[test]
fn a_call_is_refused_because_it_could_change_the_program() {
    let error = refused("Main", "Twice(big) > 0");
    assert!(
        matches!(error, ConditionCompileError::Calls(_)),
        "{error:?}"
    );
}

#[test]
fn a_pou_the_program_does_not_have_is_named() {
    let error = refused("FB_Missing", "TRUE");
    assert!(matches!(&error, ConditionCompileError::UnknownPou(name) if name == "FB_Missing"));
    assert!(error.to_string().contains("'FB_Missing'"));
}

#[test]
fn a_condition_of_a_source_file_belongs_to_the_image_of_that_file() {
    let source = SourceProject::new(SOURCE);
    let image = crate::compile_source(&source, "counter.st").unwrap_or_else(|e| panic!("{e}"));
    let compiled = compile_source_condition(&source, "counter.st", "Main", "big > 3")
        .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(compiled.image, image.identity());
    assert_eq!(
        image.verify_condition(compiled.pou, &compiled.condition),
        Ok(())
    );
}

#[test]
fn a_method_condition_sees_its_own_parameters_and_its_instance() {
    let source = "FUNCTION_BLOCK FB_Axis
VAR_OUTPUT
    position : LREAL;
END_VAR
METHOD MoveBy : BOOL
VAR_INPUT
    distance : LREAL;
END_VAR
position := position + distance;
MoveBy := TRUE;
END_METHOD
END_FUNCTION_BLOCK

PROGRAM Main
VAR
    axis : FB_Axis;
    moved : BOOL;
END_VAR
moved := axis.MoveBy(distance := 1.5);
END_PROGRAM
";
    let project = SourceProject::new(source).project;
    let compiled = compile_condition(
        &project,
        "FB_Axis.MoveBy",
        "distance > 1.0 AND position < 10.0",
    )
    .unwrap_or_else(|error| panic!("{error}"));
    let image = compile_project(&project).unwrap_or_else(|error| panic!("{error}"));
    assert_eq!(image.pous[compiled.pou as usize].name, "FB_Axis.MoveBy");
    assert_eq!(compiled.image, image.identity());
}
