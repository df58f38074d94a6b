//! The SFC import (docs/plcopen-xml.md §4.1–4.4) on small documents and on the corpus.

use project_model::{ActionQualifier, Body, Object, Pou, SfcChart, SfcNode};

use super::{ImportErrorKind, Imported, Outcome, import};
use crate::read;
use crate::reader::corpus_tests::read_corpus;

/// A v2.01 document with one function block `Seq` whose SFC body holds `objects`, and the
/// actions and transitions `extra` (in the POU's `actions`/`transitions` elements).
fn document(objects: &str, extra: &str) -> String {
    format!(
        r#"<?xml version="1.0" encoding="UTF-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201" xmlns:xhtml="http://www.w3.org/1999/xhtml">
  <fileHeader companyName="c" productName="p" productVersion="1" creationDateTime="2024-01-01T00:00:00"/>
  <contentHeader name="n"><coordinateInfo><fbd><scaling x="0" y="0"/></fbd><ld><scaling x="0" y="0"/></ld><sfc><scaling x="0" y="0"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous>
    <pou name="Seq" pouType="functionBlock">
      <interface><localVars><variable name="go"><type><BOOL/></type></variable><variable name="A_INLINE1"><type><BOOL/></type></variable></localVars></interface>
      {extra}
      <body><SFC>
{objects}
      </SFC></body>
    </pou>
  </pous></types>
  <instances><configurations/></instances>
</project>
"#
    )
}

fn step(id: u64, name: &str, initial: bool, from: Option<u64>) -> String {
    let input = from.map_or(String::new(), |from| {
        format!(r#"<connectionPointIn><connection refLocalId="{from}"/></connectionPointIn>"#)
    });
    format!(
        r#"<step localId="{id}" name="{name}" initialStep="{initial}">{input}<connectionPointOut/><connectionPointOutAction/></step>"#
    )
}

fn transition(id: u64, from: u64, condition: &str) -> String {
    format!(
        r#"<transition localId="{id}"><connectionPointIn><connection refLocalId="{from}"/></connectionPointIn><connectionPointOut/><condition>{condition}</condition></transition>"#
    )
}

fn inline_st(text: &str) -> String {
    format!(r#"<inline name=""><ST><xhtml:p><![CDATA[{text}]]></xhtml:p></ST></inline>"#)
}

fn jump(id: u64, from: u64, target: &str) -> String {
    format!(
        r#"<jumpStep localId="{id}" targetName="{target}"><connectionPointIn><connection refLocalId="{from}"/></connectionPointIn></jumpStep>"#
    )
}

fn imported(text: &str) -> Imported {
    let document = read(text, "in.xml").unwrap_or_else(|error| panic!("{error}"));
    import(&document).unwrap_or_else(|error| panic!("{error}"))
}

fn pou<'i>(imported: &'i Imported, name: &str) -> &'i Pou {
    match imported.project.application.object(name) {
        Some(Object::Pou(pou)) => pou,
        other => panic!("no POU {name}: {other:?}\n{:#?}", imported.report),
    }
}

fn chart(pou: &Pou) -> &SfcChart {
    match &pou.body {
        Body::Sfc { chart } => chart,
        other => panic!("not SFC: {other:?}"),
    }
}

fn error(text: &str) -> super::ImportError {
    let document = read(text, "bad.xml").unwrap_or_else(|error| panic!("{error}"));
    match import(&document) {
        Ok(imported) => panic!("imported: {imported:?}"),
        Err(error) => error,
    }
}

/// The chart as a compact outline: `S:Name`, `T:condition`, `J:target`, `A[..|..]`, `P[..|..]`.
fn outline(nodes: &[SfcNode]) -> String {
    nodes
        .iter()
        .map(|node| match node {
            SfcNode::Step(step) => format!("S:{}", step.name),
            SfcNode::Transition(transition) => format!("T:{}", transition.condition),
            SfcNode::Jump(jump) => format!("J:{}", jump.target),
            SfcNode::Alternative(branches) | SfcNode::Parallel(branches) => {
                let inner: Vec<String> = branches
                    .branches
                    .iter()
                    .map(|branch| outline(&branch.nodes))
                    .collect();
                let letter = if matches!(node, SfcNode::Alternative(_)) {
                    "A"
                } else {
                    "P"
                };
                format!("{letter}[{}]", inner.join(" | "))
            }
            SfcNode::Macro(macro_step) => {
                format!("M:{}({})", macro_step.name, outline(&macro_step.body))
            }
        })
        .collect::<Vec<_>>()
        .join(" ")
}

