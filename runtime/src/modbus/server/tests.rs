use super::*;
use crate::modbus::ModbusMap;
use tokio::io::{AsyncReadExt, AsyncWriteExt};

fn responder(custom: Option<CustomFunctions>) -> Responder {
    Responder {
        areas: Arc::new(Mutex::new(LocatedAreas::new(2, 2, 2))),
        map: MapSlot::new(ModbusMap::default()),
        custom,
        writes: WritePolicy::All,
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
        r#"ServerOptions { max_clients: 64, idle_timeout: 60s, frame_timeout: 5s, writes: All, custom: Some("Fn(u8, &[u8])"), closed: None }"#
    );
}

/// Short timeouts for the tests, which run on tokio's paused clock.
const TIMEOUTS: Timeouts = Timeouts {
    idle: Duration::from_secs(60),
    frame: Duration::from_secs(5),
};

/// Serves one end of an in-memory pipe; returns the other end, the server's task (ending with
/// the connection's result) and the number of whole requests it saw.
fn serve_pipe() -> (
    tokio::io::DuplexStream,
    tokio::task::JoinHandle<io::Result<()>>,
    Arc<std::sync::atomic::AtomicUsize>,
) {
    serve_pipe_with(None)
}

/// [`serve_pipe`] with the hook `custom`.
fn serve_pipe_with(
    custom: Option<CustomFunctions>,
) -> (
    tokio::io::DuplexStream,
    tokio::task::JoinHandle<io::Result<()>>,
    Arc<std::sync::atomic::AtomicUsize>,
) {
    use std::sync::atomic::{AtomicUsize, Ordering};
    let (client, mut server) = tokio::io::duplex(1024);
    let requests = Arc::new(AtomicUsize::new(0));
    let counted = Arc::clone(&requests);
    let task = tokio::spawn(async move {
        let responder = responder(custom);
        let touch = || {
            counted.fetch_add(1, Ordering::SeqCst);
        };
        serve_connection(&mut server, &responder, TIMEOUTS, touch).await
    });
    (client, task, requests)
}

/// A request reading holding register 0, transaction 9.
const READ_REQUEST: [u8; 12] = [0, 9, 0, 0, 0, 6, 1, 3, 0, 0, 0, 1];

#[tokio::test(start_paused = true)]
async fn a_connection_silent_longer_than_the_idle_timeout_is_closed() {
    let (mut client, task, requests) = serve_pipe();
    // Just before the timeout a request is still served, and restarts the wait.
    tokio::time::sleep(TIMEOUTS.idle - Duration::from_millis(1)).await;
    client.write_all(&READ_REQUEST).await.unwrap();
    let mut response = [0; 11];
    client.read_exact(&mut response).await.unwrap();
    assert_eq!(response[..2], [0, 9]);
    tokio::time::sleep(TIMEOUTS.idle - Duration::from_millis(1)).await;
    assert!(!task.is_finished());
    let error = task.await.unwrap().unwrap_err();
    assert_eq!(error.kind(), io::ErrorKind::TimedOut);
    assert_eq!(requests.load(std::sync::atomic::Ordering::SeqCst), 1);
    assert_eq!(client.read(&mut response).await.unwrap(), 0);
}

#[tokio::test(start_paused = true)]
async fn a_frame_slower_than_the_frame_timeout_closes_its_connection() {
    let (mut client, task, requests) = serve_pipe();
    // One byte a second: the frame would take 12 s, more than the 5 s allowed.
    let trickle = async {
        for byte in READ_REQUEST {
            if client.write_all(&[byte]).await.is_err() {
                break;
            }
            tokio::time::sleep(Duration::from_secs(1)).await;
        }
    };
    let (_, result) = tokio::join!(trickle, task);
    assert_eq!(result.unwrap().unwrap_err().kind(), io::ErrorKind::TimedOut);
    assert_eq!(requests.load(std::sync::atomic::Ordering::SeqCst), 0);
}

#[tokio::test(start_paused = true)]
async fn a_peer_that_does_not_take_its_responses_is_closed() {
    let (mut client, task, _requests) = serve_pipe();
    // The pipe holds 1024 bytes; responses to 200 requests (11 bytes each) do not fit.
    let requests: Vec<u8> = READ_REQUEST.repeat(200);
    let _ = client.write_all(&requests).await;
    let error = task.await.unwrap().unwrap_err();
    assert_eq!(error.kind(), io::ErrorKind::TimedOut);
}

#[tokio::test(start_paused = true)]
async fn a_peer_closing_between_frames_ends_its_connection_cleanly() {
    let (client, task, _requests) = serve_pipe();
    drop(client);
    assert!(task.await.unwrap().is_ok());
}

#[tokio::test(start_paused = true)]
async fn a_delayed_answer_holds_up_its_own_connection_only() {
    let hook: CustomFunctions = Arc::new(|function, _data| {
        if function == 0x44 {
            delay_answer(Duration::from_millis(500));
        }
        Ok(vec![7])
    });
    let (mut slow, _slow_task, _) = serve_pipe_with(Some(Arc::clone(&hook)));
    let (mut quick, _quick_task, _) = serve_pipe_with(Some(hook));
    let start = Instant::now();
    slow.write_all(&[0, 1, 0, 0, 0, 2, 1, 0x44]).await.unwrap();
    quick.write_all(&[0, 2, 0, 0, 0, 2, 1, 0x45]).await.unwrap();
    let mut answer = [0; 9];
    quick.read_exact(&mut answer).await.unwrap();
    assert_eq!(answer, [0, 2, 0, 0, 0, 3, 1, 0x45, 7]);
    assert_eq!(
        start.elapsed(),
        Duration::ZERO,
        "the other connection waited"
    );
    slow.read_exact(&mut answer).await.unwrap();
    assert_eq!(answer, [0, 1, 0, 0, 0, 3, 1, 0x44, 7]);
    assert!(start.elapsed() >= Duration::from_millis(500));
    // The delay was for that answer only.
    let again = Instant::now();
    slow.write_all(&[0, 3, 0, 0, 0, 2, 1, 0x45]).await.unwrap();
    slow.read_exact(&mut answer).await.unwrap();
    assert_eq!(again.elapsed(), Duration::ZERO);
}

#[test]
fn a_refused_write_gets_the_same_exception_whatever_it_writes() {
    let mut responder = responder(None);
    responder.writes = "holding:0".parse().unwrap();
    // Inside the range, the write is served.
    assert_eq!(responder.respond(&[6, 0, 0, 0, 7]), [6, 0, 0, 0, 7]);
    // Outside it, mapped or not, present or not, well-formed or not: exception 1 each time.
    for write in [
        &[6, 0, 1, 0, 7][..],
        &[6, 0xFF, 0xFF, 0, 7],
        &[5, 0, 0, 0x12, 0x34],
        &[16, 0, 0, 0, 0, 0],
        &[15],
    ] {
        assert_eq!(responder.respond(write), [write[0] | 0x80, 1], "{write:?}");
    }
    // Reads are not limited.
    assert_eq!(responder.respond(&[3, 0, 0, 0, 1]), [3, 2, 0, 7]);
}
