//! Round trips through the export: the example project and every corpus file, validated by
//! xmllint against the v2.01 schema, imported back equal, and exported again to the same bytes.

use std::path::PathBuf;
use std::process::Command;
use std::sync::atomic::{AtomicUsize, Ordering};

use project_model::{Body, Edge, FlowNode, Network, NetworkOutput, Object, Operand, Pou, Project};

use super::export;
use crate::import::corpus_tests::FILES;
use crate::reader::corpus_tests::{corpora, read_corpus};
use crate::{Outcome, import, read_bytes};

/// What xmllint (Debian's libxml2-utils, which `scripts/test.sh` installs) says against `xml`
/// when the v2.01 schema refuses it.
fn schema_errors(xml: &[u8]) -> Option<String> {
    static COUNT: AtomicUsize = AtomicUsize::new(0);
    let file = std::env::temp_dir().join(format!(
        "rivet-plcopen-export-{}-{}.xml",
        std::process::id(),
        COUNT.fetch_add(1, Ordering::Relaxed)
    ));
    std::fs::write(&file, xml).unwrap();
    let schema: PathBuf = corpora().join("plcopen/schema/tc6_xml_v201.xsd");
    let output = Command::new("xmllint")
        .arg("--noout")
        .arg("--schema")
        .arg(&schema)
        .arg(&file)
        .output()
        .unwrap_or_else(|error| {
            panic!("xmllint (Debian package libxml2-utils) cannot be run: {error}")
        });
    let _ = std::fs::remove_file(&file);
    (!output.status.success()).then(|| String::from_utf8_lossy(&output.stderr).into_owned())
}

/// Checks `xml` against the v2.01 schema.
#[track_caller]
pub(super) fn assert_valid(xml: &[u8], what: &str) {
    if let Some(errors) = schema_errors(xml) {
        panic!("{what}: the export does not validate:\n{errors}");
    }
}

#[test]
fn the_schema_check_refuses_what_the_schema_does_not_accept() {
    let text = String::from_utf8(export(&Project::default()).unwrap()).unwrap();
    assert!(text.contains("<resource name=\"Application\">"), "{text}");
    // A task without its required priority.
    let xml = text
        .replace(
            "<resource name=\"Application\">",
            "<resource name=\"Application\"><task name=\"t\"/>",
        )
        .into_bytes();
    let errors = schema_errors(&xml).expect("xmllint accepted a task without priority");
    assert!(errors.contains("priority"), "{errors}");
}

/// Exports `project`, checks the document, imports it back and checks the project and a second
/// export; gives the document.
#[track_caller]
pub(super) fn assert_round_trip(project: &Project, what: &str) -> Vec<u8> {
    let xml = export(project).unwrap_or_else(|error| panic!("{what}: {error}"));
    assert_valid(&xml, what);
    let document = read_bytes(&xml, "export.xml").unwrap_or_else(|error| panic!("{what}: {error}"));
    let imported = import(&document).unwrap_or_else(|error| panic!("{what}: {error}"));
    assert_eq!(
        &imported.project, project,
        "{what}: the project came back changed"
    );
    let again = export(&imported.project).unwrap_or_else(|error| panic!("{what}: {error}"));
    assert!(xml == again, "{what}: the second export differs");
    xml
}

#[test]
fn the_example_project_round_trips_through_a_valid_document() {
    let loaded = project_model::load_project(&assets::example_project_dir()).unwrap();
    let project = loaded.project;
    let xml = assert_round_trip(&project, "the example project");
    // Other tools see the POUs and lists as PLCopen, not only in Rivet's data.
    let document = read_bytes(&xml, "export.xml").unwrap();
    let pous = project
        .application
        .objects()
        .into_iter()
        .filter(|object| matches!(object, Object::Pou(_)))
        .count();
    assert_eq!(document.pous.len(), pous);
    assert!(!document.configurations[0].resources[0].tasks.is_empty());
}

