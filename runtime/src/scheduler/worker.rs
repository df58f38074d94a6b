//! The scheduler's thread: commands from the handle, and task cycles when they are due.

use std::collections::VecDeque;
use std::sync::{Arc, Mutex, MutexGuard, PoisonError};
use std::time::{Duration, Instant};

use program_image::{ImageHash, Region};

use super::alarm::Alarm;
use super::cycles::{self, Cycles, Level, copy};
use super::inbox::{Inbox, LOCK_RETRY, Received};
use super::located;
use super::modbus_io::ModbusIo;
use super::outbox::Outbox;
use super::plan::{self, TaskPlan};
use super::retain_writer::RetainWriter;
use super::{
    Between, Command, LoadReport, ModbusDevices, PRIORITY_LEVELS, Retired, SchedulerError,
    SchedulerOptions, SchedulerState, SchedulerStatus,
};
use crate::areas::LocatedAreas;
use crate::engine::{Engine, ResetKind};
use crate::modbus::master::MasterHandle;
use crate::online::{Forces, Memory, Trace};
use crate::retain::{RetainSnapshot, RetainStore};

mod switch;

/// How long the thread waits for a command while "halt all" holds every task.
const HOLD_POLL: Duration = Duration::from_millis(10);

/// Everything the scheduler's thread owns.
pub(super) struct Worker {
    areas: Arc<Mutex<LocatedAreas>>,
    status: Arc<Mutex<SchedulerStatus>>,
    options: SchedulerOptions,
    retain: Option<RetainWriter>,
    /// The origin of the scheduler's clock; task time is nanoseconds since then.
    epoch: Instant,
    program: Option<Program>,
    running: bool,
    /// When retained values are next saved, while running.
    next_retain_save_ns: u64,
    /// The forced places, written before and after every cycle; cleared by a load and an
    /// origin reset.
    forces: Forces,
    /// The trace recorder, sampling at the end of its task's cycles; reset by a load.
    trace: Trace,
    /// Cycles run by all tasks since the scheduler started.
    cycles_total: u64,
    /// Sets the preemption flag when a task of higher priority than the running one is due;
    /// `None` when preemption is off.
    alarm: Option<Alarm>,
    /// The cycles in progress while one runs, lent to [`Cycles`].
    levels: Vec<Level>,
    /// Commands that abandoned halted cycles, done once the cycles have unwound.
    deferred: Vec<Command>,
    /// Commands received but not done yet because the located areas were busy, oldest first;
    /// later commands wait behind them, so they are done in the order they came.
    postponed: VecDeque<Command>,
    /// Statistics and faults waiting for the status's lock.
    outbox: Outbox,
    /// The loaded program's Modbus devices' counters, shared with the handle.
    modbus_devices: ModbusDevices,
}

/// A loaded program and the schedule of its tasks.
struct Program {
    engine: Engine,
    plans: Vec<TaskPlan>,
    /// The Modbus master of a program with runtime devices.
    modbus: Option<ModbusIo>,
}

/// Whether the thread goes on after a command.
#[derive(PartialEq)]
enum Next {
    Continue,
    Exit,
}

impl Worker {
    pub(super) fn new(
        areas: Arc<Mutex<LocatedAreas>>,
        status: Arc<Mutex<SchedulerStatus>>,
        modbus_devices: ModbusDevices,
        options: SchedulerOptions,
    ) -> Self {
        let report_status = Arc::clone(&status);
        let report = Arc::new(move |problem: Option<String>| {
            lock(&report_status).retain_problem = problem;
        });
        let alarm = if options.preemption {
            Alarm::spawn(options.spin_before_start, options.realtime_priority)
        } else {
            None
        };
        Self {
            areas,
            status,
            retain: options
                .data_dir
                .clone()
                .map(|dir| RetainWriter::spawn(RetainStore::new(dir), report.clone())),
            options,
            epoch: Instant::now(),
            program: None,
            running: false,
            next_retain_save_ns: 0,
            forces: Forces::default(),
            trace: Trace::default(),
            cycles_total: 0,
            alarm,
            levels: Vec::with_capacity(PRIORITY_LEVELS),
            deferred: Vec::new(),
            postponed: VecDeque::new(),
            outbox: Outbox::default(),
            modbus_devices,
        }
    }

