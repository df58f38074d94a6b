//! Bad input through the whole import (`docs/plcopen-xml.md` §1.9, §1.10, §2.7): each case gives
//! one exact message with the file, line, column and element path, or a documented report line.

use project_model::Object;

use super::{Imported, Outcome, import};
use crate::read;

/// A v2.01 document whose `types` start on line 5 and whose `instances` are on the line after
/// them.
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

/// A document with the POUs `pous` (from line 5) and no instances.
fn with_pous(pous: &str) -> String {
    document(
        &format!("  <types><dataTypes/><pous>\n{pous}\n  </pous></types>"),
        "",
    )
}

/// The program `name` with one `INT` variable `count` and an ST body.
fn program(name: &str) -> String {
    format!(
        r#"<pou name="{name}" pouType="program"><interface><localVars><variable name="count"><type><INT/></type></variable></localVars></interface><body><ST><xhtml:p>count := count + 1;</xhtml:p></ST></body></pou>"#
    )
}

/// The message of reading and converting `text` as `bad.xml`, which must fail.
#[track_caller]
fn message(text: &str) -> String {
    let document = match read(text, "bad.xml") {
        Ok(document) => document,
        Err(error) => return error.to_string(),
    };
    match import(&document) {
        Ok(imported) => panic!("imported: {:?}", imported.report),
        Err(error) => error.to_string(),
    }
}

#[track_caller]
fn imported(text: &str) -> Imported {
    let document = read(text, "in.xml").unwrap_or_else(|error| panic!("{error}"));
    import(&document).unwrap_or_else(|error| panic!("{error}"))
}

#[test]
fn a_file_cut_inside_a_pou_names_where_the_text_stops() {
    let text = with_pous(&program("Main"));
    let cut = text.find("<body>").unwrap_or(text.len());
    assert_eq!(
        message(&text[..cut]),
        "bad.xml:6:135: not well-formed XML: the root node was opened but never closed"
    );
}

#[test]
fn a_file_cut_inside_an_attribute_names_where_the_text_stops() {
    let text = with_pous(&program("Main"));
    let cut = text.find("program\">").unwrap_or(text.len()) + 3;
    assert_eq!(
        message(&text[..cut]),
        "bad.xml:6:30: not well-formed XML: unexpected end of stream"
    );
}

#[test]
fn an_empty_file_is_not_xml() {
    assert_eq!(
        message(""),
        "bad.xml:1:1: not well-formed XML: the document does not have a root node"
    );
}

#[test]
fn an_unknown_namespace_is_refused_with_the_namespaces_accepted() {
    let text = with_pous(&program("Main")).replace("tc6_0201", "tc6_0202");
    assert_eq!(
        message(&text),
        "bad.xml:2:1: project: namespace `http://www.plcopen.org/xml/tc6_0202` is not a PLCopen TC6 namespace; a PLCopen TC6 file declares http://www.plcopen.org/xml/tc6_0201 (v2.01), http://www.plcopen.org/xml/tc6_0200 (CODESYS) or http://www.plcopen.org/xml/tc6.xsd (v1.0)"
    );
}

#[test]
fn a_project_without_namespace_is_refused() {
    let text =
        with_pous(&program("Main")).replace(" xmlns=\"http://www.plcopen.org/xml/tc6_0201\"", "");
    assert_eq!(
        message(&text),
        "bad.xml:2:1: project: the root element `project` has no namespace; a PLCopen TC6 file declares http://www.plcopen.org/xml/tc6_0201 (v2.01), http://www.plcopen.org/xml/tc6_0200 (CODESYS) or http://www.plcopen.org/xml/tc6.xsd (v1.0)"
    );
}

#[test]
fn a_prefixed_root_and_children_of_other_namespaces_are_read_by_local_names() {
    // The root's namespace decides the dialect; below it only local names count (§1.1).
    let text = with_pous(&program("Main"))
        .replace("<project xmlns=", "<plc:project xmlns:plc=")
        .replace("</project>", "</plc:project>")
        .replace("<pou ", "<pou xmlns=\"urn:elsewhere\" ");
    let imported = imported(&text);
    assert!(imported.project.application.object("Main").is_some());
}

