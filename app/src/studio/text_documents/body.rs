//! The implementation of a POU part in its editor (ST text here, LD and FBD networks in
//! `graphical_documents`), with live diagnostics, completion, hover, go to definition, find
//! references and values inline while online.

use editor::Gesture;
use egui::{RichText, Ui};
use project_model::{Body, Edit};

use crate::studio::command::{Command, Commands};
use crate::studio::debug::BreakpointPlace;
use crate::studio::i18n::Text;
use crate::studio::reveal::Reveal;
use crate::studio::tree_node::TreeNode;
use crate::studio::view::StudioView;

use crate::studio::graphical_documents::{
    ChartShown, GraphicalShown, cfc_body_ui, graphical_body_ui, sfc_body_ui,
};

use super::diagnostics::body_diagnostics;
use super::documents::{TextDocuments, TextKey};
use super::frame_inline;
use super::inline::instance_of;
use super::live_check;
use super::part::{Shown, body_of, target_label};
use super::services::BodyServices;

/// The implementation of the POU part, with live diagnostics, completion, hover, F12, Shift+F12
/// and values inline while online.
pub(super) fn body_ui(
    view: StudioView<'_>,
    texts: &mut TextDocuments,
    commands: &mut Commands,
    ui: &mut Ui,
    shown: Shown<'_>,
) {
    let Shown { pou, part, reveal } = shown;
    let language = view.language;
    let Some((target, body)) = body_of(pou, part) else {
        ui.label(RichText::new(Text::NoImplementation.get(language)).weak());
        return;
    };
    let Some(session) = view.session else {
        return;
    };
    let project = &session.project;
    let revision = session.history.revision();
    let Some(text) = body.text() else {
        match body {
            Body::None => {
                ui.label(RichText::new(Text::NoImplementation.get(language)).weak());
            }
            Body::Ld { networks } | Body::Fbd { networks } => {
                if texts.live.update(project, &pou.name, revision) {
                    ui.ctx().request_repaint_after(live_check::CHECK_DELAY);
                }
                let reveal = match reveal {
                    Some(Reveal::Element {
                        network, element, ..
                    }) => Some((*network, *element)),
                    _ => None,
                };
                let shown = GraphicalShown {
                    pou,
                    target: &target,
                    networks,
                    language: body.language(),
                    label: &target_label(&target),
                    findings: texts
                        .live
                        .findings(&pou.name)
                        .map(|(_, found)| found.as_slice()),
                    instance: view
                        .online
                        .is_online()
                        .then(|| instance_of(project, pou))
                        .flatten(),
                    reveal,
                };
                let paths = graphical_body_ui(
                    view,
                    &mut texts.graphical,
                    &mut texts.inline.prepared,
                    commands,
                    ui,
                    shown,
                );
                for path in paths {
                    texts.inline.show(path);
                }
            }
            Body::Cfc { .. } | Body::Sfc { .. } => {
                if texts.live.update(project, &pou.name, revision) {
                    ui.ctx().request_repaint_after(live_check::CHECK_DELAY);
                }
                let shown = ChartShown {
                    pou,
                    target: &target,
                    label: &target_label(&target),
                    findings: texts
                        .live
                        .findings(&pou.name)
                        .map(|(_, found)| found.as_slice()),
                    instance: view
                        .online
                        .is_online()
                        .then(|| instance_of(project, pou))
                        .flatten(),
                    reveal: match reveal {
                        Some(Reveal::Element { element, .. }) => *element,
                        _ => None,
                    },
                };
                let paths = match body {
                    Body::Cfc { chart } => cfc_body_ui(
                        view,
                        &mut texts.graphical,
                        &mut texts.inline.prepared,
                        commands,
                        ui,
                        shown,
                        chart,
                    ),
                    Body::Sfc { chart } => {
                        sfc_body_ui(view, &mut texts.graphical, commands, ui, shown, chart)
                    }
                    _ => Vec::new(),
                };
                for path in paths {
                    texts.inline.show(path);
                }
            }
            // An ST or IL body has its text, drawn below.
            Body::St { .. } | Body::Il { .. } => {}
        }
        if let Some(place) = texts.graphical.focused_place.take() {
            texts.last_caret = Some(place);
        }
        return;
    };
    if texts.live.update(project, &pou.name, revision) {
        ui.ctx().request_repaint_after(live_check::CHECK_DELAY);
    }
    let diagnostics = body_diagnostics(&texts.live, project, &pou.name, &target);
    let instruction_list = matches!(body, Body::Il { .. });
    let inline = if view.online.is_online() {
        // While halted in this POU (or a method or action of it), its values are the halted
        // frame's instance's; a halted function's or method's locals come from its frame.
        let shown = view.debug.shown_frame();
        let halted = shown
            .filter(|frame| {
                let owner = frame
                    .pou
                    .split_once('.')
                    .map_or(&*frame.pou, |(owner, _)| owner);
                owner.eq_ignore_ascii_case(&pou.name)
            })
            .and_then(|frame| frame.instance.as_deref());
        let mut values = texts
            .inline
            .values_for(view.online, project, &target, text, pou, halted);
        let in_frame = shown.is_some_and(|frame| {
            frame_inline::image_name(&target)
                .is_some_and(|name| name.eq_ignore_ascii_case(&frame.pou))
        });
        if in_frame {
            values.extend(frame_inline::frame_inline_values(
                text,
                view.online.frame_locals(),
            ));
            values.sort_by_key(|value| value.range.start);
        }
        values
    } else {
        texts.inline.forget(&target);
        Vec::new()
    };
    let read_only = view.online.is_logged_in();
    let key = TextKey::Body(target.clone());
    let text = text.to_owned();
    let label = Text::ImplementationOf.fill(view.language, &[("name", &target_label(&target))]);
    let services = BodyServices {
        project,
        target: target.clone(),
    };
    let entry = if instruction_list {
        texts.instruction_list_editor(key, &text)
    } else {
        texts.editor(key, &text)
    };
    entry.editor.set_read_only(read_only);
    if let Some(diagnostics) = diagnostics {
        entry.editor.set_diagnostics(diagnostics);
    }
    entry.editor.set_inline_values(inline);
    let file = body_file(project, &target);
    if let Some(file) = &file {
        let marks = match view.breakpoints() {
            Some(breakpoints) => view.debug.marks_for(file, breakpoints),
            None => view
                .debug
                .marks_for(file, &crate::studio::debug::Breakpoints::default()),
        };
        entry.editor.set_debug_marks(marks);
    }
    if let Some(Reveal::Body(_, range)) = reveal {
        entry.editor.reveal(range.clone());
        entry.editor.request_focus();
    }
    let output = entry.editor.show(ui, &label, &services);
    let caret_line = entry.editor.caret_line();
    if let Some(offset) = output.goto_definition {
        match compiler::ide::definition(project, &target, offset) {
            Some(definition) => {
                let object = definition.object.clone().unwrap_or_default();
                if object.is_empty() {
                    commands.status(
                        Text::InStandardLibrary
                            .get(language)
                            .replace("{name}", &definition.name),
                    );
                } else {
                    commands.push(Command::Reveal(
                        TreeNode::Object(object),
                        Reveal::Declaration {
                            container: definition.container.clone(),
                            name: definition.name.clone(),
                        },
                    ));
                }
            }
            None => commands.status(Text::NoDeclarationAtCaret.get(language)),
        }
    }
    if let Some(file) = file {
        let caret_place = |line: usize| BreakpointPlace::text(file.clone(), line as u32 + 1);
        if output.response.has_focus() {
            texts.last_caret = Some(caret_place(caret_line));
        }
        if let Some(line) = output.toggle_breakpoint {
            commands.push(Command::ToggleBreakpoint(caret_place(line)));
        }
    }
    if let Some(offset) = output.find_references {
        commands.push(Command::FindReferences(target.clone(), offset));
    }
    if let Some((range, value)) = output.prepared {
        texts.inline.prepare(&target, range, value);
    }
    if !output.changes.is_empty() {
        let edits = output
            .changes
            .into_iter()
            .map(|change| Edit::ReplaceText {
                target: target.clone(),
                range: change.range,
                text: change.text,
            })
            .collect();
        let merge_key = match output.gesture {
            Some(Gesture::Typing { run }) => Some(format!("{target:?} {run}")),
            _ => None,
        };
        commands.push(Command::EditText {
            label: Text::UndoEdit.fill(view.language, &[("name", &target_label(&target))]),
            edits,
            merge_key,
        });
    }
}

/// The file of the Structured Text or IL body `target`, as the image's line table names it
/// (`application/Main.st`, `application/Main.il`), or `None` when the project has no such body.
fn body_file(
    project: &project_model::Project,
    target: &project_model::TextTarget,
) -> Option<String> {
    project_model::text_body_files(project)
        .into_iter()
        .find(|body| &body.target == target)
        .map(|body| body.file.to_string_lossy().replace('\\', "/"))
}
