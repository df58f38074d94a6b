//! Applying the debugging commands: breakpoints in the settings, flow commands to the target,
//! frames of the call stack opened in their POU.

use super::state::Studio;
use crate::studio::command::Command;
use crate::studio::debug::{
    BreakpointPlace, Breakpoints, DebugCommand, DebugTarget as _, statement_line, statement_lines,
    statement_of_place,
};
use crate::studio::i18n::DebugText;
use crate::studio::settings::Settings;

impl Studio {
    /// The open project's breakpoints, to change; `None` without a project.
    fn breakpoints_mut(&mut self) -> Option<&mut Breakpoints> {
        let key = Settings::project_key(&self.shared.session.as_ref()?.dir);
        Some(self.shared.settings.breakpoints.entry(key).or_default())
    }

    /// Sets or clears the breakpoint of `place`'s line, moved to the statement that starts
    /// there or next by the last build's line table.
    pub(super) fn toggle_breakpoint(&mut self, place: BreakpointPlace) {
        let language = self.shared.settings.language;
        if place.graphical.is_some() {
            self.toggle_graphical_breakpoint(place);
            return;
        }
        let lines = self
            .shared
            .last_build
            .as_ref()
            .and_then(|build| build.image.as_ref())
            .map(|image| statement_lines(&image.program, &place.file))
            .unwrap_or_default();
        let Some(line) = statement_line(&lines, place.line) else {
            let message = DebugText::NoStatementAfter.fill(
                language,
                &[("line", &place.line.to_string()), ("file", &place.file)],
            );
            self.commands.error(message);
            return;
        };
        let place = BreakpointPlace { line, ..place };
        if let Some(breakpoints) = self.breakpoints_mut() {
            breakpoints.toggle(place);
        }
        self.sync_breakpoints();
    }

    /// Sets or clears the breakpoint of a network or element of a graphical body. A new one is
    /// refused, with the reason, when the last build is of the project as it is and no
    /// statement of the image comes from the place (the editor checked the lowering already).
    fn toggle_graphical_breakpoint(&mut self, place: BreakpointPlace) {
        let exists = self
            .breakpoints_mut()
            .is_some_and(|breakpoints| breakpoints.at(&place).is_some());
        if !exists
            && let Some(session) = self.shared.session.as_ref()
            && let Some(build) = self.shared.last_build.as_ref()
            && build.revision == session.history.revision()
            && let Some(image) = build.image.as_ref()
        {
            let bodies = self
                .panes
                .texts
                .graphical
                .graphical_bodies(&session.project, build.revision);
            if statement_of_place(&place, &image.program, &bodies).is_none() {
                let language = self.shared.settings.language;
                let what = place
                    .graphical
                    .as_ref()
                    .map(|graphical| {
                        crate::studio::panes::graphical_place_text(
                            language,
                            Some(&session.project),
                            graphical,
                        )
                    })
                    .unwrap_or_default();
                self.commands
                    .error(DebugText::NoElementStatement.fill(language, &[("place", &what)]));
                return;
            }
        }
        if let Some(breakpoints) = self.breakpoints_mut() {
            breakpoints.toggle(place);
        }
        self.sync_breakpoints();
    }

    /// Changes the open project's breakpoints with `change` and sends them to the target.
    pub(super) fn change_breakpoints(&mut self, change: impl FnOnce(&mut Breakpoints)) {
        if let Some(breakpoints) = self.breakpoints_mut() {
            change(breakpoints);
        }
        self.sync_breakpoints();
    }

    /// Sends the enabled breakpoints to the target while logged in; offline they wait in the
    /// settings for the next login.
    pub(super) fn sync_breakpoints(&mut self) {
        if !self.shared.online.is_logged_in() {
            return;
        }
        let enabled = self
            .breakpoints_mut()
            .map(|breakpoints| {
                breakpoints
                    .all()
                    .iter()
                    .filter(|breakpoint| breakpoint.enabled)
                    .cloned()
                    .collect()
            })
            .unwrap_or_default();
        self.shared
            .online
            .debug(DebugCommand::SyncBreakpoints(enabled));
    }

    /// Sends a flow command to the target, or says why it cannot go.
    pub(super) fn debug(&mut self, command: DebugCommand) {
        let language = self.shared.settings.language;
        if let DebugCommand::SetFlowControl(on) = command {
            self.shared.debug.flow_control = on;
        }
        if !self.shared.online.is_logged_in() {
            if !matches!(command, DebugCommand::SetFlowControl(_)) {
                self.commands.error(DebugText::LogInToDebug.get(language));
            }
            return;
        }
        if command.needs_halt() && !self.shared.debug.is_halted() {
            self.commands.error(DebugText::NotHalted.get(language));
            return;
        }
        let shown = self.shared.debug.shown().map(|(task, _)| task.to_owned());
        self.shared.online.set_shown_task(shown);
        if let DebugCommand::SetFlowControl(on) = command {
            let bodies = if on { self.flow_bodies() } else { Vec::new() };
            self.shared.online.set_flow_bodies(bodies);
        }
        if !self.shared.online.debug(command) {
            self.commands
                .error(DebugText::TargetRefusesDebugging.get(language));
        }
    }

    /// The POU bodies of the open Structured Text editors with the instances they show, which
    /// flow control records.
    pub(super) fn flow_bodies(&self) -> Vec<(String, Option<String>)> {
        self.shared
            .session
            .as_ref()
            .map(|session| self.panes.texts.flow_bodies(&session.project))
            .unwrap_or_default()
    }

    /// The place at the caret of the last Structured Text editor used, or a status saying to
    /// put the caret there first.
    pub(super) fn caret_place(&mut self) -> Option<BreakpointPlace> {
        let place = self.panes.texts.last_caret.clone();
        if place.is_none() {
            let language = self.shared.settings.language;
            self.commands.error(DebugText::NoCaret.get(language));
        }
        place
    }

    /// Shows frame `frame` of `task` and opens its POU at its line.
    pub(super) fn show_frame(&mut self, task: &str, frame: usize) -> Option<Command> {
        self.shared.debug.show_frame(task, frame);
        let frame = self.shared.debug.shown_frame()?.clone();
        if let Some(session) = self.shared.session.as_ref()
            && let Some((target, place)) = self.panes.texts.graphical.place_of_line(
                &session.project,
                session.history.revision(),
                &frame.file,
                frame.line,
            )
        {
            // A graphical body: its editor selects the element the halt or call is at.
            let pou = frame.pou.split('.').next().unwrap_or_default().to_owned();
            return Some(Command::Reveal(
                crate::studio::tree_node::TreeNode::Object(pou),
                crate::studio::reveal::Reveal::Element {
                    target,
                    network: place.network,
                    element: place.element,
                },
            ));
        }
        Some(crate::studio::panes::source_place(
            self.shared.view(),
            &frame.pou,
            &frame.file,
            frame.line,
        ))
    }
}
