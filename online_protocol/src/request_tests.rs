use proptest::prelude::*;

use super::*;
use crate::Status;

fn place(region: u8, offset: u32, bit: Option<u8>, size: u16) -> Place {
    Place {
        region,
        offset,
        bit,
        size,
    }
}

fn every_request() -> Vec<Request> {
    let a = place(0, 16, None, 4);
    let b = place(2, 3, Some(5), 1);
    vec![
        Request::Identify {
            protocol: crate::PROTOCOL_VERSION,
        },
        Request::Login {
            password: "sésame".to_owned(),
        },
        Request::Logout,
        Request::DownloadBegin {
            token: 7,
            size: 1000,
            hash: [9; 32],
        },
        Request::DownloadChunk {
            token: 7,
            transfer: 2,
            offset: 240,
            bytes: vec![1, 2, 3],
        },
        Request::DownloadCommit {
            token: 7,
            transfer: 2,
            start: true,
        },
        Request::DownloadAbort {
            token: 7,
            transfer: 2,
        },
        Request::OnlineChangeCheck {
            token: 7,
            transfer: 2,
        },
        Request::OnlineChangeDetails {
            token: 7,
            transfer: 2,
            from: 10,
        },
        Request::OnlineChangeApply {
            token: 7,
            transfer: 2,
        },
        Request::Start { token: 1 },
        Request::Stop { token: 1 },
        Request::Reset {
            token: 1,
            kind: ResetKind::Origin,
        },
        Request::Resolve {
            path: "Main.a[3].x".to_owned(),
        },
        Request::Read { places: vec![a, b] },
        Request::Write {
            token: 3,
            values: vec![(a, vec![1, 2, 3, 4]), (b, vec![1])],
        },
        Request::Force {
            token: 3,
            values: vec![(b, vec![0])],
        },
        Request::Unforce {
            token: 3,
            places: vec![],
        },
        Request::Forces { from: 4 },
        Request::TraceConfigure {
            token: 3,
            config: TraceConfig {
                task: 1,
                every: 2,
                samples: 100,
                pretrigger: 25,
                trigger: TriggerKind::Falling,
                trigger_place: b,
                places: vec![a, b],
            },
        },
        Request::TraceArm { token: 3 },
        Request::TraceStatus,
        Request::TraceUpload { from: 17 },
        Request::Tasks,
        Request::Faults { from: 2 },
        Request::ModbusDevices { from: 3 },
        Request::TraceAdd {
            token: 3,
            places: vec![a],
        },
        Request::Enumeration {
            path: "Main.colour".to_owned(),
            from: 2,
        },
    ]
    .into_iter()
    .chain(crate::debug_request::tests::every_debug_request())
    .collect()
}

/// The `TRACE_CONFIGURE` of [`every_request`].
fn configure() -> Vec<u8> {
    every_request()
        .into_iter()
        .find(|request| request.service() == Service::TraceConfigure)
        .map(|request| request.encode())
        .unwrap_or_default()
}

#[test]
fn every_request_survives_encoding_and_parsing() {
    for request in every_request() {
        let bytes = request.encode();
        assert_eq!(Request::decode(&bytes), Ok(request));
    }
}

#[test]
fn every_service_has_an_example_request() {
    let services: Vec<Service> = every_request().iter().map(Request::service).collect();
    for service in Service::ALL {
        assert!(services.contains(&service), "{service:?}");
    }
}

#[test]
fn a_request_is_its_service_number_then_its_fields_in_the_documented_order() {
    let read = Request::Read {
        places: vec![place(2, 0x0102_0304, Some(5), 1)],
    };
    assert_eq!(read.encode(), [0x31, 1, 2, 4, 3, 2, 1, 5, 1, 0]);
    let reset = Request::Reset {
        token: 0x0A0B_0C0D,
        kind: ResetKind::Cold,
    };
    let mut expected = vec![0x22, 0x0D, 0x0C, 0x0B, 0x0A];
    expected.extend([0; 12]);
    expected.push(1);
    assert_eq!(
        reset.encode(),
        expected,
        "a token is 16 bytes, little-endian"
    );
    assert_eq!(
        Request::ModbusDevices { from: 7 }.encode(),
        [0x52, 7],
        "MODBUS_DEVICES carries one byte, the first device to list, and no token"
    );
    let whole = place(0, 0, None, 4);
    let mut bytes = Vec::new();
    whole.encode(&mut bytes);
    assert_eq!(bytes[5], 0xFF, "a place without a bit sends 0xFF");
}

#[test]
fn a_truncated_or_extended_request_is_a_bad_request() {
    for request in every_request() {
        let bytes = request.encode();
        // A chunk's data is the rest of the request: cutting it leaves a valid chunk.
        if !matches!(request, Request::DownloadChunk { .. }) {
            for end in 1..bytes.len() {
                let status = Request::decode(&bytes[..end]).map_err(|e| e.status());
                assert!(
                    matches!(status, Err(Status::BadRequest | Status::BadPlace)),
                    "{request:?} cut to {end} bytes: {status:?}"
                );
            }
            let mut longer = bytes.clone();
            longer.push(0);
            let status = Request::decode(&longer).map_err(|e| e.status());
            assert_eq!(
                status,
                Err(Status::BadRequest),
                "{request:?} with one more byte"
            );
        }
    }
}

