use std::time::Duration;

use proptest::prelude::*;

use super::*;
use crate::areas::LocatedAreas;
use crate::scheduler::SchedulerOptions;
use crate::test_images::{TestTask, image};

fn services(password: Option<&str>, loaded: bool) -> OnlineServices {
    let areas = Arc::new(Mutex::new(LocatedAreas::default()));
    let scheduler = Scheduler::spawn(areas, SchedulerOptions::default()).unwrap();
    if loaded {
        scheduler
            .load(image(&[TestTask::cyclic(10_000_000, 1)], &[]))
            .unwrap();
    }
    OnlineServices::new(Arc::new(scheduler), password.map(str::to_owned))
}

/// The status and payload of the answer to `request`.
fn ask(services: &OnlineServices, request: &Request) -> (u8, Vec<u8>) {
    let body = services.respond(&request.encode()).unwrap();
    assert_eq!(body[0], request.service().number());
    (body[1], body[2..].to_vec())
}

/// The decoded answer to `request`.
fn answer(services: &OnlineServices, request: &Request) -> online_protocol::Answer {
    Response::decode(request, &services.respond(&request.encode()).unwrap()).unwrap()
}

/// The status and payload of the answer to `request` from Modbus connection `connection`.
fn ask_from(services: &OnlineServices, connection: u64, request: &Request) -> (u8, Vec<u8>) {
    let body = services
        .respond_from(Some(connection), &request.encode())
        .unwrap();
    assert_eq!(body[0], request.service().number());
    (body[1], body[2..].to_vec())
}

/// The token of a successful `LOGIN` answer.
fn token_of((status, payload): (u8, Vec<u8>)) -> u128 {
    assert_eq!(status, 0);
    u128::from_le_bytes(payload.try_into().unwrap())
}

fn login_with(password: &str) -> Request {
    Request::Login {
        password: password.to_owned(),
    }
}

#[test]
fn changing_services_need_a_token_from_the_password_and_reading_ones_do_not() {
    let services = services(Some("secret"), true);
    let (status, identity) = ask(
        &services,
        &Request::Identify {
            protocol: PROTOCOL_VERSION,
        },
    );
    assert_eq!(status, 0);
    // The password byte, then version 3's debug byte: debugging is on, no session (0).
    assert_eq!(identity[identity.len() - 2], 1, "a password is required");
    assert_eq!(
        identity.last(),
        Some(&0),
        "debugging is on without a session"
    );
    assert_eq!(ask(&services, &Request::Start { token: 0 }).0, 3);
    assert_eq!(ask(&services, &Request::Start { token: 1234 }).0, 4);
    assert_eq!(ask(&services, &login_with("guess")).0, 4);
    // A wrong password locks nobody out: the right one is checked at once.
    let token = token_of(ask(&services, &login_with("secret")));
    assert_ne!(token, 0);
    assert_eq!(ask(&services, &Request::Start { token }), (0, vec![2]));
    assert_eq!(ask(&services, &Request::Stop { token }), (0, vec![1]));
    assert_eq!(ask(&services, &Request::Tasks).0, 0);
}

#[test]
fn a_wrong_password_holds_every_connection_of_its_address_and_no_other_address() {
    let services = services(Some("secret"), false);
    let guesser = IpAddr::from([10, 0, 0, 1]);
    let other = IpAddr::from([10, 0, 0, 2]);
    let start = Instant::now();
    // The status of a LOGIN from `connection` of `peer`, `ms` after the start.
    let login = |connection: u64, peer: IpAddr, ms: u64, password: &str| {
        let request = login_with(password).encode();
        let at = start + Duration::from_millis(ms);
        services
            .respond_at(Some(connection), Some(peer), at, &request)
            .unwrap()[1]
    };
    let (wrong, not_now) = (Status::WrongPassword as u8, Status::NotNow as u8);
    assert_eq!(login(1, guesser, 0, "guess"), wrong);
    // For 500 ms no password of the address is checked, on any of its connections, not even
    // the right one; another address logs in at once.
    assert_eq!(login(2, guesser, 100, "secret"), not_now);
    assert_eq!(login(3, other, 100, "secret"), 0);
    // Then it is checked again; a second wrong password in a row holds the address 1 s.
    assert_eq!(login(2, guesser, 500, "guess again"), wrong);
    assert_eq!(login(1, guesser, 1499, "secret"), not_now);
    assert_eq!(login(1, guesser, 1500, "secret"), 0);
    // The right password forgets the address's wrong ones: the next wrong one holds 500 ms.
    assert_eq!(login(1, guesser, 1500, "guess"), wrong);
    assert_eq!(login(2, guesser, 2000, "secret"), 0);
}