#[test]
fn serial_ports_and_runtime_modbus_devices_round_trip_in_rivets_data() {
    use project_model::{
        ChannelDirection, ChannelTrigger, ModbusBinding, ModbusDataType, ModbusLink,
        ModbusSchedule, ModbusTable, Parity, SerialPort,
    };

    let mut project = project_model::load_project(&assets::example_project_dir())
        .unwrap()
        .project;
    project.serial_ports.push(SerialPort {
        parity: Parity::Odd,
        inter_frame_delay_us: 5000,
        ..SerialPort::new("RS485", "/dev/ttyUSB0")
    });
    project
        .serial_ports
        .push(SerialPort::new("RS232", "/dev/ttyS0"));
    let mut device = project.modbus_devices[0].clone();
    device.name = "TempController".into();
    device.link = ModbusLink::Rtu {
        serial_port: "RS485".into(),
    };
    device.poll_interval_ms = None;
    device.task = Some("MainTask".into());
    device.schedule = ModbusSchedule::EveryCycle;
    device.max_read_gap = 3;
    device.status = Some("GVL_Machine.stTemp".into());
    let mut channel = ModbusBinding::new(
        "GVL_Machine.xPulse",
        ModbusTable::Coil,
        4,
        ModbusDataType::Bool,
    );
    channel.direction = ChannelDirection::Write;
    channel.function_code = Some(5);
    channel.trigger = ChannelTrigger::RisingEdge;
    channel.trigger_variable = Some("GVL_Machine.xSend".into());
    channel.error_flag = Some("GVL_Machine.xPulseError".into());
    device.bindings.push(channel);
    project.modbus_devices.push(device);
    let xml = assert_round_trip(&project, "runtime Modbus devices");
    let text = String::from_utf8(xml).unwrap();
    assert!(text.contains("[[serial_port]]"), "{text}");
    assert!(text.contains("serial_port = \"RS485\""), "{text}");
}

#[test]
fn every_corpus_project_round_trips_through_a_valid_document() {
    for file in FILES {
        let document = read_corpus(file);
        let imported = import(&document).unwrap_or_else(|error| panic!("{file}: {error}"));
        let xml = assert_round_trip(&imported.project, file);
        // Every entry another tool wrote goes back, as it was.
        let text = String::from_utf8(xml).unwrap();
        for entry in &imported.project.vendor_data.entries {
            assert!(
                text.contains(&entry.xml) || text.contains(&format!("<![CDATA[{}", entry.xml)),
                "{file}: the entry at {} is not written back",
                entry.place
            );
        }
    }
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig {
        cases: 24,
        ..proptest::prelude::ProptestConfig::default()
    })]

    #[test]
    fn a_generated_project_round_trips_through_a_valid_document(
        project in project_model::arb::project()
    ) {
        assert_round_trip(&project, "a generated project");
    }
}

#[test]
fn codesys_entries_go_back_into_the_element_they_came_from() {
    let file = "plcopen/codesys/codesys_code_execution_speedTests.xml";
    let imported = import(&read_corpus(file)).unwrap();
    let kept = &imported.project.vendor_data;
    assert!(
        kept.at("pou:x01_ImpactOfDynamicArrays").next().is_some(),
        "{kept:?}"
    );
    let xml = export(&imported.project).unwrap();
    let document = read_bytes(&xml, "export.xml").unwrap();
    let pou = document
        .pous
        .iter()
        .find(|pou| pou.name == "x01_ImpactOfDynamicArrays")
        .unwrap();
    assert!(
        pou.add_data
            .entries
            .iter()
            .any(|entry| entry.name.ends_with("/objectid")),
        "{:?}",
        pou.add_data
    );
}

