//! Opening and saving projects, and changing them: edits, undo and redo, find references.

use std::path::Path;

use super::state::Studio;
use crate::studio::dock::Dock;
use crate::studio::documents::close_stale_documents;
use crate::studio::error_texts::edit_error_text;
use crate::studio::i18n::Text;
use crate::studio::recovery_schedule::RecoverySchedule;
use crate::studio::references::{ReferenceItem, References};
use crate::studio::session::{SaveAsError, Session};
use crate::studio::status::StatusMessage;
use crate::studio::tree_node::TreeNode;

impl Studio {
    /// Opens the project in `dir`, closing the documents the old one had; on failure the
    /// current project stays open and the errors are listed.
    pub(super) fn open_project(&mut self, dock: &mut Dock, dir: &Path) {
        let language = self.shared.settings.language;
        match Session::open(dir) {
            Ok(session) => {
                let shared = &mut self.shared;
                shared.online.logout();
                shared.problems = session.load_problems.clone();
                shared.failed_dir = None;
                shared.selection = None;
                shared.last_build = None;
                shared.build = None;
                shared.references = References::default();
                shared.overlaps = (None, Vec::new());
                close_stale_documents(dock, &session.project);
                self.recovery.schedule = RecoverySchedule::default();
                self.panes.forget_documents();
                self.recovery.offer = self
                    .recovery
                    .recovery
                    .as_ref()
                    .and_then(|recovery| recovery.find(dir))
                    .filter(|found| found.project != session.project);
                let status = if session.held_back.is_empty() {
                    StatusMessage::info(format!(
                        "{} {}",
                        Text::Opened.get(language),
                        session.title()
                    ))
                } else {
                    StatusMessage::error(Text::OpenedPartly.fill(
                        language,
                        &[
                            ("name", &session.title()),
                            ("count", &session.held_back.len().to_string()),
                        ],
                    ))
                };
                self.report(status);
                self.shared.session = Some(session);
            }
            Err(error) => {
                self.shared.problems = error.problems;
                self.shared.failed_dir = Some(dir.to_owned());
                self.report(StatusMessage::error(format!(
                    "{}: {}",
                    Text::CouldNotOpen.get(language),
                    dir.display()
                )));
            }
        }
    }

    /// Saves the project to its folder and removes the recovery copy.
    pub(super) fn save(&mut self) {
        let language = self.shared.settings.language;
        let Some(session) = &mut self.shared.session else {
            return;
        };
        let saved = session.save();
        if saved.is_ok()
            && let Some(recovery) = &self.recovery.recovery
        {
            recovery.clear(&session.dir);
            self.recovery.schedule.saved();
        }
        let message = match saved {
            Ok(report) if report.written.is_empty() && report.removed.is_empty() => {
                StatusMessage::info(Text::NothingToSave.get(language))
            }
            Ok(report) => StatusMessage::info(
                Text::SavedFiles
                    .get(language)
                    .replace("{written}", &report.written.len().to_string())
                    .replace("{removed}", &report.removed.len().to_string()),
            ),
            Err(error) => {
                StatusMessage::error(format!("{}: {error}", Text::SaveFailed.get(language)))
            }
        };
        self.report(message);
    }

    /// Saves the project into `dir`, which must not hold another project.
    pub(super) fn save_as(&mut self, dir: &Path) {
        let language = self.shared.settings.language;
        let Some(session) = &mut self.shared.session else {
            return;
        };
        let message = match session.save_as(dir) {
            Ok(_) => {
                StatusMessage::info(format!("{} {}", Text::Saved.get(language), dir.display()))
            }
            Err(SaveAsError::FolderHoldsProject(_)) => StatusMessage::error(format!(
                "{}: {}",
                Text::SaveAsRefused.get(language),
                dir.display()
            )),
            Err(error) => {
                StatusMessage::error(format!("{}: {error}", Text::SaveFailed.get(language)))
            }
        };
        self.report(message);
    }

    /// Applies one gesture's edits as one undo step.
    pub(super) fn apply_edits(&mut self, label: &str, edits: Vec<project_model::Edit>) {
        let Some(session) = &mut self.shared.session else {
            return;
        };
        if let Err(error) = session.history.apply(&mut session.project, label, edits) {
            let reason = edit_error_text(&error, self.shared.settings.language);
            self.report(StatusMessage::error(format!("{label}: {reason}")));
        }
    }

    /// Applies a text editor's edits: typing with the same merge key joins the last undo
    /// step, anything else is a step of its own.
    pub(super) fn apply_text(
        &mut self,
        label: &str,
        edits: Vec<project_model::Edit>,
        merge_key: Option<&str>,
    ) {
        let Some(session) = &mut self.shared.session else {
            return;
        };
        let result = match merge_key {
            Some(key) => session
                .history
                .apply_merging(&mut session.project, label, edits, key),
            None => {
                session.history.break_merging();
                session.history.apply(&mut session.project, label, edits)
            }
        };
        if let Err(error) = result {
            let reason = edit_error_text(&error, self.shared.settings.language);
            self.report(StatusMessage::error(format!("{label}: {reason}")));
        }
    }

    /// Undoes (or redoes) the last change and says so in the status bar.
    pub(super) fn undo_redo(&mut self, undo: bool) {
        let Some(session) = &mut self.shared.session else {
            return;
        };
        let result = if undo {
            session.history.undo(&mut session.project)
        } else {
            session.history.redo(&mut session.project)
        };
        let language = self.shared.settings.language;
        let verb = if undo { Text::Undo } else { Text::Redo }.get(language);
        self.shared.status = match result {
            Ok(Some(label)) => Some(StatusMessage::info(format!("{verb}: {label}"))),
            Ok(None) => None,
            Err(error) => Some(StatusMessage::error(format!(
                "{verb}: {}",
                edit_error_text(&error, language)
            ))),
        };
    }

    /// Lists every reference to the name at `offset` of `target` for the messages pane.
    pub(super) fn find_references(&mut self, target: &project_model::TextTarget, offset: usize) {
        let Some(session) = &self.shared.session else {
            return;
        };
        let project = &session.project;
        let name = compiler::ide::definition(project, target, offset)
            .map(|definition| definition.name)
            .unwrap_or_default();
        let bodies = project_model::st_body_files(project);
        let found = compiler::ide::references(project, target, offset);
        let items = found
            .into_iter()
            .filter_map(|reference| {
                let body = bodies.iter().find(|body| body.target == reference.target)?;
                let (line, column) =
                    crate::studio::build_job::line_column(body.text, reference.range.start);
                let text = body.text.lines().nth(line - 1).unwrap_or_default().trim();
                Some(ReferenceItem {
                    label: format!("{}:{line}:{column}: {text}", reference.file.display()),
                    node: TreeNode::Object(body.pou.name.clone()),
                    target: reference.target.clone(),
                    range: reference.range.clone(),
                })
            })
            .collect();
        self.shared.references = References { items, of: name };
    }
}