#[test]
fn a_token_is_valid_only_on_the_connection_that_logged_in_and_until_it_closes() {
    let services = Arc::new(services(Some("secret"), true));
    let first = token_of(ask_from(&services, 1, &login_with("secret")));
    assert_eq!(ask_from(&services, 1, &Request::Stop { token: first }).0, 0);
    // Seen on the wire and sent from another connection, it is refused.
    assert_eq!(ask_from(&services, 2, &Request::Stop { token: first }).0, 4);
    // Logging in again replaces the token.
    let second = token_of(ask_from(&services, 1, &login_with("secret")));
    assert_ne!(first, second);
    assert_eq!(ask_from(&services, 1, &Request::Stop { token: first }).0, 4);
    assert_eq!(
        ask_from(&services, 1, &Request::Stop { token: second }).0,
        0
    );
    let other = token_of(ask_from(&services, 2, &login_with("secret")));
    // Logging out ends the token of that connection only.
    let third = token_of(ask_from(&services, 3, &login_with("secret")));
    assert_eq!(ask_from(&services, 3, &Request::Logout), (0, vec![]));
    assert_eq!(ask_from(&services, 3, &Request::Stop { token: third }).0, 4);
    // When the connection closes (also after its idle timeout), its token ends.
    (services.closed_handler())(1);
    assert_eq!(
        ask_from(&services, 1, &Request::Stop { token: second }).0,
        4
    );
    assert_eq!(ask_from(&services, 2, &Request::Stop { token: other }).0, 0);
    assert_eq!(lock(&services.tokens).len(), 1);
}

#[test]
fn tokens_are_128_random_bits() {
    let services = services(Some("secret"), false);
    let tokens: Vec<u128> = (0..64)
        .map(|connection| token_of(ask_from(&services, connection, &login_with("secret"))))
        .collect();
    let mut distinct = tokens.clone();
    distinct.sort_unstable();
    distinct.dedup();
    assert_eq!(distinct.len(), tokens.len());
    // Every bit is used: 64 tokens of 128 random bits set each bit somewhere, and clear it
    // somewhere (a u32 widened, or a counter, would not).
    let ones = tokens.iter().fold(0u128, |bits, token| bits | token);
    let zeros = tokens.iter().fold(0u128, |bits, token| bits | !token);
    assert_eq!(ones, u128::MAX);
    assert_eq!(zeros, u128::MAX);
}

#[test]
fn another_protocol_version_is_refused_with_both_versions() {
    let services = services(None, false);
    let (status, message) = ask(&services, &Request::Identify { protocol: 7 });
    assert_eq!(status, 9);
    let message = String::from_utf8(message[1..].to_vec()).unwrap();
    assert!(
        message.contains("version 7") && message.contains(&format!("version {PROTOCOL_VERSION}")),
        "{message}"
    );
}

#[test]
fn without_a_program_the_services_that_need_one_say_not_now() {
    let services = services(None, false);
    let place = Place {
        region: 0,
        offset: 0,
        bit: None,
        size: 1,
    };
    assert_eq!(ask(&services, &Request::Start { token: 0 }).0, 7);
    assert_eq!(
        ask(
            &services,
            &Request::Read {
                places: vec![place]
            }
        )
        .0,
        7
    );
    assert_eq!(
        ask(
            &services,
            &Request::Resolve {
                path: "Main.x".to_owned()
            }
        )
        .0,
        7
    );
    let (status, identity) = ask(
        &services,
        &Request::Identify {
            protocol: PROTOCOL_VERSION,
        },
    );
    assert_eq!(status, 0);
    assert!(identity.contains(&0) && identity.ends_with(&[0, 0, 0]));
}