#[test]
fn codesys_entries_of_a_box_follow_the_element_it_became() {
    let file = "plcopen/codesys/codesys_code_execution_speedTests.xml";
    let imported = import(&read_corpus(file)).unwrap();
    // The ADD box of the LD function carries CODESYS's call type, kept with its element.
    let pou = "addTwoIntsLadder";
    let prefix = format!("pou:{pou}/body/element:");
    let kept: Vec<&project_model::VendorEntry> = imported
        .project
        .vendor_data
        .entries
        .iter()
        .filter(|entry| entry.place.starts_with(&prefix))
        .collect();
    assert_eq!(kept.len(), 1, "{kept:?}");
    assert!(kept[0].xml.contains("fbdcalltype"), "{}", kept[0].xml);
    let id: u32 = kept[0].place[prefix.len()..].parse().unwrap();
    let Some(Object::Pou(converted)) = imported.project.application.object(pou) else {
        panic!("{pou} is not converted");
    };
    let Body::Ld { networks } = &converted.body else {
        panic!("{pou}: {:?}", converted.body);
    };
    let element = networks
        .iter()
        .find_map(|network| network.element(project_model::ElementId(id)));
    assert!(
        matches!(element, Some(project_model::ElementRef::Block(block)) if block.type_name == "ADD"),
        "{element:?}"
    );
    let reported = imported
        .report
        .entries
        .iter()
        .find(|entry| entry.path.contains("addTwoIntsLadder']/body/LD/block"))
        .unwrap();
    assert_eq!(reported.outcome, Outcome::KeptOpaque);

    // The export writes it into the object of that element, and the import puts it back.
    let xml = export(&imported.project).unwrap();
    let document = read_bytes(&xml, "export.xml").unwrap();
    let block = body_object(&document, pou, id);
    assert!(matches!(
        block.kind,
        crate::body_object::ObjectKind::Block(_)
    ));
    assert_eq!(block.add_data.entries.len(), 1);
    assert_eq!(block.add_data.entries[0].xml, kept[0].xml);
    let back = import(&document).unwrap();
    assert_eq!(back.project.vendor_data, imported.project.vendor_data);
}

#[test]
fn an_entry_whose_element_was_deleted_is_kept_in_rivets_vendor_entry() {
    let file = "plcopen/codesys/codesys_code_execution_speedTests.xml";
    let mut project = import(&read_corpus(file)).unwrap().project;
    for entry in &mut project.vendor_data.entries {
        if entry
            .place
            .starts_with("pou:addTwoIntsLadder/body/element:")
        {
            entry.place = "pou:addTwoIntsLadder/body/element:999".into();
        }
    }
    let xml = assert_round_trip(&project, "an entry without its element");
    let text = String::from_utf8(xml).unwrap();
    assert!(
        text.contains("place=\"pou:addTwoIntsLadder/body/element:999\""),
        "the entry is not in Rivet's vendor entry"
    );
}

#[test]
fn the_data_of_a_wire_is_reported_not_converted() {
    let file = "plcopen/codesys/codesys_code_execution_speedTests.xml";
    let imported = import(&read_corpus(file)).unwrap();
    let wires: Vec<_> = imported
        .report
        .entries
        .iter()
        .filter(|entry| entry.path.contains("/connection[@refLocalId="))
        .collect();
    assert!(!wires.is_empty(), "no wire's data is reported");
    assert!(
        wires
            .iter()
            .all(|entry| entry.outcome == Outcome::NotConverted
                && entry.path.ends_with("ldbranchid']")),
        "{wires:?}"
    );
}

/// The id of the `addTwoIntsLadder` element that keeps CODESYS's call type, and the project.
fn project_with_box_entry() -> (Project, u32) {
    let file = "plcopen/codesys/codesys_code_execution_speedTests.xml";
    let project = import(&read_corpus(file)).unwrap().project;
    let prefix = "pou:addTwoIntsLadder/body/element:";
    let entry = project
        .vendor_data
        .entries
        .iter()
        .find(|entry| entry.place.starts_with(prefix))
        .unwrap();
    assert_eq!(
        entry.signature.as_deref(),
        Some("block ADD EN"),
        "{entry:?}"
    );
    let id = entry.place[prefix.len()..].parse().unwrap();
    (project, id)
}

/// The networks of the LD POU `name` of `project`, to edit.
fn ld_networks<'p>(project: &'p mut Project, name: &str) -> &'p mut Vec<Network> {
    let Some(Object::Pou(pou)) = project.application.object_mut(name) else {
        panic!("{name} is not a POU");
    };
    let Body::Ld { networks } = &mut pou.body else {
        panic!("{name} is not LD");
    };
    networks
}

/// The object of element `id` in the first body of POU `pou` of an exported `document`.
fn body_object<'d>(document: &'d crate::Document, pou: &str, id: u32) -> &'d crate::BodyObject {
    let written = document
        .pous
        .iter()
        .find(|written| written.name == pou)
        .unwrap();
    written.bodies[0]
        .content
        .objects()
        .iter()
        .find(|object| object.local_id == u64::from(id))
        .unwrap()
}

