//! The debugging services of `docs/protocol.md` §6 on a scheduler: the one debug session,
//! attached to a connection or lingering without one, and every §6 service, served between
//! two cycles or from inside a halt (`crate::scheduler`'s halt loop).

use std::net::IpAddr;
use std::sync::{Mutex, MutexGuard, PoisonError};
use std::time::{Duration, Instant};

use online_protocol::{
    BreakpointInfo, DebugOptions, DebugRequest, DebugResponse, DebugStatus, FlowCycle, FrameRange,
    HaltState, HitRule, MAX_FLOW_BITMAP_BYTES, MAX_PAYLOAD_BYTES, Refusal, Response, SessionState,
    TaskDebugState, TaskHalt,
};

use crate::engine::{self, BreakpointSpec, DebugError, EngineView, HitMode, StepKind};
use crate::scheduler::{Between, Scheduler, SchedulerState};

/// The longest linger a client may ask for, in seconds.
pub const MAX_LINGER_S: u16 = 300;

/// The most bytes `FRAME_READ` answers and `FRAME_WRITE` takes.
const MAX_FRAME_BYTES: usize = 250;

/// Whom the session belongs to.
#[derive(Clone, Copy, Debug)]
struct Session {
    /// The connection attached; `None` while the session lingers.
    connection: Option<Option<u64>>,
    /// The attached client's address, named to others that try to attach.
    peer: Option<IpAddr>,
    linger: Duration,
    options: DebugOptions,
    /// When a lingering session ends.
    linger_until: Option<Instant>,
}

/// The debug session of one runtime and the services on it.
pub struct Debugging {
    /// `false` for a runtime started with `--debug off`: every service is refused.
    enabled: bool,
    session: Mutex<Option<Session>>,
}

impl Debugging {
    /// The services, refusing everything when not `enabled`.
    pub fn new(enabled: bool) -> Self {
        Self {
            enabled,
            session: Mutex::new(None),
        }
    }

    /// The debug byte of `IDENTIFY`.
    pub fn status(&self, scheduler: &Scheduler) -> DebugStatus {
        let session = *lock(&self.session);
        let halted = session.is_some()
            && scheduler
                .between(|between| {
                    between
                        .memory
                        .as_ref()
                        .is_some_and(|memory| !memory.engine.debug().halted().is_empty())
                })
                .unwrap_or(false);
        DebugStatus {
            session: session.is_some(),
            halted,
            lingering: session.is_some_and(|s| s.connection.is_none()),
            switched_off: !self.enabled,
        }
    }

    /// The session's connection logged out, logged in again or went away: a logout or login
    /// (`closed` false) ends the session at once; a closed connection leaves it lingering for
    /// its linger time (or ends it with a linger of 0). Returns when a lingering session ends
    /// unless taken over, for the caller to call [`Debugging::expire`] then.
    pub fn connection_ended(
        &self,
        scheduler: &Scheduler,
        connection: Option<u64>,
        closed: bool,
    ) -> Option<Instant> {
        let mut session = lock(&self.session);
        let current = session.as_mut()?;
        if current.connection != Some(connection) {
            return None;
        }
        if closed && !current.linger.is_zero() {
            let until = Instant::now() + current.linger;
            current.connection = None;
            current.linger_until = Some(until);
            return Some(until);
        }
        *session = None;
        drop(session);
        end_session(scheduler);
        None
    }