#[test]
fn an_unknown_element_among_the_pous_is_refused() {
    assert_eq!(
        message(&with_pous("<gadget name=\"G\"/>")),
        "bad.xml:6:1: project/types/pous/gadget[@name='G']: unexpected element `gadget` in pous, which holds only pou"
    );
}

#[test]
fn an_unknown_element_as_a_type_is_refused() {
    let pou = program("Main").replace("<INT/>", "<INTEGER/>");
    assert_eq!(
        message(&with_pous(&pou)),
        "bad.xml:6:87: project/types/pous/pou[@name='Main']/interface/localVars/variable[@name='count']/type/INTEGER: unexpected element `INTEGER` in a type"
    );
}

#[test]
fn an_unknown_element_in_an_interface_is_refused() {
    let pou = program("Main").replace("<localVars>", "<scratchVars/><localVars>");
    assert_eq!(
        message(&with_pous(&pou)),
        "bad.xml:6:47: project/types/pous/pou[@name='Main']/interface/scratchVars: unexpected element `scratchVars` in interface"
    );
}

#[test]
fn a_body_without_a_language_is_refused() {
    let pou = program("Main").replace(
        "<ST><xhtml:p>count := count + 1;</xhtml:p></ST>",
        "<documentation><xhtml:p>none</xhtml:p></documentation>",
    );
    assert_eq!(
        message(&with_pous(&pou)),
        "bad.xml:6:135: project/types/pous/pou[@name='Main']/body: the required element `ST, IL, FBD, LD or SFC` is missing"
    );
}

/// An LD program `L` whose body holds `objects` (from line 6).
fn ld_program(objects: &str) -> String {
    format!(
        "<pou name=\"L\" pouType=\"program\"><interface><localVars><variable name=\"a\"><type><BOOL/></type></variable></localVars></interface><body><LD>\n{objects}\n</LD></body></pou>"
    )
}

const LEFT_RAIL: &str = r#"<leftPowerRail localId="1"><position x="0" y="0"/><connectionPointOut formalParameter=""/></leftPowerRail>"#;

#[test]
fn a_connection_to_a_missing_local_id_is_refused_at_its_attribute() {
    let coil = r#"<coil localId="2"><position x="0" y="0"/><connectionPointIn><connection refLocalId="5"/></connectionPointIn><connectionPointOut/><variable>a</variable></coil>"#;
    let text = with_pous(&ld_program(&format!("{LEFT_RAIL}\n{coil}")));
    assert_eq!(
        message(&text),
        "bad.xml:8:73: project/types/pous/pou[@name='L']/body/LD/coil[@localId='2']/connectionPointIn/connection: connection refers to localId 5, which no element of this body has"
    );
}

#[test]
fn a_connection_in_an_sfc_body_to_a_missing_local_id_is_refused() {
    let objects = r#"<step localId="1" name="Init" initialStep="true"><position x="0" y="0"/><connectionPointOut/></step>
<transition localId="2"><position x="0" y="0"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut/><condition><inline name=""><ST><xhtml:p>TRUE</xhtml:p></ST></inline></condition></transition>
<jumpStep localId="3" targetName="Init"><position x="0" y="0"/><connectionPointIn><connection refLocalId="4"/></connectionPointIn></jumpStep>"#;
    let pou =
        format!("<pou name=\"S\" pouType=\"program\"><body><SFC>\n{objects}\n</SFC></body></pou>");
    assert_eq!(
        message(&with_pous(&pou)),
        "bad.xml:9:95: project/types/pous/pou[@name='S']/body/SFC/jumpStep[@localId='3']/connectionPointIn/connection: connection refers to localId 4, which no element of this body has"
    );
}

