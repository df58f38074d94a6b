//! The one place where commands are applied: after the frame's UI, in the order they were
//! emitted, so the project and the online state never change while they are drawn.

use std::path::Path;

use super::state::Studio;
use crate::studio::command::Command;
use crate::studio::debug::{Breakpoints, DebugCommand};
use crate::studio::dock::Dock;
use crate::studio::documents::close_stale_documents;
use crate::studio::i18n::{ImportText, Text};
use crate::studio::pane::Pane;
use crate::studio::status::StatusMessage;

/// Applies every command emitted this frame (and those the commands emit in turn).
pub(super) fn apply_commands(studio: &mut Studio, dock: &mut Dock, ctx: &egui::Context) {
    save_trace_png(studio, ctx);
    let commands = studio.commands.take();
    if commands.is_empty() {
        return;
    }
    let ports_before = serial_port_names(studio);
    for command in commands {
        apply(studio, dock, command, ctx);
    }
    if let Some(session) = &studio.shared.session {
        close_stale_documents(dock, &session.project);
        studio
            .panes
            .devices
            .follow_project(&ports_before, &session.project);
    }
    // What the commands changed shows in the next frame, without waiting for input.
    ctx.request_repaint();
}

/// The names of the open project's serial ports, in order (none without a project).
fn serial_port_names(studio: &Studio) -> Vec<String> {
    studio
        .shared
        .session
        .as_ref()
        .map_or_else(Vec::new, |session| {
            let ports = &session.project.serial_ports;
            ports.iter().map(|port| port.name.clone()).collect()
        })
}

