//! When a device's rounds are due (`docs/modbus-master.md` §6.3): every `interval_ms` from the
//! master's start, or after each cycle end of the I/O task, and at once for a pending rising
//! edge; with the overruns counted as the specification says.

use std::sync::Arc;
use std::time::{Duration, Instant};

use program_image::modbus_master::Schedule;

use super::exchange::DeviceExchange;

/// What kind of round is due.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RoundKind {
    /// A whole round: cyclic requests and the pending edges'; with the round starts dropped
    /// since the last one.
    Full {
        /// Round starts dropped (interval) or cycle ends merged (every cycle).
        overruns: u32,
    },
    /// An extra round with only the pending edges' requests; it moves no due time.
    EdgesOnly,
}

/// A device's schedule as the master's task follows it.
#[derive(Debug)]
pub struct Due {
    schedule: Schedule,
    exchange: Arc<DeviceExchange>,
    /// The next due time of an interval schedule.
    next: Instant,
    /// The cycle ends the last every-cycle round answered.
    seen_cycle_ends: u64,
    /// How often an every-cycle device is polled while its task has no cycles (the program is
    /// stopped): its task's interval, or 100 ms.
    idle_interval: Duration,
}

impl Due {
    /// The schedule of a device, starting now.
    pub fn new(schedule: Schedule, exchange: Arc<DeviceExchange>, idle_interval: Duration) -> Self {
        Self {
            schedule,
            seen_cycle_ends: exchange.cycle_ends(),
            exchange,
            next: Instant::now(),
            idle_interval,
        }
    }

    /// Waits until a round is due.
    pub async fn wait(&mut self) -> RoundKind {
        match self.schedule {
            Schedule::Interval { interval_ms } => loop {
                let next = tokio::time::Instant::from_std(self.next);
                tokio::select! {
                    () = tokio::time::sleep_until(next) => {
                        let overruns = self.advance(interval_ms);
                        return RoundKind::Full { overruns };
                    }
                    () = self.exchange.notify.notified() => {
                        if self.exchange.has_pending() {
                            return RoundKind::EdgesOnly;
                        }
                    }
                }
            },
            Schedule::EveryCycle => loop {
                let ends = self.exchange.cycle_ends();
                if ends > self.seen_cycle_ends {
                    let merged = ends - self.seen_cycle_ends - 1;
                    self.seen_cycle_ends = ends;
                    return RoundKind::Full {
                        overruns: u32::try_from(merged).unwrap_or(u32::MAX),
                    };
                }
                if self.exchange.running() {
                    self.exchange.notify.notified().await;
                } else {
                    // No cycles to follow: the device is still read, at the task's pace.
                    tokio::select! {
                        () = tokio::time::sleep(self.idle_interval) => {
                            return RoundKind::Full { overruns: 0 };
                        }
                        () = self.exchange.notify.notified() => {}
                    }
                }
            },
        }
    }

    /// Moves the due time past the round that starts now. When the last round ended after
    /// this one was due, every due time passed meanwhile is dropped, and their number returned.
    fn advance(&mut self, interval_ms: u32) -> u32 {
        let interval = Duration::from_millis(u64::from(interval_ms.max(1)));
        let late = Instant::now().saturating_duration_since(self.next);
        let passed = u32::try_from(late.as_nanos() / interval.as_nanos()).unwrap_or(u32::MAX);
        self.next += interval * passed.saturating_add(1);
        passed
    }
}
