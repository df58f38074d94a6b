//! The controller's editor: its name, its address, whether it has a Modbus map of its own, and
//! the language rules (dialect) the project's programs are checked by, the project setting a
//! user looks for beside the controller it builds for. The password is typed when logging in
//! and never stored, so there is no field for it.

use egui::{RichText, Ui};
use project_model::{Controller, Dialect, Edit, ModbusServerMap, Project, controller_problems};

use super::field::{DeviceEditorState, FieldId, combo_ui, parse_whole};
use super::form::Form;
use super::map_ranges::map_ranges_ui;
use super::{DeviceEdit, DeviceTexts, checked_edit, field_label, keep, set_label};

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
    let change = |label: String, candidate: Controller| {
        checked_edit(
            label,
            controller,
            candidate,
            controller_problems,
            Edit::SetController,
        )
    };
    let mut form = Form::node(state, texts, controller, node, &change);
    form.grid_ui(ui, "controller editor", |form, ui| {
        form.field("name", &texts.name, 160.0)
            .text_ui(ui, &controller.name, |item, name| item.name = name);
        form.field("host", &texts.host, 160.0)
            .text_ui(ui, &controller.host, |item, host| item.host = host);
        // The undo label shows the port as read, where the other editors show it as typed.
        let port = controller.port.to_string();
        form.field("port", &texts.port, 60.0)
            .typed_ui(ui, &port, |item, text| {
                item.port = parse_whole(text, 0u16, u16::MAX)?;
                Ok(item.port.to_string())
            });
        ui.label("");
        ui.label(RichText::new(&texts.password_note).weak());
        ui.end_row();
    });
    ui.add_space(8.0);
    let overridden = controller.modbus_map.is_some();
    form.field("map", &texts.modbus_map_override, 0.0)
        .checkbox_ui(ui, overridden, |item, on| {
            item.modbus_map = on.then(ModbusServerMap::default);
            if on { "on" } else { "off" }
        });
    let mut out = form.finish();
    keep(&mut out, dialect_ui(ui, project, state, texts));
    match &controller.modbus_map {
        None => {
            ui.label(RichText::new(&texts.default_map_note).weak());
        }
        Some(map) => {
            let commit = |label: String, ranges: Vec<project_model::ModbusServerRange>| {
                // Deleting a range brings no problem, but it renumbers the rows old problems
                // name, which would make them look new.
                let deleted = ranges.len() < map.ranges.len();
                let problems = |controller: &Controller| {
                    if deleted {
                        Vec::new()
                    } else {
                        controller_problems(controller)
                    }
                };
                let candidate = Controller {
                    modbus_map: Some(ModbusServerMap { ranges }),
                    ..controller.clone()
                };
                let label = format!("{label} ({node})");
                checked_edit(label, controller, candidate, problems, Edit::SetController)
            };
            keep(
                &mut out,
                map_ranges_ui(ui, state, texts, &map.ranges, &commit),
            );
        }
    }
    out
}

/// The project's dialect as a choice of two, with a note saying what it decides.
fn dialect_ui(
    ui: &mut Ui,
    project: &Project,
    state: &mut DeviceEditorState,
    texts: &DeviceTexts,
) -> Option<DeviceEdit> {
    let node = project.controller.name.as_str();
    let options = [
        (texts.dialect_codesys.clone(), Dialect::Codesys),
        (texts.dialect_iec_strict.clone(), Dialect::IecStrict),
    ];
    let label = field_label(texts, &texts.dialect, node);
    ui.add_space(8.0);
    let edit = ui
        .horizontal(|ui| {
            ui.label(&texts.dialect);
            let field = FieldId {
                key: "dialect",
                label: &label,
                width: 160.0,
            };
            combo_ui(
                ui,
                state,
                texts,
                field,
                project.dialect,
                &options,
                |dialect| {
                    let shown = options
                        .iter()
                        .find(|(_, value)| *value == dialect)
                        .map_or(dialect.name(), |(text, _)| text.as_str());
                    Ok(DeviceEdit {
                        label: set_label(texts, &texts.dialect, node, shown),
                        edits: vec![Edit::SetDialect(dialect)],
                    })
                },
            )
        })
        .inner;
    ui.label(RichText::new(&texts.dialect_note).weak());
    edit
}