#[test]
fn first_steps_counter_sfc_becomes_a_structured_chart_with_inline_actions() {
    let imported = import(&read_corpus("plcopen/beremiz/exemples/first_steps/plc.xml"))
        .unwrap_or_else(|error| panic!("{error}"));
    let counter = pou(&imported, "CounterSFC");
    let chart = chart(counter);
    // Branches left to right by where their wires leave the divergence (x 70, then 501).
    assert_eq!(
        outline(&chart.sequence),
        "S:Start A[T:NOT Reset S:Count T:Reset | T:Reset S:ResetCounter T:NOT Reset] J:Start"
    );
    let SfcNode::Alternative(branches) = &chart.sequence[1] else {
        panic!("{chart:?}")
    };
    let SfcNode::Step(count) = &branches.branches[0].nodes[1] else {
        panic!("{branches:?}")
    };
    let actions: Vec<(&str, ActionQualifier)> = count
        .actions
        .iter()
        .map(|association| (association.action.as_str(), association.qualifier))
        .collect();
    assert_eq!(
        actions,
        [
            ("Count_INLINE1", ActionQualifier::N),
            ("Count_INLINE2", ActionQualifier::N)
        ]
    );
    let bodies: Vec<(&str, Option<&str>)> = counter
        .actions
        .iter()
        .map(|action| (action.name.as_str(), action.body.st_text()))
        .collect();
    assert_eq!(
        bodies,
        [
            ("Count_INLINE1", Some("Cnt := Cnt + 1;")),
            ("Count_INLINE2", Some("OUT := Cnt;")),
            ("ResetCounter_INLINE3", Some("Cnt := ResetCounterValue;")),
            ("ResetCounter_INLINE4", Some("OUT := Cnt;")),
        ]
    );
    // Element ids are fresh, from 1, in the order the walk meets the elements.
    assert_eq!(chart.sequence[0].id().0, 1);
    assert_eq!(chart.sequence[1].id().0, 2);
    let entry = imported.report.entry("POU 'CounterSFC'");
    assert_eq!(entry.map(|entry| entry.outcome), Some(Outcome::Converted));
    assert!(
        imported
            .report
            .entry("action 'CounterSFC.Count_INLINE1'")
            .is_some()
    );
}

#[test]
fn svghmi_traffic_lights_keep_qualifiers_durations_and_contact_conditions() {
    let imported = import(&read_corpus(
        "plcopen/beremiz/tests/projects/svghmi_basic/plc.xml",
    ))
    .unwrap_or_else(|error| panic!("{error}"));
    let sequence = pou(&imported, "traffic_light_sequence");
    let chart = chart(sequence);
    let text = outline(&chart.sequence);
    // Chains of choices whose one branch goes on become alternatives followed by that branch.
    assert!(text.starts_with("S:Standstill T:"), "{text}");
    assert!(text.contains("J:Standstill"), "{text}");
    assert!(project_model::sfc_problems(chart).is_empty());
    let mut qualifiers = Vec::new();
    let mut all_steps = Vec::new();
    collect_steps(&chart.sequence, &mut all_steps);
    for step in &all_steps {
        for association in &step.actions {
            qualifiers.push(association.qualifier);
            if association.qualifier == ActionQualifier::D {
                assert!(
                    association
                        .duration
                        .as_deref()
                        .is_some_and(|time| time.starts_with("T#"))
                );
            }
        }
    }
    for expected in [
        ActionQualifier::D,
        ActionQualifier::P,
        ActionQualifier::R,
        ActionQualifier::S,
    ] {
        assert!(qualifiers.contains(&expected), "{qualifiers:?}");
    }
    // A condition wired from a negated contact on a left rail is its expression.
    let mut conditions = Vec::new();
    collect_conditions(&chart.sequence, &mut conditions);
    assert!(
        conditions
            .iter()
            .any(|condition| condition.starts_with("NOT ")),
        "{conditions:?}"
    );
    // A condition wired from FBD blocks became a transition object with a CFC body.
    let wired = sequence
        .transitions
        .iter()
        .find(|transition| transition.name == "GREEN_CONDITION1");
    assert!(
        wired.is_some_and(|transition| matches!(transition.body, Body::Cfc { .. })),
        "{:?}",
        sequence.transitions
    );
    assert!(
        conditions
            .iter()
            .any(|condition| condition == "GREEN_CONDITION1")
    );
    // Free comments cannot stand in a chart: each is reported.
    assert!(
        imported
            .report
            .with_outcome(Outcome::NotConverted)
            .any(|entry| entry.what.starts_with("comment '"))
    );
}

fn collect_steps<'c>(nodes: &'c [SfcNode], steps: &mut Vec<&'c project_model::Step>) {
    for node in nodes {
        match node {
            SfcNode::Step(step) => steps.push(step),
            SfcNode::Alternative(branches) | SfcNode::Parallel(branches) => {
                for branch in &branches.branches {
                    collect_steps(&branch.nodes, steps);
                }
            }
            SfcNode::Macro(macro_step) => collect_steps(&macro_step.body, steps),
            SfcNode::Transition(_) | SfcNode::Jump(_) => {}
        }
    }
}

fn collect_conditions(nodes: &[SfcNode], conditions: &mut Vec<String>) {
    for node in nodes {
        match node {
            SfcNode::Transition(transition) => conditions.push(transition.condition.clone()),
            SfcNode::Alternative(branches) | SfcNode::Parallel(branches) => {
                for branch in &branches.branches {
                    collect_conditions(&branch.nodes, conditions);
                }
            }
            SfcNode::Macro(macro_step) => collect_conditions(&macro_step.body, conditions),
            SfcNode::Step(_) | SfcNode::Jump(_) => {}
        }
    }
}

#[test]
fn matiec_sfc_test_has_simultaneous_branches_inside_an_alternative() {
    let imported =
        import(&read_corpus("matiec/tests/SFC_TEST.xml")).unwrap_or_else(|error| panic!("{error}"));
    let chart = chart(pou(&imported, "MAIN_TEST"));
    let text = outline(&chart.sequence);
    assert!(text.starts_with("S:GO T:"), "{text}");
    assert!(
        text.contains("P[S:D1 T:"),
        "the simultaneous divergence opens with D1: {text}"
    );
    assert!(text.contains("S:E3] T:"), "and joins after E3: {text}");
    assert!(text.ends_with("J:STEP2"), "{text}");
    let SfcNode::Alternative(choice) = chart
        .sequence
        .iter()
        .find(|node| matches!(node, SfcNode::Alternative(_)))
        .unwrap_or_else(|| panic!("{text}"))
    else {
        unreachable!()
    };
    assert_eq!(choice.branches.len(), 4, "{text}");
}