#[test]
fn an_entry_never_goes_into_another_element_that_took_its_id() {
    let (mut project, id) = project_with_box_entry();
    // An edit replaces the ADD box by a TON box with the same id.
    let mut replaced = false;
    for network in ld_networks(&mut project, "addTwoIntsLadder").iter_mut() {
        for node in &mut network.rung {
            if let FlowNode::Block(block) = node
                && block.id.0 == id
            {
                block.type_name = "TON".into();
                replaced = true;
            }
        }
    }
    assert!(replaced, "the ADD box is not in the rung");
    let xml = export(&project).unwrap();
    let document = read_bytes(&xml, "export.xml").unwrap();
    let block = body_object(&document, "addTwoIntsLadder", id);
    assert!(
        !block
            .add_data
            .entries
            .iter()
            .any(|entry| entry.xml.contains("fbdcalltype")),
        "the ADD box's data went into the TON box"
    );
    // It is kept with its place and signature in Rivet's vendor entry, and comes back so.
    let text = String::from_utf8(xml).unwrap();
    assert!(
        text.contains("signature=\"block ADD EN\""),
        "not a leftover"
    );
    let back = import(&document).unwrap();
    assert_eq!(back.project.vendor_data, project.vendor_data);
}

#[test]
fn an_element_written_with_its_entry_keeps_another_elements_entry_of_its_id_as_a_leftover() {
    let (mut project, id) = project_with_box_entry();
    // The box's own entry, and one an earlier TON box of that id left.
    let own = project
        .vendor_data
        .entries
        .iter()
        .find(|entry| entry.signature.as_deref() == Some("block ADD EN"))
        .cloned()
        .unwrap();
    project
        .vendor_data
        .entries
        .push(project_model::VendorEntry {
            place: own.place.clone(),
            xml: "<data name=\"old\" handleUnknown=\"discard\"><old/></data>".into(),
            signature: Some("block TON EN".into()),
        });
    project
        .vendor_data
        .entries
        .sort_by(|left, right| left.place.cmp(&right.place));
    let xml = export(&project).unwrap();
    let document = read_bytes(&xml, "export.xml").unwrap();
    let block = body_object(&document, "addTwoIntsLadder", id);
    let names: Vec<&str> = block
        .add_data
        .entries
        .iter()
        .map(|entry| entry.name.as_str())
        .collect();
    assert!(
        !names.contains(&"old"),
        "the TON box's entry went into the ADD box"
    );
    assert!(
        String::from_utf8(xml)
            .unwrap()
            .contains("signature=\"block TON EN\""),
        "the TON box's entry was dropped"
    );
    let back = import(&document).unwrap();
    assert_eq!(back.project.vendor_data, project.vendor_data);
}

#[test]
fn an_object_another_tool_changed_does_not_take_the_entry_of_its_id() {
    let (project, id) = project_with_box_entry();
    let text = String::from_utf8(export(&project).unwrap()).unwrap();
    // Another tool turns the box of that id into a SUB box; Rivet's entry still says ADD.
    let marker = format!("localId=\"{id}\" typeName=\"ADD\"");
    assert!(text.contains(&marker), "the box is not written as expected");
    let changed = text.replace(&marker, &format!("localId=\"{id}\" typeName=\"SUB\""));
    let document = read_bytes(changed.as_bytes(), "changed.xml").unwrap();
    let back = import(&document).unwrap();
    let place = format!("pou:addTwoIntsLadder/body/element:{id}");
    assert!(
        back.project.vendor_data.at(&place).next().is_none(),
        "{:?}",
        back.project.vendor_data
    );
    assert!(
        back.report
            .entries
            .iter()
            .any(|entry| entry.outcome == Outcome::NotConverted
                && entry.path.contains(&format!("[@localId='{id}']"))),
        "not reported"
    );
}

