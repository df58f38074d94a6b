//! The preview of File ▸ Import PLCopen XML… (`docs/plcopen-xml.md` §6.2): what the file holds,
//! the import report, and the plan against the open project with a skip or replace choice per
//! clash, before anything changes.

use std::path::PathBuf;

use egui::{RichText, ScrollArea, Ui};
use plcopen::{Outcome, ReportEntry};
use project_model::{ClashChoice, IgnoredPart, MergeItem, MergePlan, ObjectKind, Project};

use super::i18n::{ImportText, Language, Text};
use crate::plcopen_import::{ImportFailure, ImportedFile, import_file, outcome_counts};

/// The dialog's width in points: room for an element path and a note on one line.
const DIALOG_WIDTH: f32 = 760.0;
/// The height of the report before it scrolls, in points.
const REPORT_HEIGHT: f32 = 220.0;
/// The height of each list of the plan before it scrolls, in points.
const PLAN_LIST_HEIGHT: f32 = 120.0;

/// The open preview of an import.
pub(crate) struct ImportDialog {
    /// The file chosen.
    pub(crate) path: PathBuf,
    /// The file read and converted, or why it could not be (`FILE:LINE:COLUMN: PATH: message`).
    pub(crate) outcome: Result<ImportedFile, ImportFailure>,
    /// The plan against the project open when the dialog opened; `None` without a project.
    pub(crate) plan: Option<MergePlan>,
    /// Why the last attempt to write a new project failed, shown until the next attempt.
    pub(crate) error: Option<String>,
}

/// What the user chose in the dialog.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum ImportAction {
    /// Apply the plan to the open project.
    IntoProject,
    /// Ask for an empty folder and write the imported project there.
    AsNewProject,
    /// Close the dialog; nothing changes.
    Close,
}

impl ImportDialog {
    /// Reads and converts `path`, and plans its merge into `project` when one is open.
    pub(crate) fn open(path: PathBuf, project: Option<&Project>) -> Self {
        let outcome = import_file(&path);
        let plan = match (&outcome, project) {
            (Ok(file), Some(project)) => Some(MergePlan::new(project, &file.imported.project)),
            _ => None,
        };
        Self {
            path,
            outcome,
            plan,
            error: None,
        }
    }

    /// Draws the dialog; gives the user's choice when a button was pressed.
    pub(crate) fn ui(&mut self, ctx: &egui::Context, language: Language) -> Option<ImportAction> {
        let modal = egui::Modal::new(egui::Id::unique("import_plcopen_dialog")).show(ctx, |ui| {
            ui.set_width(DIALOG_WIDTH);
            ui.heading(ImportText::Title.get(language));
            ui.label(RichText::new(self.path.display().to_string()).monospace());
            ui.add_space(4.0);
            match &self.outcome {
                Ok(file) => {
                    summary_ui(ui, language, file);
                    ui.separator();
                    report_ui(ui, language, file);
                    ui.separator();
                    match &mut self.plan {
                        Some(plan) => plan_ui(ui, language, plan),
                        None => {
                            ui.label(ImportText::NoProject.get(language));
                        }
                    }
                }
                Err(error) => {
                    ui.colored_label(
                        ui.visuals().error_fg_color,
                        ImportText::Failed.get(language),
                    );
                    ui.label(RichText::new(error.to_string()).monospace());
                }
            }
            if let Some(error) = &self.error {
                ui.add_space(4.0);
                ui.colored_label(ui.visuals().error_fg_color, error);
            }
            ui.separator();
            buttons_ui(ui, language, self.outcome.is_ok(), self.plan.is_some())
        });
        modal
            .inner
            .or_else(|| modal.should_close().then_some(ImportAction::Close))
    }
}

/// The format, the tool and the counts of what the file declares.
fn summary_ui(ui: &mut Ui, language: Language, file: &ImportedFile) {
    let summary = &file.summary;
    let product = if summary.product.is_empty() {
        ImportText::UnnamedTool.get(language)
    } else {
        &summary.product
    };
    ui.label(ImportText::Source.fill(
        language,
        &[("format", summary.dialect_name()), ("product", product)],
    ));
    ui.label(ImportText::Counts.fill(
        language,
        &[
            ("types", &summary.data_types.to_string()),
            ("pous", &summary.pous.to_string()),
            ("configurations", &summary.configurations.to_string()),
            ("tasks", &summary.tasks.to_string()),
        ],
    ));
}

/// The report's counts and its entries, one row each, scrolling.
fn report_ui(ui: &mut Ui, language: Language, file: &ImportedFile) {
    let [converted, kept, not_converted] = outcome_counts(&file.imported);
    ui.strong(ImportText::ReportHeading.get(language));
    ui.label(ImportText::ReportCounts.fill(
        language,
        &[
            ("converted", &converted.to_string()),
            ("kept", &kept.to_string()),
            ("not", &not_converted.to_string()),
        ],
    ));
    let entries = &file.imported.report.entries;
    // A horizontal row is as tall as an interactive widget.
    let row_height = ui.spacing().interact_size.y;
    ScrollArea::vertical()
        .id_salt("import_report")
        .max_height(REPORT_HEIGHT)
        .auto_shrink([false, true])
        .show_rows(ui, row_height, entries.len(), |ui, rows| {
            for entry in &entries[rows] {
                entry_ui(ui, language, &file.summary.file, entry);
            }
        });
}

