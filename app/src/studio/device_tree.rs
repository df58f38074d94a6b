//! The device tree panel: controller, tasks, application, I/O, Modbus devices and axes, with
//! context menus, drag and drop and dirty markers for editing it.

use std::collections::{HashMap, HashSet};

use egui::collapsing_header::CollapsingState;
use egui::{Color32, Key, Modifiers, RichText, Ui};
use project_model::{Folder, IoDirection, Node, Object, Parity, Project, SerialPort, TaskKind};

use super::command::{Command, Commands};
use super::i18n::{Language, Text};
use super::modbus_online::{DeviceLight, DeviceOnline, device_online};
use super::reveal::Reveal;
use super::theme::{StudioColors, colors};
use super::tree_actions::{
    BodyLanguage, DialogOutcome, DropPlace, ListKind, MemberDialog, MemberKind, NewObject,
    TreeAction, TreeDialog, TreeEditState, accepts, place_at, plan, rename_scope,
};
use super::tree_node::{TreeNode, object_tag};
use super::view::StudioView;

/// What the user did in the tree this frame.
#[derive(Debug, Default)]
pub struct TreeResponse {
    /// A node was clicked.
    pub clicked: Option<TreeNode>,
    /// A node was double-clicked (or Enter was pressed on it, or Open chosen in its menu).
    pub opened: Option<TreeNode>,
    /// Changes asked for through menus, drag and drop or the Delete key.
    pub actions: Vec<TreeAction>,
    /// A dialog to open (a new POU's name, a rename).
    pub dialog: Option<TreeDialog>,
}

/// The payload of a node being dragged in the tree.
#[derive(Clone, Debug)]
struct DraggedNode(TreeNode);

/// Draws the devices pane: the tree, its dialog, and the changes they ask for, which are queued
/// as commands (never applied while drawing).
pub(crate) fn devices_pane_ui(
    view: StudioView<'_>,
    state: &mut TreeEditState,
    commands: &mut Commands,
    ui: &mut Ui,
) {
    let language = view.language;
    let Some(session) = view.session else {
        match view.failed_dir {
            Some(dir) => {
                ui.label(RichText::new(Text::CouldNotOpen.get(language)).strong());
                ui.label(RichText::new(dir.display().to_string()).weak());
            }
            None => {
                ui.label(Text::NoProjectOpen.get(language));
            }
        }
        ui.label(RichText::new(Text::NoProjectHint.get(language)).weak());
        return;
    };
    let project = &session.project;
    let dirty = state
        .dirty
        .get(project, session.history.revision(), &session.saved);
    let dialog_open = state.dialog.is_some();
    // What each runtime device shows online, decided once here so the tree only draws it.
    let device_states: HashMap<String, DeviceOnline> = project
        .modbus_devices
        .iter()
        .filter_map(|device| {
            let shown = device_online(view.online, device, language)?;
            Some((device.name.clone(), shown))
        })
        .collect();
    let mut response = device_tree_ui(
        ui,
        TreeContext {
            project,
            selection: view.selection,
            language,
            dirty,
            body_language: state.body_language,
            device_states: &device_states,
        },
        !dialog_open,
    );
    if let Some(dialog) = response.dialog.take() {
        state.dialog = Some(dialog);
    }
    if let Some(dialog) = &mut state.dialog {
        match dialog.ui(ui.ctx(), project, language) {
            DialogOutcome::Open => {}
            DialogOutcome::Cancelled => state.dialog = None,
            DialogOutcome::Confirmed(action) => {
                state.dialog = None;
                if let Some(chosen) = action.body_language() {
                    state.body_language = chosen;
                }
                response.actions.push(action);
            }
        }
    }
    let mut planned = Vec::new();
    for action in &response.actions {
        let deletes = matches!(action, TreeAction::Delete(_));
        planned.push((deletes, plan(project, action, language)));
    }
    if let Some(node) = response.clicked {
        commands.push(Command::Select(Some(node)));
    }
    if let Some(node) = response.opened {
        commands.push(Command::Select(Some(node.clone())));
        if node.is_document() {
            commands.push(Command::Open(node));
        }
    }
    for (deletes, result) in planned {
        match result {
            Ok(Some(plan)) => {
                commands.push(Command::Edit(plan.label, plan.edits));
                if deletes {
                    commands.push(Command::Select(None));
                }
                if let Some(node) = plan.select {
                    commands.push(Command::Select(Some(node)));
                }
                match (plan.open, plan.part) {
                    (Some(node), Some(part)) => {
                        commands.push(Command::Reveal(node, Reveal::Body(part, 0..0)));
                    }
                    (Some(node), None) => commands.push(Command::Open(node)),
                    (None, _) => {}
                }
            }
            Ok(None) => {}
            Err(refusal) => commands.error(refusal.text(language)),
        }
    }
}

