//! The scheduler's side of one device's exchange (`docs/modbus-master.md` §4.1, §6.4): what a
//! cycle of the device's I/O task copies in at its start and out at its end.
//!
//! It never waits: it tries the exchange's mutexes and, when one is busy, works from what it
//! kept (the last round it took in; the outputs and edges it has not handed over yet). Its
//! buffers are allocated once, at load, so a cycle allocates nothing.

use std::sync::Arc;

use program_image::Region;
use program_image::modbus_master::Direction;

use super::exchange::{DeviceExchange, InputImage};
use super::resolve::{BytePlace, DevicePlaces};

/// The program's memory as the copies see it: a region's bytes by [`Region`].
pub trait ProgramMemory {
    /// The bytes of `region`.
    fn bytes(&self, region: Region) -> &[u8];
    /// The bytes of `region`, to write.
    fn bytes_mut(&mut self, region: Region) -> &mut [u8];
}

/// One device's copies, kept by the scheduler between cycles.
#[derive(Debug)]
pub struct DeviceCopier {
    /// The exchange shared with the device's master task.
    pub exchange: Arc<DeviceExchange>,
    /// Where the device's variables are in the running program.
    pub places: DevicePlaces,
    /// The last round taken in, copied again when the input image is busy.
    kept: InputImage,
    /// Each trigger's value at the end of the task's previous cycle (FALSE before the first).
    trigger_was: Vec<bool>,
    /// Edges seen but not handed over yet (the output image was busy).
    latched: Vec<bool>,
    /// The write channels' values at the end of the cycle now ending.
    outputs: Vec<u8>,
    /// The values of latched edges' channels, from the cycle end that saw the edge.
    latched_values: Vec<u8>,
}

impl DeviceCopier {
    /// The copies of a device whose variables are at `places`.
    pub fn new(exchange: Arc<DeviceExchange>, places: DevicePlaces) -> Self {
        let layout = &exchange.layout;
        Self {
            kept: InputImage::empty(layout),
            trigger_was: vec![false; layout.triggers.len()],
            latched: vec![false; layout.triggers.len()],
            outputs: vec![0; layout.total],
            latched_values: vec![0; layout.total],
            places,
            exchange,
        }
    }

    /// The I/O task's index.
    pub fn task(&self) -> usize {
        self.places.task
    }

    /// Forgets the edges latched and not handed over yet (the program stopped: a restart must
    /// not send a write for an edge of the run before).
    pub fn forget_edges(&mut self) {
        self.latched.iter_mut().for_each(|latched| *latched = false);
    }

    /// Takes new places (an online change that keeps the master running); what was kept stays.
    pub fn rebind(&mut self, places: DevicePlaces) {
        self.places = places;
    }

    /// At the start of a cycle of the I/O task: takes the newest round when the input image is
    /// free, and copies the round it has (read channels' values, error flags, status) into the
    /// program. Before the first round only the status is copied (a device not yet polled), and
    /// the variables keep their initial values. Returns whether the image was free.
    pub fn cycle_start(&mut self, memory: &mut impl ProgramMemory) -> bool {
        let taken = match self.exchange.try_input() {
            Some(input) => {
                if input.round != self.kept.round {
                    self.kept.copy_from(&input);
                }
                true
            }
            None => false,
        };
        if let Some(status) = self.places.status {
            write_place(memory, status, &self.kept.status);
        }
        if self.kept.round == 0 {
            return taken;
        }
        let layout = &self.exchange.layout;
        for (index, channel) in self.places.channels.iter().enumerate() {
            if channel.direction == Direction::Read && self.kept.deliver[index] {
                write_place(
                    memory,
                    channel.variable,
                    layout.slice(&self.kept.values, index),
                );
            }
            if let Some(flag) = channel.error_flag {
                write_place(memory, flag, &[u8::from(self.kept.failed[index])]);
            }
        }
        taken
    }

