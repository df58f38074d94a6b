//! The online change's switch on the scheduler's thread (`docs/protocol.md` §7): between two
//! cycles, the new engine takes over with the running one's values, and the tasks keep their
//! schedule, cycle counts, statistics and faults.

use std::sync::Arc;
use std::time::Instant;

use online_protocol::Place;
use program_image::{ImageHash, Region};

use super::{Worker, copy, lock};
use crate::engine::{Engine, OnlineChangePlan};
use crate::modbus::master::MasterHandle;
use crate::retain::RetainSnapshot;
use crate::scheduler::modbus_io::ModbusIo;
use crate::scheduler::{ChangeAnswer, OnlineChangeReport, Retired, SchedulerError};

/// The place number of the data region in a [`Place`].
const PLACE_DATA: u8 = 0;

impl Worker {
    /// Replaces the running engine, made from the image `from`, with `engine`, carrying the
    /// values by `plan`. Commands are handled between cycles only, so no task is in a cycle
    /// now; the task plans are kept as they are (the task configuration is the same), so the
    /// next due cycle of every task runs the new code and none is missed. The engine that is
    /// no longer needed (the old one, or `engine` when refused) goes back with the answer, so
    /// that freeing it holds no task; so does the master no longer needed: the old one when
    /// `master` (the new image's, prepared) replaces it, else `master`.
    pub(super) fn switch(
        &mut self,
        mut engine: Engine,
        plan: &Arc<OnlineChangePlan>,
        from: ImageHash,
        to: ImageHash,
        master: MasterHandle,
    ) -> ChangeAnswer {
        let started = Instant::now();
        if lock(&self.status).image != Some(from) {
            return refused(SchedulerError::ProgramChanged, engine, master);
        }
        let Some(program) = self.program.as_mut() else {
            return refused(SchedulerError::NoProgram, engine, master);
        };
        {
            // The located areas keep their content: the new engine starts from the shared
            // areas, as every cycle does, once they hold what the running engine wrote (its last
            // publish may have been skipped) and the running engine what clients wrote.
            let mut areas = lock(&self.areas);
            super::located::exchange(&mut areas, &mut program.engine.view());
            copy(&areas.input, engine.region_mut(Region::Input));
            copy(&areas.output, engine.region_mut(Region::Output));
            copy(&areas.memory, engine.region_mut(Region::Memory));
        }
        let mut old = std::mem::replace(&mut program.engine, engine);
        let applied = plan.apply(&mut old, &mut program.engine);
        // The master goes on through the switch when the section is the same, with its paths
        // as the new image's master resolved them on the caller's thread; otherwise the new
        // one replaces it, and the old one stops on the caller's thread before the new one
        // begins polling (`docs/modbus-master.md` §6.10).
        let keeps_master = program.modbus.as_mut().is_some_and(|modbus| {
            modbus.same_section(master.section()) && modbus.rebind(master.places())
        });
        let moved = |place: Place| match place.region {
            PLACE_DATA => plan
                .moved_range(place.offset as usize, place.value_bytes())
                .and_then(|at| u32::try_from(at).ok())
                .map(|offset| Place { offset, ..place }),
            _ => Some(place),
        };
        let forces_released = self.forces.follow(moved).len();
        self.forces.apply_to_engine(&mut program.engine);
        let trace_removed = self.trace.follow(moved);
        if let (Some(writer), Some(snapshot)) = (&self.retain, RetainSnapshot::of(&program.engine))
        {
            // Saved with the new retained layout, by the writer's thread.
            writer.write_later(snapshot);
        }
        lock(&self.status).image = Some(to);
        let master = if keeps_master {
            Some(master)
        } else {
            self.replace_master(master)
        };
        let report = OnlineChangeReport {
            cycles: self.cycles_total,
            applied,
            forces_released,
            trace_removed,
            switch: started.elapsed(),
        };
        let retired = Retired {
            engine: Some(old),
            master,
        };
        (Ok(report), retired)
    }
}

impl Worker {
    /// Puts `master` in place of the running program's master, running if the program runs;
    /// gives back the old one, which writes nothing from now on.
    fn replace_master(&mut self, master: MasterHandle) -> Option<MasterHandle> {
        let mut modbus = self.install_master(master);
        if let Some(modbus) = &mut modbus
            && self.running
        {
            modbus.set_running(true);
        }
        let program = self.program.as_mut()?;
        let old = std::mem::replace(&mut program.modbus, modbus);
        old.map(ModbusIo::retire)
    }
}

/// The answer to a refused online change: the new engine and master go back unused.
fn refused(error: SchedulerError, engine: Engine, master: MasterHandle) -> ChangeAnswer {
    let retired = Retired {
        engine: Some(engine),
        master: Some(master),
    };
    (Err(error), retired)
}

#[cfg(test)]
#[path = "switch_tests.rs"]
mod tests;
