use super::super::older_versions::{OlderFailure, pou_from_older};
use crate::{Body, Network, Pou};

/// The networks of the LD body of a version 1 POU file, converted.
#[track_caller]
fn convert(v1_body: &str) -> Vec<Network> {
    let text = format!("kind = \"program\"\n\n[body]\nlanguage = \"ld\"\n\n{v1_body}");
    match pou_from_older(1, "Main", &text) {
        Ok(Pou {
            body: Body::Ld { networks },
            ..
        }) => networks,
        Ok(other) => panic!("not an LD body: {other:?}"),
        Err(OlderFailure::Toml(error)) => panic!("{error}"),
        Err(OlderFailure::Networks(problems)) => panic!("{problems:#?}"),
    }
}

/// The networks of a version 2 LD body written in TOML.
#[track_caller]
fn expected(v2_body: &str) -> Vec<Network> {
    let text = format!("kind = \"program\"\n\n[body]\nlanguage = \"ld\"\n\n{v2_body}");
    match toml::from_str::<Pou>(&text) {
        Ok(Pou {
            body: Body::Ld { networks },
            ..
        }) => networks,
        other => panic!("{other:?}"),
    }
}

/// The messages of a version 1 body that cannot be converted.
#[track_caller]
fn problems(v1_body: &str) -> Vec<String> {
    let text = format!("kind = \"program\"\n\n[body]\nlanguage = \"fbd\"\n\n{v1_body}");
    match pou_from_older(1, "Main", &text) {
        Err(OlderFailure::Networks(problems)) => problems,
        Err(OlderFailure::Toml(error)) => panic!("{error}"),
        Ok(pou) => panic!("converted: {pou:?}"),
    }
}

#[test]
fn a_rung_with_a_parallel_branch_a_timer_and_a_coil_becomes_a_chain() {
    let networks = convert(
        r#"
[[body.network]]
label = "Start"
comment = "Motor start"
element = [
    { id = 1, x = 0, y = 0, kind = { type = "left_rail", height = 2 } },
    { id = 2, x = 2, y = 0, kind = { type = "contact", variable = "a" } },
    { id = 3, x = 4, y = 0, kind = { type = "contact", variable = "b" } },
    { id = 4, x = 4, y = 2, kind = { type = "contact", variable = "c", negated = true } },
    { id = 5, x = 6, y = 0, kind = { type = "block", type_name = "TON", instance = "t", inputs = ["IN", "PT"], outputs = ["Q", "ET"] } },
    { id = 6, x = 4, y = 4, kind = { type = "input", expression = "T#1s" } },
    { id = 7, x = 9, y = 0, kind = { type = "coil", variable = "q", coil = "set" } },
    { id = 8, x = 11, y = 0, kind = { type = "right_rail", height = 1 } },
    { id = 9, x = 9, y = 2, kind = { type = "output", expression = "elapsed" } },
    { id = 10, x = 0, y = 6, kind = { type = "comment", text = "Placed note", width = 4, height = 1 } },
]
connection = [
    { from = { element = 1 }, to = { element = 2 } },
    { from = { element = 2 }, to = { element = 3 } },
    { from = { element = 2 }, to = { element = 4 } },
    { from = { element = 3 }, to = { element = 5, pin = "IN" } },
    { from = { element = 4 }, to = { element = 5, pin = "IN" } },
    { from = { element = 6 }, to = { element = 5, pin = "PT" } },
    { from = { element = 5, pin = "Q" }, to = { element = 7 } },
    { from = { element = 5, pin = "ET" }, to = { element = 9 } },
    { from = { element = 7 }, to = { element = 8 } },
]
"#,
    );
    let want = expected(
        r#"
[[body.network]]
label = "Start"
comment = "Motor start\n\nPlaced note"
rung = [
    { type = "operand", id = 2, text = "a" },
    { type = "parallel", id = 11, branch = [
        { rung = [{ type = "operand", id = 3, text = "b" }] },
        { rung = [{ type = "operand", id = 4, text = "c", negated = true }] },
    ] },
    { type = "block", id = 5, type_name = "TON", instance = "t", input = [
        { pin = "IN" },
        { pin = "PT", source = [{ type = "operand", id = 6, text = "T#1s" }] },
    ], output = [{ pin = "Q" }, { pin = "ET", assign = "elapsed" }] },
]
output = [{ type = "coil", id = 7, variable = "q", kind = "set" }]
"#,
    );
    assert_eq!(networks, want);
}

