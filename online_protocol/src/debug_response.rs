//! The answers of the debugging services (`docs/protocol.md` §6.2), one variant per service,
//! carried by [`crate::Response::Debug`].

use crate::debug_request::DebugRequest;
use crate::debug_types::{DebugOptions, HitMode, HitRule};
use crate::error::DecodeError;
use crate::framing::NO_BREAKPOINT;
use crate::reader::Reader;
use crate::request::Request;
use crate::service::Service;
use crate::writer::first;

/// The answer of a debugging service done (status 0).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum DebugResponse {
    /// `DEBUG_ATTACH`: the session attached to this connection.
    Attach {
        /// Whether a lingering session was taken over.
        took_over: bool,
        /// How many tasks are halted now.
        halted: u8,
        /// How many breakpoints are set now.
        breakpoints: u16,
    },
    /// `DEBUG_DETACH`: the session ended.
    Detach,
    /// `BREAK_SET`: the breakpoint set.
    BreakSet {
        /// Its id, never [`crate::ALL_BREAKPOINTS`].
        id: u16,
        /// Whether it replaced one at the same place, instance and task.
        replaced: bool,
    },
    /// `BREAK_CLEAR`: the breakpoint (or every one) cleared.
    BreakClear,
    /// `BREAK_LIST`: the breakpoints from the request's index on.
    BreakList {
        /// How many breakpoints the session holds.
        total: u16,
        /// As many as fit one answer ([`crate::BREAK_LIST_ENTRIES`]).
        breakpoints: Vec<BreakpointInfo>,
    },
    /// `HALT_STATE`: the session and the tasks from the request's index on.
    HaltState(HaltState),
    /// `STEP`: the task goes on until the step ends.
    Step,
    /// `RUN_TO`: the task goes on until it reaches the target.
    RunTo,
    /// `CONTINUE`: the task (or every task) goes on.
    Continue,
    /// `HALT`: the task (or every task) halts at its next statement start.
    Halt,
    /// `STACK`: the frames of a halted task from the request's index on, innermost first.
    Stack {
        /// How many frames the task has.
        total: u16,
        /// As many as fit one answer ([`crate::STACK_ENTRIES`]).
        frames: Vec<StackFrame>,
    },
    /// `FRAME_READ`: the bytes of the request's ranges, one after the other.
    FrameRead {
        /// The values' bytes in the request's order.
        bytes: Vec<u8>,
    },
    /// `FRAME_WRITE`: the bytes written.
    FrameWrite,
    /// `FLOW_CONFIGURE`: the recording configured (or ended).
    FlowConfigure,
    /// `FLOW_READ`: part of a POU's flow bitmap.
    FlowRead {
        /// The task's cycle count the bitmap belongs to; 0 when none was recorded yet.
        cycle: u64,
        /// How many line-table entries (bits) the POU has.
        statements: u32,
        /// The bitmap's bytes from the request's `from` on, as many as fit
        /// ([`crate::MAX_FLOW_BITMAP_BYTES`]); bit `i mod 8` of byte `i / 8`.
        bitmap: Vec<u8>,
    },
}

/// A breakpoint of the session as `BREAK_LIST` lists it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct BreakpointInfo {
    /// Its id.
    pub id: u16,
    /// The POU's index in the image's code section.
    pub pou: u32,
    /// The instruction index of its statement start.
    pub instruction: u32,
    /// The instance it halts on (a pointer value), 0 for any.
    pub instance: u64,
    /// The task it halts, [`crate::ALL_TASKS`] for any.
    pub task: u8,
    /// When a hit halts.
    pub hit: HitRule,
    /// Hits since it was set.
    pub hits: u32,
    /// Whether it has a condition.
    pub conditional: bool,
}

/// Whether a debug session exists and is attached (`HALT_STATE`'s `session`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[repr(u8)]
pub enum SessionState {
    /// No session.
    None = 0,
    /// A session attached to a connection.
    Attached = 1,
    /// A session lingering without a connection.
    Lingering = 2,
}

impl SessionState {
    /// Every state, in the order of their numbers.
    pub const ALL: [SessionState; 3] = [
        SessionState::None,
        SessionState::Attached,
        SessionState::Lingering,
    ];
}

