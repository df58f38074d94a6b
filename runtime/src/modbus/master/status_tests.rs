//! A device's counters, state line and status bytes through failures and recovery.

use super::*;

#[test]
fn counters_follow_failures_and_the_state_line_is_written_only_on_a_change() {
    let mut status = DeviceStatus::new("BeltDrive", false);
    assert_eq!(status.encode()[2], error_codes::NOT_YET_POLLED);
    assert_eq!(status.snapshot().since_last_error_ms, None);
    status.request(Outcome::Success, Duration::from_micros(300), "");
    assert_eq!(
        status.end_round(0).as_deref(),
        Some("rivet-runtime: Modbus device 'BeltDrive': communicating")
    );
    assert_eq!(status.end_round(0), None);
    status.request(
        Outcome::Unanswered(error_codes::RESPONSE_TIMEOUT),
        Duration::ZERO,
        "no answer from 127.0.0.1:5502 within 100 ms",
    );
    status.not_sent(2, error_codes::RESPONSE_TIMEOUT, "");
    assert_eq!(
        status.end_round(3).as_deref(),
        Some(
            "rivet-runtime: Modbus device 'BeltDrive': no answer from 127.0.0.1:5502 within 100 ms; reconnecting"
        )
    );
    let bytes = status.encode();
    assert_eq!(
        (bytes[0], bytes[1], bytes[2]),
        (0, 1, error_codes::RESPONSE_TIMEOUT)
    );
    assert_eq!(
        u32::from_le_bytes([bytes[4], bytes[5], bytes[6], bytes[7]]),
        3
    );
    assert_eq!(
        u32::from_le_bytes([bytes[12], bytes[13], bytes[14], bytes[15]]),
        3
    );
    assert_eq!(
        u32::from_le_bytes([bytes[16], bytes[17], bytes[18], bytes[19]]),
        3
    );
    assert_eq!(
        u32::from_le_bytes([bytes[20], bytes[21], bytes[22], bytes[23]]),
        3
    );
    let report = status.snapshot();
    assert_eq!(report.state, DeviceState::NotAnswering);
    assert_eq!(
        (report.last_error, report.consecutive_errors, report.errors),
        (error_codes::RESPONSE_TIMEOUT, 3, 3)
    );
    assert!(report.since_last_error_ms.is_some());
    assert_eq!(report.detail, "no answer from 127.0.0.1:5502 within 100 ms");
    // An exception is an answer: connected, with an error, and the code kept afterwards.
    status.request(Outcome::Exception(2), Duration::ZERO, "exception 2");
    assert_eq!(status.state, DeviceState::NotAnswering);
    status.end_round(0);
    assert_eq!(status.state, DeviceState::AnsweringWithErrors);
    status.request(Outcome::Success, Duration::ZERO, "");
    assert!(
        status
            .end_round(0)
            .is_some_and(|line| line.ends_with("answering again"))
    );
    let bytes = status.encode();
    assert_eq!((bytes[0], bytes[1], bytes[2], bytes[3]), (1, 0, 2, 2));
    assert_eq!(bytes[4], 0);
}

#[test]
fn a_failure_long_ago_never_reads_as_none_yet() {
    use std::time::Duration;
    assert_eq!(since_last_error_ms(Duration::from_millis(1500)), 1500);
    let max = u64::from(u32::MAX);
    assert_eq!(
        since_last_error_ms(Duration::from_millis(max - 1)),
        u32::MAX - 1
    );
    // Exactly u32::MAX ms, and beyond: held one below "none yet".
    assert_eq!(
        since_last_error_ms(Duration::from_millis(max)),
        u32::MAX - 1
    );
    assert_eq!(
        since_last_error_ms(Duration::from_millis(max * 2)),
        u32::MAX - 1
    );
}
