//! Dirty markers: which device tree nodes differ from the project as last saved.

use std::collections::HashSet;
use std::sync::Arc;

use project_model::{Folder, Node, Project};

use crate::studio::tree_node::TreeNode;

/// The set of nodes whose content differs from the saved project, computed once per project
/// revision and saved snapshot, so drawing a large tree every frame stays cheap.
#[derive(Default)]
pub struct DirtyMarkers {
    /// The revision and saved snapshot the set was computed for.
    computed_for: Option<(u64, Arc<Project>)>,
    dirty: HashSet<TreeNode>,
}

impl DirtyMarkers {
    /// The dirty nodes of `project` (at `revision`) compared with `saved`.
    pub fn get(
        &mut self,
        project: &Project,
        revision: u64,
        saved: &Arc<Project>,
    ) -> &HashSet<TreeNode> {
        let current = self
            .computed_for
            .as_ref()
            .is_some_and(|(r, s)| *r == revision && Arc::ptr_eq(s, saved));
        if !current {
            self.dirty = dirty_nodes(project, saved);
            self.computed_for = Some((revision, Arc::clone(saved)));
        }
        &self.dirty
    }
}

/// Compares every node with its saved version. Objects and list entries are dirty when their
/// content (or, for objects, their folder) changed or they are new; folders and the lists
/// themselves when their children were added, removed or reordered.
pub fn dirty_nodes(project: &Project, saved: &Project) -> HashSet<TreeNode> {
    let mut dirty = HashSet::new();
    if project.controller != saved.controller
        || project.name != saved.name
        || project.description != saved.description
    {
        dirty.insert(TreeNode::Controller);
    }
    compare_list(
        &mut dirty,
        &project.tasks,
        &saved.tasks,
        |t| &t.name,
        TreeNode::TaskConfiguration,
        TreeNode::Task,
    );
    compare_list(
        &mut dirty,
        &project.io_areas,
        &saved.io_areas,
        |a| &a.name,
        TreeNode::IoAreas,
        TreeNode::IoArea,
    );
    compare_list(
        &mut dirty,
        &project.serial_ports,
        &saved.serial_ports,
        |p| &p.name,
        TreeNode::SerialPorts,
        TreeNode::SerialPort,
    );
    compare_list(
        &mut dirty,
        &project.modbus_devices,
        &saved.modbus_devices,
        |d| &d.name,
        TreeNode::ModbusDevices,
        TreeNode::ModbusDevice,
    );
    compare_list(
        &mut dirty,
        &project.axes,
        &saved.axes,
        |a| &a.name,
        TreeNode::Axes,
        TreeNode::Axis,
    );
    compare_folder(&mut dirty, &project.application, saved, &mut Vec::new());
    dirty
}

fn compare_list<T: PartialEq>(
    dirty: &mut HashSet<TreeNode>,
    items: &[T],
    saved: &[T],
    name: impl Fn(&T) -> &String,
    list_node: TreeNode,
    entry_node: impl Fn(String) -> TreeNode,
) {
    let names = |list: &[T]| list.iter().map(&name).cloned().collect::<Vec<_>>();
    if names(items) != names(saved) {
        dirty.insert(list_node);
    }
    for item in items {
        if !saved.iter().any(|old| old == item) {
            dirty.insert(entry_node(name(item).clone()));
        }
    }
}

fn compare_folder(
    dirty: &mut HashSet<TreeNode>,
    folder: &Folder,
    saved: &Project,
    path: &mut Vec<String>,
) {
    let saved_folder = saved.application.folder(path);
    let children = |folder: &Folder| {
        folder
            .children
            .iter()
            .map(|node| (matches!(node, Node::Folder(_)), node.name().to_owned()))
            .collect::<Vec<_>>()
    };
    if saved_folder.is_none_or(|old| children(old) != children(folder)) {
        dirty.insert(if path.is_empty() {
            TreeNode::Application
        } else {
            TreeNode::Folder(path.clone())
        });
    }
    for node in &folder.children {
        match node {
            Node::Folder(child) => {
                path.push(child.name.clone());
                compare_folder(dirty, child, saved, path);
                path.pop();
            }
            Node::Object(object) => {
                let unchanged = saved_folder.is_some_and(|old| {
                    old.children
                        .iter()
                        .any(|old| matches!(old, Node::Object(o) if o == object))
                });
                if !unchanged {
                    dirty.insert(TreeNode::Object(object.name().to_owned()));
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use project_model::{GlobalVarList, Object};

    #[test]
    fn a_changed_object_and_its_folder_are_marked_and_nothing_else() {
        let mut saved = Project::default();
        saved.application.children = vec![Node::Object(Object::Gvl(GlobalVarList {
            name: "GVL_A".into(),
            ..GlobalVarList::default()
        }))];
        assert!(dirty_nodes(&saved, &saved).is_empty());

        let mut edited = saved.clone();
        if let Some(Object::Gvl(gvl)) = edited.application.object_mut("GVL_A") {
            gvl.comment = "changed".into();
        }
        assert_eq!(
            dirty_nodes(&edited, &saved),
            HashSet::from([TreeNode::Object("GVL_A".into())])
        );

        edited.application.children.push(Node::Folder(Folder {
            name: "New".into(),
            children: Vec::new(),
        }));
        let dirty = dirty_nodes(&edited, &saved);
        assert!(dirty.contains(&TreeNode::Application));
        assert!(dirty.contains(&TreeNode::Folder(vec!["New".into()])));
    }
}
