//! The editor of a motion axis: kind, task, unit, modulo period, software limits, dynamic
//! limits and scaling, each value shown with its unit.

use egui::Ui;
use project_model::{Axis, AxisKind, Edit, ListEdit, Project, axis_problems};

use super::field::{
    DeviceEditorState, FieldId, checkbox_ui, combo_ui, parse_number, row_ui, text_field_ui,
};
use super::refusal::Refusal;
use super::{DeviceEdit, DeviceTexts, field_label, keep, refuse_new, set_label};

/// A number field of an axis: its key, its name, its unit and how it is read and written.
struct NumberField<'a> {
    key: &'a str,
    name: &'a str,
    unit: String,
    get: fn(&Axis) -> f64,
    put: fn(&mut Axis, f64),
}

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
    let set = |field: &str, value: &str, item: Axis| {
        refuse_new(
            axis_problems(project, Some(index), axis),
            axis_problems(project, Some(index), &item),
        )?;
        Ok(DeviceEdit {
            label: set_label(texts, field, node, value),
            edits: vec![Edit::Axes(ListEdit::Replace { index, item })],
        })
    };
    let unit = axis.unit.as_str();
    let mut out = None;
    egui::Grid::new(("axis editor", index))
        .num_columns(2)
        .spacing([12.0, 6.0])
        .show(ui, |ui| {
            let kinds = [(texts.virtual_axis.clone(), AxisKind::Virtual)];
            let label = field_label(texts, &texts.kind, node);
            let field = FieldId {
                key: "kind",
                label: &label,
                width: 120.0,
            };
            row_ui(ui, &texts.kind, |ui| {
                keep(
                    &mut out,
                    combo_ui(ui, state, texts, field, axis.kind, &kinds, |kind| {
                        set(
                            &texts.kind,
                            &texts.virtual_axis,
                            Axis {
                                kind,
                                ..axis.clone()
                            },
                        )
                    }),
                );
            });
            let tasks: Vec<(String, usize)> = project
                .tasks
                .iter()
                .enumerate()
                .map(|(position, task)| (task.name.clone(), position))
                .collect();
            let current = project
                .tasks
                .iter()
                .position(|task| project_model::same_identifier(&task.name, &axis.task))
                .unwrap_or(usize::MAX);
            let label = field_label(texts, &texts.task, node);
            let field = FieldId {
                key: "task",
                label: &label,
                width: 120.0,
            };
            row_ui(ui, &texts.task, |ui| {
                keep(
                    &mut out,
                    combo_ui(ui, state, texts, field, current, &tasks, |position| {
                        let task = tasks
                            .get(position)
                            .map(|(name, _)| name.clone())
                            .unwrap_or_default();
                        set(
                            &texts.task,
                            &task,
                            Axis {
                                task: task.clone(),
                                ..axis.clone()
                            },
                        )
                    }),
                );
            });
            let label = field_label(texts, &texts.unit, node);
            let field = FieldId {
                key: "unit",
                label: &label,
                width: 60.0,
            };
            row_ui(ui, &texts.unit, |ui| {
                keep(
                    &mut out,
                    text_field_ui(ui, state, texts, field, unit, "", |text| {
                        set(
                            &texts.unit,
                            text,
                            Axis {
                                unit: text.to_owned(),
                                ..axis.clone()
                            },
                        )
                    }),
                );
            });
            let label = field_label(texts, &texts.modulo, node);
            let field = FieldId {
                key: "modulo",
                label: &label,
                width: 0.0,
            };
            row_ui(ui, "", |ui| {
                let on = axis.modulo_period.is_some();
                keep(
                    &mut out,
                    checkbox_ui(ui, state, texts, field, &texts.modulo, on, |on| {
                        let modulo_period = on.then_some(360.0);
                        let value = if on { "360" } else { "-" };
                        set(
                            &texts.modulo_period,
                            value,
                            Axis {
                                modulo_period,
                                ..axis.clone()
                            },
                        )
                    }),
                );
            });
            if axis.modulo_period.is_some() {
                let field = NumberField {
                    key: "period",
                    name: &texts.modulo_period,
                    unit: unit.to_owned(),
                    get: |axis| axis.modulo_period.unwrap_or_default(),
                    put: |axis, value| axis.modulo_period = Some(value),
                };
                keep(&mut out, number_ui(ui, state, texts, axis, &field, &set));
            }
            let label = field_label(texts, &texts.software_limits, node);
            let field = FieldId {
                key: "limits",
                label: &label,
                width: 0.0,
            };
            row_ui(ui, "", |ui| {
                let on = axis.software_limits.enabled;
                keep(
                    &mut out,
                    checkbox_ui(
                        ui,
                        state,
                        texts,
                        field,
                        &texts.software_limits,
                        on,
                        |enabled| {
                            let mut item = axis.clone();
                            item.software_limits.enabled = enabled;
                            let value = if enabled { "on" } else { "off" };
                            set(&texts.software_limits, value, item)
                        },
                    ),
                );
            });
            let fields = [
                NumberField {
                    key: "min",
                    name: &texts.negative_limit,
                    unit: unit.to_owned(),
                    get: |axis| axis.software_limits.min,
                    put: |axis, value| axis.software_limits.min = value,
                },
                NumberField {
                    key: "max",
                    name: &texts.positive_limit,
                    unit: unit.to_owned(),
                    get: |axis| axis.software_limits.max,
                    put: |axis, value| axis.software_limits.max = value,
                },
                NumberField {
                    key: "velocity",
                    name: &texts.velocity,
                    unit: format!("{unit}/s"),
                    get: |axis| axis.limits.velocity,
                    put: |axis, value| axis.limits.velocity = value,
                },
                NumberField {
                    key: "acceleration",
                    name: &texts.acceleration,
                    unit: format!("{unit}/s²"),
                    get: |axis| axis.limits.acceleration,
                    put: |axis, value| axis.limits.acceleration = value,
                },
                NumberField {
                    key: "deceleration",
                    name: &texts.deceleration,
                    unit: format!("{unit}/s²"),
                    get: |axis| axis.limits.deceleration,
                    put: |axis, value| axis.limits.deceleration = value,
                },
                NumberField {
                    key: "jerk",
                    name: &texts.jerk,
                    unit: format!("{unit}/s³"),
                    get: |axis| axis.limits.jerk,
                    put: |axis, value| axis.limits.jerk = value,
                },
            ];
            for field in &fields {
                keep(&mut out, number_ui(ui, state, texts, axis, field, &set));
            }
            ui.strong(&texts.scaling);
            ui.end_row();
            let scaling = [
                NumberField {
                    key: "numerator",
                    name: &texts.increments,
                    unit: String::new(),
                    get: |axis| axis.scaling.numerator,
                    put: |axis, value| axis.scaling.numerator = value,
                },
                NumberField {
                    key: "denominator",
                    name: &texts.units,
                    unit: unit.to_owned(),
                    get: |axis| axis.scaling.denominator,
                    put: |axis, value| axis.scaling.denominator = value,
                },
            ];
            for field in &scaling {
                keep(&mut out, number_ui(ui, state, texts, axis, field, &set));
            }
        });
    out
}

/// One number of the axis as a grid row: its name, its field and its unit.
fn number_ui(
    ui: &mut Ui,
    state: &mut DeviceEditorState,
    texts: &DeviceTexts,
    axis: &Axis,
    number: &NumberField<'_>,
    set: &dyn Fn(&str, &str, Axis) -> Result<DeviceEdit, Refusal>,
) -> Option<DeviceEdit> {
    let label = field_label(texts, number.name, &axis.name);
    let field = FieldId {
        key: number.key,
        label: &label,
        width: 90.0,
    };
    let current = (number.get)(axis).to_string();
    row_ui(ui, number.name, |ui| {
        text_field_ui(ui, state, texts, field, &current, &number.unit, |text| {
            let value = parse_number(text)?;
            let mut item = axis.clone();
            (number.put)(&mut item, value);
            set(number.name, text, item)
        })
    })
}
