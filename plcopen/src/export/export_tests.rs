//! Tests of the whole export over small projects.

use project_model::{Body, Node, Object, Pou, PouKind, Project, Variable};

use super::export;

fn small_project() -> Project {
    let mut project = Project {
        name: "Demo".into(),
        ..Project::default()
    };
    let mut main = Pou {
        name: "Main".into(),
        kind: PouKind::Program,
        return_type: None,
        extends: None,
        implements: Vec::new(),
        comment: "The main program".into(),
        variables: vec![Variable::new("count", "INT")],
        body: Body::st("count := count + 1;\n"),
        methods: Vec::new(),
        properties: Vec::new(),
        actions: Vec::new(),
        transitions: Vec::new(),
    };
    main.variables[0].initial = Some("5".into());
    project
        .application
        .children
        .push(Node::Object(Object::Pou(main)));
    project
}

#[test]
fn the_same_project_gives_the_same_bytes() {
    let project = small_project();
    assert_eq!(export(&project).unwrap(), export(&project).unwrap());
}

#[test]
fn the_export_is_read_back_by_the_reader() {
    let bytes = export(&small_project()).unwrap();
    let document = crate::read_bytes(&bytes, "demo.xml").unwrap();
    assert_eq!(document.pous.len(), 1);
    assert_eq!(document.pous[0].name, "Main");
    assert_eq!(document.content_header.name, "Demo");
}

fn graphical(body: Body) -> Project {
    let mut project = small_project();
    if let Some(Node::Object(Object::Pou(pou))) = project.application.children.first_mut() {
        pou.body = body;
    }
    project
}

fn network(toml_text: &str) -> project_model::Network {
    toml::from_str(toml_text).unwrap()
}

#[test]
fn an_ld_network_is_a_graph_between_power_rails_with_its_header_in_rivet_data() {
    let rung = network(
        r#"
title = "Start"
label = "L1"
rung = [
  { type = "operand", id = 1, text = "a" },
  { type = "parallel", id = 2, branch = [
      { rung = [{ type = "operand", id = 3, text = "b" }] },
      { rung = [{ type = "operand", id = 4, text = "c", negated = true }] },
  ] },
]
output = [{ type = "coil", id = 5, variable = "q" }]
"#,
    );
    let xml = String::from_utf8(
        export(&graphical(Body::Ld {
            networks: vec![rung],
        }))
        .unwrap(),
    )
    .unwrap();
    // The reader checks every connection names an object of the body.
    crate::read(&xml, "ld.xml").unwrap();
    let body = &xml[xml.find("<LD>").unwrap()..xml.find("</LD>").unwrap()];
    assert!(
        body.contains("<label localId=\"6\" label=\"L1\">"),
        "{body}"
    );
    assert!(body.contains("<leftPowerRail localId=\"7\">"), "{body}");
    // The branches meet in a wired OR at the coil, in branch order.
    let coil = &body[body.find("<coil localId=\"5\">").unwrap()..];
    let b = coil.find("refLocalId=\"3\"").unwrap();
    let c = coil.find("refLocalId=\"4\"").unwrap();
    assert!(b < c, "{coil}");
    assert!(body.contains("<rightPowerRail localId=\"8\">"), "{body}");
    assert!(
        xml.contains("<network first=\"6\" title=\"Start\" label=\"L1\"/>"),
        "{xml}"
    );
}

#[test]
fn an_fbd_chain_ands_its_operands_and_assigns_box_outputs() {
    let rung = network(
        r#"
rung = [
  { type = "operand", id = 1, text = "a" },
  { type = "operand", id = 2, text = "b" },
  { type = "block", id = 3, type_name = "TON", instance = "t", input = [
      { pin = "IN" },
      { pin = "PT", source = [{ type = "operand", id = 4, text = "T#1s" }] },
  ], output = [{ pin = "Q" }, { pin = "ET", assign = "elapsed" }] },
]
output = [{ type = "coil", id = 5, variable = "q" }]
"#,
    );
    let xml = String::from_utf8(
        export(&graphical(Body::Fbd {
            networks: vec![rung],
        }))
        .unwrap(),
    )
    .unwrap();
    crate::read(&xml, "fbd.xml").unwrap();
    let body = &xml[xml.find("<FBD>").unwrap()..xml.find("</FBD>").unwrap()];
    assert!(body.contains("typeName=\"AND\""), "{body}");
    assert!(body.contains("<expression>T#1s</expression>"), "{body}");
    assert!(body.contains("<expression>elapsed</expression>"), "{body}");
    let out = &body[body.find("<outVariable localId=\"5\">").unwrap()..];
    assert!(
        out.contains("<connection refLocalId=\"3\" formalParameter=\"Q\"/>"),
        "{out}"
    );
    assert!(!body.contains("PowerRail"), "{body}");
}

#[test]
fn a_cfc_chart_is_an_fbd_body_with_execution_order_and_its_language_marked() {
    let chart: project_model::CfcChart = toml::from_str(
        r#"
[[element]]
id = 1
x = 2
y = 3
kind = { type = "input", expression = "a" }

[[element]]
id = 2
x = 10
y = 3
order = 0
kind = { type = "output", expression = "q", coil = "set" }

[[element]]
id = 3
x = 2
y = 8
kind = { type = "comment", text = "note", width = 8, height = 2 }

[[wire]]
from = { element = 1 }
to = { element = 2 }
points = [{ x = 6, y = 3 }]
"#,
    )
    .unwrap();
    let xml = String::from_utf8(export(&graphical(Body::Cfc { chart })).unwrap()).unwrap();
    crate::read(&xml, "cfc.xml").unwrap();
    let body = &xml[xml.find("<FBD>").unwrap()..xml.find("</FBD>").unwrap()];
    assert!(body.contains("<inVariable localId=\"1\">"), "{body}");
    assert!(
        body.contains("<outVariable localId=\"2\" executionOrderId=\"1\" storage=\"set\">"),
        "{body}"
    );
    assert!(body.contains("<position x=\"20\" y=\"30\"/>"), "{body}");
    assert!(
        body.contains("<connection refLocalId=\"1\">\n")
            && body.contains("<position x=\"60\" y=\"30\"/>"),
        "{body}"
    );
    assert!(body.contains("height=\"20\" width=\"80\""), "{body}");
    assert!(
        xml.contains("<language xmlns=\"https://rivet-plc.dev/plcopen/1\" name=\"CFC\"/>"),
        "{xml}"
    );
}

