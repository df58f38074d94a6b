//! CFC charts compiled and run cycle after cycle (`docs/graphical-semantics.md` §8): the
//! execution order decides what a wire reads, a feedback loop reads the previous cycle, and
//! connection marks, composers and selectors, EN/ENO and jumps do what the chart shows.
//!
//! Each chart is the body of the program `Main` of `DECLARATIONS`, run by the source's task
//! for a few cycles; the values are read from `Main` afterwards.

use project_model::{
    Body, CfcBox, CfcChart, CfcElement, CfcElementKind, CfcPin, CoilKind, ElementId, Object,
    PinRef, Wire,
};
use runtime::simulation::Simulation;

const DECLARATIONS: &str = "TYPE Pair : STRUCT n : INT; flag : BOOL; END_STRUCT END_TYPE
PROGRAM Main
VAR x, y, count, previous, n : INT; a, eno : BOOL; p : Pair; END_VAR
END_PROGRAM
";

fn element(id: u32, order: Option<u32>, kind: CfcElementKind) -> CfcElement {
    CfcElement {
        id: ElementId(id),
        x: 0,
        y: 0,
        order,
        kind,
    }
}

fn input(id: u32, expression: &str) -> CfcElement {
    element(
        id,
        None,
        CfcElementKind::Input {
            expression: expression.into(),
        },
    )
}

fn output(id: u32, order: u32, expression: &str) -> CfcElement {
    element(
        id,
        Some(order),
        CfcElementKind::Output {
            expression: expression.into(),
            coil: CoilKind::Normal,
        },
    )
}

fn pins(names: &[&str]) -> Vec<CfcPin> {
    names.iter().map(|name| CfcPin::named(*name)).collect()
}

fn boxed(id: u32, order: u32, type_name: &str, inputs: &[&str], outputs: &[&str]) -> CfcElement {
    element(
        id,
        Some(order),
        CfcElementKind::Box(CfcBox {
            type_name: type_name.into(),
            instance: String::new(),
            inputs: pins(inputs),
            outputs: pins(outputs),
        }),
    )
}

fn wire(from: u32, from_pin: &str, to: u32, to_pin: &str) -> Wire {
    Wire::routed(
        PinRef::new(ElementId(from), from_pin),
        PinRef::new(ElementId(to), to_pin),
    )
}

/// Runs `Main` with the chart as its body for `cycles` cycles.
#[track_caller]
fn run(elements: Vec<CfcElement>, wires: Vec<Wire>, cycles: u64) -> Simulation {
    let chart = CfcChart { elements, wires };
    assert_eq!(project_model::cfc_problems(&chart), Vec::new());
    let built = compiler::SourceProject::new(DECLARATIONS);
    assert!(
        built.parse.errors().is_empty(),
        "{:?}",
        built.parse.errors()
    );
    let mut project = built.project;
    if let Some(Object::Pou(main)) = project.application.object_mut("Main") {
        main.body = Body::Cfc { chart };
    }
    let image = match compiler::compile_project(&project) {
        Ok(image) => image,
        Err(compiler::CompileError::Diagnostics(found)) => {
            let errors: Vec<String> = found
                .iter()
                .filter(|d| d.diagnostic.severity == compiler::Severity::Error)
                .map(|d| format!("{:?}: {}", d.element, d.diagnostic.message))
                .collect();
            panic!("the chart does not check: {errors:#?}")
        }
        Err(error) => panic!("the chart does not compile: {error}"),
    };
    let simulation = crate::simulate(image, cycles);
    assert!(simulation.faults().is_empty(), "{:?}", simulation.faults());
    simulation
}

/// The value of `Main.<name>` as an IEC literal.
#[track_caller]
fn value(simulation: &Simulation, name: &str) -> String {
    let path = format!("Main.{name}");
    runtime::value::read(simulation.engine(), &path)
        .unwrap_or_else(|e| panic!("{path}: {e}"))
        .to_string()
}

/// `x := x + 1` and `y := x`, with the output of `y` first or last in the order.
fn increment_and_copy(copy_first: bool) -> (Vec<CfcElement>, Vec<Wire>) {
    let (add, store, copy) = if copy_first { (1, 2, 0) } else { (0, 1, 2) };
    (
        vec![
            input(1, "x"),
            input(2, "1"),
            boxed(3, add, "ADD", &["IN1", "IN2"], &["OUT"]),
            output(4, store, "x"),
            output(5, copy, "y"),
        ],
        vec![
            wire(1, "", 3, "IN1"),
            wire(2, "", 3, "IN2"),
            wire(3, "OUT", 4, ""),
            wire(1, "", 5, ""),
        ],
    )
}

#[test]
fn changing_the_execution_order_changes_the_result() {
    let (elements, wires) = increment_and_copy(false);
    let after = run(elements, wires, 3);
    assert_eq!(value(&after, "x"), "3");
    assert_eq!(value(&after, "y"), "3");
    let (elements, wires) = increment_and_copy(true);
    let before = run(elements, wires, 3);
    assert_eq!(value(&before, "x"), "3");
    assert_eq!(value(&before, "y"), "2");
}

