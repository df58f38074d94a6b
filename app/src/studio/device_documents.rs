//! The documents of the controller, I/O areas, serial ports, Modbus devices and axes: the device editors of
//! the `editor` crate in the user's language, their edits queued as commands.

use std::collections::HashMap;

use editor::{DeviceEdit, DeviceEditorState, DeviceTexts};
use egui::Ui;
use project_model::Project;

use super::command::{Command, Commands};
use super::device_refusals::refusal_words;
use super::documents::node_exists;
use super::i18n::{DeviceText, Language, ModbusOnlineText};
use super::modbus_online::device_online;
use super::online::Online;
use super::theme::colors;
use super::tree_node::TreeNode;

/// What the device editors keep between frames: each node's typed text, refusals and
/// remembered links. Not saved; kept while the node exists (a few short strings per node
/// opened), dropped when it is deleted or renamed and when another project is opened.
#[derive(Default)]
pub struct DeviceDocuments {
    /// The state of each node's editor.
    states: HashMap<TreeNode, DeviceEditorState>,
}

impl DeviceDocuments {
    /// Forgets every node's state, as opening another project does: its nodes may have the
    /// previous project's names without being the same devices.
    pub fn clear(&mut self) {
        self.states.clear();
    }

    /// Keeps the states in step with `project` after its change from `ports_before` (the serial
    /// ports' names before the change): a port renamed in place carries its new name into
    /// every remembered link, and the state of a node that no longer exists (deleted or
    /// renamed) is dropped, so a new node reusing the name starts afresh.
    pub fn follow_project(&mut self, ports_before: &[String], project: &Project) {
        // A rename changes one name in place; an addition or removal changes the count, and a
        // removed port has no new name to carry.
        if ports_before.len() == project.serial_ports.len() {
            for (old, port) in ports_before.iter().zip(&project.serial_ports) {
                if *old != port.name {
                    for state in self.states.values_mut() {
                        state.serial_port_renamed(old, &port.name);
                    }
                }
            }
        }
        self.states.retain(|node, _| node_exists(project, node));
    }
}

/// Draws the editor of `node` (the controller, an I/O area, a Modbus device or an axis) and
/// pushes its gesture onto `commands` as one edit command; `false` when `node` has no device
/// editor or is no longer part of the project.
pub(crate) fn device_editor_ui(
    ui: &mut Ui,
    project: &Project,
    node: &TreeNode,
    language: Language,
    documents: &mut DeviceDocuments,
    commands: &mut Commands,
) -> bool {
    let texts = device_texts(language);
    let state = documents.states.entry(node.clone()).or_default();
    // A channel table is wider than a narrow document pane: it scrolls sideways.
    let scroll = egui::ScrollArea::horizontal()
        .id_salt(("device editor", node))
        .auto_shrink([false, true]);
    let shown = scroll.show(ui, |ui| {
        let edit = editor_ui(ui, project, node, state, &texts);
        // Room for the scroll bar, which floats over the content's last row otherwise.
        ui.add_space(ui.spacing().scroll.bar_width + ui.spacing().scroll.bar_outer_margin + 4.0);
        edit
    });
    match shown.inner {
        Some(Some(edit)) => commands.push(Command::Edit(edit.label, edit.edits)),
        Some(None) => {}
        None => return false,
    }
    true
}

/// The read-only Online part of a runtime Modbus device's editor (`docs/modbus-master.md`
/// §9.2): its state, last error and counters while logged in; nothing for any other node, for
/// a studio device, or when not logged in.
pub(crate) fn modbus_online_part_ui(
    ui: &mut Ui,
    project: &Project,
    node: &TreeNode,
    online: &Online,
    language: Language,
) {
    let TreeNode::ModbusDevice(name) = node else {
        return;
    };
    let Some(device) = project.modbus_devices.iter().find(|d| d.name == *name) else {
        return;
    };
    let Some(shown) = device_online(online, device, language) else {
        return;
    };
    editor::modbus_online_ui(
        ui,
        &editor::ModbusOnlinePart {
            device: name,
            heading: ModbusOnlineText::Online.get(language),
            state_label: ModbusOnlineText::StateLabel.get(language),
            state: &shown.state,
            state_color: shown.light.color(colors(ui)),
            rows: &shown.rows,
        },
    );
}

