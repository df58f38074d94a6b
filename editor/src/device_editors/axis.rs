//! The editor of a motion axis: kind, task, unit, modulo period, software limits, dynamic
//! limits and scaling, each value shown with its unit.

use egui::Ui;
use project_model::{Axis, AxisKind, Edit, ListEdit, Project, axis_problems};

use super::field::DeviceEditorState;
use super::form::Form;
use super::{DeviceEdit, DeviceTexts, checked_edit};

/// Draws the settings of the axis at `index` of `project` and returns the edits of this
/// frame's gesture; nothing when there is no such axis.
pub fn axis_editor_ui(
    ui: &mut Ui,
    project: &Project,
    index: usize,
    state: &mut DeviceEditorState,
    texts: &DeviceTexts,
) -> Option<DeviceEdit> {
    let axis = project.axes.get(index)?;
    state.follow(axis);
    let node = axis.name.as_str();
    let problems = |axis: &Axis| axis_problems(project, Some(index), axis);
    let change = |label: String, item: Axis| {
        checked_edit(label, axis, item, problems, |item| {
            Edit::Axes(ListEdit::Replace { index, item })
        })
    };
    let unit = axis.unit.as_str();
    let per_second = format!("{unit}/s");
    let per_second_squared = format!("{unit}/s²");
    let per_second_cubed = format!("{unit}/s³");
    let kinds = [(texts.virtual_axis.clone(), AxisKind::Virtual)];
    let tasks: Vec<(String, usize)> = project
        .tasks
        .iter()
        .enumerate()
        .map(|(position, task)| (task.name.clone(), position))
        .collect();
    let task = project
        .tasks
        .iter()
        .position(|task| project_model::same_identifier(&task.name, &axis.task))
        .unwrap_or(usize::MAX);
    let mut form = Form::node(state, texts, axis, node, &change);
    form.grid_ui(ui, ("axis editor", index), |form, ui| {
        form.field("kind", &texts.kind, 120.0)
            .combo_ui(ui, axis.kind, &kinds, |item, kind| item.kind = kind);
        form.field("task", &texts.task, 120.0)
            .combo_ui(ui, task, &tasks, |item, position| {
                item.task = tasks
                    .get(position)
                    .map(|(name, _)| name.clone())
                    .unwrap_or_default();
            });
        form.field("unit", &texts.unit, 60.0)
            .text_ui(ui, unit, |item, unit| item.unit = unit);
        let modulo = axis.modulo_period.is_some();
        form.field("modulo", &texts.modulo, 0.0)
            .undo_name(&texts.modulo_period)
            .checkbox_ui(ui, modulo, |item, on| {
                item.modulo_period = on.then_some(360.0);
                if on { "360" } else { "-" }
            });
        if let Some(period) = axis.modulo_period {
            form.field("period", &texts.modulo_period, 90.0)
                .suffix(unit)
                .number_ui(ui, period, |item, period| item.modulo_period = Some(period));
        }
        let limits = &axis.software_limits;
        form.field("limits", &texts.software_limits, 0.0)
            .checkbox_ui(ui, limits.enabled, |item, enabled| {
                item.software_limits.enabled = enabled;
                if enabled { "on" } else { "off" }
            });
        form.field("min", &texts.negative_limit, 90.0)
            .suffix(unit)
            .number_ui(ui, limits.min, |item, min| item.software_limits.min = min);
        form.field("max", &texts.positive_limit, 90.0)
            .suffix(unit)
            .number_ui(ui, limits.max, |item, max| item.software_limits.max = max);
        let dynamics = &axis.limits;
        form.field("velocity", &texts.velocity, 90.0)
            .suffix(&per_second)
            .number_ui(ui, dynamics.velocity, |item, velocity| {
                item.limits.velocity = velocity;
            });
        form.field("acceleration", &texts.acceleration, 90.0)
            .suffix(&per_second_squared)
            .number_ui(ui, dynamics.acceleration, |item, acceleration| {
                item.limits.acceleration = acceleration;
            });
        form.field("deceleration", &texts.deceleration, 90.0)
            .suffix(&per_second_squared)
            .number_ui(ui, dynamics.deceleration, |item, deceleration| {
                item.limits.deceleration = deceleration;
            });
        form.field("jerk", &texts.jerk, 90.0)
            .suffix(&per_second_cubed)
            .number_ui(ui, dynamics.jerk, |item, jerk| item.limits.jerk = jerk);
        ui.strong(&texts.scaling);
        ui.end_row();
        let scaling = &axis.scaling;
        form.field("numerator", &texts.increments, 90.0).number_ui(
            ui,
            scaling.numerator,
            |item, numerator| {
                item.scaling.numerator = numerator;
            },
        );
        form.field("denominator", &texts.units, 90.0)
            .suffix(unit)
            .number_ui(ui, scaling.denominator, |item, denominator| {
                item.scaling.denominator = denominator;
            });
    });
    form.finish()
}
