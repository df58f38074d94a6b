//! Running a POU while a debug session is active (`docs/debugging.md` §3, "Cost"): every
//! call keeps the task's shadow call stack; a POU the debugger watches (a breakpoint or flow
//! recording in it, or its task stepping, running to a cursor or told to halt) runs the debug
//! form, which at each statement start looks at the debugger (steps, run to cursor, `HALT`,
//! breakpoints with their filters, conditions and hit counts) and halts there when it says
//! so; any other runs the light form, which asks nothing and notes its position only at calls
//! and interruptions.

use std::time::Instant;

use super::debug::{HaltReason, LoweredCondition, Pending, StackFrame};
use super::exec::{Exec, FRAME, INSTANCE};
use super::fault::FaultKind;
use super::lower::Flow;
use super::view::EngineView;

impl Exec<'_> {
    /// Notes the start of a cycle during a session: an empty stack and its count; decides
    /// whether the cycle runs with the debugger.
    pub(super) fn begin_debug_cycle(&mut self, cycle: u64) {
        if let Some(state) = self.debug.task_mut(self.task) {
            state.stack.clear();
            state.cycle = cycle;
        }
        self.debug.cycle_starts(self.task);
        self.debugging = self
            .debug
            .cycle_needs_debugger(self.task, self.hook.is_some());
    }

    /// Notes the end of a cycle during a session: the flow recording's bits become the last
    /// complete cycle's.
    pub(super) fn end_debug_cycle(&mut self, cycle: u64) {
        self.debug.end_flow_cycle(self.task, cycle + 1);
    }

    /// Notes the start of one of the task's programs: a step out of (or over the end of) the
    /// previous program's body halts at its first statement.
    pub(super) fn begin_debug_program(&mut self) {
        if let Some(state) = self.debug.task_mut(self.task)
            && state.pending == Pending::NextProgram
        {
            state.pending = Pending::Within(usize::MAX);
        }
    }

    /// Runs POU `index` with the current bases, as [`Exec::run`] does, while a session is
    /// active: pushes the POU's frame on the task's shadow stack (the caller's frame notes
    /// `call_site`), then runs the debug form when the debugger watches the POU or the task
    /// ([`DebugState::enter_pou`](super::debug::DebugState::enter_pou)), else the light form.
    #[inline(never)]
    pub(super) fn run_watched(&mut self, index: usize, call_site: u32) -> Result<(), FaultKind> {
        let code = self.code;
        let Some(pou) = code.pous.get(index) else {
            return Err(FaultKind::Memory);
        };
        let frame = StackFrame {
            pou: index as u32,
            instruction: 0,
            instance: self.bases[usize::from(INSTANCE)],
            frame: self.bases[usize::from(FRAME)],
            frame_bytes: pou.frame_size as u32,
        };
        let result = if self.debug.enter_pou(self.task, frame, call_site) {
            self.run_debug_body(index, 0)
        } else {
            self.run_light_body(index)
        };
        self.debug.leave_pou(self.task);
        result
    }

    /// The light form: the plain loop of [`Exec::run`], which asks the debugger nothing, but
    /// goes on in the debug form when the task comes to be watched during a call it makes or
    /// while it is interrupted at a backward jump.
    fn run_light_body(&mut self, index: usize) -> Result<(), FaultKind> {
        let code = self.code;
        let Some(pou) = code.pous.get(index) else {
            return Err(FaultKind::Memory);
        };
        let ops = &pou.ops;
        let mut pc = 0usize;
        while let Some(op) = ops.get(pc) {
            match op(self) {
                Ok(Flow::Next) => pc += 1,
                Ok(Flow::NextWatched) => return self.run_debug_body(index, pc + 1),
                Ok(Flow::Jump(target)) => {
                    let target = target as usize;
                    if target <= pc {
                        match self.tick(pc) {
                            Ok(false) => {}
                            Ok(true) => return self.run_debug_body(index, target),
                            Err(fault) => {
                                self.fault_at.get_or_insert((index, pc));
                                return Err(fault);
                            }
                        }
                    }
                    pc = target;
                }
                Ok(Flow::Return) => break,
                Err(fault) => {
                    if *fault != FaultKind::Abandoned {
                        self.fault_at.get_or_insert((index, pc));
                    }
                    return Err(*fault);
                }
            }
        }
        Ok(())
    }

    /// The debug form from instruction `start` on: at each statement start, the frame notes
    /// where the task is and the debugger is asked whether to halt.
    fn run_debug_body(&mut self, index: usize, start: usize) -> Result<(), FaultKind> {
        let code = self.code;
        let Some(pou) = code.pous.get(index) else {
            return Err(FaultKind::Memory);
        };
        let ops = &pou.ops;
        let mut pc = start;
        while let Some(op) = ops.get(pc) {
            if pou.statement_starts.get(pc).copied().unwrap_or(false) {
                self.statement(index, pc)?;
            }
            match op(self) {
                Ok(Flow::Next | Flow::NextWatched) => pc += 1,
                Ok(Flow::Jump(target)) => {
                    let target = target as usize;
                    if target <= pc
                        && let Err(fault) = self.tick(pc)
                    {
                        self.fault_at.get_or_insert((index, pc));
                        return Err(fault);
                    }
                    pc = target;
                }
                Ok(Flow::Return) => break,
                Err(fault) => {
                    if *fault != FaultKind::Abandoned {
                        self.fault_at.get_or_insert((index, pc));
                    }
                    return Err(*fault);
                }
            }
        }
        Ok(())
    }

    /// The task reached the statement starting at instruction `pc` of POU `pou`: notes it in
    /// the innermost frame, and halts there when a step, run to cursor, `HALT` or a
    /// breakpoint says so.
    fn statement(&mut self, pou: usize, pc: usize) -> Result<(), FaultKind> {
        let Some(depth) = self.debug.note_position(self.task, pc as u32) else {
            return Ok(());
        };
        if self.debug.records(pou) {
            let instance = self.pointer_to(self.bases[usize::from(INSTANCE)]);
            self.debug.record_flow(self.task, pou, pc as u32, instance);
        }
        let Some(state) = self.debug.task(self.task) else {
            return Ok(());
        };
        let mut reason = match state.pending {
            Pending::Within(most) if depth <= most => Some(HaltReason::Step),
            Pending::Below(fewer) if depth < fewer => Some(HaltReason::Step),
            Pending::RunTo(at_pou, at) if at_pou as usize == pou && at as usize == pc => {
                Some(HaltReason::RunTo)
            }
            Pending::Halt => Some(HaltReason::Halt),
            _ => None,
        };
        // A breakpoint that hits ends a step there with its own reason.
        if self.debug.pou_has_breakpoint(pou)
            && let Some(hit) = self.breakpoint_hit(pou, pc)
        {
            reason = Some(hit);
        }
        match reason {
            Some(reason) => self.halt(reason),
            None => Ok(()),
        }
    }

    /// The first breakpoint at this statement that accepts the task and instance, whose
    /// condition holds and whose hit mode halts, counting the hits on the way.
    fn breakpoint_hit(&mut self, pou: usize, pc: usize) -> Option<HaltReason> {
        let instance = self.pointer_to(self.bases[usize::from(INSTANCE)]);
        let mut index = 0;
        while let Some(breakpoint) = self.debug.breakpoints().get(index) {
            index += 1;
            if breakpoint.spec.pou as usize != pou
                || breakpoint.spec.instruction as usize != pc
                || !breakpoint.accepts(self.task, instance)
            {
                continue;
            }
            let id = breakpoint.id;
            // The condition is lent out of its breakpoint while it runs (it calls nothing,
            // so nothing can look at the breakpoints meanwhile): moving it costs less than
            // counting a reference to it up and down at every hit.
            let condition = self
                .debug
                .breakpoints_mut()
                .get_mut(index - 1)
                .and_then(|breakpoint| breakpoint.condition.take());
            let holds = match &condition {
                None => Ok(true),
                Some(condition) => self.evaluate(condition, pou),
            };
            if let Some(breakpoint) = self.debug.breakpoints_mut().get_mut(index - 1) {
                breakpoint.condition = condition;
            }
            match holds {
                Ok(false) => continue,
                Ok(true) => {
                    let breakpoint = self.debug.breakpoints_mut().get_mut(index - 1)?;
                    breakpoint.hits = breakpoint.hits.saturating_add(1);
                    if breakpoint
                        .spec
                        .hit_mode
                        .halts(breakpoint.hits, breakpoint.spec.hit_target)
                    {
                        return Some(HaltReason::Breakpoint(id));
                    }
                }
                // A faulting condition counts as TRUE and says why the task halted.
                Err(_) => return Some(HaltReason::ConditionFaulted(id)),
            }
        }
        None
    }

    /// Runs a condition with the bases of POU `pou`, its scratch area right after the frame.
    fn evaluate(&mut self, condition: &LoweredCondition, pou: usize) -> Result<bool, FaultKind> {
        let frame_size = self.code.pous.get(pou).map_or(0, |p| p.frame_size);
        let frame = self.bases[usize::from(FRAME)];
        let scratch = frame + frame_size;
        let end = scratch + condition.scratch_bytes;
        if end > self.stack_end {
            return Err(FaultKind::StackOverflow);
        }
        self.mem
            .get_mut(scratch..scratch + condition.init.len())
            .ok_or(FaultKind::Memory)?
            .copy_from_slice(&condition.init);
        let saved_sp = self.sp;
        self.sp = self.sp.max(end);
        let mut pc = 0usize;
        let mut outcome = Ok(());
        while let Some(op) = condition.ops.get(pc) {
            match op(self) {
                // A condition calls nothing, so it is never told to go on watched.
                Ok(Flow::Next | Flow::NextWatched) => pc += 1,
                // The verifier lets a condition jump only forward, so it ends.
                Ok(Flow::Jump(target)) if target as usize > pc => pc = target as usize,
                Ok(Flow::Jump(_)) | Ok(Flow::Return) => break,
                Err(fault) => {
                    outcome = Err(*fault);
                    break;
                }
            }
        }
        self.sp = saved_sp;
        outcome?;
        let result = self
            .mem
            .get(frame + condition.result)
            .ok_or(FaultKind::Memory)?;
        Ok(*result != 0)
    }

    /// Halts the task here: hands the engine to the scheduler until the task may go on, and
    /// moves the watchdog's deadline by the time halted. An abandoned cycle ends here.
    #[cold]
    #[inline(never)]
    fn halt(&mut self, reason: HaltReason) -> Result<(), FaultKind> {
        let task = self.task;
        self.debug.enter_halt(task, reason);
        let paused = Instant::now();
        if let Some(hook) = self.hook.as_deref_mut() {
            hook.halt(
                EngineView {
                    image: self.image,
                    regions: self.regions,
                    code: self.code,
                    memory: &mut *self.mem,
                    motion: &mut *self.motion,
                    debug: &mut *self.debug,
                },
                task,
            );
        }
        let halted = paused.elapsed();
        if let Some((deadline, _)) = &mut self.deadline {
            *deadline += halted;
        }
        self.halted_ns = self
            .halted_ns
            .saturating_add(i64::try_from(halted.as_nanos()).unwrap_or(i64::MAX));
        if self.debug.abandoning() {
            return Err(FaultKind::Abandoned);
        }
        self.debug.leave_halt(task);
        Ok(())
    }
}
