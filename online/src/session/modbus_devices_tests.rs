//! The session's `MODBUS_DEVICES` question against a small fake runtime on loopback: the
//! reports, an older runtime's unknown service and a refusal each come back as an answer, and
//! none of them ends the connection, since the studio asks every second; a question that
//! waits for a connection is dropped rather than failed.

#![allow(clippy::unwrap_used, clippy::expect_used)] // A panic is a failed test.

use std::sync::{Arc, Mutex};
use std::time::Duration;

use online_protocol::{
    ModbusDeviceReport, ModbusDeviceState, Refusal, Request, Status, modbus_devices_page,
};
use tokio::sync::mpsc;

use super::{Command, Event, ModbusDevicesAnswer, SessionOptions, spawn};

fn meter() -> ModbusDeviceReport {
    ModbusDeviceReport {
        name: "Meter".to_owned(),
        state: ModbusDeviceState::NotAnswering,
        last_error: 0xA5,
        last_exception: 0,
        consecutive_errors: 3,
        requests: 10,
        errors: 3,
        rounds: 10,
        overruns: 0,
        last_response_us: 700,
        since_last_error_ms: Some(40),
        detail: "connection refused by 127.0.0.1:5502".to_owned(),
    }
}

/// The next event, waiting at most five seconds.
async fn next(events: &mut mpsc::Receiver<Event>) -> Event {
    tokio::time::timeout(Duration::from_secs(5), events.recv())
        .await
        .expect("an event within five seconds")
        .expect("the session runs")
}

#[tokio::test]
async fn reports_an_unknown_service_and_a_refusal_are_answers_and_the_session_stays_connected() {
    // The fake answers the first question with a report, the second as an older runtime, the
    // third with a refusal.
    let asked = Arc::new(Mutex::new(0usize));
    let counter = Arc::clone(&asked);
    let address = crate::fake_target::serve_requests(move |request| {
        let Request::ModbusDevices { from } = request else {
            panic!("the fake runtime got {request:?}");
        };
        let mut asked = counter.lock().unwrap();
        *asked += 1;
        match *asked {
            1 => Ok(modbus_devices_page(&[meter()], *from)),
            2 => Err(Refusal::new(
                Status::UnknownService,
                "service 0x52 is unknown to protocol version 3",
            )),
            _ => Err(Refusal::bad("the frame is too short")),
        }
    })
    .await;
    let (commands, mut events) = spawn(SessionOptions {
        address,
        password: None,
        poll_interval: Duration::from_millis(50),
        reconnect_interval: Duration::from_secs(1),
    });
    assert!(matches!(next(&mut events).await, Event::Connected(_)));
    let expected = [
        // The fake runtime's `IDENTIFY` says it runs.
        ModbusDevicesAnswer::Reports {
            reports: vec![meter()],
            state: online_protocol::TargetState::Running,
        },
        ModbusDevicesAnswer::NotReported,
        ModbusDevicesAnswer::Refused("the frame is too short".to_owned()),
    ];
    // The fake serves a single connection: had an answer ended it, the next event would be
    // `Disconnected` rather than the next answer.
    for answer in expected {
        commands.send(Command::ModbusDevices).await.unwrap();
        match next(&mut events).await {
            Event::ModbusDevices(got) => assert_eq!(got, answer),
            other => panic!("{other:?}"),
        }
    }
    assert_eq!(
        *asked.lock().unwrap(),
        3,
        "each command asked MODBUS_DEVICES once, none was sent again"
    );
    commands.send(Command::Close).await.unwrap();
}

#[tokio::test]
async fn the_question_waiting_for_a_connection_is_dropped_without_a_failure() {
    // A port nobody listens on: bound, then let go.
    let address = {
        let listener = std::net::TcpListener::bind("127.0.0.1:0").unwrap();
        listener.local_addr().unwrap()
    };
    let (commands, mut events) = spawn(SessionOptions {
        address,
        password: None,
        poll_interval: Duration::from_millis(50),
        reconnect_interval: Duration::from_secs(30),
    });
    assert!(matches!(next(&mut events).await, Event::Disconnected(_)));
    // The question, then a command whose failure the user must see.
    commands.send(Command::ModbusDevices).await.unwrap();
    commands.send(Command::Start).await.unwrap();
    assert!(matches!(next(&mut events).await, Event::Failed(_)));
    // Commands are served in order: a failure of the question would have come first, and a
    // second one now.
    let later = tokio::time::timeout(Duration::from_millis(300), events.recv()).await;
    assert!(later.is_err(), "{later:?}");
    commands.send(Command::Close).await.unwrap();
}
