//! The files of the PLCopen and matiec corpora converted, with spot checks per file.

use project_model::{Body, Object, PouKind, TaskKind, VarSection};

use super::{Imported, Outcome, import};
use crate::reader::corpus_tests::read_corpus;
use crate::{BodyContent, Document};

fn import_corpus(relative: &str) -> (Document, Imported) {
    let document = read_corpus(relative);
    let imported = import(&document).unwrap_or_else(|error| panic!("{error}"));
    (document, imported)
}

fn pou<'p>(imported: &'p Imported, name: &str) -> &'p project_model::Pou {
    match imported.project.application.object(name) {
        Some(Object::Pou(pou)) => pou,
        other => panic!("no POU {name}: {other:?}"),
    }
}

/// True when the POU's first body is one this part of the import converts: ST, SFC or
/// CODESYS's CFC, or none.
fn is_st(pou: &crate::Pou) -> bool {
    pou.bodies.first().is_none_or(|body| {
        body.cfc.is_some() || matches!(body.content, BodyContent::St(_) | BodyContent::Sfc(_))
    })
}

/// True when the POU's first body is LD or FBD (not CODESYS's CFC).
fn is_network(pou: &crate::Pou) -> bool {
    pou.bodies.first().is_some_and(|body| {
        body.cfc.is_none() && matches!(body.content, BodyContent::Ld(_) | BodyContent::Fbd(_))
    })
}

pub(crate) const FILES: [&str; 7] = [
    "plcopen/beremiz/exemples/first_steps/plc.xml",
    "plcopen/beremiz/tests/projects/iec61131_lang_test/plc.xml",
    "plcopen/beremiz/tests/projects/svghmi_basic/plc.xml",
    "plcopen/codesys/codesys_code_execution_speedTests.xml",
    "matiec/tests/LD_TEST.xml",
    "matiec/tests/SFC_TEST.xml",
    "matiec/tests/STD_TEST.xml",
];

#[test]
fn every_corpus_file_converts_and_reports_every_pou() {
    for file in FILES {
        let (document, imported) = import_corpus(file);
        for xml_pou in &document.pous {
            let what = format!("POU '{}'", xml_pou.name);
            let entry = imported
                .report
                .entry(&what)
                .unwrap_or_else(|| panic!("{file}: {what} is not in the report"));
            let converted = imported.project.application.object(&xml_pou.name);
            if is_st(xml_pou) {
                assert_eq!(entry.outcome, Outcome::Converted, "{file}: {what}");
                assert!(converted.is_some(), "{file}: {what} is not in the project");
            } else if is_network(xml_pou) {
                // Converted into networks, or left for the CFC chart a graph needs.
                assert_eq!(
                    converted.is_some(),
                    entry.outcome == Outcome::Converted,
                    "{file}: {what}: {}",
                    entry.note
                );
                assert!(
                    converted.is_some() || entry.note.contains("not a set of networks"),
                    "{file}: {}",
                    entry.note
                );
            } else {
                // SFC, CFC and IL bodies: converted, or not with the reason.
                assert_eq!(
                    converted.is_some(),
                    entry.outcome == Outcome::Converted,
                    "{file}: {what}: {}",
                    entry.note
                );
                assert!(
                    converted.is_some() || !entry.note.is_empty(),
                    "{file}: {what}"
                );
            }
            assert_eq!(entry.line, xml_pou.line, "{file}: {what}");
        }
        // The POUs stand in the project in the document's order.
        let xml_order: Vec<&str> = document
            .pous
            .iter()
            .filter(|pou| imported.project.application.object(&pou.name).is_some())
            .map(|pou| pou.name.as_str())
            .collect();
        let project_order: Vec<&str> = imported
            .project
            .application
            .objects()
            .into_iter()
            .filter_map(|object| match object {
                Object::Pou(pou) => Some(pou.name.as_str()),
                _ => None,
            })
            .collect();
        assert_eq!(project_order, xml_order, "{file}");
        assert_eq!(
            imported.project.application.objects().len(),
            imported
                .report
                .with_outcome(Outcome::Converted)
                .filter(|entry| entry.what.starts_with("POU ")
                    || entry.what.starts_with("data type ")
                    || entry.what.starts_with("global variable list "))
                .count(),
            "{file}: every object of the project is reported as converted"
        );
    }
}

