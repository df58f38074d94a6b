use super::*;
use crate::{CfcBox, CfcPin, Wire};

fn element(id: u32, order: Option<u32>, kind: CfcElementKind) -> CfcElement {
    CfcElement {
        id: ElementId(id),
        x: 0,
        y: 0,
        order,
        kind,
    }
}

fn pin(name: &str) -> CfcPin {
    CfcPin::named(name)
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
            coil: crate::CoilKind::Normal,
        },
    )
}

fn add(id: u32, order: u32) -> CfcElement {
    element(
        id,
        Some(order),
        CfcElementKind::Box(CfcBox {
            type_name: "ADD".into(),
            instance: String::new(),
            inputs: vec![pin("IN1"), pin("IN2")],
            outputs: vec![pin("OUT")],
        }),
    )
}

fn wire(from: u32, from_pin: &str, to: u32, to_pin: &str) -> Wire {
    Wire::routed(
        PinRef::new(ElementId(from), from_pin),
        PinRef::new(ElementId(to), to_pin),
    )
}

/// `a + b` into `c`, sound.
fn sound() -> CfcChart {
    CfcChart {
        elements: vec![input(1, "a"), input(2, "b"), add(3, 0), output(4, 1, "c")],
        wires: vec![
            wire(1, "", 3, "IN1"),
            wire(2, "", 3, "in2"),
            wire(3, "OUT", 4, ""),
        ],
    }
}

fn messages(chart: &CfcChart) -> Vec<String> {
    cfc_problems(chart)
        .iter()
        .map(ToString::to_string)
        .collect()
}

#[test]
fn a_sound_chart_has_no_problem_and_pins_match_without_case() {
    assert_eq!(messages(&sound()), Vec::<String>::new());
    // A feedback wire (an output into an input of the same box) is allowed.
    let mut chart = sound();
    chart.wires[1] = wire(3, "out", 3, "IN2");
    assert_eq!(messages(&chart), Vec::<String>::new());
}

#[test]
fn ids_are_unique() {
    let mut chart = sound();
    chart.elements.push(input(2, "x"));
    assert_eq!(messages(&chart), ["element 2: two elements have the id 2"]);
}

#[test]
fn the_elements_that_run_are_numbered_densely_and_the_others_not_at_all() {
    let mut chart = sound();
    chart.elements[2].order = None;
    chart.elements[0].order = Some(0);
    assert_eq!(
        messages(&chart),
        [
            "element 1: the element does not run by itself, so it has no place in the execution order, but is numbered 0",
            "element 3: the element runs, so it needs a number in the execution order",
        ]
    );
    let mut chart = sound();
    chart.elements[3].order = Some(0);
    assert_eq!(
        messages(&chart),
        ["element 4: the execution order number 0 is also element 3's"]
    );
    let mut chart = sound();
    chart.elements[3].order = Some(2);
    assert_eq!(
        messages(&chart),
        [
            "element 4: the execution order number 2 is out of range: the 2 elements that run are numbered 0 to 1"
        ]
    );
}

#[test]
fn wires_join_existing_elements_from_an_output_pin_to_an_input_pin() {
    let mut chart = sound();
    chart.wires.push(wire(9, "", 4, ""));
    chart.wires.push(wire(3, "OUT", 8, ""));
    chart.wires.push(wire(3, "IN1", 4, ""));
    chart.wires.push(wire(1, "", 3, "Q"));
    chart.wires.push(wire(4, "", 3, "IN1"));
    assert_eq!(
        messages(&chart),
        [
            "element 4: a wire comes from element 9, which is not in the chart",
            "element 3: a wire goes to element 8, which is not in the chart",
            "element 3: a wire starts at the pin 'IN1', which is not an output pin of this element",
            "element 4: the element's only pin has two wires; an input takes one",
            "element 3: a wire ends at the pin 'Q', which is not an input pin of this element",
            "element 4: a wire starts at the element's only pin, which is not an output pin of this element",
            "element 3: the pin 'IN1' has two wires; an input takes one",
        ]
    );
}

