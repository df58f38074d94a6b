//! The Modbus TCP server: accepting connections, framing requests, answering them.

use std::io;
use std::net::IpAddr;
use std::sync::{Arc, Mutex};
use std::time::Duration;

use tokio::io::{AsyncRead, AsyncReadExt, AsyncWrite, AsyncWriteExt};
use tokio::net::TcpListener;
use tokio::task::JoinSet;
use tokio::time::{Instant, timeout, timeout_at};

use crate::areas::LocatedAreas;
use crate::modbus::connections::Connections;
use crate::modbus::exception::ExceptionCode;
use crate::modbus::frame::{HEADER_BYTES, MbapHeader};
use crate::modbus::map_slot::MapSlot;
use crate::modbus::pdu::{MAX_PDU_BYTES, is_standard_function, serve_pdu};
use crate::modbus::write_policy::WritePolicy;

/// A handler of the function codes the areas do not serve (Rivet's online services).
///
/// It gets the function code and the request's bytes after it, and returns the response's bytes
/// after the function code, or the exception to answer. It runs on the server's task, without
/// the areas locked, and should return quickly.
pub type CustomFunctions = Arc<dyn Fn(u8, &[u8]) -> Result<Vec<u8>, ExceptionCode> + Send + Sync>;

/// Told the number of a connection that has closed (see [`current_connection`]).
pub type ConnectionClosed = Arc<dyn Fn(u64) + Send + Sync>;

tokio::task_local! {
    /// The number of the connection whose request is being served.
    static CONNECTION: u64;
    /// The IP address of the peer of the connection being served.
    static PEER: IpAddr;
    /// How long the connection being served waits before it answers (see [`delay_answer`]).
    static ANSWER_DELAY: std::cell::Cell<Duration>;
}

/// Makes the connection whose request a [`CustomFunctions`] hook is serving wait `delay` before
/// it sends the answer (and so before it reads its next request), without holding up any other
/// connection; outside a server it does nothing.
///
/// The online services delay the answer to a wrong password this way, so that one connection
/// guesses slowly while everyone else logs in at once.
pub fn delay_answer(delay: Duration) {
    let _ = ANSWER_DELAY.try_with(|answer_delay| answer_delay.set(answer_delay.get().max(delay)));
}

/// The number of the connection whose request a [`CustomFunctions`] hook is serving (unique
/// for the life of the server), or `None` outside a server.
pub fn current_connection() -> Option<u64> {
    CONNECTION.try_with(|connection| *connection).ok()
}

/// The IP address of the peer whose request a [`CustomFunctions`] hook is serving, or `None`
/// outside a server; the online services count wrong passwords per address with it.
pub fn current_peer() -> Option<IpAddr> {
    PEER.try_with(|peer| *peer).ok()
}

/// How the server behaves; fixed for the life of one [`serve`] call.
#[derive(Clone)]
pub struct ServerOptions {
    /// The most connections served at once; one more takes the place of the connection that
    /// has gone longest without a whole request, which is closed (0 admits nobody).
    pub max_clients: usize,
    /// How long a connection may wait between requests before it is closed.
    pub idle_timeout: Duration,
    /// How long a request frame may take from its first byte to its last, and a response to
    /// be taken by the peer, before the connection is closed.
    pub frame_timeout: Duration,
    /// What the standard function codes may write; a refused write gets [`REFUSED_WRITE`].
    pub writes: WritePolicy,
    /// The handler of the non-standard function codes; without one they get exception 1.
    pub custom: Option<CustomFunctions>,
    /// Told when a connection has closed, so that state kept for it can go.
    pub closed: Option<ConnectionClosed>,
}