/// What the device tree is drawn from.
#[derive(Clone, Copy)]
pub struct TreeContext<'a> {
    /// The project shown.
    pub project: &'a Project,
    /// The selected node.
    pub selection: Option<&'a TreeNode>,
    /// The interface language.
    pub language: Language,
    /// The nodes that differ from the saved project; they get a `*` after their name.
    pub dirty: &'a HashSet<TreeNode>,
    /// The implementation language the add dialogs propose.
    pub body_language: BodyLanguage,
    /// What each runtime Modbus device shows while logged in, by the device's name; a device
    /// missing from it shows nothing online.
    pub device_states: &'a HashMap<String, DeviceOnline>,
}

/// Draws the device tree and reports what the user did; it never changes the project. `keys`
/// lets the Delete key act.
pub fn device_tree_ui(ui: &mut Ui, context: TreeContext<'_>, keys: bool) -> TreeResponse {
    let TreeContext {
        project,
        selection,
        language,
        dirty,
        body_language,
        device_states,
    } = context;
    let mut tree = TreeUi {
        project,
        selection,
        language,
        dirty,
        body_language,
        device_states,
        row_focused: false,
        response: TreeResponse::default(),
    };
    let scroll = egui::ScrollArea::both()
        .auto_shrink([false, false])
        .show(ui, |ui| {
            tree.branch(
                ui,
                TreeNode::Controller,
                "PLC",
                &project.controller.name,
                "",
                |tree, ui| {
                    tree.task_configuration(ui, project, language);
                    tree.branch(
                        ui,
                        TreeNode::Application,
                        "APP",
                        Text::Application.get(language),
                        "",
                        |tree, ui| {
                            tree.folder_children(ui, &project.application, &[]);
                        },
                    );
                    tree.io_areas(ui, project, language);
                    tree.serial_ports(ui, project, language);
                    tree.modbus_devices(ui, project, language);
                    tree.axes(ui, project, language);
                },
            );
        });
    // The Delete key deletes the selected node while the tree has the user's attention: a row
    // has the keyboard focus, or the pointer is over the tree and no other widget has the
    // focus (the Delete key of an editor must never delete a POU).
    let pointer_over_tree = ui
        .ctx()
        .pointer_hover_pos()
        .is_some_and(|pos| scroll.inner_rect.contains(pos));
    let attention =
        tree.row_focused || (pointer_over_tree && !ui.ctx().egui_wants_keyboard_input());
    if keys
        && attention
        && let Some(node) = selection.filter(|node| rename_scope(node).is_some())
        && ui.input_mut(|input| input.consume_key(Modifiers::NONE, Key::Delete))
    {
        tree.response.actions.push(TreeAction::Delete(node.clone()));
    }
    tree.response
}

struct TreeUi<'a> {
    project: &'a Project,
    selection: Option<&'a TreeNode>,
    language: Language,
    dirty: &'a HashSet<TreeNode>,
    /// The implementation language the add dialogs propose.
    body_language: BodyLanguage,
    /// What each runtime Modbus device shows online, by name, for their icons.
    device_states: &'a HashMap<String, DeviceOnline>,
    /// Whether a row had the keyboard focus this frame.
    row_focused: bool,
    response: TreeResponse,
}

