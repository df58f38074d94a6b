//! The CFC import (docs/plcopen-xml.md §4.5–4.6): CODESYS's CFC, Rivet's marked FBD bodies and
//! any FBD graph.

use std::collections::HashSet;

use project_model::{
    Body, CfcChart, CfcElement, CfcElementKind, CoilKind, ElementId, GridPoint, Object, PinRef,
};

use super::cfc_chart::{CfcDialect, fbd_graph_to_cfc};
use super::{ImportErrorKind, Imported, Outcome, import};
use crate::read;
use crate::reader::corpus_tests::read_corpus;
use crate::{BodyContent, Document};

/// A v2.01 document with one program `Chart` whose body is `body` (a whole `body` element).
fn document(body: &str) -> String {
    format!(
        r#"<?xml version="1.0" encoding="UTF-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201" xmlns:xhtml="http://www.w3.org/1999/xhtml">
  <fileHeader companyName="c" productName="p" productVersion="1" creationDateTime="2024-01-01T00:00:00"/>
  <contentHeader name="n"><coordinateInfo><fbd><scaling x="10" y="10"/></fbd><ld><scaling x="10" y="10"/></ld><sfc><scaling x="10" y="10"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous>
    <pou name="Chart" pouType="program">
      <interface><localVars><variable name="a"><type><INT/></type></variable><variable name="b"><type><BOOL/></type></variable></localVars></interface>
      {body}
    </pou>
  </pous></types>
  <instances><configurations/></instances>
</project>
"#
    )
}

fn imported(text: &str) -> Imported {
    let document = read(text, "in.xml").unwrap_or_else(|error| panic!("{error}"));
    import(&document).unwrap_or_else(|error| panic!("{error}"))
}

fn chart<'i>(imported: &'i Imported, name: &str) -> &'i CfcChart {
    match imported.project.application.object(name) {
        Some(Object::Pou(pou)) => match &pou.body {
            Body::Cfc { chart } => chart,
            other => panic!("not CFC: {other:?}"),
        },
        other => panic!("no POU {name}: {other:?}\n{:#?}", imported.report),
    }
}

fn element(chart: &CfcChart, wanted: impl Fn(&CfcElementKind) -> bool) -> &CfcElement {
    chart
        .elements
        .iter()
        .find(|element| wanted(&element.kind))
        .unwrap_or_else(|| panic!("{chart:#?}"))
}

fn input(chart: &CfcChart, expression: &str) -> ElementId {
    element(
        chart,
        |kind| matches!(kind, CfcElementKind::Input { expression: e } if e == expression),
    )
    .id
}

#[test]
fn codesys_add_two_ints_cfc_resolves_its_junctions_and_keeps_its_order() {
    let imported = import(&read_corpus(
        "plcopen/codesys/codesys_code_execution_speedTests.xml",
    ))
    .unwrap_or_else(|error| panic!("{error}"));
    let chart = chart(&imported, "addTwoIntsCFC");
    // Two inputs, the ADD box and the output; CODESYS's unnamed connectors are no elements.
    assert_eq!(chart.elements.len(), 4, "{chart:#?}");
    let add = element(
        chart,
        |kind| matches!(kind, CfcElementKind::Box(b) if b.type_name == "ADD"),
    );
    assert_eq!((add.x, add.y), (7, 2));
    let output = element(
        chart,
        |kind| matches!(kind, CfcElementKind::Output { expression, .. } if expression == "addTwoIntsCFC"),
    );
    assert_eq!((output.x, output.y), (11, 3));
    // CODESYS numbered the output 1 and the box 2, against the wire: data flow comes first.
    assert_eq!(add.order, Some(0));
    assert_eq!(output.order, Some(1));
    let int1 = input(chart, "int1");
    let int2 = input(chart, "int2");
    let mut wires: Vec<(PinRef, PinRef)> = chart
        .wires
        .iter()
        .map(|wire| (wire.from.clone(), wire.to.clone()))
        .collect();
    wires.sort_by_key(|(_, to)| (to.element, to.pin.clone()));
    assert_eq!(
        wires,
        [
            (PinRef::new(int1, ""), PinRef::new(add.id, "In1")),
            (PinRef::new(int2, ""), PinRef::new(add.id, "In2")),
            (PinRef::new(add.id, "Out1"), PinRef::new(output.id, "")),
        ]
    );
    let entry = imported.report.entry("POU 'addTwoIntsCFC'");
    assert_eq!(entry.map(|entry| entry.outcome), Some(Outcome::Converted));
    // The box's call type goes back inside the kept `…/cfc` entry, not on its own: the report
    // says so at its place.
    assert!(imported.report.with_outcome(Outcome::NotConverted).any(|entry| entry.path
        == "project/types/pous/pou[@name='addTwoIntsCFC']/body/addData/data[@name='http://www.3s-software.com/plcopenxml/cfc']/CFC/block[@localId='2']/addData/data[@name='http://www.3s-software.com/plcopenxml/cfccalltype']"));
}

