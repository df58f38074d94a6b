//! The tasks pane: each task's cycle statistics as the target reports them, and the fault log,
//! whose entries open the faulting POU.

use egui::{RichText, Ui};

use crate::studio::i18n::Text;
use crate::studio::studio_app::{Command, Studio};
use crate::studio::text_documents::Reveal;
use crate::studio::tree_node::TreeNode;

pub(crate) fn tasks_ui(studio: &mut Studio, ui: &mut Ui) {
    let language = studio.settings.language;
    if !studio.online.is_online() {
        ui.label(RichText::new(Text::NotOnline.get(language)).weak());
        return;
    }
    // Cycle times on the left, where people look; the fault log on the right.
    let width = ui.available_width();
    let height = ui.available_height();
    let mut open = None;
    ui.horizontal_top(|ui| {
        ui.allocate_ui(egui::vec2(width * 0.62, height), |ui| {
            super::super::cycle_plot::cycle_plot_ui(ui, &studio.cycle_history, language);
        });
        ui.separator();
        ui.vertical(|ui| open = faults_ui(studio, ui));
    });
    if let Some((pou, file, line)) = open {
        studio.pending.push(fault_place(studio, &pou, &file, line));
    }
}

/// Where a fault happened: its source line when the body is known, else its POU.
fn fault_place(studio: &Studio, pou: &str, file: &str, line: u32) -> Command {
    // The POU of a method or action is named `FB.Method`; the document is the POU's.
    let object = pou.split('.').next().unwrap_or(pou).to_owned();
    let node = TreeNode::Object(object);
    let body = studio.session.as_ref().and_then(|session| {
        project_model::st_body_files(&session.project)
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
fn faults_ui(studio: &Studio, ui: &mut Ui) -> Option<(String, String, u32)> {
    let language = studio.settings.language;
    ui.strong(Text::Faults.get(language));
    let faults = studio.online.faults();
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
