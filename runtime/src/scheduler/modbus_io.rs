//! The scheduler's copy points for the Modbus master (`docs/modbus-master.md` §4.1, §6.4): at
//! the start of a cycle of a device's I/O task (after the located areas are taken in, before
//! the forces) the device's newest round goes into the program; at its end (after the forces)
//! the write channels' variables and the triggers' edges go out, and the wake thread is
//! unparked. Nothing here waits for a lock (`copier.rs` only tries them).

use std::thread::Thread;

use program_image::Region;
use program_image::modbus_master::MasterSection;

use crate::engine::EngineView;
use crate::modbus::master::{DeviceCopier, DevicePlaces, MasterHandle, ProgramMemory};

/// The running master of the loaded program and the scheduler's side of its devices.
pub(super) struct ModbusIo {
    /// The master.
    handle: MasterHandle,
    /// Per device, what a cycle of its I/O task copies.
    copiers: Vec<DeviceCopier>,
    /// The `rivet-modbus-wake` thread, unparked after a cycle end.
    waker: Option<Thread>,
}

impl ModbusIo {
    /// The copies of `handle`'s devices.
    pub(super) fn new(handle: MasterHandle) -> Self {
        Self {
            copiers: handle.copiers(),
            waker: handle.waker(),
            handle,
        }
    }

    /// At the start of a cycle of `task`: copies each of its devices' newest round in.
    pub(super) fn cycle_start(&mut self, task: usize, engine: &mut EngineView<'_>) {
        for copier in &mut self.copiers {
            if copier.task() == task {
                copier.cycle_start(engine);
            }
        }
    }

    /// At the end of a cycle of `task`: hands each of its devices the outputs and edges, and
    /// wakes the master's devices.
    pub(super) fn cycle_end(&mut self, task: usize, engine: &EngineView<'_>) {
        let mut ended = false;
        for copier in &mut self.copiers {
            if copier.task() == task {
                copier.cycle_end(engine);
                ended = true;
            }
        }
        if ended && let Some(waker) = &self.waker {
            waker.unpark();
        }
    }

    /// Tells the devices whether the program runs (between cycles); a stop also forgets the
    /// edges seen at cycle ends and not yet handed to the master, so a restart sends none of
    /// them.
    pub(super) fn set_running(&mut self, running: bool) {
        if !running {
            self.copiers.iter_mut().for_each(DeviceCopier::forget_edges);
        }
        self.handle.set_running(running);
    }

    /// Whether `section` is the running master's, so the master may go on through an online
    /// change to an image with it (`docs/modbus-master.md` §6.10).
    pub(super) fn same_section(&self, section: &MasterSection) -> bool {
        section == self.handle.section()
    }

    /// Takes the paths as resolved in a new image with the same section (an online change):
    /// the devices' connections and kept rounds stay. False when `places` do not fit.
    pub(super) fn rebind(&mut self, places: &[DevicePlaces]) -> bool {
        if places.len() != self.copiers.len() {
            return false;
        }
        for (copier, places) in self.copiers.iter_mut().zip(places) {
            copier.rebind(places.clone());
        }
        true
    }

    /// Ends the scheduler's side; the master, told the program no longer runs so that it
    /// writes nothing more, goes to whoever stops it.
    pub(super) fn retire(mut self) -> MasterHandle {
        self.set_running(false);
        self.handle
    }
}

impl ProgramMemory for EngineView<'_> {
    fn bytes(&self, region: Region) -> &[u8] {
        self.region(region)
    }

    fn bytes_mut(&mut self, region: Region) -> &mut [u8] {
        self.region_mut(region)
    }
}
