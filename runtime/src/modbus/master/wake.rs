//! The `rivet-modbus-wake` thread (`docs/modbus-master.md` §6.1, §6.4): it carries the
//! scheduler's cycle ends to the devices' tokio tasks. Waking a tokio task takes the tokio
//! runtime's locks, which the scheduler never waits for; unparking this thread is a futex
//! wake, and this thread does the rest.

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::thread::{JoinHandle, Thread};
use std::time::Duration;

use super::exchange::DeviceExchange;

/// The longest the thread sleeps without being unparked (it looks at the stop flag then).
const IDLE: Duration = Duration::from_millis(500);

/// A device as the wake thread sees it.
pub struct WakeTarget {
    /// Its exchange.
    pub exchange: Arc<DeviceExchange>,
    /// Whether every cycle end makes a round due (`schedule = "every_cycle"`); otherwise only
    /// a published edge wakes it.
    pub every_cycle: bool,
}

/// The running thread.
pub struct Wake {
    /// The thread, until it is joined.
    thread: Option<JoinHandle<()>>,
    /// Set when the thread is to end.
    stop: Arc<AtomicBool>,
}

impl Wake {
    /// Starts the thread for `targets`, or says why the system would not.
    pub fn spawn(targets: Vec<WakeTarget>) -> std::io::Result<Self> {
        let stop = Arc::new(AtomicBool::new(false));
        let stopping = Arc::clone(&stop);
        let thread = std::thread::Builder::new()
            .name("rivet-modbus-wake".to_owned())
            .spawn(move || {
                // Started by whichever thread starts the master, which may be real-time.
                super::become_normal();
                let mut seen: Vec<u64> = targets
                    .iter()
                    .map(|target| target.exchange.cycle_ends())
                    .collect();
                while !stopping.load(Ordering::Acquire) {
                    for (target, seen) in targets.iter().zip(seen.iter_mut()) {
                        let ends = target.exchange.cycle_ends();
                        if ends == *seen {
                            continue;
                        }
                        *seen = ends;
                        let edge = target.exchange.take_edge_published();
                        if target.every_cycle || edge {
                            target.exchange.notify.notify_one();
                        }
                    }
                    std::thread::park_timeout(IDLE);
                }
            })?;
        Ok(Self {
            thread: Some(thread),
            stop,
        })
    }

    /// The thread to unpark after a cycle end.
    pub fn thread(&self) -> Option<Thread> {
        self.thread.as_ref().map(|thread| thread.thread().clone())
    }
}

impl Drop for Wake {
    fn drop(&mut self) {
        self.stop.store(true, Ordering::Release);
        if let Some(thread) = self.thread.take() {
            thread.thread().unpark();
            // The loop has nothing that can panic but a bug; there is nothing to do about one.
            let _ = thread.join();
        }
    }
}