/// An FBD body as Rivet's export writes a CFC chart: positions × 10, `executionOrderId` =
/// order + 1, and the `…/language` marker.
const RIVET_CFC: &str = r#"<body><FBD>
  <inVariable localId="1"><position x="10" y="20"/><connectionPointOut/><expression>a</expression></inVariable>
  <block localId="2" typeName="GT" executionOrderId="2"><position x="60" y="20"/>
    <inputVariables>
      <variable formalParameter="IN1"><connectionPointIn><connection refLocalId="1"/></connectionPointIn></variable>
      <variable formalParameter="IN2" negated="true" edge="rising"><connectionPointIn><connection refLocalId="6"/></connectionPointIn></variable>
    </inputVariables>
    <inOutVariables/>
    <outputVariables><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables>
  </block>
  <connector localId="3" name="flag"><position x="120" y="20"/><connectionPointIn><connection refLocalId="2" formalParameter="OUT"><position x="120" y="20"/><position x="100" y="20"/><position x="100" y="40"/><position x="90" y="40"/></connection></connectionPointIn></connector>
  <continuation localId="4" name="flag"><position x="10" y="80"/><connectionPointOut/></continuation>
  <outVariable localId="5" executionOrderId="1" storage="set"><position x="60" y="80"/><connectionPointIn><connection refLocalId="4"/></connectionPointIn><expression>b</expression></outVariable>
  <inVariable localId="6"><position x="10" y="40"/><connectionPointOut/><expression>b</expression></inVariable>
  <label localId="7" executionOrderId="3" label="done"><position x="10" y="120"/></label>
  <comment localId="8" height="20" width="50"><position x="100" y="120"/><content><xhtml:p>Sets b.</xhtml:p></content></comment>
</FBD>
<addData><data name="https://rivet-plc.dev/plcopen/1/language" handleUnknown="preserve"><language xmlns="https://rivet-plc.dev/plcopen/1" name="CFC"/></data></addData>
</body>"#;