/// The objects of `expected` that `imported` holds too, each compared whole: how many were
/// compared, and the names of those that came back changed (sorted).
fn objects_changed(expected: &Project, imported: &Project) -> (usize, Vec<String>) {
    let mut compared = 0;
    let mut changed = Vec::new();
    for object in expected.application.objects() {
        if let Some(back) = imported.application.object(object.name()) {
            if back != object {
                changed.push(object.name().to_owned());
            }
            compared += 1;
        }
    }
    changed.sort();
    (compared, changed)
}

/// The first network of the POU `name` that differs between `expected` and `imported`, both
/// printed, or else both objects: what a failed plain round trip shows.
fn first_difference(expected: &Project, imported: &Project, name: &str) -> String {
    let (Some(expected), Some(imported)) = (
        expected.application.object(name),
        imported.application.object(name),
    ) else {
        return format!("{name} is missing");
    };
    let networks = |object: &Object| match object {
        Object::Pou(pou) => match &pou.body {
            Body::Ld { networks } | Body::Fbd { networks } => Some(networks.clone()),
            _ => None,
        },
        _ => None,
    };
    if let (Some(before), Some(after)) = (networks(expected), networks(imported)) {
        let language = match expected {
            Object::Pou(pou) if matches!(pou.body, Body::Fbd { .. }) => "FBD",
            _ => "LD",
        };
        for index in 0..before.len().max(after.len()) {
            if before.get(index) != after.get(index) {
                let sketch = |network: Option<&Network>| {
                    network.map_or_else(|| "none".to_owned(), sketch_network)
                };
                return format!(
                    "{name} ({language}), network {}:\nexported {}\nimported {}",
                    index + 1,
                    sketch(before.get(index)),
                    sketch(after.get(index))
                );
            }
        }
    }
    format!("{name}:\nexported {expected:#?}\nimported {imported:#?}")
}

/// A network in one line: operands with their modifiers (`!` negated, `P`/`N` edges, `#id`),
/// parallel groups in parentheses, boxes with their inputs' sources, then `=>` the outputs.
fn sketch_network(network: &Network) -> String {
    fn operand(operand: &Operand) -> String {
        let edge = match operand.edge {
            Edge::None => "",
            Edge::Rising => "P:",
            Edge::Falling => "N:",
        };
        let not = if operand.negated { "!" } else { "" };
        format!("{not}{edge}{}#{}", operand.text, operand.id.0)
    }
    fn chain(nodes: &[FlowNode]) -> String {
        let parts: Vec<String> = nodes
            .iter()
            .map(|node| match node {
                FlowNode::Operand(o) => operand(o),
                FlowNode::Parallel(parallel) => {
                    let branches: Vec<String> =
                        parallel.branches.iter().map(|b| chain(&b.rung)).collect();
                    format!("({})#{}", branches.join(" | "), parallel.id.0)
                }
                FlowNode::Block(block) => {
                    let inputs: Vec<String> = block
                        .inputs
                        .iter()
                        .map(|input| {
                            format!(
                                "{}{}{}={}",
                                if input.negated { "!" } else { "" },
                                input.pin,
                                match input.edge {
                                    Edge::None => "",
                                    Edge::Rising => "^",
                                    Edge::Falling => "v",
                                },
                                chain(&input.source)
                            )
                        })
                        .collect();
                    let outputs: Vec<String> = block
                        .outputs
                        .iter()
                        .map(|output| {
                            format!(
                                "{}{}>{}",
                                if output.negated { "!" } else { "" },
                                output.pin,
                                output.assign
                            )
                        })
                        .collect();
                    format!(
                        "{}:{}#{}({}; {})",
                        block.instance,
                        block.type_name,
                        block.id.0,
                        inputs.join(", "),
                        outputs.join(", ")
                    )
                }
            })
            .collect();
        format!("[{}]", parts.join(" "))
    }
    fn outputs(list: &[NetworkOutput]) -> String {
        let parts: Vec<String> = list
            .iter()
            .map(|output| match output {
                NetworkOutput::Coil(coil) => {
                    format!("{}:{:?}#{}", coil.variable, coil.kind, coil.id.0)
                }
                NetworkOutput::Jump { label, id } => format!("jump {label}#{}", id.0),
                NetworkOutput::Return { id } => format!("return#{}", id.0),
                NetworkOutput::Branch {
                    id,
                    rung,
                    outputs: inner,
                } => {
                    format!("{{#{} {} => {}}}", id.0, chain(rung), outputs(inner))
                }
            })
            .collect();
        format!("<{}>", parts.join(", "))
    }
    format!("{} => {}", chain(&network.rung), outputs(&network.outputs))
}