#[test]
fn a_place_outside_its_region_is_refused_and_nothing_is_written() {
    let services = services(None, true);
    let inside = Place {
        region: 0,
        offset: 0,
        bit: None,
        size: 4,
    };
    let outside = Place {
        offset: 1 << 20,
        ..inside
    };
    let write = Request::Write {
        token: 0,
        values: vec![(inside, vec![1, 2, 3, 4]), (outside, vec![0; 4])],
    };
    assert_eq!(ask(&services, &write).0, 5);
    let (status, read) = ask(
        &services,
        &Request::Read {
            places: vec![inside],
        },
    );
    assert_eq!(status, 0);
    assert_eq!(&read[9..], &[0, 0, 0, 0]);
    let bad_bit = Place {
        region: 3,
        offset: 0,
        bit: Some(8),
        size: 1,
    };
    assert_eq!(
        ask(
            &services,
            &Request::Read {
                places: vec![bad_bit]
            }
        )
        .0,
        5
    );
}

#[test]
fn an_empty_request_is_exception_3() {
    let services = services(None, false);
    assert_eq!(services.respond(&[]), Err(ExceptionCode::IllegalDataValue));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]
    #[test]
    fn any_request_gets_an_answer_that_fits_without_a_panic(
        request in proptest::collection::vec(any::<u8>(), 1..252),
    ) {
        let services = services(None, true);
        let body = services.respond(&request).unwrap();
        prop_assert!(body.len() <= MAX_PAYLOAD_BYTES + 2);
        prop_assert_eq!(body[0], request[0]);
    }
}

#[test]
fn an_enumeration_resolves_as_one_and_lists_its_values_page_by_page() {
    let mut with_enum = image(&[TestTask::cyclic(10_000_000, 1)], &[]);
    let values: Vec<(String, i64)> = (0..40)
        .map(|index| (format!("VALUE_NUMBER_{index:02}"), index * 3 - 50))
        .collect();
    with_enum.types.push(TypeDef::Enum {
        name: "Many".to_owned(),
        base: program_image::Elementary::Int,
        values: values.clone(),
    });
    with_enum.symbols.push(program_image::Symbol {
        path: "Choice".to_owned(),
        ty: (with_enum.types.len() - 1) as u32,
        region: Region::Memory,
        offset: 0,
        bit: None,
        flags: program_image::SymbolFlags(program_image::SymbolFlags::GLOBAL),
    });
    let areas = Arc::new(Mutex::new(LocatedAreas::default()));
    let scheduler = Scheduler::spawn(areas, SchedulerOptions::default()).unwrap();
    scheduler.load(with_enum).unwrap();
    let services = OnlineServices::new(Arc::new(scheduler), None);

    let resolve = Request::Resolve {
        path: "Choice".to_owned(),
    };
    match answer(&services, &resolve) {
        Ok(Response::Resolve(resolved)) => assert_eq!(resolved.type_tag, TYPE_ENUM),
        other => panic!("{other:?}"),
    }
    // The values come in pages that each fit a response; asking from where one ended gives
    // the next, and together they are the type's values in order.
    let mut listed = Vec::new();
    let mut pages = 0;
    while listed.len() < values.len() {
        let request = Request::Enumeration {
            path: "Choice".to_owned(),
            from: listed.len() as u16,
        };
        assert!(ask(&services, &request).1.len() <= MAX_PAYLOAD_BYTES);
        match answer(&services, &request) {
            Ok(Response::Enumeration {
                base,
                total,
                values: page,
            }) => {
                assert_eq!((base, total), (program_image::Elementary::Int as u8, 40));
                assert!(!page.is_empty());
                listed.extend(page);
            }
            other => panic!("{other:?}"),
        }
        pages += 1;
    }
    assert_eq!(listed, values);
    assert!(pages > 1, "40 values take more than one response");

    let not_an_enum = Request::Enumeration {
        path: "Trigger".to_owned(),
        from: 0,
    };
    assert_eq!(ask(&services, &not_an_enum).0, 2);
    let unknown = Request::Enumeration {
        path: "Nothing".to_owned(),
        from: 0,
    };
    assert_eq!(ask(&services, &unknown).0, 6);
}

#[test]
fn modbus_devices_lists_nothing_without_a_program_or_without_runtime_devices() {
    // A program with no Modbus master section, and no program at all: both answer total 0
    // (docs/modbus-master.md §9.1), and without a password.
    for loaded in [false, true] {
        let services = services(Some("secret"), loaded);
        match answer(&services, &Request::ModbusDevices { from: 0 }) {
            Ok(Response::ModbusDevices { total, devices }) => {
                assert_eq!(total, 0, "loaded: {loaded}");
                assert!(devices.is_empty());
            }
            other => panic!("loaded: {loaded}: {other:?}"),
        }
    }
}
