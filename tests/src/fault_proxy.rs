//! A TCP proxy between a Modbus master and a slave that plays the faults of a plant's network
//! (`docs/modbus-master.md` §10): a slow slave, a pulled cable, a stopped server.
//!
//! It listens on 127.0.0.1 on a port the system picks and forwards every connection to the
//! slave; a test switches its [`ProxyMode`] while it runs, and may point it at another slave
//! ([`FaultProxy::set_slave`]): a slave stopped and started again gets a new port of its own,
//! while the master's address, the proxy's, never changes and no port is ever bound twice.
//! Plain threads and `std::net`, so any test (async or not, in any crate) can use it.

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
    /// Takes every byte and forwards none, without closing anything, and answers no new
    /// connection: a pulled cable. A request on an open connection gets no answer; a new
    /// connection gets no answer to its SYN (the listener's backlog is 0 and nothing is
    /// accepted, so the kernel queues at most one connection, which then answers nothing
    /// either), so a master's connection attempt times out. The connection the kernel queued
    /// meanwhile is reset when the mode changes, before any new one is taken, so nothing sent
    /// while the cable was out reaches the slave afterwards.
    Swallow,
    /// Completes the handshake of every new connection and resets it at once, and resets every
    /// open connection (RST, not an orderly close). A master's connection attempt therefore
    /// succeeds and its first request fails, so it reconnects at every round without backing
    /// off; a host whose server has stopped refuses the SYN instead, which a test gets from a
    /// port bound and never listened on. The proxy keeps its port all the while, so no other
    /// test can take it, and counts the connections it resets.
    Refuse,
}

/// A running proxy; dropping it stops listening at once (the port is closed before `drop`
/// returns) and ends its connections within [`POLL_INTERVAL`].
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
    /// The mode and the listener under one lock: a connection is taken only while it is held,
    /// so a switch of mode never falls between reading the mode and accepting.
    gate: Mutex<Gate>,
    /// Where new connections are forwarded.
    slave: Mutex<SocketAddr>,
    /// Connections accepted so far.
    connections: AtomicU64,
    /// Set when the proxy is dropped.
    stopping: AtomicBool,
}

/// The mode, and the listener it decides about.
struct Gate {
    /// The current mode.
    mode: ProxyMode,
    /// The listener masters connect to; it does not block. Taken (and so closed) when the
    /// proxy is dropped, while forwarding threads may still hold the shared state.
    listener: Option<TcpListener>,
}

/// How often idle threads look at the mode and at `stopping`.
const POLL_INTERVAL: Duration = Duration::from_millis(10);

/// How long [`FaultProxy::start`] waits for its own trial connection to be queued and taken.
const TRIAL_PATIENCE: Duration = Duration::from_secs(5);

impl FaultProxy {
    /// Starts a proxy in [`ProxyMode::Pass`] on 127.0.0.1, port 0, forwarding to `slave`.
    ///
    /// Fails when this machine's kernel queues no connection on a listener whose backlog is 0
    /// (see [`listen_with_backlog_0`]): the proxy could then pass nothing.
    pub fn start(slave: SocketAddr) -> io::Result<Self> {
        let listener = listen_with_backlog_0()?;
        listener.set_nonblocking(true)?;
        let address = listener.local_addr()?;
        check_one_connection_is_queued(&listener, address)?;
        let shared = Arc::new(Shared {
            gate: Mutex::new(Gate {
                mode: ProxyMode::Pass,
                listener: Some(listener),
            }),
            slave: Mutex::new(slave),
            connections: AtomicU64::new(0),
            stopping: AtomicBool::new(false),
        });
        let acceptor_shared = Arc::clone(&shared);
        let acceptor = std::thread::spawn(move || accept(&acceptor_shared));
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
    /// 10 ms for [`ProxyMode::Refuse`]), and every connection taken after this returns follows
    /// it from the start. Leaving [`ProxyMode::Swallow`] first resets the connection the kernel
    /// queued while the cable was pulled.
    pub fn set_mode(&self, mode: ProxyMode) {
        let mut gate = lock(&self.shared.gate);
        if gate.mode == ProxyMode::Swallow && mode != ProxyMode::Swallow {
            reset_queued(&gate, &self.shared);
        }
        gate.mode = mode;
    }

    /// Forwards the connections opened from now on to `slave` (a slave started again on a
    /// port of its own); open connections stay with the slave they were made to.
    pub fn set_slave(&self, slave: SocketAddr) {
        *lock(&self.shared.slave) = slave;
    }

    /// How many connections masters have opened through the proxy so far, those reset in
    /// [`ProxyMode::Refuse`] and those queued while it was a pulled cable included.
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
        // The forwarding threads hold the shared state until their pumps see `stopping`; the
        // port must not outlive the proxy meanwhile.
        lock(&self.shared.gate).listener = None;
    }
}

