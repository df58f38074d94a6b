//! Places of the online protocol checked against a region, read and written.

use online_protocol::{MAX_BIT, NO_BIT, Place, Refusal, Status};
use program_image::Region;

use crate::areas::LocatedAreas;
use crate::engine::EngineView;

/// What the runtime does with a protocol [`Place`]: find its region, check it against the
/// region's size, and read and write its value in the region's bytes.
pub trait PlaceAccess {
    /// The region the place names, if it names one.
    fn region_of(&self) -> Option<Region>;

    /// Checks that the place lies inside a region of `region_bytes` bytes and is well formed.
    fn check(&self, region_bytes: usize) -> Result<(), Refusal>;

    /// The value at the place in `bytes` (which the place has been checked against).
    fn read_from(&self, bytes: &[u8]) -> Vec<u8>;

    /// Writes `value` at the place in `bytes`; a bit place takes any non-zero byte as TRUE.
    fn write_into(&self, value: &[u8], bytes: &mut [u8]);
}

impl PlaceAccess for Place {
    fn region_of(&self) -> Option<Region> {
        match self.region {
            0 => Some(Region::Data),
            1 => Some(Region::Input),
            2 => Some(Region::Output),
            3 => Some(Region::Memory),
            _ => None,
        }
    }

    fn check(&self, region_bytes: usize) -> Result<(), Refusal> {
        let refuse = |why: &str| {
            Err(Refusal::new(
                Status::BadPlace,
                format!(
                    "place (region {}, offset {}, bit {}, size {}): {why}",
                    self.region,
                    self.offset,
                    self.bit.unwrap_or(NO_BIT),
                    self.size
                ),
            ))
        };
        if self.region_of().is_none() {
            return refuse("the region is not 0 to 3");
        }
        if self.size == 0 {
            return refuse("the size is 0");
        }
        if self.bit.is_some_and(|bit| bit > MAX_BIT) || (self.is_bit() && self.size != 1) {
            return refuse("a bit place needs a bit of 0 to 7 and a size of 1");
        }
        let end = self.offset as usize + self.value_bytes();
        if end > region_bytes {
            return refuse(&format!("the region has only {region_bytes} bytes"));
        }
        Ok(())
    }

    fn read_from(&self, bytes: &[u8]) -> Vec<u8> {
        let start = self.offset as usize;
        if let Some(bit) = self.bit {
            let byte = bytes.get(start).copied().unwrap_or(0);
            return vec![byte >> (bit & 7) & 1];
        }
        bytes
            .get(start..start + usize::from(self.size))
            .map(<[u8]>::to_vec)
            .unwrap_or_default()
    }

    fn write_into(&self, value: &[u8], bytes: &mut [u8]) {
        let start = self.offset as usize;
        if let Some(bit) = self.bit {
            if let Some(byte) = bytes.get_mut(start) {
                let mask = 1 << (bit & 7);
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
    /// The engine of the loaded program: between two cycles, or inside a halted one.
    pub engine: EngineView<'a>,
    /// The located areas shared with the Modbus server.
    pub areas: &'a mut LocatedAreas,
}

impl Memory<'_> {
    /// Checks `place` against its region's size.
    pub fn check(&self, place: Place) -> Result<(), Refusal> {
        let length = match place.region_of() {
            Some(Region::Data) => self.engine.region(Region::Data).len(),
            Some(Region::Input) => self.areas.input.len(),
            Some(Region::Output) => self.areas.output.len(),
            Some(Region::Memory) => self.areas.memory.len(),
            None => 0,
        };
        place.check(length)
    }

    /// The value at a checked place.
    pub fn read(&self, place: Place) -> Vec<u8> {
        match place.region_of() {
            Some(Region::Data) => place.read_from(self.engine.region(Region::Data)),
            Some(Region::Input) => place.read_from(&self.areas.input),
            Some(Region::Output) => place.read_from(&self.areas.output),
            Some(Region::Memory) => place.read_from(&self.areas.memory),
            None => Vec::new(),
        }
    }

    /// Writes a value at a checked place, in the located areas and the engine alike.
    pub fn write(&mut self, place: Place, value: &[u8]) {
        let Some(region) = place.region_of() else {
            return;
        };
        place.write_into(value, self.engine.region_mut(region));
        match region {
            Region::Data => {}
            Region::Input => place.write_into(value, &mut self.areas.input),
            Region::Output => place.write_into(value, &mut self.areas.output),
            Region::Memory => place.write_into(value, &mut self.areas.memory),
        }
    }
}