#[test]
fn an_fbd_body_with_rivets_marker_becomes_a_cfc_chart_in_grid_units() {
    let imported = imported(&document(RIVET_CFC));
    let chart = chart(&imported, "Chart");
    let gt = element(chart, |kind| matches!(kind, CfcElementKind::Box(_)));
    assert_eq!((gt.x, gt.y, gt.order), (6, 2, Some(1)));
    let CfcElementKind::Box(block) = &gt.kind else {
        unreachable!()
    };
    assert!(block.inputs[1].negated);
    assert_eq!(block.inputs[1].edge, project_model::Edge::Rising);
    let set = element(chart, |kind| matches!(kind, CfcElementKind::Output { .. }));
    assert_eq!(set.order, Some(0));
    assert!(matches!(
        set.kind,
        CfcElementKind::Output {
            coil: CoilKind::Set,
            ..
        }
    ));
    let label = element(chart, |kind| matches!(kind, CfcElementKind::Label { .. }));
    assert_eq!(label.order, Some(2));
    let source = element(
        chart,
        |kind| matches!(kind, CfcElementKind::ConnectionSource { name } if name == "flag"),
    );
    assert_eq!(source.order, None);
    let comment = element(chart, |kind| matches!(kind, CfcElementKind::Comment { .. }));
    assert_eq!(
        comment.kind,
        CfcElementKind::Comment {
            text: "Sets b.".into(),
            width: 5,
            height: 2
        }
    );
    // The wire's inner points, from the producer to the consumer, in grid units.
    let wire = chart
        .wires
        .iter()
        .find(|wire| wire.to.element == source.id)
        .unwrap_or_else(|| panic!("{chart:#?}"));
    assert_eq!(wire.from, PinRef::new(gt.id, "OUT"));
    assert_eq!(
        wire.points,
        [GridPoint { x: 10, y: 4 }, GridPoint { x: 10, y: 2 }]
    );
    assert!(project_model::cfc_problems(chart).is_empty());
}

#[test]
fn an_fbd_body_without_the_marker_is_left_to_the_network_import() {
    let unmarked = RIVET_CFC.replace("/1/language", "/1/other");
    let imported = imported(&document(&unmarked));
    let Some(Object::Pou(pou)) = imported.project.application.object("Chart") else {
        panic!("{:?}", imported.report)
    };
    assert!(matches!(pou.body, Body::Fbd { .. }), "{:?}", pou.body);
}

#[test]
fn a_beremiz_fbd_graph_runs_each_block_before_what_it_drives() {
    let document: Document =
        read_corpus("plcopen/beremiz/tests/projects/iec61131_lang_test/plc.xml");
    let mut converted = 0;
    for pou in &document.pous {
        let Some(body) = pou.bodies.first() else {
            continue;
        };
        let BodyContent::Fbd(objects) = &body.content else {
            continue;
        };
        let chart = fbd_graph_to_cfc(
            objects,
            CfcDialect::Beremiz,
            "body/FBD",
            body.line,
            &HashSet::new(),
        )
        .unwrap_or_else(|fault| panic!("{}: {fault:?}", pou.name));
        let order_of = |id: ElementId| {
            chart
                .elements
                .iter()
                .find(|element| element.id == id)
                .and_then(|element| element.order)
        };
        for wire in &chart.wires {
            let (Some(from), Some(to)) = (order_of(wire.from.element), order_of(wire.to.element))
            else {
                continue;
            };
            assert!(from < to, "{}: {wire:?} runs against the flow", pou.name);
        }
        assert!(
            project_model::cfc_problems(&chart).is_empty(),
            "{}",
            pou.name
        );
        converted += 1;
    }
    assert!(converted > 0);
}

#[test]
fn a_ring_of_codesys_junctions_is_an_error_with_its_path() {
    let body = r#"<body><ST><xhtml:p></xhtml:p></ST><addData><data name="http://www.3s-software.com/plcopenxml/cfc" handleUnknown="implementation"><CFC>
      <connector localId="1" name=""><position x="0" y="0"/><connectionPointIn><connection refLocalId="2"/></connectionPointIn></connector>
      <connector localId="2" name=""><position x="0" y="0"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn></connector>
      <outVariable localId="0" executionOrderId="1"><position x="11" y="3"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><expression>a</expression></outVariable>
    </CFC></data></addData></body>"#;
    let document = read(&document(body), "bad.xml").unwrap_or_else(|error| panic!("{error}"));
    let error = import(&document)
        .err()
        .unwrap_or_else(|| panic!("imported"));
    assert!(matches!(&*error.kind, ImportErrorKind::BadCfc(message) if message.contains("ring")));
    assert_eq!(
        error.path,
        "project/types/pous/pou[@name='Chart']/body/addData/data[@name='http://www.3s-software.com/plcopenxml/cfc']/CFC/outVariable[@localId='0']"
    );
}