#[test]
fn outputs_that_share_a_prefix_become_output_branches() {
    let networks = convert(
        r#"
[[body.network]]
element = [
    { id = 1, x = 0, y = 0, kind = { type = "left_rail", height = 2 } },
    { id = 2, x = 2, y = 0, kind = { type = "contact", variable = "a" } },
    { id = 3, x = 8, y = 0, kind = { type = "coil", variable = "x" } },
    { id = 4, x = 4, y = 2, kind = { type = "contact", variable = "b", edge = "rising" } },
    { id = 5, x = 8, y = 2, kind = { type = "coil", variable = "y" } },
    { id = 6, x = 8, y = 4, kind = { type = "jump", label = "Done" } },
]
connection = [
    { from = { element = 1 }, to = { element = 2 } },
    { from = { element = 2 }, to = { element = 3 } },
    { from = { element = 3 }, to = { element = 4 } },
    { from = { element = 4 }, to = { element = 5 } },
    { from = { element = 4 }, to = { element = 6 } },
]
"#,
    );
    let want = expected(
        r#"
[[body.network]]
rung = [{ type = "operand", id = 2, text = "a" }]
output = [
    { type = "coil", id = 3, variable = "x" },
    { type = "branch", id = 7, rung = [{ type = "operand", id = 4, text = "b", edge = "rising" }], output = [
        { type = "coil", id = 5, variable = "y" },
        { type = "jump", id = 6, label = "Done" },
    ] },
]
"#,
    );
    assert_eq!(networks, want);
}

#[test]
fn an_fbd_tree_of_boxes_becomes_a_chain_with_sources() {
    let networks = convert(
        r#"
[[body.network]]
element = [
    { id = 1, x = 0, y = 0, kind = { type = "input", expression = "x" } },
    { id = 2, x = 0, y = 2, kind = { type = "input", expression = "y" } },
    { id = 3, x = 3, y = 0, kind = { type = "block", type_name = "ADD", inputs = ["IN1", "IN2"], outputs = ["OUT"] } },
    { id = 4, x = 3, y = 4, kind = { type = "input", expression = "gain" } },
    { id = 5, x = 6, y = 0, kind = { type = "block", type_name = "MUL", inputs = ["IN1", "IN2"], outputs = ["OUT"] } },
    { id = 6, x = 0, y = 6, kind = { type = "input", expression = "low" } },
    { id = 7, x = 3, y = 6, kind = { type = "block", type_name = "MAX", inputs = ["IN1", "IN2"], outputs = ["OUT"] } },
    { id = 8, x = 9, y = 0, kind = { type = "output", expression = "result" } },
]
connection = [
    { from = { element = 1 }, to = { element = 3, pin = "IN1" } },
    { from = { element = 2 }, to = { element = 3, pin = "IN2" } },
    { from = { element = 3, pin = "OUT" }, to = { element = 5, pin = "IN1" } },
    { from = { element = 6 }, to = { element = 7, pin = "IN1" } },
    { from = { element = 4 }, to = { element = 7, pin = "IN2" } },
    { from = { element = 7, pin = "OUT" }, to = { element = 5, pin = "IN2" } },
    { from = { element = 5, pin = "OUT" }, to = { element = 8 } },
]
"#,
    );
    let want = expected(
        r#"
[[body.network]]
rung = [
    { type = "operand", id = 1, text = "x" },
    { type = "block", id = 3, type_name = "ADD", input = [
        { pin = "IN1" },
        { pin = "IN2", source = [{ type = "operand", id = 2, text = "y" }] },
    ], output = [{ pin = "OUT" }] },
    { type = "block", id = 5, type_name = "MUL", input = [
        { pin = "IN1" },
        { pin = "IN2", source = [
            { type = "operand", id = 6, text = "low" },
            { type = "block", id = 7, type_name = "MAX", input = [
                { pin = "IN1" },
                { pin = "IN2", source = [{ type = "operand", id = 4, text = "gain" }] },
            ], output = [{ pin = "OUT" }] },
        ] },
    ], output = [{ pin = "OUT" }] },
]
output = [{ type = "coil", id = 8, variable = "result" }]
"#,
    );
    assert_eq!(networks, want);
}