/// The plain document (no object entries) of `project`, checked against the schema.
#[track_caller]
fn plain_export(project: &Project, what: &str) -> Vec<u8> {
    let options = super::ExportOptions {
        object_entries: false,
    };
    let xml =
        super::export_with(project, options).unwrap_or_else(|error| panic!("{what}: {error}"));
    assert_valid(&xml, what);
    xml
}

/// The project a plain document gives; with `all_converted`, every object must be converted.
#[track_caller]
fn plain_import(xml: &[u8], what: &str, all_converted: bool) -> Project {
    let document = read_bytes(xml, "plain.xml").unwrap_or_else(|error| panic!("{what}: {error}"));
    let imported = import(&document).unwrap_or_else(|error| panic!("{what}: {error}"));
    let not_converted: Vec<String> = imported
        .report
        .with_outcome(Outcome::NotConverted)
        .map(|entry| format!("{}: {}", entry.what, entry.note))
        .collect();
    assert!(
        !all_converted || not_converted.is_empty(),
        "{what}: not converted: {not_converted:#?}"
    );
    imported.project
}

/// Checks that every object of `expected` comes back equal from `imported`.
#[track_caller]
fn assert_same_objects(expected: &Project, imported: &Project, what: &str) {
    let (compared, changed) = objects_changed(expected, imported);
    assert_eq!(compared, expected.application.objects().len(), "{what}");
    if let Some(name) = changed.first() {
        panic!(
            "{what}: {changed:?} came back changed; {}",
            first_difference(expected, imported, name)
        );
    }
}

/// The example with what a plain document cannot hold taken out.
fn example_as_plain_document_holds_it() -> Project {
    let mut project = project_model::load_project(&assets::example_project_dir())
        .unwrap()
        .project;
    // PLCopen has no place for an enumeration value's comment: only Rivet's entry keeps it.
    for node in &mut project.application.children {
        if let project_model::Node::Object(Object::DataType(data_type)) = node
            && let project_model::TypeDefinition::Enum { values, .. } = &mut data_type.definition
        {
            values.iter_mut().for_each(|value| value.comment.clear());
        }
    }
    project
}

#[test]
fn without_rivet_object_entries_the_example_imports_as_another_tools_file() {
    let expected = example_as_plain_document_holds_it();
    // The example's networks are written in the normal form, so each comes back as it is.
    for object in expected.application.objects() {
        if let Object::Pou(pou) = object
            && let Body::Ld { networks } | Body::Fbd { networks } = &pou.body
        {
            let mut normal = networks.clone();
            project_model::normalize_networks(&mut normal);
            assert_eq!(&normal, networks, "{} is not in the normal form", pou.name);
        }
    }
    let xml = plain_export(&expected, "the example without object entries");
    let imported = plain_import(&xml, "the example", true);
    assert_same_objects(&expected, &imported, "the example");
    // And the document it gives is the same document.
    let again = plain_export(&imported, "the example exported again");
    assert!(xml == again, "the example: the second plain export differs");
}

#[test]
fn without_rivet_object_entries_every_corpus_project_imports_back_its_objects() {
    for file in FILES {
        let project = import(&read_corpus(file)).unwrap().project;
        let xml = plain_export(&project, file);
        let imported = plain_import(&xml, file, false);
        assert_same_objects(&project, &imported, file);
        assert_eq!(imported.vendor_data, project.vendor_data, "{file}");
        let again = plain_export(&imported, file);
        assert!(xml == again, "{file}: the second plain export differs");
    }
}

