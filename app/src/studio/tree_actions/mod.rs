//! Editing the device tree: what the user asked for ([`TreeAction`]) and the edits that do it
//! ([`Plan`]), plus the state the tree keeps between frames (its dialog and dirty markers).
//!
//! Planning reads the project and never changes it; the studio applies a plan's edits after the
//! frame as one undo step, as every other view does.

mod action;
mod body_language;
mod dialog;
mod dialog_fields;
mod dirty;
mod lists;
mod member_dialog;
mod members;
mod moves;
mod names;
mod new_objects;
mod plan_step;
mod refusal;
#[cfg(test)]
mod tests;

use project_model::{Edit, EditError, Folder, Node, Object, PouKind, Project, TreeEdit};

pub use action::{TreeAction, rename_scope};
pub use body_language::BodyLanguage;
pub use dialog::{DialogOutcome, TreeDialog};
pub use dirty::DirtyMarkers;
pub use lists::ListKind;
pub use member_dialog::MemberDialog;
pub use members::MemberKind;
pub use moves::{DropPlace, accepts, place_at, plan_move};
pub use names::{NameScope, name_problem, unique_name};
pub use new_objects::NewObject;
pub use plan_step::{Plan, locate};
pub use refusal::Refusal;

use self::members::plan_add_member;
use self::new_objects::{new_pou, pou_kind_description};
use super::i18n::{Language, Text};
use super::tree_node::TreeNode;

/// What the device tree keeps between frames.
#[derive(Default)]
pub struct TreeEditState {
    /// The dialog open over the tree, if any.
    pub dialog: Option<TreeDialog>,
    /// Which nodes differ from the saved project.
    pub dirty: DirtyMarkers,
    /// The implementation language chosen in the last confirmed add dialog, which the next one
    /// proposes (as CODESYS does); kept for the session, not saved.
    pub body_language: BodyLanguage,
}

/// The edits that carry out `action` on `project`, labelled in `language`: `Ok(None)` when it
/// changes nothing, or why it cannot be done.
pub fn plan(
    project: &Project,
    action: &TreeAction,
    language: Language,
) -> Result<Option<Plan>, Refusal> {
    match action {
        TreeAction::AddPou {
            folder,
            kind,
            name,
            return_type,
            language: body_language,
        } => {
            if let Some(problem) = name_problem(project, NameScope::Object, name, None) {
                return Err(problem);
            }
            if *kind == PouKind::Function && *body_language == BodyLanguage::Sfc {
                return Err(Refusal::SfcNotHere);
            }
            let pou = new_pou(name.clone(), *kind, return_type.clone(), *body_language);
            Ok(Some(add_object(
                project,
                folder,
                Object::Pou(pou),
                pou_kind_description(*kind).get(language),
                language,
            )?))
        }
        TreeAction::AddMember { pou, member } => {
            plan_add_member(project, pou, member, language).map(Some)
        }
        TreeAction::AddObject { folder, kind } => {
            let name = unique_name(kind.base_name(), |name| {
                NameScope::Object.is_taken(project, name, None)
            });
            let object = kind.build(project, name);
            Ok(Some(add_object(
                project,
                folder,
                object,
                kind.description().get(language),
                language,
            )?))
        }
        TreeAction::AddFolder { folder } => {
            let parent = existing_folder(project, folder)?;
            let name = unique_name("Folder", |name| {
                NameScope::Folder(folder).is_taken(project, name, None)
            });
            let mut path = folder.clone();
            path.push(name.clone());
            Ok(Some(Plan {
                label: Text::UndoAddFolder.fill(language, &[("name", &name)]),
                edits: vec![Edit::Tree(TreeEdit::Insert {
                    folder: folder.clone(),
                    index: parent.children.len(),
                    node: Node::Folder(Folder {
                        name,
                        children: Vec::new(),
                    }),
                })],
                open: None,
                select: Some(TreeNode::Folder(path)),
                part: None,
            }))
        }
        TreeAction::AddListEntry(kind) => {
            let (edit, name) = kind.add(project);
            Ok(Some(Plan {
                label: Text::UndoAdd.fill(
                    language,
                    &[("kind", kind.noun().get(language)), ("name", &name)],
                ),
                edits: vec![edit],
                open: Some(kind.entry(name)),
                select: None,
                part: None,
            }))
        }
        TreeAction::Rename { node, name } => plan_rename(project, node, name, language),
        TreeAction::Duplicate(node) => plan_duplicate(project, node, language).map(Some),
        TreeAction::Delete(node) => plan_delete(project, node, language).map(Some),
        TreeAction::Move {
            node,
            target,
            place,
        } => plan_move(project, node, target, *place, language),
    }
}