#[test]
fn a_jump_to_a_missing_step_is_refused_in_its_body() {
    let objects = r#"<step localId="1" name="Init" initialStep="true"><position x="0" y="0"/><connectionPointOut/></step>
<transition localId="2"><position x="0" y="0"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut/><condition><inline name=""><ST><xhtml:p>TRUE</xhtml:p></ST></inline></condition></transition>
<jumpStep localId="3" targetName="Nowhere"><position x="0" y="0"/><connectionPointIn><connection refLocalId="2"/></connectionPointIn></jumpStep>"#;
    let pou =
        format!("<pou name=\"S\" pouType=\"program\"><body><SFC>\n{objects}\n</SFC></body></pou>");
    assert_eq!(
        message(&with_pous(&pou)),
        "bad.xml:6:1: project/types/pous/pou[@name='S']/body/SFC: the chart made of this body breaks Rivet's rules: element 3: the jump names the step 'Nowhere', which does not exist"
    );
}

#[test]
fn a_continuation_without_its_connector_is_refused_at_the_continuation() {
    let objects = r#"<continuation localId="2" name="wire"><position x="0" y="0"/><connectionPointOut/></continuation>
<outVariable localId="3"><position x="0" y="0"/><connectionPointIn><connection refLocalId="2"/></connectionPointIn><expression>a</expression></outVariable>"#;
    let pou = format!(
        "<pou name=\"F\" pouType=\"program\"><interface><localVars><variable name=\"a\"><type><BOOL/></type></variable></localVars></interface><body><FBD>\n{objects}\n</FBD></body></pou>"
    );
    assert_eq!(
        message(&with_pous(&pou)),
        "bad.xml:7:1: project/types/pous/pou[@name='F']/body/FBD/continuation[@localId='2']: the continuation `wire` has no connector of that name in its body"
    );
}

#[test]
fn a_program_instance_of_a_missing_program_is_reported_not_converted() {
    let text = document(
        &format!(
            "  <types><dataTypes/><pous>{}</pous></types>",
            program("Main")
        ),
        r#"<configuration name="C"><resource name="R"><task name="T" priority="1" interval="T#10ms"><pouInstance name="i" typeName="Missing"/></task></resource></configuration>"#,
    );
    let imported = imported(&text);
    let entry = imported.report.entry("program instance 'i'");
    assert!(
        entry.is_some_and(|entry| entry.outcome == Outcome::NotConverted
            && entry.line == 6
            && entry.note
                == "`Missing` is not a program of the imported project (not in the file, or not converted)"),
        "{:?}",
        imported.report
    );
}

#[test]
fn duplicate_local_ids_in_one_body_are_refused_naming_the_first() {
    let contact = |id: u32| {
        format!(
            r#"<contact localId="{id}"><position x="0" y="0"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut/><variable>a</variable></contact>"#
        )
    };
    let text = with_pous(&ld_program(&format!(
        "{LEFT_RAIL}\n{}\n{}",
        contact(2),
        contact(2)
    )));
    assert_eq!(
        message(&text),
        "bad.xml:9:10: project/types/pous/pou[@name='L']/body/LD/contact[@localId='2']: localId 2 is already used in this body by the element on line 8"
    );
}

#[test]
fn duplicate_pou_names_are_refused_at_the_second() {
    let text = with_pous(&format!("{}\n{}", program("Main"), program("main")));
    assert_eq!(
        message(&text),
        "bad.xml:7:6: project/types/pous/pou[@name='main']: the POU `main` has the name of the POU on line 6; IEC 61131-3 names ignore case"
    );
}

#[test]
fn a_data_type_and_a_pou_of_one_name_are_refused() {
    let text = document(
        &format!(
            "  <types><dataTypes>\n<dataType name=\"Main\"><baseType><INT/></baseType></dataType>\n</dataTypes><pous>\n{}\n</pous></types>",
            program("MAIN")
        ),
        "",
    );
    assert_eq!(
        message(&text),
        "bad.xml:8:6: project/types/pous/pou[@name='MAIN']: the POU `MAIN` has the name of the data type on line 6; IEC 61131-3 names ignore case"
    );
}