#[test]
fn first_steps_converts_its_st_pous_task_and_globals() {
    let (_, imported) = import_corpus("plcopen/beremiz/exemples/first_steps/plc.xml");
    let counter = pou(&imported, "CounterST");
    assert_eq!(counter.kind, PouKind::FunctionBlock);
    let declared: Vec<(&str, VarSection, &str, bool)> = counter
        .variables
        .iter()
        .map(|variable| {
            (
                variable.name.as_str(),
                variable.section,
                variable.ty.as_str(),
                variable.constant,
            )
        })
        .collect();
    assert_eq!(
        declared,
        [
            ("Reset", VarSection::VarInput, "BOOL", false),
            ("Cnt", VarSection::Var, "INT", false),
            ("OUT", VarSection::VarOutput, "INT", false),
            ("ResetCounterValue", VarSection::VarExternal, "INT", true),
        ]
    );
    assert!(
        counter
            .body
            .st_text()
            .is_some_and(|text| text.starts_with("IF Reset THEN\n  Cnt := ResetCounterValue;"))
    );
    let average = pou(&imported, "AverageVal");
    assert_eq!(average.kind, PouKind::Function);
    assert_eq!(average.return_type.as_deref(), Some("REAL"));

    // Every language of the five counters is converted.
    for counter in [
        "CounterST",
        "CounterFBD",
        "CounterSFC",
        "CounterIL",
        "CounterLD",
    ] {
        let entry = imported
            .report
            .entry(&format!("POU '{counter}'"))
            .unwrap_or_else(|| panic!("{counter} is not reported"));
        assert_eq!(
            entry.outcome,
            Outcome::Converted,
            "{counter}: {}",
            entry.note
        );
    }

    let [task] = imported.project.tasks.as_slice() else {
        panic!("tasks: {:?}", imported.project.tasks)
    };
    assert_eq!(task.name, "plc_task");
    assert_eq!(
        task.kind,
        TaskKind::Cyclic {
            interval_us: 100_000
        }
    );
    assert_eq!(task.priority, 1);
    // Its program, plc_prg, is FBD, converted into networks.
    assert_eq!(task.programs, ["plc_prg"]);

    match imported.project.application.object("config") {
        Some(Object::Gvl(gvl)) => {
            let [variable] = gvl.variables.as_slice() else {
                panic!("{gvl:?}")
            };
            assert_eq!(variable.name, "ResetCounterValue");
            assert_eq!(variable.section, VarSection::VarGlobal);
            assert_eq!(variable.initial.as_deref(), Some("17"));
            assert!(variable.constant);
        }
        other => panic!("no list named after the configuration: {other:?}"),
    }
}

#[test]
fn codesys_converts_st_pous_methods_and_tasks() {
    let (document, imported) =
        import_corpus("plcopen/codesys/codesys_code_execution_speedTests.xml");
    let st_pous = document.pous.iter().filter(|pou| is_st(pou)).count();
    assert!(st_pous >= 30, "only {st_pous} ST POUs");
    // Every method of every converted POU, with its interface and body.
    let mut methods = 0;
    for xml_pou in document.pous.iter().filter(|pou| is_st(pou)) {
        let converted = pou(&imported, &xml_pou.name);
        assert_eq!(
            converted.methods.len(),
            xml_pou.methods.len(),
            "{}",
            xml_pou.name
        );
        for (method, xml_method) in converted.methods.iter().zip(&xml_pou.methods) {
            assert_eq!(method.name, xml_method.name);
            assert!(matches!(method.body, Body::St { .. }), "{}", method.name);
            let declared = xml_method
                .interface
                .iter()
                .flat_map(|interface| &interface.var_lists)
                .map(|list| list.variables.len())
                .sum::<usize>();
            assert_eq!(method.variables.len(), declared, "{}", method.name);
            methods += 1;
        }
        let declared = xml_pou
            .interface
            .iter()
            .flat_map(|interface| &interface.var_lists)
            .map(|list| list.variables.len())
            .sum::<usize>();
        assert_eq!(converted.variables.len(), declared, "{}", xml_pou.name);
    }
    assert!(methods >= 3, "only {methods} methods");

    let runner = imported
        .project
        .task("SpdRnnr")
        .unwrap_or_else(|| panic!("no SpdRnnr: {:?}", imported.project.tasks));
    assert_eq!(
        runner.kind,
        TaskKind::Cyclic {
            interval_us: 200_000
        }
    );
    assert_eq!(runner.priority, 16);
    assert_eq!(runner.programs, ["speedRunner"]);
    let started = imported
        .project
        .task("x01")
        .unwrap_or_else(|| panic!("no x01"));
    assert_eq!(
        started.kind,
        TaskKind::Event {
            trigger: "x01_ImpactOfDynamicArrays.vStart".into()
        }
    );
    // CODESYS writes one configuration per device: the second device's tasks are reported.
    let second = imported
        .report
        .entry("task 'x01' of CODESYS_Control_RTE_V3_x64/Application");
    assert_eq!(
        second.map(|entry| entry.outcome),
        Some(Outcome::NotConverted)
    );
    assert_eq!(imported.project.tasks.len(), 18);
    let method = imported
        .report
        .with_outcome(Outcome::Converted)
        .find(|entry| entry.what.starts_with("method "));
    assert!(
        method.is_some_and(|entry| entry.path.contains(
            "/addData/data[@name='http://www.3s-software.com/plcopenxml/method']/Method[@name='"
        )),
        "{method:?}"
    );
    // The visualisation's program comes from a library the file does not hold.
    let visu = imported
        .report
        .entry("program instance 'VisuElems.Visu_Prg'");
    assert_eq!(visu.map(|entry| entry.outcome), Some(Outcome::NotConverted));
    // CODESYS's object ids stay opaque, with the path of their element.
    assert!(
        imported
            .report
            .with_outcome(Outcome::KeptOpaque)
            .any(|entry| {
                entry.what.ends_with("/objectid'") && entry.path.starts_with("project/")
            })
    );
}
