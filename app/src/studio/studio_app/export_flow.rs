//! File ▸ Export PLCopen XML… (`docs/plcopen-xml.md` §6.4): the project as it is in the editor,
//! unsaved changes included, written as a PLCopen XML file, with the outcome in the status bar.

use std::path::Path;

use super::state::Studio;
use crate::plcopen_export::write_export;
use crate::studio::i18n::{ExportText, ImportText};
use crate::studio::status::StatusMessage;

/// Characters no file name may hold on some platform, replaced in the proposed name.
const NOT_IN_FILE_NAMES: [char; 9] = ['/', '\\', ':', '*', '?', '"', '<', '>', '|'];

impl Studio {
    /// Asks for the file and exports the open project to it; nothing happens without a project
    /// or when the dialog is cancelled.
    pub(super) fn export_plcopen_dialog(&mut self) {
        let language = self.shared.settings.language;
        let Some(session) = &self.shared.session else {
            return;
        };
        let mut dialog = rfd::FileDialog::new()
            .set_title(ExportText::PickFile.get(language))
            .add_filter(ImportText::FileFilter.get(language), &["xml"])
            .set_file_name(proposed_file_name(&session.title()));
        // Beside the project's folder: the file is for another tool, not part of the project.
        if let Some(parent) = session.dir.parent() {
            dialog = dialog.set_directory(parent);
        }
        if let Some(path) = dialog.save_file() {
            self.export_plcopen(&path);
        }
    }

    /// Exports the project as it is in the editor (unsaved changes included, as CODESYS exports
    /// the project it has in memory) to `path`, and says in the status bar what was written or
    /// why nothing was.
    pub(super) fn export_plcopen(&mut self, path: &Path) {
        let language = self.shared.settings.language;
        let Some(session) = &self.shared.session else {
            return;
        };
        let failed = ExportText::Failed.get(language);
        // Objects whose files did not load are not in memory: the export would lack them
        // without a word.
        if !session.held_back.is_empty() {
            let count = session.held_back.len().to_string();
            let reason = ExportText::ObjectsMissing.fill(language, &[("count", &count)]);
            self.report(StatusMessage::error(format!("{failed}: {reason}")));
            return;
        }
        let message = match write_export(&session.project, path) {
            Ok(_) => {
                let text = if session.history.is_dirty() {
                    ExportText::ExportedUnsaved
                } else {
                    ExportText::Exported
                };
                let objects = session.project.application.objects().len().to_string();
                StatusMessage::info(text.fill(
                    language,
                    &[("file", &file_name(path)), ("objects", &objects)],
                ))
            }
            Err(error) => StatusMessage::error(format!("{failed}: {error}")),
        };
        self.report(message);
    }
}

/// The file name proposed for the export of the project titled `title`: the title with `.xml`,
/// characters that file names cannot hold replaced by `_`.
fn proposed_file_name(title: &str) -> String {
    let stem: String = title
        .trim()
        .chars()
        .map(|c| {
            if NOT_IN_FILE_NAMES.contains(&c) || c.is_control() {
                '_'
            } else {
                c
            }
        })
        .collect();
    let stem = if stem.is_empty() { "project" } else { &stem };
    format!("{stem}.xml")
}

/// The file's name without its folders, for the status bar.
fn file_name(path: &Path) -> String {
    path.file_name()
        .map(|name| name.to_string_lossy().into_owned())
        .unwrap_or_else(|| path.display().to_string())
}

#[cfg(test)]
mod tests {
    use super::proposed_file_name;

    #[test]
    fn the_proposed_name_is_the_title_with_xml_and_no_separators() {
        assert_eq!(
            proposed_file_name("Packaging machine"),
            "Packaging machine.xml"
        );
        assert_eq!(proposed_file_name("Line 2/3: A<B>"), "Line 2_3_ A_B_.xml");
        assert_eq!(proposed_file_name("  "), "project.xml");
    }
}