impl TreeUi<'_> {
    /// A node with children, open by default.
    fn branch(
        &mut self,
        ui: &mut Ui,
        node: TreeNode,
        tag: &str,
        label: &str,
        detail: &str,
        children: impl FnOnce(&mut Self, &mut Ui),
    ) {
        let id = ui.make_persistent_id(("device_tree", &node));
        CollapsingState::load_with_default_open(ui.ctx(), id, true)
            .show_header(ui, |ui| {
                self.row(ui, node, tag, label, detail);
            })
            .body(|ui| children(self, ui));
    }

    /// One selectable row: a tag, the name (the row's accessible label, with ` *` when the node
    /// differs from the saved project) and a weak detail. The row opens a context menu, can be
    /// dragged when the node can move, and takes drops of nodes that may land on it.
    fn row(
        &mut self,
        ui: &mut Ui,
        node: TreeNode,
        tag: &str,
        label: &str,
        detail: &str,
    ) -> egui::Response {
        // A fixed-width tag column keeps the names aligned.
        let tag_size = egui::vec2(30.0, ui.spacing().interact_size.y);
        ui.allocate_ui_with_layout(
            tag_size,
            egui::Layout::left_to_right(egui::Align::Center),
            |ui| {
                ui.set_min_size(tag_size);
                let color = tag_color(tag, colors(ui));
                ui.label(RichText::new(tag).monospace().small().color(color));
            },
        );
        let selected = self.selection == Some(&node);
        let text = if self.dirty.contains(&node) {
            format!("{label} *")
        } else {
            label.to_owned()
        };
        let movable = rename_scope(&node).is_some();
        let mut response = ui.selectable_label(selected, text);
        if movable {
            response = response.interact(egui::Sense::drag());
        }
        if !detail.is_empty() {
            ui.label(RichText::new(detail).weak().small());
        }
        self.row_focused |= response.has_focus();
        if response.double_clicked()
            || (response.has_focus() && ui.input(|i| i.key_pressed(Key::Enter)))
        {
            self.response.opened = Some(node.clone());
        }
        if response.clicked() {
            self.response.clicked = Some(node.clone());
        }
        if movable && response.drag_started() {
            egui::DragAndDrop::set_payload(ui.ctx(), DraggedNode(node.clone()));
        }
        if response.dragged() {
            ui.ctx().set_cursor_icon(egui::CursorIcon::Grabbing);
            drag_preview(ui.ctx(), label);
        }
        self.drop_target(ui, &response, &node);
        response.context_menu(|ui| self.menu(ui, &node));
        response
    }

    /// Shows where a dragged node would land on this row, and reports the drop.
    fn drop_target(&mut self, ui: &Ui, response: &egui::Response, node: &TreeNode) {
        let Some(dragged) = response.dnd_hover_payload::<DraggedNode>() else {
            return;
        };
        if !accepts(&dragged.0, node) {
            return;
        }
        let rect = response.rect;
        let pointer = ui.ctx().pointer_interact_pos().unwrap_or(rect.center());
        let fraction = (pointer.y - rect.top()) / rect.height().max(1.0);
        let place = place_at(node, fraction);
        let stroke = egui::Stroke::new(2.0, ui.visuals().selection.stroke.color);
        let right = ui.clip_rect().right();
        match place {
            DropPlace::Before => {
                ui.painter().hline(rect.left()..=right, rect.top(), stroke);
            }
            DropPlace::After => {
                ui.painter()
                    .hline(rect.left()..=right, rect.bottom(), stroke);
            }
            DropPlace::Into => {
                ui.painter()
                    .rect_stroke(rect, 2.0, stroke, egui::StrokeKind::Outside);
            }
        }
        if let Some(dropped) = response.dnd_release_payload::<DraggedNode>() {
            self.response.actions.push(TreeAction::Move {
                node: dropped.0.clone(),
                target: node.clone(),
                place,
            });
        }
    }

    /// The context menu of a node: what can be added below it and done with it.
    fn menu(&mut self, ui: &mut Ui, node: &TreeNode) {
        let language = self.language;
        let item = |ui: &mut Ui, text: Text| ui.button(text.get(language)).clicked();
        if node.is_document() && item(ui, Text::OpenNode) {
            self.response.opened = Some(node.clone());
        }
        let folder = match node {
            TreeNode::Application => Some(Vec::new()),
            TreeNode::Folder(path) => Some(path.clone()),
            _ => None,
        };
        if let Some(folder) = folder {
            if item(ui, Text::AddPouMenu) {
                self.response.dialog = Some(TreeDialog::new_pou(
                    self.project,
                    folder.clone(),
                    self.body_language,
                ));
            }
            for (text, kind) in [
                (Text::AddGvl, NewObject::Gvl),
                (Text::AddDataType, NewObject::Structure),
                (Text::AddWatchList, NewObject::WatchList),
                (Text::AddTrace, NewObject::Trace),
                (Text::CamAddCam, NewObject::Cam),
            ] {
                if item(ui, text) {
                    self.response.actions.push(TreeAction::AddObject {
                        folder: folder.clone(),
                        kind,
                    });
                }
            }
            if item(ui, Text::AddFolder) {
                self.response.actions.push(TreeAction::AddFolder { folder });
            }
        }
        if let TreeNode::Object(name) = node
            && let Some(Object::Pou(pou)) = self.project.application.object(name)
        {
            for kind in [
                MemberKind::Method,
                MemberKind::Action,
                MemberKind::Transition,
                MemberKind::Property,
            ] {
                if kind.allowed_in(pou.kind) && item(ui, kind.menu_text()) {
                    self.response.dialog = Some(TreeDialog::NewMember(MemberDialog::new(
                        self.project,
                        &pou.name,
                        kind,
                        self.body_language,
                    )));
                }
            }
        }
        let list = match node {
            TreeNode::TaskConfiguration => Some(ListKind::Tasks),
            TreeNode::IoAreas => Some(ListKind::IoAreas),
            TreeNode::SerialPorts => Some(ListKind::SerialPorts),
            TreeNode::ModbusDevices => Some(ListKind::ModbusDevices),
            TreeNode::Axes => Some(ListKind::Axes),
            other => ListKind::of_entry(other).map(|(kind, _)| kind),
        };
        if let Some(kind) = list {
            let text = match kind {
                ListKind::Tasks => Text::AddTask,
                ListKind::IoAreas => Text::AddIoArea,
                ListKind::SerialPorts => Text::AddSerialPort,
                ListKind::ModbusDevices => Text::AddModbusDevice,
                ListKind::Axes => Text::AddAxis,
            };
            if item(ui, text) {
                self.response.actions.push(TreeAction::AddListEntry(kind));
            }
        }
        if rename_scope(node).is_some() {
            ui.separator();
            if item(ui, Text::Rename) {
                self.response.dialog = TreeDialog::rename(node.clone());
            }
            if item(ui, Text::Duplicate) {
                self.response
                    .actions
                    .push(TreeAction::Duplicate(node.clone()));
            }
            if item(ui, Text::Delete) {
                self.response.actions.push(TreeAction::Delete(node.clone()));
            }
        }
    }

    /// A node without children, indented like the children of a branch.
    fn leaf(&mut self, ui: &mut Ui, node: TreeNode, tag: &str, label: &str, detail: &str) {
        ui.horizontal(|ui| {
            ui.add_space(ui.spacing().indent);
            self.row(ui, node, tag, label, detail);
        });
    }

    fn task_configuration(&mut self, ui: &mut Ui, project: &Project, language: Language) {
        let label = Text::TaskConfiguration.get(language);
        self.branch(
            ui,
            TreeNode::TaskConfiguration,
            "CFG",
            label,
            "",
            |tree, ui| {
                for task in &project.tasks {
                    let kind = match &task.kind {
                        TaskKind::Cyclic { interval_us } => format_interval(*interval_us),
                        TaskKind::Freewheeling => Text::TreeFreewheeling.get(language).to_owned(),
                        TaskKind::Event { trigger } => {
                            Text::TreeEventTask.fill(language, &[("trigger", trigger)])
                        }
                    };
                    let detail = format!("{kind} · P{}", task.priority);
                    tree.leaf(
                        ui,
                        TreeNode::Task(task.name.clone()),
                        "TSK",
                        &task.name,
                        &detail,
                    );
                }
            },
        );
    }

    fn folder_children(&mut self, ui: &mut Ui, folder: &Folder, path: &[String]) {
        for node in &folder.children {
            match node {
                Node::Folder(child) => {
                    let mut child_path = path.to_vec();
                    child_path.push(child.name.clone());
                    let tree_node = TreeNode::Folder(child_path.clone());
                    self.branch(ui, tree_node, "DIR", &child.name, "", |tree, ui| {
                        tree.folder_children(ui, child, &child_path);
                    });
                }
                Node::Object(object) => {
                    let node = TreeNode::Object(object.name().to_owned());
                    self.leaf(ui, node, object_tag(object), object.name(), "");
                }
            }
        }
    }

    fn io_areas(&mut self, ui: &mut Ui, project: &Project, language: Language) {
        self.branch(
            ui,
            TreeNode::IoAreas,
            "I/O",
            Text::IoAreas.get(language),
            "",
            |tree, ui| {
                for area in &project.io_areas {
                    let letter = area.direction.area_letter();
                    let last = area.start_byte + area.size_bytes.saturating_sub(1);
                    let detail = format!("%{letter}B{}..%{letter}B{last}", area.start_byte);
                    let tag = match area.direction {
                        IoDirection::Input => "IN",
                        IoDirection::Output => "OUT",
                        IoDirection::Memory => "MEM",
                    };
                    tree.leaf(
                        ui,
                        TreeNode::IoArea(area.name.clone()),
                        tag,
                        &area.name,
                        &detail,
                    );
                }
            },
        );
    }

    fn serial_ports(&mut self, ui: &mut Ui, project: &Project, language: Language) {
        let label = Text::SerialPorts.get(language);
        self.branch(ui, TreeNode::SerialPorts, "COM", label, "", |tree, ui| {
            for port in &project.serial_ports {
                let detail = format!("{} · {}", port.device, line_settings(port));
                tree.leaf(
                    ui,
                    TreeNode::SerialPort(port.name.clone()),
                    "COM",
                    &port.name,
                    &detail,
                );
            }
        });
    }

    fn modbus_devices(&mut self, ui: &mut Ui, project: &Project, language: Language) {
        let label = Text::ModbusDevices.get(language);
        self.branch(ui, TreeNode::ModbusDevices, "MB", label, "", |tree, ui| {
            for device in &project.modbus_devices {
                let detail = format!("{} #{}", device.link, device.unit_id);
                let node = TreeNode::ModbusDevice(device.name.clone());
                let device_states = tree.device_states;
                let Some(shown) = device_states.get(&device.name) else {
                    tree.leaf(ui, node, "MB", &device.name, &detail);
                    continue;
                };
                // A runtime device while logged in: its state as an icon in the indentation
                // before the tag, where a narrow pane does not cut it off and the names stay
                // aligned, and its counters on hovering the icon or the name.
                ui.horizontal(|ui| {
                    // Laid out as a leaf, the icon painted in the indentation.
                    let left = ui.cursor().min.x;
                    let indent = ui.spacing().indent;
                    ui.add_space(indent);
                    let row = tree.row(ui, node, "MB", &device.name, &detail);
                    let center = egui::pos2(left + indent / 2.0, row.rect.center().y);
                    let icon = device_icon_ui(ui, center, &device.name, shown);
                    for response in [row, icon] {
                        response.on_hover_ui(|ui| device_tooltip_ui(ui, &device.name, shown));
                    }
                });
            }
        });
    }

    fn axes(&mut self, ui: &mut Ui, project: &Project, language: Language) {
        self.branch(
            ui,
            TreeNode::Axes,
            "AX",
            Text::Axes.get(language),
            "",
            |tree, ui| {
                for axis in &project.axes {
                    let detail = match axis.modulo_period {
                        Some(period) => Text::TreeModuloAxis.fill(
                            language,
                            &[("period", &period.to_string()), ("unit", &axis.unit)],
                        ),
                        None => Text::TreeLinearAxis.fill(language, &[("unit", &axis.unit)]),
                    };
                    tree.leaf(
                        ui,
                        TreeNode::Axis(axis.name.clone()),
                        "AX",
                        &axis.name,
                        &detail,
                    );
                }
            },
        );
    }
}

