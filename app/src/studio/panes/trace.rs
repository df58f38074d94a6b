//! The trace pane: pick a trace of the project, start it on the target, upload and look at the
//! samples.

use egui::{RichText, Ui};
use project_model::{
    Edit, Object, TraceConfig, TraceTrigger, TraceTriggerCondition, TraceVariable,
};

use crate::studio::command::{Command, Commands};
use crate::studio::i18n::Text;
use crate::studio::online::TracePhase;
use crate::studio::trace_view::{TraceViewState, trace_samples_ui};
use crate::studio::view::StudioView;

/// What the trace pane remembers between frames.
#[derive(Default)]
pub struct TracePaneState {
    /// The trace shown; the first one when `None` or gone.
    pub selected: Option<String>,
    /// The variable path typed in the "add variable" field.
    new_variable: String,
    /// The trigger variable being typed, until Enter commits it.
    trigger_typing: Option<String>,
}

impl TracePaneState {
    /// Every trace of the project and the one shown.
    fn traces<'p>(
        &self,
        session: Option<&'p crate::studio::session::Session>,
    ) -> (Vec<&'p TraceConfig>, Option<&'p TraceConfig>) {
        super::chosen_object(session, self.selected.as_deref(), |object| match object {
            Object::Trace(trace) => Some(trace),
            _ => None,
        })
    }

    /// The variables of the trace the pane shows.
    pub fn variable_paths(&self, session: Option<&crate::studio::session::Session>) -> Vec<String> {
        self.traces(session)
            .1
            .map(|trace| trace.variables.iter().map(|v| v.path.clone()).collect())
            .unwrap_or_default()
    }
}

/// The edit that replaces a trace object, merged with the previous one of the same gesture.
fn replace(commands: &mut Commands, label: &str, changed: TraceConfig, merge: bool) {
    commands.push(Command::EditText {
        label: label.to_owned(),
        merge_key: merge.then(|| format!("trace {} {label}", changed.name)),
        edits: vec![Edit::ReplaceObject(Object::Trace(changed))],
    });
}

/// The trace's configuration, edited in place: task, record count, every n-th cycle, trigger
/// (variable, edge or level, pre-trigger share) and the recorded variables.
fn configuration_ui(
    view: StudioView<'_>,
    state: &mut TracePaneState,
    commands: &mut Commands,
    ui: &mut Ui,
    config: &TraceConfig,
) {
    let language = view.language;
    let tasks: Vec<String> = view
        .project()
        .map(|project| project.tasks.iter().map(|t| t.name.clone()).collect())
        .unwrap_or_default();
    ui.horizontal_wrapped(|ui| {
        let label = ui.label(Text::Task.get(language));
        egui::ComboBox::from_id_salt("trace_task")
            .selected_text(&config.task)
            .show_ui(ui, |ui| {
                for task in &tasks {
                    if ui.selectable_label(*task == config.task, task).clicked()
                        && *task != config.task
                    {
                        let mut changed = config.clone();
                        changed.task = task.clone();
                        replace(commands, Text::UndoTraceTask.get(language), changed, false);
                    }
                }
            })
            .response
            .labelled_by(label.id);
        let mut count = config.record_count;
        let label = ui.label(Text::RecordCount.get(language));
        if ui
            .add(egui::DragValue::new(&mut count).range(1..=1_000_000))
            .labelled_by(label.id)
            .changed()
        {
            let mut changed = config.clone();
            changed.record_count = count;
            replace(commands, Text::UndoRecordCount.get(language), changed, true);
        }
        let mut every = config.every_n_cycles;
        let label = ui.label(Text::EveryNth.get(language));
        if ui
            .add(egui::DragValue::new(&mut every).range(1..=u32::from(u16::MAX)))
            .labelled_by(label.id)
            .changed()
        {
            let mut changed = config.clone();
            changed.every_n_cycles = every;
            replace(commands, Text::UndoSampling.get(language), changed, true);
        }
    });
    ui.horizontal_wrapped(|ui| {
        let mut triggered = config.trigger.is_some();
        if ui
            .checkbox(&mut triggered, Text::TraceTrigger.get(language))
            .changed()
        {
            let mut changed = config.clone();
            changed.trigger = triggered.then(|| TraceTrigger {
                variable: config
                    .variables
                    .first()
                    .map(|v| v.path.clone())
                    .unwrap_or_default(),
                condition: TraceTriggerCondition::Rising,
                level: None,
                pre_trigger_percent: 10,
            });
            replace(commands, Text::UndoTrigger.get(language), changed, false);
        }
        let Some(trigger) = &config.trigger else {
            return;
        };
        let label = ui.label(Text::Variable.get(language));
        let mut typed = state
            .trigger_typing
            .clone()
            .unwrap_or_else(|| trigger.variable.clone());
        let field = ui
            .add(egui::TextEdit::singleline(&mut typed).desired_width(200.0))
            .labelled_by(label.id);
        if field.changed() {
            state.trigger_typing = Some(typed.clone());
        }
        if field.lost_focus() {
            state.trigger_typing = None;
            if typed.trim() != trigger.variable {
                let mut changed = config.clone();
                if let Some(t) = &mut changed.trigger {
                    t.variable = typed.trim().to_owned();
                }
                replace(
                    commands,
                    Text::UndoTriggerVariable.get(language),
                    changed,
                    false,
                );
            }
        }
        let mut condition = trigger.condition;
        for (value, text) in [
            (TraceTriggerCondition::Rising, Text::Rising),
            (TraceTriggerCondition::Falling, Text::Falling),
            (TraceTriggerCondition::Level, Text::Level),
        ] {
            ui.radio_value(&mut condition, value, text.get(language));
        }
        if condition != trigger.condition {
            let mut changed = config.clone();
            if let Some(t) = &mut changed.trigger {
                t.condition = condition;
            }
            replace(
                commands,
                Text::UndoTriggerCondition.get(language),
                changed,
                false,
            );
        }
        let mut percent = trigger.pre_trigger_percent;
        let label = ui.label(Text::PreTrigger.get(language));
        if ui
            .add(
                egui::DragValue::new(&mut percent)
                    .range(0..=100)
                    .suffix(" %"),
            )
            .labelled_by(label.id)
            .changed()
        {
            let mut changed = config.clone();
            if let Some(t) = &mut changed.trigger {
                t.pre_trigger_percent = percent;
            }
            replace(commands, Text::UndoPreTrigger.get(language), changed, true);
        }
    });
    ui.horizontal_wrapped(|ui| {
        let mut removed = None;
        for (index, variable) in config.variables.iter().enumerate() {
            ui.label(RichText::new(&variable.path).monospace());
            if ui
                .small_button("×")
                .on_hover_text(format!("{} {}", Text::Remove.get(language), variable.path))
                .clicked()
            {
                removed = Some(index);
            }
            ui.separator();
        }
        if let Some(index) = removed {
            let mut changed = config.clone();
            let gone = changed.variables.remove(index);
            replace(
                commands,
                &Text::UndoStopTracing.fill(language, &[("path", &gone.path)]),
                changed,
                false,
            );
        }
        let label = ui.label(Text::AddVariable.get(language));
        let field = ui
            .add(
                egui::TextEdit::singleline(&mut state.new_variable)
                    .hint_text("Main.fbConveyor.xMotorOn")
                    .desired_width(200.0),
            )
            .labelled_by(label.id);
        let path = state.new_variable.trim().to_owned();
        if field.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter)) && !path.is_empty() {
            let mut changed = config.clone();
            changed.variables.push(TraceVariable {
                path: path.clone(),
                color: None,
            });
            replace(
                commands,
                &Text::UndoTrace.fill(language, &[("path", &path)]),
                changed,
                false,
            );
            state.new_variable.clear();
        }
    });
}