#[test]
fn a_feedback_loop_counts_one_per_cycle_reading_the_previous_scan() {
    // The ADD's output is wired into its own input; a MOVE earlier in the order reads the
    // same output before the ADD runs, so it sees the previous cycle's count.
    let elements = vec![
        input(1, "1"),
        boxed(2, 1, "ADD", &["IN1", "IN2"], &["OUT"]),
        output(3, 2, "count"),
        boxed(4, 0, "MOVE", &["IN"], &["OUT"]),
        output(5, 3, "previous"),
    ];
    let wires = vec![
        wire(2, "OUT", 2, "IN1"),
        wire(1, "", 2, "IN2"),
        wire(2, "OUT", 3, ""),
        wire(2, "OUT", 4, "IN"),
        wire(4, "OUT", 5, ""),
    ];
    let simulation = run(elements, wires, 5);
    assert_eq!(value(&simulation, "count"), "5");
    assert_eq!(value(&simulation, "previous"), "4");
}

#[test]
fn connection_marks_carry_a_value_across_the_chart() {
    let elements = vec![
        input(1, "x + 7"),
        element(
            2,
            None,
            CfcElementKind::ConnectionSource {
                name: "Level".into(),
            },
        ),
        element(
            3,
            None,
            CfcElementKind::ConnectionSink {
                name: "LEVEL".into(),
            },
        ),
        output(4, 0, "y"),
    ];
    let wires = vec![wire(1, "", 2, ""), wire(3, "", 4, "")];
    let simulation = run(elements, wires, 1);
    assert_eq!(value(&simulation, "y"), "7");
}

#[test]
fn a_composer_builds_a_structure_and_a_selector_takes_it_apart() {
    let elements = vec![
        input(1, "41"),
        input(2, "TRUE"),
        element(
            3,
            Some(0),
            CfcElementKind::Composer {
                type_name: "Pair".into(),
                inputs: pins(&["n", "flag"]),
            },
        ),
        output(4, 1, "p"),
        input(5, "p"),
        element(
            6,
            Some(2),
            CfcElementKind::Selector {
                type_name: "Pair".into(),
                outputs: pins(&["n", "flag"]),
            },
        ),
        output(7, 3, "y"),
        output(8, 4, "a"),
    ];
    let wires = vec![
        wire(1, "", 3, "n"),
        wire(2, "", 3, "flag"),
        wire(3, "", 4, ""),
        wire(5, "", 6, ""),
        wire(6, "n", 7, ""),
        wire(6, "flag", 8, ""),
    ];
    let simulation = run(elements, wires, 1);
    assert_eq!(value(&simulation, "p.n"), "41");
    assert_eq!(value(&simulation, "y"), "41");
    assert_eq!(value(&simulation, "a"), "TRUE");
}

#[test]
fn a_box_with_en_false_keeps_its_output_and_its_eno_is_false() {
    // A counter enabled while it is below 3: it stops there and its ENO goes FALSE.
    let elements = vec![
        input(1, "count < 3"),
        input(2, "1"),
        boxed(3, 0, "ADD", &["EN", "IN1", "IN2"], &["ENO", "OUT"]),
        output(4, 1, "count"),
        output(5, 2, "eno"),
    ];
    let wires = vec![
        wire(1, "", 3, "EN"),
        wire(3, "OUT", 3, "IN1"),
        wire(2, "", 3, "IN2"),
        wire(3, "OUT", 4, ""),
        wire(3, "ENO", 5, ""),
    ];
    let simulation = run(elements.clone(), wires.clone(), 2);
    assert_eq!(value(&simulation, "count"), "2");
    assert_eq!(value(&simulation, "eno"), "TRUE");
    let simulation = run(elements, wires, 10);
    assert_eq!(value(&simulation, "count"), "3");
    assert_eq!(value(&simulation, "eno"), "FALSE");
}

#[test]
fn a_jump_skips_the_elements_up_to_its_label() {
    // `n` counts every cycle; once it reaches 2 the jump skips the copy into `y`.
    let elements = vec![
        input(1, "n"),
        input(2, "1"),
        boxed(3, 0, "ADD", &["IN1", "IN2"], &["OUT"]),
        output(4, 1, "n"),
        input(5, "n >= 2"),
        element(
            6,
            Some(2),
            CfcElementKind::Jump {
                label: "Done".into(),
            },
        ),
        output(7, 3, "y"),
        element(
            8,
            Some(4),
            CfcElementKind::Label {
                name: "Done".into(),
            },
        ),
    ];
    let wires = vec![
        wire(1, "", 3, "IN1"),
        wire(2, "", 3, "IN2"),
        wire(3, "OUT", 4, ""),
        wire(5, "", 6, ""),
        wire(1, "", 7, ""),
    ];
    let simulation = run(elements, wires, 5);
    assert_eq!(value(&simulation, "n"), "5");
    assert_eq!(value(&simulation, "y"), "1");
}
