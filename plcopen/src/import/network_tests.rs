//! LD and FBD bodies of small documents converted into networks, and their errors.

use std::fmt::Write;

use project_model::{Body, CoilKind, Edge, FlowNode, Network, NetworkOutput, Object};

use super::{ImportError, Imported, Outcome, import};
use crate::read;

/// A program `P` whose body is `language` with `objects`.
fn document(language: &str, objects: &str, body_add_data: &str) -> String {
    format!(
        r#"<?xml version="1.0" encoding="UTF-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201" xmlns:xhtml="http://www.w3.org/1999/xhtml">
  <fileHeader companyName="c" productName="p" productVersion="1" creationDateTime="2024-01-01T00:00:00"/>
  <contentHeader name="n"><coordinateInfo><fbd><scaling x="0" y="0"/></fbd><ld><scaling x="0" y="0"/></ld><sfc><scaling x="0" y="0"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous><pou name="P" pouType="program"><body><{language}>
{objects}
</{language}>{body_add_data}</body></pou></pous></types>
  <instances><configurations/></instances>
</project>
"#
    )
}

fn imported(text: &str) -> Imported {
    let document = read(text, "in.xml").unwrap_or_else(|error| panic!("{error}"));
    import(&document).unwrap_or_else(|error| panic!("{error}"))
}

fn import_error(text: &str) -> ImportError {
    let document = read(text, "bad.xml").unwrap_or_else(|error| panic!("{error}"));
    match import(&document) {
        Ok(imported) => panic!("imported: {imported:?}"),
        Err(error) => error,
    }
}

/// The networks of `P`.
#[track_caller]
fn networks(language: &str, objects: &str) -> Vec<Network> {
    networks_of(&imported(&document(language, objects, "")))
}

#[track_caller]
fn networks_of(imported: &Imported) -> Vec<Network> {
    match imported.project.application.object("P") {
        Some(Object::Pou(pou)) => match &pou.body {
            Body::Ld { networks } | Body::Fbd { networks } => networks.clone(),
            other => panic!("{other:?}"),
        },
        other => panic!("{other:?}: {:?}", imported.report),
    }
}

/// A network as one line: `a !b (c | P(d)) -> X, S:Y, {e -> Z}`.
fn render(network: &Network) -> String {
    let mut line = String::new();
    if !network.label.is_empty() {
        write!(line, "{}: ", network.label).ok();
    }
    line.push_str(&chain(&network.rung));
    if !network.outputs.is_empty() {
        write!(line, " -> {}", outputs(&network.outputs)).ok();
    }
    line.trim().to_owned()
}

fn chain(nodes: &[FlowNode]) -> String {
    let parts: Vec<String> = nodes
        .iter()
        .map(|node| match node {
            FlowNode::Operand(operand) => {
                let text = match operand.edge {
                    Edge::None => operand.text.clone(),
                    Edge::Rising => format!("P({})", operand.text),
                    Edge::Falling => format!("N({})", operand.text),
                };
                if operand.negated {
                    format!("!{text}")
                } else {
                    text
                }
            }
            FlowNode::Parallel(parallel) => format!(
                "({})",
                parallel
                    .branches
                    .iter()
                    .map(|branch| chain(&branch.rung))
                    .collect::<Vec<_>>()
                    .join(" | ")
            ),
            FlowNode::Block(block) => {
                let inputs: Vec<String> = block
                    .inputs
                    .iter()
                    .map(|input| {
                        if input.source.is_empty() {
                            input.pin.clone()
                        } else {
                            format!("{}={}", input.pin, chain(&input.source))
                        }
                    })
                    .collect();
                let assigned: String = block
                    .outputs
                    .iter()
                    .filter(|output| !output.assign.is_empty())
                    .map(|output| format!(" {}:={}", output.pin, output.assign))
                    .collect();
                let instance = if block.instance.is_empty() {
                    String::new()
                } else {
                    format!("[{}]", block.instance)
                };
                format!(
                    "{}{instance}({}){assigned}",
                    block.type_name,
                    inputs.join("; ")
                )
            }
        })
        .collect();
    parts.join(" ")
}

fn outputs(list: &[NetworkOutput]) -> String {
    list.iter()
        .map(|output| match output {
            NetworkOutput::Coil(coil) => {
                let kind = match coil.kind {
                    CoilKind::Normal => "",
                    CoilKind::Negated => "/",
                    CoilKind::Set => "S:",
                    CoilKind::Reset => "R:",
                    CoilKind::Rising => "P:",
                    CoilKind::Falling => "N:",
                };
                format!("{kind}{}", coil.variable)
            }
            NetworkOutput::Jump { label, .. } => format!("jump {label}"),
            NetworkOutput::Return { .. } => "return".to_owned(),
            NetworkOutput::Branch {
                rung,
                outputs: inner,
                ..
            } if inner.is_empty() => format!("{{{}}}", chain(rung)),
            NetworkOutput::Branch {
                rung,
                outputs: inner,
                ..
            } => format!("{{{} -> {}}}", chain(rung), outputs(inner)),
        })
        .collect::<Vec<_>>()
        .join(", ")
}

