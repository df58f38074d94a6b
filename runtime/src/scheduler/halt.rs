//! What the scheduler thread does while a task is halted (`docs/debugging.md` §2): from inside
//! the halted cycle, it publishes `%Q` and `%M`, releases the located areas, serves the
//! commands, runs the other tasks when they are due (lower priorities too) and looks at the
//! event triggers, until the task may go on; the time halted counts neither in the cycle's
//! time nor in the watchdog of any cycle in progress. A stop, reset, download or shutdown
//! abandons the halted cycles and is done by the worker once they have unwound.

use std::sync::mpsc;
use std::time::Duration;

use program_image::Region;

use super::cycles::{Cycles, copy};
use super::worker::lock;
use super::{Between, Command, SchedulerError};
use crate::engine::EngineView;
use crate::online::Memory;
use crate::retain::RetainSnapshot;

/// The longest wait for a command while halted, so event triggers are looked at often enough.
const HALT_POLL: Duration = Duration::from_millis(10);

impl Cycles<'_, '_> {
    /// Serves the halt of `task` on `engine` until it may go on or its cycle is abandoned.
    pub(super) fn serve_halt(&mut self, mut engine: EngineView<'_>, task: usize) {
        let entered = self.now_ns();
        self.disarm();
        // What the halted cycle wrote so far becomes visible, as at the end of a cycle.
        self.publish(&engine);
        *self.areas = None;
        while engine.debug().is_halted(task) && !engine.debug().abandoning() {
            let now = self.now_ns();
            if self.plans.iter().any(super::plan::TaskPlan::is_event) {
                self.observe_triggers(&engine, now);
            }
            self.save_retain(&engine, now);
            let levels = &self.levels;
            let idle = |index: usize| !levels.iter().any(|level| level.task == index);
            // In "halt all" the tasks that are not halted are held: they start no cycle.
            let holding = engine.debug().holding();
            if let Some(next) = super::plan::pick_where(self.plans, now, |index, _| idle(index))
                .filter(|_| !holding)
            {
                self.take_areas(&mut engine);
                self.run(&mut engine, next);
                *self.areas = None;
                continue;
            }
            let wait = super::plan::next_start_where(self.plans, |_| true)
                .map_or(HALT_POLL, |at| Duration::from_nanos(at.saturating_sub(now)))
                .min(HALT_POLL);
            match self.commands.recv_timeout(wait) {
                Ok(Command::Between(action)) => {
                    let lock_of = self.areas_lock;
                    let mut areas = lock(lock_of);
                    let mut between = Between {
                        memory: Some(Memory {
                            engine: engine.reborrow(),
                            areas: &mut areas,
                        }),
                        forces: &mut *self.forces,
                        trace: &mut *self.trace,
                        cycles: *self.cycles_total,
                    };
                    action(&mut between);
                }
                // An online change waits for a moment when no task is in a cycle; here one is
                // halted in its cycle, and an online change never abandons a cycle.
                Ok(Command::OnlineChange(change, reply)) => {
                    let (refused, ..) = *change;
                    let _ = reply.send((Err(SchedulerError::Halted), Some(refused)));
                }
                Ok(other) => {
                    engine.debug_mut().abandon_halted();
                    self.deferred.push(other);
                }
                Err(mpsc::RecvTimeoutError::Timeout) => {}
                Err(mpsc::RecvTimeoutError::Disconnected) => engine.debug_mut().abandon_halted(),
            }
        }
        self.take_areas(&mut engine);
        let halted_ns = self.now_ns().saturating_sub(entered);
        // Neither the halted task nor a task waiting beneath it counts the time halted.
        for level in self.levels.iter_mut() {
            level.preempted_ns += halted_ns;
        }
        if let Some(top) = self.levels.last() {
            self.arm_above(top.priority);
        }
    }

    /// Queues the retained values for the writer when a save is due, as the worker does
    /// between cycles.
    fn save_retain(&mut self, engine: &EngineView<'_>, now: u64) {
        let (Some(writer), next, interval) = (self.retain.0, &mut *self.retain.1, self.retain.2)
        else {
            return;
        };
        if now < *next {
            return;
        }
        *next = now + interval;
        if let Some(snapshot) = RetainSnapshot::of_data(engine.image(), engine.region(Region::Data))
        {
            writer.write_later(snapshot);
        }
    }

    /// Copies `%Q` and `%M` of `engine` to the located areas, with the forces.
    fn publish(&mut self, engine: &EngineView<'_>) {
        let lock_of = self.areas_lock;
        let areas = self.areas.get_or_insert_with(|| lock(lock_of));
        copy(engine.region(Region::Output), &mut areas.output);
        copy(engine.region(Region::Memory), &mut areas.memory);
        self.forces.apply_to_areas(areas);
    }

    /// Takes the located areas again and copies what the outside world wrote meanwhile into
    /// `engine`, as the worker does before a cycle.
    fn take_areas(&mut self, engine: &mut EngineView<'_>) {
        let lock_of = self.areas_lock;
        let areas = self.areas.get_or_insert_with(|| lock(lock_of));
        copy(&areas.input, engine.region_mut(Region::Input));
        copy(&areas.output, engine.region_mut(Region::Output));
        copy(&areas.memory, engine.region_mut(Region::Memory));
    }
}
