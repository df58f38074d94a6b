//! The real-time scheduler: runs an engine's tasks on their own thread, as the task table says.
//!
//! [`Scheduler`] is a handle on that thread. The thread owns the [`Engine`] and runs one task
//! cycle at a time:
//!
//! - a cyclic task every `interval_ns`, keeping its phase (a cycle that overruns its interval
//!   makes the next start at once, and the cycles missed meanwhile are dropped);
//! - a freewheeling task again [`SchedulerOptions::freewheeling_pause`] after each cycle, so
//!   that tasks of lower priority get their turn;
//! - an event task once per rising edge of its BOOL trigger, which the scheduler looks at before
//!   each decision and at least every [`SchedulerOptions::event_poll_interval`] (an edge that
//!   comes and goes between two looks is missed).
//!
//! When several tasks are due, the one with the highest priority (0 highest, 31 lowest) runs
//! first, then the one planned earliest. A task that becomes due while a task of strictly lower
//! priority runs interrupts that cycle at its next safe point (a backward jump or a call), runs
//! its own cycle on the same memory, and the interrupted cycle goes on; such cycles nest, one
//! level per distinct priority. A small alarm thread sets the flag the interpreter reads at its
//! safe points. [`SchedulerOptions::preemption`] turns this off. `docs/scheduler.md` describes
//! the model: safe points, nesting, data shared between tasks, watchdog and statistics.
//!
//! The outermost cycle copies `%I`, `%Q` and `%M` from the shared [`LocatedAreas`] into the
//! engine, runs the task's programs, and copies `%Q` and `%M` back, all with the areas locked, so
//! a Modbus request always sees them between two outermost cycles; a cycle that interrupts it
//! does not copy them in again. Forces, the trace and the statistics work per cycle, nested or
//! not; a task's cycle time and its watchdog count its own time, without the cycles that
//! interrupted it.
//!
//! The watchdog has two parts. The engine aborts a cycle that runs longer than `watchdog_ns ×
//! watchdog_sensitivity`; the scheduler counts cycles that ran longer than `watchdog_ns` but
//! finished, and faults the task at `watchdog_sensitivity` of them in a row. A faulted task runs
//! no more until a reset; the other tasks go on and the scheduler's state is
//! [`SchedulerState::Faulted`].
//!
//! With a data directory, RETAIN and PERSISTENT variables are restored when an image is loaded,
//! saved when the scheduler stops or shuts down and, while it runs, every
//! [`SchedulerOptions::retain_save_interval`] when they changed (see [`crate::retain`]). While it
//! runs, the scheduler only copies the retained bytes between two cycles; a thread of its own
//! writes them, so the disk never delays a task.

mod alarm;
mod cycles;
mod halt;
mod inbox;
mod located;
mod modbus_io;
mod outbox;
mod plan;
pub(crate) mod realtime;
mod record;
mod retain_writer;
mod statistics;
mod worker;

use std::path::PathBuf;
use std::sync::{Arc, Mutex, PoisonError, mpsc};
use std::thread::JoinHandle;
use std::time::Duration;

use program_image::{ImageHash, ProgramImage};

use crate::areas::LocatedAreas;
use crate::engine::{
    AppliedChange, Engine, EngineChoice, FaultRecord, LoadError, NativeReport, OnlineChangePlan,
    ResetKind,
};
use crate::modbus::master::{DeviceStatus, Master, MasterError, MasterHandle, MasterOptions};
use crate::online::{Forces, Memory, Trace};
use crate::retain::{RetainError, RetainRestore};

pub(crate) use realtime::make_current_thread_normal;
pub use realtime::{MAX_REALTIME_PRIORITY, Realtime};
pub use record::CycleRecord;
pub use statistics::TaskStatistics;

/// What the scheduler is doing.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SchedulerState {
    /// No task runs (no program, or stopped).
    Stopped,
    /// Every task runs.
    Running,
    /// Running, but at least one task has faulted and runs no more.
    Faulted,
}

