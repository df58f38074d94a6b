//! The conversion's rules on small documents, and bad input: each error names the file, line,
//! column and element path.

use project_model::{Object, TaskKind, TypeDefinition};

use super::{ImportError, ImportErrorKind, Imported, Outcome, import};
use crate::{ReadErrorKind, read};

/// A v2.01 document with `types` (data types and POUs, from line 5) and `instances`.
fn document(types: &str, instances: &str) -> String {
    format!(
        r#"<?xml version="1.0" encoding="UTF-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201" xmlns:xhtml="http://www.w3.org/1999/xhtml">
  <fileHeader companyName="c" productName="p" productVersion="1" creationDateTime="2024-01-01T00:00:00"/>
  <contentHeader name="n"><coordinateInfo><fbd><scaling x="0" y="0"/></fbd><ld><scaling x="0" y="0"/></ld><sfc><scaling x="0" y="0"/></sfc></coordinateInfo></contentHeader>
{types}
  <instances><configurations>{instances}</configurations></instances>
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

const PROGRAM_MAIN: &str = r#"<pou name="Main" pouType="program"><interface><localVars retain="true"><variable name="count" address="%MW0"><type><derived name="NoSuchType"/></type><initialValue><simpleValue value="3"/></initialValue><documentation><xhtml:p>Counts.</xhtml:p></documentation></variable></localVars></interface><body><ST><xhtml:p>count := count + 1;</xhtml:p></ST></body></pou>"#;

fn with_task(task: &str) -> String {
    document(
        &format!("  <types><dataTypes/><pous>{PROGRAM_MAIN}</pous></types>"),
        &format!(
            r#"<configuration name="Config"><resource name="Res">{task}</resource></configuration>"#
        ),
    )
}

#[test]
fn a_program_keeps_its_declarations_and_an_unknown_type_as_written() {
    let imported = imported(&with_task(
        r#"<task name="Fast" priority="40" interval="T#10ms"><pouInstance name="main_instance" typeName="Main"/></task>"#,
    ));
    let Some(Object::Pou(main)) = imported.project.application.object("Main") else {
        panic!("{imported:?}")
    };
    let [count] = main.variables.as_slice() else {
        panic!("{main:?}")
    };
    // The checker names the unknown type later, where the user can fix it.
    assert_eq!(count.ty, "NoSuchType");
    assert_eq!(count.initial.as_deref(), Some("3"));
    assert_eq!(count.address.as_deref(), Some("%MW0"));
    assert_eq!(count.comment, "Counts.");
    assert!(count.retain && !count.persistent && !count.constant);
    assert_eq!(main.body.st_text(), Some("count := count + 1;"));

    let [task] = imported.project.tasks.as_slice() else {
        panic!("{imported:?}")
    };
    assert_eq!(
        task.kind,
        TaskKind::Cyclic {
            interval_us: 10_000
        }
    );
    // Priorities beyond Rivet's 31 become 31, and the report says so.
    assert_eq!(task.priority, 31);
    assert_eq!(task.programs, ["Main"]);
    let task_entry = imported.report.entry("task 'Fast'");
    assert!(task_entry.is_some_and(|entry| entry.note.contains("priority 40")));
    let instance = imported.report.entry("program instance 'main_instance'");
    assert!(
        instance.is_some_and(
            |entry| entry.outcome == Outcome::Converted && entry.note.contains("`Main`")
        )
    );
}

#[test]
fn a_single_task_becomes_an_event_task() {
    let imported = imported(&with_task(
        r#"<task name="OnStart" priority="2" single="Start"><pouInstance name="Main" typeName="Main"/></task>"#,
    ));
    assert_eq!(
        imported.project.tasks[0].kind,
        TaskKind::Event {
            trigger: "Start".into()
        }
    );
}

#[test]
fn an_interval_that_is_not_a_duration_is_refused_at_its_task() {
    let error = import_error(&with_task(
        r#"<task name="Slow" priority="1" interval="100"/>"#,
    ));
    assert_eq!(*error.kind, ImportErrorKind::BadInterval("100".into()));
    assert_eq!((error.line, error.column), (6, 80), "{error}");
    assert_eq!(
        error.path,
        "project/instances/configurations/configuration[@name='Config']/resource[@name='Res']/task[@name='Slow']"
    );
    assert!(
        error.to_string().starts_with("bad.xml:6:80: project/"),
        "{error}"
    );
}

#[test]
fn names_differing_in_case_are_refused() {
    // The reader refuses two POUs alike; the conversion refuses a POU and a list alike.
    let twice = document(
        &format!(
            "  <types><dataTypes/><pous>{PROGRAM_MAIN}\n{}</pous></types>",
            PROGRAM_MAIN.replace("\"Main\"", "\"MAIN\"")
        ),
        "",
    );
    let read_error = read(&twice, "bad.xml").err();
    assert!(
        read_error.is_some_and(|error| matches!(error.kind, ReadErrorKind::DuplicateName { .. })),
        "the reader refuses duplicate POUs"
    );
    let clash = document(
        &format!("  <types><dataTypes/><pous>{PROGRAM_MAIN}</pous></types>"),
        r#"<configuration name="Config"><resource name="Res">
<globalVars name="main"><variable name="g"><type><INT/></type></variable></globalVars></resource></configuration>"#,
    );
    let error = import_error(&clash);
    assert!(
        matches!(&*error.kind, ImportErrorKind::DuplicateName { what: "global variable list", name, first, first_line: 5 } if name == "main" && first == "Main"),
        "{error}"
    );
    assert_eq!((error.line, error.column), (7, 1), "{error}");
}

#[test]
fn data_types_keep_their_kind_and_order() {
    let types = r#"  <types><dataTypes>
<dataType name="Point"><baseType><struct><variable name="x"><type><REAL/></type><initialValue><simpleValue value="1.5"/></initialValue></variable><variable name="y"><type><REAL/></type></variable></struct></baseType></dataType>
<dataType name="Colour"><baseType><enum><values><value name="Red" value="1"/><value name="Green"/></values></enum></baseType></dataType>
<dataType name="Percent"><baseType><subrangeSigned><range lower="0" upper="100"/><baseType><INT/></baseType></subrangeSigned></baseType><initialValue><simpleValue value="50"/></initialValue></dataType>
<dataType name="Name"><baseType><string length="20"/></baseType></dataType>
</dataTypes><pous/></types>"#;
    let imported = imported(&document(types, ""));
    let names: Vec<&str> = imported
        .project
        .application
        .objects()
        .iter()
        .map(|object| object.name())
        .collect();
    assert_eq!(names, ["Point", "Colour", "Percent", "Name"]);
    let definition = |name: &str| match imported.project.application.object(name) {
        Some(Object::DataType(data_type)) => data_type.definition.clone(),
        other => panic!("{other:?}"),
    };
    let TypeDefinition::Struct { members, .. } = definition("Point") else {
        panic!()
    };
    assert_eq!(members[0].initial.as_deref(), Some("1.5"));
    assert_eq!(members[1].name, "y");
    let TypeDefinition::Enum { values, base: None } = definition("Colour") else {
        panic!()
    };
    assert_eq!(values[0].value.as_deref(), Some("1"));
    assert_eq!(
        definition("Percent"),
        TypeDefinition::Alias {
            ty: "INT(0..100)".into(),
            initial: Some("50".into())
        }
    );
    assert_eq!(
        definition("Name"),
        TypeDefinition::Alias {
            ty: "STRING(20)".into(),
            initial: None
        }
    );
}

#[test]
fn a_structure_inside_a_variable_is_refused() {
    let types = r#"  <types><dataTypes/><pous><pou name="F" pouType="functionBlock"><interface><localVars>
<variable name="s"><type><struct><variable name="a"><type><INT/></type></variable></struct></type></variable></localVars></interface><body><ST><xhtml:p></xhtml:p></ST></body></pou></pous></types>"#;
    let error = import_error(&document(types, ""));
    assert!(
        matches!(*error.kind, ImportErrorKind::InexpressibleType(_)),
        "{error}"
    );
    assert_eq!(error.line, 6);
    assert!(
        error
            .path
            .ends_with("/interface/localVars/variable[@name='s']"),
        "{error}"
    );
}

#[test]
fn st_and_il_actions_convert() {
    let types = r#"  <types><dataTypes/><pous><pou name="Fb" pouType="functionBlock"><interface/><actions>
<action name="Reset"><body><ST><xhtml:p>x := 0;</xhtml:p></ST></body></action>
<action name="Old"><body><IL><xhtml:p>LD 1</xhtml:p></IL></body></action></actions>
<body><ST><xhtml:p></xhtml:p></ST></body><documentation><xhtml:p>
  A block.
</xhtml:p></documentation></pou></pous></types>"#;
    let imported = imported(&document(
        types,
        r#"<configuration name="Config"><globalVars name="Kept" persistent="true" retain="true"><variable name="total"><type><LINT/></type></variable></globalVars></configuration>"#,
    ));
    let Some(Object::Pou(block)) = imported.project.application.object("Fb") else {
        panic!("{imported:?}")
    };
    assert_eq!(block.comment, "A block.");
    let actions: Vec<&str> = block
        .actions
        .iter()
        .map(|action| action.name.as_str())
        .collect();
    assert_eq!(actions, ["Reset", "Old"]);
    assert_eq!(block.actions[0].body.st_text(), Some("x := 0;"));
    assert_eq!(block.actions[1].body.text(), Some("LD 1"));
    assert!(matches!(
        block.actions[1].body,
        project_model::Body::Il { .. }
    ));
    let Some(Object::Gvl(kept)) = imported.project.application.object("Kept") else {
        panic!("{imported:?}")
    };
    assert!(kept.variables[0].persistent && kept.variables[0].retain);
    assert_eq!(
        kept.variables[0].section,
        project_model::VarSection::VarGlobal
    );
}

#[test]
fn xml_comments_are_reported_as_not_written_back() {
    let types = "  <types><dataTypes/><pous><!--ObjectVersion: LD1--></pous></types>";
    let imported = imported(&document(types, ""));
    let entry = imported.report.entry("XML comment 'ObjectVersion: LD1'");
    assert!(
        entry.is_some_and(|entry| entry.outcome == Outcome::NotConverted
            && entry.line == 5
            && entry.path == "project/types/pous"
            && entry.note.contains("not written back")),
        "{:?}",
        imported.report
    );
    // Nothing of it is in the project, so its export has no comment.
    let xml = crate::export(&imported.project).unwrap();
    assert!(!String::from_utf8(xml).unwrap().contains("ObjectVersion"));
}

#[test]
fn pou_names_differing_in_non_ascii_case_are_refused() {
    // The reader compares names in ASCII upper case; the import as IEC identifiers compare.
    let pous = format!(
        "  <types><dataTypes/><pous>{}\n{}</pous></types>",
        PROGRAM_MAIN.replace("\"Main\"", "\"Ölpumpe\""),
        PROGRAM_MAIN.replace("\"Main\"", "\"öLPUMPE\"")
    );
    let error = import_error(&document(&pous, ""));
    assert!(
        matches!(&*error.kind, ImportErrorKind::DuplicateName { what: "POU", name, first, first_line: 5 } if name == "öLPUMPE" && first == "Ölpumpe"),
        "{error}"
    );
    assert_eq!((error.line, error.column), (6, 1), "{error}");
    assert_eq!(error.path, "project/types/pous/pou[@name='öLPUMPE']");
}
