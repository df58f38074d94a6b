//! Running an image on a simulated clock, as `rivet simulate` and tests do: each step advances
//! the clock to the next task that is due and runs every task due then, highest priority first.

use program_image::{ProgramImage, TaskKind};

use crate::engine::{Engine, EngineChoice, FaultRecord, LoadError, NativeReport};

/// The interval a freewheeling or event task gets in simulation, where nothing else paces it.
pub const FREEWHEELING_INTERVAL_NS: u64 = 1_000_000;

/// An engine on a simulated clock.
pub struct Simulation {
    engine: Engine,
    now_ns: i64,
    /// The end of the simulated time run so far.
    horizon_ns: i64,
    /// When each task is next due, and how many cycles it has run.
    next_due_ns: Vec<i64>,
    cycles: Vec<u64>,
    /// Faulted tasks stop; the others go on.
    faults: Vec<FaultRecord>,
}

impl Simulation {
    /// Loads `image` at time 0 with the default engine ([`EngineChoice::default`]).
    pub fn new(image: ProgramImage) -> Result<Self, LoadError> {
        Self::with_choice(image, EngineChoice::default()).map(|(simulation, _)| simulation)
    }

    /// Loads `image` at time 0, run by the engine `choice` names; the report says what the
    /// native engine made of it ([`Engine::with_choice`]).
    pub fn with_choice(
        image: ProgramImage,
        choice: EngineChoice,
    ) -> Result<(Self, NativeReport), LoadError> {
        let (engine, report) = Engine::with_choice(image, choice)?;
        Ok((Self::of_engine(engine), report))
    }

    /// A simulation of the freshly loaded `engine` at time 0, every task due at once and
    /// none faulted.
    fn of_engine(engine: Engine) -> Self {
        let tasks = engine.image().tasks.len();
        Self {
            engine,
            now_ns: 0,
            horizon_ns: 0,
            next_due_ns: vec![0; tasks],
            cycles: vec![0; tasks],
            faults: Vec::new(),
        }
    }

    /// The engine, for reading values.
    pub fn engine(&self) -> &Engine {
        &self.engine
    }

    /// The engine, for writing values between cycles.
    pub fn engine_mut(&mut self) -> &mut Engine {
        &mut self.engine
    }

    /// The simulated time in nanoseconds.
    pub fn now_ns(&self) -> i64 {
        self.now_ns
    }

    /// The faults so far; a faulted task runs no more.
    pub fn faults(&self) -> &[FaultRecord] {
        &self.faults
    }

    /// Cycles run per task.
    pub fn cycles(&self) -> &[u64] {
        &self.cycles
    }

    fn interval_ns(&self, task: usize) -> u64 {
        let info = &self.engine.image().tasks[task];
        match info.kind {
            TaskKind::Cyclic if info.interval_ns > 0 => info.interval_ns,
            _ => FREEWHEELING_INTERVAL_NS,
        }
    }

    fn faulted(&self, task: usize) -> bool {
        let name = &self.engine.image().tasks[task].name;
        self.faults.iter().any(|f| &f.task == name)
    }

    /// Runs `cycles` periods of the fastest task (the shortest interval): the simulated clock
    /// advances by that much, and every task runs as often as it falls due meanwhile, highest
    /// priority first. A faulted task stops; the clock and the others go on.
    pub fn run(&mut self, cycles: u64) {
        let tasks = self.engine.image().tasks.len();
        let Some(period) = (0..tasks).map(|t| self.interval_ns(t)).min() else {
            return;
        };
        let end = self
            .horizon_ns
            .saturating_add((period as i64).saturating_mul(cycles as i64));
        self.horizon_ns = end;
        loop {
            let Some(now) = (0..tasks)
                .filter(|&t| !self.faulted(t))
                .map(|t| self.next_due_ns[t])
                .min()
                .filter(|&due| due < end)
            else {
                self.now_ns = self.now_ns.max(end - period as i64).max(0);
                return;
            };
            self.now_ns = now;
            let mut due: Vec<usize> = (0..tasks)
                .filter(|&t| self.next_due_ns[t] == now && !self.faulted(t))
                .collect();
            due.sort_by_key(|&t| self.engine.image().tasks[t].priority);
            for task in due {
                let cycle = self.cycles[task];
                if let Err(fault) = self.engine.run_cycle(task, now, cycle) {
                    self.faults.push(fault);
                }
                self.cycles[task] += 1;
                self.next_due_ns[task] = now + self.interval_ns(task) as i64;
            }
        }
    }
}
