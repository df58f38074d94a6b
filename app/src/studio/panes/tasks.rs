//! The tasks pane: each task's cycle statistics as the target reports them, and the fault log,
//! whose entries open the faulting POU.

use egui::{RichText, Ui};

use crate::studio::i18n::Text;
use crate::studio::studio_app::{Command, Studio};
use crate::studio::tree_node::TreeNode;

pub(crate) fn tasks_ui(studio: &mut Studio, ui: &mut Ui) {
    let language = studio.settings.language;
    if !studio.online.is_online() {
        ui.label(RichText::new(Text::NotOnline.get(language)).weak());
        return;
    }
    let micros = |ns: u64| format!("{:.1}", ns as f64 / 1000.0);
    egui::Grid::new("task_statistics")
        .num_columns(6)
        .striped(true)
        .spacing([16.0, 4.0])
        .show(ui, |ui| {
            for header in [
                Text::Task,
                Text::Cycles,
                Text::LastCycle,
                Text::AverageCycle,
                Text::MaxCycle,
                Text::Jitter,
            ] {
                ui.strong(header.get(language));
            }
            ui.end_row();
            for task in studio.online.tasks() {
                let name = RichText::new(&task.name).monospace();
                ui.label(if task.faulted {
                    name.color(ui.visuals().error_fg_color)
                } else {
                    name
                });
                ui.label(task.cycles.to_string());
                ui.label(micros(task.last_ns));
                ui.label(micros(task.average_ns));
                ui.label(micros(task.max_ns));
                ui.label(micros(task.jitter_max_ns));
                ui.end_row();
            }
        });
    ui.separator();
    ui.strong(Text::Faults.get(language));
    let faults = studio.online.faults();
    if faults.is_empty() {
        ui.label(RichText::new(Text::NoFaults.get(language)).weak());
        return;
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
                    open = Some(fault.pou.clone());
                }
            }
        });
    if let Some(pou) = open {
        // The POU of a method or action is named `FB.Method`; the document is the POU's.
        let object = pou.split('.').next().unwrap_or(&pou).to_owned();
        studio.pending.push(Command::Open(TreeNode::Object(object)));
    }
}