/// The editor of `node` and its gesture: `None` when `node` has no device editor or is no
/// longer part of the project.
fn editor_ui(
    ui: &mut Ui,
    project: &Project,
    node: &TreeNode,
    state: &mut DeviceEditorState,
    texts: &DeviceTexts,
) -> Option<Option<DeviceEdit>> {
    let edit: Option<DeviceEdit> = match node {
        TreeNode::Controller => editor::controller_editor_ui(ui, project, state, texts),
        TreeNode::IoArea(name) => {
            let index = project.io_areas.iter().position(|a| a.name == *name)?;
            editor::io_area_editor_ui(ui, project, index, state, texts)
        }
        TreeNode::ModbusDevice(name) => {
            let index = project
                .modbus_devices
                .iter()
                .position(|d| d.name == *name)?;
            editor::modbus_device_editor_ui(ui, project, index, state, texts)
        }
        TreeNode::SerialPort(name) => {
            let index = project.serial_ports.iter().position(|p| p.name == *name)?;
            let silence = program_image::modbus_master::silent_interval_us;
            editor::serial_port_editor_ui(ui, project, index, state, texts, silence)
        }
        TreeNode::Axis(name) => {
            let index = project.axes.iter().position(|a| a.name == *name)?;
            editor::axis_editor_ui(ui, project, index, state, texts)
        }
        _ => return None,
    };
    Some(edit)
}

