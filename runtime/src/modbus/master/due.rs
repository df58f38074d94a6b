//! When a device's rounds are due (`docs/modbus-master.md` §6.3): every `interval_ms` from the
//! device's first wait (when it begins polling), or after each cycle end of the I/O task, and
//! at once for a pending rising edge; with the overruns counted as the specification says.

use std::sync::Arc;
use std::time::Duration;

use tokio::time::Instant;

use program_image::modbus_master::Schedule;

use super::exchange::DeviceExchange;

/// What kind of round is due.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RoundKind {
    /// A whole round: cyclic requests and the pending edges'; with the round starts dropped
    /// because the last round was still running (§6.3); none for the device's first round.
    Full {
        /// Round starts dropped (interval) or cycle ends merged (every cycle).
        overruns: u32,
    },
    /// An extra round with only the pending edges' requests; it moves no due time.
    EdgesOnly,
}

impl RoundKind {
    /// The same round without overruns: one the back-off kept from being sent counts none
    /// (`docs/modbus-master.md` §6.8).
    pub fn without_overruns(self) -> Self {
        match self {
            RoundKind::Full { .. } => RoundKind::Full { overruns: 0 },
            RoundKind::EdgesOnly => RoundKind::EdgesOnly,
        }
    }
}

/// A device's schedule as the master's task follows it.
#[derive(Debug)]
pub struct Due {
    /// The device's schedule.
    schedule: Schedule,
    /// The device's exchange: cycle ends, the program's state, pending edges and wake-ups.
    exchange: Arc<DeviceExchange>,
    /// The next due time of an interval schedule.
    next: Instant,
    /// The cycle ends the last every-cycle round answered.
    seen_cycle_ends: u64,
    /// Whether the first round has been due: the schedule starts when the device begins
    /// polling, not when the master was prepared.
    began: bool,
    /// How often an every-cycle device is polled while its task has no cycles (the program is
    /// stopped): its task's interval, or 100 ms.
    idle_interval: Duration,
}

impl Due {
    /// The schedule of a device; it starts at the device's first [`Due::wait`], not now (the
    /// master is prepared before its devices begin polling).
    pub fn new(schedule: Schedule, exchange: Arc<DeviceExchange>, idle_interval: Duration) -> Self {
        Self {
            schedule,
            seen_cycle_ends: exchange.cycle_ends(),
            exchange,
            next: Instant::now(),
            began: false,
            idle_interval,
        }
    }

    /// Waits until a round is due. It is called when the device's last round has ended (or
    /// before its first), so what it finds passed on entry is what that round made wait: only
    /// that counts as overruns (§6.3). Due times or cycle ends that pass while no round runs
    /// (the master's thread was slow to wake) are merged into the next round uncounted.
    pub async fn wait(&mut self) -> RoundKind {
        // One reading of the counter serves the start and the count: a cycle end between two
        // readings would count as an overrun of a round that never ran.
        let cycle_ends = self.exchange.cycle_ends();
        if !self.began {
            self.begin(cycle_ends);
        }
        match self.schedule {
            Schedule::Interval { interval_ms } => {
                let overruns = self.passed_due_times(interval_ms);
                loop {
                    // Biased, due time first: a late full round is never overtaken by an
                    // edges-only one notified in the same poll, which would move it further.
                    tokio::select! {
                        biased;
                        () = tokio::time::sleep_until(self.next) => {
                            self.advance(interval_ms);
                            return RoundKind::Full { overruns };
                        }
                        () = self.exchange.notify.notified() => {
                            if self.exchange.has_pending() {
                                return RoundKind::EdgesOnly;
                            }
                        }
                    }
                }
            }
            Schedule::EveryCycle => {
                // The first cycle end during the last round makes the next round due; the
                // others are merged into it.
                let during_round = cycle_ends.saturating_sub(self.seen_cycle_ends);
                let overruns = u32::try_from(during_round.saturating_sub(1)).unwrap_or(u32::MAX);
                loop {
                    let ends = self.exchange.cycle_ends();
                    if ends > self.seen_cycle_ends {
                        self.seen_cycle_ends = ends;
                        return RoundKind::Full { overruns };
                    }
                    // A stop wakes nobody (the scheduler never touches tokio's locks): the wait
                    // looks at the program's state at the task's pace. Stopped, there are no
                    // cycles to follow, and the device is still read at that pace (§6.10).
                    tokio::select! {
                        () = tokio::time::sleep(self.idle_interval) => {
                            if !self.exchange.running()
                                && self.exchange.cycle_ends() == self.seen_cycle_ends
                            {
                                return RoundKind::Full { overruns: 0 };
                            }
                        }
                        () = self.exchange.notify.notified() => {}
                    }
                }
            }
        }
    }