#[test]
fn pins_of_single_pin_elements_are_unnamed_and_marks_composers_and_selectors_have_their_own() {
    let kinds = [
        (CfcElementKind::Return, vec![""], vec![]),
        (
            CfcElementKind::ConnectionSink { name: "c".into() },
            vec![],
            vec![""],
        ),
        (
            CfcElementKind::Composer {
                type_name: "S".into(),
                inputs: vec![pin("x")],
            },
            vec!["x"],
            vec![""],
        ),
        (
            CfcElementKind::Selector {
                type_name: "S".into(),
                outputs: vec![pin("x")],
            },
            vec![""],
            vec!["x"],
        ),
        (CfcElementKind::Label { name: "L".into() }, vec![], vec![]),
    ];
    for (kind, inputs, outputs) in kinds {
        assert_eq!(cfc_input_pins(&kind), inputs, "{kind:?}");
        assert_eq!(cfc_output_pins(&kind), outputs, "{kind:?}");
    }
}

#[test]
fn pin_names_are_identifiers_unique_in_their_element() {
    let mut chart = sound();
    let CfcElementKind::Box(block) = &mut chart.elements[2].kind else {
        unreachable!("element 3 is a box")
    };
    block.inputs.push(pin("2nd"));
    block.inputs.push(pin("in1"));
    assert_eq!(
        messages(&chart),
        [
            "element 3: the pin name '2nd' is not an identifier (letters, digits and '_')",
            "element 3: the element has two pins named 'in1'",
        ]
    );
}

#[test]
fn boxes_have_type_names_and_labels_are_identifiers() {
    let mut chart = sound();
    let CfcElementKind::Box(block) = &mut chart.elements[2].kind else {
        unreachable!("element 3 is a box")
    };
    block.type_name = " ".into();
    chart.elements.push(element(
        5,
        Some(2),
        CfcElementKind::Label {
            name: "no good".into(),
        },
    ));
    chart.elements.push(element(
        6,
        Some(3),
        CfcElementKind::Composer {
            type_name: String::new(),
            inputs: Vec::new(),
        },
    ));
    assert_eq!(
        messages(&chart),
        [
            "element 3: the box has no type name",
            "element 5: the label 'no good' is not an identifier (letters, digits and '_')",
            "element 6: the element names no structure type",
        ]
    );
}

#[test]
fn names_with_two_underscores_are_refused() {
    let mut chart = sound();
    let CfcElementKind::Box(block) = &mut chart.elements[2].kind else {
        unreachable!("element 3 is a box")
    };
    block.instance = "t__1".into();
    block.outputs[0].name = "O__UT".into();
    chart.wires[2].from.pin = "O__UT".into();
    chart.elements.push(input(5, "x"));
    chart.elements[4].kind = CfcElementKind::ConnectionSink {
        name: "a__b".into(),
    };
    let found = messages(&chart);
    assert_eq!(found.len(), 3, "{found:#?}");
    assert!(found[0].starts_with("element 3: the instance 't__1' contains '__'"));
    assert!(found[1].starts_with("element 3: the pin name 'O__UT' contains '__'"));
    assert!(found[2].starts_with("element 5: the connection mark name 'a__b' contains '__'"));
}

#[test]
fn a_broken_chart_is_what_loads_saves_and_chart_edits_refuse() {
    let mut chart = sound();
    chart.wires.push(wire(1, "", 3, "IN1"));
    let body = crate::Body::Cfc { chart };
    assert_eq!(
        crate::validate::chart_problems(&body),
        ["element 3: the pin 'IN1' has two wires; an input takes one"]
    );
    let sound = crate::Body::Cfc { chart: sound() };
    assert_eq!(
        crate::validate::chart_problems(&sound),
        Vec::<String>::new()
    );
}