/// Draws the trace pane; starting, uploading, exporting and changing the trace become commands.
pub(crate) fn trace_ui(
    view: StudioView<'_>,
    state: &mut TracePaneState,
    plot: &mut TraceViewState,
    commands: &mut Commands,
    ui: &mut Ui,
) {
    let language = view.language;
    let (traces, current) = state.traces(view.session);
    let names: Vec<String> = traces.iter().map(|trace| trace.name.clone()).collect();
    let Some(config) = current.cloned() else {
        ui.label(RichText::new(Text::NoTrace.get(language)).weak());
        return;
    };
    let online = view.online.is_online();
    ui.horizontal(|ui| {
        let label = ui.label(Text::Trace.get(language));
        egui::ComboBox::from_id_salt("trace_choice")
            .selected_text(&config.name)
            .show_ui(ui, |ui| {
                for name in &names {
                    if ui.selectable_label(*name == config.name, name).clicked() {
                        state.selected = Some(name.clone());
                    }
                }
            })
            .response
            .labelled_by(label.id);
        // A trace of the channels of a Modbus device the studio polls records by polling,
        // without a login.
        let on_device = config
            .variables
            .iter()
            .any(|v| view.online.is_polled_by_studio(&v.path));
        let can_start = online || (on_device && view.online.can_write());
        if ui
            .add_enabled(can_start, egui::Button::new(Text::StartTrace.get(language)))
            .clicked()
        {
            commands.push(Command::StartTrace(config.clone()));
        }
        let phase = view.online.trace().phase();
        let can_upload = online
            && matches!(
                phase,
                TracePhase::Recording { .. } | TracePhase::Complete | TracePhase::Uploaded
            );
        if ui
            .add_enabled(
                can_upload,
                egui::Button::new(Text::UploadTrace.get(language)),
            )
            .clicked()
        {
            commands.push(Command::UploadTrace);
        }
        phase_ui(ui, phase, config.record_count, language);
    });
    let editable = !view.online.trace().is_recording();
    ui.add_enabled_ui(editable, |ui| {
        configuration_ui(view, state, commands, ui, &config)
    });
    ui.separator();
    trace_samples_ui(view, plot, commands, ui, Some(&config));
}

fn phase_ui(
    ui: &mut Ui,
    phase: TracePhase,
    record_count: u32,
    language: crate::studio::i18n::Language,
) {
    match phase {
        TracePhase::Idle => {}
        TracePhase::Resolving | TracePhase::Arming => {
            ui.spinner();
        }
        TracePhase::Recording {
            recorded,
            triggered,
        } => {
            let fraction = recorded as f32 / record_count.max(1) as f32;
            let text = if triggered {
                Text::Triggered.get(language)
            } else {
                Text::Recording.get(language)
            };
            ui.add(
                egui::ProgressBar::new(fraction)
                    .desired_width(160.0)
                    .text(format!("{text} {recorded}")),
            );
        }
        TracePhase::Complete => {
            ui.label(Text::Complete.get(language));
        }
        TracePhase::Uploading { received, total } => {
            let fraction = received as f32 / total.max(1) as f32;
            ui.add(
                egui::ProgressBar::new(fraction)
                    .desired_width(160.0)
                    .text(format!(
                        "{} {received}/{total}",
                        Text::Uploading.get(language)
                    )),
            );
        }
        TracePhase::Uploaded => {}
    }
}