fn existing_folder<'a>(project: &'a Project, path: &[String]) -> Result<&'a Folder, Refusal> {
    project
        .application
        .folder(path)
        .ok_or_else(|| EditError::NoSuchFolder(path.join("/")).into())
}

fn add_object(
    project: &Project,
    folder: &[String],
    object: Object,
    description: &str,
    language: Language,
) -> Result<Plan, Refusal> {
    let parent = existing_folder(project, folder)?;
    let name = object.name().to_owned();
    Ok(Plan {
        label: Text::UndoAdd.fill(language, &[("kind", description), ("name", &name)]),
        edits: vec![Edit::Tree(TreeEdit::Insert {
            folder: folder.to_vec(),
            index: parent.children.len(),
            node: Node::Object(object),
        })],
        open: Some(TreeNode::Object(name)),
        select: None,
        part: None,
    })
}

fn missing(project: &Project, node: &TreeNode) -> Refusal {
    EditError::NoSuchObject(node.title(Some(project))).into()
}

fn plan_rename(
    project: &Project,
    node: &TreeNode,
    name: &str,
    language: Language,
) -> Result<Option<Plan>, Refusal> {
    let (scope, old) = rename_scope(node).ok_or_else(|| missing(project, node))?;
    if old == name {
        return Ok(None);
    }
    if let Some(problem) = name_problem(project, scope, name, Some(old)) {
        return Err(problem);
    }
    let label = Text::UndoRename.fill(language, &[("old", old), ("name", name)]);
    if let Some((kind, _)) = ListKind::of_entry(node) {
        let index = kind
            .index_of(project, old)
            .ok_or_else(|| missing(project, node))?;
        let edit = kind
            .renamed(project, index, name)
            .ok_or_else(|| missing(project, node))?;
        let mut edits = vec![edit];
        // The devices on a renamed serial port follow it, and the devices, axes and traces of
        // a renamed task follow the task, in the same undo step.
        match kind {
            ListKind::SerialPorts => {
                edits.extend(project_model::serial_port_rename_edits(project, old, name));
            }
            ListKind::Tasks => {
                edits.extend(project_model::task_rename_edits(project, old, name));
            }
            _ => {}
        }
        return Ok(Some(Plan {
            label,
            edits,
            open: None,
            select: Some(kind.entry(name.to_owned())),
            part: None,
        }));
    }
    let (folder, index) = locate(project, node).ok_or_else(|| missing(project, node))?;
    let mut edits = vec![Edit::Tree(TreeEdit::Rename {
        folder: folder.clone(),
        index,
        name: name.to_owned(),
    })];
    let select = match node {
        TreeNode::Folder(_) => {
            let mut path = folder;
            path.push(name.to_owned());
            TreeNode::Folder(path)
        }
        _ => {
            // Tasks call programs by name: they follow the rename in the same undo step, so
            // renaming a program never leaves a task calling one that does not exist.
            edits.extend(task_calls_renamed(project, old, name));
            TreeNode::Object(name.to_owned())
        }
    };
    Ok(Some(Plan {
        label,
        edits,
        open: None,
        select: Some(select),
        part: None,
    }))
}