#[test]
fn a_loop_back_without_a_jump_step_becomes_a_jump_and_statements_a_transition_object() {
    let objects = [
        step(1, "Idle", true, Some(4)),
        transition(2, 1, &inline_st("go")),
        step(3, "Busy", false, Some(2)),
        transition(4, 3, &inline_st("T := NOT go;")),
    ]
    .join("\n");
    let imported = imported(&document(&objects, ""));
    let seq = pou(&imported, "Seq");
    assert_eq!(
        outline(&chart(seq).sequence),
        "S:Idle T:go S:Busy T:Busy_CONDITION1 J:Idle"
    );
    let [condition] = seq.transitions.as_slice() else {
        panic!("{:?}", seq.transitions)
    };
    assert_eq!(condition.body.st_text(), Some("T := NOT go;"));
}

#[test]
fn references_negation_priorities_and_qualifiers_are_kept() {
    let objects = [
        step(1, "A", true, None),
        r#"<actionBlock localId="9"><connectionPointIn><connection refLocalId="1"/></connectionPointIn>
             <action localId="0" qualifier="P1"><reference name="Enter"/></action>
             <action localId="0" qualifier="L" duration="T#2s" indicator="lit"><reference name="go"/></action>
             <action localId="0" qualifier="DL" duration="T#1s"><reference name="Enter"/></action>
             <action localId="0"><inline><ST><xhtml:p>go := TRUE;</xhtml:p></ST></inline></action>
           </actionBlock>"#
            .to_owned(),
        r#"<selectionDivergence localId="2"><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut/><connectionPointOut/></selectionDivergence>"#.to_owned(),
        r#"<transition localId="3" priority="2"><position x="10" y="0"/><connectionPointIn><connection refLocalId="2"/></connectionPointIn><connectionPointOut/><condition negated="true"><reference name="Ready"/></condition></transition>"#.to_owned(),
        r#"<transition localId="4" priority="1"><position x="90" y="0"/><connectionPointIn><connection refLocalId="2"/></connectionPointIn><connectionPointOut/><condition negated="true"><inline name=""><ST><xhtml:p>go OR go</xhtml:p></ST></inline></condition></transition>"#.to_owned(),
        jump(5, 3, "A"),
        jump(6, 4, "A"),
    ]
    .join("\n");
    let extra = r#"<actions><action name="Enter"><body><ST><xhtml:p>;</xhtml:p></ST></body></action></actions><transitions><transition name="Ready"><body><ST><xhtml:p>go</xhtml:p></ST></body></transition></transitions>"#;
    let imported = imported(&document(&objects, extra));
    let seq = pou(&imported, "Seq");
    let chart = chart(seq);
    assert_eq!(
        outline(&chart.sequence),
        "S:A A[T:NOT Ready() J:A | T:NOT (go OR go) J:A]"
    );
    let SfcNode::Alternative(branches) = &chart.sequence[1] else {
        panic!()
    };
    let SfcNode::Transition(first) = &branches.branches[0].nodes[0] else {
        panic!()
    };
    assert_eq!(first.priority, Some(2));
    let SfcNode::Step(step) = &chart.sequence[0] else {
        panic!()
    };
    let associations: Vec<(&str, ActionQualifier, Option<&str>, Option<&str>)> = step
        .actions
        .iter()
        .map(|association| {
            (
                association.action.as_str(),
                association.qualifier,
                association.duration.as_deref(),
                association.indicator.as_deref(),
            )
        })
        .collect();
    // The inline action's name `A_INLINE1` is a variable of the POU: it gets a suffix.
    assert_eq!(
        associations,
        [
            ("Enter", ActionQualifier::P1, None, None),
            ("go", ActionQualifier::L, Some("T#2s"), Some("lit")),
            ("Enter", ActionQualifier::D, Some("T#1s"), None),
            ("A_INLINE1_2", ActionQualifier::N, None, None),
        ]
    );
    let notes: Vec<&str> = imported
        .report
        .entries
        .iter()
        .map(|entry| entry.note.as_str())
        .collect();
    assert!(notes.iter().any(|note| note.contains("DL")), "{notes:?}");
    assert!(
        notes
            .iter()
            .any(|note| note.contains("`A_INLINE1` was taken")),
        "{notes:?}"
    );
}

#[test]
fn a_wired_in_variable_and_rivets_step_data_are_read() {
    let objects = [
        r#"<step localId="1" name="Fill" initialStep="true"><connectionPointOut/>
             <addData><data name="https://rivet-plc.dev/plcopen/1/step" handleUnknown="preserve"><step xmlns="https://rivet-plc.dev/plcopen/1" entryAction="Open" exitAction="Close" minTime="T#1s" maxTime="T#9s" comment="Fills the tank."/></data></addData>
           </step>"#.to_owned(),
        r#"<inVariable localId="7"><connectionPointOut/><expression>go AND go</expression></inVariable>"#.to_owned(),
        r#"<transition localId="2"><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut/><condition><connectionPointIn><connection refLocalId="7"/></connectionPointIn></condition></transition>"#.to_owned(),
        jump(3, 2, "Fill"),
    ]
    .join("\n");
    let imported = imported(&document(&objects, ""));
    let chart = chart(pou(&imported, "Seq"));
    assert_eq!(outline(&chart.sequence), "S:Fill T:go AND go J:Fill");
    let SfcNode::Step(fill) = &chart.sequence[0] else {
        panic!()
    };
    assert_eq!(fill.entry_action.as_deref(), Some("Open"));
    assert_eq!(fill.exit_action.as_deref(), Some("Close"));
    assert_eq!(fill.main_action, None);
    assert_eq!(fill.min_time.as_deref(), Some("T#1s"));
    assert_eq!(fill.max_time.as_deref(), Some("T#9s"));
    assert_eq!(fill.comment, "Fills the tank.");
}