    /// At the end of a cycle of the I/O task, after the forces: reads the write channels'
    /// variables and the triggers, latches rising edges with their channels' values, and hands
    /// them over when the output image is free; then counts the cycle end. Returns whether the
    /// image was free.
    pub fn cycle_end(&mut self, memory: &impl ProgramMemory) -> bool {
        let layout = &self.exchange.layout;
        for (index, channel) in self.places.channels.iter().enumerate() {
            if channel.direction == Direction::Write {
                read_place(
                    memory,
                    channel.variable,
                    layout.slice_mut(&mut self.outputs, index),
                );
            }
        }
        for (trigger, place) in self.places.triggers.iter().enumerate() {
            let set = read_bool(memory, *place);
            if set && !self.trigger_was[trigger] {
                // A later edge while one is latched merges into it, with the newer values.
                self.latched[trigger] = true;
                for (index, of) in layout.trigger_of.iter().enumerate() {
                    if *of == Some(trigger) {
                        let (start, length) = layout.ranges[index];
                        self.latched_values[start..start + length]
                            .copy_from_slice(&self.outputs[start..start + length]);
                    }
                }
            }
            self.trigger_was[trigger] = set;
        }
        let mut edge_published = false;
        let free = match self.exchange.try_output() {
            Some(mut output) => {
                output.published = true;
                output.values.copy_from_slice(&self.outputs);
                for (trigger, latched) in self.latched.iter_mut().enumerate() {
                    if std::mem::take(latched) {
                        output.pending[trigger] = true;
                        edge_published = true;
                        for (index, of) in layout.trigger_of.iter().enumerate() {
                            if *of == Some(trigger) {
                                let (start, length) = layout.ranges[index];
                                output.edge_values[start..start + length]
                                    .copy_from_slice(&self.latched_values[start..start + length]);
                            }
                        }
                    }
                }
                true
            }
            None => false,
        };
        self.exchange.cycle_ended(edge_published);
        free
    }

    /// The round the program sees now (for tests and the benchmark).
    pub fn kept_round(&self) -> u64 {
        self.kept.round
    }
}

/// Writes `bytes` at `place`; a located BOOL changes only its bit.
fn write_place(memory: &mut impl ProgramMemory, place: BytePlace, bytes: &[u8]) {
    let region = memory.bytes_mut(place.region);
    let Some(target) = region.get_mut(place.offset..place.offset + place.bytes) else {
        return;
    };
    match place.bit {
        Some(bit) => {
            let mask = 1u8 << (bit & 7);
            let set = bytes.first().is_some_and(|byte| *byte != 0);
            target[0] = if set {
                target[0] | mask
            } else {
                target[0] & !mask
            };
        }
        None => {
            let length = target.len().min(bytes.len());
            target[..length].copy_from_slice(&bytes[..length]);
        }
    }
}

/// Reads the bytes at `place` into `into`; a located BOOL gives 0 or 1.
fn read_place(memory: &impl ProgramMemory, place: BytePlace, into: &mut [u8]) {
    let region = memory.bytes(place.region);
    let Some(source) = region.get(place.offset..place.offset + place.bytes) else {
        return;
    };
    match place.bit {
        Some(bit) => {
            if let Some(first) = into.first_mut() {
                *first = (source[0] >> (bit & 7)) & 1;
            }
        }
        None => {
            let length = source.len().min(into.len());
            into[..length].copy_from_slice(&source[..length]);
        }
    }
}

/// A BOOL's value at `place`.
fn read_bool(memory: &impl ProgramMemory, place: BytePlace) -> bool {
    let mut byte = [0u8];
    read_place(memory, place, &mut byte);
    byte[0] != 0
}

#[cfg(test)]
mod tests {
    use super::*;

    struct Located(Vec<u8>);

    impl ProgramMemory for Located {
        fn bytes(&self, _region: Region) -> &[u8] {
            &self.0
        }
        fn bytes_mut(&mut self, _region: Region) -> &mut [u8] {
            &mut self.0
        }
    }

    #[test]
    fn a_located_bool_is_copied_as_its_bit_and_the_other_bits_stay() {
        let bit = BytePlace {
            region: Region::Output,
            offset: 1,
            bytes: 1,
            bit: Some(3),
        };
        let mut memory = Located(vec![0b1010_0101, 0b1111_0111]);
        write_place(&mut memory, bit, &[1]);
        assert_eq!(memory.0, [0b1010_0101, 0b1111_1111]);
        write_place(&mut memory, bit, &[0]);
        assert_eq!(memory.0, [0b1010_0101, 0b1111_0111]);
        let mut value = [7u8];
        read_place(&memory, bit, &mut value);
        assert_eq!(value, [0]);
        memory.0[1] = 0b0000_1000;
        assert!(read_bool(&memory, bit));
        // A place beyond the region is neither read nor written.
        let beyond = BytePlace { offset: 9, ..bit };
        write_place(&mut memory, beyond, &[1]);
        assert_eq!(memory.0, [0b1010_0101, 0b0000_1000]);
        assert!(!read_bool(&memory, beyond));
    }
}
