//! The engine's side of the debug session (`docs/protocol.md` §6, `docs/debugging.md`):
//! breakpoints, steps, halts and the tasks' call stacks.
//!
//! A cycle runs with the debugger only while a session is active and something can halt
//! while it runs ([`DebugState::cycle_needs_debugger`]); then every call pushes its frame on
//! the task's shadow call stack ([`DebugState::enter_pou`]), and only a POU with a breakpoint
//! or flow recording, or any POU of a task that is stepping, running to a cursor or told to
//! halt, runs the debug form (`Exec::run_watched`), which at each statement start asks
//! [`DebugState`] whether to halt. Any other cycle runs as the engine always did, at the cost
//! of one test per call. A halt hands the cycle's engine to the
//! scheduler's [`super::Preempt::halt`], which serves requests and runs other tasks until the
//! halted task is told to go on; the cycle's Rust stack stays where it is meanwhile.

mod breakpoint;
mod control;
mod flow;
mod reach;
mod task_debug;

use std::sync::Arc;

use program_image::{BreakCondition, ConditionError, ProgramImage};

pub(crate) use breakpoint::LoweredCondition;
pub use breakpoint::{Breakpoint, BreakpointSpec, HitMode};
pub use flow::{FlowRecording, FlowRecordings, FlowTrack};
pub(crate) use task_debug::Pending;
pub use task_debug::{Halt, HaltReason, StackFrame, StepKind, TaskDebug};

/// At most this many POUs are recorded at once (`FLOW_CONFIGURE`).
pub const MAX_FLOW_TRACKS: usize = 8;

/// A session holds at most this many breakpoints (`docs/protocol.md` §6.2).
pub const MAX_BREAKPOINTS: usize = 128;