impl Shared {
    fn mode(&self) -> ProxyMode {
        lock(&self.gate).mode
    }

    fn slave(&self) -> SocketAddr {
        *lock(&self.slave)
    }
}

/// A value the proxy's threads share, even when a thread panicked while holding it (they
/// only ever store a whole value).
fn lock<T>(value: &Mutex<T>) -> std::sync::MutexGuard<'_, T> {
    value
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner)
}

/// A listener on 127.0.0.1, port 0, whose accept queue holds one connection: while the proxy
/// accepts nothing (a pulled cable), the kernel answers no further SYN, so a master's
/// connection attempt times out as it would without a cable.
///
/// A backlog of 0 queues that one connection only on a kernel that allows a connection when
/// `sk_max_ack_backlog` is zero (the accept queue counts as full only beyond its backlog), or
/// that answers with SYN cookies (`net.ipv4.tcp_syncookies`) the SYN a backlog of 0 would
/// drop; elsewhere nothing gets through, which [`FaultProxy::start`] finds out and says.
fn listen_with_backlog_0() -> io::Result<TcpListener> {
    let socket = socket2::Socket::new(socket2::Domain::IPV4, socket2::Type::STREAM, None)?;
    socket.bind(&SocketAddr::from(([127, 0, 0, 1], 0)).into())?;
    socket.listen(0)?;
    Ok(socket.into())
}

/// Connects to `listener` (at `address`, not blocking) once and takes the connection, as
/// [`ProxyMode::Pass`] will; fails with what to look at when the kernel queues nothing.
fn check_one_connection_is_queued(listener: &TcpListener, address: SocketAddr) -> io::Result<()> {
    let refused = |what: String| {
        io::Error::other(format!(
            "the fault proxy's listener on {address} (backlog 0) {what}: this kernel queues \
             no connection on a listener with backlog 0; the proxy needs a kernel that allows \
             one connection when sk_max_ack_backlog is zero, or SYN cookies \
             (net.ipv4.tcp_syncookies = 1)"
        ))
    };
    let trial = TcpStream::connect_timeout(&address, TRIAL_PATIENCE)
        .map_err(|error| refused(format!("took no trial connection ({error})")))?;
    let deadline = std::time::Instant::now() + TRIAL_PATIENCE;
    loop {
        match listener.accept() {
            // The trial is no master's: it is closed and not counted.
            Ok(_) => return Ok(()),
            Err(error) if is_timeout(&error) && std::time::Instant::now() < deadline => {
                std::thread::sleep(POLL_INTERVAL);
            }
            Err(error) => {
                drop(trial);
                return Err(refused(format!("queued no trial connection ({error})")));
            }
        }
    }
}

/// Accepts connections until the proxy is dropped; while refusing, resets each at once; while
/// the cable is pulled, accepts none (see [`ProxyMode::Swallow`]).
fn accept(shared: &Arc<Shared>) {
    while !shared.stopping.load(Ordering::SeqCst) {
        // The mode is read and the connection taken under one lock, so that a connection made
        // after `set_mode` returns is always handled in the new mode. The listener does not
        // block, so the lock is held only for a look, and the thread sees the drop.
        let taken = {
            let gate = lock(&shared.gate);
            match (&gate.listener, gate.mode) {
                (_, ProxyMode::Swallow) | (None, _) => None,
                (Some(listener), mode) => listener.accept().ok().map(|(master, _)| (master, mode)),
            }
        };
        // Nobody is connecting (or a connection failed before it was taken), or the cable is
        // pulled.
        let Some((master, mode)) = taken else {
            std::thread::sleep(POLL_INTERVAL);
            continue;
        };
        shared.connections.fetch_add(1, Ordering::SeqCst);
        if mode == ProxyMode::Refuse {
            reset(&master);
            continue;
        }
        let shared = Arc::clone(shared);
        std::thread::spawn(move || {
            let _ = forward(master, &shared);
        });
    }
}

