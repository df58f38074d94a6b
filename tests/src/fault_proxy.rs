//! A TCP proxy between a Modbus master and a slave that plays the faults of a plant's network
//! (`docs/modbus-master.md` §10): a slow slave, a pulled cable, a stopped server.
//!
//! It listens on 127.0.0.1 on a port the system picks and forwards every connection to the
//! slave; a test switches its [`ProxyMode`] while it runs. Plain threads and `std::net`, so any
//! test (async or not, in any crate) can use it.

use std::io::{self, Read, Write};
use std::net::{Shutdown, SocketAddr, TcpListener, TcpStream};
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::{Arc, Mutex};
use std::thread::JoinHandle;
use std::time::Duration;

/// What the proxy does with the traffic; switched with [`FaultProxy::set_mode`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ProxyMode {
    /// Forwards everything at once, both ways.
    Pass,
    /// Forwards requests at once and every answer `Duration` late: a slow slave.
    Delay(Duration),
    /// Takes every byte and forwards none, without closing anything: a pulled cable.
    Swallow,
    /// Resets every open connection and every new one as soon as it is accepted (RST, not an
    /// orderly close): a stopped server behind a host that is still up. The proxy keeps its
    /// port all the while, so no other test can take it, and counts the connections it resets.
    Refuse,
}

/// A running proxy; dropping it closes its connections and stops listening.
pub struct FaultProxy {
    /// The address masters connect to.
    address: SocketAddr,
    /// What the proxy's threads share.
    shared: Arc<Shared>,
    /// The thread accepting connections, joined on drop.
    acceptor: Option<JoinHandle<()>>,
}

/// The state the proxy's threads share.
struct Shared {
    /// The current mode.
    mode: Mutex<ProxyMode>,
    /// Connections accepted so far.
    connections: AtomicU64,
    /// Set when the proxy is dropped.
    stopping: AtomicBool,
}

/// How often idle threads look at the mode and at `stopping`.
const POLL_INTERVAL: Duration = Duration::from_millis(10);

impl FaultProxy {
    /// Starts a proxy in [`ProxyMode::Pass`] on 127.0.0.1, port 0, forwarding to `slave`.
    pub fn start(slave: SocketAddr) -> io::Result<Self> {
        let listener = TcpListener::bind("127.0.0.1:0")?;
        listener.set_nonblocking(true)?;
        let address = listener.local_addr()?;
        let shared = Arc::new(Shared {
            mode: Mutex::new(ProxyMode::Pass),
            connections: AtomicU64::new(0),
            stopping: AtomicBool::new(false),
        });
        let acceptor_shared = Arc::clone(&shared);
        let acceptor = std::thread::spawn(move || accept(&listener, slave, &acceptor_shared));
        Ok(Self {
            address,
            shared,
            acceptor: Some(acceptor),
        })
    }

    /// The address a master connects to instead of the slave's.
    pub fn address(&self) -> SocketAddr {
        self.address
    }

    /// Switches the mode; connections open now follow it from their next bytes on (within
    /// 10 ms for [`ProxyMode::Refuse`]).
    pub fn set_mode(&self, mode: ProxyMode) {
        *lock(&self.shared.mode) = mode;
    }

    /// How many connections masters have opened through the proxy so far, those reset in
    /// [`ProxyMode::Refuse`] included.
    pub fn connections(&self) -> u64 {
        self.shared.connections.load(Ordering::SeqCst)
    }
}

impl Drop for FaultProxy {
    fn drop(&mut self) {
        self.shared.stopping.store(true, Ordering::SeqCst);
        if let Some(acceptor) = self.acceptor.take() {
            let _ = acceptor.join();
        }
    }
}

impl Shared {
    fn mode(&self) -> ProxyMode {
        *lock(&self.mode)
    }
}

/// The mode, even when a thread panicked while holding it (it only ever stores a value).
fn lock(mode: &Mutex<ProxyMode>) -> std::sync::MutexGuard<'_, ProxyMode> {
    mode.lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner)
}

/// Accepts connections until the proxy is dropped; while refusing, resets each at once.
fn accept(listener: &TcpListener, slave: SocketAddr, shared: &Arc<Shared>) {
    while !shared.stopping.load(Ordering::SeqCst) {
        // The listener does not block, so that the thread sees the drop.
        match listener.accept() {
            Ok((master, _)) => {
                shared.connections.fetch_add(1, Ordering::SeqCst);
                if shared.mode() == ProxyMode::Refuse {
                    reset(&master);
                    continue;
                }
                let shared = Arc::clone(shared);
                std::thread::spawn(move || {
                    let _ = forward(master, slave, &shared);
                });
            }
            // Nobody is connecting (or a connection failed before it was taken).
            Err(_) => std::thread::sleep(POLL_INTERVAL),
        }
    }
}

/// Makes the closing of `stream`'s last handle send a reset (SO_LINGER 0) rather than an
/// orderly end; a stream that cannot be set so still closes.
fn reset(stream: &TcpStream) {
    let _ = socket2::SockRef::from(stream).set_linger(Some(Duration::ZERO));
}