#[test]
fn a_last_step_without_successor_stays_active_with_a_false_transition() {
    let objects = [
        step(1, "Start", true, None),
        transition(2, 1, &inline_st("go")),
        step(3, "Done", false, Some(2)),
    ]
    .join("\n");
    let imported = imported(&document(&objects, ""));
    assert_eq!(
        outline(&chart(pou(&imported, "Seq")).sequence),
        "S:Start T:go S:Done T:FALSE J:Done"
    );
}

#[test]
fn a_macro_step_holds_its_body() {
    let objects = [
        step(1, "Start", true, None),
        transition(2, 1, &inline_st("go")),
        format!(
            r#"<macroStep localId="3" name="Inner"><connectionPointIn><connection refLocalId="2"/></connectionPointIn><connectionPointOut/><body><SFC>{}{}{}</SFC></body></macroStep>"#,
            step(1, "In1", false, None),
            transition(2, 1, &inline_st("NOT go")),
            step(3, "In2", false, Some(2)),
        ),
        transition(4, 3, &inline_st("TRUE")),
        jump(5, 4, "Start"),
    ]
    .join("\n");
    let imported = imported(&document(&objects, ""));
    assert_eq!(
        outline(&chart(pou(&imported, "Seq")).sequence),
        "S:Start T:go M:Inner(S:In1 T:NOT go S:In2) T:TRUE J:Start"
    );
}

#[test]
fn a_chart_without_initial_step_or_with_two_is_refused_at_the_element() {
    let none = error(&document(
        &[
            step(1, "A", false, None),
            transition(2, 1, &inline_st("go")),
            jump(3, 2, "A"),
        ]
        .join("\n"),
        "",
    ));
    assert!(
        matches!(&*none.kind, ImportErrorKind::BadSfc(message) if message.contains("initialStep"))
    );
    assert_eq!(none.path, "project/types/pous/pou[@name='Seq']/body/SFC");
    let two = error(&document(
        &[step(1, "A", true, None), step(2, "B", true, None)].join("\n"),
        "",
    ));
    assert!(two.to_string().contains("`A` and `B`"), "{two}");
    assert!(
        two.path.ends_with("/SFC/step[@localId='2']"),
        "{}",
        two.path
    );
}

#[test]
fn a_transition_leading_nowhere_is_refused_with_its_line() {
    let text = document(
        &[step(1, "A", true, None), transition(2, 1, &inline_st("go"))].join("\n"),
        "",
    );
    let refused = error(&text);
    assert!(
        refused.path.ends_with("/SFC/transition[@localId='2']"),
        "{}",
        refused.path
    );
    assert!(refused.to_string().contains("leads nowhere"), "{refused}");
    assert_eq!(refused.file, "bad.xml");
    assert!(refused.line > 5);
}

#[test]
fn a_convergence_of_branches_of_different_divergences_is_refused() {
    // Two alternatives whose branches all meet at one convergence.
    let objects = [
        step(1, "A", true, None),
        r#"<selectionDivergence localId="2"><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut/><connectionPointOut/></selectionDivergence>"#.to_owned(),
        transition(3, 2, &inline_st("go")),
        transition(4, 2, &inline_st("NOT go")),
        step(5, "B", false, Some(3)),
        r#"<selectionDivergence localId="6"><connectionPointIn><connection refLocalId="5"/></connectionPointIn><connectionPointOut/><connectionPointOut/></selectionDivergence>"#.to_owned(),
        transition(7, 6, &inline_st("go")),
        transition(8, 6, &inline_st("NOT go")),
        r#"<selectionConvergence localId="9"><connectionPointIn><connection refLocalId="4"/></connectionPointIn><connectionPointIn><connection refLocalId="7"/></connectionPointIn><connectionPointIn><connection refLocalId="8"/></connectionPointIn><connectionPointOut/></selectionConvergence>"#.to_owned(),
        step(10, "C", false, Some(9)),
        transition(11, 10, &inline_st("TRUE")),
        jump(12, 11, "A"),
    ]
    .join("\n");
    let refused = error(&document(&objects, ""));
    assert!(
        refused.path.ends_with("selectionConvergence[@localId='9']"),
        "{refused}"
    );
}

/// A chain of `choices` choices: each step offers `go` to the next step and `stop` back to the
/// first, drawn as Beremiz draws it (no convergence).
fn chain_of_choices(choices: u64) -> String {
    let mut objects = vec![step(1, "S0", true, None)];
    let mut previous_step = 1;
    for index in 0..choices {
        let base = 10 + index * 10;
        objects.push(format!(
            r#"<selectionDivergence localId="{base}"><connectionPointIn><connection refLocalId="{previous_step}"/></connectionPointIn><connectionPointOut/><connectionPointOut/></selectionDivergence>"#
        ));
        objects.push(transition(base + 1, base, &inline_st("go")));
        objects.push(transition(base + 2, base, &inline_st("NOT go")));
        objects.push(jump(base + 3, base + 2, "S0"));
        objects.push(step(
            base + 4,
            &format!("S{}", index + 1),
            false,
            Some(base + 1),
        ));
        previous_step = base + 4;
    }
    objects.push(transition(5, previous_step, &inline_st("TRUE")));
    objects.push(jump(6, 5, "S0"));
    objects.join("\n")
}

