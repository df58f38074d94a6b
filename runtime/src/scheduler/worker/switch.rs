//! The online change's switch on the scheduler's thread (`docs/protocol.md` §7): between two
//! cycles, the new engine takes over with the running one's values, and the tasks keep their
//! schedule, cycle counts, statistics and faults.

use std::sync::Arc;
use std::time::Instant;

use online_protocol::Place;
use program_image::{ImageHash, Region};

use super::{Worker, copy, lock};
use crate::engine::{Engine, OnlineChangePlan};
use crate::retain::RetainSnapshot;
use crate::scheduler::{ChangeAnswer, OnlineChangeReport, SchedulerError};

/// The place number of the data region in a [`Place`].
const PLACE_DATA: u8 = 0;

impl Worker {
    /// Replaces the running engine, made from the image `from`, with `engine`, carrying the
    /// values by `plan`. Commands are handled between cycles only, so no task is in a cycle
    /// now; the task plans are kept as they are (the task configuration is the same), so the
    /// next due cycle of every task runs the new code and none is missed. The engine that is
    /// no longer needed (the old one, or `engine` when refused) goes back with the answer, so
    /// that freeing it holds no task.
    pub(super) fn switch(
        &mut self,
        mut engine: Engine,
        plan: &Arc<OnlineChangePlan>,
        from: ImageHash,
        to: ImageHash,
    ) -> ChangeAnswer {
        let started = Instant::now();
        if lock(&self.status).image != Some(from) {
            return (Err(SchedulerError::ProgramChanged), Some(engine));
        }
        let Some(program) = self.program.as_mut() else {
            return (Err(SchedulerError::NoProgram), Some(engine));
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
        // resolved in the new program; otherwise the old one stops and the new one starts
        // (`docs/modbus-master.md` §6.10).
        let keeps_master = program.modbus.as_mut().is_some_and(|modbus| {
            modbus.same_section(program.engine.image())
                && modbus.rebind(program.engine.image()).is_ok()
        });
        let restart = !keeps_master
            && (program.modbus.is_some() || program.engine.image().modbus_master.is_some());
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
        if restart {
            self.restart_master();
        }
        let report = OnlineChangeReport {
            cycles: self.cycles_total,
            applied,
            forces_released,
            trace_removed,
            switch: started.elapsed(),
        };
        (Ok(report), Some(old))
    }
}

impl Worker {
    /// Stops the running program's master and starts the master of its (new) image, running
    /// if the program runs. The caller checked the image's paths, so only a thread that cannot
    /// be started stops it: the program then runs without its devices, which the status says.
    fn restart_master(&mut self) {
        let Some(program) = self.program.as_mut() else {
            return;
        };
        program.modbus = None;
        let image = program.engine.shared_image();
        match self.start_master(&image) {
            Ok(modbus) => {
                if let Some(modbus) = &modbus
                    && self.running
                {
                    modbus.set_running(true);
                }
                if let Some(program) = self.program.as_mut() {
                    program.modbus = modbus;
                }
            }
            Err(_) => {
                // Every device then shows no counters; there is no caller left to tell.
                lock(&self.modbus_devices).clear();
            }
        }
    }
}

#[cfg(test)]
#[path = "switch_tests.rs"]
mod tests;