/// Serves Modbus TCP on `listener`: the standard function codes on `areas` through the map in
/// `map` (which may be replaced while serving, as a download does), the others through
/// `options.custom`.
///
/// Each connection is served on its own task, one request at a time in the order they come;
/// each request locks `areas` while it is served. A connection whose frames cannot be trusted
/// (see `docs/modbus-map.md`), that stays silent longer than `options.idle_timeout`, or whose
/// frame takes longer than `options.frame_timeout`, is closed; when `options.max_clients` are
/// open, a new connection closes the one that has gone longest without a whole request. The future runs until it is dropped, which closes every
/// connection; it ends early with an error only when the listener fails with an error that
/// waiting cannot cure (not an aborted handshake, not running out of file descriptors).
pub async fn serve(
    listener: TcpListener,
    areas: Arc<Mutex<LocatedAreas>>,
    map: Arc<MapSlot>,
    options: ServerOptions,
) -> io::Result<()> {
    let responder = Arc::new(Responder {
        areas,
        map,
        custom: options.custom,
        writes: options.writes,
    });
    let open = Arc::new(Connections::default());
    let timeouts = Timeouts {
        idle: options.idle_timeout,
        frame: options.frame_timeout,
    };
    let mut connections = JoinSet::new();
    let mut connection = 0u64;
    loop {
        tokio::select! {
            accepted = listener.accept() => {
                let (stream, peer) = match accepted {
                    Ok(accepted) => accepted,
                    Err(error) if is_transient(&error) => {
                        tokio::time::sleep(ACCEPT_RETRY_DELAY).await;
                        continue;
                    }
                    Err(error) => return Err(error),
                };
                connection += 1;
                let id = connection;
                // Without a place (`max_clients` is 0) the stream is dropped here, closing it.
                let Some(evicted) = open.admit(id, Instant::now(), options.max_clients) else {
                    continue;
                };
                let responder = Arc::clone(&responder);
                let closed = options.closed.clone();
                let open = Arc::clone(&open);
                connections.spawn(CONNECTION.scope(id, PEER.scope(peer.ip(), async move {
                    let mut stream = stream;
                    let served = async {
                        stream.set_nodelay(true)?;
                        let touch = || open.touch(id, Instant::now());
                        serve_connection(&mut stream, &responder, timeouts, touch).await
                    };
                    // An error ends only this connection, which is all there is to do about a
                    // peer that breaks the protocol, goes silent or goes away; an evicted
                    // connection is dropped unanswered, as its place is needed now.
                    tokio::select! {
                        _ = served => {}
                        () = evicted.notified() => {}
                    }
                    open.remove(id);
                    if let Some(closed) = closed {
                        closed(id);
                    }
                })));
            }
            Some(_) = connections.join_next(), if !connections.is_empty() => {}
        }
    }
}

impl Default for ServerOptions {
    /// 64 clients, closed after 60 s without a request or 5 s into a frame; every write
    /// served; no custom function codes.
    fn default() -> Self {
        Self {
            max_clients: 64,
            idle_timeout: DEFAULT_IDLE_TIMEOUT,
            frame_timeout: DEFAULT_FRAME_TIMEOUT,
            writes: WritePolicy::All,
            custom: None,
            closed: None,
        }
    }
}

impl std::fmt::Debug for ServerOptions {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ServerOptions")
            .field("max_clients", &self.max_clients)
            .field("idle_timeout", &self.idle_timeout)
            .field("frame_timeout", &self.frame_timeout)
            .field("writes", &self.writes)
            .field("custom", &self.custom.as_ref().map(|_| "Fn(u8, &[u8])"))
            .field("closed", &self.closed.as_ref().map(|_| "Fn(u64)"))
            .finish()
    }
}

/// How long a connection may stay silent between requests by default: long enough for a
/// client polling slowly, short enough that forgotten connections do not pile up.
pub const DEFAULT_IDLE_TIMEOUT: Duration = Duration::from_secs(60);

/// How long one frame may take to arrive by default: a whole frame is at most 260 bytes, which
/// any live link carries in far less.
pub const DEFAULT_FRAME_TIMEOUT: Duration = Duration::from_secs(5);

/// The timeouts of one connection.
#[derive(Clone, Copy, Debug)]
struct Timeouts {
    /// The most time between requests.
    idle: Duration,
    /// The most time for a frame to arrive or its response to leave.
    frame: Duration,
}

/// How long to wait before accepting again after an error that time may cure.
const ACCEPT_RETRY_DELAY: Duration = Duration::from_millis(100);

