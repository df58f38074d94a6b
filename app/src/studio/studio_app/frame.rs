//! What the studio does at the start of each frame: takes in what background work produced
//! (the build, online events, recovery copies) and tells the online state what to read.

use std::time::{Duration, Instant};

use super::state::Studio;
use crate::studio::status::StatusMessage;
use crate::studio::watch_sources::{WatchSources, watched_paths};

/// How many online messages the messages pane keeps.
const ONLINE_MESSAGES_KEPT: usize = 200;

impl Studio {
    /// Collects what background work produced since the last frame: the build's outcome and
    /// online events. Keeps the UI drawing while something is under way.
    pub(super) fn take_in_background_results(&mut self, ctx: &egui::Context) {
        self.keep_recovery_copy(ctx);
        self.shared.refresh_overlaps();
        let language = self.shared.settings.language;
        self.panes.texts.inline.begin_frame();
        self.panes.texts.set_language(language);
        if let Some(job) = &self.shared.build {
            match job.poll() {
                Some(outcome) => {
                    self.shared.build = None;
                    self.finish_build(outcome, ctx);
                }
                None => ctx.request_repaint_after(Duration::from_millis(50)),
            }
        }
        if !self.waker_set {
            let wake = ctx.clone();
            self.shared
                .online
                .set_waker(std::sync::Arc::new(move || wake.request_repaint()));
            self.waker_set = true;
        }
        self.set_watched_variables();
        self.shared.online.set_language(language);
        self.shared.online.poll(Instant::now());
        self.record_cycle_times();
        for message in self.shared.online.take_messages() {
            self.shared.status = Some(StatusMessage {
                text: message.text.clone(),
                is_error: message.is_error,
            });
            self.shared.online_messages.push(message);
        }
        let messages = &mut self.shared.online_messages;
        if messages.len() > ONLINE_MESSAGES_KEPT {
            let excess = messages.len() - ONLINE_MESSAGES_KEPT;
            messages.drain(..excess);
        }
        if self.shared.online.is_logged_in() || self.shared.online.can_write() {
            // Values, statistics and trace states arrive by polling; redraw to show them.
            ctx.request_repaint_after(Duration::from_millis(100));
        }
    }

    /// Tells the online state every variable a pane or editor shows.
    fn set_watched_variables(&mut self) {
        let session = self.shared.session.as_ref();
        let devices = session
            .map(|session| session.project.modbus_devices.as_slice())
            .unwrap_or_default();
        let sources = WatchSources {
            watch_list: self.panes.watch.watched_paths(session),
            trace: self.panes.trace.variable_paths(session),
            inline: self.panes.texts.inline.paths().cloned().collect(),
            cams: self.panes.cams.take_live_paths(),
        };
        let watched = watched_paths(sources, devices, self.shared.online.is_logged_in());
        self.shared.online.set_watch(watched, devices);
    }

    /// Adds the tasks' cycle times to the history when the target reported new ones.
    fn record_cycle_times(&mut self) {
        let online = &self.shared.online;
        if online.tasks_generation() == self.cycles_seen {
            return;
        }
        self.cycles_seen = online.tasks_generation();
        let at_s = self.started.elapsed().as_secs_f64();
        for task in online.tasks() {
            self.shared.cycle_history.push(
                &task.name,
                at_s,
                task.last_ns,
                task.average_ns,
                task.max_ns,
                task.min_ns,
                task.jitter_max_ns,
                task.cycles,
            );
        }
    }

    /// Sends the window title when it changed: the project, a `*` when it has unsaved changes.
    pub(super) fn update_title(&mut self, ctx: &egui::Context) {
        let title = match &self.shared.session {
            Some(session) => {
                let dirty = if session.history.is_dirty() { "*" } else { "" };
                format!("{}{dirty} — Rivet", session.title())
            }
            None => "Rivet".to_owned(),
        };
        if title != self.title {
            ctx.send_viewport_cmd(egui::ViewportCommand::Title(title.clone()));
            self.title = title;
        }
    }
}
