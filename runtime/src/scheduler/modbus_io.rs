//! The scheduler's copy points for the Modbus master (`docs/modbus-master.md` §4.1, §6.4): at
//! the start of a cycle of a device's I/O task (after the located areas are taken in, before
//! the forces) the device's newest round goes into the program; at its end (after the forces)
//! the write channels' variables and the triggers' edges go out, and the wake thread is
//! unparked. Nothing here waits for a lock (`copier.rs` only tries them).

use std::thread::Thread;

use program_image::{ProgramImage, Region};

use crate::engine::EngineView;
use crate::modbus::master::{
    DeviceCopier, MasterHandle, ProgramMemory, ResolveError, resolve_section,
};

/// The running master of the loaded program and the scheduler's side of its devices.
pub(super) struct ModbusIo {
    handle: MasterHandle,
    copiers: Vec<DeviceCopier>,
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

    /// Tells the devices whether the program runs (between cycles).
    pub(super) fn set_running(&self, running: bool) {
        self.handle.set_running(running);
    }

    /// Whether `image` has the same section as the running master, so the master may go on
    /// through an online change to it (`docs/modbus-master.md` §6.10).
    pub(super) fn same_section(&self, image: &ProgramImage) -> bool {
        image.modbus_master.clone().unwrap_or_default() == *self.handle.section()
    }

    /// Resolves the paths again in `image` (an online change to an image with the same
    /// section): the devices' connections and kept rounds stay.
    pub(super) fn rebind(&mut self, image: &ProgramImage) -> Result<(), ResolveError> {
        let places = resolve_section(image, self.handle.section())?;
        for (copier, places) in self.copiers.iter_mut().zip(places) {
            copier.rebind(places);
        }
        Ok(())
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
