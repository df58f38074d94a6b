//! The Call stack pane: the frames of each halted task (and of a task waiting beneath one),
//! innermost first; a click shows the frame and opens its POU at its line.

use egui::{RichText, Ui};

use crate::studio::command::{Command, Commands};
use crate::studio::debug::Beneath;
use crate::studio::i18n::DebugText;
use crate::studio::view::StudioView;

/// The Call stack pane.
pub(crate) fn call_stack_ui(view: StudioView<'_>, commands: &mut Commands, ui: &mut Ui) {
    let language = view.language;
    let halted = view.debug.halted();
    if halted.is_empty() {
        ui.label(RichText::new(DebugText::NoHaltedTask.get(language)).weak());
        return;
    }
    let shown = view.debug.shown();
    egui::ScrollArea::vertical()
        .id_salt("call_stack")
        .auto_shrink([false, false])
        .show(ui, |ui| {
            for task in halted {
                let heading = match &task.beneath {
                    Some(Beneath::Task(halted)) => DebugText::WaitingBeneath
                        .fill(language, &[("task", &task.task), ("halted", halted)]),
                    Some(Beneath::AHaltedTask) => {
                        DebugText::WaitingBeneathAHaltedTask.fill(language, &[("task", &task.task)])
                    }
                    None => DebugText::Halted.fill(language, &[("task", &task.task)]),
                };
                ui.strong(heading);
                for (index, frame) in task.frames.iter().enumerate() {
                    let who = frame.instance.as_deref().unwrap_or(&frame.pou);
                    let text = format!("{who} ({}) {}:{}", frame.pou, frame.file, frame.line);
                    let selected = shown == Some((task.task.as_str(), index));
                    if ui.selectable_label(selected, text).clicked() {
                        commands.push(Command::ShowFrame(task.task.clone(), index));
                    }
                }
            }
        });
}