/// One report entry: outcome, what, `file:line` and the note.
fn entry_ui(ui: &mut Ui, language: Language, file: &str, entry: &ReportEntry) {
    let (word, color) = match entry.outcome {
        Outcome::Converted => (ImportText::Converted, ui.visuals().text_color()),
        Outcome::KeptOpaque => (ImportText::Kept, ui.visuals().weak_text_color()),
        Outcome::NotConverted => (ImportText::NotConverted, ui.visuals().warn_fg_color),
    };
    ui.horizontal(|ui| {
        ui.colored_label(color, word.get(language));
        ui.label(&entry.what);
        let place = format!("{}:{}", short_name(file), entry.line);
        ui.label(RichText::new(place).weak())
            .on_hover_text(&entry.path);
        if !entry.note.is_empty() {
            // A long note is cut at the dialog's edge rather than widening it; the whole note
            // shows on hover.
            ui.add(egui::Label::new(RichText::new(&entry.note).weak()).truncate())
                .on_hover_text(&entry.note);
        }
    });
}

/// The file name without its folders, which the dialog shows once above.
fn short_name(file: &str) -> &str {
    file.rsplit(['/', '\\']).next().unwrap_or(file)
}

/// What the merge adds, what clashes (each with its choice), and what the project keeps.
fn plan_ui(ui: &mut Ui, language: Language, plan: &mut MergePlan) {
    ui.strong(ImportText::PlanHeading.get(language));
    if plan.additions.is_empty() {
        ui.label(ImportText::NothingAdded.get(language));
    } else {
        let count = plan.additions.len().to_string();
        ui.label(ImportText::Added.fill(language, &[("count", &count)]));
        // Only the visible rows are laid out: a large file adds thousands of things.
        let row_height = ui.text_style_height(&egui::TextStyle::Body);
        let additions = &plan.additions;
        ScrollArea::vertical()
            .id_salt("import_additions")
            .max_height(PLAN_LIST_HEIGHT)
            .auto_shrink([false, true])
            .show_rows(ui, row_height, additions.len(), |ui, rows| {
                for item in &additions[rows] {
                    ui.label(format!("+ {}", item_text(language, item)));
                }
            });
    }
    if !plan.clashes.is_empty() {
        ui.add_space(4.0);
        let count = plan.clashes.len().to_string();
        ui.label(ImportText::Clashes.fill(language, &[("count", &count)]));
        let row_height = ui.spacing().interact_size.y;
        let rows_count = plan.clashes.len();
        ScrollArea::vertical()
            .id_salt("import_clashes")
            .max_height(PLAN_LIST_HEIGHT)
            .auto_shrink([false, true])
            .show_rows(ui, row_height, rows_count, |ui, rows| {
                for clash in &mut plan.clashes[rows] {
                    ui.horizontal(|ui| {
                        ui.radio_value(
                            &mut clash.choice,
                            ClashChoice::Skip,
                            ImportText::Skip.get(language),
                        );
                        ui.radio_value(
                            &mut clash.choice,
                            ClashChoice::Replace,
                            ImportText::Replace.get(language),
                        );
                        ui.label(item_text(language, &clash.imported));
                        let existing = item_text(language, &clash.existing);
                        ui.label(
                            RichText::new(
                                ImportText::ClashesWith.fill(language, &[("existing", &existing)]),
                            )
                            .weak(),
                        );
                    });
                }
            });
    }
    if !plan.ignored.is_empty() {
        ui.add_space(4.0);
        let parts: Vec<&str> = plan
            .ignored
            .iter()
            .map(|part| part_text(*part).get(language))
            .collect();
        ui.label(
            RichText::new(
                ImportText::KeptFromProject.fill(language, &[("parts", &parts.join(", "))]),
            )
            .weak(),
        );
    }
}

/// The three buttons; those that cannot act are disabled.
fn buttons_ui(
    ui: &mut Ui,
    language: Language,
    imported: bool,
    has_project: bool,
) -> Option<ImportAction> {
    let mut action = None;
    ui.horizontal(|ui| {
        let into = egui::Button::new(ImportText::IntoProject.get(language));
        if ui.add_enabled(imported && has_project, into).clicked() {
            action = Some(ImportAction::IntoProject);
        }
        let new = egui::Button::new(ImportText::AsNewProject.get(language));
        if ui.add_enabled(imported, new).clicked() {
            action = Some(ImportAction::AsNewProject);
        }
        if ui.button(Text::Cancel.get(language)).clicked() {
            action = Some(ImportAction::Close);
        }
    });
    action
}

/// A plan item in the interface language: `POU Main`, `task Fast`, `call of Main by task Fast`.
pub(crate) fn item_text(language: Language, item: &MergeItem) -> String {
    match item {
        MergeItem::Object { kind, name } => {
            format!("{} {name}", kind_text(*kind).get(language))
        }
        MergeItem::Task { name } => ImportText::ItemTask.fill(language, &[("name", name)]),
        MergeItem::ProgramCall { task, program } => {
            ImportText::ItemCall.fill(language, &[("program", program), ("task", task)])
        }
    }
}

fn kind_text(kind: ObjectKind) -> ImportText {
    match kind {
        ObjectKind::Pou => ImportText::KindPou,
        ObjectKind::Gvl => ImportText::KindGvl,
        ObjectKind::DataType => ImportText::KindDataType,
        ObjectKind::CamTable => ImportText::KindCam,
        ObjectKind::Trace => ImportText::KindTrace,
        ObjectKind::WatchList => ImportText::KindWatchList,
    }
}

fn part_text(part: IgnoredPart) -> ImportText {
    match part {
        IgnoredPart::ProjectInfo => ImportText::PartProjectInfo,
        IgnoredPart::Controller => ImportText::PartController,
        IgnoredPart::Dialect => ImportText::PartDialect,
        IgnoredPart::IoAreas => ImportText::PartIoAreas,
        IgnoredPart::SerialPorts => ImportText::PartSerialPorts,
        IgnoredPart::ModbusDevices => ImportText::PartModbusDevices,
        IgnoredPart::Axes => ImportText::PartAxes,
    }
}