fn apply(studio: &mut Studio, dock: &mut Dock, command: Command, ctx: &egui::Context) {
    let language = studio.shared.settings.language;
    match command {
        Command::Open(node) => {
            studio.shared.selection = Some(node.clone());
            dock.open_document(node);
        }
        Command::Reveal(node, reveal) => {
            studio.shared.selection = Some(node.clone());
            studio.panes.texts.reveal = Some((node.clone(), reveal));
            dock.open_document(node);
        }
        Command::Select(node) => studio.shared.selection = node,
        Command::ShowPane(pane) => dock.show(&pane),
        Command::FindReferences(target, offset) => {
            studio.find_references(&target, offset);
            dock.show(&Pane::Messages);
        }
        Command::ResetLayout => {
            let open = dock.documents();
            *dock = Dock::default();
            for node in open {
                dock.open_document(node);
            }
        }
        Command::OpenDialog => {
            if let Some(dir) = rfd::FileDialog::new()
                .set_title(Text::OpenProjectFolder.get(language))
                .pick_folder()
            {
                studio.open_project(dock, &dir);
            }
        }
        Command::SaveAsDialog => {
            if let Some(dir) = rfd::FileDialog::new()
                .set_title(Text::SaveProjectIntoFolder.get(language))
                .pick_folder()
            {
                studio.save_as(&dir);
            }
        }
        Command::ImportPlcopenDialog => {
            if let Some(path) = rfd::FileDialog::new()
                .set_title(ImportText::PickFile.get(language))
                .add_filter(ImportText::FileFilter.get(language), &["xml"])
                .pick_file()
            {
                studio.open_import(path);
            }
        }
        Command::ImportIntoProject => studio.import_into_project(),
        Command::ImportAsNewProjectDialog => {
            if let Some(dir) = rfd::FileDialog::new()
                .set_title(ImportText::PickFolder.get(language))
                .pick_folder()
            {
                studio.import_as_new_project(dock, &dir);
            }
        }
        Command::CloseImport => studio.import = None,
        Command::ExportPlcopenDialog => studio.export_plcopen_dialog(),
        Command::Save => studio.save(),
        Command::Quit => ctx.send_viewport_cmd(egui::ViewportCommand::Close),
        Command::Undo | Command::Redo => studio.undo_redo(command == Command::Undo),
        Command::Build => studio.start_build(),
        Command::Login => studio.login(ctx),
        Command::Logout => {
            studio.shared.online.logout();
            studio.shared.debug.end_session();
        }
        // F5 continues a halted task and starts a stopped program (`docs/debugging.md` §4).
        Command::Start if studio.shared.debug.is_halted() => studio.debug(DebugCommand::Continue),
        Command::Start => studio.shared.online.start(),
        Command::Stop => studio.shared.online.stop(),
        Command::Reset(kind) => studio.shared.online.reset(kind),
        Command::ConfirmDownload => studio.shared.online.confirm_download(),
        Command::CancelDownload => studio.shared.online.cancel_download(),
        Command::ChooseLogin(choice) => studio.shared.online.choose_login(choice),
        Command::WriteValues(values) => {
            if let Err(refused) = studio.shared.online.write(&values)
                && let Some((path, reason)) = refused.first()
            {
                let message = StatusMessage::error(format!("{path}: {reason}"));
                studio.report(message);
            }
        }
        Command::ToggleExecutionOrder => studio.panes.texts.graphical.toggle_execution_order(),
        Command::WritePrepared | Command::ForcePrepared => {
            write_prepared(studio, command == Command::WritePrepared);
        }
        Command::ReleaseAllForces => studio.shared.online.unforce_all(),
        Command::Unforce(source) => studio.shared.online.unforce(&source),
        Command::StartTrace(config) => studio.shared.online.trace_start(&config),
        Command::UploadTrace => studio.shared.online.trace_upload(),
        Command::ExportTraceCsv => export_trace_csv(studio),
        Command::ExportTracePng(rect) => {
            studio.panes.trace_view.request_png(ctx, rect);
        }
        Command::ImportCamCsv(name) => import_cam_csv(studio, &name),
        Command::ExportCamCsv(name) => export_cam_csv(studio, &name),
        Command::Edit(label, edits) => studio.apply_edits(&label, edits),
        Command::EditText {
            label,
            edits,
            merge_key,
        } => studio.apply_text(&label, edits, merge_key.as_deref()),
        Command::Report(message) => studio.report(message),
        Command::ClearMessages => {
            studio.shared.online_messages.clear();
            studio.shared.problems.clear();
        }
        Command::SetLanguage(language) => studio.shared.settings.language = language,
        Command::SetTheme(theme) => {
            studio.shared.settings.theme = theme;
            ctx.set_theme(theme.egui_theme());
        }
        Command::SetTarget(target) => studio.shared.settings.target = target,
        Command::ToggleBreakpoint(place) => studio.toggle_breakpoint(place),
        Command::ToggleBreakpointAtCaret => {
            if let Some(place) = studio.caret_place() {
                studio.toggle_breakpoint(place);
            }
        }
        Command::UpdateBreakpoint(breakpoint) => {
            studio.change_breakpoints(|breakpoints| breakpoints.update(breakpoint));
        }
        Command::RemoveBreakpoint(place) => {
            studio.change_breakpoints(|breakpoints| breakpoints.remove(&place));
        }
        Command::RemoveAllBreakpoints => studio.change_breakpoints(Breakpoints::clear),
        Command::Debug(command) => studio.debug(command),
        Command::RunToCaret => {
            if let Some(place) = studio.caret_place() {
                studio.debug(DebugCommand::RunToCursor(place));
            }
        }
        Command::ShowFrame(task, frame) => {
            if let Some(open) = studio.show_frame(&task, frame) {
                apply(studio, dock, open, ctx);
            }
        }
    }
}

/// Writes (or forces) the prepared values of the watch list and of the editors' inline boxes.
fn write_prepared(studio: &mut Studio, write: bool) {
    let mut prepared = studio
        .panes
        .watch
        .prepared_values(studio.shared.session.as_ref());
    // Values prepared in an editor's inline boxes go too, and are used up as CODESYS uses them
    // up.
    prepared.extend(std::mem::take(&mut studio.panes.texts.inline.prepared));
    let result = if write {
        studio.shared.online.write(&prepared)
    } else {
        studio.shared.online.force(&prepared)
    };
    studio.panes.watch.refused = result.err().unwrap_or_default();
    if let Some((path, reason)) = studio.panes.watch.refused.first() {
        let message = StatusMessage::error(format!("{path}: {reason}"));
        studio.report(message);
    }
}

