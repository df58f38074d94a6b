//! Halting and going on: steps, run to cursor, continue, `HALT` and "halt all", the order
//! halted tasks resume in, and which tasks wait beneath a halted one.

use std::time::Instant;

use super::{DebugError, DebugState, Halt, HaltReason, Pending, StepKind};

impl DebugState {
    /// Checks that `task` is halted and on top, so it may go on.
    fn check_on_top(&self, task: usize) -> Result<(), DebugError> {
        let state = self
            .tasks
            .get(task)
            .ok_or(DebugError::UnknownTask(task as u8))?;
        if state.halt.is_none() {
            return Err(DebugError::NotHalted(self.task_name(task).to_owned()));
        }
        match self.halted.last() {
            Some(&top) if top != task => Err(DebugError::Beneath {
                task: self.task_name(task).to_owned(),
                top: self.task_name(top).to_owned(),
            }),
            _ => Ok(()),
        }
    }

    /// Lets halted task `task` go on until `pending` says it halts.
    fn resume(&mut self, task: usize, pending: Pending) {
        if let Some(state) = self.tasks.get_mut(task) {
            state.halt = None;
            state.pending = pending;
            state.stepping = true;
        }
        self.halted.retain(|&halted| halted != task);
        self.generation = self.generation.wrapping_add(1);
    }

    /// `STEP`: the halted task on top goes on and halts at the statement `kind` says.
    pub fn step(&mut self, task: usize, kind: StepKind) -> Result<(), DebugError> {
        self.check_on_top(task)?;
        let depth = self.tasks.get(task).map_or(0, |state| state.stack.len());
        let pending = match kind {
            StepKind::Into => Pending::Within(usize::MAX),
            StepKind::Over => Pending::Within(depth),
            StepKind::Out if depth <= 1 => Pending::NextProgram,
            StepKind::Out => Pending::Below(depth),
        };
        self.resume(task, pending);
        Ok(())
    }

    /// `RUN_TO`: the halted task on top goes on and halts at the statement start of `pou` at
    /// `instruction` (any instance), or at a breakpoint before.
    pub fn run_to(&mut self, task: usize, pou: u32, instruction: u32) -> Result<(), DebugError> {
        self.check_statement(pou, instruction)?;
        self.check_on_top(task)?;
        self.resume(task, Pending::RunTo(pou, instruction));
        Ok(())
    }

    /// `CONTINUE` of one task: a halted task on top goes on until a breakpoint; a stepping
    /// task's step ends.
    pub fn continue_task(&mut self, task: usize) -> Result<(), DebugError> {
        let stepping = self.tasks.get(task).is_some_and(|state| state.stepping);
        if stepping && self.tasks.get(task).is_some_and(|s| s.halt.is_none()) {
            if let Some(state) = self.tasks.get_mut(task) {
                state.pending = Pending::Nothing;
                state.stepping = false;
            }
            self.generation = self.generation.wrapping_add(1);
            return Ok(());
        }
        self.check_on_top(task)?;
        self.resume(task, Pending::Nothing);
        if let Some(state) = self.tasks.get_mut(task) {
            state.stepping = false;
        }
        Ok(())
    }

    /// `HALT` of one task: it halts at the next statement start it runs; a halted task stays.
    pub fn halt_task(&mut self, task: usize) -> Result<(), DebugError> {
        let state = self
            .tasks
            .get_mut(task)
            .ok_or(DebugError::UnknownTask(task as u8))?;
        if state.halt.is_none() {
            state.pending = Pending::Halt;
        }
        Ok(())
    }

    /// `CONTINUE` of every task: every halted task goes on (each beneath the top one as soon
    /// as it is on top) and every step, run-to-cursor target and `HALT` ends.
    pub fn continue_all(&mut self) {
        self.halt_all = false;
        self.halt_next_cycle = false;
        for task in &mut self.tasks {
            task.halt = None;
            task.pending = Pending::Nothing;
            task.stepping = false;
        }
        self.halted.clear();
        self.generation = self.generation.wrapping_add(1);
    }

    /// `HALT` of every task ("halt all"): every task that is not halted is held (starts no
    /// cycle) until [`DebugState::continue_all`]; when no task is halted, the next task to
    /// start a cycle halts at its first statement, so there is one halted place to look at.
    pub fn halt_all(&mut self) {
        self.halt_all = true;
        self.halt_next_cycle = self.halted.is_empty();
        self.generation = self.generation.wrapping_add(1);
    }

    /// Whether task `task` waits beneath a halted task: its cycle is in progress and a task
    /// halted in a cycle that started after it (nested in it).
    pub fn waiting(&self, task: usize) -> bool {
        if self.is_halted(task) {
            return false;
        }
        let Some(at) = self.in_cycle.iter().position(|&t| t == task) else {
            return false;
        };
        self.in_cycle[at + 1..].iter().any(|&t| self.is_halted(t))
    }

    /// A cycle of `task` ended (or faulted, or was abandoned).
    pub(crate) fn cycle_ends(&mut self, task: usize) {
        if let Some(at) = self.in_cycle.iter().rposition(|&t| t == task) {
            self.in_cycle.truncate(at);
        }
    }

    /// A cycle of `task` starts: in "halt all" with no task halted, it halts at once.
    pub(crate) fn cycle_starts(&mut self, task: usize) {
        self.in_cycle.push(task);
        if self.halt_next_cycle
            && let Some(state) = self.tasks.get_mut(task)
        {
            state.pending = Pending::Halt;
            self.halt_next_cycle = false;
        }
    }

    /// Notes that task `task` halts at the top of its stack for `reason`.
    pub(crate) fn enter_halt(&mut self, task: usize, reason: HaltReason) {
        if let Some(state) = self.tasks.get_mut(task) {
            let (pou, instruction) = state
                .stack
                .last()
                .map_or((0, 0), |frame| (frame.pou, frame.instruction));
            state.halt = Some(Halt {
                reason,
                pou,
                instruction,
                depth: state.stack.len().min(usize::from(u16::MAX)) as u16,
                cycle: state.cycle,
                since: Instant::now(),
            });
            state.pending = Pending::Nothing;
            state.stepping = false;
        }
        self.halted.push(task);
        if self.halt_all_on_halt {
            self.halt_all = true;
            self.halt_next_cycle = false;
        }
        self.generation = self.generation.wrapping_add(1);
    }

    /// Whether task `task` is still halted (the scheduler keeps serving until it is not).
    pub fn is_halted(&self, task: usize) -> bool {
        self.tasks
            .get(task)
            .is_some_and(|state| state.halt.is_some())
    }

    /// Makes a task that is still halted go on as `CONTINUE` would, whatever is on top: the
    /// cycle has returned from its halt (a hook that serves nothing, or the session ended).
    pub(crate) fn leave_halt(&mut self, task: usize) {
        if self.is_halted(task) {
            self.resume(task, Pending::Nothing);
        }
        if let Some(state) = self.tasks.get_mut(task) {
            state.stepping = false;
        }
    }
}
