//! A small fake runtime on loopback for the client's tests: it answers `IDENTIFY` as a
//! version-3 runtime and every other request with a function the test gives, framed as
//! `online_protocol` frames them.

#![allow(clippy::unwrap_used, clippy::expect_used)] // A panic is a failed test.

use std::net::SocketAddr;

use online_protocol::{
    DebugRequest, DebugResponse, DebugStatus, Identity, PROTOCOL_VERSION, Refusal, Request,
    Response, TargetState,
};
use tokio::io::{AsyncReadExt as _, AsyncWriteExt as _};
use tokio::net::TcpListener;

/// Serves one connection on 127.0.0.1 and a free port, answering each debugging request with
/// `answer` (any other request but `IDENTIFY` fails the test); returns the address to
/// connect to.
pub(crate) async fn serve(
    mut answer: impl FnMut(&DebugRequest) -> Result<DebugResponse, Refusal> + Send + 'static,
) -> SocketAddr {
    serve_requests(move |request| match request {
        Request::Debug(debug) => answer(debug).map(Response::Debug),
        other => panic!("the fake runtime got {other:?}"),
    })
    .await
}

/// Serves one connection on 127.0.0.1 and a free port, answering each request but
/// `IDENTIFY` with `answer`; returns the address to connect to.
pub(crate) async fn serve_requests(
    mut answer: impl FnMut(&Request) -> Result<Response, Refusal> + Send + 'static,
) -> SocketAddr {
    let listener = TcpListener::bind("127.0.0.1:0").await.unwrap();
    let address = listener.local_addr().unwrap();
    tokio::spawn(async move {
        let (mut stream, _) = listener.accept().await.unwrap();
        loop {
            let mut header = [0u8; 7];
            if stream.read_exact(&mut header).await.is_err() {
                return;
            }
            let length = usize::from(u16::from_be_bytes([header[4], header[5]]));
            let mut pdu = vec![0u8; length - 1];
            stream.read_exact(&mut pdu).await.unwrap();
            let request = Request::decode(&pdu[1..]).unwrap();
            let body = match &request {
                Request::Identify { .. } => Response::Identify(Identity {
                    protocol: PROTOCOL_VERSION,
                    runtime_version: "fake".to_owned(),
                    state: TargetState::Running,
                    image_hash: None,
                    project: String::new(),
                    password_required: false,
                    debug: DebugStatus::default(),
                })
                .encode(),
                other => match answer(other) {
                    Ok(response) => response.encode(),
                    Err(refusal) => refusal.encode(other.service().number()),
                },
            };
            let mut frame = header[..4].to_vec();
            frame.extend_from_slice(&((body.len() + 2) as u16).to_be_bytes());
            frame.push(header[6]);
            frame.push(online_protocol::FUNCTION_CODE);
            frame.extend_from_slice(&body);
            stream.write_all(&frame).await.unwrap();
        }
    });
    address
}
