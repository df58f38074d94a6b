//! The record of one task cycle, for those who want every cycle rather than the statistics.

/// One finished cycle, sent to [`super::SchedulerOptions::cycle_log`] when one is given.
///
/// Times are nanoseconds of the scheduler's monotonic clock (since the scheduler started).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CycleRecord {
    /// The task, by its index in the task table.
    pub task: usize,
    /// When the cycle was planned to start.
    pub planned_ns: u64,
    /// When it started: `started_ns - planned_ns` is its start jitter.
    pub started_ns: u64,
    /// When it ended, time spent in cycles that interrupted it included.
    pub ended_ns: u64,
    /// The time spent in cycles of tasks of higher priority that interrupted it.
    pub preempted_ns: u64,
    /// The task whose cycle this one interrupted, if it ran nested in another.
    pub interrupted: Option<usize>,
}

impl CycleRecord {
    /// The start jitter: how much later than planned the cycle started.
    pub fn jitter_ns(&self) -> u64 {
        self.started_ns.saturating_sub(self.planned_ns)
    }

    /// The cycle's own execution time, without the cycles that interrupted it.
    pub fn own_ns(&self) -> u64 {
        self.ended_ns
            .saturating_sub(self.started_ns)
            .saturating_sub(self.preempted_ns)
    }
}