/// What a task is doing as `HALT_STATE` says it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[repr(u8)]
pub enum TaskDebugState {
    /// Between cycles or in a cycle.
    Running = 0,
    /// Halted at a statement start.
    Halted = 1,
    /// In a cycle interrupted by a halted task's cycle on the same thread.
    Waiting = 2,
    /// Held by "halt all": it starts no cycle.
    Held = 3,
    /// A step, run to cursor or continue was given and it has not halted since.
    Stepping = 4,
    /// Stopped by a fault.
    Faulted = 5,
    /// The program is stopped.
    Stopped = 6,
}

impl TaskDebugState {
    /// Every state, in the order of their numbers.
    pub const ALL: [TaskDebugState; 7] = [
        TaskDebugState::Running,
        TaskDebugState::Halted,
        TaskDebugState::Waiting,
        TaskDebugState::Held,
        TaskDebugState::Stepping,
        TaskDebugState::Faulted,
        TaskDebugState::Stopped,
    ];
}

/// Why a halted task halted.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[repr(u8)]
pub enum HaltReason {
    /// A breakpoint was hit (also sent, and meaningless, for a task that is not halted).
    Breakpoint = 0,
    /// A step ended.
    Step = 1,
    /// Run to cursor reached its target.
    RunTo = 2,
    /// `HALT` was asked.
    Halt = 3,
    /// A breakpoint's condition faulted.
    ConditionFaulted = 4,
}

impl HaltReason {
    /// Every reason, in the order of their numbers.
    pub const ALL: [HaltReason; 5] = [
        HaltReason::Breakpoint,
        HaltReason::Step,
        HaltReason::RunTo,
        HaltReason::Halt,
        HaltReason::ConditionFaulted,
    ];
}

/// One task in a `HALT_STATE` answer.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct TaskHalt {
    /// The task's index in the image's task table.
    pub task: u8,
    /// What it is doing.
    pub state: TaskDebugState,
    /// Why it halted (state [`TaskDebugState::Halted`]).
    pub reason: HaltReason,
    /// The breakpoint it halted at; `None` ([`NO_BREAKPOINT`] on the wire) for none.
    pub breakpoint: Option<u16>,
    /// The POU where it is (halted or waiting), else 0.
    pub pou: u32,
    /// The instruction where it is (halted or waiting), else 0.
    pub instruction: u32,
    /// Its frames (1: a program's body) when halted or waiting, else 0.
    pub depth: u16,
    /// Its count of finished cycles before the halted one, else 0.
    pub cycle: u64,
    /// How long it has been halted or waiting, in milliseconds (saturating).
    pub halted_ms: u32,
}

/// The debug session and the tasks (`HALT_STATE`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct HaltState {
    /// Whether a session exists and is attached.
    pub session: SessionState,
    /// The session's options.
    pub options: DebugOptions,
    /// Grows by one whenever any task's state, reason or position changes.
    pub generation: u32,
    /// How many tasks the program has.
    pub total: u8,
    /// The tasks from the request's index on, as many as fit ([`crate::HALT_STATE_ENTRIES`]).
    pub tasks: Vec<TaskHalt>,
}

/// One frame of a halted task's call stack (`STACK`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct StackFrame {
    /// The POU's index in the image's code section.
    pub pou: u32,
    /// Where the task is (frame 0) or the call instruction (the frames beyond).
    pub instruction: u32,
    /// The instance the frame runs on (a pointer value).
    pub instance: u64,
    /// The frame's start in the task's stack.
    pub frame: u32,
    /// The frame's size, the POU's `frame_size`.
    pub frame_bytes: u32,
}

impl DebugResponse {
    /// The service this answers.
    pub fn service(&self) -> Service {
        use DebugResponse::*;
        match self {
            Attach { .. } => Service::DebugAttach,
            Detach => Service::DebugDetach,
            BreakSet { .. } => Service::BreakSet,
            BreakClear => Service::BreakClear,
            BreakList { .. } => Service::BreakList,
            HaltState(_) => Service::HaltState,
            Step => Service::Step,
            RunTo => Service::RunTo,
            Continue => Service::Continue,
            Halt => Service::Halt,
            Stack { .. } => Service::Stack,
            FrameRead { .. } => Service::FrameRead,
            FrameWrite => Service::FrameWrite,
            FlowConfigure => Service::FlowConfigure,
            FlowRead { .. } => Service::FlowRead,
        }
    }

