//! The device tree panel: controller, tasks, application, I/O, Modbus devices and axes.

use egui::collapsing_header::CollapsingState;
use egui::{Color32, RichText, Ui};
use project_model::{Folder, IoDirection, Node, Project, TaskKind};

use super::i18n::{Language, Text};
use super::tree_node::{TreeNode, object_tag};

/// What the user did in the tree this frame.
#[derive(Debug, Default)]
pub struct TreeResponse {
    /// A node was clicked.
    pub clicked: Option<TreeNode>,
    /// A node was double-clicked (or Enter was pressed on it): open it.
    pub opened: Option<TreeNode>,
}

/// Draws the device tree of `project` and reports clicks; it never changes the project.
pub fn device_tree_ui(
    ui: &mut Ui,
    project: &Project,
    selection: Option<&TreeNode>,
    language: Language,
) -> TreeResponse {
    let mut tree = TreeUi {
        selection,
        response: TreeResponse::default(),
    };
    egui::ScrollArea::both()
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
                    tree.modbus_devices(ui, project, language);
                    tree.axes(ui, project, language);
                },
            );
        });
    tree.response
}

struct TreeUi<'a> {
    selection: Option<&'a TreeNode>,
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
            .show_header(ui, |ui| self.row(ui, node, tag, label, detail))
            .body(|ui| children(self, ui));
    }

    /// One selectable row: a tag, the name (the row's accessible label) and a weak detail.
    fn row(&mut self, ui: &mut Ui, node: TreeNode, tag: &str, label: &str, detail: &str) {
        // A fixed-width tag column keeps the names aligned.
        let tag_size = egui::vec2(30.0, ui.spacing().interact_size.y);
        ui.allocate_ui_with_layout(
            tag_size,
            egui::Layout::left_to_right(egui::Align::Center),
            |ui| {
                ui.set_min_size(tag_size);
                ui.label(RichText::new(tag).monospace().small().color(tag_color(tag)));
            },
        );
        let selected = self.selection == Some(&node);
        let response = ui.selectable_label(selected, label);
        if !detail.is_empty() {
            ui.label(RichText::new(detail).weak().small());
        }
        if response.double_clicked()
            || (response.has_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter)))
        {
            self.response.opened = Some(node.clone());
        }
        if response.clicked() {
            self.response.clicked = Some(node);
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
                        TaskKind::Freewheeling => "freewheeling".to_owned(),
                        TaskKind::Event { trigger } => format!("event {trigger}"),
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

    fn modbus_devices(&mut self, ui: &mut Ui, project: &Project, language: Language) {
        let label = Text::ModbusDevices.get(language);
        self.branch(ui, TreeNode::ModbusDevices, "MB", label, "", |tree, ui| {
            for device in &project.modbus_devices {
                let detail = format!("{}:{} #{}", device.host, device.port, device.unit_id);
                tree.leaf(
                    ui,
                    TreeNode::ModbusDevice(device.name.clone()),
                    "MB",
                    &device.name,
                    &detail,
                );
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
                        Some(period) => format!("modulo {period} {}", axis.unit),
                        None => format!("linear, {}", axis.unit),
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

/// `10000` µs as `10 ms`, `500` as `500 µs`.
fn format_interval(interval_us: u32) -> String {
    if interval_us.is_multiple_of(1000) {
        format!("{} ms", interval_us / 1000)
    } else {
        format!("{interval_us} µs")
    }
}

/// A colour per tag family, so kinds are told apart at a glance.
fn tag_color(tag: &str) -> Color32 {
    match tag {
        "PRG" => Color32::from_rgb(90, 160, 230),
        "FB" => Color32::from_rgb(120, 190, 120),
        "FUN" => Color32::from_rgb(200, 160, 80),
        "GVL" | "DUT" | "ITF" => Color32::from_rgb(170, 130, 210),
        "CAM" | "AX" => Color32::from_rgb(230, 120, 100),
        "TSK" | "CFG" => Color32::from_rgb(100, 180, 180),
        _ => Color32::GRAY,
    }
}