/// The editors' words in `language`.
fn device_texts(language: Language) -> DeviceTexts {
    let get = |text: DeviceText| text.get(language).to_owned();
    DeviceTexts {
        name: get(DeviceText::Name),
        host: get(DeviceText::Host),
        port: get(DeviceText::Port),
        password_note: get(DeviceText::PasswordNote),
        modbus_map_override: get(DeviceText::ModbusMapOverride),
        default_map_note: get(DeviceText::DefaultMapNote),
        map_ranges: get(DeviceText::MapRanges),
        table: get(DeviceText::Table),
        start: get(DeviceText::Start),
        count: get(DeviceText::Count),
        area_address: get(DeviceText::AreaAddress),
        add_range: get(DeviceText::AddRange),
        new_channel: get(DeviceText::NewChannel),
        delete: get(DeviceText::Delete),
        direction: get(DeviceText::Direction),
        start_byte: get(DeviceText::StartByte),
        size: get(DeviceText::Size),
        bytes: get(DeviceText::Bytes),
        milliseconds: get(DeviceText::Milliseconds),
        comment: get(DeviceText::Comment),
        inputs: get(DeviceText::Inputs),
        outputs: get(DeviceText::Outputs),
        markers: get(DeviceText::Markers),
        unit_id: get(DeviceText::UnitId),
        word_order: get(DeviceText::WordOrder),
        high_first: get(DeviceText::HighFirst),
        low_first: get(DeviceText::LowFirst),
        poll_interval: get(DeviceText::PollInterval),
        no_poll_interval: get(DeviceText::NoPollInterval),
        timeout: get(DeviceText::Timeout),
        channels: get(DeviceText::Channels),
        variable: get(DeviceText::Variable),
        address: get(DeviceText::Address),
        data_type: get(DeviceText::DataType),
        coil: get(DeviceText::Coil),
        discrete_input: get(DeviceText::DiscreteInput),
        holding_register: get(DeviceText::HoldingRegister),
        input_register: get(DeviceText::InputRegister),
        kind: get(DeviceText::Kind),
        virtual_axis: get(DeviceText::VirtualAxis),
        task: get(DeviceText::Task),
        unit: get(DeviceText::Unit),
        modulo: get(DeviceText::Modulo),
        modulo_period: get(DeviceText::ModuloPeriod),
        software_limits: get(DeviceText::SoftwareLimits),
        negative_limit: get(DeviceText::NegativeLimit),
        positive_limit: get(DeviceText::PositiveLimit),
        velocity: get(DeviceText::Velocity),
        acceleration: get(DeviceText::Acceleration),
        deceleration: get(DeviceText::Deceleration),
        jerk: get(DeviceText::Jerk),
        increments: get(DeviceText::Increments),
        units: get(DeviceText::Units),
        scaling: get(DeviceText::Scaling),
        dialect: get(DeviceText::Dialect),
        dialect_codesys: get(DeviceText::DialectCodesys),
        dialect_iec_strict: get(DeviceText::DialectIecStrict),
        dialect_note: get(DeviceText::DialectNote),
        link: get(DeviceText::Link),
        link_tcp: get(DeviceText::LinkTcp),
        link_rtu: get(DeviceText::LinkRtu),
        serial_port: get(DeviceText::SerialPort),
        io_task: get(DeviceText::IoTask),
        no_task: get(DeviceText::NoTask),
        studio_device_note: get(DeviceText::StudioDeviceNote),
        schedule: get(DeviceText::Schedule),
        schedule_interval: get(DeviceText::ScheduleInterval),
        schedule_every_cycle: get(DeviceText::ScheduleEveryCycle),
        max_read_gap: get(DeviceText::MaxReadGap),
        addresses: get(DeviceText::Addresses),
        status_variable: get(DeviceText::StatusVariable),
        optional: get(DeviceText::Optional),
        request_per_round: get(DeviceText::RequestPerRound),
        requests_per_round: get(DeviceText::RequestsPerRound),
        round: get(DeviceText::Round),
        read: get(DeviceText::Read),
        write: get(DeviceText::Write),
        function_code: get(DeviceText::FunctionCode),
        default_code: get(DeviceText::DefaultCode),
        write_single_coil: get(DeviceText::WriteSingleCoil),
        write_multiple_coils: get(DeviceText::WriteMultipleCoils),
        write_single_register: get(DeviceText::WriteSingleRegister),
        write_multiple_registers: get(DeviceText::WriteMultipleRegisters),
        trigger: get(DeviceText::Trigger),
        cyclic: get(DeviceText::Cyclic),
        rising_edge: get(DeviceText::RisingEdge),
        trigger_variable: get(DeviceText::TriggerVariable),
        trigger_variable_hint: get(DeviceText::TriggerVariableHint),
        on_error: get(DeviceText::OnError),
        keep_last_value: get(DeviceText::KeepLastValue),
        set_to_zero: get(DeviceText::SetToZero),
        error_flag: get(DeviceText::ErrorFlag),
        not_applicable: get(DeviceText::NotApplicable),
        device_file: get(DeviceText::DeviceFile),
        baud_rate: get(DeviceText::BaudRate),
        parity: get(DeviceText::Parity),
        parity_none: get(DeviceText::ParityNone),
        parity_even: get(DeviceText::ParityEven),
        parity_odd: get(DeviceText::ParityOdd),
        data_bits: get(DeviceText::DataBits),
        stop_bits: get(DeviceText::StopBits),
        inter_frame_delay: get(DeviceText::InterFrameDelay),
        microseconds: get(DeviceText::Microseconds),
        standard_delay: get(DeviceText::StandardDelay),
        devices_on_port: get(DeviceText::DevicesOnPort),
        no_devices_on_port: get(DeviceText::NoDevicesOnPort),
        field_of: get(DeviceText::FieldOf),
        field_of_row: get(DeviceText::FieldOfRow),
        set_field: get(DeviceText::SetField),
        add_row: get(DeviceText::AddRow),
        delete_row: get(DeviceText::DeleteRow),
        refusal: refusal_words(language),
    }
}
