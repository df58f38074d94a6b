//! The debugger's door to the target (`docs/protocol.md` §6): the Debug menu's commands become
//! the session's debugging commands through the image the studio logged in with, and the
//! session's halts and flow bitmaps come back as the studio's [`HaltedTask`]s and flow lines.

use std::collections::VecDeque;

use online::session::{Command, DebugCommand as SessionCommand, HaltedTask as ReportedTask};
use online::{ALL_TASKS, FlowBitmap, FlowEntry, StepKind};

use super::{Online, Phase};
use crate::debug_bodies::GraphicalBodies;
use crate::studio::debug::{
    Breakpoint, BreakpointPlace, ConditionCache, ConditionKey, DebugCommand, DebugTarget,
    HaltedTask, breakpoint_spec_with, breakpoint_statement, compile_condition, condition_key,
    flow_entries, flow_lines, halted_tasks,
};
use crate::studio::i18n::DebugText;

/// The debugging side of the login: whether the session is attached, what the studio asked for
/// (sent again at each attach), and what the target reported since the studio last looked.
#[derive(Default)]
pub(super) struct Debugging {
    /// `DEBUG_ATTACH` was sent on this connection.
    attach_sent: bool,
    /// The target answered it: the session is attached.
    attached: bool,
    /// The enabled breakpoints the studio asked for last.
    breakpoints: Vec<Breakpoint>,
    /// The task whose frame the studio shows, which steps and continues act on.
    shown_task: Option<String>,
    /// The bodies flow control records (POU name, instance path), empty when it is off.
    flow_bodies: Vec<(String, Option<String>)>,
    /// The places of each breakpoint replacement sent and not answered yet, in the order sent.
    sent: VecDeque<Vec<BreakpointPlace>>,
    /// The halted tasks as the session reported them last.
    reported: Vec<ReportedTask>,
    /// The halted tasks reported and not taken by the studio yet.
    halted: Option<Vec<HaltedTask>>,
    /// The flow lines reported and not taken by the studio yet.
    flow: Option<Vec<(String, Vec<u32>)>>,
    /// The breakpoints' conditions compiled for the image logged in with.
    conditions: ConditionCache,
    /// Why breakpoints of the last list sent are not set, by place, in words naming the place;
    /// the Breakpoints pane shows each under its breakpoint.
    problems: Vec<(BreakpointPlace, String)>,
}

impl DebugTarget for Online {
    /// Queues `command` while logged in to a target that offers debugging; breakpoints and
    /// flow control given before the session is attached are sent once it is.
    fn debug(&mut self, command: DebugCommand) -> bool {
        if self.link.is_none() || !self.offers_debugging() {
            return false;
        }
        match command {
            DebugCommand::SyncBreakpoints(breakpoints) => {
                self.debugging.breakpoints = breakpoints;
                if self.debugging.attached {
                    self.send_breakpoints();
                }
                true
            }
            DebugCommand::SetFlowControl(_) => {
                if self.debugging.attached {
                    self.send_flow();
                }
                true
            }
            DebugCommand::Continue => self.on_shown_task(SessionCommand::Continue),
            DebugCommand::StepOver => self.on_shown_task(|task| SessionCommand::Step {
                task,
                kind: StepKind::Over,
            }),
            DebugCommand::StepInto => self.on_shown_task(|task| SessionCommand::Step {
                task,
                kind: StepKind::Into,
            }),
            DebugCommand::StepOut => self.on_shown_task(|task| SessionCommand::Step {
                task,
                kind: StepKind::Out,
            }),
            DebugCommand::RunToCursor(place) => {
                let Some(image) = &self.image else {
                    return false;
                };
                let bodies = GraphicalBodies::of_project(&image.project);
                match breakpoint_statement(&image.program, &bodies, &place) {
                    Ok(statement) => self.on_shown_task(|task| SessionCommand::RunTo {
                        task,
                        pou: statement.pou,
                        instruction: statement.instruction,
                    }),
                    Err(error) => {
                        let reason = error.to_string();
                        self.error(
                            DebugText::DebugRefused.fill(self.language, &[("reason", &reason)]),
                        );
                        true
                    }
                }
            }
            DebugCommand::Halt(task) => match self.task_index(&task) {
                Some(task) => self.send_debug(SessionCommand::Halt(task)),
                None => false,
            },
            DebugCommand::HaltAll => self.send_debug(SessionCommand::Halt(ALL_TASKS)),
        }
    }
}