/// Why a debugging request is refused; the message names the task, POU or instruction.
#[derive(Debug, thiserror::Error)]
pub enum DebugError {
    /// The image has no such POU.
    #[error("the image has no POU {0}")]
    UnknownPou(u32),
    /// The image has no such task.
    #[error("the image has no task {0}")]
    UnknownTask(u8),
    /// The instruction starts no statement (status 2).
    #[error("instruction {instruction} of POU '{pou}' starts no statement")]
    NotStatementStart {
        /// The POU's name.
        pou: String,
        /// The instruction asked for.
        instruction: u32,
    },
    /// A hit mode other than "always" with a target of 0, or an unknown mode (status 2).
    #[error("hit mode {mode} needs a hit target of at least 1")]
    HitTarget {
        /// The mode's number.
        mode: u8,
    },
    /// The condition is refused (status 2).
    #[error(transparent)]
    Condition(#[from] ConditionError),
    /// The session has 128 breakpoints already (status 7).
    #[error("the debug session holds {MAX_BREAKPOINTS} breakpoints already")]
    TooManyBreakpoints,
    /// More POUs than a flow recording takes (status 2).
    #[error("flow recording takes at most {MAX_FLOW_TRACKS} POUs, not {0}")]
    TooManyFlowEntries(usize),
    /// No breakpoint has this id (status 2).
    #[error("no breakpoint has id {0}")]
    UnknownBreakpoint(u16),
    /// The task is not halted (status 7).
    #[error("task '{0}' is not halted")]
    NotHalted(String),
    /// The task is halted beneath another, which must go on first (status 7).
    #[error("task '{task}' is halted beneath task '{top}': continue '{top}' first")]
    Beneath {
        /// The task asked about.
        task: String,
        /// The task halted on top of it.
        top: String,
    },
}

/// The debug session's state as the engine uses it: owned by the engine, changed by the
/// scheduler (between cycles or from inside a halt) and read at statement starts.
#[derive(Debug)]
pub struct DebugState {
    /// Whether cycles run with the debugger (a session exists).
    active: bool,
    breakpoints: Vec<Breakpoint>,
    /// Per POU, whether a breakpoint is in it, so a statement of another POU looks no further.
    pou_has_breakpoint: Vec<bool>,
    /// Per POU, whether its calls run the debug form: a breakpoint or flow recording is in it
    /// (kept by [`DebugState::refresh_debug_forms`] whenever either changes).
    debug_form: Vec<bool>,
    /// Per task, per POU, whether a cycle of the task may run the POU.
    task_runs: Vec<Vec<bool>>,
    /// Per task, whether a breakpoint that accepts it is in a POU it may run (kept with
    /// `debug_form`).
    task_may_hit: Vec<bool>,
    /// Per task, its priority (0 highest): a task is interrupted only by higher ones.
    task_priorities: Vec<u8>,
    next_id: u16,
    tasks: Vec<TaskDebug>,
    /// The halted tasks in the order they halted: the last one is on top.
    halted: Vec<usize>,
    /// Grows whenever a task's halt state or position changes.
    generation: u32,
    /// Set to abandon every halted cycle (`STOP`, `RESET`, `DOWNLOAD_COMMIT`).
    abandon: bool,
    /// The statement starts of each POU, sorted.
    statements: Vec<Vec<u32>>,
    task_names: Vec<String>,
    pou_names: Vec<String>,
    /// Per POU, its line table's entries as (instruction, entry index), sorted.
    entries: Vec<Vec<(u32, u32)>>,
    /// The flow recordings, one per recorded task.
    flow: FlowRecordings,
    /// Per POU, whether some task's flow recording lists it.
    pou_recorded: Vec<bool>,
    /// "Halt all": tasks that are not halted start no cycle.
    halt_all: bool,
    /// In "halt all" with no task halted: the next cycle to start may, and halts at once.
    halt_next_cycle: bool,
    /// The session's option: any halt starts "halt all".
    halt_all_on_halt: bool,
    /// The tasks in a cycle run with the debugger, in the order their cycles started: each
    /// runs nested in the one before it on the scheduler thread.
    in_cycle: Vec<usize>,
}

impl DebugState {
    /// No session, for `image`.
    pub(crate) fn new(image: &ProgramImage) -> Self {
        Self {
            active: false,
            breakpoints: Vec::new(),
            pou_has_breakpoint: vec![false; image.pous.len()],
            debug_form: vec![false; image.pous.len()],
            task_runs: reach::pous_run_by_tasks(image),
            task_may_hit: vec![false; image.tasks.len()],
            task_priorities: image.tasks.iter().map(|t| t.priority).collect(),
            next_id: 1,
            tasks: image.tasks.iter().map(|_| TaskDebug::new()).collect(),
            halted: Vec::new(),
            generation: 0,
            abandon: false,
            statements: image
                .pous
                .iter()
                .map(|pou| {
                    let mut starts: Vec<u32> = pou.lines.iter().map(|e| e.index).collect();
                    starts.sort_unstable();
                    starts.dedup();
                    starts
                })
                .collect(),
            task_names: image.tasks.iter().map(|t| t.name.clone()).collect(),
            entries: image
                .pous
                .iter()
                .map(|pou| {
                    let mut entries: Vec<(u32, u32)> = (0u32..)
                        .zip(&pou.lines)
                        .map(|(entry, line)| (line.index, entry))
                        .collect();
                    entries.sort_unstable();
                    entries
                })
                .collect(),
            flow: FlowRecordings::default(),
            pou_recorded: vec![false; image.pous.len()],
            halt_all: false,
            halt_next_cycle: false,
            halt_all_on_halt: false,
            in_cycle: Vec::new(),
            pou_names: image.pous.iter().map(|p| p.name.clone()).collect(),
        }
    }

    /// Whether cycles run with the debugger.
    pub fn active(&self) -> bool {
        self.active
    }

    /// Starts running cycles with the debugger (a session was attached). A cycle already in
    /// progress goes on without it.
    pub fn begin_session(&mut self) {
        self.active = true;
    }

    /// Ends the session: every breakpoint, step and run-to-cursor target is removed and every
    /// halted task goes on (it returns from its halt when the scheduler next looks).
    pub fn end_session(&mut self) {
        self.active = false;
        self.breakpoints.clear();
        self.pou_has_breakpoint.fill(false);
        self.next_id = 1;
        for task in &mut self.tasks {
            task.pending = Pending::Nothing;
            task.stepping = false;
            task.halt = None;
        }
        self.halted.clear();
        self.flow = FlowRecordings::default();
        self.pou_recorded.fill(false);
        self.debug_form.fill(false);
        self.task_may_hit.fill(false);
        self.halt_all = false;
        self.halt_next_cycle = false;
        self.halt_all_on_halt = false;
        self.generation = self.generation.wrapping_add(1);
    }

    /// Sets the session's option "halt all tasks whenever one halts".
    pub fn set_halt_all_on_halt(&mut self, on: bool) {
        self.halt_all_on_halt = on;
    }

