//! The Call stack pane: the frames of each halted task (and of a task waiting beneath one),
//! innermost first; a click shows the frame and opens its POU at its line. A frame in a
//! graphical body names its network, element, step or transition rather than the line of the
//! text the body was compiled from.

use egui::{RichText, Ui};

use crate::studio::command::{Command, Commands};
use crate::studio::debug::{Beneath, GraphicalPlace, StackFrame};
use crate::studio::graphical_documents::GraphicalDocuments;
use crate::studio::i18n::DebugText;
use crate::studio::view::StudioView;

use super::breakpoints::graphical_place_text;

/// The Call stack pane; `graphical` finds the element a graphical body's line comes from.
pub(crate) fn call_stack_ui(
    view: StudioView<'_>,
    graphical: &mut GraphicalDocuments,
    commands: &mut Commands,
    ui: &mut Ui,
) {
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
                    let text = frame_text(view, graphical, frame);
                    let selected = shown == Some((task.task.as_str(), index));
                    if ui.selectable_label(selected, text).clicked() {
                        commands.push(Command::ShowFrame(task.task.clone(), index));
                    }
                }
            }
        });
}

/// The frame as the pane lists it: who runs (the instance, or the function), the POU when
/// that is not the same name, and where: the network, element, step or transition of a
/// graphical body (which names the body itself), or the file and line of a textual one.
fn frame_text(
    view: StudioView<'_>,
    graphical: &mut GraphicalDocuments,
    frame: &StackFrame,
) -> String {
    let who = frame.instance.as_deref().unwrap_or(&frame.pou);
    let place = view.session.and_then(|session| {
        graphical.place_of_line(
            &session.project,
            session.history.revision(),
            &frame.file,
            frame.line,
        )
    });
    match place {
        Some((target, place)) => {
            let place = graphical_place_text(
                view.language,
                view.project(),
                &GraphicalPlace::of_editor(&target, place),
            );
            if who == frame.pou {
                place
            } else {
                format!("{who} {place}")
            }
        }
        None if who == frame.pou => format!("{who} {}:{}", frame.file, frame.line),
        None => format!("{who} ({}) {}:{}", frame.pou, frame.file, frame.line),
    }
}
