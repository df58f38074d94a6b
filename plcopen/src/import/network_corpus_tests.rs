//! The LD and FBD bodies of the corpora converted into networks.

use project_model::{Body, Network, Object};

use super::converter::{Converter, Place};
use super::network_import::NetworkOutcome;
use super::network_tests::rendered;
use super::{Imported, Outcome, import};
use crate::reader::corpus_tests::read_corpus;

fn import_corpus(relative: &str) -> Imported {
    let document = read_corpus(relative);
    import(&document).unwrap_or_else(|error| panic!("{error}"))
}

#[track_caller]
fn networks<'i>(imported: &'i Imported, name: &str) -> &'i [Network] {
    match imported.project.application.object(name) {
        Some(Object::Pou(pou)) => match &pou.body {
            Body::Ld { networks } | Body::Fbd { networks } => networks,
            other => panic!("{name}: {other:?}"),
        },
        other => panic!("{name}: {other:?}"),
    }
}

const FIRST_STEPS: &str = "plcopen/beremiz/exemples/first_steps/plc.xml";

#[test]
fn first_steps_counters_in_ld_and_fbd_write_the_counter_and_its_output() {
    let imported = import_corpus(FIRST_STEPS);
    // The inOutVariable Cnt is written by SEL and read by ADD before the write.
    assert_eq!(
        rendered(networks(&imported, "CounterLD")),
        ["Reset SEL(G; IN0=1 ADD(IN1; IN2=Cnt); IN1=ResetCounterValue) -> Out, Cnt"]
    );
    assert_eq!(
        rendered(networks(&imported, "CounterFBD")),
        ["Reset SEL(G; IN0=1 ADD(IN1; IN2=Cnt); IN1=ResetCounterValue) -> OUT, Cnt"]
    );
}

#[test]
fn first_steps_program_runs_its_counters_before_the_average_that_reads_them() {
    let imported = import_corpus(FIRST_STEPS);
    let networks = networks(&imported, "plc_prg");
    assert_eq!(
        rendered(networks),
        [
            "Reset CounterFBD[CounterFBD0](Reset) -> Cnt2",
            "Reset CounterSFC[CounterSFC0](Reset) -> Cnt3",
            "Reset CounterIL[CounterIL0](Reset) -> Cnt4",
            "Reset CounterLD[CounterLD0](Reset) -> Cnt5",
            "Reset CounterST[CounterST0](Reset) -> {AverageVal(Cnt1; Cnt2=Cnt2; Cnt3=Cnt3; Cnt4=Cnt4; Cnt5=Cnt5) -> AVCnt}, Cnt1",
        ]
    );
    assert!(networks[0].comment.contains("all five IEC 61131-3"));
    assert_eq!(
        imported
            .report
            .entry("POU 'plc_prg'")
            .map(|entry| entry.outcome),
        Some(Outcome::Converted)
    );
}

#[test]
fn language_test_reads_instance_outputs_wired_to_several_boxes_as_variables() {
    let imported = import_corpus("plcopen/beremiz/tests/projects/iec61131_lang_test/plc.xml");
    let rendered = rendered(networks(&imported, "main_test"));
    // CONVERSION_TEST0's ENO drives two boxes: two branches of the power.
    assert_eq!(
        rendered,
        [
            "TRUE R_TRIG[R_TRIG0](CLK) CONVERSION_TEST[CONVERSION_TEST0](EN) -> {AND(IN1; IN2=CONVERSION_TEST0.RESULT EQ(IN1; IN2='OK')) SR[SR1](S1; R) AND(IN1; IN2=TRUE TEMPO_TEST[TEMPO_TEST0](RUN) AND(IN1; IN2=TEMPO_TEST0.RESULT EQ(IN1; IN2='OK')) SR[SR0](S1; R)) LOGGER[LOGGER2](TRIG; MSG='ALL TESTS OK'; LEVEL=DEBUG)}, {LOGGER[LOGGER0](TRIG; MSG='CONVERSION: ' CONCAT(IN1; IN2=CONVERSION_TEST0.RESULT); LEVEL=DEBUG)}",
            "TEMPO_TEST0.VALID LOGGER[LOGGER1](TRIG; MSG='TEMPO: ' CONCAT(IN1; IN2=TEMPO_TEST0.RESULT); LEVEL=DEBUG)",
        ]
    );
    // SUB's result, not its ENO, feeds the next box: a graph for a CFC chart.
    let tempo = imported.report.entry("FBD body of POU 'TEMPO_TEST'");
    assert!(
        tempo.is_some_and(|entry| entry.outcome == Outcome::Converted
            && entry
                .note
                .contains("the output OUT of the function SUB drives another element")),
        "{tempo:?}"
    );
}