    /// Runs until the handle asks it to end or goes away.
    pub(super) fn run(mut self, commands: &Inbox) {
        loop {
            // Commands first, so the handle is never kept waiting by a busy schedule; those
            // postponed before come first.
            while let Some(command) = self.postponed.pop_front() {
                match self.try_handle(command) {
                    Ok(Next::Exit) => return,
                    Ok(Next::Continue) => {}
                    Err(command) => {
                        self.postponed.push_front(command);
                        break;
                    }
                }
            }
            loop {
                match commands.try_take() {
                    Received::Command(command) => {
                        if self.receive(command) == Next::Exit {
                            return;
                        }
                    }
                    Received::Nothing => break,
                    Received::Gone => return self.exit(),
                }
            }
            let mut wait = self.run_due(commands);
            if let Some(program) = &self.program {
                self.outbox.try_publish(&self.status, &program.plans);
            }
            if !self.postponed.is_empty() || self.outbox.pending() {
                wait = Some(wait.map_or(LOCK_RETRY, |wait| wait.min(LOCK_RETRY)));
            }
            // A command that abandoned halted cycles is done now that they have unwound.
            for command in std::mem::take(&mut self.deferred) {
                if self.receive(command) == Next::Exit {
                    return;
                }
            }
            if wait.is_some_and(|wait| wait.is_zero()) {
                continue;
            }
            match commands.wait(wait) {
                Received::Command(command) => {
                    if self.receive(command) == Next::Exit {
                        return;
                    }
                }
                Received::Nothing => {}
                Received::Gone => return self.exit(),
            }
        }
    }

    /// Runs the task that is due, if any, and returns how long to wait before looking again:
    /// zero after a cycle, `None` when nothing will ever be due without a command.
    fn run_due(&mut self, commands: &Inbox) -> Option<Duration> {
        if !self.running {
            return None;
        }
        let now = self.now_ns();
        self.observe_triggers(now);
        if now >= self.next_retain_save_ns {
            self.save_retain_periodically();
            self.next_retain_save_ns = now + duration_ns(self.options.retain_save_interval);
        }
        let program = self.program.as_ref()?;
        if program.engine.debug().holding() {
            // "Halt all" holds every task: only commands are served, until continue all.
            return Some(HOLD_POLL);
        }
        if let Some(task) = plan::pick(&program.plans, now) {
            self.run_cycle(task, commands);
            return Some(Duration::ZERO);
        }
        let mut wake = self.next_retain_save_ns;
        if let Some(start) = plan::next_start_ns(&program.plans) {
            wake = wake.min(start);
        }
        if program
            .plans
            .iter()
            .any(|plan| plan.is_event() && !plan.statistics.faulted)
        {
            wake = wake.min(now + duration_ns(self.options.event_poll_interval));
        }
        let wait = wake.saturating_sub(now);
        let spin = duration_ns(self.options.spin_before_start);
        if wait <= spin {
            // Close to the start: give the processor away without sleeping, so the wake-up
            // latency of a sleep does not add to the jitter.
            std::thread::yield_now();
            return Some(Duration::ZERO);
        }
        Some(Duration::from_nanos(wait - spin))
    }