    /// Whether "halt all" holds the tasks that are not halted: the scheduler starts no cycle.
    pub fn holding(&self) -> bool {
        self.halt_all && !self.halt_next_cycle
    }

    /// Whether "halt all" is on.
    pub fn halting_all(&self) -> bool {
        self.halt_all
    }

    /// `FLOW_CONFIGURE`: records, for each cycle of `task`, which statements of each listed
    /// POU (on one instance, or every instance with 0) ran; replaces that task's list only, and
    /// an empty list ends that task's recording.
    pub fn configure_flow(&mut self, task: usize, pous: &[(u32, u64)]) -> Result<(), DebugError> {
        if task >= self.tasks.len() {
            return Err(DebugError::UnknownTask(task.min(255) as u8));
        }
        if pous.len() > MAX_FLOW_TRACKS {
            return Err(DebugError::TooManyFlowEntries(pous.len()));
        }
        let mut tracks = Vec::with_capacity(pous.len());
        for &(pou, instance) in pous {
            let entries = self
                .entries
                .get(pou as usize)
                .ok_or(DebugError::UnknownPou(pou))?;
            tracks.push(FlowTrack::new(pou, instance, entries.len() as u32));
        }
        self.flow.configure(task, tracks);
        for (pou, flag) in (0u32..).zip(self.pou_recorded.iter_mut()) {
            *flag = self.flow.records(pou);
        }
        self.refresh_debug_forms();
        Ok(())
    }

    /// Recomputes which POUs run the debug form after a breakpoint or the flow recording
    /// changed (those with a breakpoint or recorded), and which tasks may reach a breakpoint.
    /// A call decides its form on entry, so a change takes effect from the POU's next call
    /// on (`docs/debugging.md` §3).
    fn refresh_debug_forms(&mut self) {
        for ((form, &breakpoint), &recorded) in self
            .debug_form
            .iter_mut()
            .zip(&self.pou_has_breakpoint)
            .zip(&self.pou_recorded)
        {
            *form = breakpoint || recorded;
        }
        for (task, (may_hit, runs)) in self
            .task_may_hit
            .iter_mut()
            .zip(&self.task_runs)
            .enumerate()
        {
            *may_hit = self.breakpoints.iter().any(|breakpoint| {
                breakpoint
                    .spec
                    .task
                    .is_none_or(|only| usize::from(only) == task)
                    && runs
                        .get(breakpoint.spec.pou as usize)
                        .copied()
                        .unwrap_or(false)
            });
        }
    }

    /// Whether task `task` may halt: it is watched or may reach a breakpoint.
    pub(crate) fn may_halt(&self, task: usize) -> bool {
        self.watched(task) || self.task_may_hit.get(task).copied().unwrap_or(false)
    }

    /// Whether a cycle of task `task` that starts now runs with the debugger: keeps its
    /// shadow call stack and lets the POUs the debugger watches run the debug form. It need
    /// not when nothing can halt while it runs (`docs/debugging.md` §3, "Cost"): the task may
    /// reach no breakpoint and is not watched, no flow recording is of it, no "halt all" is
    /// on, no task is halted and, when it can be `interrupted`, no task of higher priority may
    /// halt (a task waiting beneath a halted one shows its call stack too). Nothing of this
    /// changes while the cycle runs, since requests are served only between cycles and during
    /// halts; a cycle that starts while a task is halted runs above that halt, where requests
    /// are served at its safe points, so it always runs with the debugger.
    pub(crate) fn cycle_needs_debugger(&self, task: usize, interrupted: bool) -> bool {
        if !self.active {
            return false;
        }
        if self.halt_all
            || self.halt_next_cycle
            || !self.halted.is_empty()
            || self.may_halt(task)
            || self.flow.records_task(task)
        {
            return true;
        }
        let priority = self.task_priorities.get(task).copied().unwrap_or(0);
        interrupted
            && (0..self.tasks.len()).any(|other| {
                other != task
                    && self.task_priorities.get(other).copied().unwrap_or(u8::MAX) < priority
                    && self.may_halt(other)
            })
    }

