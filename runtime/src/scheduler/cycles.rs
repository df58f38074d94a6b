//! One task cycle with everything around it (forces, located areas, trace, statistics, faults),
//! and the cycles of tasks of higher priority that interrupt it at its safe points.
//!
//! The outermost cycle is started by the worker after exchanging the located areas with the
//! engine; a cycle that interrupts another runs on the same engine memory, so it does not take
//! the areas in again (that would undo what the interrupted cycle wrote), and does not publish
//! its `%Q` and `%M` either: the outermost cycle does at its end, so nobody sees the
//! intermediate state. Every cycle, nested or not, applies the forces before and after, feeds
//! the trace at its end, and records its statistics. None of it waits for a lock another
//! thread holds (`located.rs`, `outbox.rs`).

use std::panic::AssertUnwindSafe;
use std::sync::atomic::AtomicBool;
use std::sync::{Mutex, mpsc};
use std::time::{Duration, Instant};

use online_protocol::Place;
use program_image::{ProgramImage, Region};

use super::alarm::Alarm;
use super::modbus_io::ModbusIo;
use super::outbox::Outbox;
use super::plan::{self, TaskPlan};
use super::record::CycleRecord;
use super::retain_writer::RetainWriter;
use super::{Command, SchedulerStatus};
use crate::areas::LocatedAreas;
use crate::engine::{EngineView, FaultKind, FaultRecord, Preempt, Preemption, TaskClock};
use crate::online::{Forces, PlaceAccess, Trace};

/// The preemption flag when preemption is off: never set.
static NEVER_DUE: AtomicBool = AtomicBool::new(false);

/// What running cycles touches, borrowed from the worker for the outermost cycle and lent on
/// to the cycles that interrupt it.
pub(super) struct Cycles<'w, 'm> {
    pub(super) plans: &'w mut [TaskPlan],
    pub(super) forces: &'w mut Forces,
    pub(super) trace: &'w mut Trace,
    /// The located areas, exchanged with the engine when their lock is free.
    pub(super) areas: &'m Mutex<LocatedAreas>,
    /// Cycles that start at this depth of nesting or less publish `%Q` and `%M` at their end:
    /// 0, the outermost only, but while a halt runs cycles above it.
    pub(super) publish_depth: usize,
    /// The scheduler's commands, served while a task is halted.
    pub(super) commands: &'w super::inbox::Inbox,
    /// The commands the worker postponed while the areas were busy; a halt serves them first.
    pub(super) postponed: &'w mut std::collections::VecDeque<Command>,
    /// Commands that abandoned the halted cycles, for the worker once they have unwound.
    pub(super) deferred: &'w mut Vec<Command>,
    /// Saves retained values while a task is halted, as between cycles: the writer, when the
    /// next save is due, and the interval between saves.
    pub(super) retain: (Option<&'w RetainWriter>, &'w mut u64, u64),
    pub(super) status: &'w Mutex<SchedulerStatus>,
    /// Statistics and faults waiting for the status's lock.
    pub(super) outbox: &'w mut Outbox,
    /// The preemption alarm; `None` runs every cycle to its end.
    pub(super) alarm: Option<&'w Alarm>,
    /// The origin of the scheduler's clock.
    pub(super) epoch: Instant,
    /// The pause after each cycle of a freewheeling task.
    pub(super) pause_ns: u64,
    /// The longest time between two looks at the triggers of event tasks.
    pub(super) event_poll_ns: u64,
    /// Cycles run by all tasks since the scheduler started.
    pub(super) cycles_total: &'w mut u64,
    /// Where each cycle's record goes, if anywhere.
    pub(super) log: Option<&'w mpsc::Sender<CycleRecord>>,
    /// The cycles in progress, outermost first (empty between outermost cycles; kept by the
    /// worker so that a cycle allocates nothing).
    pub(super) levels: &'w mut Vec<Level>,
    /// How many halts are being served beneath the running cycle: while there are any, its
    /// safe points serve the commands too.
    pub(super) halts: u32,
    /// The Modbus master's copy points, when the program has runtime devices.
    pub(super) modbus: Option<&'w mut ModbusIo>,
}

