//! The editor of a Modbus device: its link (TCP or a serial port), unit, word order, timing,
//! the runtime master's settings once an I/O task is chosen, and the channel table.

use egui::Ui;
use project_model::{
    Edit, ListEdit, ModbusBinding, ModbusDevice, Project, WordOrder, modbus_device_problems,
};

use super::channels::channels_ui;
use super::field::DeviceEditorState;
use super::form::Form;
use super::modbus_master::{link_fields_ui, master_fields_ui, poll_interval_ui};
use super::{DeviceEdit, DeviceTexts, checked_edit, keep};

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
    state.links.remember(&device.link);
    let links = state.links.clone();
    let node = device.name.as_str();
    let replace = |label: String, item: ModbusDevice| {
        // Deleting a channel brings no problem, but it renumbers the rows old problems name,
        // which would make them look new.
        let deleted = item.bindings.len() < device.bindings.len();
        let problems = |device: &ModbusDevice| {
            if deleted {
                Vec::new()
            } else {
                modbus_device_problems(project, Some(index), device)
            }
        };
        checked_edit(label, device, item, problems, |item| {
            Edit::ModbusDevices(ListEdit::Replace { index, item })
        })
    };
    let orders = [
        (texts.high_first.clone(), WordOrder::HighFirst),
        (texts.low_first.clone(), WordOrder::LowFirst),
    ];
    let milliseconds = texts.milliseconds.as_str();
    let mut form = Form::node(state, texts, device, node, &replace);
    form.grid_ui(ui, ("modbus device editor", index), |form, ui| {
        link_fields_ui(form, ui, project, device, texts, &links);
        form.field("unit", &texts.unit_id, 60.0).whole_ui(
            ui,
            device.unit_id,
            0..=u8::MAX,
            |item, unit| item.unit_id = unit,
        );
        form.field("order", &texts.word_order, 140.0).combo_ui(
            ui,
            device.word_order,
            &orders,
            |item, order| item.word_order = order,
        );
        poll_interval_ui(form, ui, device, texts);
        form.field("timeout", &texts.timeout, 60.0)
            .suffix(milliseconds)
            .whole_ui(ui, device.timeout_ms, 0..=u32::MAX, |item, timeout| {
                item.timeout_ms = timeout;
            });
        master_fields_ui(form, ui, project, device, texts);
    });
    let mut out = form.finish();
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
    let master = device.is_runtime_device();
    keep(
        &mut out,
        channels_ui(ui, project, state, texts, &device.bindings, master, &commit),
    );
    out
}