    /// Runs one cycle of `task` with the located areas locked (tasks of higher priority may
    /// interrupt it), then plans its next one.
    fn run_cycle(&mut self, task: usize, commands: &Inbox) {
        let Some(program) = self.program.as_mut() else {
            return;
        };
        // When a Modbus thread holds the areas, this cycle runs on the values of the last
        // exchange; nothing is lost (`located.rs`).
        located::take_in(&self.areas, &mut program.engine.view());
        let mut cycles = Cycles {
            plans: &mut program.plans,
            forces: &mut self.forces,
            trace: &mut self.trace,
            areas: &self.areas,
            publish_depth: 0,
            commands,
            postponed: &mut self.postponed,
            deferred: &mut self.deferred,
            retain: (
                self.retain.as_ref(),
                &mut self.next_retain_save_ns,
                duration_ns(self.options.retain_save_interval),
            ),
            status: &self.status,
            outbox: &mut self.outbox,
            alarm: self.alarm.as_ref(),
            epoch: self.epoch,
            pause_ns: duration_ns(self.options.freewheeling_pause),
            event_poll_ns: duration_ns(self.options.event_poll_interval),
            cycles_total: &mut self.cycles_total,
            log: self.options.cycle_log.as_ref(),
            levels: &mut self.levels,
            halts: 0,
            modbus: program.modbus.as_mut(),
        };
        cycles.run(&mut program.engine.view(), task);
        // Abandoned halted cycles have unwound: the next cycles run normally.
        if program.engine.debug().abandoning() {
            program.engine.debug_mut().settled();
        }
    }

    /// Looks at the triggers of the event tasks.
    fn observe_triggers(&mut self, now: u64) {
        let Some(program) = self.program.as_mut() else {
            return;
        };
        if !program.plans.iter().any(TaskPlan::is_event) {
            return;
        }
        // Busy areas: the next look (at most an event poll interval later) sees the trigger.
        let Some(areas) = located::try_lock(&self.areas) else {
            return;
        };
        for (task, plan) in program.plans.iter_mut().enumerate() {
            if plan.is_event() {
                let set = trigger_is_set(&program.engine, &areas, task);
                plan.observe_trigger(set, now);
            }
        }
    }

    /// Does a command that just came, or postpones it behind those postponed before.
    fn receive(&mut self, command: Command) -> Next {
        if !self.postponed.is_empty() {
            self.postponed.push_back(command);
            return Next::Continue;
        }
        match self.try_handle(command) {
            Ok(next) => next,
            Err(command) => {
                self.postponed.push_back(command);
                Next::Continue
            }
        }
    }

    /// Does what the handle asked, but gives back an action between cycles when the located
    /// areas are busy: the thread does not wait for a Modbus thread that holds them.
    fn try_handle(&mut self, command: Command) -> Result<Next, Command> {
        match command {
            Command::Between(action) => {
                let Some(mut areas) = located::try_lock(&self.areas) else {
                    return Err(Command::Between(action));
                };
                let mut between = Between {
                    memory: self.program.as_mut().map(|program| Memory {
                        engine: program.engine.view(),
                        areas: &mut areas,
                    }),
                    forces: &mut self.forces,
                    trace: &mut self.trace,
                    cycles: self.cycles_total,
                };
                action(&mut between);
                Ok(Next::Continue)
            }
            other => Ok(self.handle(other)),
        }
    }

    /// Does what the handle asked.
    fn handle(&mut self, command: Command) -> Next {
        match command {
            Command::Load(load, reply) => {
                let (engine, identity, master) = *load;
                let _ = reply.send(self.load(engine, identity, master));
            }
            Command::Start(reply) => {
                let _ = reply.send(self.start());
            }
            Command::Stop(reply) => {
                let _ = reply.send(self.stop());
            }
            Command::Reset(kind, reply) => {
                let _ = reply.send(self.reset(kind));
            }
            // An action needs the located areas: `try_handle` does it when they are free.
            Command::Between(action) => self.postponed.push_back(Command::Between(action)),
            Command::OnlineChange(change, reply) => {
                let (engine, plan, from, to, master) = *change;
                let _ = reply.send(self.switch(engine, &plan, from, to, master));
            }
            Command::Shutdown(reply) => {
                let _ = reply.send(self.stop());
                return Next::Exit;
            }
        }
        Next::Continue
    }

    /// Ends the thread after the handle went away without asking.
    fn exit(mut self) {
        // Nobody is left to hear about a failed save.
        let _ = self.stop();
    }