#[test]
fn an_unknown_service_and_fields_out_of_range_are_refused() {
    assert_eq!(
        Request::decode(&[0x7F]).map_err(|e| e.status()),
        Err(Status::UnknownService)
    );
    let mut configure = configure();
    configure[25] = 9; // The trigger kind.
    assert_eq!(
        Request::decode(&configure).map_err(|e| e.status()),
        Err(Status::BadRequest)
    );
    let login = [0x02, 2, 0xFF, 0xFE];
    assert_eq!(
        Request::decode(&login).map_err(|e| e.status()),
        Err(Status::BadRequest)
    );
}

#[test]
fn an_empty_frame_is_an_error_of_its_own() {
    assert_eq!(Request::decode(&[]), Err(DecodeError::Empty));
}

#[test]
fn a_truncated_request_names_the_field_and_the_byte_where_it_ends() {
    let start = Request::Start { token: 1 }.encode();
    assert_eq!(
        Request::decode(&start[..3]),
        Err(DecodeError::TooShort {
            field: "token",
            at: 1,
            needed: 16,
            left: 2
        })
    );
}

#[test]
fn bytes_after_the_last_field_are_named_with_their_position() {
    let mut stop = Request::Stop { token: 1 }.encode();
    stop.extend_from_slice(&[0, 0]);
    assert_eq!(
        Request::decode(&stop),
        Err(DecodeError::LeftOver { at: 17, count: 2 })
    );
}

#[test]
fn a_trigger_out_of_range_is_named_at_its_byte() {
    let mut configure = configure();
    configure[25] = 9;
    assert_eq!(
        Request::decode(&configure),
        Err(DecodeError::OutOfRange {
            field: "trigger",
            at: 25,
            value: 9,
            expected: "0 to 3"
        })
    );
}

#[test]
fn a_trace_sampling_every_zero_cycles_or_keeping_more_than_all_before_the_trigger_is_refused() {
    let mut never = configure();
    never[18] = 0; // `every`, little-endian u16 at bytes 18 and 19.
    never[19] = 0;
    assert!(matches!(
        Request::decode(&never),
        Err(DecodeError::OutOfRange {
            field: "every",
            at: 18,
            ..
        })
    ));
    let mut too_much = configure();
    too_much[24] = 101; // `pretrigger`.
    assert!(matches!(
        Request::decode(&too_much),
        Err(DecodeError::OutOfRange {
            field: "pretrigger",
            at: 24,
            ..
        })
    ));
}

#[test]
fn a_reset_kind_out_of_range_is_a_bad_request() {
    let mut reset = Request::Reset {
        token: 0,
        kind: ResetKind::Warm,
    }
    .encode();
    reset[17] = 3;
    let error = Request::decode(&reset).unwrap_err();
    assert_eq!(error.status(), Status::BadRequest);
    assert!(error.to_string().contains("reset kind"), "{error}");
}

#[test]
fn a_password_that_is_not_utf8_is_named_as_such() {
    assert_eq!(
        Request::decode(&[0x02, 2, 0xFF, 0xFE]),
        Err(DecodeError::NotUtf8 {
            field: "password",
            at: 1
        })
    );
}

#[test]
fn a_value_longer_than_the_rest_of_the_frame_is_a_bad_place() {
    let mut write = Request::Write {
        token: 0,
        values: vec![(place(0, 0, None, 4), vec![1, 2, 3, 4])],
    }
    .encode();
    write.truncate(write.len() - 1);
    let error = Request::decode(&write).unwrap_err();
    assert_eq!(
        error,
        DecodeError::ValueTooLong {
            at: 26,
            size: 4,
            left: 3
        }
    );
    assert_eq!(error.status(), Status::BadPlace);
}

#[test]
fn only_a_start_byte_of_1_starts_after_loading() {
    let mut commit = Request::DownloadCommit {
        token: 0,
        transfer: 1,
        start: true,
    }
    .encode();
    commit[19] = 2;
    assert!(matches!(
        Request::decode(&commit),
        Ok(Request::DownloadCommit { start: false, .. })
    ));
}

proptest! {
    #[test]
    fn every_request_decodes_to_itself(request in crate::arb::request()) {
        prop_assert_eq!(Request::decode(&request.encode()), Ok(request));
    }

    #[test]
    fn any_bytes_parse_or_are_refused_without_a_panic(
        frame in proptest::collection::vec(any::<u8>(), 0..260),
    ) {
        if let Ok(request) = Request::decode(&frame) {
            prop_assert_eq!(Request::decode(&request.encode()), Ok(request));
        }
    }
}

#[test]
fn every_enum_lists_its_values_in_the_order_of_their_wire_numbers() {
    // `Reader::choice` decodes these enums by their index in `ALL`.
    for (index, kind) in ResetKind::ALL.iter().enumerate() {
        assert_eq!(*kind as usize, index);
    }
    for (index, trigger) in TriggerKind::ALL.iter().enumerate() {
        assert_eq!(*trigger as usize, index);
    }
    for (index, state) in crate::TargetState::ALL.iter().enumerate() {
        assert_eq!(*state as usize, index);
    }
    for (index, state) in crate::TraceState::ALL.iter().enumerate() {
        assert_eq!(*state as usize, index);
    }
}