/// What every connection answers with.
struct Responder {
    areas: Arc<Mutex<LocatedAreas>>,
    map: Arc<MapSlot>,
    custom: Option<CustomFunctions>,
    writes: WritePolicy,
}

impl Responder {
    /// The response PDU to the request PDU `request`.
    fn respond(&self, request: &[u8]) -> Vec<u8> {
        let Some((&function, data)) = request.split_first() else {
            return ExceptionCode::IllegalFunction.response(0);
        };
        if is_standard_function(function) {
            return serve_pdu(&self.areas, &self.map.get(), &self.writes, request);
        }
        let custom = match &self.custom {
            Some(custom) if function < 0x80 => custom,
            _ => return ExceptionCode::IllegalFunction.response(function),
        };
        match custom(function, data) {
            Ok(body) if body.len() < MAX_PDU_BYTES => {
                let mut response = Vec::with_capacity(1 + body.len());
                response.push(function);
                response.extend_from_slice(&body);
                response
            }
            Ok(_) => ExceptionCode::ServerDeviceFailure.response(function),
            Err(exception) => exception.response(function),
        }
    }
}

/// Serves one connection until the peer closes it, breaks the framing, stays silent longer
/// than `timeouts.idle` or is slower than `timeouts.frame`; `touch` is called on each whole
/// request.
async fn serve_connection<Stream: AsyncRead + AsyncWrite + Unpin>(
    stream: &mut Stream,
    responder: &Responder,
    timeouts: Timeouts,
    touch: impl Fn(),
) -> io::Result<()> {
    let mut header_bytes = [0; HEADER_BYTES];
    let mut request = [0; MAX_PDU_BYTES];
    loop {
        // The first byte may be as late as the idle timeout; from it, the frame timeout counts.
        match timeout(timeouts.idle, stream.read(&mut header_bytes[..1])).await {
            Err(_elapsed) => return Err(io::Error::new(io::ErrorKind::TimedOut, "idle")),
            Ok(Ok(0)) => return Ok(()),
            Ok(Ok(_)) => {}
            Ok(Err(error)) => return Err(error),
        }
        let deadline = Instant::now() + timeouts.frame;
        let header = timeout_at(deadline, async {
            stream.read_exact(&mut header_bytes[1..]).await?;
            let header = MbapHeader::parse(header_bytes)
                .map_err(|error| io::Error::new(io::ErrorKind::InvalidData, error))?;
            stream.read_exact(&mut request[..header.pdu_bytes]).await?;
            Ok::<_, io::Error>(header)
        })
        .await
        .map_err(|_elapsed| io::Error::new(io::ErrorKind::TimedOut, "slow frame"))??;
        touch();
        let (response, delay) =
            ANSWER_DELAY.sync_scope(std::cell::Cell::new(Duration::ZERO), || {
                let response = responder.respond(&request[..header.pdu_bytes]);
                (response, ANSWER_DELAY.with(std::cell::Cell::get))
            });
        if !delay.is_zero() {
            tokio::time::sleep(delay).await;
        }
        let frame = header.response_frame(&response);
        // A peer that does not take its responses would hold the connection forever.
        timeout(timeouts.frame, stream.write_all(&frame))
            .await
            .map_err(|_elapsed| io::Error::new(io::ErrorKind::TimedOut, "slow reader"))??;
    }
}

/// Whether an accept error concerns one connection or passes with time, rather than the
/// listener itself.
fn is_transient(error: &io::Error) -> bool {
    use io::ErrorKind::*;
    // EMFILE and ENFILE (out of file descriptors) pass when connections close.
    const OUT_OF_FILE_DESCRIPTORS: [i32; 2] = [23, 24];
    matches!(
        error.kind(),
        ConnectionAborted
            | ConnectionReset
            | ConnectionRefused
            | Interrupted
            | WouldBlock
            | TimedOut
            | OutOfMemory
    ) || cfg!(unix)
        && error
            .raw_os_error()
            .is_some_and(|code| OUT_OF_FILE_DESCRIPTORS.contains(&code))
}

#[cfg(test)]
mod tests;