pub(super) fn rendered(networks: &[Network]) -> Vec<String> {
    networks.iter().map(render).collect()
}

/// `<connectionPointIn>` with a connection to each of `from`.
fn wires(from: &[u64]) -> String {
    let connections: String = from
        .iter()
        .map(|id| format!(r#"<connection refLocalId="{id}"/>"#))
        .collect();
    format!("<connectionPointIn>{connections}</connectionPointIn>")
}

fn rail(id: u64, y: u32) -> String {
    format!(
        r#"<leftPowerRail localId="{id}"><position x="0" y="{y}"/><connectionPointOut formalParameter=""/></leftPowerRail>"#
    )
}

fn contact(id: u64, variable: &str, from: &[u64], y: u32, attributes: &str) -> String {
    format!(
        r#"<contact localId="{id}" {attributes}><position x="{}" y="{y}"/>{}<connectionPointOut/><variable>{variable}</variable></contact>"#,
        id * 10,
        wires(from)
    )
}

fn coil(id: u64, variable: &str, from: &[u64], y: u32, attributes: &str) -> String {
    format!(
        r#"<coil localId="{id}" {attributes}><position x="500" y="{y}"/>{}<connectionPointOut/><variable>{variable}</variable></coil>"#,
        wires(from)
    )
}

#[test]
fn contacts_in_series_and_a_wired_or_become_a_chain_with_a_parallel_group() {
    let objects = [
        rail(1, 0),
        contact(2, "a", &[1], 0, ""),
        contact(3, "b", &[2], 0, r#"negated="true""#),
        contact(4, "c", &[1], 40, r#"edge="rising""#),
        coil(5, "X", &[3, 4], 0, ""),
    ]
    .concat();
    assert_eq!(rendered(&networks("LD", &objects)), ["(a !b | P(c)) -> X"]);
}

#[test]
fn coil_attributes_give_coil_kinds() {
    let objects = [
        rail(1, 0),
        contact(2, "a", &[1], 0, ""),
        coil(3, "N", &[2], 0, r#"negated="true""#),
        coil(4, "S", &[2], 20, r#"storage="set""#),
        coil(5, "R", &[2], 40, r#"storage="reset""#),
        coil(6, "U", &[2], 60, r#"edge="rising""#),
        coil(7, "D", &[2], 80, r#"edge="falling""#),
    ]
    .concat();
    assert_eq!(
        rendered(&networks("LD", &objects)),
        ["a -> /N, S:S, R:R, P:U, N:D"]
    );
}

#[test]
fn a_coil_both_negated_and_set_is_refused_at_its_line() {
    let objects = [
        rail(1, 0),
        contact(2, "a", &[1], 0, ""),
        coil(3, "X", &[2], 0, r#"negated="true" storage="set""#),
    ]
    .concat();
    let error = import_error(&document("LD", &objects, "")).to_string();
    assert!(error.starts_with("bad.xml:6:"), "{error}");
    assert!(
        error.contains("body/LD/coil[@localId='3']: the coil of `X` is negated and set"),
        "{error}"
    );
}

#[test]
fn a_coil_with_nothing_before_it_is_refused() {
    let objects = [rail(1, 0), coil(3, "X", &[], 0, "")].concat();
    let error = import_error(&document("LD", &objects, "")).to_string();
    assert!(
        error.contains("coil[@localId='3']: the coil has nothing connected before it"),
        "{error}"
    );
}

#[test]
fn coils_in_series_pass_the_power_on_to_a_branch() {
    let objects = [
        rail(1, 0),
        contact(2, "a", &[1], 0, ""),
        coil(3, "X", &[2], 0, ""),
        contact(4, "b", &[3], 0, ""),
        coil(5, "Y", &[4], 0, ""),
    ]
    .concat();
    assert_eq!(rendered(&networks("LD", &objects)), ["a -> X, {b -> Y}"]);
}

#[test]
fn a_bridge_of_contacts_is_expanded_into_one_branch_per_path() {
    // a and b from the rail; c after a, d after b; e bridges a's output to d's input.
    let objects = [
        rail(1, 0),
        contact(2, "a", &[1], 0, ""),
        contact(3, "b", &[1], 40, ""),
        contact(4, "e", &[2], 20, ""),
        contact(5, "c", &[2], 0, ""),
        contact(6, "d", &[3, 4], 40, ""),
        coil(7, "X", &[5, 6], 0, ""),
    ]
    .concat();
    assert_eq!(
        rendered(&networks("LD", &objects)),
        ["(a c | a e d | b d) -> X"]
    );
}

#[test]
fn a_bridge_through_a_function_box_is_refused() {
    // An instance's output would be read as `t.Q` by the second path; a function's cannot.
    let objects = [
        rail(1, 0),
        r#"<block localId="2" typeName="MOVE"><position x="20" y="0"/><inputVariables><variable formalParameter="IN"><connectionPointIn><connection refLocalId="1"/></connectionPointIn></variable></inputVariables><inOutVariables/><outputVariables><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables></block>"#.to_owned(),
        contact(3, "b", &[1], 40, ""),
        contact(4, "e", &[2], 20, ""),
        contact(5, "c", &[2], 0, ""),
        contact(6, "d", &[3, 4], 40, ""),
        coil(7, "X", &[5, 6], 0, ""),
    ]
    .concat();
    let error = import_error(&document("LD", &objects, "")).to_string();
    assert!(
        error.contains("not series-parallel and a block lies on several of its paths"),
        "{error}"
    );
}

#[test]
fn separate_rungs_become_networks_ordered_by_their_top() {
    let objects = [
        rail(1, 100),
        contact(2, "b", &[1], 100, ""),
        coil(3, "Y", &[2], 100, ""),
        rail(4, 0),
        contact(5, "a", &[4], 0, ""),
        coil(6, "X", &[5], 0, ""),
        r#"<comment localId="7" height="20" width="100"><position x="0" y="90"/><content><xhtml:p>Second</xhtml:p></content></comment>"#.to_owned(),
    ]
    .concat();
    let networks = networks("LD", &objects);
    assert_eq!(rendered(&networks), ["a -> X", "b -> Y"]);
    assert_eq!(networks[1].comment, "Second");
    // Ids are fresh, from 1 in tree order.
    let ids: Vec<u32> = networks
        .iter()
        .flat_map(|network| {
            network
                .rung
                .iter()
                .map(FlowNode::id)
                .chain(network.outputs.iter().map(NetworkOutput::id))
        })
        .map(|id| id.0)
        .collect();
    assert_eq!(ids, [1, 2, 3, 4]);
}

const TON: &str = r#"<inVariable localId="1"><position x="0" y="0"/><connectionPointOut/><expression>start</expression></inVariable>
<inVariable localId="2"><position x="0" y="30"/><connectionPointOut/><expression>T#1s</expression></inVariable>
<block localId="3" typeName="TON" instanceName="timer"><position x="100" y="0"/><inputVariables>
<variable formalParameter="IN"><connectionPointIn><connection refLocalId="1"/></connectionPointIn></variable>
<variable formalParameter="PT" negated="false"><connectionPointIn><connection refLocalId="2"/></connectionPointIn></variable>
</inputVariables><inOutVariables/><outputVariables>
<variable formalParameter="Q"><connectionPointOut/></variable>
<variable formalParameter="ET"><connectionPointOut/></variable>
</outputVariables></block>
<outVariable localId="4"><position x="200" y="0"/><connectionPointIn><connection refLocalId="3" formalParameter="Q"/></connectionPointIn><expression>done</expression></outVariable>
<outVariable localId="5"><position x="200" y="30"/><connectionPointIn><connection refLocalId="3" formalParameter="ET"/></connectionPointIn><expression>elapsed</expression></outVariable>"#;

#[test]
fn an_fbd_box_takes_its_first_input_from_the_chain_and_assigns_its_other_outputs() {
    assert_eq!(
        rendered(&networks("FBD", TON)),
        ["start TON[timer](IN; PT=T#1s) ET:=elapsed -> done"]
    );
}

#[test]
fn an_instance_output_read_by_another_box_is_a_variable_read() {
    let objects = format!(
        r#"{TON}
<block localId="6" typeName="ADD"><position x="300" y="100"/><inputVariables>
<variable formalParameter="IN1"><connectionPointIn><connection refLocalId="7"/></connectionPointIn></variable>
<variable formalParameter="IN2"><connectionPointIn><connection refLocalId="3" formalParameter="ET"/></connectionPointIn></variable>
</inputVariables><inOutVariables/><outputVariables><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables></block>
<inVariable localId="7"><position x="200" y="100"/><connectionPointOut/><expression>base</expression></inVariable>
<outVariable localId="8"><position x="400" y="100"/><connectionPointIn><connection refLocalId="6" formalParameter="OUT"/></connectionPointIn><expression>total</expression></outVariable>"#
    );
    assert_eq!(
        rendered(&networks("FBD", &objects)),
        [
            "start TON[timer](IN; PT=T#1s) ET:=elapsed -> done",
            "base ADD(IN1; IN2=timer.ET) -> total"
        ]
    );
}

/// An FBD body where `ADD`'s result feeds `MUL` through connector `sum`.
fn with_connectors(second_connector: &str, continuation: &str) -> String {
    format!(
        r#"<inVariable localId="1"><position x="0" y="0"/><connectionPointOut/><expression>a</expression></inVariable>
<inVariable localId="2"><position x="0" y="30"/><connectionPointOut/><expression>b</expression></inVariable>
<block localId="3" typeName="ADD"><position x="100" y="0"/><inputVariables>
<variable formalParameter="IN1"><connectionPointIn><connection refLocalId="1"/></connectionPointIn></variable>
<variable formalParameter="IN2"><connectionPointIn><connection refLocalId="2"/></connectionPointIn></variable>
</inputVariables><inOutVariables/><outputVariables><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables></block>
<connector name="sum" localId="4"><position x="200" y="0"/><connectionPointIn><connection refLocalId="3" formalParameter="OUT"/></connectionPointIn></connector>
{second_connector}
<continuation name="{continuation}" localId="5"><position x="0" y="100"/><connectionPointOut/></continuation>
<block localId="6" typeName="MUL"><position x="100" y="100"/><inputVariables>
<variable formalParameter="IN1"><connectionPointIn><connection refLocalId="5"/></connectionPointIn></variable>
<variable formalParameter="IN2"><connectionPointIn><connection refLocalId="7"/></connectionPointIn></variable>
</inputVariables><inOutVariables/><outputVariables><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables></block>
<inVariable localId="7"><position x="0" y="130"/><connectionPointOut/><expression>2</expression></inVariable>
<outVariable localId="8"><position x="200" y="100"/><connectionPointIn><connection refLocalId="6" formalParameter="OUT"/></connectionPointIn><expression>y</expression></outVariable>"#
    )
}

#[test]
fn a_continuation_reads_its_connector_as_a_direct_wire() {
    assert_eq!(
        rendered(&networks("FBD", &with_connectors("", "sum"))),
        ["a ADD(IN1; IN2=b) MUL(IN1; IN2=2) -> y"]
    );
}

#[test]
fn a_continuation_without_its_connector_is_refused_with_its_name() {
    let error = import_error(&document("FBD", &with_connectors("", "total"), "")).to_string();
    assert!(
        error.contains(
            "continuation[@localId='5']: the continuation `total` has no connector of that name"
        ),
        "{error}"
    );
}

#[test]
fn two_connectors_of_one_name_are_refused_naming_both_lines() {
    let second = r#"<connector name="sum" localId="9"><position x="200" y="50"/><connectionPointIn><connection refLocalId="2"/></connectionPointIn></connector>"#;
    let error = import_error(&document("FBD", &with_connectors(second, "sum"), "")).to_string();
    assert!(
        error.contains("the connector `sum` is defined twice in its body (lines 12 and 13)"),
        "{error}"
    );
}

#[test]
fn a_feedback_loop_is_not_a_network_and_is_reported() {
    // y := ADD(y's own result, 1) drawn as a wire from the output back to the input.
    let objects = r#"<inVariable localId="1"><position x="0" y="0"/><connectionPointOut/><expression>1</expression></inVariable>
<block localId="2" typeName="ADD"><position x="100" y="0"/><inputVariables>
<variable formalParameter="IN1"><connectionPointIn><connection refLocalId="1"/></connectionPointIn></variable>
<variable formalParameter="IN2"><connectionPointIn><connection refLocalId="2" formalParameter="OUT"/></connectionPointIn></variable>
</inputVariables><inOutVariables/><outputVariables><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables></block>
<outVariable localId="3"><position x="200" y="0"/><connectionPointIn><connection refLocalId="2" formalParameter="OUT"/></connectionPointIn><expression>y</expression></outVariable>"#;
    let imported = imported(&document("FBD", objects, ""));
    // A CFC chart runs the loop as drawn, and the report says why the body became one.
    assert!(matches!(
        imported.project.application.object("P"),
        Some(Object::Pou(pou)) if matches!(pou.body, Body::Cfc { .. })
    ));
    let entry = imported.report.entry("FBD body of POU 'P'");
    assert!(
        entry.is_some_and(|entry| entry.outcome == Outcome::Converted
            && entry.note.contains("imported as a CFC chart")
            && entry.note.contains("feedback loop")),
        "{entry:?}"
    );
}

#[test]
fn a_function_result_read_by_two_inputs_is_not_a_network() {
    let objects = r#"<inVariable localId="1"><position x="0" y="0"/><connectionPointOut/><expression>a</expression></inVariable>
<block localId="2" typeName="NOT"><position x="100" y="0"/><inputVariables>
<variable formalParameter="IN"><connectionPointIn><connection refLocalId="1"/></connectionPointIn></variable>
</inputVariables><inOutVariables/><outputVariables><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables></block>
<block localId="3" typeName="AND"><position x="200" y="0"/><inputVariables>
<variable formalParameter="IN1"><connectionPointIn><connection refLocalId="4"/></connectionPointIn></variable>
<variable formalParameter="IN2"><connectionPointIn><connection refLocalId="2" formalParameter="OUT"/></connectionPointIn></variable>
</inputVariables><inOutVariables/><outputVariables><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables></block>
<inVariable localId="4"><position x="100" y="50"/><connectionPointOut/><expression>b</expression></inVariable>
<outVariable localId="5"><position x="300" y="0"/><connectionPointIn><connection refLocalId="3" formalParameter="OUT"/></connectionPointIn><expression>y</expression></outVariable>
<outVariable localId="6"><position x="200" y="60"/><connectionPointIn><connection refLocalId="2" formalParameter="OUT"/></connectionPointIn><expression>z</expression></outVariable>"#;
    let imported = imported(&document("FBD", objects, ""));
    let entry = imported.report.entry("FBD body of POU 'P'");
    assert!(
        entry.is_some_and(|entry| entry.note.contains("imported as a CFC chart")
            && entry.note.contains("drives more than one input")),
        "{entry:?}"
    );
}

#[test]
fn jumps_returns_and_labels_stand_in_their_networks() {
    let objects = [
        rail(1, 0),
        contact(2, "a", &[1], 0, ""),
        format!(
            r#"<jump localId="3" label="Done"><position x="500" y="0"/>{}</jump>"#,
            wires(&[2])
        ),
        r#"<label localId="4" label="Done"><position x="0" y="100"/></label>"#.to_owned(),
        rail(5, 100),
        contact(6, "b", &[5], 100, ""),
        format!(
            r#"<return localId="7"><position x="500" y="100"/>{}</return>"#,
            wires(&[6])
        ),
    ]
    .concat();
    assert_eq!(
        rendered(&networks("LD", &objects)),
        ["a -> jump Done", "Done: b -> return"]
    );
}

#[test]
fn rivets_networks_entry_delimits_networks_and_gives_their_headers() {
    let objects = [
        rail(1, 0),
        contact(2, "a", &[1], 0, ""),
        coil(3, "X", &[2], 0, ""),
        contact(4, "b", &[1], 40, ""),
        coil(5, "Y", &[4], 40, ""),
    ]
    .concat();
    let entry = r#"<addData><data name="https://rivet-plc.dev/plcopen/1/networks" handleUnknown="preserve"><networks xmlns="https://rivet-plc.dev/plcopen/1"><network first="1" title="First"/><network first="4" comment="Two" label="L2"/></networks></data></addData>"#;
    let imported = imported(&document("LD", &objects, entry));
    let networks = networks_of(&imported);
    assert_eq!(rendered(&networks), ["a -> X", "L2: b -> Y"]);
    assert_eq!(networks[0].title, "First");
    assert_eq!(networks[1].comment, "Two");
}

#[test]
fn codesys_network_titles_delimit_networks_in_document_order() {
    let title = |id: u64, text: &str| {
        format!(
            r#"<comment localId="{}" height="0" width="0"><content><xhtml:p>{text} comment</xhtml:p></content></comment><vendorElement localId="{id}"><alternativeText><xhtml:p>{text}</xhtml:p></alternativeText><addData><data name="http://www.3s-software.com/plcopenxml/fbdelementtype" handleUnknown="implementation"><ElementType xmlns="">networktitle</ElementType></data></addData></vendorElement>"#,
            id + 100
        )
    };
    let objects = format!(
        r#"<leftPowerRail localId="0"><connectionPointOut formalParameter="none"/></leftPowerRail>{}<contact localId="2" negated="false" storage="none" edge="none"><connectionPointIn><connection refLocalId="0"/></connectionPointIn><connectionPointOut/><variable>a</variable></contact><coil localId="3" negated="false" storage="none" edge="none"><connectionPointIn><connection refLocalId="2"/></connectionPointIn><connectionPointOut/><variable>X</variable></coil>{}<contact localId="5"><connectionPointIn><connection refLocalId="0"/></connectionPointIn><connectionPointOut/><variable>b</variable></contact><coil localId="6"><connectionPointIn><connection refLocalId="5"/></connectionPointIn><connectionPointOut/><variable>Y</variable></coil>"#,
        title(1, "One"),
        title(4, "Two"),
    );
    let networks = networks("LD", &objects);
    assert_eq!(rendered(&networks), ["a -> X", "b -> Y"]);
    assert_eq!(
        (networks[1].title.as_str(), networks[1].comment.as_str()),
        ("Two", "Two comment")
    );
}

#[test]
fn actions_and_transitions_drawn_in_ld_and_fbd_become_networks() {
    let ld = [
        rail(1, 0),
        contact(2, "a", &[1], 0, ""),
        coil(3, "X", &[2], 0, ""),
    ]
    .concat();
    let fbd = r#"<inVariable localId="1"><position x="0" y="0"/><connectionPointOut/><expression>a</expression></inVariable><outVariable localId="2"><position x="100" y="0"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><expression>T</expression></outVariable>"#;
    let text = document("LD", &ld, "").replace(
        r#"<pou name="P" pouType="program"><body>"#,
        &format!(
            r#"<pou name="P" pouType="program"><actions><action name="Act"><body><LD>{ld}</LD></body></action></actions><transitions><transition name="T"><body><FBD>{fbd}</FBD></body></transition></transitions><body>"#
        ),
    );
    let imported = imported(&text);
    let Some(Object::Pou(pou)) = imported.project.application.object("P") else {
        panic!("{imported:?}")
    };
    let Body::Ld { networks } = &pou.actions[0].body else {
        panic!("{:?}", pou.actions)
    };
    assert_eq!(rendered(networks), ["a -> X"]);
    let Body::Fbd { networks } = &pou.transitions[0].body else {
        panic!("{:?}", pou.transitions)
    };
    assert_eq!(rendered(networks), ["a -> T"]);
    for what in ["action 'P.Act'", "transition 'P.T'"] {
        assert_eq!(
            imported.report.entry(what).map(|entry| entry.outcome),
            Some(Outcome::Converted),
            "{what}"
        );
    }
}

#[test]
fn rivets_networks_entry_naming_a_missing_object_is_refused() {
    let objects = [
        rail(1, 0),
        contact(2, "a", &[1], 0, ""),
        coil(3, "X", &[2], 0, ""),
    ]
    .concat();
    let entry = r#"<addData><data name="https://rivet-plc.dev/plcopen/1/networks" handleUnknown="preserve"><networks xmlns="https://rivet-plc.dev/plcopen/1"><network first="9"/></networks></data></addData>"#;
    let error = import_error(&document("LD", &objects, entry)).to_string();
    assert!(
        error.contains("Rivet's networks entry is unreadable: no object has the localId 9"),
        "{error}"
    );
}

#[test]
fn an_in_out_variable_with_a_negation_is_refused() {
    let objects = r#"<inVariable localId="1"><position x="0" y="0"/><connectionPointOut/><expression>a</expression></inVariable><inOutVariable localId="2" negatedIn="true"><position x="100" y="0"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut/><expression>v</expression></inOutVariable>"#;
    let error = import_error(&document("FBD", objects, "")).to_string();
    assert!(
        error.contains("inOutVariable[@localId='2']: the inOutVariable `v` has a negation"),
        "{error}"
    );
}

#[test]
fn a_variable_or_box_that_drives_nothing_ends_a_chain_of_its_own() {
    let objects = r#"<inVariable localId="1"><position x="0" y="0"/><connectionPointOut/><expression>alone</expression></inVariable>
<block localId="2" typeName="TON" instanceName="t"><position x="0" y="100"/><inputVariables><variable formalParameter="IN"><connectionPointIn/></variable></inputVariables><inOutVariables/><outputVariables><variable formalParameter="Q"><connectionPointOut/></variable></outputVariables></block>"#;
    assert_eq!(rendered(&networks("FBD", objects)), ["alone", "TON[t](IN)"]);
}

#[test]
fn a_block_naming_one_pin_twice_is_refused() {
    let objects = r#"<block localId="2" typeName="ADD"><position x="0" y="0"/><inputVariables><variable formalParameter="IN1"><connectionPointIn/></variable><variable formalParameter="in1"><connectionPointIn/></variable></inputVariables><inOutVariables/><outputVariables><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables></block>"#;
    let error = import_error(&document("FBD", objects, "")).to_string();
    assert!(
        error.contains("block[@localId='2']: the block `ADD` has two pins named `in1`"),
        "{error}"
    );
}

#[test]
fn without_positions_the_connections_of_a_wired_or_order_its_branches() {
    // CODESYS: no positions; b is written before a, but the OR connects a first.
    let objects = r#"<leftPowerRail localId="0"><connectionPointOut formalParameter="none"/></leftPowerRail>
<contact localId="1"><connectionPointIn><connection refLocalId="0"/></connectionPointIn><connectionPointOut/><variable>b</variable></contact>
<contact localId="2"><connectionPointIn><connection refLocalId="0"/></connectionPointIn><connectionPointOut/><variable>a</variable></contact>
<coil localId="3"><connectionPointIn><connection refLocalId="2"/><connection refLocalId="1"/></connectionPointIn><connectionPointOut/><variable>X</variable></coil>"#;
    assert_eq!(rendered(&networks("LD", objects)), ["(a | b) -> X"]);
}

#[test]
fn boxes_nested_deeper_than_a_body_may_hold_are_refused() {
    // ADD k adds `x` to ADD k-1 through its second input, 100 levels deep.
    let mut objects = String::from(
        r#"<inVariable localId="1"><position x="0" y="0"/><connectionPointOut/><expression>x</expression></inVariable>"#,
    );
    for level in 0..100u64 {
        let id = 10 + level;
        let second = if level == 0 { 1 } else { id - 1 };
        objects.push_str(&format!(
            r#"<block localId="{id}" typeName="ADD"><position x="0" y="0"/><inputVariables><variable formalParameter="IN1"><connectionPointIn><connection refLocalId="1"/></connectionPointIn></variable><variable formalParameter="IN2"><connectionPointIn><connection refLocalId="{second}" formalParameter="OUT"/></connectionPointIn></variable></inputVariables><inOutVariables/><outputVariables><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables></block>
"#
        ));
    }
    objects.push_str(r#"<outVariable localId="500"><position x="0" y="0"/><connectionPointIn><connection refLocalId="109" formalParameter="OUT"/></connectionPointIn><expression>y</expression></outVariable>"#);
    let error = import_error(&document("FBD", &objects, "")).to_string();
    assert!(
        error.contains("the network nests boxes or branches more than 64 levels deep"),
        "{error}"
    );
}

/// Rivet's `…/networks` entry with a network starting at each of `firsts`.
fn networks_entry(firsts: &[u64]) -> String {
    let networks: String = firsts
        .iter()
        .map(|first| format!(r#"<network first="{first}"/>"#))
        .collect();
    format!(
        r#"<addData><data name="https://rivet-plc.dev/plcopen/1/networks" handleUnknown="preserve"><networks xmlns="https://rivet-plc.dev/plcopen/1">{networks}</networks></data></addData>"#
    )
}

fn in_variable(id: u64, expression: &str, y: u32) -> String {
    format!(
        r#"<inVariable localId="{id}"><position x="0" y="{y}"/><connectionPointOut/><expression>{expression}</expression></inVariable>"#
    )
}

fn out_variable(id: u64, expression: &str, from: &str, y: u32) -> String {
    format!(
        r#"<outVariable localId="{id}"><position x="500" y="{y}"/><connectionPointIn>{from}</connectionPointIn><expression>{expression}</expression></outVariable>"#
    )
}

/// A box `type_name` at `y` with one input per `(pin, connections)` and the output `OUT`;
/// `add_data` is written inside it.
fn function_box(
    id: u64,
    type_name: &str,
    inputs: &[(&str, &str)],
    y: u32,
    add_data: &str,
) -> String {
    let pins: String = inputs
        .iter()
        .map(|(pin, from)| {
            format!(
                r#"<variable formalParameter="{pin}"><connectionPointIn>{from}</connectionPointIn></variable>"#
            )
        })
        .collect();
    format!(
        r#"<block localId="{id}" typeName="{type_name}"><position x="200" y="{y}"/><inputVariables>{pins}</inputVariables><inOutVariables/><outputVariables><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables>{add_data}</block>"#
    )
}

fn from(id: u64) -> String {
    format!(r#"<connection refLocalId="{id}"/>"#)
}

fn from_out(id: u64) -> String {
    format!(r#"<connection refLocalId="{id}" formalParameter="OUT"/>"#)
}

#[test]
fn another_tools_variable_read_by_two_first_inputs_is_read_again_for_each() {
    let objects = [
        in_variable(1, "x", 0),
        in_variable(2, "1", 40),
        function_box(3, "ADD", &[("IN1", &from(1)), ("IN2", &from(2))], 0, ""),
        out_variable(4, "x", &from_out(3), 0),
        in_variable(5, "10", 140),
        function_box(6, "ADD", &[("IN1", &from(1)), ("IN2", &from(5))], 100, ""),
        out_variable(7, "y", &from_out(6), 100),
    ]
    .concat();
    // An INT is no power: kept as one operand the two boxes follow, the lowering would store
    // it in a BOOL, and the lower box would not see the upper box's write.
    assert_eq!(
        rendered(&networks("FBD", &objects)),
        ["-> {x ADD(IN1; IN2=1) -> x}, {x ADD(IN1; IN2=10) -> y}"]
    );
}

#[test]
fn a_network_of_rivets_body_another_tool_changed_falls_back_alone_and_is_reported() {
    let objects = [
        // Network 1, as Rivet's export writes it: b's power fans out to two coils.
        in_variable(1, "b", 0),
        out_variable(2, "P", &from(1), 0),
        out_variable(3, "Q", &from(1), 40),
        // Network 2, edited: x drives F1 and F2, and F1's result is a value into ADD.
        in_variable(10, "x", 100),
        function_box(11, "F1", &[("IN", &from(10))], 100, ""),
        in_variable(12, "y", 160),
        function_box(
            13,
            "ADD",
            &[("IN1", &from(12)), ("IN2", &from_out(11))],
            160,
            "",
        ),
        out_variable(14, "Z", &from_out(13), 160),
        function_box(15, "F2", &[("IN", &from(10))], 200, ""),
        out_variable(16, "W", &from_out(15), 200),
    ]
    .concat();
    let imported = imported(&document("FBD", &objects, &networks_entry(&[1, 10])));
    assert_eq!(
        rendered(&networks_of(&imported)),
        [
            "b -> P, Q",
            "-> {x F2(IN) -> W}, {y ADD(IN1; IN2=x F1(IN)) -> Z}"
        ]
    );
    let notes: Vec<&str> = imported
        .report
        .entries
        .iter()
        .filter(|entry| entry.what.starts_with("network "))
        .map(|entry| entry.what.as_str())
        .collect();
    assert_eq!(notes, ["network 2 of POU 'P'"]);
}

#[test]
fn a_marked_or_without_inputs_is_an_ordinary_box_and_keeps_what_follows_it() {
    let gate = r#"<addData><data name="https://rivet-plc.dev/plcopen/1/gate" handleUnknown="discard"><gate xmlns="https://rivet-plc.dev/plcopen/1" of="parallel"/></data></addData>"#;
    let objects = [
        in_variable(1, "a", 0),
        out_variable(2, "X", &from(1), 0),
        function_box(3, "OR", &[], 40, gate),
        out_variable(4, "Y", &from_out(3), 40),
    ]
    .concat();
    let imported = imported(&document("FBD", &objects, &networks_entry(&[1, 3])));
    assert_eq!(rendered(&networks_of(&imported)), ["a -> X", "OR() -> Y"]);
}

#[test]
fn an_output_no_wire_from_the_rail_reaches_makes_the_body_no_set_of_networks() {
    // Y's wire comes from the jump, which passes nothing on.
    let objects = [
        rail(1, 0),
        contact(2, "a", &[1], 0, ""),
        format!(
            r#"<jump localId="3" label="Done"><position x="500" y="0"/>{}</jump>"#,
            wires(&[2])
        ),
        coil(4, "Y", &[3], 40, ""),
    ]
    .concat();
    let imported = imported(&document("LD", &objects, ""));
    let entry = imported.report.entries.iter().find(|entry| {
        entry
            .note
            .contains("is reached by no wire from the power rail")
    });
    assert!(
        entry.is_some_and(|entry| entry.note.contains("coil with local id 4")),
        "{:?}",
        imported.report
    );
}

#[test]
fn a_source_mark_the_wires_no_longer_fit_is_ignored() {
    let mark = r#"<addData><data name="https://rivet-plc.dev/plcopen/1/source" handleUnknown="discard"><source xmlns="https://rivet-plc.dev/plcopen/1" pin="IN1"/></data></addData>"#;
    // Another tool wired the rail to the marked pin: the box takes the power, as any box.
    let ladder = [
        rail(1, 0),
        in_variable(2, "x", 40),
        function_box(3, "ADD", &[("IN1", &from(1)), ("IN2", &from(2))], 0, mark),
        coil(4, "Y", &[3], 0, ""),
    ]
    .concat();
    assert_eq!(rendered(&networks("LD", &ladder)), ["ADD(IN1; IN2=x) -> Y"]);
    // The marked pin's variable also drives a coil: one read, the power for both.
    let blocks = [
        in_variable(1, "a", 0),
        function_box(2, "ADD", &[("IN1", &from(1)), ("IN2", "")], 0, mark),
        out_variable(3, "Y", &from_out(2), 0),
        out_variable(4, "Z", &from(1), 40),
    ]
    .concat();
    assert_eq!(
        rendered(&networks_of(&imported(&document(
            "FBD",
            &blocks,
            &networks_entry(&[1])
        )))),
        ["a -> {ADD(IN1; IN2) -> Y}, Z"]
    );
}

#[test]
fn parallel_groups_nested_deeper_than_a_body_may_hold_are_refused_as_too_deep() {
    // Level k: (level k-1, then c_k) in parallel with b_k, 100 levels deep.
    let mut objects = vec![rail(1, 0), contact(2, "a", &[1], 0, "")];
    let mut end = 2;
    for level in 0..100u64 {
        let b = 1000 + 2 * level;
        let c = b + 1;
        objects.push(contact(b, "b", &[1], 40, ""));
        objects.push(contact(c, "c", &[end, b], 0, ""));
        end = c;
    }
    objects.push(coil(5000, "X", &[end], 0, ""));
    let error = import_error(&document("LD", &objects.concat(), "")).to_string();
    assert!(
        error.contains("the network nests boxes or branches more than 64 levels deep"),
        "{error}"
    );
}
