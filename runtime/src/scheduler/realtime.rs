//! Real-time priority for the scheduler's threads (`docs/scheduler.md` §6): on Linux a
//! `SCHED_FIFO` thread runs before every normal thread of the machine, so Modbus clients, the
//! studio or a build on the same processors cannot delay a task's start.

use std::fmt;

/// The scheduling the scheduler's thread runs with, as the status reports it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Realtime {
    /// Normal scheduling (no real-time priority was asked for).
    Normal,
    /// `SCHED_FIFO` at this priority (1–99); the preemption alarm runs one above.
    Fifo(u8),
    /// A real-time priority was asked for and refused: the threads run with normal scheduling.
    Refused {
        /// The priority asked for.
        priority: u8,
        /// What the system said.
        reason: String,
    },
}

impl fmt::Display for Realtime {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Realtime::Normal => write!(f, "normal scheduling"),
            Realtime::Fifo(priority) => write!(f, "real-time priority {priority} (SCHED_FIFO)"),
            Realtime::Refused { priority, reason } => write!(
                f,
                "real-time priority {priority} refused ({reason}): normal scheduling; run the \
                 runtime as root or give it CAP_SYS_NICE (or an RLIMIT_RTPRIO of {priority})"
            ),
        }
    }
}

/// The highest priority `SCHED_FIFO` offers on Linux.
pub const MAX_REALTIME_PRIORITY: u8 = 99;

/// Puts the calling thread at `SCHED_FIFO` priority `priority` (clamped to 1–99) and says what
/// it got.
pub(crate) fn make_current_thread_realtime(priority: u8) -> Realtime {
    let priority = priority.clamp(1, MAX_REALTIME_PRIORITY);
    match fifo_refusal(priority) {
        None => Realtime::Fifo(priority),
        Some(reason) => Realtime::Refused { priority, reason },
    }
}

/// Asks for `SCHED_FIFO` at `priority` for the calling thread; the system's reason when it
/// refuses, `None` when granted.
#[cfg(unix)]
fn fifo_refusal(priority: u8) -> Option<String> {
    use thread_priority::unix::{
        RealtimeThreadSchedulePolicy, ThreadSchedulePolicy, set_thread_priority_and_policy,
        thread_native_id,
    };
    use thread_priority::{Error, ThreadPriority, ThreadPriorityValue};
    let value = match ThreadPriorityValue::try_from(priority) {
        Ok(value) => value,
        Err(reason) => return Some(reason),
    };
    let result = set_thread_priority_and_policy(
        thread_native_id(),
        ThreadPriority::Crossplatform(value),
        ThreadSchedulePolicy::Realtime(RealtimeThreadSchedulePolicy::Fifo),
    );
    match result {
        Ok(()) => None,
        // The system's words for its error number ("Operation not permitted").
        Err(Error::OS(code)) => Some(std::io::Error::from_raw_os_error(code).to_string()),
        Err(other) => Some(other.to_string()),
    }
}

/// Real-time scheduling is offered on Linux (and other Unix systems) only.
#[cfg(not(unix))]
fn fifo_refusal(_priority: u8) -> Option<String> {
    Some("real-time scheduling is offered on Linux only".to_owned())
}

/// Why the system refused to change a thread's scheduling: the `thread-priority` crate's error,
/// whose text names the system's error number.
#[cfg(unix)]
pub(crate) type SchedulingError = thread_priority::Error;

/// Scheduling is never changed where real-time scheduling is not offered, so nothing is
/// refused.
#[cfg(not(unix))]
pub(crate) type SchedulingError = std::convert::Infallible;

/// Puts the calling thread back to normal scheduling (`SCHED_OTHER`, nice 0) when it inherited
/// a real-time policy, and leaves a normal thread as it is; says why when the system refuses.
///
/// A thread started by a `SCHED_FIFO` thread inherits its policy: the Modbus master's threads,
/// which may be started while the scheduler's thread runs at real-time priority, call this
/// first, so a busy network or a slow name lookup never competes with the tasks.
pub(crate) fn make_current_thread_normal() -> Result<(), SchedulingError> {
    #[cfg(unix)]
    {
        use thread_priority::unix::{
            NormalThreadSchedulePolicy, ThreadSchedulePolicy, set_thread_priority_and_policy,
            thread_native_id, thread_schedule_policy,
        };
        use thread_priority::{ThreadPriority, ThreadPriorityValue};
        let normal = ThreadSchedulePolicy::Normal(NormalThreadSchedulePolicy::Other);
        match thread_schedule_policy() {
            Ok(ThreadSchedulePolicy::Normal(_)) => return Ok(()),
            Ok(_) => {}
            Err(error) => return Err(error),
        }
        // The crate maps its portable priorities to nice values for normal policies: the one
        // that gives nice 0, a new thread's default.
        let nice_zero = (0..=MAX_REALTIME_PRIORITY)
            .filter_map(|value| ThreadPriorityValue::try_from(value).ok())
            .map(ThreadPriority::Crossplatform)
            .find(|priority| priority.to_posix(normal).is_ok_and(|nice| nice == 0))
            .unwrap_or(ThreadPriority::Min);
        set_thread_priority_and_policy(thread_native_id(), nice_zero, normal)
    }
    #[cfg(not(unix))]
    Ok(())
}

/// The policy the calling thread runs with: whether it is real-time (`SCHED_FIFO`, `SCHED_RR`
/// or `SCHED_DEADLINE`).
#[cfg(all(test, unix))]
pub(crate) fn current_thread_is_realtime() -> bool {
    use thread_priority::unix::{ThreadSchedulePolicy, thread_schedule_policy};
    matches!(
        thread_schedule_policy(),
        Ok(ThreadSchedulePolicy::Realtime(_))
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_thread_gets_the_priority_or_says_why_not() {
        // Whether the system allows it depends on the user running the tests; either way the
        // answer names the priority, clamped to what SCHED_FIFO offers.
        let got = std::thread::spawn(|| make_current_thread_realtime(120))
            .join()
            .unwrap();
        match got {
            Realtime::Fifo(priority) => assert_eq!(priority, MAX_REALTIME_PRIORITY),
            Realtime::Refused { priority, reason } => {
                assert_eq!(priority, MAX_REALTIME_PRIORITY);
                assert!(!reason.is_empty());
            }
            Realtime::Normal => panic!("a priority was asked for"),
        }
        let refused = Realtime::Refused {
            priority: 40,
            reason: "Operation not permitted".to_owned(),
        };
        assert!(refused.to_string().contains("CAP_SYS_NICE"));
        assert_eq!(
            Realtime::Fifo(40).to_string(),
            "real-time priority 40 (SCHED_FIFO)"
        );
    }

    #[cfg(unix)]
    #[test]
    fn a_thread_started_by_a_realtime_one_goes_back_to_normal_scheduling() {
        let (granted, inherited, normal) = std::thread::spawn(|| {
            let granted = matches!(make_current_thread_realtime(10), Realtime::Fifo(_));
            // A thread started now inherits SCHED_FIFO, as the Modbus master's would.
            std::thread::spawn(move || {
                let inherited = current_thread_is_realtime();
                make_current_thread_normal().unwrap();
                (granted, inherited, !current_thread_is_realtime())
            })
            .join()
            .unwrap()
        })
        .join()
        .unwrap();
        // Without the right to real-time priority there is nothing to undo; with it, the
        // child inherits the policy and gives it up.
        assert_eq!(inherited, granted);
        assert!(normal);
        // A normal thread stays as it is.
        std::thread::spawn(|| make_current_thread_normal().unwrap())
            .join()
            .unwrap();
    }
}
