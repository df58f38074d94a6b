//! The force table: places whose values the scheduler writes before and after every cycle.

use program_image::Region;

use online_protocol::Place;

use super::place::PlaceAccess;
use crate::areas::LocatedAreas;
use crate::engine::{Engine, EngineView};

/// The forced places and their values, in the order they were forced; lives in the
/// scheduler's thread, is cleared by a download and an origin reset, and is never saved.
#[derive(Clone, Debug, Default)]
pub struct Forces {
    entries: Vec<(Place, Vec<u8>)>,
}

impl Forces {
    /// Forces `place` to `value` (checked by the caller), replacing an earlier force of it.
    pub fn set(&mut self, place: Place, value: Vec<u8>) {
        match self.entries.iter_mut().find(|(forced, _)| *forced == place) {
            Some(entry) => entry.1 = value,
            None => self.entries.push((place, value)),
        }
    }

    /// Releases the force of `place`, if there is one.
    pub fn release(&mut self, place: Place) {
        self.entries.retain(|(forced, _)| *forced != place);
    }

    /// Releases every force.
    pub fn clear(&mut self) {
        self.entries.clear();
    }

    /// Moves every force to its variable's place after an online change, as `moved` gives
    /// it, and releases those whose variable is gone or changed type (`moved` gives `None`);
    /// returns the released places.
    pub fn follow(&mut self, moved: impl Fn(Place) -> Option<Place>) -> Vec<Place> {
        let mut released = Vec::new();
        self.entries.retain_mut(|(place, _)| match moved(*place) {
            Some(new_place) => {
                *place = new_place;
                true
            }
            None => {
                released.push(*place);
                false
            }
        });
        released
    }

    /// Whether `place` is forced (as exactly that place).
    pub fn is_forced(&self, place: Place) -> bool {
        self.entries.iter().any(|(forced, _)| *forced == place)
    }

    /// The forces, in the order they were set.
    pub fn entries(&self) -> &[(Place, Vec<u8>)] {
        &self.entries
    }

    /// Writes the forced values into the engine's memory.
    pub fn apply_to_engine(&self, engine: &mut Engine) {
        self.apply_to_view(&mut engine.view());
    }

    /// Writes the forced values into the memory of a running or interrupted cycle.
    pub fn apply_to_view(&self, engine: &mut EngineView<'_>) {
        for (place, value) in &self.entries {
            if let Some(region) = place.region_of() {
                place.write_into(value, engine.region_mut(region));
            }
        }
    }

    /// Writes the forced located values into the shared areas.
    pub fn apply_to_areas(&self, areas: &mut LocatedAreas) {
        for (place, value) in &self.entries {
            match place.region_of() {
                Some(Region::Input) => place.write_into(value, &mut areas.input),
                Some(Region::Output) => place.write_into(value, &mut areas.output),
                Some(Region::Memory) => place.write_into(value, &mut areas.memory),
                Some(Region::Data) | None => {}
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn place(offset: u32, bit: Option<u8>, size: u16) -> Place {
        Place {
            region: 2,
            offset,
            bit,
            size,
        }
    }

    #[test]
    fn forced_values_overwrite_the_areas_and_a_release_stops_that() {
        let mut forces = Forces::default();
        let mut areas = LocatedAreas::new(4, 4, 4);
        forces.set(place(0, Some(3), 1), vec![1]);
        forces.set(place(2, None, 2), vec![0x34, 0x12]);
        forces.set(place(2, None, 2), vec![0x78, 0x56]);
        forces.apply_to_areas(&mut areas);
        assert_eq!(areas.output, [0b1000, 0, 0x78, 0x56]);
        assert_eq!(forces.entries().len(), 2);
        forces.release(place(0, Some(3), 1));
        assert!(!forces.is_forced(place(0, Some(3), 1)));
        assert!(forces.is_forced(place(2, None, 2)));
        forces.set(place(0, Some(3), 1), vec![0]);
        forces.apply_to_areas(&mut areas);
        assert_eq!(areas.output, [0, 0, 0x78, 0x56]);
        forces.clear();
        assert!(forces.entries().is_empty());
    }
}