/// Joins one master connection to a new connection to the slave until either closes, the
/// proxy refuses or is dropped.
fn forward(master: TcpStream, slave: SocketAddr, shared: &Arc<Shared>) -> io::Result<()> {
    master.set_nonblocking(false)?;
    let upstream = TcpStream::connect_timeout(&slave, Duration::from_secs(5))?;
    for stream in [&master, &upstream] {
        stream.set_nodelay(true)?;
        stream.set_read_timeout(Some(POLL_INTERVAL))?;
    }
    let answers_shared = Arc::clone(shared);
    let (answers_from, answers_to) = (upstream.try_clone()?, master.try_clone()?);
    let answers = std::thread::spawn(move || {
        pump(
            answers_from,
            answers_to,
            Direction::Answers,
            &answers_shared,
        )
    });
    let requests = pump(master, upstream, Direction::Requests, shared);
    let _ = answers.join();
    requests
}

/// Which way a pump carries bytes.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Direction {
    /// From the master to the slave.
    Requests,
    /// From the slave to the master, which [`ProxyMode::Delay`] holds back.
    Answers,
}

/// Carries bytes from `from` to `to` as the mode says, until either side closes or the
/// connection is to end; then shuts both down, which ends the pump of the other direction too.
fn pump(
    mut from: TcpStream,
    mut to: TcpStream,
    direction: Direction,
    shared: &Shared,
) -> io::Result<()> {
    let mut buffer = [0; 1024];
    let carried = loop {
        if shared.mode() == ProxyMode::Refuse {
            // The master's side is reset when its last handle closes, after both pumps end:
            // an orderly shutdown first would send an end of file before the reset.
            let master = match direction {
                Direction::Requests => &from,
                Direction::Answers => &to,
            };
            reset(master);
            return Ok(());
        }
        if shared.stopping.load(Ordering::SeqCst) {
            break Ok(());
        }
        let count = match from.read(&mut buffer) {
            Ok(0) => break Ok(()),
            Ok(count) => count,
            Err(error) if is_timeout(&error) => continue,
            Err(error) => break Err(error),
        };
        match shared.mode() {
            ProxyMode::Swallow => continue,
            ProxyMode::Delay(delay) if direction == Direction::Answers => std::thread::sleep(delay),
            _ => {}
        }
        if let Err(error) = to.write_all(&buffer[..count]) {
            break Err(error);
        }
    };
    let _ = from.shutdown(Shutdown::Both);
    let _ = to.shutdown(Shutdown::Both);
    carried
}

/// Whether a read failed only because its timeout passed.
fn is_timeout(error: &io::Error) -> bool {
    matches!(
        error.kind(),
        io::ErrorKind::WouldBlock | io::ErrorKind::TimedOut
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::time::Instant;

    /// A slave that answers every chunk with the same bytes, on 127.0.0.1:0.
    fn echo_slave() -> SocketAddr {
        let listener = TcpListener::bind("127.0.0.1:0").unwrap();
        let address = listener.local_addr().unwrap();
        std::thread::spawn(move || {
            for stream in listener.incoming() {
                let Ok(mut stream) = stream else { return };
                std::thread::spawn(move || {
                    let mut buffer = [0; 256];
                    while let Ok(count @ 1..) = stream.read(&mut buffer) {
                        if stream.write_all(&buffer[..count]).is_err() {
                            return;
                        }
                    }
                });
            }
        });
        address
    }

    fn connect(proxy: &FaultProxy) -> TcpStream {
        let stream = TcpStream::connect(proxy.address()).unwrap();
        stream
            .set_read_timeout(Some(Duration::from_millis(300)))
            .unwrap();
        stream
    }

    /// Sends `bytes` and reads the echo, or `None` when none came within 300 ms.
    fn echo(stream: &mut TcpStream, bytes: &[u8]) -> Option<Vec<u8>> {
        stream.write_all(bytes).unwrap();
        let mut answer = vec![0; bytes.len()];
        stream.read_exact(&mut answer).ok().map(|()| answer)
    }

    #[test]
    fn the_proxy_passes_delays_swallows_and_refuses_as_switched_and_counts_connections() {
        let proxy = FaultProxy::start(echo_slave()).unwrap();
        let mut stream = connect(&proxy);
        assert_eq!(echo(&mut stream, b"one").as_deref(), Some(&b"one"[..]));
        assert_eq!(proxy.connections(), 1);

        proxy.set_mode(ProxyMode::Delay(Duration::from_millis(100)));
        let start = Instant::now();
        assert_eq!(echo(&mut stream, b"two").as_deref(), Some(&b"two"[..]));
        assert!(start.elapsed() >= Duration::from_millis(100));

        proxy.set_mode(ProxyMode::Swallow);
        assert_eq!(echo(&mut stream, b"three"), None);

        proxy.set_mode(ProxyMode::Refuse);
        // The open connection is reset, and so is a new one, on the port the proxy keeps.
        let deadline = Instant::now() + Duration::from_secs(5);
        let mut byte = [0; 1];
        loop {
            match stream.read(&mut byte) {
                Err(error) if error.kind() == io::ErrorKind::ConnectionReset => break,
                Err(error) if is_timeout(&error) => {
                    assert!(Instant::now() < deadline, "the proxy kept its connection");
                }
                other => panic!("the connection ended without a reset: {other:?}"),
            }
        }
        let before = proxy.connections();
        let mut refused = connect(&proxy);
        let read = refused.read(&mut byte);
        assert!(
            read.as_ref()
                .is_err_and(|error| error.kind() == io::ErrorKind::ConnectionReset),
            "a new connection was not reset: {read:?}"
        );
        assert_eq!(proxy.connections(), before + 1);

        proxy.set_mode(ProxyMode::Pass);
        let mut stream = connect(&proxy);
        assert_eq!(echo(&mut stream, b"four").as_deref(), Some(&b"four"[..]));
        assert_eq!(proxy.connections(), before + 2);
    }
}
