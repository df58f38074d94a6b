//! The exchange between a device's master task and the scheduler (`docs/modbus-master.md` §6.4):
//! an input image the master replaces whole after each round, an output image the scheduler
//! replaces whole at the end of each cycle of the device's I/O task, and the counter of those
//! cycle ends.
//!
//! The scheduler only ever tries the two mutexes, as it does the located areas: a busy input
//! image makes its cycle copy the round it kept from before (the new round arrives one cycle
//! later), and a busy output image keeps the cycle's outputs and edges for the next cycle's end.
//! The master holds either mutex only to copy bytes, never across a request.

use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::{Mutex, MutexGuard, PoisonError, TryLockError};

use program_image::modbus_master::{DeviceDef, Trigger};

use super::status::{DeviceStatus, STATUS_BYTES};

/// Where each channel's values lie in the images' value buffers: channels in the project's
/// order, each taking its values' bytes in the program's memory layout.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ValueLayout {
    /// Per channel, its first byte and its length.
    pub ranges: Vec<(usize, usize)>,
    /// Per channel, the index of its trigger in [`ValueLayout::triggers`], for a rising-edge
    /// channel.
    pub trigger_of: Vec<Option<usize>>,
    /// The distinct trigger variables in the order they first appear (paths compared without
    /// case), as `plan` ranks them.
    pub triggers: Vec<String>,
    /// Bytes of all channels' values.
    pub total: usize,
}

impl ValueLayout {
    /// The layout of `device`'s channels.
    pub fn of(device: &DeviceDef) -> Self {
        let mut ranges = Vec::with_capacity(device.channels.len());
        let mut trigger_of = Vec::with_capacity(device.channels.len());
        let mut triggers: Vec<String> = Vec::new();
        let mut total = 0;
        for channel in &device.channels {
            let length = channel.value_bytes() as usize;
            ranges.push((total, length));
            total += length;
            trigger_of.push(match &channel.trigger {
                Trigger::Cyclic => None,
                Trigger::RisingEdge { variable } => Some(
                    match triggers
                        .iter()
                        .position(|known| known.eq_ignore_ascii_case(variable))
                    {
                        Some(index) => index,
                        None => {
                            triggers.push(variable.clone());
                            triggers.len() - 1
                        }
                    },
                ),
            });
        }
        Self {
            ranges,
            trigger_of,
            triggers,
            total,
        }
    }

    /// The bytes of channel `channel` in `values`.
    pub fn slice<'v>(&self, values: &'v [u8], channel: usize) -> &'v [u8] {
        let (start, length) = self.ranges.get(channel).copied().unwrap_or((0, 0));
        values.get(start..start + length).unwrap_or(&[])
    }

    /// The bytes of channel `channel` in `values`, to write.
    pub fn slice_mut<'v>(&self, values: &'v mut [u8], channel: usize) -> &'v mut [u8] {
        let (start, length) = self.ranges.get(channel).copied().unwrap_or((0, 0));
        values.get_mut(start..start + length).unwrap_or(&mut [])
    }
}

/// The newest complete round of a device, as the program is to see it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct InputImage {
    /// Rounds ended since the master started; 0 before the first (nothing is copied then).
    pub round: u64,
    /// Every channel's values ([`ValueLayout`]); only read channels' matter.
    pub values: Vec<u8>,
    /// Per channel, whether its values are to be copied: a read channel that has delivered at
    /// least once, or that failed with `set_to_zero`.
    pub deliver: Vec<bool>,
    /// Per channel, whether the last request that carried it failed (its error flag).
    pub failed: Vec<bool>,
    /// The `MODBUS_DEVICE_STATUS` value's bytes (`status.rs`).
    pub status: [u8; STATUS_BYTES],
}

/// The outputs of the newest ended cycle of a device's I/O task.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct OutputImage {
    /// Whether a cycle has ended since the program started: nothing is written before.
    pub published: bool,
    /// Every channel's values at the end of the newest cycle; only write channels' matter.
    pub values: Vec<u8>,
    /// Per trigger, whether its group is pending: a rising edge the master has not yet served.
    pub pending: Vec<bool>,
    /// The values of rising-edge write channels latched at the cycle end that saw their edge.
    pub edge_values: Vec<u8>,
}

impl InputImage {
    /// The image before any round: nothing to deliver, and the status of a device not yet
    /// polled (`eLastError` is `NOT_YET_POLLED`, every counter 0).
    pub fn empty(layout: &ValueLayout) -> Self {
        Self {
            round: 0,
            values: vec![0; layout.total],
            deliver: vec![false; layout.ranges.len()],
            failed: vec![false; layout.ranges.len()],
            status: DeviceStatus::new("", false).encode(),
        }
    }

    /// Copies `other` into `self` without allocating (both have the same layout).
    pub fn copy_from(&mut self, other: &InputImage) {
        self.round = other.round;
        copy_same(&other.values, &mut self.values);
        copy_same(&other.deliver, &mut self.deliver);
        copy_same(&other.failed, &mut self.failed);
        self.status = other.status;
    }
}

impl OutputImage {
    /// The image before any cycle: nothing published, nothing pending.
    pub fn empty(layout: &ValueLayout) -> Self {
        Self {
            published: false,
            values: vec![0; layout.total],
            pending: vec![false; layout.triggers.len()],
            edge_values: vec![0; layout.total],
        }
    }
}

