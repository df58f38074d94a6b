use super::*;
use crate::{ALL_TASKS, MAX_CONDITION_BYTES, MAX_PAYLOAD_BYTES, Request, Status};

/// One request of every debugging service, each with its lists filled.
pub(crate) fn every_debug_request() -> Vec<Request> {
    let breakpoint = BreakpointSpec {
        pou: 3,
        instruction: 17,
        instance: 1 << 56 | 0x40,
        task: ALL_TASKS,
        hit: HitRule {
            mode: HitMode::Multiple,
            target: 5,
        },
        condition: vec![1, 2, 3],
    };
    [
        DebugRequest::Attach {
            token: 9,
            linger_s: 60,
            options: DebugOptions {
                halt_all_on_halt: true,
            },
        },
        DebugRequest::Detach { token: 9 },
        DebugRequest::BreakSet {
            token: 9,
            breakpoint,
        },
        DebugRequest::BreakClear {
            token: 9,
            id: crate::ALL_BREAKPOINTS,
        },
        DebugRequest::BreakList { from: 8 },
        DebugRequest::HaltState { from: 1 },
        DebugRequest::Step {
            token: 9,
            task: 1,
            kind: StepKind::Out,
        },
        DebugRequest::RunTo {
            token: 9,
            task: 0,
            pou: 2,
            instruction: 40,
        },
        DebugRequest::Continue {
            token: 9,
            task: ALL_TASKS,
        },
        DebugRequest::Halt { token: 9, task: 2 },
        DebugRequest::Stack { task: 1, from: 10 },
        DebugRequest::FrameRead {
            task: 1,
            frame: 2,
            ranges: vec![
                FrameRange { offset: 0, size: 4 },
                FrameRange { offset: 8, size: 2 },
            ],
        },
        DebugRequest::FrameWrite {
            token: 9,
            task: 1,
            frame: crate::WHOLE_STACK,
            values: vec![(FrameRange { offset: 4, size: 2 }, vec![7, 8])],
        },
        DebugRequest::FlowConfigure {
            token: 9,
            task: 0,
            entries: vec![FlowEntry {
                pou: 4,
                instance: 0,
            }],
        },
        DebugRequest::FlowRead {
            entry: 0,
            which: FlowCycle::Current,
            from: 16,
        },
    ]
    .into_iter()
    .map(Request::Debug)
    .collect()
}

fn decode_status(bytes: &[u8]) -> Result<Request, Status> {
    Request::decode(bytes).map_err(|error| error.status())
}

#[test]
fn a_breakpoint_is_its_place_filters_hit_rule_and_condition_in_the_documented_order() {
    let bytes = every_debug_request()[2].encode();
    let mut expected = vec![0x62, 9];
    expected.extend([0; 15]);
    expected.extend([3, 0, 0, 0, 17, 0, 0, 0]);
    expected.extend([0x40, 0, 0, 0, 0, 0, 0, 1]);
    expected.extend([0xFF, 2, 5, 0, 0, 0, 3, 1, 2, 3]);
    assert_eq!(bytes, expected);
}

#[test]
fn the_longest_condition_fills_a_break_set_payload_exactly() {
    let Request::Debug(DebugRequest::BreakSet { breakpoint, .. }) = &every_debug_request()[2]
    else {
        panic!("the third example is a BREAK_SET");
    };
    let request = Request::Debug(DebugRequest::BreakSet {
        token: 1,
        breakpoint: BreakpointSpec {
            condition: vec![0; MAX_CONDITION_BYTES],
            ..breakpoint.clone()
        },
    });
    let bytes = request.encode();
    assert_eq!(MAX_CONDITION_BYTES, 211);
    assert_eq!(bytes.len() - 1, MAX_PAYLOAD_BYTES);
    assert_eq!(Request::decode(&bytes), Ok(request));
}

#[test]
fn a_condition_longer_than_its_frame_is_too_short() {
    let mut bytes = every_debug_request()[2].encode();
    let length_at = bytes.len() - 4;
    bytes[length_at] = 4;
    assert!(matches!(
        Request::decode(&bytes),
        Err(DecodeError::TooShort {
            field: "condition",
            needed: 4,
            left: 3,
            ..
        })
    ));
}