/// A cycle in progress.
pub(super) struct Level {
    pub(super) task: usize,
    pub(super) priority: u8,
    /// Nanoseconds spent so far in cycles that interrupted this one, or halted.
    pub(super) preempted_ns: u64,
}

impl Cycles<'_, '_> {
    /// Runs one cycle of `task` on `engine` (whose located regions hold the areas' values),
    /// then plans its next one and publishes its statistics and fault.
    pub(super) fn run(&mut self, engine: &mut EngineView<'_>, task: usize) {
        let Some(plan) = self.plans.get(task) else {
            return;
        };
        let Some(planned) = plan.next_start_ns() else {
            return;
        };
        let cycle = plan.statistics.cycles;
        let priority = plan.statistics.priority;
        let interrupted = self.levels.last().map(|level| level.task);
        let depth = self.levels.len();
        self.levels.push(Level {
            task,
            priority,
            preempted_ns: 0,
        });
        self.arm_above(priority);
        let started = self.now_ns();
        // The devices' newest rounds come in after the located areas and before the forces,
        // so a forced variable of a read channel holds (`docs/modbus-master.md` §4.1).
        if let Some(modbus) = self.modbus.as_deref_mut() {
            modbus.cycle_start(task, engine);
        }
        // Forced values hold before and after the cycle, whatever the program assigns.
        self.forces.apply_to_view(engine);
        // The hook is given without preemption too: it serves the halts of the debugger.
        let due = self.alarm.map_or(&NEVER_DUE, Alarm::due);
        let preemption = Preemption { due, hook: self };
        let result = run_guarded(engine, task, started, cycle, Some(preemption));
        // A panic of the scheduler's own code in a nested cycle unwinds to this cycle's guard
        // without popping its levels; what is left of them belongs to no running cycle.
        self.levels.truncate(depth + 1);
        self.forces.apply_to_view(engine);
        // The devices get the outputs with the forces applied: a forced value is sent. A halted
        // cycle abandoned by a stop, reset or download did not end: its half-run outputs and
        // edges are not the program's, and its end wakes no device.
        let abandoned = matches!(&result, Err(fault) if fault.kind == FaultKind::Abandoned);
        if !abandoned && let Some(modbus) = self.modbus.as_deref_mut() {
            modbus.cycle_end(task, engine);
        }
        if depth <= self.publish_depth {
            // A busy lock leaves the outputs to the next exchange, which loses nothing.
            super::located::publish(self.areas, engine, self.forces);
        }
        *self.cycles_total += 1;
        if self.trace.recording_task() == Some(task) {
            let engine = &*engine;
            self.trace
                .end_of_cycle(cycle + 1, started, |place| read_place(place, engine));
        }
        let ended = self.now_ns();
        let preempted_ns = self.levels.pop().map_or(0, |level| level.preempted_ns);
        match self.levels.last() {
            Some(outer) => self.arm_above(outer.priority),
            None => self.disarm(),
        }
        self.finish(
            engine.image(),
            task,
            cycle,
            result,
            planned,
            started,
            ended,
            preempted_ns,
        );
        if let Some(log) = self.log {
            // A log whose reader went away is simply not written.
            let _ = log.send(CycleRecord {
                task,
                planned_ns: planned,
                started_ns: started,
                ended_ns: ended,
                preempted_ns,
                interrupted,
            });
        }
    }