    /// Appends the answer after the status. Lists longer than their one-byte count allows
    /// are cut; whether the body fits a PDU is for the sender to check.
    pub(crate) fn encode_fields(&self, out: &mut Vec<u8>) {
        use DebugResponse::*;
        match self {
            Attach {
                took_over,
                halted,
                breakpoints,
            } => {
                out.push(u8::from(*took_over));
                out.push(*halted);
                out.extend_from_slice(&breakpoints.to_le_bytes());
            }
            Detach | BreakClear | Step | RunTo | Continue | Halt | FrameWrite | FlowConfigure => {}
            BreakSet { id, replaced } => {
                out.extend_from_slice(&id.to_le_bytes());
                out.push(u8::from(*replaced));
            }
            BreakList { total, breakpoints } => {
                out.extend_from_slice(&total.to_le_bytes());
                let breakpoints = first(breakpoints);
                out.push(breakpoints.len() as u8);
                for b in breakpoints {
                    out.extend_from_slice(&b.id.to_le_bytes());
                    out.extend_from_slice(&b.pou.to_le_bytes());
                    out.extend_from_slice(&b.instruction.to_le_bytes());
                    out.extend_from_slice(&b.instance.to_le_bytes());
                    out.push(b.task);
                    out.push(b.hit.mode as u8);
                    out.extend_from_slice(&b.hit.target.to_le_bytes());
                    out.extend_from_slice(&b.hits.to_le_bytes());
                    out.push(u8::from(b.conditional));
                }
            }
            HaltState(state) => {
                out.push(state.session as u8);
                out.push(state.options.bits());
                out.extend_from_slice(&state.generation.to_le_bytes());
                out.push(state.total);
                let tasks = first(&state.tasks);
                out.push(tasks.len() as u8);
                for t in tasks {
                    out.push(t.task);
                    out.push(t.state as u8);
                    out.push(t.reason as u8);
                    out.extend_from_slice(&t.breakpoint.unwrap_or(NO_BREAKPOINT).to_le_bytes());
                    out.extend_from_slice(&t.pou.to_le_bytes());
                    out.extend_from_slice(&t.instruction.to_le_bytes());
                    out.extend_from_slice(&t.depth.to_le_bytes());
                    out.extend_from_slice(&t.cycle.to_le_bytes());
                    out.extend_from_slice(&t.halted_ms.to_le_bytes());
                }
            }
            Stack { total, frames } => {
                out.extend_from_slice(&total.to_le_bytes());
                let frames = first(frames);
                out.push(frames.len() as u8);
                for f in frames {
                    out.extend_from_slice(&f.pou.to_le_bytes());
                    out.extend_from_slice(&f.instruction.to_le_bytes());
                    out.extend_from_slice(&f.instance.to_le_bytes());
                    out.extend_from_slice(&f.frame.to_le_bytes());
                    out.extend_from_slice(&f.frame_bytes.to_le_bytes());
                }
            }
            FrameRead { bytes } => out.extend_from_slice(bytes),
            FlowRead {
                cycle,
                statements,
                bitmap,
            } => {
                out.extend_from_slice(&cycle.to_le_bytes());
                out.extend_from_slice(&statements.to_le_bytes());
                let bitmap = first(bitmap);
                out.push(bitmap.len() as u8);
                out.extend_from_slice(bitmap);
            }
        }
    }

