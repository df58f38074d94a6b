//! The scheduler's side of the located areas: it exchanges them with the engine only when their
//! lock is free, and never waits for it (`docs/scheduler.md`, "Located areas and online
//! access"). A Modbus thread that holds the lock may itself be waiting for a processor; a
//! real-time scheduler waiting for it would wait for every normally scheduled thread of the
//! machine (a priority inversion). A skipped exchange loses nothing (see
//! [`LocatedAreas::exchange`]): the inputs and the clients' writes reach the program one cycle
//! later, and the program's outputs reach the areas at the next exchange.

use std::sync::{Mutex, MutexGuard, TryLockError};

use program_image::Region;

use crate::areas::{Area, LocatedAreas};
use crate::engine::EngineView;
use crate::online::Forces;

/// The areas, locked, when nobody holds them now; a poisoned lock is taken as it is (the
/// Modbus server reports a poisoned lock on its own).
pub(super) fn try_lock(areas: &Mutex<LocatedAreas>) -> Option<MutexGuard<'_, LocatedAreas>> {
    match areas.try_lock() {
        Ok(guard) => Some(guard),
        Err(TryLockError::Poisoned(poisoned)) => Some(poisoned.into_inner()),
        Err(TryLockError::WouldBlock) => None,
    }
}

/// At the start of a cycle: takes the inputs and the clients' writes into `engine` and gives
/// the areas what the engine wrote since the last exchange. Returns whether the lock was free.
pub(super) fn take_in(areas: &Mutex<LocatedAreas>, engine: &mut EngineView<'_>) -> bool {
    let Some(mut areas) = try_lock(areas) else {
        return false;
    };
    exchange(&mut areas, engine);
    true
}

/// [`take_in`] with the areas already locked.
pub(super) fn exchange(areas: &mut LocatedAreas, engine: &mut EngineView<'_>) {
    areas.exchange(Area::Input, engine.region_mut(Region::Input));
    areas.exchange(Area::Output, engine.region_mut(Region::Output));
    areas.exchange(Area::Memory, engine.region_mut(Region::Memory));
}

/// At the end of an outermost cycle (or at a halt): makes `%Q` and `%M` of `engine` visible,
/// with the forced values. Returns whether the lock was free.
pub(super) fn publish(
    areas: &Mutex<LocatedAreas>,
    engine: &EngineView<'_>,
    forces: &Forces,
) -> bool {
    let Some(mut areas) = try_lock(areas) else {
        return false;
    };
    areas.publish(engine.region(Region::Output), engine.region(Region::Memory));
    forces.apply_to_areas(&mut areas);
    true
}
