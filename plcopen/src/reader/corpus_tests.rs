//! Every file of the PLCopen and matiec corpora reads, with spot checks per file.

use std::path::{Path, PathBuf};

use crate::{
    BodyContent, BodyObject, ConditionForm, Dialect, Document, ObjectKind, PouLocation, Qualifier,
    TextMarkup, read_bytes,
};

/// The shared corpora beside the repository, as the compiler's tests find them.
pub(crate) fn corpora() -> PathBuf {
    let folder = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../../shared/corpora"));
    assert!(
        folder.is_dir(),
        "the shared corpora are expected at {}",
        folder.display()
    );
    folder.to_path_buf()
}

/// The corpus file at `relative` below [`corpora`], read.
pub(crate) fn read_corpus(relative: &str) -> Document {
    let path = corpora().join(relative);
    let bytes = std::fs::read(&path).unwrap_or_else(|error| panic!("{}: {error}", path.display()));
    read_bytes(&bytes, relative).unwrap_or_else(|error| panic!("{error}"))
}

/// Every `.xml` file under a folder, recursively.
fn xml_files(folder: &Path, found: &mut Vec<PathBuf>) {
    let entries = std::fs::read_dir(folder).unwrap_or_else(|error| panic!("{error}"));
    for entry in entries {
        let path = entry.unwrap_or_else(|error| panic!("{error}")).path();
        if path.is_dir() {
            xml_files(&path, found);
        } else if path.extension().is_some_and(|extension| extension == "xml") {
            found.push(path);
        }
    }
}

fn pou<'d>(document: &'d Document, name: &str) -> &'d crate::Pou {
    document
        .pous
        .iter()
        .find(|pou| pou.name == name)
        .unwrap_or_else(|| panic!("no POU {name}"))
}

fn objects_named<'o>(objects: &'o [BodyObject], element: &str) -> Vec<&'o BodyObject> {
    objects
        .iter()
        .filter(|object| object.kind.element_name() == element)
        .collect()
}

#[test]
fn every_corpus_file_reads() {
    let mut files = Vec::new();
    xml_files(&corpora().join("plcopen"), &mut files);
    xml_files(&corpora().join("matiec/tests"), &mut files);
    assert!(files.len() >= 7, "found only {files:?}");
    for file in files {
        let bytes = std::fs::read(&file).unwrap_or_else(|error| panic!("{error}"));
        let document = read_bytes(&bytes, &file.display().to_string())
            .unwrap_or_else(|error| panic!("{error}"));
        assert!(!document.pous.is_empty(), "{} has no POU", file.display());
    }
}

