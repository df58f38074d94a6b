//! The Breakpoints pane: every breakpoint of the project, to switch on and off, edit (condition,
//! hit count, instance and task) in a small dialog, remove, and go to.

use egui::{RichText, Ui};

use crate::studio::command::{Command, Commands};
use crate::studio::debug::{Breakpoint, GraphicalPlace, HitMode, body_target};
use crate::studio::i18n::{DebugText, Language};
use crate::studio::view::StudioView;

use super::tasks::fault_place as source_place;

/// What the Breakpoints pane keeps between frames: the breakpoint being edited in the dialog.
#[derive(Default)]
pub(crate) struct BreakpointsPaneState {
    /// The dialog's copy of the breakpoint, changed as the user types; `None` when closed.
    editing: Option<Breakpoint>,
}

/// The Breakpoints pane.
pub(crate) fn breakpoints_ui(
    view: StudioView<'_>,
    state: &mut BreakpointsPaneState,
    commands: &mut Commands,
    ui: &mut Ui,
) {
    let language = view.language;
    let breakpoints = view.breakpoints().map_or(&[][..], |list| list.all());
    if breakpoints.is_empty() {
        ui.label(RichText::new(DebugText::NoBreakpoints.get(language)).weak());
    } else if ui.button(DebugText::RemoveAll.get(language)).clicked() {
        commands.push(Command::RemoveAllBreakpoints);
    }
    egui::ScrollArea::vertical()
        .id_salt("breakpoints")
        .auto_shrink([false, false])
        .show(ui, |ui| {
            for breakpoint in breakpoints {
                breakpoint_row_ui(view, state, commands, ui, breakpoint);
            }
        });
    edit_dialog_ui(language, state, commands, ui.ctx());
}

/// One breakpoint: its switch and place, what it halts on, and its buttons.
fn breakpoint_row_ui(
    view: StudioView<'_>,
    state: &mut BreakpointsPaneState,
    commands: &mut Commands,
    ui: &mut Ui,
    breakpoint: &Breakpoint,
) {
    let language = view.language;
    let place = place_text(language, view, breakpoint);
    ui.horizontal(|ui| {
        let mut enabled = breakpoint.enabled;
        if ui.checkbox(&mut enabled, place.as_str()).changed() {
            commands.push(Command::UpdateBreakpoint(Breakpoint {
                enabled,
                ..breakpoint.clone()
            }));
        }
        let summary = summary(language, breakpoint);
        if !summary.is_empty() {
            ui.label(RichText::new(summary).weak());
        }
        if ui.small_button(DebugText::GoTo.get(language)).clicked() {
            commands.push(go_to(view, breakpoint));
        }
        if ui
            .small_button(DebugText::EditBreakpoint.get(language))
            .clicked()
        {
            state.editing = Some(breakpoint.clone());
        }
        if ui.small_button(DebugText::Remove.get(language)).clicked() {
            commands.push(Command::RemoveBreakpoint(breakpoint.place.clone()));
        }
    });
    if let Some(problem) = view.online.breakpoint_problem(&breakpoint.place) {
        ui.label(RichText::new(problem).color(ui.visuals().error_fg_color));
    }
}

/// The place in words: `FILE:LINE` in text, `Interlock: network 2, element 7` in LD, FBD or
/// CFC, `PackCycle: step Fill` and `PackCycle: transition bFull` in an SFC chart.
fn place_text(language: Language, view: StudioView<'_>, breakpoint: &Breakpoint) -> String {
    match &breakpoint.place.graphical {
        Some(graphical) => graphical_place_text(language, view.project(), graphical),
        None => breakpoint.place.label(),
    }
}

