//! The places "find references" found, which the messages pane lists.

use std::ops::Range;

use project_model::TextTarget;

use super::tree_node::TreeNode;

/// A place found by "find references", listed in the messages pane.
#[derive(Clone, Debug, PartialEq)]
pub struct ReferenceItem {
    /// `file:line: text of the line`.
    pub label: String,
    /// The document.
    pub node: TreeNode,
    /// The body and range.
    pub target: TextTarget,
    /// The name's byte range.
    pub range: Range<usize>,
}

/// The results of the last "find references"; kept until the next search or another project,
/// never saved.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct References {
    /// The places found, in project order.
    pub items: Vec<ReferenceItem>,
    /// The name the references are of.
    pub of: String,
}