    /// Serves one debugging request from `connection` of the client at `peer`.
    pub fn serve(
        &self,
        scheduler: &Scheduler,
        connection: Option<u64>,
        peer: Option<IpAddr>,
        now: Instant,
        request: DebugRequest,
    ) -> Result<Response, Refusal> {
        if !self.enabled {
            return Err(Refusal::not_now(
                "debugging is switched off on this runtime (rivet-runtime --debug off)",
            ));
        }
        self.expire(scheduler, now);
        let response = match request {
            DebugRequest::Attach {
                linger_s, options, ..
            } => self.attach(scheduler, connection, peer, linger_s, options)?,
            DebugRequest::Detach { .. } => {
                self.require(connection)?;
                *lock(&self.session) = None;
                end_session(scheduler);
                DebugResponse::Detach
            }
            DebugRequest::BreakSet { breakpoint, .. } => {
                self.require(connection)?;
                let hit_mode = match breakpoint.hit.mode {
                    online_protocol::HitMode::Always => HitMode::Always,
                    online_protocol::HitMode::Equal => HitMode::Equal,
                    online_protocol::HitMode::Multiple => HitMode::Multiple,
                    online_protocol::HitMode::AtLeast => HitMode::AtLeast,
                };
                let spec = BreakpointSpec {
                    pou: breakpoint.pou,
                    instruction: breakpoint.instruction,
                    instance: breakpoint.instance,
                    task: (breakpoint.task != 0xFF).then_some(breakpoint.task),
                    hit_mode,
                    hit_target: breakpoint.hit.target,
                    condition: breakpoint.condition,
                };
                let (id, replaced) =
                    on_engine(scheduler, move |engine| Ok(engine.set_breakpoint(spec)?))?;
                DebugResponse::BreakSet { id, replaced }
            }
            DebugRequest::BreakClear { id, .. } => {
                self.require(connection)?;
                on_engine(scheduler, move |engine| {
                    Ok(engine.debug_mut().clear_breakpoint(id)?)
                })?;
                DebugResponse::BreakClear
            }
            DebugRequest::BreakList { from } => break_list(scheduler, from)?,
            DebugRequest::HaltState { from } => {
                let session = *lock(&self.session);
                DebugResponse::HaltState(halt_state(scheduler, session, from)?)
            }
            DebugRequest::Step { task, kind, .. } => {
                self.require(connection)?;
                let kind = match kind {
                    online_protocol::StepKind::Into => StepKind::Into,
                    online_protocol::StepKind::Over => StepKind::Over,
                    online_protocol::StepKind::Out => StepKind::Out,
                };
                on_engine(scheduler, move |engine| {
                    Ok(engine.debug_mut().step(usize::from(task), kind)?)
                })?;
                DebugResponse::Step
            }
            DebugRequest::RunTo {
                task,
                pou,
                instruction,
                ..
            } => {
                self.require(connection)?;
                on_engine(scheduler, move |engine| {
                    Ok(engine
                        .debug_mut()
                        .run_to(usize::from(task), pou, instruction)?)
                })?;
                DebugResponse::RunTo
            }
            DebugRequest::Continue { task, .. } => {
                self.require(connection)?;
                on_engine(scheduler, move |engine| {
                    if task == 0xFF {
                        engine.debug_mut().continue_all();
                        Ok(())
                    } else {
                        Ok(engine.debug_mut().continue_task(usize::from(task))?)
                    }
                })?;
                DebugResponse::Continue
            }
            DebugRequest::Halt { task, .. } => {
                self.require(connection)?;
                on_engine(scheduler, move |engine| {
                    if task == 0xFF {
                        engine.debug_mut().halt_all();
                        Ok(())
                    } else {
                        Ok(engine.debug_mut().halt_task(usize::from(task))?)
                    }
                })?;
                DebugResponse::Halt
            }
            DebugRequest::Stack { task, from } => stack(scheduler, task, from)?,
            DebugRequest::FrameRead {
                task,
                frame,
                ranges,
            } => on_engine(scheduler, move |engine| {
                let (start, end) = frame_span(engine, task, frame)?;
                let stack = engine.stack_bytes(usize::from(task));
                let mut bytes = Vec::new();
                for range in &ranges {
                    let (from, to) = range_in(start, end, range)?;
                    bytes.extend_from_slice(stack.get(from..to).unwrap_or_default());
                    if bytes.len() > MAX_FRAME_BYTES {
                        return Err(Refusal::bad(format!(
                            "the values take more than {MAX_FRAME_BYTES} bytes: read fewer at once"
                        )));
                    }
                }
                Ok(DebugResponse::FrameRead { bytes })
            })?,
            DebugRequest::FrameWrite {
                task,
                frame,
                values,
                ..
            } => {
                self.require(connection)?;
                on_engine(scheduler, move |engine| {
                    let (start, end) = frame_span(engine, task, frame)?;
                    let mut places = Vec::with_capacity(values.len());
                    for (range, value) in &values {
                        places.push(range_in(start, end, range)?);
                        if value.len() != usize::from(range.size) {
                            return Err(Refusal::bad(format!(
                                "{} bytes given for a place of {}",
                                value.len(),
                                range.size
                            )));
                        }
                    }
                    let stack = engine.stack_bytes_mut(usize::from(task));
                    for ((from, to), (_, value)) in places.into_iter().zip(&values) {
                        if let Some(place) = stack.get_mut(from..to) {
                            place.copy_from_slice(value);
                        }
                    }
                    Ok(())
                })?;
                DebugResponse::FrameWrite
            }
            DebugRequest::FlowConfigure { task, entries, .. } => {
                self.require(connection)?;
                let pous: Vec<(u32, u64)> = entries.iter().map(|e| (e.pou, e.instance)).collect();
                on_engine(scheduler, move |engine| {
                    Ok(engine
                        .debug_mut()
                        .configure_flow(usize::from(task), &pous)?)
                })?;
                DebugResponse::FlowConfigure
            }
            DebugRequest::FlowRead { entry, which, from } => {
                if from % 8 != 0 {
                    return Err(Refusal::bad(format!(
                        "a flow bitmap is read from a multiple of 8, not from {from}"
                    )));
                }
                on_engine(scheduler, move |engine| {
                    let flow = engine
                        .debug()
                        .flow()
                        .ok_or_else(|| Refusal::not_now("no flow recording is configured"))?;
                    let track = flow.tracks.get(usize::from(entry)).ok_or_else(|| {
                        Refusal::bad(format!(
                            "the flow recording has {} entries, not {}",
                            flow.tracks.len(),
                            u16::from(entry) + 1
                        ))
                    })?;
                    let (bits, cycle) = match which {
                        FlowCycle::LastComplete => (&track.last, track.last_cycle),
                        // The cycle in progress is the one after the task's finished cycles.
                        FlowCycle::Current => (
                            &track.current,
                            engine.debug().task(flow.task).map_or(0, |t| t.cycle + 1),
                        ),
                    };
                    let bitmap = bits
                        .iter()
                        .skip((from / 8) as usize)
                        .take(MAX_FLOW_BITMAP_BYTES)
                        .copied()
                        .collect();
                    Ok(DebugResponse::FlowRead {
                        cycle,
                        statements: track.statements,
                        bitmap,
                    })
                })?
            }
        };
        Ok(Response::Debug(response))
    }