/// A graphical place as the user knows it: an SFC step by its name, a transition by its
/// condition, a CFC element and an LD/FBD element by what it reads, writes or calls, an LD/FBD
/// network by its number (from 1); shared by the Breakpoints and Call stack panes.
pub(crate) fn graphical_place_text(
    language: Language,
    project: Option<&project_model::Project>,
    graphical: &GraphicalPlace,
) -> String {
    let name = &graphical.body;
    let (pou, member) = name.split_once('.').unwrap_or((name, ""));
    let body = project.and_then(|project| match project.application.object(pou) {
        Some(project_model::Object::Pou(pou)) => pou.body_named(member),
        _ => None,
    });
    let network = (graphical.network + 1).to_string();
    let Some(id) = graphical.element.map(project_model::ElementId) else {
        return DebugText::GraphicalNetwork
            .fill(language, &[("body", name), ("network", &network)]);
    };
    if let Some(project_model::Body::Sfc { chart }) = body {
        match project_model::sfc_edit::find_node(chart, id) {
            Some(project_model::SfcNode::Step(step)) => {
                return DebugText::GraphicalStep
                    .fill(language, &[("body", name), ("name", &step.name)]);
            }
            Some(project_model::SfcNode::Transition(transition)) => {
                return DebugText::GraphicalTransition.fill(
                    language,
                    &[("body", name), ("condition", &transition.condition)],
                );
            }
            _ => {}
        }
    }
    let caption = body.and_then(|body| body.element_caption(graphical.network, id));
    match (body, caption) {
        (Some(project_model::Body::Cfc { .. }), Some(caption)) => {
            DebugText::GraphicalChartElement.fill(language, &[("body", name), ("name", &caption)])
        }
        (_, Some(caption)) => DebugText::GraphicalNamedElement.fill(
            language,
            &[("body", name), ("network", &network), ("name", &caption)],
        ),
        (_, None) => DebugText::GraphicalElement.fill(
            language,
            &[
                ("body", name),
                ("network", &network),
                ("element", &id.0.to_string()),
            ],
        ),
    }
}

/// Opens the breakpoint's body at its line, network or element.
fn go_to(view: StudioView<'_>, breakpoint: &Breakpoint) -> Command {
    let place = &breakpoint.place;
    let Some(graphical) = &place.graphical else {
        let pou = pou_of_file(&place.file);
        return source_place(view, &pou, &place.file, place.line);
    };
    let pou = graphical
        .body
        .split('.')
        .next()
        .unwrap_or_default()
        .to_owned();
    let node = crate::studio::tree_node::TreeNode::Object(pou);
    match view
        .project()
        .and_then(|project| body_target(project, &graphical.body))
    {
        Some(target) => Command::Reveal(
            node,
            crate::studio::reveal::Reveal::Element {
                target,
                network: graphical.network,
                element: graphical.element.map(project_model::ElementId),
            },
        ),
        None => Command::Open(node),
    }
}

/// The condition and hit count in words, empty for a plain breakpoint.
fn summary(language: Language, breakpoint: &Breakpoint) -> String {
    let mut parts = Vec::new();
    let condition = breakpoint.condition.trim();
    if !condition.is_empty() {
        parts.push(DebugText::SummaryCondition.fill(language, &[("condition", condition)]));
    }
    if breakpoint.hit_mode != HitMode::Always {
        parts.push(DebugText::SummaryHits.fill(
            language,
            &[
                ("mode", hit_mode_text(breakpoint.hit_mode).get(language)),
                ("target", &breakpoint.hit_target.to_string()),
            ],
        ));
    }
    for filter in [&breakpoint.instance, &breakpoint.task] {
        if !filter.trim().is_empty() {
            parts.push(filter.trim().to_owned());
        }
    }
    parts.join(" · ")
}

/// The object a body's file belongs to: `application/FB_Conveyor.Reset.st` is FB_Conveyor's.
fn pou_of_file(file: &str) -> String {
    let name = file.rsplit('/').next().unwrap_or(file);
    name.split('.').next().unwrap_or(name).to_owned()
}