impl Online {
    /// Whether the target said it offers debugging (not a runtime started with `--debug off`).
    fn offers_debugging(&self) -> bool {
        self.target_identity
            .as_ref()
            .is_none_or(|identity| !identity.debug.switched_off)
    }

    /// Tells which task's frame the studio shows: steps and continues act on it.
    pub fn set_shown_task(&mut self, task: Option<String>) {
        self.debugging.shown_task = task;
    }

    /// Sets the bodies flow control records, each a POU's name with the instance its editor
    /// shows (none for every instance); empty turns it off. Sent with the next
    /// [`DebugCommand::SetFlowControl`] or attach.
    pub fn set_flow_bodies(&mut self, bodies: Vec<(String, Option<String>)>) {
        self.debugging.flow_bodies = bodies;
    }

    /// Keeps flow control recording the bodies open now: sent again when they changed (an
    /// editor opened or closed) while the session is attached. Called every frame while flow
    /// control is on.
    pub fn keep_flow_bodies(&mut self, bodies: Vec<(String, Option<String>)>) {
        if bodies != self.debugging.flow_bodies {
            self.debugging.flow_bodies = bodies;
            if self.debugging.attached {
                self.send_flow();
            }
        }
    }

    /// The halted tasks the session reported since the last call, if it reported any.
    pub fn take_halted(&mut self) -> Option<Vec<HaltedTask>> {
        self.debugging.halted.take()
    }

    /// Why the breakpoint at `place` is not set on the target, if the last list sent says so
    /// (a condition that does not compile, a place without a statement, a refusal).
    pub fn breakpoint_problem(&self, place: &BreakpointPlace) -> Option<&str> {
        self.debugging
            .problems
            .iter()
            .find(|(known, _)| known == place)
            .map(|(_, text)| text.as_str())
    }

    /// The flow lines the session reported since the last call, if it reported any.
    pub fn take_flow(&mut self) -> Option<Vec<(String, Vec<u32>)>> {
        self.debugging.flow.take()
    }

    /// Attaches the debug session once the target runs the project's program, if it offers
    /// debugging. Called every frame; sends at most one attach per connection.
    pub(super) fn attach_when_online(&mut self) {
        if self.phase == Phase::Online
            && !self.debugging.attach_sent
            && self.offers_debugging()
            && self.command(Command::Debug(SessionCommand::Attach))
        {
            self.debugging.attach_sent = true;
        }
    }

    /// The connection ended or a new one began: there is no debug session on it, and no task
    /// is halted as far as the studio is concerned.
    pub(super) fn debug_connection_ended(&mut self) {
        let had = self.debugging.attach_sent;
        self.debugging.reported.clear();
        self.debugging.attach_sent = false;
        self.debugging.attached = false;
        self.debugging.problems.clear();
        if had {
            self.debugging.halted = Some(Vec::new());
            self.debugging.flow = Some(Vec::new());
        }
    }

    /// The session is attached: the breakpoints and flow control asked for so far are sent.
    pub(super) fn debug_attached(&mut self) {
        self.debugging.attached = true;
        self.send_breakpoints();
        if !self.debugging.flow_bodies.is_empty() {
            self.send_flow();
        }
    }

    /// Takes the session's report of the halted tasks.
    pub(super) fn debug_halted(&mut self, reported: Vec<ReportedTask>) {
        if let Some(image) = &self.image {
            self.debugging.halted = Some(halted_tasks(&image.program, &reported));
        }
        self.debugging.reported = reported;
        self.frame_locals_stale();
    }

    /// The POU index of frame `frame` of task `task` as the session reported it last.
    pub(super) fn reported_frame_pou(&self, task: u8, frame: u16) -> Option<usize> {
        let task = self
            .debugging
            .reported
            .iter()
            .find(|reported| reported.halt.task == task)?;
        Some(task.frames.get(usize::from(frame))?.pou as usize)
    }

    /// Takes the session's flow bitmaps.
    pub(super) fn debug_flow(&mut self, bitmaps: &[(u8, FlowEntry, FlowBitmap)]) {
        if let Some(image) = &self.image {
            let bitmaps = bitmaps.iter().map(|(_, entry, bitmap)| (entry, bitmap));
            self.debugging.flow = Some(flow_lines(&image.program, bitmaps));
        }
    }

