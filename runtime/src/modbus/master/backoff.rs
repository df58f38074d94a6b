//! The back-off between failed connection attempts (`docs/modbus-master.md` §6.8): 100 ms,
//! then doubling up to 5 s, reset by the first request that succeeds.

use std::time::{Duration, Instant};

/// The waits after the first failures, in milliseconds; the last one holds from then on.
const STEPS_MS: [u64; 7] = [100, 200, 400, 800, 1600, 3200, 5000];

/// When the next connection attempt (or port open) may be made.
#[derive(Clone, Debug, Default)]
pub struct Backoff {
    /// Failed attempts in a row.
    failures: usize,
    /// Not before this instant; `None` at once.
    not_before: Option<Instant>,
}

impl Backoff {
    /// Counts a failed attempt made at `now` and returns how long the next one waits.
    pub fn failed(&mut self, now: Instant) -> Duration {
        let step = STEPS_MS[self.failures.min(STEPS_MS.len() - 1)];
        self.failures += 1;
        let wait = Duration::from_millis(step);
        self.not_before = Some(now + wait);
        wait
    }

    /// Forgets the failures: the next attempt is made at once.
    pub fn succeeded(&mut self) {
        self.failures = 0;
        self.not_before = None;
    }

    /// Whether an attempt may be made at `now`.
    pub fn may_try(&self, now: Instant) -> bool {
        self.not_before.is_none_or(|at| now >= at)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_waits_double_up_to_five_seconds_and_a_success_resets_them() {
        let mut backoff = Backoff::default();
        let now = Instant::now();
        assert!(backoff.may_try(now));
        let waits: Vec<u64> = (0..9)
            .map(|_| backoff.failed(now).as_millis() as u64)
            .collect();
        assert_eq!(waits, [100, 200, 400, 800, 1600, 3200, 5000, 5000, 5000]);
        assert!(!backoff.may_try(now));
        assert!(backoff.may_try(now + Duration::from_millis(5000)));
        backoff.succeeded();
        assert!(backoff.may_try(now));
        assert_eq!(backoff.failed(now), Duration::from_millis(100));
    }
}
