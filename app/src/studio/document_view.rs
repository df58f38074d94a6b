//! What a document tab shows: POUs, variable lists and types as IEC text; everything else as a
//! property grid.

use editor::CodeView;
use egui::{RichText, Ui};
use project_model::{Object, Project};

use super::i18n::{Language, Text};
use super::property_view::property_view_ui;
use super::tree_node::TreeNode;

/// Draws the document `node` of `project`, read-only.
pub fn document_ui(ui: &mut Ui, project: &Project, node: &TreeNode, language: Language) {
    egui::ScrollArea::both()
        .id_salt(("document", node))
        .auto_shrink([false, false])
        .show(ui, |ui| {
            ui.add_space(4.0);
            match document_content(project, node) {
                Some(content) => content_ui(ui, node, content),
                None => {
                    ui.label(
                        RichText::new(
                            Text::NoLongerInProject
                                .get(language)
                                .replace("{name}", &node.title(Some(project))),
                        )
                        .color(ui.visuals().warn_fg_color),
                    );
                }
            }
        });
}

/// The model data a document shows.
enum Content<'a> {
    Object(&'a Object),
    Controller(&'a project_model::Controller),
    IoArea(&'a project_model::IoArea),
    SerialPort(&'a project_model::SerialPort),
    ModbusDevice(&'a project_model::ModbusDevice),
    Axis(&'a project_model::Axis),
}

fn document_content<'a>(project: &'a Project, node: &TreeNode) -> Option<Content<'a>> {
    match node {
        TreeNode::Object(name) => project.application.object(name).map(Content::Object),
        TreeNode::Controller => Some(Content::Controller(&project.controller)),
        TreeNode::IoArea(name) => project
            .io_areas
            .iter()
            .find(|a| a.name == *name)
            .map(Content::IoArea),
        TreeNode::SerialPort(name) => project
            .serial_ports
            .iter()
            .find(|p| p.name == *name)
            .map(Content::SerialPort),
        TreeNode::ModbusDevice(name) => project
            .modbus_devices
            .iter()
            .find(|d| d.name == *name)
            .map(Content::ModbusDevice),
        TreeNode::Axis(name) => project
            .axes
            .iter()
            .find(|a| a.name == *name)
            .map(Content::Axis),
        _ => None,
    }
}

fn content_ui(ui: &mut Ui, node: &TreeNode, content: Content<'_>) {
    let salt = format!("{node:?}");
    match content {
        // POUs and global variable lists are edited in place (`text_documents`), and the
        // settings of the device nodes are shown by `settings_ui` with their I/O mapping.
        Content::Object(Object::Pou(_) | Object::Gvl(_)) => {}
        Content::Object(Object::DataType(data_type)) => {
            CodeView::new((&salt, "decl"), &data_type.declaration_text()).show(ui);
        }
        // Cam tables are edited in place (`cam_documents`), which needs the studio to queue
        // their edits; they never reach this view.
        Content::Object(Object::CamTable(_)) => {}
        Content::Object(Object::Trace(trace)) => property_view_ui(ui, &salt, trace),
        Content::Object(Object::WatchList(watch)) => property_view_ui(ui, &salt, watch),
        Content::Controller(_)
        | Content::IoArea(_)
        | Content::SerialPort(_)
        | Content::ModbusDevice(_) => {}
        Content::Axis(axis) => property_view_ui(ui, &salt, axis),
    }
}

/// The settings of a device tree node that has some (controller, task, I/O area, serial port,
/// Modbus device, axis) as a property grid; `false` when the node has none.
pub fn settings_ui(ui: &mut Ui, project: &Project, node: &TreeNode) -> bool {
    let salt = format!("settings {node:?}");
    if let TreeNode::Task(name) = node {
        return match project.task(name) {
            Some(task) => {
                property_view_ui(ui, &salt, task);
                true
            }
            None => false,
        };
    }
    match document_content(project, node) {
        Some(Content::Controller(controller)) => property_view_ui(ui, &salt, controller),
        Some(Content::IoArea(area)) => property_view_ui(ui, &salt, area),
        Some(Content::SerialPort(port)) => property_view_ui(ui, &salt, port),
        Some(Content::ModbusDevice(device)) => property_view_ui(ui, &salt, device),
        Some(Content::Axis(axis)) => property_view_ui(ui, &salt, axis),
        Some(Content::Object(_)) | None => return false,
    }
    true
}
