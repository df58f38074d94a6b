//! Round trips through the export: the example project and every corpus file, validated by
//! xmllint against the v2.01 schema, imported back equal, and exported again to the same bytes.

use std::path::PathBuf;
use std::process::Command;
use std::sync::atomic::{AtomicUsize, Ordering};

use project_model::{Object, Project};

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
    let project_model::Body::Ld { networks } = &converted.body else {
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
    let written = document
        .pous
        .iter()
        .find(|written| written.name == pou)
        .unwrap();
    let block = written.bodies[0]
        .content
        .objects()
        .iter()
        .find(|object| object.local_id == u64::from(id))
        .unwrap();
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

/// The POUs of the example whose graphical bodies come back from a plain PLCopen document in
/// another (equivalent) shape: the export's FBD and LD graphs and the import's normal form of a
/// network differ (issue 18, left open: a chain's operands written through an AND box, a box
/// first in a rung with a driven first input, a branch holding one parallel group).
const GRAPHS_NOT_YET_ROUND_TRIPPING_IN_THE_EXAMPLE: [&str; 2] = ["Scaling", "TempControl"];

#[test]
fn without_rivet_object_entries_the_example_imports_as_another_tools_file() {
    let project = project_model::load_project(&assets::example_project_dir())
        .unwrap()
        .project;
    let options = super::ExportOptions {
        object_entries: false,
    };
    let xml = super::export_with(&project, options).unwrap();
    assert_valid(&xml, "the example without object entries");
    let document = read_bytes(&xml, "plain.xml").unwrap();
    let imported = import(&document).unwrap();
    // PLCopen has no place for an enumeration value's comment: only Rivet's entry keeps it.
    let mut expected = project.clone();
    for node in &mut expected.application.children {
        if let project_model::Node::Object(Object::DataType(data_type)) = node
            && let project_model::TypeDefinition::Enum { values, .. } = &mut data_type.definition
        {
            values.iter_mut().for_each(|value| value.comment.clear());
        }
    }
    let (compared, changed) = objects_changed(&expected, &imported.project);
    assert_eq!(compared, expected.application.objects().len());
    assert_eq!(
        changed, GRAPHS_NOT_YET_ROUND_TRIPPING_IN_THE_EXAMPLE,
        "the example"
    );
}

#[test]
fn without_rivet_object_entries_every_corpus_project_imports_back_its_objects() {
    let options = super::ExportOptions {
        object_entries: false,
    };
    for file in FILES {
        let project = import(&read_corpus(file)).unwrap().project;
        let xml = super::export_with(&project, options).unwrap();
        assert_valid(&xml, file);
        let document = read_bytes(&xml, "plain.xml").unwrap_or_else(|error| panic!("{error}"));
        let imported = import(&document).unwrap_or_else(|error| panic!("{file}: {error}"));
        let (compared, changed) = objects_changed(&project, &imported.project);
        assert_eq!(compared, project.application.objects().len(), "{file}");
        assert!(changed.is_empty(), "{file}: {changed:?} came back changed");
        assert_eq!(imported.project.vendor_data, project.vendor_data, "{file}");
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
    assert!(matches!(counter.body, project_model::Body::Il { .. }));
}