/// Asks for a file and writes the trace plot's data to it as CSV.
fn export_trace_csv(studio: &mut Studio) {
    let language = studio.shared.settings.language;
    let name = studio.shared.online.trace().name();
    let name = if name.is_empty() { "trace" } else { name };
    if let Some(path) = rfd::FileDialog::new()
        .set_title(Text::ExportTraceCsv.get(language))
        .add_filter("CSV", &["csv"])
        .set_file_name(format!("{name}.csv"))
        .save_file()
    {
        let csv = studio.panes.trace_view.csv();
        report_export(studio, std::fs::write(&path, csv), &path);
    }
}

/// Saves the plot area of a screenshot that arrived for a PNG export, asking for the file.
fn save_trace_png(studio: &mut Studio, ctx: &egui::Context) {
    let Some(png) = studio.panes.trace_view.take_png(ctx.pixels_per_point()) else {
        return;
    };
    let language = studio.shared.settings.language;
    match png {
        Ok(png) => {
            let name = studio.shared.online.trace().name();
            let name = if name.is_empty() { "trace" } else { name };
            if let Some(path) = rfd::FileDialog::new()
                .set_title(Text::ExportTracePng.get(language))
                .add_filter("PNG", &["png"])
                .set_file_name(format!("{name}.png"))
                .save_file()
            {
                report_export(studio, std::fs::write(&path, png), &path);
            }
        }
        Err(error) => studio.report(StatusMessage::error(format!(
            "{}: {error}",
            Text::PngExport.get(language)
        ))),
    }
}

fn report_export(studio: &mut Studio, result: std::io::Result<()>, path: &Path) {
    let language = studio.shared.settings.language;
    let message = match result {
        Ok(()) => StatusMessage::info(format!(
            "{} {}",
            Text::Exported.get(language),
            path.display()
        )),
        Err(error) => StatusMessage::error(format!("{}: {error}", path.display())),
    };
    studio.report(message);
}

/// The cam table `name` of the open project, copied.
fn cam_named(studio: &Studio, name: &str) -> Option<project_model::CamTable> {
    match studio
        .shared
        .session
        .as_ref()?
        .project
        .application
        .object(name)
    {
        Some(project_model::Object::CamTable(cam)) => Some(cam.clone()),
        _ => None,
    }
}

/// Asks for a CSV file and replaces the points of the cam `name` by its points, as one undo
/// step; a read or parse error goes to the status bar with the file and the line.
fn import_cam_csv(studio: &mut Studio, name: &str) {
    let language = studio.shared.settings.language;
    let Some(cam) = cam_named(studio, name) else {
        return;
    };
    let Some(path) = rfd::FileDialog::new()
        .set_title(Text::CamImportPoints.get(language))
        .add_filter("CSV", &["csv"])
        .pick_file()
    else {
        return;
    };
    match crate::studio::cam_documents::import_csv_file(&cam, &path, language) {
        Ok((label, edits, message)) => {
            studio.report(message);
            studio.apply_edits(&label, edits);
        }
        Err(message) => studio.report(message),
    }
}

/// Asks for a file and writes the points of the cam `name` to it as CSV.
fn export_cam_csv(studio: &mut Studio, name: &str) {
    let language = studio.shared.settings.language;
    let Some(cam) = cam_named(studio, name) else {
        return;
    };
    if let Some(path) = rfd::FileDialog::new()
        .set_title(Text::CamExportPoints.get(language))
        .add_filter("CSV", &["csv"])
        .set_file_name(format!("{name}.csv"))
        .save_file()
    {
        let message = crate::studio::cam_documents::export_csv_file(&cam, &path, language);
        studio.report(message);
    }
}