    /// Reports the breakpoints the target refused, naming each one's place.
    pub(super) fn breakpoints_set<Refusal: std::fmt::Display>(
        &mut self,
        ids: Vec<Result<u16, Refusal>>,
    ) {
        // The session answers each replacement in the order they were sent.
        let places = self.debugging.sent.pop_front().unwrap_or_default();
        for (place, id) in places.iter().zip(ids) {
            if let Err(reason) = id {
                let text = DebugText::BreakpointNotSet.fill(
                    self.language,
                    &[("place", &place.label()), ("reason", &reason.to_string())],
                );
                self.debugging.problems.push((place.clone(), text.clone()));
                self.error(text);
            }
        }
    }

    /// Replaces the target's breakpoints with the studio's; one that does not convert is
    /// reported with its place and not sent. Conditions still waiting to be compiled are
    /// compiled on a worker thread first, and the list goes once they are
    /// ([`Online::poll_conditions`]).
    fn send_breakpoints(&mut self) {
        let Some(image) = &self.image else { return };
        let mut specs = Vec::new();
        let mut errors = Vec::new();
        let mut places = Vec::new();
        // Lowered once for all the breakpoints, and only when a graphical place needs it.
        let bodies = if self
            .debugging
            .breakpoints
            .iter()
            .any(|breakpoint| breakpoint.place.graphical.is_some())
        {
            GraphicalBodies::of_project(&image.project)
        } else {
            GraphicalBodies::default()
        };
        let keys: Vec<ConditionKey> = self
            .debugging
            .breakpoints
            .iter()
            .filter_map(|breakpoint| condition_key(&image.program, image.hash, &bodies, breakpoint))
            .collect();
        let conditions = &mut self.debugging.conditions;
        if conditions.compile_missing(&image.project, &keys, self.waker.clone()) {
            return;
        }
        for breakpoint in &self.debugging.breakpoints {
            let spec = breakpoint_spec_with(
                &image.program,
                image.hash,
                &bodies,
                breakpoint,
                &mut |key| match conditions.get(key) {
                    Some(outcome) => outcome.clone(),
                    // Not reached: every key was compiled above.
                    None => compile_condition(&image.project, key),
                },
            );
            match spec {
                Ok(spec) => {
                    specs.push(spec);
                    places.push(breakpoint.place.clone());
                }
                Err(error) => errors.push((breakpoint.place.clone(), error.text(self.language))),
            }
        }
        self.debugging.problems.clone_from(&errors);
        for (_, error) in errors {
            self.error(error);
        }
        if self.send_debug(SessionCommand::SetBreakpoints(specs)) {
            self.debugging.sent.push_back(places);
        }
    }

    /// Sends the breakpoints once the conditions they waited for are compiled. Called every
    /// frame.
    pub(super) fn poll_conditions(&mut self) {
        if self.debugging.conditions.take_finished() && self.debugging.attached {
            self.send_breakpoints();
        }
    }

    /// Configures flow recording for the bodies asked for, in every task that runs each one
    /// (`flow_entries`); a task that runs none of them ends its recording.
    fn send_flow(&mut self) {
        let Some(image) = &self.image else { return };
        let tasks = flow_entries(&image.program, &self.debugging.flow_bodies);
        if tasks.iter().all(|(_, entries)| entries.is_empty()) {
            self.debugging.flow = Some(Vec::new());
        }
        for (task, entries) in tasks {
            self.send_debug(SessionCommand::Flow { task, entries });
        }
    }

    /// Sends a command for the task whose frame is shown.
    fn on_shown_task(&mut self, command: impl FnOnce(u8) -> SessionCommand) -> bool {
        let shown = self.debugging.shown_task.clone();
        match shown.and_then(|task| self.task_index(&task)) {
            Some(task) => self.send_debug(command(task)),
            None => false,
        }
    }

    /// The index of the task named `name` in the image logged in with.
    pub(super) fn task_index(&self, name: &str) -> Option<u8> {
        let image = self.image.as_ref()?;
        let index = image
            .program
            .tasks
            .iter()
            .position(|task| task.name.eq_ignore_ascii_case(name))?;
        u8::try_from(index).ok()
    }

    /// Queues a debugging command for the session.
    fn send_debug(&mut self, command: SessionCommand) -> bool {
        self.command(Command::Debug(command))
    }
}