#[test]
fn two_wires_into_one_input_are_refused() {
    let body = RIVET_CFC.replace(
        r#"<connection refLocalId="4"/>"#,
        r#"<connection refLocalId="4"/><connection refLocalId="6"/>"#,
    );
    let document = read(&document(&body), "bad.xml").unwrap_or_else(|error| panic!("{error}"));
    let error = import(&document)
        .err()
        .unwrap_or_else(|| panic!("imported"));
    assert!(error.to_string().contains("2 wires"), "{error}");
    assert!(
        error.path.ends_with("/FBD/outVariable[@localId='5']"),
        "{}",
        error.path
    );
}

#[test]
fn an_action_with_a_marked_body_is_a_cfc_action_and_off_grid_wires_route_themselves() {
    let off_grid = RIVET_CFC.replace(
        r#"<position x="100" y="40"/>"#,
        r#"<position x="105" y="40"/>"#,
    );
    let action = format!(
        r#"<actions><action name="Act">{off_grid}</action></actions><body><ST><xhtml:p>Act();</xhtml:p></ST></body>"#
    );
    let imported = imported(&document(&action));
    let Some(Object::Pou(pou)) = imported.project.application.object("Chart") else {
        panic!("{:#?}", imported.report)
    };
    let [act] = pou.actions.as_slice() else {
        panic!("{:?}", pou.actions)
    };
    let Body::Cfc { chart } = &act.body else {
        panic!("{:?}", act.body)
    };
    assert!(
        chart.wires.iter().all(|wire| wire.points.is_empty()),
        "{chart:#?}"
    );
    let entry = imported.report.entry("action 'Chart.Act'");
    assert_eq!(entry.map(|entry| entry.outcome), Some(Outcome::Converted));
}

#[test]
fn a_beremiz_feedback_loop_keeps_every_element_once() {
    // ADD reads its own output through a connector: the loop is broken, each element runs once.
    let body = r#"<body><FBD>
      <inVariable localId="1"><position x="10" y="10"/><connectionPointOut/><expression>1</expression></inVariable>
      <continuation localId="2" name="loop"><position x="10" y="40"/><connectionPointOut/></continuation>
      <block localId="3" typeName="ADD" executionOrderId="0"><position x="60" y="10"/>
        <inputVariables>
          <variable formalParameter="IN1"><connectionPointIn><connection refLocalId="1"/></connectionPointIn></variable>
          <variable formalParameter="IN2"><connectionPointIn><connection refLocalId="2"/></connectionPointIn></variable>
        </inputVariables><inOutVariables/>
        <outputVariables><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables>
      </block>
      <connector localId="4" name="loop"><position x="120" y="40"/><connectionPointIn><connection refLocalId="3" formalParameter="OUT"/></connectionPointIn></connector>
      <outVariable localId="5" executionOrderId="0"><position x="120" y="10"/><connectionPointIn><connection refLocalId="3" formalParameter="OUT"/></connectionPointIn><expression>a</expression></outVariable>
    </FBD></body>"#;
    let looped = read(&document(body), "in.xml").unwrap_or_else(|error| panic!("{error}"));
    let objects = match &looped.pous[0].bodies[0].content {
        BodyContent::Fbd(objects) => objects,
        other => panic!("{other:?}"),
    };
    let chart = fbd_graph_to_cfc(objects, CfcDialect::Beremiz, "body/FBD", 1, &HashSet::new())
        .unwrap_or_else(|fault| panic!("{fault:?}"));
    let add = element(&chart, |kind| matches!(kind, CfcElementKind::Box(_)));
    let out = element(&chart, |kind| matches!(kind, CfcElementKind::Output { .. }));
    assert_eq!((add.order, out.order), (Some(0), Some(1)));
    assert!(project_model::cfc_problems(&chart).is_empty());
    // Numbered against the flow, as CODESYS writes them: the flow still comes first.
    let numbered = body
        .replace(
            r#"typeName="ADD" executionOrderId="0""#,
            r#"typeName="ADD" executionOrderId="2""#,
        )
        .replace(
            r#"<outVariable localId="5" executionOrderId="0""#,
            r#"<outVariable localId="5" executionOrderId="1""#,
        );
    let renumbered = read(&document(&numbered), "in.xml").unwrap_or_else(|error| panic!("{error}"));
    let objects = match &renumbered.pous[0].bodies[0].content {
        BodyContent::Fbd(objects) => objects,
        other => panic!("{other:?}"),
    };
    let codesys = fbd_graph_to_cfc(objects, CfcDialect::Codesys, "body/FBD", 1, &HashSet::new())
        .unwrap_or_else(|fault| panic!("{fault:?}"));
    let rivet = fbd_graph_to_cfc(objects, CfcDialect::Rivet, "body/FBD", 1, &HashSet::new())
        .unwrap_or_else(|fault| panic!("{fault:?}"));
    let orders = |chart: &CfcChart| {
        let add = element(chart, |kind| matches!(kind, CfcElementKind::Box(_))).order;
        let out = element(chart, |kind| matches!(kind, CfcElementKind::Output { .. })).order;
        (add, out)
    };
    assert_eq!(orders(&codesys), (Some(0), Some(1)));
    // Rivet's own numbers are kept exactly.
    assert_eq!(orders(&rivet), (Some(1), Some(0)));
}