/// Copies as many elements as both slices have (they have the same length by construction).
fn copy_same<T: Copy>(from: &[T], to: &mut [T]) {
    let length = from.len().min(to.len());
    to[..length].copy_from_slice(&from[..length]);
}

/// The buffers one device shares between its master task and the scheduler.
#[derive(Debug)]
pub struct DeviceExchange {
    /// The layout of both images' values.
    pub layout: ValueLayout,
    /// The newest complete round, replaced whole by the master, tried by the scheduler.
    input: Mutex<InputImage>,
    /// The newest cycle end's outputs and pending edges, replaced by the scheduler (which only
    /// tries it), taken by the master at a round's start.
    output: Mutex<OutputImage>,
    /// Cycles of the I/O task ended since the master started.
    cycle_ends: AtomicU64,
    /// Set by the scheduler when it published a pending edge, taken by the wake thread.
    edge_published: AtomicBool,
    /// Whether the program runs: a stopped program's device is read but not written.
    running: AtomicBool,
    /// Wakes the device's master task (from the wake thread, never from the scheduler).
    pub notify: tokio::sync::Notify,
}

impl DeviceExchange {
    /// The exchange of `device`, before any round and any cycle.
    pub fn new(device: &DeviceDef) -> Self {
        let layout = ValueLayout::of(device);
        Self {
            input: Mutex::new(InputImage::empty(&layout)),
            output: Mutex::new(OutputImage::empty(&layout)),
            layout,
            cycle_ends: AtomicU64::new(0),
            edge_published: AtomicBool::new(false),
            running: AtomicBool::new(false),
            notify: tokio::sync::Notify::new(),
        }
    }

    /// The scheduler's side: the input image if nobody holds it now.
    pub fn try_input(&self) -> Option<MutexGuard<'_, InputImage>> {
        try_lock(&self.input)
    }

    /// The scheduler's side: the output image if nobody holds it now.
    pub fn try_output(&self) -> Option<MutexGuard<'_, OutputImage>> {
        try_lock(&self.output)
    }

    /// The master's side: replaces the input image with `round` (held only for the copy).
    pub fn publish_round(&self, round: &InputImage) {
        lock(&self.input).copy_from(round);
    }

    /// The master's side: copies the newest outputs into `values` and the latched edge values
    /// into `edge_values`, takes the pending triggers into `pending` (clearing them), and says
    /// whether a cycle has ended yet.
    pub fn take_outputs(
        &self,
        values: &mut [u8],
        edge_values: &mut [u8],
        pending: &mut [bool],
    ) -> bool {
        let mut output = lock(&self.output);
        copy_same(&output.values, values);
        copy_same(&output.edge_values, edge_values);
        for (taken, flag) in pending.iter_mut().zip(output.pending.iter_mut()) {
            *taken = std::mem::take(flag);
        }
        output.published
    }

    /// Whether some trigger is pending (a look for the master, which may wait for the lock).
    pub fn has_pending(&self) -> bool {
        lock(&self.output).pending.iter().any(|pending| *pending)
    }

    /// The scheduler's side, at the end of a cycle of the I/O task: counts it.
    pub fn cycle_ended(&self, edge_published: bool) {
        // The flag first: the wake thread that sees the new count must see the edge with it.
        if edge_published {
            self.edge_published.store(true, Ordering::Release);
        }
        self.cycle_ends.fetch_add(1, Ordering::Release);
    }

    /// Cycles of the I/O task ended since the master started.
    pub fn cycle_ends(&self) -> u64 {
        self.cycle_ends.load(Ordering::Acquire)
    }

    /// Takes the flag of a published edge (for the wake thread).
    pub fn take_edge_published(&self) -> bool {
        self.edge_published.swap(false, Ordering::AcqRel)
    }

    /// Says whether the program runs; a stop also forgets the outputs, so that writes resume
    /// only after the I/O task ended a cycle of the next run (called between cycles).
    pub fn set_running(&self, running: bool) {
        self.running.store(running, Ordering::Release);
        if !running {
            let mut output = lock(&self.output);
            output.published = false;
            output
                .pending
                .iter_mut()
                .for_each(|pending| *pending = false);
        }
    }

    /// Whether the program runs.
    pub fn running(&self) -> bool {
        self.running.load(Ordering::Acquire)
    }
}

/// Locks a mutex for the master's short copies; a poisoned one is taken as it is (its data
/// are plain bytes, whole after any copy).
fn lock<T>(mutex: &Mutex<T>) -> MutexGuard<'_, T> {
    mutex.lock().unwrap_or_else(PoisonError::into_inner)
}

/// Tries a mutex without waiting; a poisoned one is taken as it is.
fn try_lock<T>(mutex: &Mutex<T>) -> Option<MutexGuard<'_, T>> {
    match mutex.try_lock() {
        Ok(guard) => Some(guard),
        Err(TryLockError::Poisoned(poisoned)) => Some(poisoned.into_inner()),
        Err(TryLockError::WouldBlock) => None,
    }
}

#[cfg(test)]
#[path = "exchange_tests.rs"]
mod tests;