#[test]
fn duplicate_data_type_names_are_refused_at_the_second() {
    let data_type =
        |name: &str| format!("<dataType name=\"{name}\"><baseType><INT/></baseType></dataType>");
    let text = document(
        &format!(
            "  <types><dataTypes>\n{}\n{}\n</dataTypes><pous/></types>",
            data_type("Speed"),
            data_type("SPEED")
        ),
        "",
    );
    assert_eq!(
        message(&text),
        "bad.xml:7:11: project/types/dataTypes/dataType[@name='SPEED']: the data type `SPEED` has the name of the data type on line 6; IEC 61131-3 names ignore case"
    );
}

#[test]
fn duplicate_global_variable_lists_of_two_resources_are_refused() {
    let list =
        r#"<globalVars name="G"><variable name="g"><type><INT/></type></variable></globalVars>"#;
    let text = document(
        "  <types><dataTypes/><pous/></types>",
        &format!(
            "<configuration name=\"C\"><resource name=\"R1\">{list}</resource>\n<resource name=\"R2\">{}</resource></configuration>",
            list.replace("\"G\"", "\"g\"")
        ),
    );
    assert_eq!(
        message(&text),
        "bad.xml:7:21: project/instances/configurations/configuration[@name='C']/resource[@name='R2']/globalVars[@name='g']: the global variable list `g` has the name of `G` (line 6); IEC 61131-3 names ignore case"
    );
}

#[test]
fn duplicate_task_names_are_refused_at_the_second() {
    let text = document(
        "  <types><dataTypes/><pous/></types>",
        "<configuration name=\"C\"><resource name=\"R\"><task name=\"T\" priority=\"1\" interval=\"T#10ms\"/>\n<task name=\"t\" priority=\"1\" interval=\"T#20ms\"/></resource></configuration>",
    );
    assert_eq!(
        message(&text),
        "bad.xml:7:1: project/instances/configurations/configuration[@name='C']/resource[@name='R']/task[@name='t']: the task `t` has the name of `T` (line 6); IEC 61131-3 names ignore case"
    );
}

#[test]
fn duplicate_variables_are_kept_for_the_checker_to_name() {
    // The checker reports E0108 at the second declaration, where the user can rename it; the
    // import keeps both as written (§2.7).
    let pou = program("Main").replace(
        "</localVars>",
        "</localVars><localVars><variable name=\"COUNT\"><type><BOOL/></type></variable></localVars>",
    );
    let imported = imported(&with_pous(&pou));
    let Some(Object::Pou(main)) = imported.project.application.object("Main") else {
        panic!("{:?}", imported.report)
    };
    let names: Vec<&str> = main
        .variables
        .iter()
        .map(|variable| variable.name.as_str())
        .collect();
    assert_eq!(names, ["count", "COUNT"]);
}

#[test]
fn rivet_data_of_the_wrong_kind_is_refused_at_its_pou() {
    let entry = r#"<addData><data name="https://rivet-plc.dev/plcopen/1/object" handleUnknown="preserve"><r:object xmlns:r="https://rivet-plc.dev/plcopen/1" kind="type" name="Main"><r:toml/></r:object></data></addData>"#;
    let pou = program("Main").replace("</body></pou>", &format!("</body>{entry}</pou>"));
    assert_eq!(
        message(&with_pous(&pou)),
        "bad.xml:6:1: project/types/pous/pou[@name='Main']: Rivet's data cannot be read: the entry is of a type, not of a pou"
    );
}

#[test]
fn rivet_data_whose_toml_is_no_pou_is_refused_naming_the_object() {
    let entry = r#"<addData><data name="https://rivet-plc.dev/plcopen/1/object" handleUnknown="preserve"><r:object xmlns:r="https://rivet-plc.dev/plcopen/1" kind="pou" name="Main"><r:toml>kind = "gadget"</r:toml></r:object></data></addData>"#;
    let pou = program("Main").replace("</body></pou>", &format!("</body>{entry}</pou>"));
    assert_eq!(
        message(&with_pous(&pou)),
        "bad.xml:6:1: project/types/pous/pou[@name='Main']: Rivet's data cannot be read: the pou 'Main': TOML parse error at line 1, column 8\n  |\n1 | kind = \"gadget\"\n  |        ^^^^^^^^\nunknown variant `gadget`, expected one of `program`, `function_block`, `function`, `interface`\n"
    );
}
