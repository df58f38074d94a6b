//! The editor of a serial port (`docs/modbus-master.md` §2.3): its device file and line
//! settings, and the Modbus devices on it. The port is renamed in the device tree, as every
//! device node is (a rename closes its open tab there), and the new name is carried into the
//! devices that name the port, in the same undo step (`project_model::serial_port_rename_edits`).

use egui::{RichText, Ui};
use project_model::{Edit, ListEdit, Parity, Project, SerialPort, serial_port_problems};

use super::field::DeviceEditorState;
use super::form::Form;
use super::texts::fill;
use super::{DeviceEdit, DeviceTexts, checked_edit};

/// The standard's silence of 3.5 characters at a baud rate, in microseconds
/// (`program_image::modbus_master::silent_interval_us`, which this crate does not depend on:
/// the app gives it).
pub type StandardSilence = fn(u32) -> u32;

/// Draws the settings of the serial port at `index` of `project` and returns the edits of this
/// frame's gesture; nothing when there is no such port. `standard_silence_us` says what a
/// delay of 0 means at the port's baud rate.
pub fn serial_port_editor_ui(
    ui: &mut Ui,
    project: &Project,
    index: usize,
    state: &mut DeviceEditorState,
    texts: &DeviceTexts,
    standard_silence_us: StandardSilence,
) -> Option<DeviceEdit> {
    let port = project.serial_ports.get(index)?;
    state.follow(port);
    let node = port.name.as_str();
    let ports = &project.serial_ports;
    let problems = |port: &SerialPort| serial_port_problems(ports, Some(index), port);
    let change = |label: String, item: SerialPort| {
        checked_edit(label, port, item, problems, |item| {
            Edit::SerialPorts(ListEdit::Replace { index, item })
        })
    };
    let mut rates: Vec<(String, u32)> = SerialPort::BAUD_RATES
        .iter()
        .map(|rate| (rate.to_string(), *rate))
        .collect();
    if !SerialPort::BAUD_RATES.contains(&port.baud_rate) {
        rates.push((port.baud_rate.to_string(), port.baud_rate));
    }
    let parities = [
        (texts.parity_none.clone(), Parity::None),
        (texts.parity_even.clone(), Parity::Even),
        (texts.parity_odd.clone(), Parity::Odd),
    ];
    let mut stop_bits: Vec<(String, u8)> = [1, 2].map(|bits| (bits.to_string(), bits)).into();
    if !matches!(port.stop_bits, 1 | 2) {
        stop_bits.push((port.stop_bits.to_string(), port.stop_bits));
    }
    let standard = fill(
        &texts.standard_delay,
        &[("us", &standard_silence_us(port.baud_rate).to_string())],
    );
    let delay_suffix = format!("{}   {standard}", texts.microseconds);
    let mut form = Form::node(state, texts, port, node, &change);
    form.grid_ui(ui, ("serial port editor", index), |form, ui| {
        form.field("device", &texts.device_file, 220.0).text_ui(
            ui,
            &port.device,
            |item, device| item.device = device,
        );
        form.field("baud", &texts.baud_rate, 100.0).combo_ui(
            ui,
            port.baud_rate,
            &rates,
            |item, rate| item.baud_rate = rate,
        );
        form.field("parity", &texts.parity, 100.0).combo_ui(
            ui,
            port.parity,
            &parities,
            |item, parity| item.parity = parity,
        );
        form.field("data bits", &texts.data_bits, 60.0).whole_ui(
            ui,
            port.data_bits,
            0..=u8::MAX,
            |item, bits| item.data_bits = bits,
        );
        form.field("stop bits", &texts.stop_bits, 60.0).combo_ui(
            ui,
            port.stop_bits,
            &stop_bits,
            |item, bits| item.stop_bits = bits,
        );
        form.field("delay", &texts.inter_frame_delay, 80.0)
            .suffix(&delay_suffix)
            .whole_ui(
                ui,
                port.inter_frame_delay_us,
                0..=u32::MAX,
                |item, delay| {
                    item.inter_frame_delay_us = delay;
                },
            );
        ui.label(&texts.devices_on_port);
        let devices = project.devices_on_serial_port(&port.name);
        if devices.is_empty() {
            ui.label(RichText::new(&texts.no_devices_on_port).weak());
        } else {
            ui.label(devices.join(", "));
        }
        ui.end_row();
    });
    form.finish()
}
