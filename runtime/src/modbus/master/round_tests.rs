//! The checks of a response against its request (`docs/modbus-master.md` §6.6).

use super::*;

fn code(result: Result<Answer, (u8, String)>) -> Option<u8> {
    result.err().map(|(code, _)| code)
}

#[test]
fn counts_echoes_and_functions_are_checked_and_a_wrong_unit_is_named() {
    let read = Request::ReadHoldingRegisters(5, 3);
    let short = Response::ReadHoldingRegisters(vec![1, 2]);
    assert_eq!(
        code(check(&read, short, 5, 3)),
        Some(error_codes::RESPONSE_INVALID_DATA)
    );
    let right = Response::ReadHoldingRegisters(vec![1, 2, 3]);
    assert!(
        matches!(check(&read, right, 5, 3), Ok(Answer::Registers(words)) if words == [1, 2, 3])
    );
    let other = Response::ReadInputRegisters(vec![1, 2, 3]);
    assert_eq!(
        code(check(&read, other, 5, 3)),
        Some(error_codes::RESPONSE_WRONG_FUNCTIONCODE)
    );
    // Ten coils come as two whole bytes; one byte is too few.
    let coils = Request::ReadCoils(0, 10);
    let bits = Response::ReadCoils(vec![true; 16]);
    assert!(matches!(check(&coils, bits, 0, 10), Ok(Answer::Bits(bits)) if bits.len() == 10));
    let byte = Response::ReadCoils(vec![true; 8]);
    assert_eq!(
        code(check(&coils, byte, 0, 10)),
        Some(error_codes::RESPONSE_INVALID_DATA)
    );
    let write = Request::WriteMultipleRegisters(7, Cow::Owned(vec![1, 2]));
    let echoed = Response::WriteMultipleRegisters(8, 2);
    assert_eq!(
        code(check(&write, echoed, 7, 2)),
        Some(error_codes::RESPONSE_INVALID_DATA)
    );
    let single = Request::WriteSingleRegister(7, 99);
    let value = Response::WriteSingleRegister(7, 98);
    assert_eq!(
        code(check(&single, value, 7, 1)),
        Some(error_codes::RESPONSE_INVALID_DATA)
    );
    let value = Response::WriteSingleRegister(7, 99);
    assert!(matches!(check(&single, value, 7, 1), Ok(Answer::Written)));

    assert!(unit_ids_differ(
        "expected/request = Header { transaction_id: 4, unit_id: 1 }, actual/response = Header { transaction_id: 4, unit_id: 2 }"
    ));
    assert!(!unit_ids_differ(
        "expected/request = Header { transaction_id: 4, unit_id: 1 }, actual/response = Header { transaction_id: 5, unit_id: 1 }"
    ));
    assert!(unit_ids_differ(
        "expected/request = Header { slave_id: 1 }, actual/response = Header { slave_id: 3 }"
    ));
}

#[test]
fn an_rtu_request_s_sending_time_is_its_frame_s_bytes_at_eleven_bits_each() {
    // A read is 8 bytes: unit, function, address, count, CRC.
    let read = Request::ReadHoldingRegisters(0, 10);
    assert_eq!(rtu_frame_bytes(&read), 8);
    assert_eq!(rtu_frame_bytes(&Request::WriteSingleCoil(3, true)), 8);
    // Writes of many carry a byte count and their data: 10 coils in 2 bytes, 3 registers in 6.
    let coils = Request::WriteMultipleCoils(0, Cow::Owned(vec![true; 10]));
    assert_eq!(rtu_frame_bytes(&coils), 11);
    let words = Request::WriteMultipleRegisters(0, Cow::Owned(vec![1, 2, 3]));
    assert_eq!(rtu_frame_bytes(&words), 15);
    // 8 bytes × 11 bits at 9600 baud: 88 / 9600 s = 9166.67 µs, rounded up.
    assert_eq!(rtu_send_time(8, 9600), Duration::from_micros(9167));
    // 15 bytes at 19200 baud: 165 / 19200 s = 8593.75 µs.
    assert_eq!(rtu_send_time(15, 19200), Duration::from_micros(8594));
    // Exact at 110 baud: 10 bytes take one second.
    assert_eq!(rtu_send_time(10, 110), Duration::from_secs(1));
}