/// A counter as Beremiz draws it, in CODESYS's CFC: `ADD(a, 1)` into an in-out `a`, whose
/// output `b` reads.
const IN_OUT_COUNTER: &str = r#"<body><ST><xhtml:p></xhtml:p></ST><addData><data name="http://www.3s-software.com/plcopenxml/cfc" handleUnknown="implementation"><CFC>
      <inVariable localId="1"><position x="1" y="2"/><connectionPointOut/><expression>1</expression></inVariable>
      <block localId="3" typeName="ADD" executionOrderId="1"><position x="6" y="1"/>
        <inputVariables>
          <variable formalParameter="IN1"><connectionPointIn><connection refLocalId="4"/></connectionPointIn></variable>
          <variable formalParameter="IN2"><connectionPointIn><connection refLocalId="1"/></connectionPointIn></variable>
        </inputVariables><inOutVariables/>
        <outputVariables><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables>
      </block>
      <inOutVariable localId="4" executionOrderId="0"><position x="12" y="1"/><connectionPointIn><connection refLocalId="3" formalParameter="OUT"/></connectionPointIn><connectionPointOut/><expression>a</expression></inOutVariable>
      <outVariable localId="5" executionOrderId="2"><position x="20" y="1"/><connectionPointIn><connection refLocalId="4"/></connectionPointIn><expression>b</expression></outVariable>
    </CFC></data></addData></body>"#;

#[test]
fn an_in_out_variable_is_an_output_and_an_input_read_after_it() {
    let imported = imported(&document(IN_OUT_COUNTER));
    let chart = chart(&imported, "Chart");
    let write = element(
        chart,
        |kind| matches!(kind, CfcElementKind::Output { expression, .. } if expression == "a"),
    );
    let read = input(chart, "a");
    let add = element(chart, |kind| matches!(kind, CfcElementKind::Box(_)));
    let out = element(
        chart,
        |kind| matches!(kind, CfcElementKind::Output { expression, .. } if expression == "b"),
    );
    // The output stands where the in-out stood, the input to its right.
    assert_eq!((write.x, write.y), (12, 1));
    let read_element = element(
        chart,
        |kind| matches!(kind, CfcElementKind::Input { expression } if expression == "a"),
    );
    assert!(read_element.x > write.x, "{chart:#?}");
    assert!(chart.wires.contains(&project_model::Wire::routed(
        PinRef::new(add.id, "OUT"),
        PinRef::new(write.id, "")
    )));
    for reader in [PinRef::new(add.id, "IN1"), PinRef::new(out.id, "")] {
        assert!(
            chart
                .wires
                .iter()
                .any(|wire| wire.from == PinRef::new(read, "") && wire.to == reader),
            "{chart:#?}"
        );
    }
    // ADD reads the value of the previous cycle, the write follows it, and `b` reads the new
    // value after the write.
    assert_eq!(
        (add.order, write.order, out.order),
        (Some(0), Some(1), Some(2))
    );
    assert!(project_model::cfc_problems(chart).is_empty());
    assert!(
        imported
            .report
            .with_outcome(Outcome::NotConverted)
            .all(|entry| !entry.what.contains("Chart")),
        "{:#?}",
        imported.report
    );
}