    /// Ends a lingering session whose time is up at `now`.
    pub fn expire(&self, scheduler: &Scheduler, now: Instant) {
        let mut session = lock(&self.session);
        if session
            .and_then(|s| s.linger_until)
            .is_some_and(|until| now >= until)
        {
            *session = None;
            drop(session);
            end_session(scheduler);
        }
    }

    /// Checks that the session is attached to `connection`.
    fn require(&self, connection: Option<u64>) -> Result<(), Refusal> {
        match *lock(&self.session) {
            None => Err(Refusal::not_now("no debug session: attach first")),
            Some(session) if session.connection == Some(connection) => Ok(()),
            Some(session) => Err(Refusal::not_now(attached_elsewhere(session))),
        }
    }

    fn attach(
        &self,
        scheduler: &Scheduler,
        connection: Option<u64>,
        peer: Option<IpAddr>,
        linger_s: u16,
        options: DebugOptions,
    ) -> Result<DebugResponse, Refusal> {
        if linger_s > MAX_LINGER_S {
            return Err(Refusal::bad(format!(
                "a linger of {linger_s} s is longer than {MAX_LINGER_S} s"
            )));
        }
        let mut session = lock(&self.session);
        let took_over = match *session {
            Some(current) if current.connection.is_none() => true,
            Some(current) if current.connection == Some(connection) => false,
            Some(current) => return Err(Refusal::not_now(attached_elsewhere(current))),
            None => false,
        };
        let (halted, breakpoints) = on_engine(scheduler, move |engine| {
            if engine.debug().task_count() > 255 {
                return Err(Refusal::not_now(
                    "a program with more than 255 tasks cannot be debugged",
                ));
            }
            engine.debug_mut().begin_session();
            engine
                .debug_mut()
                .set_halt_all_on_halt(options.halt_all_on_halt);
            let debug = engine.debug();
            Ok((
                u8::try_from(debug.halted().len()).unwrap_or(u8::MAX),
                u16::try_from(debug.breakpoints().len()).unwrap_or(u16::MAX),
            ))
        })?;
        *session = Some(Session {
            connection: Some(connection),
            peer,
            linger: Duration::from_secs(u64::from(linger_s)),
            options,
            linger_until: None,
        });
        Ok(DebugResponse::Attach {
            took_over,
            halted,
            breakpoints,
        })
    }