#[test]
fn codesys_boxes_without_positions_assign_their_output_expressions() {
    let imported = import_corpus("plcopen/codesys/codesys_code_execution_speedTests.xml");
    // CODESYS writes a contact TRUE before a box's EN, and the box's result as an expression.
    assert_eq!(
        rendered(networks(&imported, "addTwoIntsLadder")),
        ["TRUE ADD(EN; In2=Int1; In3=Int2) Out2:=addTwoIntsLadder"]
    );
    assert_eq!(
        rendered(networks(&imported, "addTwoIntsFBD")),
        ["int1 ADD(In1; In2=int2) -> addTwoIntsFBD"]
    );
}

#[test]
fn matiec_empty_ld_body_has_no_networks() {
    let imported = import_corpus("matiec/tests/LD_TEST.xml");
    assert!(networks(&imported, "MAIN_TEST").is_empty());
}

#[test]
fn matiec_string_tests_convert_and_a_function_read_twice_is_left_for_a_chart() {
    let imported = import_corpus("matiec/tests/STD_TEST.xml");
    assert_eq!(
        rendered(networks(&imported, "TEST_FROM_STRINGS"))[0],
        "-> {TESTNR -> NEXT_TEST}, {0 LIMIT(MN; IN=TESTNR; MX=3) -> {MUX(K; IN0=IN1 LEN(IN); IN1=IN1 EQ(IN1; IN2=IN2); IN2=IN2 EQ(IN1; IN2=IN2); IN3=IN1 FIND(IN1; IN2=IN2)) -> INTRES}, {MUX(K; IN0='LEN'; IN1='EQ(IN1,IN2)'; IN2='EQ(IN2,IN2)'; IN3='FIND') -> TEST_NAME}}"
    );
    let entry = imported.report.entry("FBD body of POU 'TEST_TO_STRINGS'");
    assert!(
        entry.is_some_and(|entry| entry
            .note
            .contains("the value of the block with local id 2 drives more than one input")),
        "{entry:?}"
    );
}

/// Every LD and FBD body of a POU, action, transition or method of `document`, with its name.
fn network_bodies(document: &crate::Document) -> Vec<(String, &crate::Body)> {
    let mut found: Vec<(String, &crate::Body)> = Vec::new();
    for pou in &document.pous {
        found.extend(pou.bodies.iter().map(|body| (pou.name.clone(), body)));
        found.extend(
            pou.actions
                .iter()
                .map(|action| (format!("{}.{}", pou.name, action.name), &action.body)),
        );
        found.extend(pou.transitions.iter().map(|transition| {
            (
                format!("{}.{}", pou.name, transition.name),
                &transition.body,
            )
        }));
        for method in &pou.methods {
            found.extend(
                method
                    .bodies
                    .iter()
                    .map(|body| (format!("{}.{}", pou.name, method.name), body)),
            );
        }
    }
    found.retain(|(_, body)| {
        body.cfc.is_none()
            && matches!(
                body.content,
                crate::BodyContent::Ld(_) | crate::BodyContent::Fbd(_)
            )
    });
    found
}

#[test]
fn every_ld_and_fbd_body_of_the_corpora_converts_or_is_left_for_a_chart() {
    let mut converted = 0;
    for file in [
        FIRST_STEPS,
        "plcopen/beremiz/tests/projects/iec61131_lang_test/plc.xml",
        "plcopen/beremiz/tests/projects/svghmi_basic/plc.xml",
        "plcopen/codesys/codesys_code_execution_speedTests.xml",
        "matiec/tests/LD_TEST.xml",
        "matiec/tests/STD_TEST.xml",
    ] {
        let document = read_corpus(file);
        let mut converter = Converter::new(&document);
        for (what, body) in network_bodies(&document) {
            let place = Place {
                path: what.clone(),
                line: body.line,
                column: 1,
            };
            match converter.networks(body, &place, &what) {
                Ok(Some(NetworkOutcome::Networks(networks, _))) => {
                    assert!(
                        project_model::network_problems(&networks).is_empty(),
                        "{file}: {what}"
                    );
                    converted += 1;
                }
                Ok(Some(NetworkOutcome::NotANetwork { reason })) => {
                    assert!(
                        ["TEMPO_TEST", "TEST_TO_STRINGS"]
                            .iter()
                            .any(|expected| what.starts_with(expected)),
                        "{file}: {what}: {reason}"
                    );
                }
                Ok(None) => panic!("{file}: {what} is not LD or FBD"),
                Err(error) => panic!("{file}: {what}: {error}"),
            }
        }
    }
    // first_steps 3, iec61131_lang_test 1, svghmi_basic 3 (its program and two actions of its
    // SFC block), CODESYS 2, LD_TEST 1, STD_TEST 3.
    assert_eq!(converted, 13);
}