/// Beremiz's counter: `ADD(a, 1)` into an in-out `a`, whose output `b` reads; `b` drawn at
/// `b_y` pixels (the in-out at 10).
fn beremiz_in_out_counter(b_y: u32) -> String {
    format!(
        r#"<body><FBD>
      <inVariable localId="1"><position x="10" y="20"/><connectionPointOut/><expression>1</expression></inVariable>
      <block localId="3" typeName="ADD"><position x="60" y="10"/>
        <inputVariables>
          <variable formalParameter="IN1"><connectionPointIn><connection refLocalId="4"/></connectionPointIn></variable>
          <variable formalParameter="IN2"><connectionPointIn><connection refLocalId="1"/></connectionPointIn></variable>
        </inputVariables><inOutVariables/>
        <outputVariables><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables>
      </block>
      <inOutVariable localId="4"><position x="120" y="10"/><connectionPointIn><connection refLocalId="3" formalParameter="OUT"/></connectionPointIn><connectionPointOut/><expression>a</expression></inOutVariable>
      <outVariable localId="5"><position x="200" y="{b_y}"/><connectionPointIn><connection refLocalId="4"/></connectionPointIn><expression>b</expression></outVariable>
    </FBD></body>"#
    )
}

/// The FBD graph of the one body of `body`'s document, as a chart in Beremiz's dialect.
fn beremiz_chart(body: &str, structures: &HashSet<String>) -> CfcChart {
    let parsed = read(&document(body), "in.xml").unwrap_or_else(|error| panic!("{error}"));
    let objects = parsed.pous[0].bodies[0].content.objects();
    fbd_graph_to_cfc(objects, CfcDialect::Beremiz, "body/FBD", 1, structures)
        .unwrap_or_else(|fault| panic!("{fault:?}"))
}

#[test]
fn an_in_out_variable_in_beremiz_order_is_written_before_its_readers_below_it() {
    let order = |chart: &CfcChart| {
        let output = |expression: &str| {
            element(
                chart,
                |kind| matches!(kind, CfcElementKind::Output { expression: e, .. } if e == expression),
            )
            .order
        };
        let add = element(chart, |kind| matches!(kind, CfcElementKind::Box(_))).order;
        (add, output("a"), output("b"))
    };
    // `b` on the in-out's row, right of it: Beremiz runs the write first, `b` reads the new
    // value.
    let level = beremiz_chart(&beremiz_in_out_counter(10), &HashSet::new());
    assert_eq!(order(&level), (Some(0), Some(1), Some(2)), "{level:#?}");
    // `b` drawn above the in-out: Beremiz's generator reads an in-out as its variable's name
    // and runs `b` first, so `b` reads the previous cycle's value.
    let above = beremiz_chart(&beremiz_in_out_counter(0), &HashSet::new());
    assert_eq!(order(&above), (Some(1), Some(2), Some(0)), "{above:#?}");
}

#[test]
fn an_in_out_variable_nothing_is_wired_into_is_only_read() {
    let body = IN_OUT_COUNTER.replace(
        r#"<connectionPointIn><connection refLocalId="3" formalParameter="OUT"/></connectionPointIn><connectionPointOut/><expression>a</expression>"#,
        r#"<connectionPointIn/><connectionPointOut/><expression>a</expression>"#,
    );
    assert_ne!(body, IN_OUT_COUNTER);
    let imported = imported(&document(&body));
    let chart = chart(&imported, "Chart");
    assert!(
        !chart
            .elements
            .iter()
            .any(|element| matches!(&element.kind, CfcElementKind::Output { expression, .. } if expression == "a")),
        "{chart:#?}"
    );
    let read = input(chart, "a");
    let out = element(
        chart,
        |kind| matches!(kind, CfcElementKind::Output { expression, .. } if expression == "b"),
    );
    assert!(chart.wires.contains(&project_model::Wire::routed(
        PinRef::new(read, ""),
        PinRef::new(out.id, "")
    )));
    assert!(project_model::cfc_problems(chart).is_empty());
}