/// Resets every connection the kernel queued while the cable was pulled (counting them: a
/// master opened them); called with the mode still [`ProxyMode::Swallow`] and locked in
/// `gate`, so the acceptor takes none of them and every later one is new.
fn reset_queued(gate: &Gate, shared: &Shared) {
    let Some(listener) = &gate.listener else {
        return;
    };
    while let Ok((queued, _)) = listener.accept() {
        shared.connections.fetch_add(1, Ordering::SeqCst);
        reset(&queued);
    }
}

/// Makes the closing of `stream`'s last handle send a reset (SO_LINGER 0) rather than an
/// orderly end; a stream that cannot be set so still closes.
fn reset(stream: &TcpStream) {
    let _ = socket2::SockRef::from(stream).set_linger(Some(Duration::ZERO));
}

/// Joins one master connection to a new connection to the slave until either closes, the
/// proxy refuses or is dropped.
fn forward(master: TcpStream, shared: &Arc<Shared>) -> io::Result<()> {
    master.set_nonblocking(false)?;
    let upstream = TcpStream::connect_timeout(&shared.slave(), Duration::from_secs(5))?;
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

    /// A slave that answers every chunk with the same bytes (in capitals when `shouting`, to
    /// tell two slaves apart), on 127.0.0.1:0.
    fn echo_slave(shouting: bool) -> SocketAddr {
        let listener = TcpListener::bind("127.0.0.1:0").unwrap();
        let address = listener.local_addr().unwrap();
        std::thread::spawn(move || {
            for stream in listener.incoming() {
                let Ok(mut stream) = stream else { return };
                std::thread::spawn(move || {
                    let mut buffer = [0; 256];
                    while let Ok(count @ 1..) = stream.read(&mut buffer) {
                        if shouting {
                            buffer[..count].make_ascii_uppercase();
                        }
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
        let stream = TcpStream::connect_timeout(&proxy.address(), Duration::from_secs(5)).unwrap();
        stream
            .set_read_timeout(Some(Duration::from_millis(300)))
            .unwrap();
        stream
    }

    /// Sends `bytes` and reads the answer, or `None` when none came within 300 ms.
    fn echo(stream: &mut TcpStream, bytes: &[u8]) -> Option<Vec<u8>> {
        stream.write_all(bytes).unwrap();
        let mut answer = vec![0; bytes.len()];
        stream.read_exact(&mut answer).ok().map(|()| answer)
    }

    /// Waits until the proxy resets `stream`; panics when it ends otherwise or stays open.
    #[track_caller]
    fn wait_for_a_reset(stream: &mut TcpStream, what: &str) {
        let deadline = Instant::now() + Duration::from_secs(5);
        let mut byte = [0; 1];
        loop {
            match stream.read(&mut byte) {
                Err(error) if error.kind() == io::ErrorKind::ConnectionReset => return,
                Err(error) if is_timeout(&error) => {
                    assert!(Instant::now() < deadline, "the proxy kept {what}");
                }
                other => panic!("{what} ended without a reset: {other:?}"),
            }
        }
    }

    #[test]
    fn the_proxy_passes_delays_swallows_and_refuses_as_switched_and_counts_connections() {
        let proxy = FaultProxy::start(echo_slave(false)).unwrap();
        let mut stream = connect(&proxy);
        assert_eq!(echo(&mut stream, b"one").as_deref(), Some(&b"one"[..]));
        assert_eq!(proxy.connections(), 1);

        proxy.set_mode(ProxyMode::Delay(Duration::from_millis(100)));
        let start = Instant::now();
        assert_eq!(echo(&mut stream, b"two").as_deref(), Some(&b"two"[..]));
        assert!(start.elapsed() >= Duration::from_millis(100));

        // A pulled cable: the open connection answers nothing; of the new ones, the kernel
        // completes one handshake (which answers nothing either) and answers no SYN after it.
        proxy.set_mode(ProxyMode::Swallow);
        assert_eq!(echo(&mut stream, b"three"), None);
        let mut queued = connect(&proxy);
        assert_eq!(echo(&mut queued, b"lost"), None);
        let unanswered = TcpStream::connect_timeout(&proxy.address(), Duration::from_millis(300));
        assert!(
            unanswered.as_ref().is_err_and(is_timeout),
            "a connection was answered without a cable: {unanswered:?}"
        );

        proxy.set_mode(ProxyMode::Refuse);
        // The open connection is reset, and so is the one queued while the cable was out,
        // and a new one, on the port the proxy keeps.
        wait_for_a_reset(&mut stream, "its connection");
        wait_for_a_reset(&mut queued, "the connection queued without a cable");
        let before = proxy.connections();
        let mut refused = connect(&proxy);
        wait_for_a_reset(&mut refused, "a new connection");
        assert_eq!(proxy.connections(), before + 1);

        proxy.set_mode(ProxyMode::Pass);
        let mut stream = connect(&proxy);
        assert_eq!(echo(&mut stream, b"four").as_deref(), Some(&b"four"[..]));
        assert_eq!(proxy.connections(), before + 2);

        // Another slave (one started again on a port of its own) behind the same address:
        // new connections go to it, the open one stays with the first.
        proxy.set_slave(echo_slave(true));
        let mut moved = connect(&proxy);
        assert_eq!(echo(&mut moved, b"five").as_deref(), Some(&b"FIVE"[..]));
        assert_eq!(echo(&mut stream, b"six").as_deref(), Some(&b"six"[..]));
    }

    #[test]
    fn nothing_sent_while_the_cable_was_out_reaches_the_slave_when_it_is_back() {
        // A slave that counts the bytes it receives.
        let listener = TcpListener::bind("127.0.0.1:0").unwrap();
        let slave = listener.local_addr().unwrap();
        let received = Arc::new(AtomicU64::new(0));
        let counting = Arc::clone(&received);
        std::thread::spawn(move || {
            for stream in listener.incoming() {
                let Ok(mut stream) = stream else { return };
                let counting = Arc::clone(&counting);
                std::thread::spawn(move || {
                    let mut buffer = [0; 256];
                    while let Ok(count @ 1..) = stream.read(&mut buffer) {
                        counting.fetch_add(count as u64, Ordering::SeqCst);
                        let _ = stream.write_all(&buffer[..count]);
                    }
                });
            }
        });
        let proxy = FaultProxy::start(slave).unwrap();
        proxy.set_mode(ProxyMode::Swallow);
        let mut queued = connect(&proxy);
        assert_eq!(echo(&mut queued, b"stale"), None);
        proxy.set_mode(ProxyMode::Pass);
        wait_for_a_reset(&mut queued, "the connection queued without a cable");
        let mut stream = connect(&proxy);
        assert_eq!(echo(&mut stream, b"fresh").as_deref(), Some(&b"fresh"[..]));
        assert_eq!(
            received.load(Ordering::SeqCst),
            5,
            "the stale request reached the slave"
        );
    }

    #[test]
    fn a_connection_made_after_a_switch_follows_the_new_mode_every_time() {
        // The acceptor takes a connection only under the mode's lock: one made after the
        // switch to Pass is never reset as the Refuse before it would, and one made after the
        // switch to Refuse is never passed.
        let proxy = FaultProxy::start(echo_slave(false)).unwrap();
        for round in 0..20 {
            proxy.set_mode(ProxyMode::Refuse);
            let mut refused = connect(&proxy);
            wait_for_a_reset(
                &mut refused,
                &format!("connection {round} made while refusing"),
            );
            proxy.set_mode(ProxyMode::Pass);
            let mut passed = connect(&proxy);
            // An answer is expected: a loaded machine may take long to forward it.
            passed
                .set_read_timeout(Some(Duration::from_secs(5)))
                .unwrap();
            assert_eq!(
                echo(&mut passed, b"on").as_deref(),
                Some(&b"on"[..]),
                "connection {round} made after the switch to Pass"
            );
        }
        assert_eq!(proxy.connections(), 40);
    }

    #[test]
    fn a_dropped_proxy_stops_listening_though_a_connection_was_still_open() {
        let proxy = FaultProxy::start(echo_slave(false)).unwrap();
        let address = proxy.address();
        let mut stream = connect(&proxy);
        assert_eq!(echo(&mut stream, b"open").as_deref(), Some(&b"open"[..]));
        drop(proxy);
        let after = TcpStream::connect_timeout(&address, Duration::from_secs(5));
        assert!(
            after
                .as_ref()
                .is_err_and(|error| error.kind() == io::ErrorKind::ConnectionRefused),
            "the port still took a connection after the drop: {after:?}"
        );
    }
}