#[test]
fn beremiz_first_steps_has_its_five_languages_and_task() {
    let document = read_corpus("plcopen/beremiz/exemples/first_steps/plc.xml");
    assert_eq!(document.dialect, Dialect::V201);
    assert_eq!(document.file_header.company_name, "Beremiz");
    let languages: Vec<(&str, &str)> = [
        "CounterST",
        "CounterFBD",
        "CounterSFC",
        "CounterIL",
        "CounterLD",
    ]
    .into_iter()
    .map(|name| (name, pou(&document, name).bodies[0].content.language()))
    .collect();
    assert_eq!(
        languages,
        [
            ("CounterST", "ST"),
            ("CounterFBD", "FBD"),
            ("CounterSFC", "SFC"),
            ("CounterIL", "IL"),
            ("CounterLD", "LD")
        ]
    );
    let BodyContent::St(text) = &pou(&document, "CounterST").bodies[0].content else {
        panic!("CounterST is not ST");
    };
    assert_eq!(text.markup, TextMarkup::XhtmlParagraph);
    assert!(text.cdata);
    assert!(text.text.contains("Cnt := Cnt + 1"), "{}", text.text);
    assert!(
        !text.text.starts_with('\n'),
        "indentation around xhtml:p is not text"
    );
    let ld = pou(&document, "CounterLD").bodies[0].content.objects();
    assert!(!objects_named(ld, "leftPowerRail").is_empty());
    assert!(!objects_named(ld, "contact").is_empty());
    assert!(ld.iter().all(|object| object.position.is_some()));
    let plc_prg = pou(&document, "plc_prg").bodies[0].content.objects();
    assert!(!objects_named(plc_prg, "block").is_empty());
    // The SFC: an initial step, a selection divergence, transitions with inline ST conditions.
    let sfc = pou(&document, "CounterSFC").bodies[0].content.objects();
    let ObjectKind::Step(start) = &sfc[0].kind else {
        panic!("the SFC does not start with its step");
    };
    assert_eq!((start.name.as_str(), start.initial), ("Start", true));
    let ObjectKind::SelectionDivergence(divergence) = &sfc[1].kind else {
        panic!("no selection divergence");
    };
    assert_eq!(divergence.outputs.len(), 2);
    assert_eq!(divergence.outputs[0].formal_parameter.as_deref(), Some(""));
    let conditions: Vec<&str> = objects_named(sfc, "transition")
        .iter()
        .filter_map(|object| match &object.kind {
            ObjectKind::Transition(transition) => transition.condition.as_ref(),
            _ => None,
        })
        .filter_map(|condition| match &condition.form {
            ConditionForm::Inline { body, .. } => match &body.content {
                BodyContent::St(text) => Some(text.text.as_str()),
                _ => None,
            },
            _ => None,
        })
        .take(2)
        .collect();
    assert_eq!(conditions, ["Reset", "NOT Reset"]);
    // Absent and 0 stay apart: transition 3 has no executionOrderId, transition 4 has 0.
    assert_eq!((sfc[2].local_id, sfc[2].execution_order_id), (3, None));
    assert_eq!((sfc[3].local_id, sfc[3].execution_order_id), (4, Some(0)));
    let task = &document.configurations[0].resources[0].tasks[0];
    assert_eq!(task.name, "plc_task");
    assert_eq!(task.interval.as_deref(), Some("T#100ms"));
    assert_eq!(task.priority, 1);
    assert_eq!(task.pou_instances[0].type_name, "plc_prg");
}

#[test]
fn beremiz_svghmi_basic_keeps_action_qualifiers() {
    let document = read_corpus("plcopen/beremiz/tests/projects/svghmi_basic/plc.xml");
    let mut qualifiers = Vec::new();
    let mut durations = Vec::new();
    for pou in &document.pous {
        for body in &pou.bodies {
            for object in body.content.objects() {
                if let ObjectKind::ActionBlock(block) = &object.kind {
                    for action in &block.actions {
                        qualifiers.extend(action.qualifier);
                        durations.extend(action.duration.clone());
                    }
                }
            }
        }
    }
    for expected in [Qualifier::D, Qualifier::P, Qualifier::R, Qualifier::S] {
        assert!(
            qualifiers.contains(&expected),
            "{expected:?} in {qualifiers:?}"
        );
    }
    assert!(
        durations.iter().any(|duration| duration == "T#2s"),
        "{durations:?}"
    );
}

#[test]
fn beremiz_language_test_has_connectors_and_continuations() {
    let document = read_corpus("plcopen/beremiz/tests/projects/iec61131_lang_test/plc.xml");
    let all: Vec<&BodyObject> = document
        .pous
        .iter()
        .flat_map(|pou| &pou.bodies)
        .flat_map(|body| body.content.objects())
        .collect();
    assert!(
        all.iter()
            .any(|object| matches!(object.kind, ObjectKind::Connector(_)))
    );
    assert!(
        all.iter()
            .any(|object| matches!(object.kind, ObjectKind::Continuation(_)))
    );
    // Beremiz writes `executionOrderId="0"` (unordered), kept apart from an absent id.
    assert!(
        all.iter()
            .any(|object| object.execution_order_id == Some(0))
    );
}

