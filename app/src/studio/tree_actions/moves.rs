//! Moving nodes by drag and drop: which drops are allowed and the edit each one makes.

use project_model::{Edit, EditError, Project, TreeEdit};

use super::lists::ListKind;
use super::plan_step::{Plan, locate};
use super::refusal::Refusal;
use crate::studio::i18n::{Language, Text};
use crate::studio::tree_node::TreeNode;

/// Where a dragged node lands relative to the node it is dropped on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DropPlace {
    /// Just before the target, in the target's folder or list.
    Before,
    /// Just after the target.
    After,
    /// Inside the target folder (or the application), after its last child.
    Into,
}

/// Whether `dragged` may be dropped on `target` at all: application nodes go to the
/// application, its folders and objects; list entries stay in their own list.
pub fn accepts(dragged: &TreeNode, target: &TreeNode) -> bool {
    if dragged == target {
        return false;
    }
    match (dragged, ListKind::of_entry(dragged)) {
        (TreeNode::Object(_) | TreeNode::Folder(_), _) => matches!(
            target,
            TreeNode::Application | TreeNode::Folder(_) | TreeNode::Object(_)
        ),
        (_, Some((kind, _))) => ListKind::of_entry(target).is_some_and(|(other, _)| other == kind),
        _ => false,
    }
}

/// The place a drop at `fraction` of the target row's height (0 at the top) means: folders
/// take drops into themselves except near their top edge; other rows split at half height.
pub fn place_at(target: &TreeNode, fraction: f32) -> DropPlace {
    match target {
        TreeNode::Application => DropPlace::Into,
        TreeNode::Folder(_) if fraction < 0.3 => DropPlace::Before,
        TreeNode::Folder(_) => DropPlace::Into,
        _ if fraction < 0.5 => DropPlace::Before,
        _ => DropPlace::After,
    }
}

/// The edit that drops `dragged` on `target` at `place`, `Ok(None)` when the drop changes
/// nothing, or the reason it is refused.
pub fn plan_move(
    project: &Project,
    dragged: &TreeNode,
    target: &TreeNode,
    place: DropPlace,
    language: Language,
) -> Result<Option<Plan>, Refusal> {
    if !accepts(dragged, target) {
        return Ok(None);
    }
    if let Some((kind, name)) = ListKind::of_entry(dragged) {
        return Ok(plan_list_move(project, kind, name, target, place, language));
    }
    let missing = || Refusal::from(EditError::NoSuchObject(dragged.title(Some(project))));
    let (from_folder, from_index) = locate(project, dragged).ok_or_else(missing)?;
    let (to_folder, slot) = match (target, place) {
        (TreeNode::Application, _) => (Vec::new(), project.application.children.len()),
        (TreeNode::Folder(path), DropPlace::Into) => {
            let folder = project
                .application
                .folder(path)
                .ok_or_else(|| Refusal::from(EditError::NoSuchFolder(path.join("/"))))?;
            (path.clone(), folder.children.len())
        }
        (_, place) => {
            let (folder, index) = locate(project, target).ok_or_else(missing)?;
            let slot = if place == DropPlace::After {
                index + 1
            } else {
                index
            };
            (folder, slot)
        }
    };
    let name = dragged.title(Some(project));
    if let TreeNode::Folder(path) = dragged
        && to_folder.starts_with(path)
    {
        return Err(EditError::MoveIntoItself.into());
    }
    let to_index = if to_folder == from_folder && from_index < slot {
        slot - 1
    } else {
        slot
    };
    if to_folder == from_folder && to_index == from_index {
        return Ok(None);
    }
    let template = match (target, place) {
        (TreeNode::Application, _) => Text::UndoMoveIntoApplication,
        (TreeNode::Folder(_), DropPlace::Into) => Text::UndoMoveInto,
        (_, DropPlace::After) => Text::UndoMoveAfter,
        _ => Text::UndoMoveBefore,
    };
    let label = template.fill(
        language,
        &[("name", &name), ("target", &target.title(Some(project)))],
    );
    let moved = match dragged {
        TreeNode::Folder(_) => {
            let mut path = to_folder.clone();
            path.push(name.clone());
            TreeNode::Folder(path)
        }
        other => other.clone(),
    };
    Ok(Some(Plan {
        label,
        edits: vec![Edit::Tree(TreeEdit::Move {
            from_folder,
            from_index,
            to_folder,
            to_index,
        })],
        open: None,
        select: Some(moved),
        part: None,
    }))
}

fn plan_list_move(
    project: &Project,
    kind: ListKind,
    name: &str,
    target: &TreeNode,
    place: DropPlace,
    language: Language,
) -> Option<Plan> {
    let from = kind.index_of(project, name)?;
    let (_, target_name) = ListKind::of_entry(target)?;
    let index = kind.index_of(project, target_name)?;
    let slot = if place == DropPlace::After {
        index + 1
    } else {
        index
    };
    let to = if from < slot { slot - 1 } else { slot };
    if to == from {
        return None;
    }
    let template = if place == DropPlace::After {
        Text::UndoMoveAfter
    } else {
        Text::UndoMoveBefore
    };
    Some(Plan {
        label: template.fill(language, &[("name", name), ("target", target_name)]),
        edits: vec![kind.moved(from, to)],
        open: None,
        select: Some(kind.entry(name.to_owned())),
        part: None,
    })
}