/// The side of a runtime device's state icon, in points.
const DEVICE_ICON_SIZE: f32 = 12.0;

/// A runtime device's state as a small icon in the theme's colour of its light, its shape
/// telling the lights apart without colour: a disc (communicating), a triangle (failing), a
/// ring (off) and a ring with a dot (waiting), centred on `center`. Its accessible label is
/// "NAME: STATE".
fn device_icon_ui(
    ui: &mut Ui,
    center: egui::Pos2,
    name: &str,
    shown: &DeviceOnline,
) -> egui::Response {
    let size = egui::vec2(DEVICE_ICON_SIZE, DEVICE_ICON_SIZE);
    let rect = egui::Rect::from_center_size(center, size);
    let id = ui.scope_id().with(("device state icon", name));
    let response = ui.interact(rect, id, egui::Sense::hover());
    let label = format!("{name}: {}", shown.state);
    response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Image, true, &label));
    let color = shown.light.color(colors(ui));
    let painter = ui.painter();
    let center = rect.center();
    let radius = 4.5;
    match shown.light {
        DeviceLight::Communicating => {
            painter.circle_filled(center, radius, color);
        }
        DeviceLight::Failing => {
            let points = vec![
                center + egui::vec2(0.0, -radius - 0.5),
                center + egui::vec2(radius + 0.5, radius),
                center + egui::vec2(-radius - 0.5, radius),
            ];
            painter.add(egui::Shape::convex_polygon(
                points,
                color,
                egui::Stroke::NONE,
            ));
        }
        DeviceLight::Off => {
            painter.circle_stroke(center, radius, egui::Stroke::new(1.5, color));
        }
        DeviceLight::Waiting => {
            painter.circle_stroke(center, radius, egui::Stroke::new(1.5, color));
            painter.circle_filled(center, 1.5, color);
        }
    }
    response
}

