//! The editor of a Modbus TCP device: its address, unit, word order, timing and channel table.

use egui::Ui;
use project_model::{
    Edit, ListEdit, ModbusBinding, ModbusDevice, Project, WordOrder, modbus_device_problems,
};

use super::channels::channels_ui;
use super::field::{DeviceEditorState, FieldId, combo_ui, parse_whole, row_ui, text_field_ui};
use super::{DeviceEdit, DeviceTexts, field_label, keep, refuse_new, set_label};

/// Draws the settings and channels of the Modbus device at `index` of `project` and returns
/// the edits of this frame's gesture; nothing when there is no such device.
pub fn modbus_device_editor_ui(
    ui: &mut Ui,
    project: &Project,
    index: usize,
    state: &mut DeviceEditorState,
    texts: &DeviceTexts,
) -> Option<DeviceEdit> {
    let device = project.modbus_devices.get(index)?;
    state.follow(device);
    let node = device.name.as_str();
    let devices = &project.modbus_devices;
    let replace = |label: String, item: ModbusDevice| {
        // Deleting a channel brings no problem, but it renumbers the rows old problems name,
        // which would make them look new.
        let deleted = item.bindings.len() < device.bindings.len();
        if !deleted {
            refuse_new(
                modbus_device_problems(devices, Some(index), device),
                modbus_device_problems(devices, Some(index), &item),
            )?;
        }
        Ok(DeviceEdit {
            label,
            edits: vec![Edit::ModbusDevices(ListEdit::Replace { index, item })],
        })
    };
    let set = |field: &str, value: &str, item: ModbusDevice| {
        replace(set_label(texts, field, node, value), item)
    };
    let mut out = None;
    egui::Grid::new(("modbus device editor", index))
        .num_columns(2)
        .spacing([12.0, 6.0])
        .show(ui, |ui| {
            let label = field_label(texts, &texts.host, node);
            let field = FieldId {
                key: "host",
                label: &label,
                width: 160.0,
            };
            row_ui(ui, &texts.host, |ui| {
                keep(
                    &mut out,
                    text_field_ui(ui, state, texts, field, &device.host, "", |text| {
                        set(
                            &texts.host,
                            text,
                            ModbusDevice {
                                host: text.to_owned(),
                                ..device.clone()
                            },
                        )
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
                let current = device.port.to_string();
                keep(
                    &mut out,
                    text_field_ui(ui, state, texts, field, &current, "", |text| {
                        let port = parse_whole(text, 0u16, u16::MAX)?;
                        set(
                            &texts.port,
                            text,
                            ModbusDevice {
                                port,
                                ..device.clone()
                            },
                        )
                    }),
                );
            });
            let label = field_label(texts, &texts.unit_id, node);
            let field = FieldId {
                key: "unit",
                label: &label,
                width: 60.0,
            };
            row_ui(ui, &texts.unit_id, |ui| {
                let current = device.unit_id.to_string();
                keep(
                    &mut out,
                    text_field_ui(ui, state, texts, field, &current, "", |text| {
                        let unit_id = parse_whole(text, 0u8, u8::MAX)?;
                        set(
                            &texts.unit_id,
                            text,
                            ModbusDevice {
                                unit_id,
                                ..device.clone()
                            },
                        )
                    }),
                );
            });
            let orders = [
                (texts.high_first.clone(), WordOrder::HighFirst),
                (texts.low_first.clone(), WordOrder::LowFirst),
            ];
            let label = field_label(texts, &texts.word_order, node);
            let field = FieldId {
                key: "order",
                label: &label,
                width: 140.0,
            };
            row_ui(ui, &texts.word_order, |ui| {
                keep(
                    &mut out,
                    combo_ui(
                        ui,
                        state,
                        texts,
                        field,
                        device.word_order,
                        &orders,
                        |word_order| {
                            let name = if word_order == WordOrder::HighFirst {
                                &texts.high_first
                            } else {
                                &texts.low_first
                            };
                            set(
                                &texts.word_order,
                                name,
                                ModbusDevice {
                                    word_order,
                                    ..device.clone()
                                },
                            )
                        },
                    ),
                );
            });
            let label = field_label(texts, &texts.poll_interval, node);
            let field = FieldId {
                key: "poll",
                label: &label,
                width: 60.0,
            };
            row_ui(ui, &texts.poll_interval, |ui| {
                let current = device.poll_interval_ms.to_string();
                keep(
                    &mut out,
                    text_field_ui(
                        ui,
                        state,
                        texts,
                        field,
                        &current,
                        &texts.milliseconds,
                        |text| {
                            let poll_interval_ms = parse_whole(text, 0u32, u32::MAX)?;
                            set(
                                &texts.poll_interval,
                                text,
                                ModbusDevice {
                                    poll_interval_ms,
                                    ..device.clone()
                                },
                            )
                        },
                    ),
                );
            });
            let label = field_label(texts, &texts.timeout, node);
            let field = FieldId {
                key: "timeout",
                label: &label,
                width: 60.0,
            };
            row_ui(ui, &texts.timeout, |ui| {
                let current = device.timeout_ms.to_string();
                keep(
                    &mut out,
                    text_field_ui(
                        ui,
                        state,
                        texts,
                        field,
                        &current,
                        &texts.milliseconds,
                        |text| {
                            let timeout_ms = parse_whole(text, 0u32, u32::MAX)?;
                            set(
                                &texts.timeout,
                                text,
                                ModbusDevice {
                                    timeout_ms,
                                    ..device.clone()
                                },
                            )
                        },
                    ),
                );
            });
        });
    ui.add_space(8.0);
    let commit = |label: String, bindings: Vec<ModbusBinding>| {
        replace(
            format!("{label} ({node})"),
            ModbusDevice {
                bindings,
                ..device.clone()
            },
        )
    };
    keep(
        &mut out,
        channels_ui(ui, project, state, texts, &device.bindings, &commit),
    );
    out
}