#[test]
fn codesys_export_keeps_its_dialect() {
    let document = read_corpus("plcopen/codesys/codesys_code_execution_speedTests.xml");
    assert_eq!(document.dialect, Dialect::V200);
    assert_eq!(document.file_header.product_name, "CODESYS");
    // The CFC lives in the body's addData, beside an empty ST.
    let cfc_pou = pou(&document, "addTwoIntsCFC");
    let body = &cfc_pou.bodies[0];
    assert!(matches!(&body.content, BodyContent::St(text) if text.text.is_empty()));
    let cfc = body.cfc.as_deref().unwrap_or_else(|| panic!("no CFC"));
    let block = objects_named(cfc, "block")[0];
    assert_eq!(block.execution_order_id, Some(2));
    let unnamed_connectors = objects_named(cfc, "connector");
    assert_eq!(unnamed_connectors.len(), 3);
    assert!(
        objects_named(cfc, "inVariable")
            .iter()
            .all(|variable| variable.execution_order_id.is_none())
    );
    assert!(
        body.add_data
            .entry_ending_with("/cfc")
            .is_some_and(|entry| entry.xml.starts_with("<data"))
    );
    // Local ids above u32 in FBD.
    let fbd = pou(&document, "addTwoIntsFBD").bodies[0].content.objects();
    assert!(fbd.iter().any(|object| object.local_id == 10_000_000_003));
    // The LD: a left rail with id 0 that the contact links to, no positions worth the name.
    let ld = pou(&document, "addTwoIntsLadder").bodies[0]
        .content
        .objects();
    let rail = objects_named(ld, "leftPowerRail")[0];
    assert_eq!(rail.local_id, 0);
    let ObjectKind::LeftPowerRail(left) = &rail.kind else {
        panic!("not a rail");
    };
    assert_eq!(left.outputs[0].formal_parameter.as_deref(), Some("none"));
    let ObjectKind::Contact(contact) = &objects_named(ld, "contact")[0].kind else {
        panic!("not a contact");
    };
    assert_eq!(
        contact
            .input
            .as_ref()
            .map(|input| input.connections[0].ref_local_id),
        Some(0)
    );
    assert!(
        objects_named(ld, "rightPowerRail")
            .iter()
            .any(|rail| rail.local_id == 2_147_483_646)
    );
    // Document order: the rail, the network comment and title come first.
    let order: Vec<&str> = ld
        .iter()
        .take(3)
        .map(|object| object.kind.element_name())
        .collect();
    assert_eq!(order, ["leftPowerRail", "comment", "vendorElement"]);
    // Methods in the POU's addData.
    let methods = &pou(&document, "x04_FunctionOverhead").methods;
    assert_eq!(methods[0].name, "addTwoNumbers");
    // Tasks: CODESYS intervals and event tasks.
    let resource = &document.configurations[0].resources[0];
    let task = &resource.tasks[0];
    assert_eq!(
        (task.name.as_str(), task.interval.as_deref(), task.priority),
        ("SpdRnnr", Some("PT0.2S"), 16)
    );
    assert_eq!(task.pou_instances[0].type_name, "");
    assert!(
        resource
            .tasks
            .iter()
            .any(|task| task.single.as_deref() == Some("x01_ImpactOfDynamicArrays.vStart"))
    );
    assert!(task.add_data.entry_ending_with("/tasksettings").is_some());
}

