//! Keeping the copy of unsaved changes current, and offering an earlier one back.

use std::time::Instant;

use super::state::Studio;
use crate::studio::i18n::Text;
use crate::studio::recovery_schedule::{RECOVERY_DELAY, RecoveryStep};
use crate::studio::status::StatusMessage;

impl Studio {
    /// Keeps the copy of unsaved changes current: written once the project rested
    /// [`RECOVERY_DELAY`] after a change, removed once the project equals its files again. A
    /// copy that failed is reported in the status bar and tried again after the delay.
    pub(super) fn keep_recovery_copy(&mut self, ctx: &egui::Context) {
        self.take_in_recovery_outcome(ctx);
        let copies = &mut self.recovery;
        let (Some(recovery), Some(session)) = (&copies.recovery, &self.shared.session) else {
            return;
        };
        let revision = session.history.revision();
        let dirty = session.history.is_dirty();
        match copies.schedule.next(revision, dirty, Instant::now()) {
            RecoveryStep::Nothing => {}
            RecoveryStep::WaitFor(delay) => ctx.request_repaint_after(delay),
            RecoveryStep::Clear => recovery.clear(&session.dir),
            RecoveryStep::Write => {
                // The copy is written on a thread so a large project never stalls a frame.
                let recovery = recovery.clone();
                let dir = session.dir.clone();
                let project = session.project.clone();
                let (send, receive) = std::sync::mpsc::channel();
                let wake = ctx.clone();
                let spawned = std::thread::Builder::new()
                    .name("rivet-recovery".into())
                    .spawn(move || {
                        // The studio may have closed meanwhile; then nobody waits for the outcome.
                        let _ = send.send(recovery.write(&dir, &project));
                        wake.request_repaint();
                    });
                match spawned {
                    Ok(_) => copies.writing = Some(receive),
                    Err(error) => self.recovery_failed(error, ctx),
                }
            }
        }
    }

    /// Takes in the outcome of the copy written on its thread, if it arrived.
    fn take_in_recovery_outcome(&mut self, ctx: &egui::Context) {
        let Some(receive) = &self.recovery.writing else {
            return;
        };
        let outcome = match receive.try_recv() {
            Ok(outcome) => outcome,
            Err(std::sync::mpsc::TryRecvError::Empty) => return,
            Err(std::sync::mpsc::TryRecvError::Disconnected) => Err(std::io::Error::other(
                "the thread writing the copy ended without an outcome",
            )),
        };
        self.recovery.writing = None;
        if let Err(error) = self.recovery.schedule.finished(outcome, Instant::now()) {
            self.report_recovery_failure(&error, ctx);
        }
    }

    /// A copy that could not even be started counts as failed.
    fn recovery_failed(&mut self, error: std::io::Error, ctx: &egui::Context) {
        let outcome = self.recovery.schedule.finished(Err(error), Instant::now());
        if let Err(error) = outcome {
            self.report_recovery_failure(&error, ctx);
        }
    }

    fn report_recovery_failure(&mut self, error: &std::io::Error, ctx: &egui::Context) {
        let language = self.shared.settings.language;
        self.report(StatusMessage::error(format!(
            "{}: {error}",
            Text::RecoveryCopyFailed.get(language)
        )));
        ctx.request_repaint_after(RECOVERY_DELAY);
    }

    /// Offers the unsaved changes of an earlier session, if any were found.
    pub(super) fn recovery_dialog_ui(&mut self, ctx: &egui::Context) {
        let Some(offer) = &self.recovery.offer else {
            return;
        };
        let language = self.shared.settings.language;
        let age = offer
            .written
            .elapsed()
            .map(|age| format!("{} min", age.as_secs() / 60))
            .unwrap_or_default();
        let mut choice = None;
        egui::Modal::new(egui::Id::unique("recovery_dialog")).show(ctx, |ui| {
            ui.set_width(460.0);
            ui.heading(Text::RecoverTitle.get(language));
            ui.label(format!("{} ({age})", Text::RecoverQuestion.get(language)));
            ui.horizontal(|ui| {
                if ui.button(Text::Recover.get(language)).clicked() {
                    choice = Some(true);
                }
                if ui.button(Text::Discard.get(language)).clicked() {
                    choice = Some(false);
                }
            });
        });
        match choice {
            Some(true) => {
                if let Some(offer) = self.recovery.offer.take() {
                    self.apply_edits(
                        Text::UndoRecover.get(language),
                        vec![project_model::Edit::ReplaceProject(Box::new(offer.project))],
                    );
                }
            }
            Some(false) => {
                self.recovery.offer = None;
                if let (Some(recovery), Some(session)) =
                    (&self.recovery.recovery, &self.shared.session)
                {
                    recovery.clear(&session.dir);
                }
            }
            None => {}
        }
    }
}