/// A project of LD and FBD programs with generated drawn networks, and nothing else.
fn graphical_project() -> impl proptest::strategy::Strategy<Value = Project> {
    use proptest::prelude::*;
    let body = prop_oneof![
        project_model::arb::drawn_networks().prop_map(|networks| Body::Ld { networks }),
        project_model::arb::drawn_networks().prop_map(|networks| Body::Fbd { networks }),
    ];
    proptest::collection::vec(body, 1..4).prop_map(|bodies| {
        let mut project = Project::default();
        for (index, body) in bodies.into_iter().enumerate() {
            project
                .application
                .children
                .push(project_model::Node::Object(program(
                    &format!("Graph{index}"),
                    body,
                )));
        }
        project
    })
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig {
        cases: 64,
        ..proptest::prelude::ProptestConfig::default()
    })]

    #[test]
    fn generated_ld_and_fbd_networks_round_trip_through_a_plain_document(
        project in graphical_project()
    ) {
        let xml = plain_export(&project, "generated networks");
        let imported = plain_import(&xml, "generated networks", true);
        // The import gives each network in the normal form, its elements numbered in tree
        // order.
        let mut expected = project.clone();
        for node in &mut expected.application.children {
            if let project_model::Node::Object(Object::Pou(pou)) = node
                && let Body::Ld { networks } | Body::Fbd { networks } = &mut pou.body
            {
                project_model::normalize_networks(networks);
                import::number_elements(networks);
            }
        }
        assert_same_objects(&expected, &imported, "generated networks");
        let again = plain_export(&imported, "generated networks exported again");
        let back = plain_import(&again, "generated networks exported again", true);
        assert_same_objects(&imported, &back, "generated networks exported again");
        assert!(
            again == plain_export(&back, "generated networks exported a third time"),
            "the plain export of imported networks changes when imported again"
        );
    }
}

#[test]
fn a_body_another_tool_rewrote_in_another_language_wins_over_rivets_entry() {
    let document = read_corpus("plcopen/beremiz/exemples/first_steps/plc.xml");
    let project = import(&document).unwrap().project;
    let xml = String::from_utf8(export(&project).unwrap()).unwrap();
    // CounterST's body (it has no actions) rewritten in IL, Rivet's object entry left as it was.
    let pou = xml.find("<pou name=\"CounterST\"").unwrap();
    let open = pou + xml[pou..].find("<ST>").unwrap();
    let close = open + xml[open..].find("</ST>").unwrap();
    let body = &xml[open + "<ST>".len()..close];
    let il = "<![CDATA[LD Cnt\nADD 1\nST Cnt\nST OUT]]>";
    let rewritten = format!(
        "{}<IL><xhtml:p xmlns:xhtml=\"http://www.w3.org/1999/xhtml\">{il}</xhtml:p></IL>{}",
        &xml[..open],
        &xml[close + "</ST>".len()..]
    );
    assert!(!body.is_empty());
    let document = read_bytes(rewritten.as_bytes(), "rewritten.xml").unwrap();
    let imported = import(&document).unwrap();
    let Some(Object::Pou(counter)) = imported.project.application.object("CounterST") else {
        panic!("CounterST is not imported")
    };
    assert_eq!(counter.body.text(), Some("LD Cnt\nADD 1\nST Cnt\nST OUT"));
    assert!(matches!(counter.body, Body::Il { .. }));
}

/// A POU named `name` with `body` and nothing else.
fn program(name: &str, body: Body) -> Object {
    Object::Pou(Pou {
        name: name.to_owned(),
        kind: project_model::PouKind::Program,
        return_type: None,
        extends: None,
        implements: Vec::new(),
        comment: String::new(),
        variables: Vec::new(),
        body,
        methods: Vec::new(),
        properties: Vec::new(),
        actions: Vec::new(),
        transitions: Vec::new(),
    })
}