/// The task edits that make calls of program `old` call `new`.
fn task_calls_renamed(project: &Project, old: &str, new: &str) -> Vec<Edit> {
    let is_program = matches!(
        project.application.object(old),
        Some(Object::Pou(pou)) if pou.kind == PouKind::Program
    );
    if !is_program {
        return Vec::new();
    }
    project
        .tasks
        .iter()
        .enumerate()
        .filter(|(_, task)| {
            task.programs
                .iter()
                .any(|p| project_model::same_identifier(p, old))
        })
        .map(|(index, task)| {
            let mut item = task.clone();
            for program in &mut item.programs {
                if project_model::same_identifier(program, old) {
                    *program = new.to_owned();
                }
            }
            Edit::Tasks(project_model::ListEdit::Replace { index, item })
        })
        .collect()
}

fn plan_duplicate(project: &Project, node: &TreeNode, language: Language) -> Result<Plan, Refusal> {
    if let Some((kind, name)) = ListKind::of_entry(node) {
        let index = kind
            .index_of(project, name)
            .ok_or_else(|| missing(project, node))?;
        let copy = kind.fresh_name(project, name);
        let edit = kind
            .duplicated(project, index, &copy)
            .ok_or_else(|| missing(project, node))?;
        return Ok(Plan {
            label: Text::UndoDuplicate.fill(language, &[("name", name), ("copy", &copy)]),
            edits: vec![edit],
            open: None,
            select: Some(kind.entry(copy)),
            part: None,
        });
    }
    let (folder, index) = locate(project, node).ok_or_else(|| missing(project, node))?;
    let original = existing_folder(project, &folder)?
        .children
        .get(index)
        .ok_or_else(|| missing(project, node))?;
    let mut copy = original.clone();
    // Object names are global: every object in the copy needs a new one, different from the
    // project's names and from the copy's other new names.
    let mut chosen: Vec<String> = Vec::new();
    let mut fresh_object_name = |object: &mut Object| {
        let name = unique_name(object.name(), |candidate| {
            NameScope::Object.is_taken(project, candidate, None)
                || chosen
                    .iter()
                    .any(|other| project_model::same_identifier(other, candidate))
        });
        chosen.push(name.clone());
        object.set_name(name);
    };
    let (copy_name, select) = match &mut copy {
        Node::Object(object) => {
            fresh_object_name(object);
            let name = object.name().to_owned();
            (name.clone(), TreeNode::Object(name))
        }
        Node::Folder(copied) => {
            let name = unique_name(&copied.name, |candidate| {
                NameScope::Folder(&folder).is_taken(project, candidate, None)
            });
            copied.name = name.clone();
            rename_objects(copied, &mut fresh_object_name);
            let mut path = folder.clone();
            path.push(name.clone());
            (name, TreeNode::Folder(path))
        }
    };
    Ok(Plan {
        label: Text::UndoDuplicate
            .fill(language, &[("name", original.name()), ("copy", &copy_name)]),
        edits: vec![Edit::Tree(TreeEdit::Insert {
            folder,
            index: index + 1,
            node: copy,
        })],
        open: None,
        select: Some(select),
        part: None,
    })
}

fn rename_objects(folder: &mut Folder, rename: &mut impl FnMut(&mut Object)) {
    for child in &mut folder.children {
        match child {
            Node::Object(object) => rename(object),
            Node::Folder(sub) => rename_objects(sub, rename),
        }
    }
}

fn plan_delete(project: &Project, node: &TreeNode, language: Language) -> Result<Plan, Refusal> {
    let name = node.title(Some(project));
    let edit = if let Some((kind, entry)) = ListKind::of_entry(node) {
        // A port the devices still name stays: deleting it would leave them dangling.
        if kind == ListKind::SerialPorts {
            let devices = project.devices_on_serial_port(entry);
            if !devices.is_empty() {
                return Err(Refusal::SerialPortInUse(
                    entry.to_owned(),
                    devices.into_iter().map(str::to_owned).collect(),
                ));
            }
        }
        let index = kind
            .index_of(project, entry)
            .ok_or_else(|| missing(project, node))?;
        kind.removed(index)
    } else {
        let (folder, index) = locate(project, node).ok_or_else(|| missing(project, node))?;
        Edit::Tree(TreeEdit::Remove { folder, index })
    };
    Ok(Plan {
        label: Text::UndoDelete.fill(language, &[("name", &name)]),
        edits: vec![edit],
        open: None,
        select: None,
        part: None,
    })
}