    /// Task `task` enters a POU whose frame is `frame`, called from instruction `call_site`
    /// of the POU on top of its shadow stack: the caller's frame notes the call site and the
    /// new frame goes on top. Says whether the POU runs the debug form: it has a breakpoint or
    /// is recorded, or the task is watched ([`DebugState::watched`]).
    #[inline(always)]
    pub(crate) fn enter_pou(&mut self, task: usize, frame: StackFrame, call_site: u32) -> bool {
        let Some(state) = self.tasks.get_mut(task) else {
            return false;
        };
        if let Some(caller) = state.stack.last_mut() {
            caller.instruction = call_site;
        }
        state.stack.push(frame);
        state.pending != Pending::Nothing
            || self
                .debug_form
                .get(frame.pou as usize)
                .copied()
                .unwrap_or(false)
    }

    /// Task `task` leaves the POU on top of its shadow stack.
    #[inline(always)]
    pub(crate) fn leave_pou(&mut self, task: usize) {
        if let Some(state) = self.tasks.get_mut(task) {
            state.stack.pop();
        }
    }

    /// Whether every POU task `task` runs must run the debug form: it is stepping, running to
    /// a cursor or told to halt, so any statement start may be where it halts.
    #[inline(always)]
    pub(crate) fn watched(&self, task: usize) -> bool {
        self.tasks
            .get(task)
            .is_some_and(|state| state.pending != Pending::Nothing)
    }

    /// Notes that task `task` stands at instruction `instruction` of the POU on top of its
    /// shadow stack; returns the stack's depth, `None` when the task is unknown.
    pub(crate) fn note_position(&mut self, task: usize, instruction: u32) -> Option<usize> {
        let state = self.tasks.get_mut(task)?;
        if let Some(top) = state.stack.last_mut() {
            top.instruction = instruction;
        }
        Some(state.stack.len())
    }

    /// The flow recordings of every task that records.
    pub fn flow(&self) -> &FlowRecordings {
        &self.flow
    }

    /// Whether the flow recording lists POU `pou` (for some task).
    pub(crate) fn records(&self, pou: usize) -> bool {
        self.pou_recorded.get(pou).copied().unwrap_or(false)
    }

    /// Notes that task `task` started the statement at instruction `instruction` of POU `pou`
    /// on the instance whose pointer value is `instance`.
    pub(crate) fn record_flow(&mut self, task: usize, pou: usize, instruction: u32, instance: u64) {
        if !self.records(pou) {
            return;
        }
        let (Some(flow), Some(entries)) = (self.flow.of_task_mut(task), self.entries.get(pou))
        else {
            return;
        };
        let first = entries.partition_point(|&(at, _)| at < instruction);
        for track in flow
            .tracks
            .iter_mut()
            .filter(|t| t.pou as usize == pou && (t.instance == 0 || t.instance == instance))
        {
            for &(_, entry) in entries[first..]
                .iter()
                .take_while(|&&(at, _)| at == instruction)
            {
                track.mark(entry);
            }
        }
    }

    /// Task `task` completed its cycle: `finished` cycles are done now.
    pub(crate) fn end_flow_cycle(&mut self, task: usize, finished: u64) {
        self.flow.end_cycle(task, finished);
    }

    /// Abandons every halted cycle: each returns from its halt without running the rest of its
    /// cycle (and without a fault). The scheduler clears this with [`DebugState::settled`]
    /// once no cycle is in progress.
    pub fn abandon_halted(&mut self) {
        self.abandon = true;
        for &task in &self.halted {
            if let Some(state) = self.tasks.get_mut(task) {
                state.halt = None;
            }
        }
        self.halted.clear();
        self.generation = self.generation.wrapping_add(1);
    }

    /// Whether halted cycles are being abandoned.
    pub fn abandoning(&self) -> bool {
        self.abandon
    }

    /// No cycle is in progress any more: the next cycles run normally.
    pub fn settled(&mut self) {
        self.abandon = false;
        self.in_cycle.clear();
        for task in &mut self.tasks {
            task.stack.clear();
        }
    }

    /// The breakpoints, in the order they were set.
    pub fn breakpoints(&self) -> &[Breakpoint] {
        &self.breakpoints
    }

    /// The debugger's view of task `task`.
    pub fn task(&self, task: usize) -> Option<&TaskDebug> {
        self.tasks.get(task)
    }

    /// How many tasks the image has.
    pub fn task_count(&self) -> usize {
        self.tasks.len()
    }

    /// The halted tasks, the one on top (halted last) last.
    pub fn halted(&self) -> &[usize] {
        &self.halted
    }

    /// Grows by one whenever any task's halt state or position changes.
    pub fn generation(&self) -> u32 {
        self.generation
    }

