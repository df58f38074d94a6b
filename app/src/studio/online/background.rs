//! The studio's async runtime: one thread that drives every network task (sessions with
//! targets, the embedded simulator's Modbus server), so the UI thread never waits on I/O.

use std::thread::JoinHandle;
use std::time::Duration;

use tokio::sync::{mpsc, oneshot};

/// How long stopping the runtime waits for the sessions still open to log out (each waits at
/// most [`online::session::LOGOUT_TIMEOUT`] for its answer) before it ends them all the same.
pub const LOGOUT_GRACE: Duration = Duration::from_secs(2);

/// A tokio runtime on its own thread; dropping it lets the sessions that are ending log out,
/// for at most [`LOGOUT_GRACE`], then ends the tasks and joins the thread.
pub struct Background {
    handle: tokio::runtime::Handle,
    stop: Option<oneshot::Sender<()>>,
    thread: Option<JoinHandle<()>>,
    /// The original of the guards sessions hold; the thread's receiver ends when it and every
    /// guard are gone.
    sessions: Option<mpsc::Sender<()>>,
}

/// Held by a session's task until it has ended (and so logged out); the runtime's thread
/// waits for every guard to go before it stops.
pub struct SessionGuard {
    _held: mpsc::Sender<()>,
}

impl Background {
    /// Starts the runtime thread.
    pub fn start() -> std::io::Result<Self> {
        let runtime = tokio::runtime::Builder::new_current_thread()
            .enable_all()
            .build()?;
        let handle = runtime.handle().clone();
        let (stop, stopped) = oneshot::channel::<()>();
        // Nothing is ever sent: the receiver only tells when every sender is gone.
        let (sessions, mut sessions_ended) = mpsc::channel::<()>(1);
        let thread = std::thread::Builder::new()
            .name("rivet-online".into())
            .spawn(move || {
                // Spawned tasks run while this thread waits in `block_on`; an error only means
                // the sender was dropped, which also asks the thread to end. The sessions told
                // to close get their time to log out, but a target that does not answer cannot
                // hold the studio's exit longer than the grace.
                runtime.block_on(async move {
                    let _ = stopped.await;
                    let _ = tokio::time::timeout(LOGOUT_GRACE, sessions_ended.recv()).await;
                });
            })?;
        Ok(Self {
            handle,
            stop: Some(stop),
            thread: Some(thread),
            sessions: Some(sessions),
        })
    }

    /// The handle that spawns tasks on the runtime.
    pub fn handle(&self) -> &tokio::runtime::Handle {
        &self.handle
    }

    /// A guard for a new session's task to hold until it ends.
    pub fn session_guard(&self) -> Option<SessionGuard> {
        self.sessions
            .clone()
            .map(|held| SessionGuard { _held: held })
    }
}

impl Drop for Background {
    fn drop(&mut self) {
        self.sessions = None;
        if let Some(stop) = self.stop.take() {
            let _ = stop.send(());
        }
        if let Some(thread) = self.thread.take() {
            let _ = thread.join();
        }
    }
}