/// How the scheduler behaves; fixed for its life.
#[derive(Clone, Debug)]
pub struct SchedulerOptions {
    /// Where RETAIN and PERSISTENT variables are saved; `None` keeps them in memory only.
    pub data_dir: Option<PathBuf>,
    /// How often changed retained values are saved while running.
    pub retain_save_interval: Duration,
    /// The pause after each cycle of a freewheeling task.
    pub freewheeling_pause: Duration,
    /// The longest time between two looks at the triggers of event tasks.
    pub event_poll_interval: Duration,
    /// How long before a planned start the scheduler stops sleeping and yields the processor
    /// in a loop instead: less start jitter (a sleep wakes late by the system's timer slack and
    /// wake-up latency) for that much busy time per cycle. Zero always sleeps. The preemption
    /// alarm spins (without yielding) for that long before the start of a task that interrupts
    /// another.
    pub spin_before_start: Duration,
    /// Whether a task of higher priority that becomes due interrupts a running cycle of a
    /// lower one at its next safe point (`docs/scheduler.md`); off, every cycle runs to its end.
    pub preemption: bool,
    /// Where to send a record of every finished cycle (for measurements such as the jitter
    /// benchmark); the channel is unbounded, so its receiver must keep reading.
    pub cycle_log: Option<mpsc::Sender<CycleRecord>>,
    /// The `SCHED_FIFO` priority (1–99) of the scheduler's thread, the preemption alarm's one
    /// above (`docs/scheduler.md` §6); `None` keeps normal scheduling. Refused without the
    /// right to it (root or CAP_SYS_NICE): then the status says why and the tasks still run.
    pub realtime_priority: Option<u8>,
    /// The Modbus master of an image with runtime devices (`docs/modbus-master.md` §6.11): on
    /// or off, the serial ports' device files on this machine, where state lines go.
    pub modbus_master: MasterOptions,
    /// The engine every image is loaded with: by [`Scheduler::load`], and by the online
    /// services for a download or an online change (`docs/native-engine.md` §8.3).
    pub engine: EngineChoice,
}

/// A snapshot of the scheduler's state, statistics and faults.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SchedulerStatus {
    /// Stopped, running or faulted.
    pub state: SchedulerState,
    /// The identity hash of the loaded image, if any.
    pub image: Option<ImageHash>,
    /// The statistics of each task, in task-table order.
    pub tasks: Vec<TaskStatistics>,
    /// The last faults, oldest first (at most [`MAX_FAULTS`]); kept over resets and loads.
    pub faults: Vec<FaultRecord>,
    /// How many faults there have been since the scheduler started, older ones included.
    pub faults_total: u64,
    /// Why the last periodic save of retained values failed; `None` once one succeeds.
    pub retain_problem: Option<String>,
    /// The scheduling the scheduler's thread got.
    pub realtime: Realtime,
}

/// The native stack of the scheduler's thread: a cycle may use
/// [`crate::engine::NATIVE_STACK_BUDGET`] and, with preemption, cycles nest one level per
/// distinct priority (32), each with the same budget, plus room for the scheduler itself. Only
/// the pages touched are ever backed by memory.
const SCHEDULER_STACK_BYTES: usize =
    PRIORITY_LEVELS * (crate::engine::NATIVE_STACK_BUDGET + 64 * 1024) + 2 * 1024 * 1024;

/// How many distinct priorities there are (0 to 31).
const PRIORITY_LEVELS: usize = 32;

/// How many fault records the status keeps.
pub const MAX_FAULTS: usize = 64;

/// What loading an image did besides loading it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LoadReport {
    /// What became of the saved retained values; `None` without a data directory.
    pub retain: Option<RetainRestore>,
    /// How many RETAIN and PERSISTENT variables of the program loaded before kept their
    /// values because they kept their path and type.
    pub carried: usize,
    /// What the engine choice made of the image (`docs/native-engine.md` §8.2); the online
    /// services do not send it in protocol version 3.
    pub native: NativeReport,
}

/// What an online change did (`docs/protocol.md` §7, `ONLINE_CHANGE_APPLY`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct OnlineChangeReport {
    /// Cycles run by all tasks before the switch.
    pub cycles: u64,
    /// What the switch carried, moved and cleared.
    pub applied: AppliedChange,
    /// How many forces were released because their variable is gone or changed type.
    pub forces_released: usize,
    /// Whether the trace was removed because one of its variables is gone or changed type.
    pub trace_removed: bool,
    /// How long no task could start.
    pub switch: Duration,
}

/// The scheduler's answer to an online change, with what it no longer needs, for the asking
/// thread to drop.
type ChangeAnswer = (Result<OnlineChangeReport, SchedulerError>, Retired);

