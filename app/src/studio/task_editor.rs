//! The task configuration editor: a table of the tasks (name, kind, interval or trigger,
//! priority, watchdog) and the ordered program calls of the selected task.
//!
//! Values are typed as text and checked when the field is left (Enter, Tab or a click
//! elsewhere): a refused value stays in its field with the reason below it and changes nothing;
//! an accepted one becomes one `Edit::Tasks(ListEdit::Replace { .. })`, one undo step.

mod fields;
mod refusal;
mod time_literal;

use std::collections::HashMap;

use egui::{Key, RichText, Ui, WidgetInfo};
use project_model::{Edit, ListEdit, Object, PouKind, Project, Task, TaskKind};

use self::fields::{Field, call_problem, default_watchdog};
use self::time_literal::{describe_time_us, parse_time_us};
use super::command::{Command, Commands};
use super::i18n::{Language, Text};
use super::tree_actions::ListKind;
use super::tree_node::TreeNode;
use super::view::StudioView;

/// What the task editor keeps between frames: the selected task, text being typed and the
/// reasons typed values were refused. Typed text is dropped when the project changes, so a
/// field never shows a stale draft after an undo.
#[derive(Default)]
pub(crate) struct TaskEditorState {
    /// The task whose program calls are shown, by name.
    selected: Option<String>,
    /// Text typed into a field and not yet accepted, by task name and field.
    drafts: HashMap<(String, Field), String>,
    /// Why a typed value was refused, by task name and field.
    refused: HashMap<(String, Field), String>,
    /// The program name typed or chosen for a new call.
    call: String,
    /// Why the last program call could not be added.
    call_refused: Option<String>,
    /// The project revision the drafts belong to.
    revision: Option<u64>,
}

/// One accepted change: its undo label and edits, one undo step.
type Change = (String, Vec<Edit>);

/// Draws the editor for `node` (the task configuration, or a single task) and queues the
/// accepted changes as edits.
pub(crate) fn task_editor_ui(
    view: StudioView<'_>,
    state: &mut TaskEditorState,
    commands: &mut Commands,
    ui: &mut Ui,
    node: &TreeNode,
) {
    let language = view.language;
    let Some(session) = view.session else {
        return;
    };
    let project = &session.project;
    let revision = session.history.revision();
    if state.revision != Some(revision) {
        state.drafts.clear();
        state.refused.clear();
        state.call_refused = None;
        state.revision = Some(revision);
    }
    let shown: Vec<usize> = match node {
        TreeNode::Task(name) => project
            .tasks
            .iter()
            .position(|task| task.name == *name)
            .into_iter()
            .collect(),
        _ => (0..project.tasks.len()).collect(),
    };
    let selected = match node {
        TreeNode::Task(name) => Some(name.clone()),
        _ => state
            .selected
            .clone()
            .filter(|name| project.task(name).is_some())
            .or_else(|| project.tasks.first().map(|task| task.name.clone())),
    };
    let mut changes: Vec<Change> = Vec::new();
    egui::ScrollArea::both()
        .id_salt(("task editor", node))
        .auto_shrink([false, false])
        .show(ui, |ui| {
            ui.add_space(4.0);
            if let TreeNode::Task(name) = node
                && shown.is_empty()
            {
                let text = Text::NoLongerInProject
                    .get(language)
                    .replace("{name}", name);
                ui.label(RichText::new(text).color(ui.visuals().warn_fg_color));
                return;
            }
            if *node == TreeNode::TaskConfiguration
                && ui.button(Text::AddTask.get(language)).clicked()
            {
                let (edit, name) = ListKind::Tasks.add(project);
                changes.push((
                    Text::UndoAddTask.fill(language, &[("name", &name)]),
                    vec![edit],
                ));
                state.selected = Some(name);
            }
            let mut editor = Editor {
                project,
                state,
                language,
                selected: selected.as_deref(),
                changes: &mut changes,
            };
            editor.table_ui(ui, &shown);
            if let Some(index) = selected
                .as_deref()
                .and_then(|name| project.tasks.iter().position(|task| task.name == name))
            {
                ui.add_space(12.0);
                editor.calls_ui(ui, index);
            }
        });
    for (label, edits) in changes {
        commands.push(Command::Edit(label, edits));
    }
}