    /// After a download: the new program's engine runs with the debugger when a session is
    /// attached (its breakpoints went with the old code).
    pub fn program_loaded(&self, scheduler: &Scheduler) {
        if lock(&self.session).is_some() {
            let _ = on_engine(scheduler, |engine| {
                engine.debug_mut().begin_session();
                Ok(())
            });
        }
    }
}

/// The message for a connection that is not the one attached.
fn attached_elsewhere(session: Session) -> String {
    match (session.connection, session.peer) {
        (None, _) => "the debug session lingers: attach to take it over".to_owned(),
        (Some(_), Some(peer)) => format!("the debug session is attached to {peer}"),
        (Some(_), None) => "the debug session is attached to another connection".to_owned(),
    }
}

/// Ends the engine's session: breakpoints removed, halted tasks going on.
fn end_session(scheduler: &Scheduler) {
    let _ = on_engine(scheduler, |engine| {
        engine.debug_mut().end_session();
        Ok(())
    });
}

/// Runs `action` on the engine between two cycles or inside a halt.
fn on_engine<T: Send + 'static>(
    scheduler: &Scheduler,
    action: impl FnOnce(&mut EngineView<'_>) -> Result<T, Refusal> + Send + 'static,
) -> Result<T, Refusal> {
    scheduler
        .between(
            move |between: &mut Between<'_>| match between.memory.as_mut() {
                Some(memory) => action(&mut memory.engine),
                None => Err(Refusal::not_now("no program is loaded")),
            },
        )
        .map_err(|error| Refusal::not_now(error.to_string()))?
}

impl From<DebugError> for Refusal {
    fn from(error: DebugError) -> Self {
        match error {
            DebugError::TooManyBreakpoints
            | DebugError::NotHalted(_)
            | DebugError::Beneath { .. } => Refusal::not_now(error.to_string()),
            _ => Refusal::bad(error.to_string()),
        }
    }
}

fn break_list(scheduler: &Scheduler, from: u16) -> Result<DebugResponse, Refusal> {
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

fn halt_state(
    scheduler: &Scheduler,
    session: Option<Session>,
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
            session: match session {
                None => SessionState::None,
                Some(s) if s.connection.is_none() => SessionState::Lingering,
                Some(_) => SessionState::Attached,
            },
            options: session.map(|s| s.options).unwrap_or_default(),
            generation: debug.generation(),
            total: u8::try_from(count).unwrap_or(u8::MAX),
            tasks,
        })
    })
}

/// Whether task `task` is halted or waits beneath a halted task.
fn stopped_in_cycle(engine: &EngineView<'_>, task: usize) -> bool {
    let debug = engine.debug();
    debug.is_halted(task) || debug.waiting(task)
}

fn not_stopped(engine: &EngineView<'_>, task: u8) -> Refusal {
    Refusal::not_now(format!(
        "task '{}' is neither halted nor waiting beneath a halted task",
        engine.debug().task_name(usize::from(task))
    ))
}

fn stack(scheduler: &Scheduler, task: u8, from: u16) -> Result<DebugResponse, Refusal> {
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
fn frame_span(engine: &EngineView<'_>, task: u8, frame: u16) -> Result<(usize, usize), Refusal> {
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
fn range_in(start: usize, end: usize, range: &FrameRange) -> Result<(usize, usize), Refusal> {
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

fn lock<T>(mutex: &Mutex<T>) -> MutexGuard<'_, T> {
    mutex.lock().unwrap_or_else(PoisonError::into_inner)
}

#[cfg(test)]
#[path = "debug_tests.rs"]
mod tests;
