use proptest::prelude::*;

use super::*;
use crate::arb::request_of;
use crate::framing::MAX_PAYLOAD_BYTES;

#[test]
fn a_refusal_carries_its_status_and_a_message_that_fits() {
    let body = Refusal {
        status: Status::BadPlace,
        message: "é".repeat(300),
    }
    .encode(0x31);
    assert_eq!(&body[..2], &[0x31, 5]);
    assert_eq!(usize::from(body[2]), body.len() - 3);
    assert!(body.len() <= MAX_PAYLOAD_BYTES + 2);
    assert!(std::str::from_utf8(&body[3..]).is_ok());
}

#[test]
fn an_answer_is_its_service_status_0_then_its_fields() {
    let stop = Response::Stop {
        state: TargetState::Stopped,
    };
    assert_eq!(stop.encode(), [0x21, 0, 1]);
    let status = Response::TraceStatus(TraceStatus {
        state: TraceState::Armed,
        recorded: 3,
        trigger_sample: None,
    });
    assert_eq!(
        status.encode(),
        [0x42, 0, 2, 3, 0, 0, 0, 0xFF, 0xFF, 0xFF, 0xFF]
    );
}

#[test]
fn an_enumeration_answer_is_its_base_total_count_then_names_and_values() {
    let answer = Response::Enumeration {
        base: 2,
        total: 3,
        values: vec![("RED".to_owned(), -1), ("GREEN".to_owned(), 300)],
    };
    let mut expected = vec![0x36, 0, 2, 3, 0, 2, 3];
    expected.extend_from_slice(b"RED");
    expected.extend_from_slice(&(-1i64).to_le_bytes());
    expected.push(5);
    expected.extend_from_slice(b"GREEN");
    expected.extend_from_slice(&300i64.to_le_bytes());
    assert_eq!(answer.encode(), expected);
    let request = Request::Enumeration {
        path: "Main.light".to_owned(),
        from: 1,
    };
    assert_eq!(request.encode()[..2], [0x36, 10]);
    assert_eq!(Response::decode(&request, &expected), Ok(Ok(answer)));
}

#[test]
fn a_read_answer_has_one_forced_bit_per_place_least_significant_first() {
    let places = vec![
        Place {
            region: 0,
            offset: 0,
            bit: None,
            size: 2,
        };
        9
    ];
    let values = (0..9).map(|i| (vec![i, 0], i == 1 || i == 8)).collect();
    let read = Response::Read(Snapshot { cycle: 7, values });
    let body = read.encode();
    assert_eq!(&body[10..12], &[0b10, 0b1]);
    let request = Request::Read { places };
    assert_eq!(Response::decode(&request, &body), Ok(Ok(read)));
}

#[test]
fn an_answer_for_another_service_is_an_error() {
    let body = Response::Start {
        state: TargetState::Running,
    }
    .encode();
    assert_eq!(
        Response::decode(&request_of(Service::Stop), &body),
        Err(DecodeError::OtherService {
            expected: 0x21,
            found: 0x20
        })
    );
}

#[test]
fn a_status_that_version_1_does_not_have_is_an_error() {
    assert_eq!(
        Response::decode(&request_of(Service::Tasks), &[0x50, 10, 0]),
        Err(DecodeError::UnknownStatus(10))
    );
}

#[test]
fn a_refusal_without_its_message_is_too_short() {
    assert!(matches!(
        Response::decode(&request_of(Service::Tasks), &[0x50, 7]),
        Err(DecodeError::TooShort {
            field: "message",
            at: 2,
            ..
        })
    ));
}

#[test]
fn a_truncated_answer_names_the_field_where_it_ends() {
    let body = Response::Login { token: 5 }.encode();
    assert_eq!(
        Response::decode(&request_of(Service::Login), &body[..4]),
        Err(DecodeError::TooShort {
            field: "token",
            at: 2,
            needed: 16,
            left: 2
        })
    );
}

#[test]
fn an_answer_with_bytes_left_over_is_an_error() {
    let mut body = Response::Write.encode();
    body.push(0);
    assert_eq!(
        Response::decode(&request_of(Service::Write), &body),
        Err(DecodeError::LeftOver { at: 2, count: 1 })
    );
}

#[test]
fn a_state_out_of_range_is_named_at_its_byte() {
    assert_eq!(
        Response::decode(&request_of(Service::Start), &[0x20, 0, 4]),
        Err(DecodeError::OutOfRange {
            field: "state",
            at: 2,
            value: 4,
            expected: "0 to 3"
        })
    );
}

#[test]
fn trace_samples_that_cannot_share_one_size_are_an_error() {
    // Two samples in 33 bytes: not two samples of one size.
    let mut body = vec![0x43, 0, 2];
    body.extend_from_slice(&[0; 33]);
    assert_eq!(
        Response::decode(&request_of(Service::TraceUpload), &body),
        Err(DecodeError::UnevenSamples {
            at: 3,
            count: 2,
            bytes: 33
        })
    );
    // One sample shorter than its cycle and time.
    let body = [0x43, 0, 1, 0, 0, 0];
    assert!(matches!(
        Response::decode(&request_of(Service::TraceUpload), &body),
        Err(DecodeError::UnevenSamples { .. })
    ));
}

