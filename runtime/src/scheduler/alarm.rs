//! The preemption alarm: a thread that sets a flag at the planned start of the next task that
//! may interrupt the cycle in progress.
//!
//! The interpreter reads the flag at every safe point, where a relaxed load costs about a
//! nanosecond; reading the clock there instead would slow every loop. The scheduler arms the
//! alarm before each cycle (and again when a preempting cycle ends) for the earliest start of a
//! task of higher priority than the running one, and disarms it when the outermost cycle ends.

use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::{Arc, Condvar, Mutex, MutexGuard, PoisonError};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

/// A handle on the alarm's thread; dropping it ends the thread.
pub(super) struct Alarm {
    shared: Arc<Shared>,
    thread: Option<JoinHandle<()>>,
}

/// What the scheduler's thread and the alarm's thread share.
struct Shared {
    /// Set at the armed time; read by the interpreter at its safe points.
    due: AtomicBool,
    state: Mutex<State>,
    changed: Condvar,
    /// Counts the changes of `state`, so that the thread can spin without taking the lock and
    /// still see at once that the scheduler armed it for another time or asked it to end.
    revision: AtomicU64,
    /// How long before the armed time the thread stops sleeping and spins instead: a sleep
    /// wakes late by the system's timer slack and wake-up latency.
    spin: Duration,
}

struct State {
    /// When to set the flag; `None` while disarmed.
    at: Option<Instant>,
    /// Whether the thread should end.
    quit: bool,
}

impl Alarm {
    /// Starts the alarm's thread, disarmed, spinning `spin` before each armed time; `None` when
    /// the system refuses a thread (then the scheduler runs without preemption). With
    /// `realtime_priority` the thread asks for `SCHED_FIFO` one above it, so that it runs while
    /// the scheduler's thread is busy in a cycle even on one processor.
    pub(super) fn spawn(spin: Duration, realtime_priority: Option<u8>) -> Option<Self> {
        let shared = Arc::new(Shared {
            due: AtomicBool::new(false),
            state: Mutex::new(State {
                at: None,
                quit: false,
            }),
            changed: Condvar::new(),
            revision: AtomicU64::new(0),
            spin,
        });
        let watched = Arc::clone(&shared);
        let thread = std::thread::Builder::new()
            .name("rivet-preemption-alarm".to_owned())
            .spawn(move || {
                if let Some(priority) = realtime_priority {
                    // The scheduler's thread asks with the same rights and reports a refusal.
                    let _ =
                        super::realtime::make_current_thread_realtime(priority.saturating_add(1));
                }
                watched.run();
            })
            .ok()?;
        Some(Self {
            shared,
            thread: Some(thread),
        })
    }

    /// The flag the interpreter reads at its safe points.
    pub(super) fn due(&self) -> &AtomicBool {
        &self.shared.due
    }

    /// Clears the flag and sets it again at `at` (at once when `at` has passed); `None`
    /// disarms.
    pub(super) fn arm(&self, at: Option<Instant>) {
        let mut state = self.shared.lock();
        // Under the lock, so a flag the thread sets for an older time cannot outlive this.
        self.shared.due.store(false, Ordering::Relaxed);
        match at {
            Some(at) if at <= Instant::now() => {
                self.shared.due.store(true, Ordering::Relaxed);
                state.at = None;
                self.shared.revision.fetch_add(1, Ordering::Release);
            }
            // The thread is woken only when the time changes: most cycles arm it for the
            // same next start as the cycle before, and a wake-up costs a context switch.
            _ if state.at == at => {}
            _ => {
                state.at = at;
                self.shared.revision.fetch_add(1, Ordering::Release);
                self.shared.changed.notify_one();
            }
        }
    }
}

impl Shared {
    fn lock(&self) -> MutexGuard<'_, State> {
        self.state.lock().unwrap_or_else(PoisonError::into_inner)
    }

    /// The alarm's thread: waits for the armed time and sets the flag.
    fn run(&self) {
        let mut state = self.lock();
        loop {
            if state.quit {
                return;
            }
            state = match state.at {
                None => self
                    .changed
                    .wait(state)
                    .unwrap_or_else(PoisonError::into_inner),
                Some(at) => {
                    let now = Instant::now();
                    if now >= at {
                        self.due.store(true, Ordering::Relaxed);
                        state.at = None;
                        continue;
                    }
                    let wait = at - now;
                    if wait <= self.spin {
                        // Unlocked meanwhile, so the scheduler can arm it again; the loop reads
                        // only the clock and the revision, so it does not contend for the lock
                        // the scheduler takes before every cycle. A busy loop, not
                        // `yield_now`: a thread that yields in a loop looks like a processor hog
                        // to Linux's normal scheduler, which then lets other threads run first
                        // for milliseconds; the jitter benchmark measured the preempting task's
                        // start p95 at 3.2 ms that way, 4–44 µs with the busy loop.
                        let revision = self.revision.load(Ordering::Acquire);
                        drop(state);
                        while Instant::now() < at
                            && self.revision.load(Ordering::Acquire) == revision
                        {
                            std::hint::spin_loop();
                        }
                        state = self.lock();
                        continue;
                    }
                    self.changed
                        .wait_timeout(state, wait - self.spin)
                        .unwrap_or_else(PoisonError::into_inner)
                        .0
                }
            };
        }
    }
}

impl Drop for Alarm {
    fn drop(&mut self) {
        self.shared.lock().quit = true;
        self.shared.revision.fetch_add(1, Ordering::Release);
        self.shared.changed.notify_one();
        if let Some(thread) = self.thread.take() {
            // The thread only waits and stores a flag; it has nothing to report.
            let _ = thread.join();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn is_set(alarm: &Alarm) -> bool {
        alarm.due().load(Ordering::Relaxed)
    }

    /// Waits until the flag is set, for at most ten seconds.
    fn wait_until_set(alarm: &Alarm) {
        let start = Instant::now();
        while !is_set(alarm) {
            assert!(
                start.elapsed() < Duration::from_secs(10),
                "the alarm never rang"
            );
            std::thread::sleep(Duration::from_millis(1));
        }
    }

    #[test]
    fn the_flag_is_set_at_the_armed_time_and_cleared_by_arming_again() {
        for spin in [Duration::ZERO, Duration::from_micros(200)] {
            let alarm = Alarm::spawn(spin, None).unwrap();
            assert!(!is_set(&alarm));
            // A time that has passed sets the flag at once.
            alarm.arm(Some(Instant::now()));
            assert!(is_set(&alarm));
            alarm.arm(None);
            assert!(!is_set(&alarm));
            alarm.arm(Some(Instant::now() + Duration::from_millis(2)));
            wait_until_set(&alarm);
            // Armed far away, then nearer: the nearer time counts.
            alarm.arm(Some(Instant::now() + Duration::from_secs(3600)));
            assert!(!is_set(&alarm));
            alarm.arm(Some(Instant::now() + Duration::from_millis(2)));
            wait_until_set(&alarm);
        }
    }
}
