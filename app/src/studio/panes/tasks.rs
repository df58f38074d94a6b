//! The tasks pane: each task's cycle statistics as the target reports them, and the fault log,
//! whose entries open the faulting POU.

use egui::{RichText, Ui};

use crate::studio::command::{Command, Commands};
use crate::studio::cycle_plot::cycle_plot_ui;
use crate::studio::i18n::Text;
use crate::studio::reveal::Reveal;
use crate::studio::tree_node::TreeNode;
use crate::studio::view::StudioView;

/// Draws the tasks pane; a click on a fault opens its place.
pub(crate) fn tasks_ui(view: StudioView<'_>, commands: &mut Commands, ui: &mut Ui) {
    let language = view.language;
    if !view.online.is_online() {
        ui.label(RichText::new(Text::NotOnline.get(language)).weak());
        return;
    }
    // Cycle times on the left, where people look; the fault log on the right.
    let width = ui.available_width();
    let height = ui.available_height();
    let mut open = None;
    ui.horizontal_top(|ui| {
        ui.allocate_ui(egui::vec2(width * 0.62, height), |ui| {
            cycle_plot_ui(ui, view.cycle_history, language);
        });
        ui.separator();
        ui.vertical(|ui| open = faults_ui(view, ui));
    });
    if let Some((pou, file, line)) = open {
        commands.push(fault_place(view, &pou, &file, line));
    }
}

/// Where a fault happened (or a call stack frame is): its source line when the body is
/// known, else its POU.
pub(crate) fn fault_place(view: StudioView<'_>, pou: &str, file: &str, line: u32) -> Command {
    // The POU of a method or action is named `FB.Method`; the document is the POU's.
    let object = pou.split('.').next().unwrap_or(pou).to_owned();
    let node = TreeNode::Object(object);
    let body = view.project().and_then(|project| {
        project_model::st_body_files(project)
            .into_iter()
            .find(|body| body.file == std::path::Path::new(file))
            .map(|body| (body.target, body.text.to_owned()))
    });
    match body {
        Some((target, text)) if line > 0 => {
            let start: usize = text
                .split_inclusive('\n')
                .take(line as usize - 1)
                .map(str::len)
                .sum();
            let end = text[start.min(text.len())..]
                .find('\n')
                .map_or(text.len(), |at| start + at);
            Command::Reveal(node, Reveal::Body(target, start.min(end)..end))
        }
        _ => Command::Open(node),
    }
}

/// The fault log; returns the POU, file and line of a clicked fault.
fn faults_ui(view: StudioView<'_>, ui: &mut Ui) -> Option<(String, String, u32)> {
    let language = view.language;
    ui.strong(Text::Faults.get(language));
    let faults = view.online.faults();
    if faults.is_empty() {
        ui.label(RichText::new(Text::NoFaults.get(language)).weak());
        return None;
    }
    let mut open = None;
    egui::ScrollArea::vertical()
        .id_salt("faults")
        .auto_shrink([false, false])
        .show(ui, |ui| {
            for fault in faults {
                let place = if fault.line > 0 {
                    format!("{}:{}", fault.file, fault.line)
                } else {
                    fault.file.clone()
                };
                let text = format!(
                    "{}: {} in {} ({place}), cycle {}",
                    fault.task, fault.kind, fault.pou, fault.cycle
                );
                if ui
                    .link(RichText::new(text).color(ui.visuals().error_fg_color))
                    .clicked()
                {
                    open = Some((fault.pou.clone(), fault.file.clone(), fault.line));
                }
            }
        });
    open
}