fn hit_mode_text(mode: HitMode) -> DebugText {
    match mode {
        HitMode::Always => DebugText::HitAlways,
        HitMode::Equal => DebugText::HitEqual,
        HitMode::MultipleOf => DebugText::HitMultipleOf,
        HitMode::AtLeast => DebugText::HitAtLeast,
    }
}

/// The breakpoint dialog, as CODESYS's: the condition, the hit count, one instance, one task.
fn edit_dialog_ui(
    language: Language,
    state: &mut BreakpointsPaneState,
    commands: &mut Commands,
    ctx: &egui::Context,
) {
    let Some(editing) = &mut state.editing else {
        return;
    };
    let title = DebugText::BreakpointAt.fill(language, &[("place", &editing.place.label())]);
    let mut close = false;
    egui::Window::new(title)
        .id(egui::Id::unique("breakpoint_dialog"))
        .collapsible(false)
        .resizable(false)
        .show(ctx, |ui| {
            egui::Grid::new("breakpoint_fields")
                .num_columns(2)
                .show(ui, |ui| {
                    let label = ui.label(DebugText::Condition.get(language));
                    ui.text_edit_singleline(&mut editing.condition)
                        .labelled_by(label.id);
                    ui.end_row();
                    let label = ui.label(DebugText::HitCount.get(language));
                    egui::ComboBox::from_id_salt("hit_mode")
                        .selected_text(hit_mode_text(editing.hit_mode).get(language))
                        .show_ui(ui, |ui| {
                            for mode in HitMode::ALL {
                                ui.selectable_value(
                                    &mut editing.hit_mode,
                                    mode,
                                    hit_mode_text(mode).get(language),
                                );
                            }
                        })
                        .response
                        .labelled_by(label.id);
                    ui.end_row();
                    let label = ui.label(DebugText::HitTarget.get(language));
                    ui.add_enabled(
                        editing.hit_mode != HitMode::Always,
                        egui::DragValue::new(&mut editing.hit_target).range(0..=u32::MAX),
                    )
                    .labelled_by(label.id);
                    ui.end_row();
                    let label = ui.label(DebugText::Instance.get(language));
                    ui.add(
                        egui::TextEdit::singleline(&mut editing.instance)
                            .hint_text(DebugText::EveryInstance.get(language)),
                    )
                    .labelled_by(label.id);
                    ui.end_row();
                    let label = ui.label(DebugText::Task.get(language));
                    ui.add(
                        egui::TextEdit::singleline(&mut editing.task)
                            .hint_text(DebugText::EveryTask.get(language)),
                    )
                    .labelled_by(label.id);
                    ui.end_row();
                });
            ui.horizontal(|ui| {
                if ui.button(DebugText::Ok.get(language)).clicked() {
                    commands.push(Command::UpdateBreakpoint(editing.clone()));
                    close = true;
                }
                if ui.button(DebugText::Cancel.get(language)).clicked() {
                    close = true;
                }
            });
        });
    if close {
        state.editing = None;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::studio::debug::BreakpointPlace;

    #[test]
    fn a_bodys_file_names_its_object() {
        assert_eq!(
            pou_of_file("application/FB_Conveyor.Reset.st"),
            "FB_Conveyor"
        );
        assert_eq!(pou_of_file("Main.st"), "Main");
    }

    #[test]
    fn the_summary_names_the_condition_the_hit_count_and_the_filters() {
        let mut breakpoint = Breakpoint::at(BreakpointPlace::text("application/Main.st", 2));
        assert_eq!(summary(Language::English, &breakpoint), "");
        breakpoint.condition = "x > 1".to_owned();
        breakpoint.hit_mode = HitMode::AtLeast;
        breakpoint.hit_target = 3;
        breakpoint.task = "Fast".to_owned();
        assert_eq!(
            summary(Language::English, &breakpoint),
            "when x > 1 · hit count Greater than or equal to 3 · Fast"
        );
    }
}