#[test]
fn a_zero_hash_means_no_program() {
    let identity = Identity {
        protocol: crate::PROTOCOL_VERSION,
        runtime_version: "0.1.0".to_owned(),
        state: TargetState::NoProgram,
        image_hash: None,
        project: String::new(),
        password_required: false,
        debug: DebugStatus::default(),
    };
    let body = Response::Identify(identity).encode();
    assert_eq!(&body[11..43], &[0; 32]);
}

proptest! {
    #[test]
    fn every_response_decodes_to_itself((request, response) in crate::arb::response()) {
        prop_assert_eq!(Response::decode(&request, &response.encode()), Ok(Ok(response)));
    }

    #[test]
    fn every_refusal_decodes_to_itself(
        refusal in crate::arb::refusal(),
        request in crate::arb::request(),
    ) {
        let body = refusal.encode(request.service().number());
        prop_assert_eq!(Response::decode(&request, &body), Ok(Err(refusal)));
    }

    #[test]
    fn any_bytes_decode_as_an_answer_or_an_error_without_a_panic(
        request in crate::arb::request(),
        body in proptest::collection::vec(any::<u8>(), 0..260),
    ) {
        let _ = Response::decode(&request, &body);
    }
}

#[test]
fn identify_of_version_3_ends_with_the_debug_byte() {
    let identity = Identity {
        protocol: crate::PROTOCOL_VERSION,
        runtime_version: String::new(),
        state: TargetState::Running,
        image_hash: None,
        project: String::new(),
        password_required: false,
        debug: DebugStatus {
            session: true,
            halted: true,
            lingering: false,
            switched_off: true,
        },
    };
    let body = Response::Identify(identity.clone()).encode();
    assert_eq!(body.last(), Some(&0b1011));
    let request = request_of(Service::Identify);
    assert_eq!(
        Response::decode(&request, &body),
        Ok(Ok(Response::Identify(identity)))
    );
    assert!(matches!(
        Response::decode(&request, &body[..body.len() - 1]),
        Err(DecodeError::TooShort { field: "debug", .. })
    ));
}

#[test]
fn a_frame_read_answer_has_the_bytes_of_its_request_ranges() {
    use crate::{DebugRequest, DebugResponse, FrameRange};
    let request = Request::Debug(DebugRequest::FrameRead {
        task: 0,
        frame: 0,
        ranges: vec![
            FrameRange { offset: 0, size: 2 },
            FrameRange { offset: 8, size: 1 },
        ],
    });
    let body = [0x6B, 0, 1, 2, 3];
    assert_eq!(
        Response::decode(&request, &body),
        Ok(Ok(Response::Debug(DebugResponse::FrameRead {
            bytes: vec![1, 2, 3]
        })))
    );
    assert!(matches!(
        Response::decode(&request, &body[..4]),
        Err(DecodeError::TooShort { .. })
    ));
    assert!(matches!(
        Response::decode(&request, &[0x6B, 0, 1, 2, 3, 4]),
        Err(DecodeError::LeftOver { at: 5, count: 1 })
    ));
}

#[test]
fn a_truncated_or_extended_debugging_answer_is_an_error() {
    use proptest::strategy::{Strategy, ValueTree};
    use proptest::test_runner::TestRunner;
    let mut runner = TestRunner::deterministic();
    for _ in 0..200 {
        let (request, response) = crate::debug_arb::response()
            .new_tree(&mut runner)
            .map(|tree| tree.current())
            .unwrap_or_else(|error| panic!("{error}"));
        let body = response.encode();
        for end in 0..body.len() {
            assert!(
                Response::decode(&request, &body[..end]).is_err(),
                "{response:?} cut to {end} bytes"
            );
        }
        let mut longer = body;
        longer.push(0);
        assert!(
            Response::decode(&request, &longer).is_err(),
            "{response:?} with one more byte"
        );
    }
}

#[test]
fn a_halt_state_entry_names_no_breakpoint_with_0xffff() {
    use crate::{
        DebugOptions, DebugResponse, HaltReason, HaltState, SessionState, TaskDebugState, TaskHalt,
    };
    let state = HaltState {
        session: SessionState::Lingering,
        options: DebugOptions::default(),
        generation: 7,
        total: 1,
        tasks: vec![TaskHalt {
            task: 0,
            state: TaskDebugState::Halted,
            reason: HaltReason::Halt,
            breakpoint: None,
            pou: 1,
            instruction: 2,
            depth: 1,
            cycle: 10,
            halted_ms: 5,
        }],
    };
    let body = Response::Debug(DebugResponse::HaltState(state)).encode();
    assert_eq!(
        body.len(),
        2 + crate::HALT_STATE_HEADER_BYTES + crate::HALT_ENTRY_BYTES
    );
    assert_eq!(&body[2 + 8 + 3..2 + 8 + 5], &[0xFF, 0xFF]);
}
