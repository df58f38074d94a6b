//! The edits that carry out a tree action, and where application nodes are.

use project_model::{Edit, Node, Project, TextTarget};

use crate::studio::tree_node::TreeNode;

/// The edits that carry out a [`TreeAction`], applied as one undo step named `label`.
#[derive(Clone, Debug, PartialEq)]
pub struct Plan {
    /// What the undo step is called ("Rename FB_Motor to FB_Drive").
    pub label: String,
    /// The edits, in order.
    pub edits: Vec<Edit>,
    /// A node to open in a tab once the edits are applied.
    pub open: Option<TreeNode>,
    /// A node to select once the edits are applied.
    pub select: Option<TreeNode>,
    /// The part of the opened document to show (a new method's body, for instance).
    pub part: Option<TextTarget>,
}

/// The folder path and index of an application node (object or folder).
pub fn locate(project: &Project, node: &TreeNode) -> Option<(Vec<String>, usize)> {
    match node {
        TreeNode::Object(name) => project.application.locate(name),
        TreeNode::Folder(path) => {
            let (last, parent) = path.split_last()?;
            let index = project
                .application
                .folder(parent)?
                .children
                .iter()
                .position(|child| matches!(child, Node::Folder(f) if f.name == *last))?;
            Some((parent.to_vec(), index))
        }
        _ => None,
    }
}