#[test]
fn a_hit_target_of_zero_is_refused_except_for_always() {
    let bytes = every_debug_request()[2].encode();
    let target_at = 1 + 16 + 4 + 4 + 8 + 1 + 1;
    let mut zero = bytes.clone();
    zero[target_at] = 0;
    assert_eq!(
        Request::decode(&zero),
        Err(DecodeError::OutOfRange {
            field: "hit target",
            at: target_at,
            value: 0,
            expected: "at least 1 for hit modes 1 to 3",
        })
    );
    let mut always = zero.clone();
    always[target_at - 1] = 0;
    assert!(decode_status(&always).is_ok());
    let mut mode = bytes;
    mode[target_at - 1] = 4;
    assert_eq!(decode_status(&mode), Err(Status::BadRequest));
}

#[test]
fn a_linger_above_300_seconds_and_unknown_options_are_bad_requests() {
    let attach = every_debug_request()[0].encode();
    let mut linger = attach.clone();
    linger[17..19].copy_from_slice(&301u16.to_le_bytes());
    assert!(matches!(
        Request::decode(&linger),
        Err(DecodeError::OutOfRange {
            field: "linger",
            value: 301,
            ..
        })
    ));
    linger[17..19].copy_from_slice(&300u16.to_le_bytes());
    assert!(decode_status(&linger).is_ok());
    let mut options = attach;
    options[19] = 2;
    assert_eq!(decode_status(&options), Err(Status::BadRequest));
}

#[test]
fn more_than_eight_flow_entries_and_a_flow_start_off_a_byte_are_refused() {
    let configure = Request::Debug(DebugRequest::FlowConfigure {
        token: 0,
        task: 0,
        entries: vec![
            FlowEntry {
                pou: 0,
                instance: 0
            };
            9
        ],
    });
    assert!(matches!(
        Request::decode(&configure.encode()),
        Err(DecodeError::OutOfRange {
            field: "count",
            at: 18,
            value: 9,
            ..
        })
    ));
    let mut read = every_debug_request()[14].encode();
    read[3] = 17;
    assert!(matches!(
        Request::decode(&read),
        Err(DecodeError::OutOfRange {
            field: "from",
            at: 3,
            value: 17,
            ..
        })
    ));
}

#[test]
fn a_frame_value_longer_than_the_rest_of_the_frame_is_a_bad_request() {
    let mut write = every_debug_request()[12].encode();
    write.pop();
    assert!(matches!(
        Request::decode(&write),
        Err(DecodeError::TooShort {
            field: "frame value",
            needed: 2,
            left: 1,
            ..
        })
    ));
}

#[test]
fn only_changing_debugging_services_carry_a_token() {
    for request in every_debug_request() {
        let Request::Debug(debug) = &request else {
            continue;
        };
        let read_only = matches!(
            debug,
            DebugRequest::BreakList { .. }
                | DebugRequest::HaltState { .. }
                | DebugRequest::Stack { .. }
                | DebugRequest::FrameRead { .. }
                | DebugRequest::FlowRead { .. }
        );
        assert_eq!(request.token().is_none(), read_only, "{request:?}");
    }
}

#[test]
fn every_debugging_enum_lists_its_values_in_the_order_of_their_wire_numbers() {
    for (index, mode) in HitMode::ALL.iter().enumerate() {
        assert_eq!(*mode as usize, index);
    }
    for (index, kind) in StepKind::ALL.iter().enumerate() {
        assert_eq!(*kind as usize, index);
    }
    for (index, which) in FlowCycle::ALL.iter().enumerate() {
        assert_eq!(*which as usize, index);
    }
    for (index, state) in crate::SessionState::ALL.iter().enumerate() {
        assert_eq!(*state as usize, index);
    }
    for (index, state) in crate::TaskDebugState::ALL.iter().enumerate() {
        assert_eq!(*state as usize, index);
    }
    for (index, reason) in crate::HaltReason::ALL.iter().enumerate() {
        assert_eq!(*reason as usize, index);
    }
}

#[test]
fn hit_rules_halt_at_the_counts_their_mode_names() {
    let rule = |mode, target| HitRule { mode, target };
    assert!(HitRule::ALWAYS.halts_at(1));
    assert!(rule(HitMode::Equal, 3).halts_at(3));
    assert!(!rule(HitMode::Equal, 3).halts_at(4));
    assert!(rule(HitMode::Multiple, 3).halts_at(6));
    assert!(!rule(HitMode::Multiple, 3).halts_at(7));
    assert!(!rule(HitMode::Multiple, 0).halts_at(7));
    assert!(rule(HitMode::AtLeast, 3).halts_at(4));
    assert!(!rule(HitMode::AtLeast, 3).halts_at(2));
}
