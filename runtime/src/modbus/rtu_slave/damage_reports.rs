//! How often the runtime tells its operator about damaged RTU frames: a noisy cable or a wrong
//! line setting damages frames all day, and a line for each would bury everything else the
//! runtime says.

use std::time::{Duration, Instant};

use crate::modbus::rtu_slave::counters::RtuSlaveCounts;

/// The shortest time between two lines about damaged frames; the first damaged frame is
/// reported at once.
pub const DAMAGED_FRAMES_REPORT_INTERVAL: Duration = Duration::from_secs(30);

/// What has been said about damaged frames so far; lives as long as the RTU slave.
#[derive(Debug, Default)]
pub struct DamagedFrameReports {
    /// The damaged frames counted when the last line was said.
    reported: u64,
    /// When the last line was said; `None` before the first.
    last_line_at: Option<Instant>,
}

impl DamagedFrameReports {
    /// The number of frames damaged since the last line, when a line is due at `now` with
    /// the slave's `counts`: some frames were damaged since, and the last line is at least
    /// [`DAMAGED_FRAMES_REPORT_INTERVAL`] old. A `Some` counts as said.
    pub fn due(&mut self, counts: &RtuSlaveCounts, now: Instant) -> Option<u64> {
        let damaged = counts.dropped().checked_sub(self.reported)?;
        if damaged == 0 {
            return None;
        }
        let waited_enough = self.last_line_at.is_none_or(|last| {
            now.saturating_duration_since(last) >= DAMAGED_FRAMES_REPORT_INTERVAL
        });
        if !waited_enough {
            return None;
        }
        self.reported = counts.dropped();
        self.last_line_at = Some(now);
        Some(damaged)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn damaged(bad_crc: u64) -> RtuSlaveCounts {
        RtuSlaveCounts {
            answered: 5,
            bad_crc,
            ..RtuSlaveCounts::default()
        }
    }

    #[test]
    fn the_first_damaged_frame_is_reported_at_once_and_later_ones_at_most_once_an_interval() {
        let mut reports = DamagedFrameReports::default();
        let start = Instant::now();
        assert_eq!(reports.due(&damaged(0), start), None);
        assert_eq!(reports.due(&damaged(1), start), Some(1));
        // More damage soon after waits for the interval, and is then said with its count.
        let soon = start + Duration::from_secs(1);
        assert_eq!(reports.due(&damaged(4), soon), None);
        let almost = start + DAMAGED_FRAMES_REPORT_INTERVAL - Duration::from_millis(1);
        assert_eq!(reports.due(&damaged(9), almost), None);
        let later = start + DAMAGED_FRAMES_REPORT_INTERVAL;
        assert_eq!(reports.due(&damaged(9), later), Some(8));
        // Nothing new: nothing to say, however long it has been.
        let much_later = later + 10 * DAMAGED_FRAMES_REPORT_INTERVAL;
        assert_eq!(reports.due(&damaged(9), much_later), None);
        // A frame damaged after a long quiet time is said at once.
        assert_eq!(reports.due(&damaged(10), much_later), Some(1));
    }
}