    /// The answer of the debugging `service` done, after the status; `request` gives the
    /// sizes of a `FRAME_READ` answer. `None` when `service` is not a debugging service.
    pub(crate) fn decode_fields(
        request: &Request,
        service: Service,
        r: &mut Reader<'_>,
    ) -> Result<Option<Self>, DecodeError> {
        Ok(Some(match service {
            Service::DebugAttach => DebugResponse::Attach {
                took_over: r.u8("took over")? != 0,
                halted: r.u8("halted")?,
                breakpoints: r.u16("breakpoints")?,
            },
            Service::DebugDetach => DebugResponse::Detach,
            Service::BreakSet => DebugResponse::BreakSet {
                id: r.u16("id")?,
                replaced: r.u8("replaced")? != 0,
            },
            Service::BreakClear => DebugResponse::BreakClear,
            Service::BreakList => {
                let total = r.u16("total")?;
                let count = r.u8("count")?;
                let mut breakpoints = Vec::with_capacity(usize::from(count));
                for _ in 0..count {
                    breakpoints.push(BreakpointInfo {
                        id: r.u16("breakpoint id")?,
                        pou: r.u32("breakpoint pou")?,
                        instruction: r.u32("breakpoint instruction")?,
                        instance: r.u64("breakpoint instance")?,
                        task: r.u8("breakpoint task")?,
                        hit: HitRule {
                            mode: r.choice("hit mode", &HitMode::ALL, "0 to 3")?,
                            target: r.u32("hit target")?,
                        },
                        hits: r.u32("hits")?,
                        conditional: r.u8("conditional")? != 0,
                    });
                }
                DebugResponse::BreakList { total, breakpoints }
            }
            Service::HaltState => DebugResponse::HaltState(halt_state(r)?),
            Service::Step => DebugResponse::Step,
            Service::RunTo => DebugResponse::RunTo,
            Service::Continue => DebugResponse::Continue,
            Service::Halt => DebugResponse::Halt,
            Service::Stack => {
                let total = r.u16("total")?;
                let count = r.u8("count")?;
                let mut frames = Vec::with_capacity(usize::from(count));
                for _ in 0..count {
                    frames.push(StackFrame {
                        pou: r.u32("frame pou")?,
                        instruction: r.u32("frame instruction")?,
                        instance: r.u64("frame instance")?,
                        frame: r.u32("frame start")?,
                        frame_bytes: r.u32("frame bytes")?,
                    });
                }
                DebugResponse::Stack { total, frames }
            }
            Service::FrameRead => {
                let size: usize = match request {
                    Request::Debug(DebugRequest::FrameRead { ranges, .. }) => first(ranges)
                        .iter()
                        .map(|range| usize::from(range.size))
                        .sum(),
                    _ => 0,
                };
                DebugResponse::FrameRead {
                    bytes: r.take("frame values", size)?.to_vec(),
                }
            }
            Service::FrameWrite => DebugResponse::FrameWrite,
            Service::FlowConfigure => DebugResponse::FlowConfigure,
            Service::FlowRead => {
                let cycle = r.u64("cycle")?;
                let statements = r.u32("statements")?;
                let count = usize::from(r.u8("count")?);
                DebugResponse::FlowRead {
                    cycle,
                    statements,
                    bitmap: r.take("bitmap", count)?.to_vec(),
                }
            }
            _ => return Ok(None),
        }))
    }
}

fn halt_state(r: &mut Reader<'_>) -> Result<HaltState, DecodeError> {
    let session = r.choice("session", &SessionState::ALL, "0 to 2")?;
    let options_at = r.position();
    let bits = r.u8("options")?;
    let options = DebugOptions::from_bits(bits).ok_or(DecodeError::OutOfRange {
        field: "options",
        at: options_at,
        value: bits.into(),
        expected: "0 or 1",
    })?;
    let generation = r.u32("generation")?;
    let total = r.u8("total")?;
    let count = r.u8("count")?;
    let mut tasks = Vec::with_capacity(usize::from(count));
    for _ in 0..count {
        tasks.push(TaskHalt {
            task: r.u8("task")?,
            state: r.choice("task state", &TaskDebugState::ALL, "0 to 6")?,
            reason: r.choice("halt reason", &HaltReason::ALL, "0 to 4")?,
            breakpoint: Some(r.u16("breakpoint")?).filter(|&id| id != NO_BREAKPOINT),
            pou: r.u32("pou")?,
            instruction: r.u32("instruction")?,
            depth: r.u16("depth")?,
            cycle: r.u64("cycle")?,
            halted_ms: r.u32("halted time")?,
        });
    }
    Ok(HaltState {
        session,
        options,
        generation,
        total,
        tasks,
    })
}