    /// Replaces the program with `engine` and its `master` (prepared, not yet polling); the
    /// old engine and master go back for the asking thread to drop. The old master, writing
    /// nothing from now on, is stopped there before the new one begins polling (a serial port
    /// is opened by one master at a time), so its devices take no output of the new program
    /// (`docs/modbus-master.md` §6.10).
    fn load(
        &mut self,
        engine: Engine,
        identity: ImageHash,
        master: MasterHandle,
    ) -> (Result<LoadReport, SchedulerError>, Retired) {
        let mut retired = Retired::default();
        if let Some(old) = self.program.as_mut() {
            retired.master = old.modbus.take().map(ModbusIo::retire);
        }
        let modbus = self.install_master(master);
        let result = self.load_engine(engine, identity, modbus, &mut retired);
        (result, retired)
    }

    /// The rest of [`Worker::load`]: the old program's values, the new program in place.
    fn load_engine(
        &mut self,
        mut engine: Engine,
        identity: ImageHash,
        master: Option<ModbusIo>,
        retired: &mut Retired,
    ) -> Result<LoadReport, SchedulerError> {
        let was_running = self.running;
        // The old program's retained values go to the disk first, so an image with the same
        // retained layout takes them over.
        let saved = self.stop();
        let retain = self
            .retain
            .as_ref()
            .map(|writer| writer.with_store(|store| store.restore(&mut engine)));
        // Variables that keep their path and type keep their values, however the retained
        // layout changed (and without a data directory too).
        let carried = self.program.as_ref().map_or(0, |old| {
            crate::engine::carry_retained(&old.engine, &mut engine)
        });
        {
            let mut areas = lock(&self.areas);
            areas.input = engine.region(Region::Input).to_vec();
            areas.output = engine.region(Region::Output).to_vec();
            areas.memory = engine.region(Region::Memory).to_vec();
            areas.forget_writes();
        }
        let plans = engine.image().tasks.iter().map(TaskPlan::new).collect();
        let native = engine.native_report().clone();
        let old = self.program.replace(Program {
            engine,
            plans,
            modbus: master,
        });
        retired.engine = old.map(|old| old.engine);
        // The new program's places are not the old one's.
        self.forces.clear();
        self.trace.unconfigure();
        self.publish(Some(identity));
        if was_running {
            self.start()?;
        }
        saved?;
        Ok(LoadReport {
            retain,
            carried,
            native,
        })
    }

    fn start(&mut self) -> Result<(), SchedulerError> {
        if self.running {
            return Ok(());
        }
        let now = self.now_ns();
        let Some(program) = self.program.as_mut() else {
            return Err(SchedulerError::NoProgram);
        };
        {
            let areas = lock(&self.areas);
            for (task, plan) in program.plans.iter_mut().enumerate() {
                plan.start(now, trigger_is_set(&program.engine, &areas, task));
            }
        }
        self.running = true;
        if let Some(modbus) = &mut program.modbus {
            modbus.set_running(true);
        }
        self.next_retain_save_ns = now + duration_ns(self.options.retain_save_interval);
        self.publish_state();
        Ok(())
    }

    fn stop(&mut self) -> Result<(), SchedulerError> {
        let was_running = std::mem::replace(&mut self.running, false);
        let saved = match self.program.as_mut() {
            Some(program) => {
                program.plans.iter_mut().for_each(TaskPlan::stop);
                if let Some(modbus) = &mut program.modbus {
                    modbus.set_running(false);
                }
                match (&self.retain, was_running) {
                    (Some(writer), true) => {
                        writer.with_store(|store| store.save(&program.engine).map(|_| ()))
                    }
                    _ => Ok(()),
                }
            }
            None => Ok(()),
        };
        self.publish_state();
        saved.map_err(Into::into)
    }

