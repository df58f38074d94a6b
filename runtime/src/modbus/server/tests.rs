use super::*;
use crate::modbus::ModbusMap;

fn responder(custom: Option<CustomFunctions>) -> Responder {
    Responder {
        areas: Arc::new(Mutex::new(LocatedAreas::new(2, 2, 2))),
        map: MapSlot::new(ModbusMap::default()),
        custom,
    }
}

fn echo_hook() -> CustomFunctions {
    Arc::new(|function, data| match function {
        0x41 => Ok(data.iter().rev().copied().collect()),
        0x42 => Err(ExceptionCode::IllegalDataValue),
        0x43 => Ok(vec![0; MAX_PDU_BYTES]),
        _ => Err(ExceptionCode::IllegalFunction),
    })
}

#[test]
fn without_a_hook_custom_function_codes_are_illegal() {
    let responder = responder(None);
    assert_eq!(responder.respond(&[0x41, 1, 2]), [0xc1, 1]);
    assert_eq!(responder.respond(&[3, 0, 0, 0, 1]), [3, 2, 0, 0]);
}

#[test]
fn a_hook_answers_the_function_codes_the_areas_do_not_serve() {
    let responder = responder(Some(echo_hook()));
    assert_eq!(responder.respond(&[0x41, 1, 2, 3]), [0x41, 3, 2, 1]);
    assert_eq!(responder.respond(&[0x42]), [0xc2, 3]);
    assert_eq!(responder.respond(&[0x07]), [0x87, 1]);
    // The standard codes never reach the hook, nor do codes with the exception bit set.
    assert_eq!(
        responder.respond(&[6, 0, 0, 0x12, 0x34]),
        [6, 0, 0, 0x12, 0x34]
    );
    assert_eq!(responder.respond(&[0xc1, 1]), [0xc1, 1]);
    assert_eq!(responder.respond(&[]), [0x80, 1]);
}

#[test]
fn a_hook_answer_too_long_for_a_frame_is_a_device_failure() {
    let responder = responder(Some(echo_hook()));
    assert_eq!(responder.respond(&[0x43]), [0xc3, 4]);
}

#[test]
fn areas_poisoned_by_a_panic_give_device_failures() {
    let responder = responder(None);
    let areas = Arc::clone(&responder.areas);
    let _ = std::thread::spawn(move || {
        let _guard = areas.lock();
        panic!("the engine fails while it holds the areas");
    })
    .join();
    assert_eq!(responder.respond(&[3, 0, 0, 0, 1]), [0x83, 4]);
}

#[test]
fn accept_errors_of_one_connection_are_transient() {
    assert!(is_transient(&io::Error::from(
        io::ErrorKind::ConnectionAborted
    )));
    assert!(is_transient(&io::Error::from_raw_os_error(24)));
    assert!(!is_transient(&io::Error::from(io::ErrorKind::InvalidInput)));
}

#[test]
fn default_options_take_64_clients_and_no_hook() {
    let options = ServerOptions::default();
    assert_eq!(options.max_clients, 64);
    assert!(options.custom.is_none());
    let with_hook = ServerOptions {
        custom: Some(echo_hook()),
        ..ServerOptions::default()
    };
    assert_eq!(
        format!("{with_hook:?}"),
        r#"ServerOptions { max_clients: 64, custom: Some("Fn(u8, &[u8])"), closed: None }"#
    );
}
