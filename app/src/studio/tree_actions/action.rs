//! The changes of the device tree the user can ask for.

use project_model::PouKind;

use super::body_language::BodyLanguage;
use super::lists::ListKind;
use super::members::NewMember;
use super::moves::DropPlace;
use super::names::NameScope;
use super::new_objects::NewObject;
use crate::studio::tree_node::TreeNode;

/// A change of the device tree the user asked for.
#[derive(Clone, Debug, PartialEq)]
pub enum TreeAction {
    /// Adds a POU with an empty body to `folder`.
    AddPou {
        /// The folder's path (empty for the application).
        folder: Vec<String>,
        /// Program, function block or function.
        kind: PouKind,
        /// The name, already checked by the dialog.
        name: String,
        /// A function's return type.
        return_type: Option<String>,
        /// The language of its body.
        language: BodyLanguage,
    },
    /// Adds a method, action or property to a program or function block.
    AddMember {
        /// The POU's name.
        pou: String,
        /// What to add.
        member: NewMember,
    },
    /// Adds an object with a fresh default name to `folder`.
    AddObject {
        /// The folder's path.
        folder: Vec<String>,
        /// What to add.
        kind: NewObject,
    },
    /// Adds a folder with a fresh default name to `folder`.
    AddFolder {
        /// The parent folder's path.
        folder: Vec<String>,
    },
    /// Appends an entry with a fresh default name to a list of the device tree.
    AddListEntry(ListKind),
    /// Gives a node another name.
    Rename {
        /// The node.
        node: TreeNode,
        /// The new name.
        name: String,
    },
    /// Copies a node, with a fresh name, right after it.
    Duplicate(TreeNode),
    /// Deletes a node (undoable, like everything else).
    Delete(TreeNode),
    /// Moves a node to where it was dropped.
    Move {
        /// The dragged node.
        node: TreeNode,
        /// The node it was dropped on.
        target: TreeNode,
        /// Where, relative to the target.
        place: DropPlace,
    },
}

impl TreeAction {
    /// The implementation language the action creates a body in, if it creates one; the next
    /// add dialog proposes it.
    pub fn body_language(&self) -> Option<BodyLanguage> {
        match self {
            Self::AddPou { language, .. } => Some(*language),
            Self::AddMember { member, .. } => Some(member.language),
            _ => None,
        }
    }
}

/// The name scope a node's name lives in, and its current name; `None` for nodes that cannot
/// be renamed.
pub fn rename_scope<'a>(node: &'a TreeNode) -> Option<(NameScope<'a>, &'a str)> {
    match node {
        TreeNode::Object(name) => Some((NameScope::Object, name)),
        TreeNode::Folder(path) => {
            let (last, parent) = path.split_last()?;
            Some((NameScope::Folder(parent), last))
        }
        other => ListKind::of_entry(other).map(|(kind, name)| (kind.scope(), name)),
    }
}