#[test]
fn a_chain_of_choices_becomes_a_flat_sequence_and_a_too_deep_one_an_error() {
    let imported = imported(&document(&chain_of_choices(100), ""));
    let chart = chart(pou(&imported, "Seq"));
    // Step, alternative, step…: the last choice's two branches both end in jumps, so it holds
    // its step; the 99 before it are followed by theirs.
    assert_eq!(chart.sequence.len(), 100 * 2);
    assert!(project_model::sfc_problems(chart).is_empty());
    let refused = error(&document(&chain_of_choices(1001), ""));
    assert!(
        refused.to_string().contains("nest more than 1000"),
        "{refused}"
    );
}

/// A step `A` whose action block holds one inline action with `inline` (an `inline` element),
/// then a transition `go` and a jump back.
fn inline_action_chart(inline: &str) -> String {
    [
        step(1, "A", true, None),
        format!(
            r#"<actionBlock localId="9"><connectionPointIn><connection refLocalId="1"/></connectionPointIn><action localId="0">{inline}</action></actionBlock>"#
        ),
        transition(2, 1, &inline_st("go")),
        jump(3, 2, "A"),
    ]
    .join("\n")
}

/// The one action of `Seq` in `imported` (named `A_INLINE1_2`: the test's POU declares a
/// variable `A_INLINE1`).
fn inline_action(imported: &Imported) -> &project_model::PouAction {
    let seq = pou(imported, "Seq");
    let [action] = seq.actions.as_slice() else {
        panic!("{:?}\n{:#?}", seq.actions, imported.report)
    };
    assert_eq!(action.name, "A_INLINE1_2");
    action
}

/// An inline LD body: a contact `go` from a left rail drives the coil `A_INLINE1`.
const INLINE_LD: &str = r#"<inline><LD>
        <leftPowerRail localId="1"><position x="10" y="10"/><connectionPointOut formalParameter=""/></leftPowerRail>
        <contact localId="2"><position x="40" y="10"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut/><variable>go</variable></contact>
        <coil localId="3"><position x="90" y="10"/><connectionPointIn><connection refLocalId="2"/></connectionPointIn><connectionPointOut/><variable>A_INLINE1</variable></coil>
      </LD></inline>"#;

#[test]
fn inline_ld_fbd_and_il_actions_become_actions_in_their_language() {
    let ld = imported(&document(&inline_action_chart(INLINE_LD), ""));
    let Body::Ld { networks } = &inline_action(&ld).body else {
        panic!("{:?}", inline_action(&ld).body)
    };
    let [network] = networks.as_slice() else {
        panic!("{networks:?}")
    };
    assert!(
        matches!(network.rung.as_slice(), [project_model::FlowNode::Operand(go)] if go.text == "go"),
        "{network:?}"
    );
    assert!(
        matches!(network.outputs.as_slice(), [project_model::NetworkOutput::Coil(coil)] if coil.variable == "A_INLINE1"),
        "{network:?}"
    );
    let step = &chart(pou(&ld, "Seq")).sequence[0];
    assert!(
        matches!(step, SfcNode::Step(a) if a.actions[0].action == "A_INLINE1_2"),
        "{step:?}"
    );

    let fbd = r#"<inline><FBD>
        <inVariable localId="1"><position x="10" y="10"/><connectionPointOut/><expression>TRUE</expression></inVariable>
        <outVariable localId="2"><position x="60" y="10"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><expression>go</expression></outVariable>
      </FBD></inline>"#;
    let networks = imported(&document(&inline_action_chart(fbd), ""));
    assert!(
        matches!(&inline_action(&networks).body, Body::Fbd { networks } if networks.len() == 1),
        "{:?}",
        inline_action(&networks).body
    );

    let il = r#"<inline><IL><xhtml:p><![CDATA[LD go
ST A_INLINE1]]></xhtml:p></IL></inline>"#;
    let text = imported(&document(&inline_action_chart(il), ""));
    assert_eq!(
        inline_action(&text).body,
        Body::Il {
            text: "LD go\nST A_INLINE1".to_owned()
        }
    );
}

#[test]
fn an_inline_fbd_action_with_feedback_becomes_a_cfc_action_with_a_note() {
    // ADD reads its own output through a connector: no network holds that loop.
    let looped = r#"<inline><FBD>
        <inVariable localId="1"><position x="10" y="10"/><connectionPointOut/><expression>1</expression></inVariable>
        <continuation localId="2" name="loop"><position x="10" y="40"/><connectionPointOut/></continuation>
        <block localId="3" typeName="ADD"><position x="60" y="10"/>
          <inputVariables>
            <variable formalParameter="IN1"><connectionPointIn><connection refLocalId="1"/></connectionPointIn></variable>
            <variable formalParameter="IN2"><connectionPointIn><connection refLocalId="2"/></connectionPointIn></variable>
          </inputVariables><inOutVariables/>
          <outputVariables><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables>
        </block>
        <connector localId="4" name="loop"><position x="120" y="40"/><connectionPointIn><connection refLocalId="3" formalParameter="OUT"/></connectionPointIn></connector>
      </FBD></inline>"#;
    let imported = imported(&document(&inline_action_chart(looped), ""));
    assert!(
        matches!(&inline_action(&imported).body, Body::Cfc { chart } if chart.elements.len() == 4),
        "{:?}",
        inline_action(&imported).body
    );
    let note = imported
        .report
        .entry("FBD body of inline action of step 'A'");
    assert!(
        note.is_some_and(|entry| entry.note.contains("imported as a CFC chart")
            && entry
                .path
                .ends_with("/actionBlock[@localId='9']/action/inline")),
        "{note:?}"
    );
}

