//! Places as the online protocol sends them, checked against a region, read and written.

use program_image::Region;

use super::codec::{Refusal, Status};
use crate::areas::LocatedAreas;
use crate::engine::Engine;

/// A place as it travels: `region:u8`, `offset:u32`, `bit:u8` (0xFF for none), `size:u16`.
///
/// A bit place (a located BOOL) has a size of 1 and its value is one byte, 0 or 1.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct WirePlace {
    /// 0 data, 1 `%I`, 2 `%Q`, 3 `%M`.
    pub region: u8,
    /// The byte offset in the region.
    pub offset: u32,
    /// 0 to 7 for a bit, 0xFF for none.
    pub bit: u8,
    /// The size of the value in bytes.
    pub size: u16,
}

/// The bit value meaning "no bit".
pub const NO_BIT: u8 = 0xFF;

impl WirePlace {
    /// The region this place names, if it names one.
    pub fn region(self) -> Option<Region> {
        match self.region {
            0 => Some(Region::Data),
            1 => Some(Region::Input),
            2 => Some(Region::Output),
            3 => Some(Region::Memory),
            _ => None,
        }
    }

    /// Whether the place is a single bit.
    pub fn is_bit(self) -> bool {
        self.bit != NO_BIT
    }

    /// Checks that the place lies inside a region of `region_bytes` bytes and is well formed.
    pub fn check(self, region_bytes: usize) -> Result<(), Refusal> {
        let refuse = |why: &str| {
            Err(Refusal {
                status: Status::BadPlace,
                message: format!(
                    "place (region {}, offset {}, bit {}, size {}): {why}",
                    self.region, self.offset, self.bit, self.size
                ),
            })
        };
        if self.region().is_none() {
            return refuse("the region is not 0 to 3");
        }
        if self.size == 0 {
            return refuse("the size is 0");
        }
        if self.is_bit() && (self.bit > 7 || self.size != 1) {
            return refuse("a bit place needs a bit of 0 to 7 and a size of 1");
        }
        let end = self.offset as usize
            + if self.is_bit() {
                1
            } else {
                usize::from(self.size)
            };
        if end > region_bytes {
            return refuse(&format!("the region has only {region_bytes} bytes"));
        }
        Ok(())
    }

    /// The value at the place in `bytes` (which the place has been checked against).
    pub fn read(self, bytes: &[u8]) -> Vec<u8> {
        let start = self.offset as usize;
        if self.is_bit() {
            let byte = bytes.get(start).copied().unwrap_or(0);
            return vec![byte >> (self.bit & 7) & 1];
        }
        bytes
            .get(start..start + usize::from(self.size))
            .map(<[u8]>::to_vec)
            .unwrap_or_default()
    }

    /// Writes `value` at the place in `bytes`; a bit place takes any non-zero byte as TRUE.
    pub fn write(self, value: &[u8], bytes: &mut [u8]) {
        let start = self.offset as usize;
        if self.is_bit() {
            if let Some(byte) = bytes.get_mut(start) {
                let mask = 1 << (self.bit & 7);
                if value.first().is_some_and(|&set| set != 0) {
                    *byte |= mask;
                } else {
                    *byte &= !mask;
                }
            }
            return;
        }
        if let Some(target) = bytes.get_mut(start..start + value.len()) {
            target.copy_from_slice(value);
        }
    }
}

/// The engine's memory and the shared located areas, as the online services see them between
/// two cycles: the located areas are where the outside world reads and writes `%I`, `%Q` and
/// `%M`, the engine holds the data region.
pub struct Memory<'a> {
    /// The engine of the loaded program.
    pub engine: &'a mut Engine,
    /// The located areas shared with the Modbus server.
    pub areas: &'a mut LocatedAreas,
}

impl Memory<'_> {
    /// Checks `place` against its region's size.
    pub fn check(&self, place: WirePlace) -> Result<(), Refusal> {
        let length = match place.region() {
            Some(Region::Data) => self.engine.region(Region::Data).len(),
            Some(Region::Input) => self.areas.input.len(),
            Some(Region::Output) => self.areas.output.len(),
            Some(Region::Memory) => self.areas.memory.len(),
            None => 0,
        };
        place.check(length)
    }

    /// The value at a checked place.
    pub fn read(&self, place: WirePlace) -> Vec<u8> {
        match place.region() {
            Some(Region::Data) => place.read(self.engine.region(Region::Data)),
            Some(Region::Input) => place.read(&self.areas.input),
            Some(Region::Output) => place.read(&self.areas.output),
            Some(Region::Memory) => place.read(&self.areas.memory),
            None => Vec::new(),
        }
    }

    /// Writes a value at a checked place, in the located areas and the engine alike.
    pub fn write(&mut self, place: WirePlace, value: &[u8]) {
        let Some(region) = place.region() else {
            return;
        };
        place.write(value, self.engine.region_mut(region));
        match region {
            Region::Data => {}
            Region::Input => place.write(value, &mut self.areas.input),
            Region::Output => place.write(value, &mut self.areas.output),
            Region::Memory => place.write(value, &mut self.areas.memory),
        }
    }
}