#[test]
fn codesys_pous_in_a_resource_are_found() {
    let text = r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0200">
  <fileHeader companyName="CODESYS" productName="CODESYS" productVersion="3.5" creationDateTime="2024-01-01T00:00:00"/>
  <contentHeader name="p"><coordinateInfo><fbd><scaling x="1" y="1"/></fbd><ld><scaling x="1" y="1"/></ld><sfc><scaling x="1" y="1"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous/></types>
  <instances><configurations><configuration name="Device"><resource name="Application">
    <addData>
      <data name="http://www.3s-software.com/plcopenxml/pou" handleUnknown="implementation">
        <pou name="PLC_PRG" pouType="program">
          <interface><localVars><variable name="x"><type><INT/></type></variable></localVars></interface>
          <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">x := x + 1;</xhtml></ST></body>
          <!--ObjectVersion: ST1-->
        </pou>
      </data>
    </addData>
  </resource></configuration></configurations></instances>
</project>"#;
    let document = crate::read(text, "resource.xml").unwrap_or_else(|error| panic!("{error}"));
    let found = pou(&document, "PLC_PRG");
    assert_eq!(
        found.location,
        PouLocation::Resource {
            configuration: "Device".to_owned(),
            resource: "Application".to_owned()
        }
    );
    assert!(
        matches!(&found.bodies[0].content, BodyContent::St(text) if text.text == "x := x + 1;" && text.markup == TextMarkup::XhtmlElement && !text.cdata)
    );
    // The comment stands in addData, so it stays in the entry's raw text.
    assert!(
        document.configurations[0].resources[0].add_data.entries[0]
            .xml
            .contains("<!--ObjectVersion: ST1-->")
    );
}

#[test]
fn xml_comments_outside_add_data_are_kept_where_they_sit() {
    let text = r#"<project xmlns="http://www.plcopen.org/xml/tc6_0201">
  <fileHeader companyName="c" productName="p" productVersion="1" creationDateTime="2024-01-01 10:00:00"/>
  <contentHeader name="p"><coordinateInfo><fbd><scaling x="0" y="0"/></fbd><ld><scaling x="0" y="0"/></ld><sfc><scaling x="0" y="0"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous><pou name="F" pouType="functionBlock"><body><LD>
    <leftPowerRail localId="1"><connectionPointOut formalParameter=""/></leftPowerRail>
    <!--ObjectVersion: LD1-->
  </LD></body></pou></pous></types>
</project>"#;
    let document = crate::read(text, "comments.xml").unwrap_or_else(|error| panic!("{error}"));
    assert_eq!(document.xml_comments.len(), 1);
    let comment = &document.xml_comments[0];
    assert_eq!(comment.text, "ObjectVersion: LD1");
    assert_eq!(
        comment.parent_path,
        "project/types/pous/pou[@name='F']/body/LD"
    );
    assert_eq!((comment.elements_before, comment.line), (1, 6));
    assert_eq!(
        document.file_header.creation_date_time,
        "2024-01-01 10:00:00"
    );
}

#[test]
fn matiec_v10_files_are_upgraded() {
    let document = read_corpus("matiec/tests/SFC_TEST.xml");
    assert_eq!(document.dialect, Dialect::V10);
    let sfc = pou(&document, "MAIN_TEST").bodies[0].content.objects();
    assert_eq!(objects_named(sfc, "simultaneousDivergence").len(), 1);
    assert_eq!(objects_named(sfc, "simultaneousConvergence").len(), 1);
    let ObjectKind::SimultaneousDivergence(divergence) =
        &objects_named(sfc, "simultaneousDivergence")[0].kind
    else {
        panic!("not a divergence");
    };
    assert!(divergence.outputs.len() >= 2);
    let ObjectKind::Transition(transition) = &objects_named(sfc, "transition")[0].kind else {
        panic!("not a transition");
    };
    let condition = transition
        .condition
        .as_ref()
        .unwrap_or_else(|| panic!("no condition"));
    let ConditionForm::Inline { body, .. } = &condition.form else {
        panic!("not inline: {condition:?}");
    };
    assert!(
        matches!(&body.content, BodyContent::St(text) if text.text == "IX1 = FALSE" && text.markup == TextMarkup::Bare)
    );
    let ObjectKind::ActionBlock(block) = &objects_named(sfc, "actionBlock")[0].kind else {
        panic!("not an action block");
    };
    assert_eq!(block.actions[0].local_id, 0);
    let ld_test = read_corpus("matiec/tests/LD_TEST.xml");
    let task = &ld_test.configurations[0].resources[0].tasks[0];
    assert_eq!(task.interval.as_deref(), Some("T#100ms"));
    assert_eq!(
        ld_test.configurations[0].resources[0].pou_instances[0].type_name,
        "MAIN_TEST"
    );
}