#[test]
fn a_wrong_inline_ld_action_is_an_error_at_its_object_inside_the_action() {
    // The coil has nothing before it.
    let dangling = INLINE_LD.replace(
        r#"<connectionPointIn><connection refLocalId="2"/></connectionPointIn><connectionPointOut/><variable>A_INLINE1"#,
        r#"<connectionPointOut/><variable>A_INLINE1"#,
    );
    assert_ne!(dangling, INLINE_LD);
    let refused = error(&document(&inline_action_chart(&dangling), ""));
    assert!(
        refused
            .path
            .ends_with("/body/SFC/actionBlock[@localId='9']/action/inline/LD/coil[@localId='3']"),
        "{}",
        refused.path
    );
    assert!(
        matches!(&*refused.kind, ImportErrorKind::Network(_)),
        "{refused}"
    );
}

/// A left rail, a contact `go` with `edge`, a coil `seen` and a contact `A_INLINE1` in series,
/// wired into the condition of the transition 2 (after step 1 `A`), then a jump back.
fn ld_wired_chart(edge: &str) -> String {
    [
        step(1, "A", true, None),
        r#"<leftPowerRail localId="10"><position x="10" y="100"/><connectionPointOut formalParameter=""/></leftPowerRail>"#.to_owned(),
        format!(
            r#"<contact localId="11"{edge}><position x="40" y="100"/><connectionPointIn><connection refLocalId="10"/></connectionPointIn><connectionPointOut/><variable>go</variable></contact>"#
        ),
        r#"<coil localId="12"><position x="80" y="100"/><connectionPointIn><connection refLocalId="11"/></connectionPointIn><connectionPointOut/><variable>seen</variable></coil>"#.to_owned(),
        r#"<contact localId="13"><position x="120" y="100"/><connectionPointIn><connection refLocalId="12"/></connectionPointIn><connectionPointOut/><variable>A_INLINE1</variable></contact>"#.to_owned(),
        r#"<transition localId="2"><position x="160" y="100"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut/><condition><connectionPointIn><connection refLocalId="13"/></connectionPointIn></condition></transition>"#.to_owned(),
        jump(3, 2, "A"),
    ]
    .join("\n")
}

