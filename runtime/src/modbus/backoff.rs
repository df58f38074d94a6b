//! The waits between attempts to open a connection or a port that failed
//! (`docs/modbus-master.md` §6.8).

use std::time::Duration;

/// The waits, in milliseconds: doubling from 100 ms, then 5 s from the seventh attempt on.
const WAITS_MS: [u64; 7] = [100, 200, 400, 800, 1600, 3200, 5000];

/// Back-off after failed attempts: each failure waits longer, up to 5 s, and a success starts
/// again from 100 ms. Lives as long as the connection or port it paces; not saved.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Backoff {
    /// How many waits have been given since the last success (saturating at the last step).
    failures: usize,
}

impl Backoff {
    /// The wait before the next attempt, after one more failure.
    pub fn next_wait(&mut self) -> Duration {
        let wait = WAITS_MS[self.failures.min(WAITS_MS.len() - 1)];
        self.failures = self.failures.saturating_add(1);
        Duration::from_millis(wait)
    }

    /// Starts again from the shortest wait, after an attempt that worked.
    pub fn reset(&mut self) {
        self.failures = 0;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn waits_double_from_100_ms_stay_at_5_s_and_start_again_after_a_success() {
        let mut backoff = Backoff::default();
        let waits: Vec<u128> = (0..9).map(|_| backoff.next_wait().as_millis()).collect();
        assert_eq!(waits, [100, 200, 400, 800, 1600, 3200, 5000, 5000, 5000]);
        backoff.reset();
        assert_eq!(backoff.next_wait(), Duration::from_millis(100));
    }
}
