use proptest::prelude::*;

use super::*;
use crate::online::place::NO_BIT;

fn place(region: u8, offset: u32, bit: u8, size: u16) -> WirePlace {
    WirePlace {
        region,
        offset,
        bit,
        size,
    }
}

fn every_request() -> Vec<Request> {
    let a = place(0, 16, NO_BIT, 4);
    let b = place(2, 3, 5, 1);
    vec![
        Request::Identify { protocol: 1 },
        Request::Login {
            password: "sésame".to_owned(),
        },
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
        Request::Start { token: 1 },
        Request::Stop { token: 1 },
        Request::Reset { token: 1, kind: 2 },
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
    ]
}

#[test]
fn every_request_survives_encoding_and_parsing() {
    for request in every_request() {
        let bytes = request.encode();
        assert_eq!(parse_request(bytes[0], &bytes[1..]), Ok(request));
    }
}

#[test]
fn a_truncated_or_extended_request_is_a_bad_request() {
    for request in every_request() {
        let bytes = request.encode();
        // A chunk's data is the rest of the request: cutting it leaves a valid chunk.
        if !matches!(request, Request::DownloadChunk { .. }) {
            for end in 1..bytes.len() {
                let status = parse_request(bytes[0], &bytes[1..end]).map_err(|r| r.status);
                assert!(
                    matches!(status, Err(Status::BadRequest | Status::BadPlace)),
                    "{request:?} cut to {end} bytes: {status:?}"
                );
            }
            let mut longer = bytes.clone();
            longer.push(0);
            let status = parse_request(longer[0], &longer[1..]).map_err(|r| r.status);
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
        parse_request(0x7F, &[]).map_err(|r| r.status),
        Err(Status::UnknownService)
    );
    let mut configure = every_request()[15].encode();
    configure[13] = 9; // The trigger kind.
    assert_eq!(
        parse_request(configure[0], &configure[1..]).map_err(|r| r.status),
        Err(Status::BadRequest)
    );
    let login = [0x02, 2, 0xFF, 0xFE];
    assert_eq!(
        parse_request(login[0], &login[1..]).map_err(|r| r.status),
        Err(Status::BadRequest)
    );
}

#[test]
fn a_refusal_carries_its_status_and_a_message_that_fits() {
    let body = refused(
        0x31,
        &Refusal {
            status: Status::BadPlace,
            message: "é".repeat(300),
        },
    );
    assert_eq!(&body[..2], &[0x31, 5]);
    assert_eq!(usize::from(body[2]), body.len() - 3);
    assert!(body.len() <= MAX_PAYLOAD_BYTES + 2);
    assert!(std::str::from_utf8(&body[3..]).is_ok());
}

proptest! {
    #[test]
    fn any_bytes_parse_or_are_refused_without_a_panic(
        service in any::<u8>(),
        payload in proptest::collection::vec(any::<u8>(), 0..260),
    ) {
        let _ = parse_request(service, &payload);
    }
}