/// A runtime device's tooltip: its name and state, then the last error and the counters.
fn device_tooltip_ui(ui: &mut Ui, name: &str, shown: &DeviceOnline) {
    let color = shown.light.color(colors(ui));
    ui.label(
        RichText::new(format!("{name}: {}", shown.state))
            .strong()
            .color(color),
    );
    if shown.rows.is_empty() {
        return;
    }
    egui::Grid::new(("device tooltip", name))
        .num_columns(2)
        .spacing([12.0, 2.0])
        .show(ui, |ui| {
            for (label, value) in &shown.rows {
                ui.label(RichText::new(label).weak());
                ui.label(value);
                ui.end_row();
            }
        });
}

/// The name of the dragged node beside the pointer, so the user sees what is being moved.
fn drag_preview(ctx: &egui::Context, label: &str) {
    let Some(pointer) = ctx.pointer_interact_pos() else {
        return;
    };
    egui::Area::new(egui::Id::unique("device_tree_drag_preview"))
        .order(egui::Order::Tooltip)
        .interactable(false)
        .fixed_pos(pointer + egui::vec2(14.0, 4.0))
        .show(ctx, |ui| {
            egui::Frame::popup(ui.style()).show(ui, |ui| {
                ui.label(label);
            });
        });
}

/// A port's line settings as PLC engineers write them: `19200-8E1`.
fn line_settings(port: &SerialPort) -> String {
    let parity = match port.parity {
        Parity::None => 'N',
        Parity::Even => 'E',
        Parity::Odd => 'O',
    };
    format!(
        "{}-{}{parity}{}",
        port.baud_rate, port.data_bits, port.stop_bits
    )
}

/// `10000` µs as `10 ms`, `500` as `500 µs`.
fn format_interval(interval_us: u32) -> String {
    if interval_us.is_multiple_of(1000) {
        format!("{} ms", interval_us / 1000)
    } else {
        format!("{interval_us} µs")
    }
}

/// A colour per tag family, so kinds are told apart at a glance.
fn tag_color(tag: &str, colors: &StudioColors) -> Color32 {
    match tag {
        "PRG" => colors.tag_program,
        "FB" => colors.tag_function_block,
        "FUN" => colors.tag_function,
        "GVL" | "DUT" | "ITF" => colors.tag_data,
        "CAM" | "AX" => colors.tag_motion,
        "TSK" | "CFG" => colors.tag_task,
        _ => colors.tag_other,
    }
}