#[test]
fn a_parallel_branch_that_reduces_last_keeps_its_place_among_the_branches() {
    use project_model::{BlockCall, BlockInput, BlockOutput, Branch, Coil, ElementId, Parallel};
    let operand = |text: &str| {
        FlowNode::Operand(Operand {
            text: text.to_owned(),
            ..Operand::default()
        })
    };
    let parallel = |branches: Vec<Vec<FlowNode>>| {
        FlowNode::Parallel(Parallel {
            id: ElementId(0),
            branches: branches.into_iter().map(|rung| Branch { rung }).collect(),
        })
    };
    let block = FlowNode::Block(BlockCall {
        type_name: "F".to_owned(),
        inputs: vec![BlockInput {
            pin: "IN".to_owned(),
            ..BlockInput::default()
        }],
        outputs: vec![BlockOutput {
            pin: "OUT".to_owned(),
            ..BlockOutput::default()
        }],
        ..BlockCall::default()
    });
    // The middle branch holds a group and a box: it becomes one chain only after the simple
    // branches below and above it were joined.
    let mut networks = vec![Network {
        rung: vec![
            operand("x"),
            parallel(vec![
                vec![operand("a")],
                vec![
                    operand("b"),
                    parallel(vec![vec![operand("c")], vec![operand("d")]]),
                    block,
                ],
                vec![operand("z")],
            ]),
        ],
        outputs: vec![NetworkOutput::Coil(Coil {
            variable: "q".to_owned(),
            ..Coil::default()
        })],
        ..Network::default()
    }];
    import::number_elements(&mut networks);
    let mut project = Project::default();
    project.application.children = vec![
        project_model::Node::Object(program(
            "Ladder",
            Body::Ld {
                networks: networks.clone(),
            },
        )),
        project_model::Node::Object(program("Blocks", Body::Fbd { networks })),
    ];
    let xml = plain_export(&project, "three branches");
    let imported = plain_import(&xml, "three branches", true);
    assert_same_objects(&project, &imported, "three branches");
}

#[test]
fn an_empty_parallel_branch_keeps_its_place_and_the_outputs_their_order() {
    use project_model::{Branch, Coil, ElementId, Parallel};
    let operand = |text: &str| {
        FlowNode::Operand(Operand {
            text: text.to_owned(),
            ..Operand::default()
        })
    };
    let parallel = |branches: Vec<Vec<FlowNode>>| {
        FlowNode::Parallel(Parallel {
            id: ElementId(0),
            branches: branches.into_iter().map(|rung| Branch { rung }).collect(),
        })
    };
    let coil = |variable: &str| {
        NetworkOutput::Coil(Coil {
            variable: variable.to_owned(),
            ..Coil::default()
        })
    };
    // [x] => <X, {(a|) => Y}>: the group's empty branch is wired from x, above the group, and
    // the group stands below X.
    let mut networks = vec![
        Network {
            rung: vec![operand("x")],
            outputs: vec![
                coil("X"),
                NetworkOutput::Branch {
                    id: ElementId(0),
                    rung: vec![parallel(vec![vec![operand("a")], Vec::new()])],
                    outputs: vec![coil("Y")],
                },
            ],
            ..Network::default()
        },
        Network {
            rung: vec![operand("x"), parallel(vec![vec![operand("a")], Vec::new()])],
            outputs: vec![
                NetworkOutput::Jump {
                    id: ElementId(0),
                    label: "L".to_owned(),
                },
                coil("Y"),
            ],
            ..Network::default()
        },
        // An empty branch after two others, the second on a row of its own, and after a
        // group that the normal form gives its branches.
        Network {
            rung: vec![
                operand("x"),
                parallel(vec![vec![operand("a")], vec![operand("b")], Vec::new()]),
            ],
            outputs: vec![NetworkOutput::Return { id: ElementId(0) }],
            ..Network::default()
        },
        Network {
            rung: vec![
                operand("y"),
                parallel(vec![
                    vec![parallel(vec![vec![operand("c")], vec![operand("d")]])],
                    Vec::new(),
                ]),
            ],
            outputs: vec![coil("Z")],
            ..Network::default()
        },
    ];
    import::number_elements(&mut networks);
    let project_of = |networks: &[Network]| {
        let mut project = Project::default();
        project.application.children = vec![
            project_model::Node::Object(program(
                "Ladder",
                Body::Ld {
                    networks: networks.to_vec(),
                },
            )),
            project_model::Node::Object(program(
                "Blocks",
                Body::Fbd {
                    networks: networks.to_vec(),
                },
            )),
        ];
        project
    };
    let xml = plain_export(&project_of(&networks), "an empty branch");
    let imported = plain_import(&xml, "an empty branch", true);
    project_model::normalize_networks(&mut networks);
    import::number_elements(&mut networks);
    assert_same_objects(&project_of(&networks), &imported, "an empty branch");
}