#[test]
fn a_rung_that_ends_in_a_box_keeps_the_box() {
    let networks = convert(
        r#"
[[body.network]]
element = [
    { id = 1, x = 0, y = 0, kind = { type = "left_rail", height = 1 } },
    { id = 2, x = 2, y = 0, kind = { type = "contact", variable = "go" } },
    { id = 3, x = 4, y = 0, kind = { type = "block", type_name = "CTU", instance = "count", inputs = ["CU"], outputs = ["Q"], en_eno = true } },
    { id = 4, x = 2, y = 2, kind = { type = "input", expression = "pulse" } },
]
connection = [
    { from = { element = 1 }, to = { element = 2 } },
    { from = { element = 2 }, to = { element = 3, pin = "EN" } },
    { from = { element = 4 }, to = { element = 3, pin = "CU" } },
]
"#,
    );
    let want = expected(
        r#"
[[body.network]]
rung = [
    { type = "operand", id = 2, text = "go" },
    { type = "block", id = 3, type_name = "CTU", instance = "count", input = [
        { pin = "EN" },
        { pin = "CU", source = [{ type = "operand", id = 4, text = "pulse" }] },
    ], output = [{ pin = "ENO" }, { pin = "Q" }] },
]
"#,
    );
    assert_eq!(networks, want);
}

#[test]
fn one_contact_wired_to_two_pins_of_a_box_cannot_be_converted() {
    let shared = problems(
        r#"
[[body.network]]
element = [
    { id = 1, x = 0, y = 0, kind = { type = "left_rail", height = 1 } },
    { id = 2, x = 2, y = 0, kind = { type = "contact", variable = "go" } },
    { id = 3, x = 4, y = 0, kind = { type = "block", type_name = "CTU", instance = "count", inputs = ["CU"], outputs = ["Q"], en_eno = true } },
]
connection = [
    { from = { element = 1 }, to = { element = 2 } },
    { from = { element = 2 }, to = { element = 3, pin = "EN" } },
    { from = { element = 2 }, to = { element = 3, pin = "CU" } },
]
"#,
    );
    assert_eq!(
        shared,
        [
            "POU 'Main', network 1, element 2: cannot be converted to version 2: its flow feeds \
          branches that do not join again in series and parallel"
        ]
    );
}

#[test]
fn graphs_that_cannot_be_converted_name_the_network_and_element() {
    let dangling = problems(
        r#"
[[body.network]]
element = [{ id = 1, x = 0, y = 0, kind = { type = "input", expression = "a" } }]
connection = [{ from = { element = 1 }, to = { element = 9 } }]
"#,
    );
    assert_eq!(
        dangling,
        [
            "POU 'Main', network 1, element 1: cannot be converted to version 2: a connection \
          leads to element 9, which does not exist"
        ]
    );

    let missing_pin = problems(
        r#"
[[body.network]]
label = "Scale"
element = [
    { id = 1, x = 0, y = 0, kind = { type = "input", expression = "a" } },
    { id = 2, x = 2, y = 0, kind = { type = "block", type_name = "ABS", inputs = ["IN"], outputs = ["OUT"] } },
]
connection = [{ from = { element = 1 }, to = { element = 2, pin = "XIN" } }]
"#,
    );
    assert_eq!(
        missing_pin,
        [
            "POU 'Main', network 1 'Scale', element 2: cannot be converted to version 2: a \
          connection ends at 'XIN', which is not an input"
        ]
    );

    let cycle = problems(
        r#"
[[body.network]]
element = [
    { id = 1, x = 0, y = 0, kind = { type = "block", type_name = "AND", inputs = ["IN1", "IN2"], outputs = ["OUT"] } },
    { id = 2, x = 3, y = 0, kind = { type = "block", type_name = "OR", inputs = ["IN1", "IN2"], outputs = ["OUT"] } },
    { id = 3, x = 6, y = 0, kind = { type = "output", expression = "q" } },
]
connection = [
    { from = { element = 1, pin = "OUT" }, to = { element = 2, pin = "IN1" } },
    { from = { element = 2, pin = "OUT" }, to = { element = 1, pin = "IN1" } },
    { from = { element = 2, pin = "OUT" }, to = { element = 3 } },
]
"#,
    );
    assert_eq!(cycle.len(), 1);
    assert!(cycle[0].contains("cycle"), "{cycle:?}");

    let two_drivers = problems(
        r#"
[[body.network]]
element = [
    { id = 1, x = 0, y = 0, kind = { type = "input", expression = "a" } },
    { id = 2, x = 0, y = 2, kind = { type = "input", expression = "b" } },
    { id = 3, x = 0, y = 4, kind = { type = "input", expression = "c" } },
    { id = 4, x = 3, y = 0, kind = { type = "block", type_name = "ADD", inputs = ["IN1", "IN2"], outputs = ["OUT"] } },
    { id = 5, x = 6, y = 0, kind = { type = "output", expression = "q" } },
]
connection = [
    { from = { element = 1 }, to = { element = 4, pin = "IN1" } },
    { from = { element = 2 }, to = { element = 4, pin = "IN2" } },
    { from = { element = 3 }, to = { element = 4, pin = "IN2" } },
    { from = { element = 4, pin = "OUT" }, to = { element = 5 } },
]
"#,
    );
    assert_eq!(
        two_drivers,
        [
            "POU 'Main', network 1, element 4: cannot be converted to version 2: the input 'IN2' \
          has 2 drivers"
        ]
    );
}

