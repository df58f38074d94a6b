//! Cycle-time statistics of one task.

use program_image::TaskKind;

/// The cycle times and start jitter of one task since it was loaded or last reset.
///
/// Times are nanoseconds of the scheduler's monotonic clock. A cycle's time runs from the start
/// of its programs to their end (copying the located areas included, waiting for them not),
/// without the time spent in cycles of tasks of higher priority that interrupted it: the task's
/// own execution time. Its jitter is how much later it started than planned. Kept in memory
/// only, never saved.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TaskStatistics {
    /// The task's name.
    pub name: String,
    /// How it is started.
    pub kind: TaskKind,
    /// 0 (highest) to 31.
    pub priority: u8,
    /// Cycles run (a faulted cycle included).
    pub cycles: u64,
    /// The time of the last cycle.
    pub last_cycle_ns: u64,
    /// The shortest cycle (0 before the first).
    pub min_cycle_ns: u64,
    /// The longest cycle.
    pub max_cycle_ns: u64,
    /// The sum of all cycle times, for the average.
    pub total_cycle_ns: u128,
    /// The start jitter of the last cycle.
    pub last_jitter_ns: u64,
    /// The largest start jitter.
    pub max_jitter_ns: u64,
    /// The sum of all start jitters, for the average.
    pub total_jitter_ns: u128,
    /// Planned cycles of a cyclic task that were dropped because an earlier cycle (its own or
    /// another task's) ran past them; the task kept its phase instead of catching up.
    pub missed_cycles: u64,
    /// Cycles in a row, up to the last, that ran longer than the watchdog time.
    pub consecutive_overruns: u32,
    /// Whether the task has faulted and runs no more.
    pub faulted: bool,
}

impl TaskStatistics {
    /// Empty statistics of a task.
    pub fn new(name: String, kind: TaskKind, priority: u8) -> Self {
        Self {
            name,
            kind,
            priority,
            cycles: 0,
            last_cycle_ns: 0,
            min_cycle_ns: 0,
            max_cycle_ns: 0,
            total_cycle_ns: 0,
            last_jitter_ns: 0,
            max_jitter_ns: 0,
            total_jitter_ns: 0,
            missed_cycles: 0,
            consecutive_overruns: 0,
            faulted: false,
        }
    }

    /// The average cycle time (0 before the first cycle).
    pub fn average_cycle_ns(&self) -> u64 {
        average(self.total_cycle_ns, self.cycles)
    }

    /// The average start jitter (0 before the first cycle).
    pub fn average_jitter_ns(&self) -> u64 {
        average(self.total_jitter_ns, self.cycles)
    }

    /// Counts a cycle that took `cycle_ns` and started `jitter_ns` late.
    pub(crate) fn record(&mut self, cycle_ns: u64, jitter_ns: u64) {
        self.min_cycle_ns = if self.cycles == 0 {
            cycle_ns
        } else {
            self.min_cycle_ns.min(cycle_ns)
        };
        self.cycles += 1;
        self.last_cycle_ns = cycle_ns;
        self.max_cycle_ns = self.max_cycle_ns.max(cycle_ns);
        self.total_cycle_ns += u128::from(cycle_ns);
        self.last_jitter_ns = jitter_ns;
        self.max_jitter_ns = self.max_jitter_ns.max(jitter_ns);
        self.total_jitter_ns += u128::from(jitter_ns);
    }
}

fn average(total: u128, count: u64) -> u64 {
    if count == 0 {
        0
    } else {
        u64::try_from(total / u128::from(count)).unwrap_or(u64::MAX)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn statistics_keep_last_min_max_and_averages() {
        let mut statistics = TaskStatistics::new("Fast".to_owned(), TaskKind::Cyclic, 3);
        assert_eq!(statistics.average_cycle_ns(), 0);
        statistics.record(300, 10);
        statistics.record(100, 50);
        statistics.record(200, 0);
        assert_eq!(statistics.cycles, 3);
        assert_eq!(statistics.last_cycle_ns, 200);
        assert_eq!(statistics.min_cycle_ns, 100);
        assert_eq!(statistics.max_cycle_ns, 300);
        assert_eq!(statistics.average_cycle_ns(), 200);
        assert_eq!(statistics.last_jitter_ns, 0);
        assert_eq!(statistics.max_jitter_ns, 50);
        assert_eq!(statistics.average_jitter_ns(), 20);
    }
}
