//! The reading services of the debug session (`docs/protocol.md` §6.2): the breakpoint
//! list, the halt state, a halted task's call stack and the places in its frames.

use online_protocol::{
    BreakpointInfo, DebugOptions, DebugResponse, FrameRange, HaltState, HitRule, MAX_PAYLOAD_BYTES,
    Refusal, SessionState, TaskDebugState, TaskHalt,
};

use super::debug::on_engine;
use crate::engine::{self, EngineView, HitMode};
use crate::scheduler::{Scheduler, SchedulerState};

pub(super) fn break_list(scheduler: &Scheduler, from: u16) -> Result<DebugResponse, Refusal> {
    on_engine(scheduler, move |engine| {
        let all = engine.debug().breakpoints();
        // 2 + 1 bytes of header, 28 of each breakpoint.
        let fit = (MAX_PAYLOAD_BYTES - 3) / 28;
        let breakpoints = all
            .iter()
            .skip(usize::from(from))
            .take(fit.min(255))
            .map(|b| BreakpointInfo {
                id: b.id,
                pou: b.spec.pou,
                instruction: b.spec.instruction,
                instance: b.spec.instance,
                task: b.spec.task.unwrap_or(0xFF),
                hit: HitRule {
                    mode: match b.spec.hit_mode {
                        HitMode::Always => online_protocol::HitMode::Always,
                        HitMode::Equal => online_protocol::HitMode::Equal,
                        HitMode::Multiple => online_protocol::HitMode::Multiple,
                        HitMode::AtLeast => online_protocol::HitMode::AtLeast,
                    },
                    target: b.spec.hit_target,
                },
                hits: b.hits,
                conditional: b.conditional(),
            })
            .collect();
        Ok(DebugResponse::BreakList {
            total: u16::try_from(all.len()).unwrap_or(u16::MAX),
            breakpoints,
        })
    })
}

pub(super) fn halt_state(
    scheduler: &Scheduler,
    (session, options): (SessionState, DebugOptions),
    from: u8,
) -> Result<HaltState, Refusal> {
    let status = scheduler.status();
    let stopped = status.state == SchedulerState::Stopped;
    let faulted: Vec<bool> = status.tasks.iter().map(|t| t.faulted).collect();
    on_engine(scheduler, move |engine| {
        let debug = engine.debug();
        let count = debug.task_count();
        // 4 + 4 + 2 bytes of header, 34 of each task.
        let fit = (MAX_PAYLOAD_BYTES - 10) / 34;
        let tasks = (usize::from(from)..count)
            .take(fit)
            .filter_map(|index| {
                let state = debug.task(index)?;
                let mut halt = TaskHalt {
                    task: index as u8,
                    state: TaskDebugState::Running,
                    reason: online_protocol::HaltReason::Breakpoint,
                    breakpoint: None,
                    pou: 0,
                    instruction: 0,
                    depth: 0,
                    cycle: 0,
                    halted_ms: 0,
                };
                if let Some(at) = state.halt() {
                    halt.state = TaskDebugState::Halted;
                    halt.reason = match at.reason {
                        engine::HaltReason::Breakpoint(_) => {
                            online_protocol::HaltReason::Breakpoint
                        }
                        engine::HaltReason::Step => online_protocol::HaltReason::Step,
                        engine::HaltReason::RunTo => online_protocol::HaltReason::RunTo,
                        engine::HaltReason::Halt => online_protocol::HaltReason::Halt,
                        engine::HaltReason::ConditionFaulted(_) => {
                            online_protocol::HaltReason::ConditionFaulted
                        }
                    };
                    let id = at.reason.breakpoint();
                    halt.breakpoint = (id != 0xFFFF).then_some(id);
                    halt.pou = at.pou;
                    halt.instruction = at.instruction;
                    halt.depth = at.depth;
                    halt.cycle = at.cycle;
                    halt.halted_ms =
                        u32::try_from(at.since.elapsed().as_millis()).unwrap_or(u32::MAX);
                } else if debug.waiting(index) {
                    halt.state = TaskDebugState::Waiting;
                    if let Some(top) = state.stack().next() {
                        halt.pou = top.pou;
                        halt.instruction = top.instruction;
                    }
                    halt.depth = u16::try_from(state.stack().count()).unwrap_or(u16::MAX);
                    halt.cycle = state.cycle;
                } else if debug.halting_all() && !state.in_cycle() {
                    halt.state = TaskDebugState::Held;
                } else if faulted.get(index).copied().unwrap_or(false) {
                    halt.state = TaskDebugState::Faulted;
                } else if stopped {
                    halt.state = TaskDebugState::Stopped;
                } else if state.stepping() {
                    halt.state = TaskDebugState::Stepping;
                }
                Some(halt)
            })
            .collect();
        Ok(HaltState {
            session,
            options,
            generation: debug.generation(),
            total: u8::try_from(count).unwrap_or(u8::MAX),
            tasks,
        })
    })
}

