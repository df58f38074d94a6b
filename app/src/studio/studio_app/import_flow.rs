//! File ▸ Import PLCopen XML… (`docs/plcopen-xml.md` §6.2): the preview dialog, and what its
//! two buttons do: apply the plan to the open project as one undo step, or write a new project
//! into an empty folder and open it.

use std::path::{Path, PathBuf};

use project_model::{ClashChoice, Edit};

use super::state::Studio;
use crate::plcopen_import::{NewProjectError, write_new_project};
use crate::studio::command::Command;
use crate::studio::dock::Dock;
use crate::studio::error_texts::edit_error_text;
use crate::studio::i18n::ImportText;
use crate::studio::import_dialog::{ImportAction, ImportDialog};
use crate::studio::status::StatusMessage;

impl Studio {
    /// Reads and converts `path` and shows the preview; nothing changes until a button says so.
    pub(super) fn open_import(&mut self, path: PathBuf) {
        let project = self.shared.session.as_ref().map(|session| &session.project);
        self.import = Some(ImportDialog::open(path, project));
    }

    /// Draws the preview while it is open and turns its buttons into commands.
    pub(super) fn import_dialog_ui(&mut self, ctx: &egui::Context) {
        let language = self.shared.settings.language;
        let Some(dialog) = &mut self.import else {
            return;
        };
        let command = match dialog.ui(ctx, language) {
            Some(ImportAction::IntoProject) => Command::ImportIntoProject,
            Some(ImportAction::AsNewProject) => Command::ImportAsNewProjectDialog,
            Some(ImportAction::Close) => Command::CloseImport,
            None => return,
        };
        self.commands.push(command);
    }

    /// Applies the preview's plan to the open project as one undo step and closes the preview;
    /// the project is marked changed and nothing is written until it is saved.
    pub(super) fn import_into_project(&mut self) {
        let language = self.shared.settings.language;
        let (Some(dialog), Some(session)) = (&self.import, &self.shared.session) else {
            return;
        };
        let (Ok(file), Some(plan)) = (&dialog.outcome, &dialog.plan) else {
            return;
        };
        let merged = plan.apply(&session.project, &file.imported.project);
        let name = file_name(&dialog.path);
        let count = |choice| {
            plan.clashes
                .iter()
                .filter(|clash| clash.choice == choice)
                .count()
                .to_string()
        };
        let status = ImportText::ImportedInto.fill(
            language,
            &[
                ("file", &name),
                ("added", &plan.additions.len().to_string()),
                ("replaced", &count(ClashChoice::Replace)),
                ("skipped", &count(ClashChoice::Skip)),
            ],
        );
        let label = ImportText::UndoLabel.fill(language, &[("file", &name)]);
        self.import = None;
        let Some(session) = &mut self.shared.session else {
            return;
        };
        let edits = vec![Edit::ReplaceProject(Box::new(merged))];
        let message = match session.history.apply(&mut session.project, &label, edits) {
            Ok(()) => StatusMessage::info(status),
            Err(error) => {
                StatusMessage::error(format!("{label}: {}", edit_error_text(&error, language)))
            }
        };
        self.report(message);
    }

    /// Writes the previewed project into `dir` (which must not exist or be empty) and opens it;
    /// on failure the preview stays open with the reason and nothing is written.
    pub(super) fn import_as_new_project(&mut self, dock: &mut Dock, dir: &Path) {
        let language = self.shared.settings.language;
        let Some(dialog) = &mut self.import else {
            return;
        };
        let Ok(file) = &dialog.outcome else {
            return;
        };
        match write_new_project(&file.imported.project, dir) {
            Ok(()) => {
                self.import = None;
                self.open_project(dock, dir);
            }
            Err(NewProjectError::NotEmpty(folder)) => {
                let folder = folder.display().to_string();
                dialog.error =
                    Some(ImportText::FolderNotEmpty.fill(language, &[("folder", &folder)]));
            }
            Err(error) => {
                let failed = ImportText::NewProjectFailed.get(language);
                dialog.error = Some(format!("{failed}: {error}"));
            }
        }
    }
}

/// The file's name without its folders, for the status bar and the undo label.
fn file_name(path: &Path) -> String {
    path.file_name()
        .map(|name| name.to_string_lossy().into_owned())
        .unwrap_or_else(|| path.display().to_string())
}