    /// Starts the schedule when the device begins polling. A master is prepared on the loading
    /// thread and its devices begin polling only after the master it replaces has stopped
    /// (`MasterStarter::go`), while the new program's cycles already run: the due times and
    /// cycle ends passed meanwhile found no round running, so they are no overruns (§6.3
    /// counts only what a running round made wait). The first round is due at once, the
    /// interval's due times count from it, and cycle ends already passed make one round;
    /// `cycle_ends` is the counter as the first wait read it.
    fn begin(&mut self, cycle_ends: u64) {
        self.began = true;
        self.next = Instant::now();
        self.seen_cycle_ends = cycle_ends.saturating_sub(1).max(self.seen_cycle_ends);
    }

    /// How many due times after the next one have passed by now: when the last round ended
    /// after its successor was due, those are the round starts it made the device drop.
    fn passed_due_times(&self, interval_ms: u32) -> u32 {
        let interval = Duration::from_millis(u64::from(interval_ms.max(1)));
        let late = Instant::now().saturating_duration_since(self.next);
        u32::try_from(late.as_nanos() / interval.as_nanos()).unwrap_or(u32::MAX)
    }

    /// Moves the due time past the round that starts now, dropping every due time passed.
    fn advance(&mut self, interval_ms: u32) {
        let interval = Duration::from_millis(u64::from(interval_ms.max(1)));
        let passed = self.passed_due_times(interval_ms);
        self.next += interval * passed.saturating_add(1);
    }
}

#[cfg(test)]
mod tests {
    use program_image::modbus_master::{
        ChannelDef, DeviceDef, Direction, Link, OnError, Trigger, WordOrder,
    };
    use program_image::{Elementary, ModbusTable};

    use super::*;

    fn exchange() -> Arc<DeviceExchange> {
        Arc::new(DeviceExchange::new(&exchange_device()))
    }

    /// A device without channels, polled after every cycle.
    fn exchange_device() -> DeviceDef {
        DeviceDef {
            name: "Drive".to_owned(),
            link: Link::Tcp {
                host: "127.0.0.1".to_owned(),
                port: 502,
            },
            unit_id: 1,
            timeout_ms: 100,
            task: 0,
            schedule: Schedule::EveryCycle,
            word_order: WordOrder::HighFirst,
            max_read_gap: 0,
            status: None,
            channels: Vec::new(),
        }
    }

    /// An exchange whose device writes one register on the rising edge of `Main.xSend`.
    fn exchange_with_an_edge() -> Arc<DeviceExchange> {
        let mut device = DeviceDef {
            channels: vec![ChannelDef {
                variable: "Main.iOut".to_owned(),
                table: ModbusTable::HoldingRegisters,
                address: 0,
                value_type: Elementary::Int,
                count: 1,
                direction: Direction::Write,
                function_code: 16,
                trigger: Trigger::RisingEdge {
                    variable: "Main.xSend".to_owned(),
                },
                on_error: OnError::KeepLastValue,
                error_flag: None,
            }],
            ..exchange_device()
        };
        device.schedule = Schedule::Interval { interval_ms: 10 };
        Arc::new(DeviceExchange::new(&device))
    }