    fn reset(&mut self, kind: ResetKind) -> Result<(), SchedulerError> {
        let saved = self.stop();
        let Some(program) = self.program.as_mut() else {
            return Err(SchedulerError::NoProgram);
        };
        program.engine.reset(kind);
        // Forces outlive a warm or cold reset and hold at once, also while stopped.
        if kind == ResetKind::Origin {
            self.forces.clear();
        }
        self.forces.apply_to_engine(&mut program.engine);
        program.plans = program
            .engine
            .image()
            .tasks
            .iter()
            .map(TaskPlan::new)
            .collect();
        {
            let mut areas = lock(&self.areas);
            copy(program.engine.region(Region::Output), &mut areas.output);
            copy(program.engine.region(Region::Memory), &mut areas.memory);
            areas.forget_writes();
        }
        let retain = match (&self.retain, kind) {
            (Some(writer), ResetKind::Origin) => writer.with_store(RetainStore::delete),
            (Some(writer), _) => writer.with_store(|store| store.save(&program.engine).map(|_| ())),
            (None, _) => Ok(()),
        };
        let identity = lock(&self.status).image;
        self.publish(identity);
        saved?;
        retain.map_err(Into::into)
    }

    /// Publishes the devices' counters of `master` (a handle without threads when it has no
    /// devices or the master is off); its copy points, `None` when the master copies nothing.
    fn install_master(&mut self, master: MasterHandle) -> Option<ModbusIo> {
        *lock(&self.modbus_devices) = master.statuses();
        // A handle without threads is dropped at once: there is nothing to wait for.
        master.active().then(|| ModbusIo::new(master))
    }

    /// Queues the retained values for the writer thread while running; it writes them when
    /// they changed and shows a failure in the status.
    fn save_retain_periodically(&mut self) {
        let (Some(writer), Some(program)) = (&self.retain, &self.program) else {
            return;
        };
        if let Some(snapshot) = RetainSnapshot::of(&program.engine) {
            writer.write_later(snapshot);
        }
    }

    /// Publishes the whole status after a load or reset.
    fn publish(&mut self, identity: Option<ImageHash>) {
        let mut status = lock(&self.status);
        // The faults of cycles before come first (the statistics are replaced below).
        if let Some(program) = &self.program {
            self.outbox.publish(&mut status, &program.plans);
        }
        status.image = identity;
        status.tasks = self
            .program
            .iter()
            .flat_map(|program| program.plans.iter().map(|plan| plan.statistics.clone()))
            .collect();
        status.state = self.state();
    }

    fn publish_state(&mut self) {
        let mut status = lock(&self.status);
        if let Some(program) = &self.program {
            self.outbox.publish(&mut status, &program.plans);
        }
        status.state = self.state();
    }

    fn state(&self) -> SchedulerState {
        let faulted = self
            .program
            .iter()
            .flat_map(|program| &program.plans)
            .any(|plan| plan.statistics.faulted);
        match (self.running, faulted) {
            (false, _) => SchedulerState::Stopped,
            (true, false) => SchedulerState::Running,
            (true, true) => SchedulerState::Faulted,
        }
    }

    fn now_ns(&self) -> u64 {
        self.epoch.elapsed().as_nanos() as u64
    }
}

/// Locks a mutex whose holder may have panicked: the scheduler's data stays usable, and the
/// Modbus server reports a poisoned area lock on its own.
pub(super) fn lock<T>(mutex: &Mutex<T>) -> MutexGuard<'_, T> {
    mutex.lock().unwrap_or_else(PoisonError::into_inner)
}

fn duration_ns(duration: Duration) -> u64 {
    u64::try_from(duration.as_nanos()).unwrap_or(u64::MAX)
}

/// The value of the BOOL trigger of event task `task` between two cycles: a located one in the
/// shared areas, where Modbus clients write it, another in the engine's data region.
fn trigger_is_set(engine: &Engine, areas: &LocatedAreas, task: usize) -> bool {
    cycles::trigger_is_set(engine.image(), task, |region| match region {
        Region::Data => engine.region(Region::Data),
        Region::Input => &areas.input,
        Region::Output => &areas.output,
        Region::Memory => &areas.memory,
    })
}