    /// Checks that `instruction` starts a statement of POU `pou`.
    pub fn check_statement(&self, pou: u32, instruction: u32) -> Result<(), DebugError> {
        let starts = self
            .statements
            .get(pou as usize)
            .ok_or(DebugError::UnknownPou(pou))?;
        if starts.binary_search(&instruction).is_ok() {
            Ok(())
        } else {
            Err(DebugError::NotStatementStart {
                pou: self
                    .pou_names
                    .get(pou as usize)
                    .cloned()
                    .unwrap_or_default(),
                instruction,
            })
        }
    }

    /// Sets a breakpoint whose condition is already lowered; replaces one at the same place,
    /// instance and task. Returns its id and whether it replaced one.
    pub(crate) fn insert_breakpoint(
        &mut self,
        spec: BreakpointSpec,
        condition: Option<LoweredCondition>,
    ) -> Result<(u16, bool), DebugError> {
        self.check_statement(spec.pou, spec.instruction)?;
        if let Some(task) = spec.task
            && usize::from(task) >= self.tasks.len()
        {
            return Err(DebugError::UnknownTask(task));
        }
        if spec.hit_mode != HitMode::Always && spec.hit_target == 0 {
            return Err(DebugError::HitTarget {
                mode: spec.hit_mode.code(),
            });
        }
        let same = self.breakpoints.iter().position(|b| {
            b.spec.pou == spec.pou
                && b.spec.instruction == spec.instruction
                && b.spec.instance == spec.instance
                && b.spec.task == spec.task
        });
        if same.is_none() && self.breakpoints.len() >= MAX_BREAKPOINTS {
            return Err(DebugError::TooManyBreakpoints);
        }
        // Ids count from 1, as the user sees them (`breakpoint 1`), are never 0xFFFF (every
        // breakpoint) and are not reused within a session; a session that sets 65534
        // breakpoints wraps around, past ids long cleared.
        let id = self.next_id;
        self.next_id = if self.next_id >= 0xFFFE {
            1
        } else {
            self.next_id + 1
        };
        if let Some(flag) = self.pou_has_breakpoint.get_mut(spec.pou as usize) {
            *flag = true;
        }
        let breakpoint = Breakpoint {
            id,
            spec,
            hits: 0,
            condition: condition.map(Arc::new),
        };
        let replaced = match same {
            Some(index) => {
                self.breakpoints[index] = breakpoint;
                true
            }
            None => {
                self.breakpoints.push(breakpoint);
                false
            }
        };
        self.refresh_debug_forms();
        Ok((id, replaced))
    }

    /// Removes breakpoint `id`, or every breakpoint with 0xFFFF.
    pub fn clear_breakpoint(&mut self, id: u16) -> Result<(), DebugError> {
        if id == 0xFFFF {
            self.breakpoints.clear();
        } else {
            let index = self
                .breakpoints
                .iter()
                .position(|b| b.id == id)
                .ok_or(DebugError::UnknownBreakpoint(id))?;
            self.breakpoints.remove(index);
        }
        self.pou_has_breakpoint.fill(false);
        for breakpoint in &self.breakpoints {
            if let Some(flag) = self
                .pou_has_breakpoint
                .get_mut(breakpoint.spec.pou as usize)
            {
                *flag = true;
            }
        }
        self.refresh_debug_forms();
        Ok(())
    }

    /// The name of task `task`.
    pub fn task_name(&self, task: usize) -> &str {
        self.task_names.get(task).map_or("", String::as_str)
    }

    pub(crate) fn task_mut(&mut self, task: usize) -> Option<&mut TaskDebug> {
        self.tasks.get_mut(task)
    }

    pub(crate) fn pou_has_breakpoint(&self, pou: usize) -> bool {
        self.pou_has_breakpoint.get(pou).copied().unwrap_or(false)
    }

    pub(crate) fn breakpoints_mut(&mut self) -> &mut [Breakpoint] {
        &mut self.breakpoints
    }

    /// Decodes and verifies a condition for POU `pou`, for [`DebugState::insert_breakpoint`].
    pub(crate) fn decode_condition(
        image: &ProgramImage,
        pou: u32,
        bytes: &[u8],
    ) -> Result<Option<BreakCondition>, DebugError> {
        if bytes.is_empty() {
            return Ok(None);
        }
        let condition = BreakCondition::decode(bytes)?;
        image.verify_condition(pou, &condition)?;
        Ok(Some(condition))
    }
}

#[cfg(test)]
#[path = "state_tests.rs"]
mod tests;
