//! Keeping document tabs in step with the project: a tab whose node left the project closes.

use project_model::Project;

use super::dock::Dock;
use super::tree_node::TreeNode;

/// Whether `node` still names something in `project`.
pub fn node_exists(project: &Project, node: &TreeNode) -> bool {
    match node {
        TreeNode::Controller
        | TreeNode::TaskConfiguration
        | TreeNode::Application
        | TreeNode::IoAreas
        | TreeNode::ModbusDevices
        | TreeNode::Axes
        | TreeNode::SerialPorts => true,
        TreeNode::Task(name) => project.task(name).is_some(),
        TreeNode::Object(name) => project.application.object(name).is_some(),
        TreeNode::Folder(_) => true,
        TreeNode::IoArea(name) => project.io_areas.iter().any(|area| area.name == *name),
        TreeNode::ModbusDevice(name) => project.modbus_devices.iter().any(|d| d.name == *name),
        TreeNode::Axis(name) => project.axes.iter().any(|axis| axis.name == *name),
        TreeNode::SerialPort(name) => project.serial_ports.iter().any(|port| port.name == *name),
    }
}

/// Closes the tabs of documents that are no longer part of `project` (after an undo of their
/// creation, a delete, or opening another project).
pub fn close_stale_documents(dock: &mut Dock, project: &Project) {
    if dock
        .documents()
        .iter()
        .any(|node| !node_exists(project, node))
    {
        dock.retain_documents(|node| node_exists(project, node));
    }
}
