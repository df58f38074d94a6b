//! The controller's editor: its name, its address and whether it has a Modbus map of its own.
//! The password is typed when logging in and never stored, so there is no field for it.

use egui::{RichText, Ui};
use project_model::{Controller, Edit, ModbusServerMap, Project, controller_problems};

use super::field::{DeviceEditorState, FieldId, checkbox_ui, parse_whole, row_ui, text_field_ui};
use super::map_ranges::map_ranges_ui;
use super::{DeviceEdit, DeviceTexts, field_label, keep, refuse_new, set_label};

/// Draws the controller's settings of `project` and returns the edits of this frame's gesture.
pub fn controller_editor_ui(
    ui: &mut Ui,
    project: &Project,
    state: &mut DeviceEditorState,
    texts: &DeviceTexts,
) -> Option<DeviceEdit> {
    let controller = &project.controller;
    state.follow(controller);
    let node = controller.name.as_str();
    let set = |field: &str, value: &str, candidate: Controller| {
        refuse_new(
            controller_problems(controller),
            controller_problems(&candidate),
        )?;
        Ok(DeviceEdit {
            label: set_label(texts, field, node, value),
            edits: vec![Edit::SetController(candidate)],
        })
    };
    let mut out = None;
    egui::Grid::new("controller editor")
        .num_columns(2)
        .spacing([12.0, 6.0])
        .show(ui, |ui| {
            let label = field_label(texts, &texts.name, node);
            let field = FieldId {
                key: "name",
                label: &label,
                width: 160.0,
            };
            row_ui(ui, &texts.name, |ui| {
                keep(
                    &mut out,
                    text_field_ui(ui, state, texts, field, &controller.name, "", |text| {
                        let candidate = Controller {
                            name: text.to_owned(),
                            ..controller.clone()
                        };
                        set(&texts.name, text, candidate)
                    }),
                );
            });
            let label = field_label(texts, &texts.host, node);
            let field = FieldId {
                key: "host",
                label: &label,
                width: 160.0,
            };
            row_ui(ui, &texts.host, |ui| {
                keep(
                    &mut out,
                    text_field_ui(ui, state, texts, field, &controller.host, "", |text| {
                        let candidate = Controller {
                            host: text.to_owned(),
                            ..controller.clone()
                        };
                        set(&texts.host, text, candidate)
                    }),
                );
            });
            let label = field_label(texts, &texts.port, node);
            let field = FieldId {
                key: "port",
                label: &label,
                width: 60.0,
            };
            row_ui(ui, &texts.port, |ui| {
                let current = controller.port.to_string();
                keep(
                    &mut out,
                    text_field_ui(ui, state, texts, field, &current, "", |text| {
                        let port = parse_whole(text, 0u16, u16::MAX)?;
                        let candidate = Controller {
                            port,
                            ..controller.clone()
                        };
                        set(&texts.port, &port.to_string(), candidate)
                    }),
                );
            });
            ui.label("");
            ui.label(RichText::new(&texts.password_note).weak());
            ui.end_row();
        });
    ui.add_space(8.0);
    let label = field_label(texts, &texts.modbus_map_override, node);
    let field = FieldId {
        key: "map",
        label: &label,
        width: 0.0,
    };
    let overridden = controller.modbus_map.is_some();
    keep(
        &mut out,
        checkbox_ui(
            ui,
            state,
            texts,
            field,
            &texts.modbus_map_override,
            overridden,
            |on| {
                let candidate = Controller {
                    modbus_map: on.then(ModbusServerMap::default),
                    ..controller.clone()
                };
                let value = if on { "on" } else { "off" };
                set(&texts.modbus_map_override, value, candidate)
            },
        ),
    );
    match &controller.modbus_map {
        None => {
            ui.label(RichText::new(&texts.default_map_note).weak());
        }
        Some(map) => {
            let commit = |label: String, ranges: Vec<project_model::ModbusServerRange>| {
                // Deleting a range brings no problem, but it renumbers the rows old problems
                // name, which would make them look new.
                let deleted = ranges.len() < map.ranges.len();
                let candidate = Controller {
                    modbus_map: Some(ModbusServerMap { ranges }),
                    ..controller.clone()
                };
                if !deleted {
                    refuse_new(
                        controller_problems(controller),
                        controller_problems(&candidate),
                    )?;
                }
                Ok(DeviceEdit {
                    label: format!("{label} ({node})"),
                    edits: vec![Edit::SetController(candidate)],
                })
            };
            keep(
                &mut out,
                map_ranges_ui(ui, state, texts, &map.ranges, &commit),
            );
        }
    }
    out
}