#[test]
fn a_bridge_between_two_parallel_paths_is_not_series_parallel() {
    // a feeds c and d; b feeds d only; c and d both drive q: d is on two paths that do not
    // split and join as nested groups.
    let bridge = problems(
        r#"
[[body.network]]
element = [
    { id = 1, x = 0, y = 0, kind = { type = "left_rail", height = 2 } },
    { id = 2, x = 2, y = 0, kind = { type = "contact", variable = "a" } },
    { id = 3, x = 2, y = 2, kind = { type = "contact", variable = "b" } },
    { id = 4, x = 4, y = 0, kind = { type = "contact", variable = "c" } },
    { id = 5, x = 4, y = 2, kind = { type = "contact", variable = "d" } },
    { id = 6, x = 6, y = 0, kind = { type = "coil", variable = "q" } },
    { id = 7, x = 6, y = 2, kind = { type = "coil", variable = "r" } },
]
connection = [
    { from = { element = 1 }, to = { element = 2 } },
    { from = { element = 1 }, to = { element = 3 } },
    { from = { element = 2 }, to = { element = 4 } },
    { from = { element = 2 }, to = { element = 5 } },
    { from = { element = 3 }, to = { element = 5 } },
    { from = { element = 4 }, to = { element = 6 } },
    { from = { element = 5 }, to = { element = 7 } },
]
"#,
    );
    assert_eq!(bridge.len(), 1, "{bridge:?}");
    assert!(bridge[0].contains("do not join again"), "{bridge:?}");
}

#[test]
fn a_chain_of_boxes_nested_deeper_than_version_2_allows_is_refused() {
    // Each ABS box feeds the second input of the next ADD, so every box is one source deeper.
    let mut elements =
        vec![r#"{ id = 1, x = 0, y = 0, kind = { type = "input", expression = "x" } }"#.to_owned()];
    let mut connections = Vec::new();
    let count = 200;
    for index in 0..count {
        let id = index + 2;
        elements.push(format!(
            r#"{{ id = {id}, x = 0, y = {id}, kind = {{ type = "block", type_name = "ADD", inputs = ["IN1", "IN2"], outputs = ["OUT"] }} }}"#
        ));
        connections.push(format!(
            r#"{{ from = {{ element = 1 }}, to = {{ element = {id}, pin = "IN1" }} }}"#
        ));
        if index > 0 {
            connections.push(format!(
                r#"{{ from = {{ element = {}, pin = "OUT" }}, to = {{ element = {id}, pin = "IN2" }} }}"#,
                id - 1
            ));
        }
    }
    let body = format!(
        "[[body.network]]\nelement = [\n{}\n]\nconnection = [\n{}\n]\n",
        elements.join(",\n"),
        connections.join(",\n")
    );
    let found = problems(&body);
    assert_eq!(found.len(), 1, "{found:?}");
    assert!(found[0].contains("nested more than"), "{found:?}");
}