    #[tokio::test(start_paused = true)]
    async fn a_late_due_time_is_served_before_an_edge_notified_with_it() {
        // A round ended after its successor was due, and an edge was notified meanwhile: the
        // full round goes first (the edge's requests go in it). Were the two branches polled
        // in a random order, about one trial in two would start an edges-only round first.
        for trial in 0..20 {
            let exchange = exchange_with_an_edge();
            let schedule = Schedule::Interval { interval_ms: 10 };
            let mut due = Due::new(schedule, Arc::clone(&exchange), Duration::from_millis(100));
            assert_eq!(due.wait().await, RoundKind::Full { overruns: 0 });
            tokio::time::advance(Duration::from_millis(15)).await;
            if let Some(mut output) = exchange.try_output() {
                output.pending[0] = true;
            }
            assert!(exchange.has_pending(), "trial {trial}");
            exchange.notify.notify_one();
            assert_eq!(
                due.wait().await,
                RoundKind::Full { overruns: 0 },
                "trial {trial}"
            );
        }
    }

    #[tokio::test(start_paused = true)]
    async fn a_late_round_starts_its_successor_at_once_and_drops_the_due_times_passed() {
        let schedule = Schedule::Interval { interval_ms: 10 };
        let mut due = Due::new(schedule, exchange(), Duration::from_millis(100));
        let start = Instant::now();
        assert_eq!(due.wait().await, RoundKind::Full { overruns: 0 });
        // A round of 35 ms: the round due at 10 ms starts at once, those of 20 and 30 ms are
        // dropped, and the next is due at 40 ms.
        tokio::time::advance(Duration::from_millis(35)).await;
        assert_eq!(due.wait().await, RoundKind::Full { overruns: 2 });
        assert_eq!(Instant::now() - start, Duration::from_millis(35));
        assert_eq!(due.wait().await, RoundKind::Full { overruns: 0 });
        assert_eq!(Instant::now() - start, Duration::from_millis(40));
    }

    #[tokio::test(start_paused = true)]
    async fn due_times_passed_before_the_device_began_polling_are_no_overruns() {
        // The master is prepared at load; its devices begin polling 35 ms later, once the old
        // master has stopped. No round ran meanwhile, so nothing was dropped by one.
        let schedule = Schedule::Interval { interval_ms: 10 };
        let mut due = Due::new(schedule, exchange(), Duration::from_millis(100));
        tokio::time::advance(Duration::from_millis(35)).await;
        let began = Instant::now();
        assert_eq!(due.wait().await, RoundKind::Full { overruns: 0 });
        assert_eq!(Instant::now(), began);
        // The interval counts from the first round.
        assert_eq!(due.wait().await, RoundKind::Full { overruns: 0 });
        assert_eq!(Instant::now() - began, Duration::from_millis(10));
    }

    #[tokio::test(start_paused = true)]
    async fn cycle_ends_before_the_device_began_polling_make_one_round_without_overruns() {
        // The new program's first cycles end before its master's devices begin polling (the
        // start-up of a download): no round was running at those ends.
        let exchange = exchange();
        let mut due = Due::new(
            Schedule::EveryCycle,
            Arc::clone(&exchange),
            Duration::from_millis(100),
        );
        exchange.set_running(true);
        exchange.cycle_ended(false);
        exchange.cycle_ended(false);
        assert_eq!(due.wait().await, RoundKind::Full { overruns: 0 });
        // From then on, the ends while a round runs are counted as §6.3 says: the first is
        // the next round's, the second merged into it.
        exchange.cycle_ended(false);
        exchange.cycle_ended(false);
        assert_eq!(due.wait().await, RoundKind::Full { overruns: 1 });
        // Without a cycle end since the last round, no round is due.
        exchange.cycle_ended(false);
        assert_eq!(due.wait().await, RoundKind::Full { overruns: 0 });
        let waited = tokio::time::timeout(Duration::from_millis(50), due.wait()).await;
        assert!(
            waited.is_err(),
            "no cycle ended, yet a round was due: {waited:?}"
        );
    }