    /// Plans the next cycle of `task` and publishes its statistics and its fault, if any.
    #[allow(clippy::too_many_arguments, clippy::result_large_err)]
    fn finish(
        &mut self,
        image: &ProgramImage,
        task: usize,
        cycle: u64,
        result: Result<(), FaultRecord>,
        planned: u64,
        started: u64,
        ended: u64,
        preempted_ns: u64,
    ) {
        let Some(plan) = self.plans.get_mut(task) else {
            return;
        };
        let overrun = plan.finish(planned, started, ended, preempted_ns, self.pause_ns);
        let fault = match result {
            // A halted cycle abandoned by a stop, reset or download is no fault.
            Err(fault) if fault.kind == FaultKind::Abandoned => None,
            Err(fault) => Some(fault),
            Ok(()) if overrun => {
                let limit_us = image.tasks.get(task).map_or(0, |task| task.watchdog_ns) / 1000;
                let kind = FaultKind::Watchdog { limit_us };
                Some(task_fault(image, task, cycle, kind))
            }
            Ok(()) => None,
        };
        if fault.is_some() {
            plan.fault();
        }
        self.outbox.post(fault);
        // A reader holding the status leaves it to the next cycle or the worker's next look.
        self.outbox.try_publish(self.status, self.plans);
    }

    /// Arms the alarm for the earliest planned start of a task of higher priority than
    /// `priority`, and for the next look at the triggers when an event task of higher priority
    /// waits for its trigger.
    pub(super) fn arm_above(&self, priority: u8) {
        let Some(alarm) = self.alarm else {
            return;
        };
        // A task already in a cycle beneath (halted by the debugger) cannot start another, so
        // it arms nothing: the cycles above its halt would stop at every safe point in vain.
        let above = |index: usize, plan: &TaskPlan| {
            plan.statistics.priority < priority
                && !self.levels.iter().any(|level| level.task == index)
        };
        let mut at = self
            .plans
            .iter()
            .enumerate()
            .filter(|(index, plan)| above(*index, plan))
            .filter_map(|(_, plan)| plan.next_start_ns())
            .min();
        if self
            .plans
            .iter()
            .enumerate()
            .any(|(index, plan)| above(index, plan) && plan.is_event() && !plan.statistics.faulted)
        {
            let poll = self.now_ns() + self.event_poll_ns;
            at = Some(at.map_or(poll, |at| at.min(poll)));
        }
        if self.halts > 0 {
            // A halt beneath: the cycle's safe points let the debugger's commands in.
            let poll = self.now_ns() + super::halt::HALT_POLL.as_nanos() as u64;
            at = Some(at.map_or(poll, |at| at.min(poll)));
        }
        alarm.arm(at.map(|at| self.epoch + Duration::from_nanos(at)));
    }

    pub(super) fn disarm(&self) {
        if let Some(alarm) = self.alarm {
            alarm.arm(None);
        }
    }

    /// Looks at the triggers of the event tasks in the interrupted cycle's memory, which holds
    /// the located areas' values of the last exchange.
    pub(super) fn observe_triggers(&mut self, engine: &EngineView<'_>, now: u64) {
        for (task, plan) in self.plans.iter_mut().enumerate() {
            if plan.is_event() {
                let set = trigger_is_set(engine.image(), task, |region| engine.region(region));
                plan.observe_trigger(set, now);
            }
        }
    }

    pub(super) fn now_ns(&self) -> u64 {
        self.epoch.elapsed().as_nanos() as u64
    }
}

impl Preempt for Cycles<'_, '_> {
    /// Runs each task of higher priority than the interrupted one that is due, at most once
    /// each (so the interrupted cycle moves on by at least one safe point between two rounds),
    /// the highest priority first; each may in turn be interrupted by a still higher one.
    fn preempt(&mut self, mut engine: EngineView<'_>) {
        let entered = self.now_ns();
        let Some(priority) = self.levels.last().map(|level| level.priority) else {
            return;
        };
        if self.halts > 0 {
            self.serve_above_halt(&mut engine);
        }
        if engine.debug().abandoning() {
            // The cycle ends at once (the engine sees the same); nothing new starts.
            return;
        }
        if self.plans.iter().any(TaskPlan::is_event) {
            self.observe_triggers(&engine, entered);
        }
        let mut ran = Vec::new();
        // A task already in a cycle beneath (halted by the debugger, which runs tasks of lower
        // priority above it) cannot start another before that one ends.
        while let Some(task) = plan::pick_where(self.plans, self.now_ns(), |index, plan| {
            plan.statistics.priority < priority
                && !ran.contains(&index)
                && !self.levels.iter().any(|level| level.task == index)
        }) {
            ran.push(task);
            self.run(&mut engine, task);
            if engine.debug().abandoning() {
                break;
            }
        }
        self.arm_above(priority);
        let spent = self.now_ns().saturating_sub(entered);
        if let Some(level) = self.levels.last_mut() {
            level.preempted_ns += spent;
        }
    }

