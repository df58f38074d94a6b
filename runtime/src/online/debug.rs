//! The debugging services of `docs/protocol.md` §6 on a scheduler: the one debug session,
//! attached to a connection or lingering without one, and every §6 service, served between
//! two cycles or from inside a halt (`crate::scheduler`'s halt loop).

use std::net::IpAddr;
use std::sync::{Mutex, MutexGuard, PoisonError};
use std::time::{Duration, Instant};

use online_protocol::{
    DebugOptions, DebugRequest, DebugResponse, DebugStatus, FlowCycle, MAX_FLOW_BITMAP_BYTES,
    Refusal, Response, SessionState,
};

use super::debug_reads::{break_list, frame_span, halt_state, range_in, stack};
use crate::engine::{BreakpointSpec, DebugError, EngineView, HitMode, StepKind};
use crate::scheduler::{Between, Scheduler};

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
                let state = match session {
                    None => SessionState::None,
                    Some(s) if s.connection.is_none() => SessionState::Lingering,
                    Some(_) => SessionState::Attached,
                };
                let options = session.map(|s| s.options).unwrap_or_default();
                DebugResponse::HaltState(halt_state(scheduler, (state, options), from)?)
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
                    let flow = engine.debug().flow();
                    if flow.is_empty() {
                        return Err(Refusal::not_now("no flow recording is configured"));
                    }
                    // Entries are numbered through every task's list in task order.
                    let (task, track) = flow.entry(usize::from(entry)).ok_or_else(|| {
                        Refusal::bad(format!(
                            "the flow recordings have {} entries, not {}",
                            flow.entry_count(),
                            u16::from(entry) + 1
                        ))
                    })?;
                    let (bits, cycle) = match which {
                        FlowCycle::LastComplete => (&track.last, track.last_cycle),
                        // The cycle in progress is the one after the task's finished cycles.
                        FlowCycle::Current => (
                            &track.current,
                            engine.debug().task(task).map_or(0, |t| t.cycle + 1),
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
pub(super) fn on_engine<T: Send + 'static>(
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

fn lock<T>(mutex: &Mutex<T>) -> MutexGuard<'_, T> {
    mutex.lock().unwrap_or_else(PoisonError::into_inner)
}

#[cfg(test)]
#[path = "debug_tests.rs"]
mod tests;