#[test]
fn a_condition_wired_from_an_ld_graph_becomes_a_transition_object_of_ld_networks() {
    let imported = imported(&document(&ld_wired_chart(r#" edge="rising""#), ""));
    let seq = pou(&imported, "Seq");
    assert_eq!(
        outline(&chart(seq).sequence),
        "S:A T:A_CONDITION1 J:A",
        "{:#?}",
        imported.report
    );
    let [condition] = seq.transitions.as_slice() else {
        panic!("{:?}", seq.transitions)
    };
    assert_eq!(condition.name, "A_CONDITION1");
    let Body::Ld { networks } = &condition.body else {
        panic!("{:?}", condition.body)
    };
    // go (rising) and A_INLINE1 → the object's own name; the coil `seen` passes its power on
    // and writes nothing, as in Beremiz's generator.
    let [network] = networks.as_slice() else {
        panic!("{networks:?}")
    };
    assert!(
        matches!(network.rung.as_slice(), [project_model::FlowNode::Operand(go), project_model::FlowNode::Operand(and)]
            if go.text == "go" && go.edge == project_model::Edge::Rising && and.text == "A_INLINE1"),
        "{network:#?}"
    );
    assert!(
        matches!(network.outputs.as_slice(), [project_model::NetworkOutput::Coil(coil)] if coil.variable == "A_CONDITION1"),
        "{network:#?}"
    );
    assert!(project_model::network_problems(networks).is_empty());
    let coil = imported.report.entry("coil 'seen'");
    assert!(
        coil.is_some_and(|entry| entry.note.contains("writes nothing")
            && entry.path.ends_with("/body/SFC/coil[@localId='12']")),
        "{:#?}",
        imported.report
    );
    // The edge's trigger runs only when the transition is tested: the report says so.
    let note = imported.report.entry("condition 'A_CONDITION1'");
    assert!(
        note.is_some_and(|entry| entry.outcome == Outcome::Converted
            && entry
                .note
                .contains("0 function block instance(s) and 1 edge detection(s)")
            && entry.note.contains("when the transition is tested")),
        "{:#?}",
        imported.report
    );
    assert!(
        imported
            .report
            .with_outcome(Outcome::NotConverted)
            .all(|entry| !entry.path.contains("pou[@name='Seq']")),
        "{:#?}",
        imported.report
    );
    // A negated condition calls the object under NOT.
    let negated = ld_wired_chart(r#" edge="falling""#).replace(
        "<condition><connectionPointIn>",
        r#"<condition negated="true"><connectionPointIn>"#,
    );
    let imported = self::imported(&document(&negated, ""));
    assert_eq!(
        outline(&chart(pou(&imported, "Seq")).sequence),
        "S:A T:NOT A_CONDITION1() J:A"
    );
    // Without the edge, the coil passing its power on leaves contacts: an expression.
    let contacts = ld_wired_chart("").replace(
        "<condition><connectionPointIn>",
        r#"<condition negated="true"><connectionPointIn>"#,
    );
    let imported = self::imported(&document(&contacts, ""));
    let seq = pou(&imported, "Seq");
    assert_eq!(
        outline(&chart(seq).sequence),
        "S:A T:NOT (go AND A_INLINE1) J:A"
    );
    assert!(seq.transitions.is_empty(), "{:?}", seq.transitions);
    assert!(imported.report.entry("coil 'seen'").is_some());
}

#[test]
fn an_error_at_the_end_of_a_wired_ld_condition_names_the_condition() {
    // The condition reads a coil with nothing before it: the coil passes on no power, so the
    // import's own coil at the wire's end has nothing before it.
    let objects = [
        step(1, "A", true, None),
        r#"<coil localId="12"><position x="80" y="100"/><connectionPointOut/><variable>seen</variable></coil>"#.to_owned(),
        r#"<transition localId="2"><position x="160" y="100"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut/><condition><connectionPointIn><connection refLocalId="12"/></connectionPointIn></condition></transition>"#.to_owned(),
        jump(3, 2, "A"),
    ]
    .join("\n");
    let refused = error(&document(&objects, ""));
    assert!(
        refused
            .path
            .ends_with("/body/SFC/transition[@localId='2']/condition"),
        "{refused}"
    );
    assert!(
        matches!(&*refused.kind, ImportErrorKind::Network(_)),
        "{refused}"
    );
}

#[test]
fn a_block_instance_in_a_wired_ld_condition_is_counted_in_the_note() {
    // A contact `go` drives the EN of a TON `delay`, whose Q is the condition.
    let objects = [
        step(1, "A", true, None),
        r#"<leftPowerRail localId="10"><position x="10" y="100"/><connectionPointOut formalParameter=""/></leftPowerRail>"#.to_owned(),
        r#"<contact localId="11"><position x="40" y="100"/><connectionPointIn><connection refLocalId="10"/></connectionPointIn><connectionPointOut/><variable>go</variable></contact>"#.to_owned(),
        r#"<block localId="12" typeName="TON" instanceName="delay"><position x="80" y="100"/>
          <inputVariables>
            <variable formalParameter="IN"><connectionPointIn><connection refLocalId="11"/></connectionPointIn></variable>
            <variable formalParameter="PT"><connectionPointIn/></variable>
          </inputVariables><inOutVariables/>
          <outputVariables><variable formalParameter="Q"><connectionPointOut/></variable><variable formalParameter="ET"><connectionPointOut/></variable></outputVariables>
        </block>"#.to_owned(),
        r#"<transition localId="2"><position x="160" y="100"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut/><condition><connectionPointIn><connection refLocalId="12" formalParameter="Q"/></connectionPointIn></condition></transition>"#.to_owned(),
        jump(3, 2, "A"),
    ]
    .join("\n");
    let imported = imported(&document(&objects, ""));
    let note = imported.report.entry("condition 'A_CONDITION1'");
    assert!(
        note.is_some_and(|entry| entry
            .note
            .contains("1 function block instance(s) and 0 edge detection(s)")),
        "{:#?}",
        imported.report
    );
}

#[test]
fn an_inline_sfc_action_leaves_the_pou_not_converted_with_the_reason() {
    let sfc = format!(
        r#"<inline><SFC>{}</SFC></inline>"#,
        step(1, "Inner", true, None)
    );
    let imported = imported(&document(&inline_action_chart(&sfc), ""));
    let entry = imported.report.entry("POU 'Seq'");
    assert!(
        entry.is_some_and(|entry| entry.outcome == Outcome::NotConverted
            && entry.note.contains("is an SFC chart")
            && entry.note.contains("not inside an action")),
        "{entry:?}"
    );
}

#[test]
fn an_error_in_the_second_inline_action_of_a_block_names_the_action() {
    let dangling = INLINE_LD.replace(
        r#"<connectionPointIn><connection refLocalId="2"/></connectionPointIn><connectionPointOut/><variable>A_INLINE1"#,
        r#"<connectionPointOut/><variable>A_INLINE1"#,
    );
    let two = inline_action_chart(INLINE_LD).replace(
        "</action></actionBlock>",
        &format!(r#"</action><action localId="1">{dangling}</action></actionBlock>"#),
    );
    let refused = error(&document(&two, ""));
    assert!(
        refused.path.ends_with(
            "/body/SFC/actionBlock[@localId='9']/action[2]/inline/LD/coil[@localId='3']"
        ),
        "{}",
        refused.path
    );
}

#[test]
fn the_data_of_an_object_shared_by_two_conditions_is_reported_once() {
    // The contacts `go` (edge) and `A_INLINE1` feed both transitions out of `A`'s alternative;
    // the contact `go` carries another tool's entry.
    let entry =
        r#"<addData><data name="urn:other/x" handleUnknown="preserve"><x/></data></addData>"#;
    let objects = ld_wired_chart(r#" edge="rising""#)
        .replace(
            "<variable>go</variable></contact>",
            &format!("<variable>go</variable>{entry}</contact>"),
        )
        .replace(
            &jump(3, 2, "A"),
            &format!(
                "{}\n{}\n{}\n{}",
                r#"<selectionDivergence localId="20"><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut formalParameter=""/></selectionDivergence>"#,
                r#"<transition localId="21"><position x="300" y="100"/><connectionPointIn><connection refLocalId="20"/></connectionPointIn><connectionPointOut/><condition><connectionPointIn><connection refLocalId="13"/></connectionPointIn></condition></transition>"#,
                jump(3, 2, "A"),
                jump(22, 21, "A"),
            ),
        )
        .replace(
            r#"<transition localId="2"><position x="160" y="100"/><connectionPointIn><connection refLocalId="1"/>"#,
            r#"<transition localId="2"><position x="160" y="100"/><connectionPointIn><connection refLocalId="20"/>"#,
        );
    let imported = imported(&document(&objects, ""));
    let seq = pou(&imported, "Seq");
    assert_eq!(seq.transitions.len(), 2, "{:#?}", imported.report);
    let reported: Vec<_> = imported
        .report
        .entries
        .iter()
        .filter(|entry| entry.what == "addData 'urn:other/x'")
        .collect();
    assert_eq!(reported.len(), 1, "{reported:#?}");
}

#[test]
fn an_ld_condition_that_is_no_network_leaves_the_pou_not_converted_with_the_reason() {
    // A box whose value input is powered by the contact's power as well as its EN: a contact's
    // power that also drives a box's value input is no network (docs/plcopen-xml.md §3.6).
    let objects = [
        step(1, "A", true, None),
        r#"<leftPowerRail localId="10"><position x="10" y="100"/><connectionPointOut formalParameter=""/></leftPowerRail>"#.to_owned(),
        r#"<contact localId="11"><position x="40" y="100"/><connectionPointIn><connection refLocalId="10"/></connectionPointIn><connectionPointOut/><variable>go</variable></contact>"#.to_owned(),
        r#"<block localId="12" typeName="AND"><position x="80" y="100"/>
          <inputVariables>
            <variable formalParameter="EN"><connectionPointIn><connection refLocalId="11"/></connectionPointIn></variable>
            <variable formalParameter="IN1"><connectionPointIn><connection refLocalId="11"/></connectionPointIn></variable>
            <variable formalParameter="IN2"><connectionPointIn><connection refLocalId="11"/></connectionPointIn></variable>
          </inputVariables><inOutVariables/>
          <outputVariables><variable formalParameter="ENO"><connectionPointOut/></variable><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables>
        </block>"#.to_owned(),
        r#"<transition localId="2"><position x="160" y="100"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut/><condition><connectionPointIn><connection refLocalId="12" formalParameter="OUT"/></connectionPointIn></condition></transition>"#.to_owned(),
        jump(3, 2, "A"),
    ]
    .join("\n");
    let imported = imported(&document(&objects, ""));
    let entry = imported.report.entry("POU 'Seq'");
    assert!(
        entry.is_some_and(|entry| entry.outcome == Outcome::NotConverted
            && entry
                .note
                .contains("wired from an LD graph that cannot be converted")
            && entry.note.contains("not a set of networks")),
        "{entry:?}"
    );
}

#[test]
fn an_inline_il_condition_becomes_an_il_transition_object_and_an_inline_ld_one_is_reported() {
    let il = r#"<inline name=""><IL><xhtml:p><![CDATA[LD go
AND A_INLINE1]]></xhtml:p></IL></inline>"#;
    let objects = [
        step(1, "A", true, None),
        transition(2, 1, il),
        jump(3, 2, "A"),
    ]
    .join("\n");
    let imported = imported(&document(&objects, ""));
    let seq = pou(&imported, "Seq");
    assert_eq!(outline(&chart(seq).sequence), "S:A T:A_CONDITION1 J:A");
    assert_eq!(
        seq.transitions
            .iter()
            .map(|transition| (transition.name.as_str(), &transition.body))
            .collect::<Vec<_>>(),
        [(
            "A_CONDITION1",
            &Body::Il {
                text: "LD go\nAND A_INLINE1".to_owned()
            }
        )]
    );

    let ld = objects.replace(il, r#"<inline name=""><LD/></inline>"#);
    let reported = self::imported(&document(&ld, ""));
    let entry = reported.report.entry("POU 'Seq'");
    assert!(
        entry.is_some_and(|entry| entry.outcome == Outcome::NotConverted
            && entry.note.contains("no variable to write the condition to")),
        "{entry:?}"
    );
}

#[test]
fn ld_conditions_and_inline_ld_actions_come_back_from_the_plain_export() {
    let objects = ld_wired_chart(r#" edge="rising""#).replace(
        &step(1, "A", true, None),
        &format!(
            r#"{}<actionBlock localId="9"><connectionPointIn><connection refLocalId="1"/></connectionPointIn><action localId="0">{INLINE_LD}</action></actionBlock>"#,
            step(1, "A", true, None)
        ),
    );
    let first = imported(&document(&objects, ""));
    let options = crate::ExportOptions {
        object_entries: false,
    };
    let xml = crate::export_with(&first.project, options).unwrap_or_else(|error| panic!("{error}"));
    let document = crate::read_bytes(&xml, "plain.xml").unwrap_or_else(|error| panic!("{error}"));
    let again = import(&document).unwrap_or_else(|error| panic!("{error}"));
    let seq = pou(&first, "Seq");
    assert_eq!(seq.actions.len(), 1, "{:?}", seq.actions);
    assert_eq!(seq.transitions.len(), 1, "{:?}", seq.transitions);
    assert_eq!(pou(&again, "Seq"), seq);
}