    fn halt(&mut self, engine: EngineView<'_>, task: usize) {
        self.serve_halt(engine, task);
    }
}

/// The value at `place` in the engine's memory, forces applied, as the cycle left it.
fn read_place(place: Place, engine: &EngineView<'_>) -> Vec<u8> {
    match place.region_of() {
        Some(region) => place.read_from(engine.region(region)),
        None => Vec::new(),
    }
}

/// Copies as many bytes as both slices have.
pub(super) fn copy(from: &[u8], to: &mut [u8]) {
    let length = from.len().min(to.len());
    to[..length].copy_from_slice(&from[..length]);
}

/// The value of the BOOL trigger of event task `task`, read from the region `bytes` gives.
pub(super) fn trigger_is_set<'b>(
    image: &ProgramImage,
    task: usize,
    bytes: impl Fn(Region) -> &'b [u8],
) -> bool {
    let Some(symbol) = image
        .tasks
        .get(task)
        .and_then(|task| task.trigger)
        .and_then(|trigger| image.symbols.get(trigger as usize))
    else {
        return false;
    };
    let byte = bytes(symbol.region)
        .get(symbol.offset as usize)
        .copied()
        .unwrap_or(0);
    match symbol.bit {
        Some(bit) => byte >> (bit & 7) & 1 == 1,
        None => byte != 0,
    }
}

/// Runs one cycle of `task`. A panic of the engine is a bug of the runtime, not of the program:
/// it faults the task instead of ending the process. A panic in a cycle that interrupted another
/// is caught here too, so the interrupted cycle goes on.
// As for `EngineView::run_cycle`: a fault is rare and ends the task, so its record is not boxed.
#[allow(clippy::result_large_err)]
fn run_guarded(
    engine: &mut EngineView<'_>,
    task: usize,
    now_ns: u64,
    cycle: u64,
    preemption: Option<Preemption<'_>>,
) -> Result<(), FaultRecord> {
    match std::panic::catch_unwind(AssertUnwindSafe(|| {
        engine.run_cycle(task, now_ns as i64, TaskClock::Real, cycle, preemption)
    })) {
        Ok(result) => result,
        Err(panic) => {
            let message = panic
                .downcast_ref::<&str>()
                .map(|text| (*text).to_owned())
                .or_else(|| panic.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "the engine panicked".to_owned());
            Err(task_fault(
                engine.image(),
                task,
                cycle,
                FaultKind::Internal(message),
            ))
        }
    }
}

/// A fault of task `task` that belongs to no single instruction (too many watchdog overruns
/// in a row, a failure of the engine); it names the task's first program.
pub(super) fn task_fault(
    image: &ProgramImage,
    task: usize,
    cycle: u64,
    kind: FaultKind,
) -> FaultRecord {
    let info = image.tasks.get(task);
    FaultRecord {
        task: info.map(|task| task.name.clone()).unwrap_or_default(),
        kind,
        pou: info
            .and_then(|task| task.programs.first())
            .and_then(|call| image.pous.get(call.pou as usize))
            .map(|pou| pou.name.clone())
            .unwrap_or_default(),
        file: None,
        line: None,
        instruction: 0,
        cycle,
    }
}