#[test]
fn an_sfc_chart_is_written_in_beremiz_form_with_rivet_step_details() {
    use project_model::{
        ActionAssociation, ActionQualifier, ElementId, SfcBranches, SfcChart, SfcNode,
    };
    let mut init = SfcNode::step(ElementId(1), "Init");
    if let SfcNode::Step(step) = &mut init {
        step.max_time = Some("T#5s".into());
        step.actions.push(ActionAssociation {
            action: "Fill".into(),
            qualifier: ActionQualifier::S,
            duration: Some("T#2s".into()),
            indicator: None,
        });
    }
    let mut ready = SfcNode::transition(ElementId(3), "Ready");
    if let SfcNode::Transition(transition) = &mut ready {
        transition.priority = Some(1);
    }
    let chart = SfcChart {
        sequence: vec![
            init,
            SfcNode::Alternative(SfcBranches::new(
                ElementId(2),
                vec![
                    vec![
                        ready,
                        SfcNode::step(ElementId(4), "Run"),
                        SfcNode::transition(ElementId(5), "done AND NOT stop"),
                    ],
                    vec![
                        SfcNode::transition(ElementId(6), "abort"),
                        SfcNode::jump(ElementId(7), "Init"),
                    ],
                ],
            )),
            SfcNode::jump(ElementId(8), "Init"),
        ],
    };
    let mut project = graphical(Body::Sfc { chart });
    if let Some(Node::Object(Object::Pou(pou))) = project.application.children.first_mut() {
        pou.transitions.push(project_model::PouAction {
            name: "Ready".into(),
            body: Body::st("Ready := TRUE;"),
        });
    }
    let bytes = export(&project).unwrap();
    super::round_trip_tests::assert_valid(&bytes, "an SFC chart");
    let xml = String::from_utf8(bytes).unwrap();
    crate::read(&xml, "sfc.xml").unwrap();
    let body = &xml[xml.find("<SFC>").unwrap()..xml.find("</SFC>").unwrap()];
    assert!(
        body.contains("<step localId=\"1\" name=\"Init\" initialStep=\"true\">"),
        "{body}"
    );
    assert!(body.contains("maxTime=\"T#5s\""), "{body}");
    assert!(body.contains("qualifier=\"S\" duration=\"T#2s\""), "{body}");
    assert!(body.contains("<reference name=\"Ready\"/>"), "{body}");
    assert!(body.contains("<![CDATA[done AND NOT stop]]>"), "{body}");
    assert!(
        body.contains("<transition localId=\"3\" priority=\"1\">"),
        "{body}"
    );
    assert!(
        body.contains("<selectionDivergence localId=\"2\">"),
        "{body}"
    );
    // Only the first branch goes on: the convergence gathers it, then the jump back.
    let convergence = &body[body.find("<selectionConvergence").unwrap()..];
    assert!(convergence.contains("refLocalId=\"5\""), "{convergence}");
    assert!(
        !convergence[..convergence.find("</selectionConvergence>").unwrap()]
            .contains("refLocalId=\"7\"")
    );
    assert!(
        body.contains("<jumpStep localId=\"8\" targetName=\"Init\">"),
        "{body}"
    );
}

#[test]
fn declarations_another_tool_changed_win_over_rivet_data_and_st_edits_are_taken() {
    let mut project = small_project();
    project
        .application
        .children
        .push(Node::Object(Object::Gvl(project_model::GlobalVarList {
            name: "G".into(),
            comment: String::new(),
            variables: vec![Variable {
                section: project_model::VarSection::VarGlobal,
                ..Variable::new("a", "INT")
            }],
        })));
    let xml = String::from_utf8(export(&project).unwrap()).unwrap();
    let added = "<variable name=\"extra\">\n<type>\n<BOOL/>\n</type>\n</variable>\n";
    // Another tool adds a variable to the POU and one to the list, and edits the ST body.
    let edited = xml
        .replacen("</localVars>", &format!("{added}</localVars>"), 1)
        .replacen(
            "<globalVars name=\"G\">",
            &format!("<globalVars name=\"G\">{added}"),
            1,
        )
        .replace("count := count + 1;", "count := count + 2;");
    assert_ne!(edited, xml);
    let document = crate::read(&edited, "edited.xml").unwrap();
    let imported = crate::import(&document).unwrap();
    let Some(Object::Pou(main)) = imported.project.application.object("Main") else {
        panic!("no Main");
    };
    let names: Vec<&str> = main.variables.iter().map(|v| v.name.as_str()).collect();
    assert_eq!(names, ["count", "extra"]);
    assert_eq!(main.body.st_text(), Some("count := count + 2;\n"));
    let Some(Object::Gvl(list)) = imported.project.application.object("G") else {
        panic!("no G");
    };
    let names: Vec<&str> = list.variables.iter().map(|v| v.name.as_str()).collect();
    assert_eq!(names, ["extra", "a"], "{edited}");
}