/// The scheduler's answer to a load, with what it no longer needs, for the asking thread to
/// drop.
type LoadAnswer = (Result<LoadReport, SchedulerError>, Retired);

/// What a load or an online change leaves over: freeing an engine's code takes milliseconds
/// for a large program, and stopping a Modbus master joins its threads, which may wait for a
/// name lookup (`docs/modbus-master.md` §6.10); on the asking thread neither holds a task.
#[derive(Default)]
struct Retired {
    /// The old engine after a switch or a load, the new one when refused.
    engine: Option<Engine>,
    /// The old master when a new one replaced it, or the new one when it is not needed.
    master: Option<MasterHandle>,
}

/// What an action run between two cycles (see [`Scheduler::between`]) may touch; it lives only
/// while the action runs.
pub struct Between<'a> {
    /// The loaded program's memory and the located areas (locked); `None` without a program.
    pub memory: Option<Memory<'a>>,
    /// The force table.
    pub forces: &'a mut Forces,
    /// The trace recorder.
    pub trace: &'a mut Trace,
    /// Cycles run by all tasks since the scheduler started.
    pub cycles: u64,
}

/// Why the scheduler could not do what it was asked.
#[derive(Debug, thiserror::Error)]
pub enum SchedulerError {
    /// Starting without a program.
    #[error("no program is loaded")]
    NoProgram,
    /// The image cannot be loaded; the scheduler keeps what it had.
    #[error("the program image cannot be loaded: {0}")]
    Load(#[from] LoadError),
    /// Retained values could not be saved or deleted; the rest of the command was done.
    #[error(transparent)]
    Retain(#[from] RetainError),
    /// An online change was planned against another program than the one running now.
    #[error("the running program changed since the online change was checked")]
    ProgramChanged,
    /// An online change came while a task is halted at a breakpoint: it would abandon the
    /// halted cycle, which an online change never does.
    #[error("a task is halted: continue it first (an online change never abandons a cycle)")]
    Halted,
    /// The image's Modbus master cannot run: its paths do not fit the program, or its threads
    /// cannot be started; the scheduler keeps what it had.
    #[error(transparent)]
    ModbusMaster(#[from] MasterError),
    /// The scheduler's thread could not be started or has ended.
    #[error("the scheduler thread is not running")]
    Gone,
}

/// A handle on the scheduler's thread. Dropping it stops the tasks, saves retained values and
/// ends the thread.
pub struct Scheduler {
    commands: inbox::Postbox,
    /// The scheduler's thread, unparked after each command (`inbox.rs`).
    waker: std::thread::Thread,
    status: Arc<Mutex<SchedulerStatus>>,
    /// The Modbus master's devices of the loaded program, replaced at each load.
    modbus_devices: ModbusDevices,
    /// How the masters run; each load's master is prepared on the caller's thread.
    modbus_master: MasterOptions,
    /// The engine every image is loaded with.
    engine: EngineChoice,
    thread: Option<JoinHandle<()>>,
}

/// The counters of the loaded program's Modbus devices, shared with the worker, which
/// replaces the list when it loads a program.
pub(crate) type ModbusDevices = Arc<Mutex<Vec<Arc<Mutex<DeviceStatus>>>>>;

impl Default for SchedulerOptions {
    /// No data directory; retained values saved every second; a freewheeling task pauses
    /// 500 µs; event triggers looked at every millisecond at least; no spinning; preemption on;
    /// no cycle log; normal scheduling; the Modbus master on; the default engine.
    fn default() -> Self {
        Self {
            data_dir: None,
            retain_save_interval: Duration::from_secs(1),
            freewheeling_pause: Duration::from_micros(500),
            event_poll_interval: Duration::from_millis(1),
            spin_before_start: Duration::ZERO,
            preemption: true,
            cycle_log: None,
            realtime_priority: None,
            modbus_master: MasterOptions::default(),
            engine: EngineChoice::default(),
        }
    }
}

impl Scheduler {
    /// Starts the scheduler's thread, stopped and without a program, on `areas`.
    pub fn spawn(
        areas: Arc<Mutex<LocatedAreas>>,
        options: SchedulerOptions,
    ) -> Result<Self, SchedulerError> {
        let (commands, received) = inbox::queue();
        let status = Arc::new(Mutex::new(SchedulerStatus {
            state: SchedulerState::Stopped,
            image: None,
            tasks: Vec::new(),
            faults: Vec::new(),
            faults_total: 0,
            retain_problem: None,
            realtime: Realtime::Normal,
        }));
        let realtime_priority = options.realtime_priority;
        let modbus_master = options.modbus_master.clone();
        let engine = options.engine;
        let modbus_devices = ModbusDevices::default();
        let worker = worker::Worker::new(
            areas,
            Arc::clone(&status),
            Arc::clone(&modbus_devices),
            options,
        );
        let (scheduled, scheduling) = mpsc::sync_channel(1);
        let thread = std::thread::Builder::new()
            .name("rivet-scheduler".to_owned())
            .stack_size(SCHEDULER_STACK_BYTES)
            .spawn(move || {
                let realtime = realtime_priority
                    .map_or(Realtime::Normal, realtime::make_current_thread_realtime);
                let _ = scheduled.send(realtime);
                worker.run(&received);
            })
            .map_err(|_| SchedulerError::Gone)?;
        // Known before the first command, so a caller can report it at once.
        if let Ok(realtime) = scheduling.recv() {
            status
                .lock()
                .unwrap_or_else(PoisonError::into_inner)
                .realtime = realtime;
        }
        Ok(Self {
            commands,
            waker: thread.thread().clone(),
            status,
            modbus_devices,
            modbus_master,
            engine,
            thread: Some(thread),
        })
    }

    /// Verifies and loads `image`, replacing the program (after saving its retained values),
    /// and restores retained values saved for the same layout. The scheduler keeps running if
    /// it ran. When the image is refused, everything stays as it was.
    pub fn load(&self, image: ProgramImage) -> Result<LoadReport, SchedulerError> {
        let identity = image.identity();
        // Translated here, on the caller's thread: the tasks go on meanwhile.
        let (engine, _) = Engine::with_choice(image, self.engine)?;
        // The new master is made here, not on the scheduler's thread, which may run at
        // real-time priority and must not wait for threads to start; its devices begin
        // polling once the old master has closed its connections and ports.
        let master = Master::start(engine.image(), &self.modbus_master)?;
        let starter = master.starter();
        let (loaded, retired) =
            self.ask(|reply| Command::Load(Box::new((engine, identity, master)), reply))?;
        drop(retired);
        starter.go();
        loaded
    }

    /// The engine every image is loaded with ([`SchedulerOptions::engine`]); an online change
    /// prepares its new engine with it too.
    pub fn engine_choice(&self) -> EngineChoice {
        self.engine
    }

    /// Replaces the running program, made from the image `from`, with `engine` (made from
    /// `to`) between two cycles without stopping the tasks, carrying the values by `plan`
    /// (made for those two images, and possible); the tasks keep their schedule, cycle counts,
    /// statistics and faults, and forces and the trace follow their variables.
    pub fn online_change(
        &self,
        engine: Engine,
        plan: Arc<OnlineChangePlan>,
        from: ImageHash,
        to: ImageHash,
    ) -> Result<OnlineChangeReport, SchedulerError> {
        // Prepared whether or not the switch keeps the running master (only the scheduler
        // knows): a master that is not needed goes back unstarted with the answer.
        let master = Master::start(engine.image(), &self.modbus_master)?;
        let starter = master.starter();
        let (result, retired) = self.ask(|reply| {
            Command::OnlineChange(Box::new((engine, plan, from, to, master)), reply)
        })?;
        // Freeing an engine's code and joining a master's threads take time: here, on the
        // caller's thread, they hold no task.
        drop(retired);
        starter.go();
        result
    }

    /// The loaded program's Modbus devices with their state and counters, in the image's
    /// order (`docs/modbus-master.md` §9.1); empty without a program or without devices.
    pub fn modbus_devices(&self) -> Vec<online_protocol::ModbusDeviceReport> {
        self.each_modbus_device(DeviceStatus::snapshot)
    }

    /// How many connections each loaded Modbus device has tried to open (TCP; 0 on a serial
    /// line), in the image's order. `MODBUS_DEVICES` does not carry the count: it is for the
    /// runtime's own readers and the tests that check the back-off (§6.8).
    pub fn modbus_connection_attempts(&self) -> Vec<u32> {
        self.each_modbus_device(|status| status.connection_attempts)
    }

    /// `read` of each loaded Modbus device's status, in the image's order. A poisoned lock
    /// still holds the last status written, which is what a reader wants to see.
    fn each_modbus_device<T>(&self, read: impl Fn(&DeviceStatus) -> T) -> Vec<T> {
        self.modbus_devices
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .iter()
            .map(|device| read(&device.lock().unwrap_or_else(PoisonError::into_inner)))
            .collect()
    }

    /// Starts every task that has not faulted.
    pub fn start(&self) -> Result<(), SchedulerError> {
        self.ask(Command::Start)?
    }

    /// Stops every task after its current cycle and saves the retained values.
    pub fn stop(&self) -> Result<(), SchedulerError> {
        self.ask(Command::Stop)?
    }

    /// Stops, re-initialises memory as `kind` says (an origin reset also deletes the saved
    /// retained values), clears the tasks' faults and statistics, and stays stopped.
    pub fn reset(&self, kind: ResetKind) -> Result<(), SchedulerError> {
        self.ask(|reply| Command::Reset(kind, reply))?
    }

    /// Runs `action` on the scheduler's thread between two cycles (at once when stopped), with
    /// the located areas locked, and returns what it returns. It should be quick: no task runs
    /// meanwhile. With preemption, "between two cycles" means between two outermost cycles:
    /// no cycle is interrupted then.
    pub fn between<T: Send + 'static>(
        &self,
        action: impl FnOnce(&mut Between<'_>) -> T + Send + 'static,
    ) -> Result<T, SchedulerError> {
        self.ask(|reply: inbox::Answer<T>| {
            Command::Between(Box::new(move |between| {
                let _ = reply.send(action(between));
            }))
        })
    }

    /// The state, statistics and faults now.
    pub fn status(&self) -> SchedulerStatus {
        self.status
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .clone()
    }

    /// Stops, saves the retained values and ends the thread.
    pub fn shutdown(mut self) -> Result<(), SchedulerError> {
        let saved = self.ask(Command::Shutdown);
        if let Some(thread) = self.thread.take() {
            // The worker catches nothing: a panic there has already been reported by the
            // panic hook, and the handle has nothing left to do about it.
            let _ = thread.join();
        }
        saved?
    }

    /// Sends a command and waits for its answer.
    fn ask<T>(
        &self,
        command: impl FnOnce(inbox::Answer<T>) -> Command,
    ) -> Result<T, SchedulerError> {
        let (reply, answer) = inbox::answer();
        self.commands
            .send(command(reply))
            .map_err(|_| SchedulerError::Gone)?;
        self.waker.unpark();
        inbox::wait_for_answer(&answer).ok_or(SchedulerError::Gone)
    }
}

impl Drop for Scheduler {
    fn drop(&mut self) {
        if let Some(thread) = self.thread.take() {
            // A failed save cannot be reported from a drop; `shutdown` reports it.
            let (reply, answer) = inbox::answer();
            if self.commands.send(Command::Shutdown(reply)).is_ok() {
                self.waker.unpark();
                let _ = inbox::wait_for_answer(&answer);
            }
            let _ = thread.join();
        }
    }
}

/// The answer to a command.
type Reply = inbox::Answer<Result<(), SchedulerError>>;

/// What the handle asks of the thread.
enum Command {
    /// A load: the new engine, its image's identity and its master, prepared (not polling).
    Load(
        Box<(Engine, ImageHash, MasterHandle)>,
        inbox::Answer<LoadAnswer>,
    ),
    Start(Reply),
    Stop(Reply),
    Reset(ResetKind, Reply),
    /// An online change: the new engine, its plan, the images it changes from and to, and the
    /// new image's master, prepared (not polling).
    OnlineChange(
        Box<(
            Engine,
            Arc<OnlineChangePlan>,
            ImageHash,
            ImageHash,
            MasterHandle,
        )>,
        inbox::Answer<ChangeAnswer>,
    ),
    /// An action between two cycles, which sends its own answer.
    Between(BetweenAction),
    Shutdown(Reply),
}

/// An action run between two cycles.
type BetweenAction = Box<dyn FnOnce(&mut Between<'_>) + Send>;

#[cfg(test)]
mod tests;

#[cfg(test)]
mod clock_tests;
#[cfg(test)]
mod halt_tests;
#[cfg(test)]
mod lock_tests;
#[cfg(test)]
mod preemption_tests;
