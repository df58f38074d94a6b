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

/// Where a fault happened (or a call stack frame or a breakpoint is): the caret at the start
/// of the statement on its source line when the body is known, else its POU.
///
/// The line table gives lines, not columns, so the statement starts at the line's first
/// character that is not blank; nothing is selected, so the editor scrolls to the line's
/// start rather than to the end of a long line, as CODESYS shows its arrow and line.
pub(crate) fn fault_place(view: StudioView<'_>, pou: &str, file: &str, line: u32) -> Command {
    // The POU of a method or action is named `FB.Method`; the document is the POU's.
    let object = pou.split('.').next().unwrap_or(pou).to_owned();
    let node = TreeNode::Object(object);
    let body = view.project().and_then(|project| {
        project_model::text_body_files(project)
            .into_iter()
            .find(|body| body.file == std::path::Path::new(file))
            .map(|body| (body.target, body.text.to_owned()))
    });
    match body {
        Some((target, text)) if line > 0 => {
            let statement = statement_start(&text, line);
            Command::Reveal(node, Reveal::Body(target, statement..statement))
        }
        _ => Command::Open(node),
    }
}

/// The byte offset of the first character of line `line` (from 1) of `text` that is not
/// blank, or the line's end when it is all blank; the text's end past its last line.
fn statement_start(text: &str, line: u32) -> usize {
    let start: usize = text
        .split_inclusive('\n')
        .take(line as usize - 1)
        .map(str::len)
        .sum::<usize>()
        .min(text.len());
    let rest = &text[start..];
    let line_text = &rest[..rest.find('\n').unwrap_or(rest.len())];
    start
        + line_text
            .find(|c: char| !c.is_whitespace())
            .unwrap_or(line_text.trim_end_matches('\r').len())
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

#[cfg(test)]
mod tests {
    use super::statement_start;

    #[test]
    fn a_statement_starts_at_its_lines_first_character_that_is_not_blank() {
        let text = "(* a comment *)\n    x := 1;\r\n\n\ty := 2;";
        assert_eq!(statement_start(text, 1), 0);
        assert_eq!(&text[statement_start(text, 2)..][..7], "x := 1;");
        // A blank line has its statement place at the line's end, on the line.
        assert_eq!(statement_start(text, 3), text.find("\n\n").unwrap() + 1);
        assert_eq!(&text[statement_start(text, 4)..], "y := 2;");
        assert_eq!(statement_start(text, 9), text.len());
    }
}