/// The editor while it is drawn: what it reads and where it puts accepted changes.
struct Editor<'a> {
    project: &'a Project,
    state: &'a mut TaskEditorState,
    language: Language,
    selected: Option<&'a str>,
    changes: &'a mut Vec<Change>,
}

impl Editor<'_> {
    fn table_ui(&mut self, ui: &mut Ui, shown: &[usize]) {
        let language = self.language;
        egui::Grid::new("task table")
            .num_columns(9)
            .striped(true)
            .spacing([12.0, 6.0])
            .show(ui, |ui| {
                ui.label("");
                for header in [
                    Text::Name,
                    Text::Kind,
                    Text::Interval,
                    Text::TriggerVariable,
                    Text::Priority,
                    Text::Watchdog,
                    Text::WatchdogTime,
                    Text::Sensitivity,
                ] {
                    ui.strong(header.get(language));
                }
                ui.end_row();
                let project = self.project;
                for &index in shown {
                    if let Some(task) = project.tasks.get(index) {
                        self.row_ui(ui, index, task);
                        ui.end_row();
                    }
                }
            });
    }

    fn row_ui(&mut self, ui: &mut Ui, index: usize, task: &Task) {
        let language = self.language;
        let is_selected = self.selected == Some(task.name.as_str());
        let select = ui.selectable_label(is_selected, format!("{}", index + 1));
        select.widget_info(|| {
            WidgetInfo::labeled(
                egui::Role::Button,
                true,
                accessible(language, Text::ProgramCalls, &task.name),
            )
        });
        if select.clicked() {
            self.state.selected = Some(task.name.clone());
        }
        self.field_ui(ui, index, task, Field::Name, 110.0);
        self.kind_ui(ui, index, task);
        self.field_ui(ui, index, task, Field::Interval, 90.0);
        self.field_ui(ui, index, task, Field::Trigger, 130.0);
        self.field_ui(ui, index, task, Field::Priority, 40.0);
        let mut enabled = task.watchdog.is_some();
        let checkbox = ui.checkbox(&mut enabled, "");
        checkbox.widget_info(|| {
            WidgetInfo::labeled(
                egui::Role::CheckBox,
                true,
                accessible(language, Text::Watchdog, &task.name),
            )
        });
        if checkbox.changed() {
            let mut item = task.clone();
            item.watchdog = enabled.then(|| default_watchdog(task));
            let template = if enabled {
                Text::UndoEnableWatchdog
            } else {
                Text::UndoDisableWatchdog
            };
            let label = template.fill(language, &[("name", &task.name)]);
            self.replace(label, index, item);
        }
        self.field_ui(ui, index, task, Field::WatchdogTime, 90.0);
        self.field_ui(ui, index, task, Field::Sensitivity, 40.0);
    }

    /// Replaces the task at `index` with `item`; a new name is carried into the devices, axes
    /// and traces that name the task, in the same undo step.
    fn replace(&mut self, label: String, index: usize, item: Task) {
        let carried = self.project.tasks.get(index).map_or_else(Vec::new, |old| {
            project_model::task_rename_edits(self.project, &old.name, &item.name)
        });
        let mut edits = vec![Edit::Tasks(ListEdit::Replace { index, item })];
        edits.extend(carried);
        self.changes.push((label, edits));
    }

    /// A text field of the table; the value is checked and applied when the field is left.
    fn field_ui(&mut self, ui: &mut Ui, index: usize, task: &Task, field: Field, width: f32) {
        let Some(current) = field.current(task) else {
            ui.label(RichText::new("-").weak());
            return;
        };
        let key = (task.name.clone(), field);
        let language = self.language;
        let mut text = self
            .state
            .drafts
            .get(&key)
            .cloned()
            .unwrap_or_else(|| current.clone());
        ui.vertical(|ui| {
            let response = ui.add(egui::TextEdit::singleline(&mut text).desired_width(width));
            response.widget_info(|| {
                WidgetInfo::labeled(
                    egui::Role::TextInput,
                    true,
                    accessible(language, field.text(), &task.name),
                )
            });
            if response.gained_focus() {
                self.state.selected = Some(task.name.clone());
            }
            if response.changed() {
                self.state.drafts.insert(key.clone(), text.clone());
                self.state.refused.remove(&key);
            }
            if response.lost_focus() {
                let escaped = ui.input(|input| input.key_pressed(Key::Escape));
                if escaped || text.trim() == current {
                    self.state.drafts.remove(&key);
                    self.state.refused.remove(&key);
                    text = current.clone();
                } else {
                    match field.apply(self.project, task, &text, language) {
                        Ok((item, label)) => {
                            self.state.drafts.remove(&key);
                            self.replace(label, index, item);
                        }
                        Err(reason) => {
                            let reason = reason.text(language);
                            self.state.refused.insert(key.clone(), reason);
                        }
                    }
                }
            }
            if matches!(field, Field::Interval | Field::WatchdogTime)
                && let Ok(micros) = parse_time_us(&text)
            {
                ui.label(RichText::new(describe_time_us(micros)).weak().small());
            }
            let missing_trigger = field == Field::Trigger && text.trim().is_empty();
            if let Some(reason) = self.state.refused.get(&key) {
                ui.label(
                    RichText::new(reason)
                        .small()
                        .color(ui.visuals().error_fg_color),
                );
            } else if missing_trigger {
                // A task just made an event task has no trigger yet: say what it needs.
                ui.label(
                    RichText::new(Text::TriggerNeeded.get(language))
                        .small()
                        .color(ui.visuals().warn_fg_color),
                );
            }
        });
    }

    fn kind_ui(&mut self, ui: &mut Ui, index: usize, task: &Task) {
        let language = self.language;
        let kinds = [
            (
                Text::Cyclic,
                TaskKind::Cyclic {
                    interval_us: 10_000,
                },
            ),
            (Text::Freewheeling, TaskKind::Freewheeling),
            (
                Text::EventTask,
                TaskKind::Event {
                    trigger: String::new(),
                },
            ),
        ];
        let same_kind =
            |a: &TaskKind, b: &TaskKind| std::mem::discriminant(a) == std::mem::discriminant(b);
        let current = kinds
            .iter()
            .find(|(_, kind)| same_kind(kind, &task.kind))
            .map(|(text, _)| text.get(language))
            .unwrap_or_default();
        let mut chosen = None;
        egui::ComboBox::from_id_salt(("task kind", &task.name))
            .selected_text(current)
            .show_ui(ui, |ui| {
                for (text, kind) in &kinds {
                    if ui
                        .selectable_label(same_kind(kind, &task.kind), text.get(language))
                        .clicked()
                    {
                        chosen = Some((text, kind.clone()));
                    }
                }
            })
            .response
            .widget_info(|| {
                WidgetInfo::labeled(
                    egui::Role::ComboBox,
                    true,
                    accessible(language, Text::Kind, &task.name),
                )
            });
        if let Some((text, kind)) = chosen
            && !same_kind(&kind, &task.kind)
        {
            let mut item = task.clone();
            item.kind = kind;
            self.replace(
                format!(
                    "Make {} {}",
                    task.name,
                    text.get(Language::English).to_lowercase()
                ),
                index,
                item,
            );
        }
    }

    /// The selected task's program calls in calling order, with buttons to reorder and remove
    /// them, and a field to add one.
    fn calls_ui(&mut self, ui: &mut Ui, index: usize) {
        let language = self.language;
        let project = self.project;
        let Some(task) = project.tasks.get(index) else {
            return;
        };
        ui.strong(format!(
            "{} · {}",
            Text::ProgramCalls.get(language),
            task.name
        ));
        ui.add_space(4.0);
        let last = task.programs.len().saturating_sub(1);
        for (position, program) in task.programs.iter().enumerate() {
            ui.horizontal(|ui| {
                let known = is_program(self.project, program);
                let text = RichText::new(format!("{}. {program}", position + 1)).monospace();
                ui.label(if known {
                    text
                } else {
                    text.color(ui.visuals().warn_fg_color)
                });
                let buttons = [
                    (Text::MoveUp, position > 0),
                    (Text::MoveDown, position < last),
                    (Text::Remove, true),
                ];
                for (text, enabled) in buttons {
                    let button = ui.add_enabled(enabled, egui::Button::new(text.get(language)));
                    button.widget_info(|| {
                        WidgetInfo::labeled(
                            egui::Role::Button,
                            enabled,
                            format!("{} {program}", text.get(language)),
                        )
                    });
                    if button.clicked() {
                        self.change_call(index, task, position, text);
                    }
                }
            });
        }
        ui.horizontal(|ui| {
            let label = ui.label(Text::ProgramToCall.get(language));
            let field = ui
                .add(egui::TextEdit::singleline(&mut self.state.call).desired_width(130.0))
                .labelled_by(label.id);
            if field.changed() {
                self.state.call_refused = None;
            }
            let programs: Vec<&str> = self
                .project
                .application
                .objects()
                .into_iter()
                .filter_map(|object| match object {
                    Object::Pou(pou) if pou.kind == PouKind::Program => Some(pou.name.as_str()),
                    _ => None,
                })
                .collect();
            egui::ComboBox::from_id_salt("program to call")
                .selected_text("")
                .width(24.0)
                .show_ui(ui, |ui| {
                    for program in programs {
                        if ui.selectable_label(false, program).clicked() {
                            self.state.call = program.to_owned();
                            self.state.call_refused = None;
                        }
                    }
                })
                .response
                .widget_info(|| {
                    WidgetInfo::labeled(
                        egui::Role::ComboBox,
                        true,
                        Text::ChooseProgram.get(language),
                    )
                });
            let entered = field.lost_focus() && ui.input(|input| input.key_pressed(Key::Enter));
            if ui.button(Text::AddCall.get(language)).clicked() || entered {
                let program = self.state.call.trim().to_owned();
                match call_problem(self.project, task, &program) {
                    Some(reason) => self.state.call_refused = Some(reason.text(language)),
                    None => {
                        let mut item = task.clone();
                        item.programs.push(program.clone());
                        let label = Text::UndoAddCall
                            .fill(language, &[("program", &program), ("task", &task.name)]);
                        self.replace(label, index, item);
                        self.state.call.clear();
                    }
                }
            }
        });
        if let Some(reason) = &self.state.call_refused {
            ui.label(RichText::new(reason).color(ui.visuals().error_fg_color));
        }
    }

    fn change_call(&mut self, index: usize, task: &Task, position: usize, action: Text) {
        let mut item = task.clone();
        let Some(program) = item.programs.get(position).cloned() else {
            return;
        };
        let template = match action {
            Text::MoveUp if position > 0 => {
                item.programs.swap(position, position - 1);
                Text::UndoMoveCallUp
            }
            Text::MoveDown if position + 1 < item.programs.len() => {
                item.programs.swap(position, position + 1);
                Text::UndoMoveCallDown
            }
            Text::Remove => {
                item.programs.remove(position);
                Text::UndoRemoveCall
            }
            _ => return,
        };
        let label = template.fill(
            self.language,
            &[("program", &program), ("task", &task.name)],
        );
        self.replace(label, index, item);
    }
}

/// Whether `program` names a PROGRAM of the project (calls of anything else are shown in the
/// warning colour, as the build will refuse them).
fn is_program(project: &Project, program: &str) -> bool {
    matches!(
        project.application.object(program),
        Some(Object::Pou(pou)) if pou.kind == PouKind::Program
    )
}

/// The accessible label of a task's field: "Priority of MainTask".
fn accessible(language: Language, field: Text, task: &str) -> String {
    Text::CellOf.fill(language, &[("column", field.get(language)), ("name", task)])
}
