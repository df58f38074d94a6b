//! The Modbus TCP server: accepting connections, framing requests, answering them.

use std::io;
use std::sync::{Arc, Mutex};
use std::time::Duration;

use tokio::io::{AsyncReadExt, AsyncWriteExt};
use tokio::net::{TcpListener, TcpStream};
use tokio::sync::Semaphore;
use tokio::task::JoinSet;

use crate::areas::LocatedAreas;
use crate::modbus::exception::ExceptionCode;
use crate::modbus::frame::{HEADER_BYTES, MbapHeader};
use crate::modbus::map_slot::MapSlot;
use crate::modbus::pdu::{MAX_PDU_BYTES, handle_pdu, is_standard_function};

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
}

/// The number of the connection whose request a [`CustomFunctions`] hook is serving (unique
/// for the life of the server), or `None` outside a server.
pub fn current_connection() -> Option<u64> {
    CONNECTION.try_with(|connection| *connection).ok()
}

/// How the server behaves; fixed for the life of one [`serve`] call.
#[derive(Clone)]
pub struct ServerOptions {
    /// The most connections served at once; one more is closed as soon as it is accepted.
    pub max_clients: usize,
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
/// (see `docs/modbus-map.md`) is closed. The future runs until it is dropped, which closes every
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
    });
    let places = Arc::new(Semaphore::new(
        options.max_clients.min(Semaphore::MAX_PERMITS),
    ));
    let mut connections = JoinSet::new();
    let mut connection = 0u64;
    loop {
        tokio::select! {
            accepted = listener.accept() => {
                let stream = match accepted {
                    Ok((stream, _peer)) => stream,
                    Err(error) if is_transient(&error) => {
                        tokio::time::sleep(ACCEPT_RETRY_DELAY).await;
                        continue;
                    }
                    Err(error) => return Err(error),
                };
                // A connection beyond `max_clients` is dropped here, which closes it.
                if let Ok(place) = Arc::clone(&places).try_acquire_owned() {
                    let responder = Arc::clone(&responder);
                    let closed = options.closed.clone();
                    connection += 1;
                    let id = connection;
                    connections.spawn(CONNECTION.scope(id, async move {
                        // An error ends only this connection, which is all there is to do
                        // about a peer that breaks the protocol or goes away.
                        let _ = serve_connection(stream, &responder).await;
                        if let Some(closed) = closed {
                            closed(id);
                        }
                        drop(place);
                    }));
                }
            }
            Some(_) = connections.join_next(), if !connections.is_empty() => {}
        }
    }
}

impl Default for ServerOptions {
    /// 64 clients, no custom function codes.
    fn default() -> Self {
        Self {
            max_clients: 64,
            custom: None,
            closed: None,
        }
    }
}

impl std::fmt::Debug for ServerOptions {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ServerOptions")
            .field("max_clients", &self.max_clients)
            .field("custom", &self.custom.as_ref().map(|_| "Fn(u8, &[u8])"))
            .field("closed", &self.closed.as_ref().map(|_| "Fn(u64)"))
            .finish()
    }
}

/// How long to wait before accepting again after an error that time may cure.
const ACCEPT_RETRY_DELAY: Duration = Duration::from_millis(100);

/// What every connection answers with.
struct Responder {
    areas: Arc<Mutex<LocatedAreas>>,
    map: Arc<MapSlot>,
    custom: Option<CustomFunctions>,
}

impl Responder {
    /// The response PDU to the request PDU `request`.
    fn respond(&self, request: &[u8]) -> Vec<u8> {
        let Some((&function, data)) = request.split_first() else {
            return ExceptionCode::IllegalFunction.response(0);
        };
        if is_standard_function(function) {
            let map = self.map.get();
            return match self.areas.lock() {
                Ok(mut areas) => handle_pdu(&mut areas, &map, request),
                // The engine panicked while it held the areas: their state is unknown.
                Err(_) => ExceptionCode::ServerDeviceFailure.response(function),
            };
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

/// Serves one connection until the peer closes it or breaks the framing.
async fn serve_connection(mut stream: TcpStream, responder: &Responder) -> io::Result<()> {
    stream.set_nodelay(true)?;
    let mut header_bytes = [0; HEADER_BYTES];
    let mut request = [0; MAX_PDU_BYTES];
    loop {
        match stream.read_exact(&mut header_bytes).await {
            Ok(_) => {}
            Err(error) if error.kind() == io::ErrorKind::UnexpectedEof => return Ok(()),
            Err(error) => return Err(error),
        }
        let header = MbapHeader::parse(header_bytes)
            .map_err(|error| io::Error::new(io::ErrorKind::InvalidData, error))?;
        let request = &mut request[..header.pdu_bytes];
        stream.read_exact(request).await?;
        let response = responder.respond(request);
        stream.write_all(&header.response_frame(&response)).await?;
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
