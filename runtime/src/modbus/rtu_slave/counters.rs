//! What the RTU slave has received, counted for people reading the runtime's messages.

use std::sync::atomic::{AtomicU64, Ordering};

use crate::modbus::rtu_slave::frame::DroppedFrame;

/// The RTU slave's counters, shared between its task and whoever reports them; they count
/// from the start of the runtime and are not saved.
#[derive(Debug, Default)]
pub struct RtuSlaveCounters {
    /// Requests for this slave that were answered.
    answered: AtomicU64,
    /// Broadcast writes run (address 0, no answer).
    broadcasts: AtomicU64,
    /// Frames for another slave, broadcast reads and exception answers, ignored.
    ignored: AtomicU64,
    /// Frames dropped for a bad CRC or too few bytes.
    bad_crc: AtomicU64,
    /// Frames dropped for running past 256 bytes.
    too_long: AtomicU64,
}

/// A snapshot of [`RtuSlaveCounters`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RtuSlaveCounts {
    /// Requests for this slave that were answered.
    pub answered: u64,
    /// Broadcast writes run (address 0, no answer).
    pub broadcasts: u64,
    /// Frames for another slave, broadcast reads and exception answers, ignored.
    pub ignored: u64,
    /// Frames dropped for a bad CRC or too few bytes.
    pub bad_crc: u64,
    /// Frames dropped for running past 256 bytes.
    pub too_long: u64,
}

impl RtuSlaveCounters {
    /// The counts now.
    pub fn counts(&self) -> RtuSlaveCounts {
        let load = |counter: &AtomicU64| counter.load(Ordering::Relaxed);
        RtuSlaveCounts {
            answered: load(&self.answered),
            broadcasts: load(&self.broadcasts),
            ignored: load(&self.ignored),
            bad_crc: load(&self.bad_crc),
            too_long: load(&self.too_long),
        }
    }

    pub(super) fn count_answered(&self) {
        self.answered.fetch_add(1, Ordering::Relaxed);
    }

    pub(super) fn count_broadcast(&self) {
        self.broadcasts.fetch_add(1, Ordering::Relaxed);
    }

    pub(super) fn count_ignored(&self) {
        self.ignored.fetch_add(1, Ordering::Relaxed);
    }

    pub(super) fn count_dropped(&self, dropped: DroppedFrame) {
        let counter = match dropped {
            DroppedFrame::BadCrc => &self.bad_crc,
            DroppedFrame::TooLong => &self.too_long,
        };
        counter.fetch_add(1, Ordering::Relaxed);
    }
}

impl RtuSlaveCounts {
    /// Every frame received, whatever became of it.
    pub fn frames(&self) -> u64 {
        self.answered + self.broadcasts + self.ignored + self.bad_crc + self.too_long
    }

    /// Frames dropped without an answer because they were damaged.
    pub fn dropped(&self) -> u64 {
        self.bad_crc + self.too_long
    }
}

impl std::fmt::Display for RtuSlaveCounts {
    /// `12 answered, 0 broadcast, 1 for other slaves, 2 dropped (2 bad CRC, 0 too long)`.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{} answered, {} broadcast, {} for other slaves, {} dropped ({} bad CRC, {} too long)",
            self.answered,
            self.broadcasts,
            self.ignored,
            self.dropped(),
            self.bad_crc,
            self.too_long
        )
    }
}