/// A block `type_name` (with `instance` attributes) with one input and one unnamed output,
/// read from `a` and written to `b`, in a Beremiz FBD graph.
fn unnamed_output_block(type_name: &str, instance: &str) -> String {
    format!(
        r#"<body><FBD>
      <inVariable localId="1"><position x="10" y="10"/><connectionPointOut/><expression>a</expression></inVariable>
      <block localId="2" typeName="{type_name}"{instance}><position x="60" y="10"/>
        <inputVariables><variable formalParameter="IN"><connectionPointIn><connection refLocalId="1"/></connectionPointIn></variable></inputVariables>
        <inOutVariables/>
        <outputVariables><variable formalParameter=""><connectionPointOut/></variable></outputVariables>
      </block>
      <outVariable localId="3"><position x="120" y="10"/><connectionPointIn><connection refLocalId="2"/></connectionPointIn><expression>b</expression></outVariable>
    </FBD></body>"#
    )
}

#[test]
fn only_a_structure_of_the_document_without_instance_is_taken_for_a_composer() {
    let structures: HashSet<String> = ["point".to_owned()].into();
    let kind_of = |body: &str| {
        let chart = beremiz_chart(body, &structures);
        element(&chart, |kind| {
            matches!(
                kind,
                CfcElementKind::Box(_) | CfcElementKind::Composer { .. }
            )
        })
        .kind
        .clone()
    };
    // Beremiz names a function's result "": ABS stays a box.
    assert!(
        matches!(kind_of(&unnamed_output_block("ABS", "")), CfcElementKind::Box(b) if b.type_name == "ABS"),
    );
    assert!(matches!(
        kind_of(&unnamed_output_block("Point", "")),
        CfcElementKind::Composer { type_name, .. } if type_name == "Point"
    ));
    // An instance is kept: a box of that name.
    assert!(matches!(
        kind_of(&unnamed_output_block("Point", r#" instanceName="p1""#)),
        CfcElementKind::Box(b) if b.instance == "p1"
    ));
}

#[test]
fn an_in_out_at_the_end_of_the_coordinates_finds_a_free_place() {
    // Both elements of the pair round to the last place of the grid: the input goes above.
    let body = beremiz_in_out_counter(10).replace(
        r#"<inOutVariable localId="4"><position x="120" y="10"/>"#,
        r#"<inOutVariable localId="4"><position x="1e300" y="1e300"/>"#,
    );
    let chart = beremiz_chart(&body, &HashSet::new());
    let places: HashSet<(i32, i32)> = chart
        .elements
        .iter()
        .map(|element| (element.x, element.y))
        .collect();
    assert_eq!(places.len(), chart.elements.len(), "{chart:#?}");
    assert!(places.contains(&(i32::MAX, i32::MAX)), "{chart:#?}");
}

#[test]
fn an_in_out_variable_comes_back_from_the_plain_export_as_the_same_pair() {
    let imported = imported(&document(IN_OUT_COUNTER));
    let options = crate::ExportOptions {
        object_entries: false,
    };
    let xml =
        crate::export_with(&imported.project, options).unwrap_or_else(|error| panic!("{error}"));
    let document = crate::read_bytes(&xml, "plain.xml").unwrap_or_else(|error| panic!("{error}"));
    let again = import(&document).unwrap_or_else(|error| panic!("{error}"));
    assert_eq!(chart(&again, "Chart"), chart(&imported, "Chart"));
}

#[test]
fn an_in_out_variable_that_detects_an_edge_on_its_output_is_not_converted() {
    let body = IN_OUT_COUNTER.replace(
        r#"<inOutVariable localId="4""#,
        r#"<inOutVariable localId="4" edgeOut="rising""#,
    );
    let imported = imported(&document(&body));
    let entry = imported.report.entry("POU 'Chart'");
    assert!(
        entry.is_some_and(|entry| entry.outcome == Outcome::NotConverted
            && entry.note.contains("detects an edge on its output")),
        "{entry:?}"
    );
}

#[test]
fn composers_and_selectors_come_back_from_the_plain_export() {
    let mut project = imported(&document(RIVET_CFC)).project;
    let at = |id: u32, x: i32, order: Option<u32>, kind: CfcElementKind| CfcElement {
        id: ElementId(id),
        x,
        y: 2,
        order,
        kind,
    };
    let members = || {
        vec![
            project_model::CfcPin::named("x"),
            project_model::CfcPin::named("y"),
        ]
    };
    let structures = CfcChart {
        elements: vec![
            at(
                1,
                1,
                None,
                CfcElementKind::Input {
                    expression: "a".into(),
                },
            ),
            at(
                2,
                6,
                Some(0),
                CfcElementKind::Composer {
                    type_name: "Point".into(),
                    inputs: members(),
                },
            ),
            at(
                3,
                12,
                Some(1),
                CfcElementKind::Selector {
                    type_name: "Point".into(),
                    outputs: members(),
                },
            ),
            at(
                4,
                18,
                Some(2),
                CfcElementKind::Output {
                    expression: "b".into(),
                    coil: CoilKind::Normal,
                },
            ),
        ],
        wires: vec![
            project_model::Wire::routed(
                PinRef::new(ElementId(1), ""),
                PinRef::new(ElementId(2), "x"),
            ),
            project_model::Wire::routed(
                PinRef::new(ElementId(1), ""),
                PinRef::new(ElementId(2), "y"),
            ),
            project_model::Wire::routed(
                PinRef::new(ElementId(2), ""),
                PinRef::new(ElementId(3), ""),
            ),
            project_model::Wire::routed(
                PinRef::new(ElementId(3), "x"),
                PinRef::new(ElementId(4), ""),
            ),
        ],
    };
    assert!(project_model::cfc_problems(&structures).is_empty());
    let Some(Object::Pou(pou)) = project.application.object_mut("Chart") else {
        panic!("no POU Chart")
    };
    pou.body = Body::Cfc {
        chart: structures.clone(),
    };
    let options = crate::ExportOptions {
        object_entries: false,
    };
    let xml = crate::export_with(&project, options).unwrap_or_else(|error| panic!("{error}"));
    let document = crate::read_bytes(&xml, "plain.xml").unwrap_or_else(|error| panic!("{error}"));
    let again = import(&document).unwrap_or_else(|error| panic!("{error}"));
    assert_eq!(chart(&again, "Chart"), &structures);
}

#[test]
fn a_codesys_composer_is_reported_with_its_element_type() {
    let body = r#"<body><ST><xhtml:p></xhtml:p></ST><addData><data name="http://www.3s-software.com/plcopenxml/cfc" handleUnknown="implementation"><CFC>
      <vendorElement localId="1"><position x="2" y="2"/><alternativeText><xhtml xmlns="http://www.w3.org/1999/xhtml">Point</xhtml></alternativeText>
        <addData><data name="http://www.3s-software.com/plcopenxml/cfcelementtype" handleUnknown="implementation"><ElementType xmlns="">composer</ElementType></data></addData>
      </vendorElement>
    </CFC></data></addData></body>"#;
    let imported = imported(&document(body));
    let entry = imported.report.entry("POU 'Chart'");
    assert!(
        entry.is_some_and(|entry| entry.outcome == Outcome::NotConverted
            && entry.note.contains("CODESYS composer at line")),
        "{entry:?}"
    );
}