/// Whether task `task` is halted or waits beneath a halted task.
pub(super) fn stopped_in_cycle(engine: &EngineView<'_>, task: usize) -> bool {
    let debug = engine.debug();
    debug.is_halted(task) || debug.waiting(task)
}

pub(super) fn not_stopped(engine: &EngineView<'_>, task: u8) -> Refusal {
    Refusal::not_now(format!(
        "task '{}' is neither halted nor waiting beneath a halted task",
        engine.debug().task_name(usize::from(task))
    ))
}

pub(super) fn stack(scheduler: &Scheduler, task: u8, from: u16) -> Result<DebugResponse, Refusal> {
    on_engine(scheduler, move |engine| {
        let index = usize::from(task);
        if !stopped_in_cycle(engine, index) {
            return Err(not_stopped(engine, task));
        }
        let base = engine.stack_start(index);
        let state = engine
            .debug()
            .task(index)
            .ok_or_else(|| not_stopped(engine, task))?;
        // 2 + 1 bytes of header, 24 of each frame.
        let fit = (MAX_PAYLOAD_BYTES - 3) / 24;
        let frames = state
            .stack()
            .skip(usize::from(from))
            .take(fit.min(255))
            .map(|frame| online_protocol::StackFrame {
                pou: frame.pou,
                instruction: frame.instruction,
                instance: engine.pointer_value(index, frame.instance),
                frame: u32::try_from(frame.frame.saturating_sub(base)).unwrap_or(u32::MAX),
                frame_bytes: frame.frame_bytes,
            })
            .collect();
        Ok(DebugResponse::Stack {
            total: u16::try_from(state.stack().count()).unwrap_or(u16::MAX),
            frames,
        })
    })
}

/// The span of frame `frame` (0xFFFF: the whole stack) of task `task` in its stack's bytes.
pub(super) fn frame_span(
    engine: &EngineView<'_>,
    task: u8,
    frame: u16,
) -> Result<(usize, usize), Refusal> {
    let index = usize::from(task);
    if !stopped_in_cycle(engine, index) {
        return Err(not_stopped(engine, task));
    }
    let stack_len = engine.stack_bytes(index).len();
    if frame == 0xFFFF {
        return Ok((0, stack_len));
    }
    let base = engine.stack_start(index);
    let state = engine
        .debug()
        .task(index)
        .ok_or_else(|| not_stopped(engine, task))?;
    let found = state.stack().nth(usize::from(frame)).ok_or_else(|| {
        Refusal::bad(format!(
            "task '{}' has {} frames, not {}",
            engine.debug().task_name(index),
            state.stack().count(),
            u32::from(frame) + 1
        ))
    })?;
    let start = found.frame.saturating_sub(base);
    Ok((start, start + found.frame_bytes as usize))
}

/// The bytes of `range` inside a frame spanning `start..end` of the stack.
pub(super) fn range_in(
    start: usize,
    end: usize,
    range: &FrameRange,
) -> Result<(usize, usize), Refusal> {
    let from = start + range.offset as usize;
    let to = from + usize::from(range.size);
    if to > end {
        return Err(Refusal::new(
            online_protocol::Status::BadPlace,
            format!(
                "{} bytes at offset {} lie outside the frame of {} bytes",
                range.size,
                range.offset,
                end - start
            ),
        ));
    }
    Ok((from, to))
}
