//! What the scheduler thread does while a task is halted (`docs/debugging.md` §2): from inside
//! the halted cycle, it publishes `%Q` and `%M`, serves the commands, runs the other tasks when they are due (lower priorities too) and looks at the
//! event triggers, until the task may go on; the time halted counts neither in the cycle's
//! time nor in the watchdog of any cycle in progress. A cycle the halt runs serves the
//! commands at its safe points (at least every [`HALT_POLL`]), so a task that loops does not
//! make the debugger wait for its watchdog. A stop, reset, download or shutdown abandons the
//! halted cycles, and every cycle beneath or above them at its next safe point, and is done
//! by the worker once they have unwound.

use std::time::Duration;

use program_image::Region;

use super::cycles::Cycles;
use super::inbox::Received;
use super::located;
use super::worker::lock;
use super::{Between, Command, Retired, SchedulerError};
use crate::engine::EngineView;
use crate::online::Memory;
use crate::retain::RetainSnapshot;

/// The longest wait for a command while halted, so event triggers are looked at often enough;
/// also how often a cycle run by the halt lets the commands in.
pub(super) const HALT_POLL: Duration = Duration::from_millis(10);

impl Cycles<'_, '_> {
    /// Serves the halt of `task` on `engine` until it may go on or its cycle is abandoned.
    pub(super) fn serve_halt(&mut self, mut engine: EngineView<'_>, task: usize) {
        let entered = self.now_ns();
        self.halts += 1;
        self.disarm();
        // What the halted cycle wrote so far becomes visible, as at the end of a cycle (when the
        // areas are free: else at the next look).
        let mut published = located::publish(self.areas, &engine, self.forces);
        // The cycles the halt runs publish their outputs, as outermost ones do.
        let publish_depth = std::mem::replace(&mut self.publish_depth, self.levels.len());
        while engine.debug().is_halted(task) && !engine.debug().abandoning() {
            if !published {
                published = located::publish(self.areas, &engine, self.forces);
            }
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
                located::take_in(self.areas, &mut engine);
                self.run(&mut engine, next);
                continue;
            }
            // The tasks in a cycle (the halted one among them) are planned in the past: only
            // the others say how long to wait, or the thread would spin while halted.
            let mut wait = super::plan::next_start_where(self.plans, |index, _| idle(index))
                .map_or(HALT_POLL, |at| Duration::from_nanos(at.saturating_sub(now)))
                .min(HALT_POLL);
            // Statistics and faults a reader kept from being published go out while halted too.
            if !self.outbox.try_publish(self.status, self.plans) {
                wait = wait.min(super::inbox::LOCK_RETRY);
            }
            self.serve_postponed(&mut engine);
            match self.commands.wait(Some(wait)) {
                Received::Command(command) => self.serve_while_halted(&mut engine, command),
                Received::Nothing => {}
                Received::Gone => engine.debug_mut().abandon_halted(),
            }
        }
        self.halts -= 1;
        self.publish_depth = publish_depth;
        // What the outside world wrote meanwhile, for the rest of the halted cycle (a waiting
        // one takes it at the next exchange when the areas are busy now).
        located::take_in(self.areas, &mut engine);
        let halted_ns = self.now_ns().saturating_sub(entered);
        // Neither the halted task nor a task waiting beneath it counts the time halted.
        for level in self.levels.iter_mut() {
            level.preempted_ns += halted_ns;
        }
        if let Some(top) = self.levels.last() {
            self.arm_above(top.priority);
        }
    }

    /// Serves the commands that came while a cycle run by a halt is in progress, from one of
    /// its safe points: what a halted task is told (continue, logout) is heard without waiting
    /// for that cycle's end, and a stop abandons it here.
    pub(super) fn serve_above_halt(&mut self, engine: &mut EngineView<'_>) {
        self.serve_postponed(engine);
        loop {
            match self.commands.try_take() {
                Received::Command(command) => self.serve_while_halted(engine, command),
                Received::Nothing => return,
                Received::Gone => {
                    engine.debug_mut().abandon_halted();
                    return;
                }
            }
        }
    }

    /// Serves the commands postponed before the halt because the areas were busy, in the order
    /// they came and before any newer one: the client that sent them may be the one that has
    /// to continue the halt.
    fn serve_postponed(&mut self, engine: &mut EngineView<'_>) {
        while let Some(command) = self.postponed.pop_front() {
            self.serve_while_halted(engine, command);
        }
    }

    /// Does a command that came while a task is halted: an action at once, on the memory as it
    /// is; an online change refused; anything else (stop, reset, download, shutdown) abandons
    /// the cycles in progress and is left for the worker.
    fn serve_while_halted(&mut self, engine: &mut EngineView<'_>, command: Command) {
        match command {
            Command::Between(action) => {
                // While a task is halted the thread may wait for the areas: debugging suspends
                // the timing guarantees anyway.
                let mut areas = lock(self.areas);
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
            Command::OnlineChange(change, reply) => {
                let (refused, _, _, _, master) = *change;
                let retired = Retired {
                    engine: Some(refused),
                    master: Some(master),
                };
                let _ = reply.send((Err(SchedulerError::Halted), retired));
            }
            other => {
                engine.debug_mut().abandon_halted();
                self.deferred.push(other);
            }
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
}
