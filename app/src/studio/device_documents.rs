//! The documents of the controller, I/O areas, Modbus devices and axes: the device editors of
//! the `editor` crate in the user's language, their edits queued as commands.

use std::collections::HashMap;

use editor::{DeviceEdit, DeviceEditorState, DeviceTexts};
use egui::{RichText, Ui};
use project_model::Project;

use super::command::{Command, Commands};
use super::device_refusals::refusal_words;
use super::i18n::{Language, Text};
use super::tree_node::TreeNode;

/// What the device editors keep between frames: each node's typed text and refusals. Not
/// saved; kept while the studio runs (a few short strings per node opened).
#[derive(Default)]
pub struct DeviceDocuments {
    /// The state of each node's editor.
    states: HashMap<TreeNode, DeviceEditorState>,
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
        TreeNode::Axis(name) => {
            let index = project.axes.iter().position(|a| a.name == *name)?;
            editor::axis_editor_ui(ui, project, index, state, texts)
        }
        _ => return None,
    };
    Some(edit)
}

/// An axis document: its title and its editor, scrolled.
pub(crate) fn axis_document_ui(
    ui: &mut Ui,
    project: &Project,
    node: &TreeNode,
    language: Language,
    documents: &mut DeviceDocuments,
    commands: &mut Commands,
) {
    egui::ScrollArea::vertical()
        .id_salt(("axis document", node))
        .auto_shrink([false, false])
        .show(ui, |ui| {
            ui.add_space(4.0);
            ui.label(RichText::new(node.title(Some(project))).strong());
            ui.separator();
            device_editor_ui(ui, project, node, language, documents, commands);
        });
}

/// The editors' words in `language`.
fn device_texts(language: Language) -> DeviceTexts {
    let get = |text: Text| text.get(language).to_owned();
    DeviceTexts {
        name: get(Text::DeviceName),
        host: get(Text::DeviceHost),
        port: get(Text::DevicePort),
        password_note: get(Text::DevicePasswordNote),
        modbus_map_override: get(Text::DeviceModbusMapOverride),
        default_map_note: get(Text::DeviceDefaultMapNote),
        map_ranges: get(Text::DeviceMapRanges),
        table: get(Text::DeviceTable),
        start: get(Text::DeviceStart),
        count: get(Text::DeviceCount),
        area_address: get(Text::DeviceAreaAddress),
        add_range: get(Text::DeviceAddRange),
        new_channel: get(Text::DeviceNewChannel),
        delete: get(Text::DeviceDelete),
        direction: get(Text::DeviceDirection),
        start_byte: get(Text::DeviceStartByte),
        size: get(Text::DeviceSize),
        bytes: get(Text::DeviceBytes),
        milliseconds: get(Text::DeviceMilliseconds),
        comment: get(Text::DeviceComment),
        inputs: get(Text::DeviceInputs),
        outputs: get(Text::DeviceOutputs),
        markers: get(Text::DeviceMarkers),
        unit_id: get(Text::DeviceUnitId),
        word_order: get(Text::DeviceWordOrder),
        high_first: get(Text::DeviceHighFirst),
        low_first: get(Text::DeviceLowFirst),
        poll_interval: get(Text::DevicePollInterval),
        timeout: get(Text::DeviceTimeout),
        channels: get(Text::DeviceChannels),
        variable: get(Text::DeviceVariable),
        address: get(Text::DeviceAddress),
        data_type: get(Text::DeviceDataType),
        coil: get(Text::DeviceCoil),
        discrete_input: get(Text::DeviceDiscreteInput),
        holding_register: get(Text::DeviceHoldingRegister),
        input_register: get(Text::DeviceInputRegister),
        kind: get(Text::DeviceKind),
        virtual_axis: get(Text::DeviceVirtualAxis),
        task: get(Text::DeviceTask),
        unit: get(Text::DeviceUnit),
        modulo: get(Text::DeviceModulo),
        modulo_period: get(Text::DeviceModuloPeriod),
        software_limits: get(Text::DeviceSoftwareLimits),
        negative_limit: get(Text::DeviceNegativeLimit),
        positive_limit: get(Text::DevicePositiveLimit),
        velocity: get(Text::DeviceVelocity),
        acceleration: get(Text::DeviceAcceleration),
        deceleration: get(Text::DeviceDeceleration),
        jerk: get(Text::DeviceJerk),
        increments: get(Text::DeviceIncrements),
        units: get(Text::DeviceUnits),
        scaling: get(Text::DeviceScaling),
        field_of: get(Text::DeviceFieldOf),
        field_of_row: get(Text::DeviceFieldOfRow),
        set_field: get(Text::DeviceSetField),
        add_row: get(Text::DeviceAddRow),
        delete_row: get(Text::DeviceDeleteRow),
        refusal: refusal_words(language),
    }
}