    #[tokio::test(start_paused = true)]
    async fn due_times_passed_while_no_round_runs_are_no_overruns() {
        let schedule = Schedule::Interval { interval_ms: 10 };
        let mut due = Due::new(schedule, exchange(), Duration::from_millis(100));
        let start = Instant::now();
        assert_eq!(due.wait().await, RoundKind::Full { overruns: 0 });
        // The round ends at once; the master's thread then wakes 35 ms late (a loaded
        // machine): the rounds due at 20 and 30 ms are dropped, but no round made them wait.
        let (waited, ()) = tokio::join!(due.wait(), async {
            tokio::time::advance(Duration::from_millis(35)).await;
        });
        assert_eq!(waited, RoundKind::Full { overruns: 0 });
        assert_eq!(Instant::now() - start, Duration::from_millis(35));
        assert_eq!(due.wait().await, RoundKind::Full { overruns: 0 });
        assert_eq!(Instant::now() - start, Duration::from_millis(40));
    }

    #[tokio::test(start_paused = true)]
    async fn cycle_ends_while_no_round_runs_make_one_round_without_overruns() {
        let exchange = exchange();
        let mut due = Due::new(
            Schedule::EveryCycle,
            Arc::clone(&exchange),
            Duration::from_millis(100),
        );
        exchange.set_running(true);
        exchange.cycle_ended(false);
        assert_eq!(due.wait().await, RoundKind::Full { overruns: 0 });
        // The round ends before the next cycle end; two cycles then end before the device's
        // task is woken (the wake thread or the master's thread was slow).
        let (waited, ()) = tokio::join!(due.wait(), async {
            exchange.cycle_ended(false);
            exchange.cycle_ended(false);
            exchange.notify.notify_one();
        });
        assert_eq!(waited, RoundKind::Full { overruns: 0 });
    }

    #[tokio::test(start_paused = true)]
    async fn cycle_ends_during_a_round_are_merged_into_one_more_round() {
        let exchange = exchange();
        let mut due = Due::new(
            Schedule::EveryCycle,
            Arc::clone(&exchange),
            Duration::from_millis(100),
        );
        exchange.set_running(true);
        exchange.cycle_ended(false);
        assert_eq!(due.wait().await, RoundKind::Full { overruns: 0 });
        for _ in 0..3 {
            exchange.cycle_ended(false);
        }
        assert_eq!(due.wait().await, RoundKind::Full { overruns: 2 });
        // Stopped, the device is read at its task's pace without cycle ends.
        exchange.set_running(false);
        let start = Instant::now();
        assert_eq!(due.wait().await, RoundKind::Full { overruns: 0 });
        assert_eq!(Instant::now() - start, Duration::from_millis(100));
    }

    #[tokio::test(start_paused = true)]
    async fn a_stop_while_waiting_for_a_cycle_end_turns_to_polling_at_the_task_s_pace() {
        let exchange = exchange();
        let mut due = Due::new(
            Schedule::EveryCycle,
            Arc::clone(&exchange),
            Duration::from_millis(100),
        );
        exchange.set_running(true);
        // The round waits for a cycle end that never comes: the program stops meanwhile, and
        // nobody notifies the device.
        let stopping = async {
            tokio::time::sleep(Duration::from_millis(30)).await;
            exchange.set_running(false);
        };
        let waited = tokio::time::timeout(Duration::from_secs(10), async {
            tokio::join!(due.wait(), stopping).0
        })
        .await;
        assert_eq!(waited, Ok(RoundKind::Full { overruns: 0 }));
        // And it goes on being due at that pace.
        let again = tokio::time::timeout(Duration::from_secs(10), due.wait()).await;
        assert_eq!(again, Ok(RoundKind::Full { overruns: 0 }));
    }
}
