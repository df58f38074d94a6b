//! Reversible edits of a project: the only way the studio changes it.
//!
//! Every edit's [`Edit::apply`] returns the edit that undoes it, so undo and redo never store
//! snapshots of the project. An edit that cannot be applied leaves the project unchanged.

use std::ops::Range;

use thiserror::Error;

use crate::chart_replace::replace_chart;
use crate::list_edit::IndexOutOfRange;
use crate::network_splice::{body_mut, splice_networks};
use crate::validate::object_problem;
use crate::{
    Axis, Body, Controller, Dialect, Folder, IoArea, ListEdit, ModbusDevice, Network, Node, Object,
    Project, SerialPort, Task, Variable, is_valid_identifier, same_identifier,
};

/// A reversible change to a project.
#[derive(Clone, Debug, PartialEq)]
#[allow(clippy::large_enum_variant)] // Edits are built one at a time by gestures.
pub enum Edit {
    /// Sets the project's display name and description.
    SetProjectInfo {
        /// The new name.
        name: String,
        /// The new description.
        description: String,
    },
    /// Replaces the controller node's settings.
    SetController(Controller),
    /// Sets the language rules the project is checked by (the manifest's `dialect`).
    SetDialect(Dialect),
    /// Edits the task configuration.
    Tasks(ListEdit<Task>),
    /// Edits the I/O areas.
    IoAreas(ListEdit<IoArea>),
    /// Edits the serial ports.
    SerialPorts(ListEdit<SerialPort>),
    /// Edits the Modbus devices.
    ModbusDevices(ListEdit<ModbusDevice>),
    /// Edits the motion axes.
    Axes(ListEdit<Axis>),
    /// Adds, removes, moves or renames folders and objects of the application.
    Tree(TreeEdit),
    /// Replaces an object with a new version of the same name and kind.
    ReplaceObject(Object),
    /// Edits the declarations of a POU, method, property accessor or global variable list.
    Variables {
        /// Whose declarations.
        owner: VarOwner,
        /// The change.
        edit: ListEdit<Variable>,
    },
    /// Replaces a byte range of an ST body with new text.
    ReplaceText {
        /// Which body.
        target: TextTarget,
        /// The byte range replaced; it must lie on character boundaries.
        range: Range<usize>,
        /// The new text.
        text: String,
    },
    /// Replaces the `remove` networks starting at index `at` of an LD or FBD body with
    /// `insert`: inserting, deleting, changing or pasting networks as one undo step. Its
    /// inverse is the splice that puts the old networks back. The body must keep the rules of
    /// `network_check`.
    SpliceNetworks {
        /// Which body (named as a text body is; it must be LD or FBD).
        target: TextTarget,
        /// The index of the first network replaced.
        at: usize,
        /// How many networks are replaced.
        remove: usize,
        /// The networks put in their place.
        insert: Vec<Network>,
    },
    /// Replaces a CFC or SFC body with another chart of the same language: every change an
    /// editor makes to a chart, as one undo step. Its inverse puts the old chart back. The
    /// chart must keep the structural rules of its language (`cfc.rs`, `sfc.rs`).
    ReplaceChart {
        /// Which body (named as a text body is; it must be CFC or SFC).
        target: TextTarget,
        /// The new body: `Body::Cfc` or `Body::Sfc`, the language the body has.
        body: Box<Body>,
    },
    /// Several edits applied in order as one; undone in reverse order.
    Group(Vec<Edit>),
    /// Replaces the whole project (recovering unsaved changes after a crash, for instance);
    /// undone by putting the previous project back.
    ReplaceProject(Box<Project>),
}

/// A change to the application tree. Folders are named by their path of folder names from the
/// application root; the root is the empty path.
#[derive(Clone, Debug, PartialEq)]
#[allow(clippy::large_enum_variant)] // Edits are built one at a time by gestures.
pub enum TreeEdit {
    /// Inserts a folder or object at `index` in `folder`.
    Insert {
        /// The parent folder.
        folder: Vec<String>,
        /// The position among its children.
        index: usize,
        /// The new folder or object.
        node: Node,
    },
    /// Removes the node at `index` in `folder`, with everything below it.
    Remove {
        /// The parent folder.
        folder: Vec<String>,
        /// The position among its children.
        index: usize,
    },
    /// Moves a node to another place.
    Move {
        /// The current parent folder.
        from_folder: Vec<String>,
        /// The current position.
        from_index: usize,
        /// The new parent folder (as it is before the move).
        to_folder: Vec<String>,
        /// The position among the new parent's children after the move.
        to_index: usize,
    },
    /// Renames the node at `index` in `folder`.
    Rename {
        /// The parent folder.
        folder: Vec<String>,
        /// The position among its children.
        index: usize,
        /// The new name.
        name: String,
    },
}

/// Whose variable declarations an edit changes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum VarOwner {
    /// A POU's declarations.
    Pou(String),
    /// A method's declarations.
    Method {
        /// The POU.
        pou: String,
        /// The method.
        method: String,
    },
    /// A global variable list.
    Gvl(String),
}

/// Which ST body an edit changes.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum TextTarget {
    /// A POU's body.
    Pou(String),
    /// A method's body.
    Method {
        /// The POU.
        pou: String,
        /// The method.
        method: String,
    },
    /// A property's getter (`get == true`) or setter body.
    Property {
        /// The POU.
        pou: String,
        /// The property.
        property: String,
        /// The getter rather than the setter.
        get: bool,
    },
    /// An action's body.
    Action {
        /// The POU.
        pou: String,
        /// The action.
        action: String,
    },
    /// The body of a transition object (`Pou::transitions`).
    Transition {
        /// The POU.
        pou: String,
        /// The transition object.
        transition: String,
    },
}

/// Why an edit could not be applied. The project is unchanged when one is returned.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
pub enum EditError {
    /// No object has that name.
    #[error("there is no object named '{0}'")]
    NoSuchObject(String),
    /// No folder has that path.
    #[error("there is no folder '{0}'")]
    NoSuchFolder(String),
    /// The POU has no such method, property, action or transition.
    #[error("'{pou}' has no {what} named '{name}'")]
    NoSuchMember {
        /// The POU.
        pou: String,
        /// `method`, `property`, `action` or `transition`.
        what: &'static str,
        /// The missing name.
        name: String,
    },
    /// An index past the end of a list.
    #[error("position {index} is out of range (the list has {len} entries)")]
    IndexOutOfRange {
        /// The index asked for.
        index: usize,
        /// The list's length.
        len: usize,
    },
    /// A name is not an identifier.
    #[error(
        "'{0}' is not a valid name: use letters, digits and '_', starting with a letter or '_'"
    )]
    InvalidName(String),
    /// A name is already taken.
    #[error("the name '{0}' is already used")]
    DuplicateName(String),
    /// The object's content cannot be stored, for example two methods of the same name.
    #[error("{0}")]
    InvalidObject(String),
    /// The targeted body is not Structured Text.
    #[error("the body of {0} is not Structured Text")]
    NotText(String),
    /// A text range outside the text or inside a character.
    #[error("the range {start}..{end} is not a valid range of a text of {len} bytes")]
    BadTextRange {
        /// Range start.
        start: usize,
        /// Range end.
        end: usize,
        /// Text length in bytes.
        len: usize,
    },
    /// A folder would be moved into itself.
    #[error("a folder cannot be moved into itself")]
    MoveIntoItself,
    /// A replacement object has another kind than the object it replaces.
    #[error("'{0}' cannot change its kind")]
    KindChanged(String),
    /// The targeted body is not LD or FBD.
    #[error("the body of {0} is not a Ladder or Function Block Diagram")]
    NotNetworks(String),
    /// The targeted body is not a chart of the language of the replacement.
    #[error("the body of {0} is not a chart of that language")]
    NotChart(String),
    /// A run of networks that goes past the end of its body.
    #[error("cannot replace {remove} networks at position {at}: the body has {len} networks")]
    NetworkRangeOutOfRange {
        /// The index of the first network.
        at: usize,
        /// How many networks.
        remove: usize,
        /// How many networks the body has.
        len: usize,
    },
}

impl From<IndexOutOfRange> for EditError {
    fn from(error: IndexOutOfRange) -> Self {
        Self::IndexOutOfRange {
            index: error.index,
            len: error.len,
        }
    }
}

impl Edit {
    /// Applies the edit and returns the edit that undoes it.
    pub fn apply(self, project: &mut Project) -> Result<Self, EditError> {
        match self {
            Self::SetProjectInfo { name, description } => Ok(Self::SetProjectInfo {
                name: std::mem::replace(&mut project.name, name),
                description: std::mem::replace(&mut project.description, description),
            }),
            Self::SetController(controller) => Ok(Self::SetController(std::mem::replace(
                &mut project.controller,
                controller,
            ))),
            Self::SetDialect(dialect) => Ok(Self::SetDialect(std::mem::replace(
                &mut project.dialect,
                dialect,
            ))),
            Self::Tasks(edit) => {
                // A renamed task's vendor data follows it, as its place (`task:NAME`) names it;
                // the inverse renames it back, so undo moves the entries back too.
                let renamed = match &edit {
                    ListEdit::Replace { index, item } => project
                        .tasks
                        .get(*index)
                        .filter(|task| task.name != item.name)
                        .map(|task| (task.name.clone(), item.name.clone())),
                    _ => None,
                };
                let inverse = edit.apply(&mut project.tasks)?;
                if let Some((old, new)) = renamed {
                    project.vendor_data.rename_task(&old, &new);
                }
                Ok(Self::Tasks(inverse))
            }
            Self::IoAreas(edit) => Ok(Self::IoAreas(edit.apply(&mut project.io_areas)?)),
            Self::SerialPorts(edit) => {
                Ok(Self::SerialPorts(edit.apply(&mut project.serial_ports)?))
            }
            Self::ModbusDevices(edit) => Ok(Self::ModbusDevices(
                edit.apply(&mut project.modbus_devices)?,
            )),
            Self::Axes(edit) => Ok(Self::Axes(edit.apply(&mut project.axes)?)),
            Self::Tree(edit) => {
                // A renamed object's vendor data follows it, as its places name it.
                let renamed = match &edit {
                    TreeEdit::Rename {
                        folder,
                        index,
                        name,
                    } => project
                        .application
                        .folder(folder)
                        .and_then(|parent| parent.children.get(*index))
                        .and_then(|node| match node {
                            Node::Object(object) => {
                                Some((object.kind(), object.name().to_owned(), name.clone()))
                            }
                            Node::Folder(_) => None,
                        }),
                    _ => None,
                };
                let inverse = apply_tree_edit(edit, &mut project.application)?;
                if let Some((kind, old, new)) = renamed {
                    project.vendor_data.rename_object(kind, &old, &new);
                }
                Ok(Self::Tree(inverse))
            }
            Self::ReplaceObject(object) => replace_object(object, &mut project.application),
            Self::ReplaceProject(replacement) => Ok(Self::ReplaceProject(Box::new(
                std::mem::replace(project, *replacement),
            ))),
            Self::Variables { owner, edit } => {
                let list = variables_mut(&mut project.application, &owner)?;
                let edit = edit.apply(list)?;
                Ok(Self::Variables { owner, edit })
            }
            Self::ReplaceText {
                target,
                range,
                text,
            } => {
                let body = text_mut(&mut project.application, &target)?;
                let len = body.len();
                let bad_range = EditError::BadTextRange {
                    start: range.start,
                    end: range.end,
                    len,
                };
                if range.start > range.end
                    || !body.is_char_boundary(range.start)
                    || !body.is_char_boundary(range.end)
                {
                    return Err(bad_range);
                }
                let old = body[range.clone()].to_owned();
                body.replace_range(range.clone(), &text);
                Ok(Self::ReplaceText {
                    target,
                    range: range.start..range.start + text.len(),
                    text: old,
                })
            }
            Self::SpliceNetworks {
                target,
                at,
                remove,
                insert,
            } => splice_networks(&mut project.application, target, at, remove, insert),
            Self::ReplaceChart { target, body } => {
                replace_chart(&mut project.application, target, *body)
            }
            Self::Group(edits) => {
                let mut inverses = Vec::with_capacity(edits.len());
                for edit in edits {
                    match edit.apply(project) {
                        Ok(inverse) => inverses.push(inverse),
                        Err(error) => {
                            // Roll back what was applied, so a failed group changes nothing.
                            // The inverses of applied edits always apply.
                            for inverse in inverses.into_iter().rev() {
                                inverse.apply(project).ok();
                            }
                            return Err(error);
                        }
                    }
                }
                inverses.reverse();
                Ok(Self::Group(inverses))
            }
        }
    }
}

fn folder_mut<'a>(root: &'a mut Folder, path: &[String]) -> Result<&'a mut Folder, EditError> {
    root.folder_mut(path)
        .ok_or_else(|| EditError::NoSuchFolder(path.join("/")))
}

fn apply_tree_edit(edit: TreeEdit, root: &mut Folder) -> Result<TreeEdit, EditError> {
    match edit {
        TreeEdit::Insert {
            folder,
            index,
            node,
        } => {
            check_node_names(&node)?;
            check_names_free(root, &folder, &node)?;
            let parent = folder_mut(root, &folder)?;
            ListEdit::Insert { index, item: node }.apply(&mut parent.children)?;
            Ok(TreeEdit::Remove { folder, index })
        }
        TreeEdit::Remove { folder, index } => {
            let parent = folder_mut(root, &folder)?;
            let ListEdit::Insert { item: node, .. } =
                ListEdit::Remove { index }.apply(&mut parent.children)?
            else {
                unreachable!("the inverse of a removal is an insertion");
            };
            Ok(TreeEdit::Insert {
                folder,
                index,
                node,
            })
        }
        TreeEdit::Move {
            from_folder,
            from_index,
            to_folder,
            to_index,
        } => {
            let source = folder_mut(root, &from_folder)?;
            let len = source.children.len();
            let moved = source
                .children
                .get(from_index)
                .ok_or(EditError::IndexOutOfRange {
                    index: from_index,
                    len,
                })?;
            // A folder cannot go below itself.
            if let Node::Folder(moved_folder) = moved {
                let mut moved_path = from_folder.clone();
                moved_path.push(moved_folder.name.clone());
                if to_folder.starts_with(&moved_path) {
                    return Err(EditError::MoveIntoItself);
                }
            }
            let moved_name = moved.name().to_owned();
            let is_folder = matches!(moved, Node::Folder(_));
            if from_folder != to_folder {
                let target = root
                    .folder(&to_folder)
                    .ok_or_else(|| EditError::NoSuchFolder(to_folder.join("/")))?;
                if is_folder && has_folder_named(target, &moved_name) {
                    return Err(EditError::DuplicateName(moved_name));
                }
                let target_len = target.children.len();
                if to_index > target_len {
                    return Err(EditError::IndexOutOfRange {
                        index: to_index,
                        len: target_len,
                    });
                }
            } else if to_index >= len {
                return Err(EditError::IndexOutOfRange {
                    index: to_index,
                    len,
                });
            }
            let node = folder_mut(root, &from_folder)?.children.remove(from_index);
            // The target path stays valid: removing a node never renames folders above it.
            let target = folder_mut(root, &to_folder)?;
            target.children.insert(to_index, node);
            Ok(TreeEdit::Move {
                from_folder: to_folder,
                from_index: to_index,
                to_folder: from_folder,
                to_index: from_index,
            })
        }
        TreeEdit::Rename {
            folder,
            index,
            name,
        } => {
            if !is_valid_identifier(&name) {
                return Err(EditError::InvalidName(name));
            }
            let parent = root
                .folder(&folder)
                .ok_or_else(|| EditError::NoSuchFolder(folder.join("/")))?;
            let len = parent.children.len();
            let node = parent
                .children
                .get(index)
                .ok_or(EditError::IndexOutOfRange { index, len })?;
            let old = node.name().to_owned();
            let taken = match node {
                Node::Folder(_) => parent.children.iter().enumerate().any(|(other, sibling)| {
                    other != index
                        && matches!(sibling, Node::Folder(f) if same_identifier(&f.name, &name))
                }),
                Node::Object(_) => root
                    .objects()
                    .iter()
                    .any(|object| object.name() != old && same_identifier(object.name(), &name)),
            };
            if taken {
                return Err(EditError::DuplicateName(name));
            }
            match &mut folder_mut(root, &folder)?.children[index] {
                Node::Folder(renamed) => renamed.name = name,
                Node::Object(renamed) => renamed.set_name(name),
            }
            Ok(TreeEdit::Rename {
                folder,
                index,
                name: old,
            })
        }
    }
}

fn has_folder_named(folder: &Folder, name: &str) -> bool {
    folder
        .children
        .iter()
        .any(|node| matches!(node, Node::Folder(f) if same_identifier(&f.name, name)))
}

/// Whether a folder among the first `before` children of `folder` is named `name`.
fn has_folder_named_before(folder: &Folder, before: usize, name: &str) -> bool {
    folder.children[..before]
        .iter()
        .any(|node| matches!(node, Node::Folder(f) if same_identifier(&f.name, name)))
}

/// Checks that every name in a node about to be inserted is valid and storable.
fn check_node_names(node: &Node) -> Result<(), EditError> {
    match node {
        Node::Folder(folder) => {
            if !is_valid_identifier(&folder.name) {
                return Err(EditError::InvalidName(folder.name.clone()));
            }
            for (index, child) in folder.children.iter().enumerate() {
                if let Node::Folder(sub) = child
                    && has_folder_named_before(folder, index, &sub.name)
                {
                    return Err(EditError::DuplicateName(sub.name.clone()));
                }
            }
            folder.children.iter().try_for_each(check_node_names)
        }
        Node::Object(object) => {
            if !is_valid_identifier(object.name()) {
                return Err(EditError::InvalidName(object.name().to_owned()));
            }
            match object_problem(object) {
                Some(problem) => Err(EditError::InvalidObject(problem)),
                None => Ok(()),
            }
        }
    }
}

/// Checks that a node inserted into `folder` clashes with no folder beside it and that its
/// objects clash with no object of the application.
fn check_names_free(root: &Folder, folder: &[String], node: &Node) -> Result<(), EditError> {
    let parent = root
        .folder(folder)
        .ok_or_else(|| EditError::NoSuchFolder(folder.join("/")))?;
    if let Node::Folder(new_folder) = node
        && has_folder_named(parent, &new_folder.name)
    {
        return Err(EditError::DuplicateName(new_folder.name.clone()));
    }
    let existing = root.objects();
    let mut new_objects: Vec<&Object> = Vec::new();
    match node {
        Node::Folder(new_folder) => new_objects.extend(new_folder.objects()),
        Node::Object(object) => new_objects.push(object),
    }
    for (position, object) in new_objects.iter().enumerate() {
        let name = object.name();
        let clash_existing = existing
            .iter()
            .any(|other| same_identifier(other.name(), name));
        let clash_new = new_objects[..position]
            .iter()
            .any(|other| same_identifier(other.name(), name));
        if clash_existing || clash_new {
            return Err(EditError::DuplicateName(name.to_owned()));
        }
    }
    Ok(())
}

fn replace_object(object: Object, root: &mut Folder) -> Result<Edit, EditError> {
    if let Some(problem) = object_problem(&object) {
        return Err(EditError::InvalidObject(problem));
    }
    let name = object.name().to_owned();
    let slot = root
        .object_mut(&name)
        .ok_or_else(|| EditError::NoSuchObject(name.clone()))?;
    if slot.name() != name {
        // Renaming goes through `TreeEdit::Rename`, which checks for clashes.
        return Err(EditError::NoSuchObject(name));
    }
    if slot.kind() != object.kind() {
        return Err(EditError::KindChanged(name));
    }
    Ok(Edit::ReplaceObject(std::mem::replace(slot, object)))
}

/// The POU named `name`.
pub(crate) fn pou_mut<'a>(
    root: &'a mut Folder,
    name: &str,
) -> Result<&'a mut crate::Pou, EditError> {
    match root.object_mut(name) {
        Some(Object::Pou(pou)) => Ok(pou),
        _ => Err(EditError::NoSuchObject(name.to_owned())),
    }
}

fn no_member(pou: &str, what: &'static str, name: &str) -> EditError {
    EditError::NoSuchMember {
        pou: pou.to_owned(),
        what,
        name: name.to_owned(),
    }
}

fn variables_mut<'a>(
    root: &'a mut Folder,
    owner: &VarOwner,
) -> Result<&'a mut Vec<Variable>, EditError> {
    match owner {
        VarOwner::Pou(pou) => Ok(&mut pou_mut(root, pou)?.variables),
        VarOwner::Method { pou, method } => pou_mut(root, pou)?
            .methods
            .iter_mut()
            .find(|m| m.name == *method)
            .map(|m| &mut m.variables)
            .ok_or_else(|| no_member(pou, "method", method)),
        VarOwner::Gvl(name) => match root.object_mut(name) {
            Some(Object::Gvl(gvl)) => Ok(&mut gvl.variables),
            _ => Err(EditError::NoSuchObject(name.clone())),
        },
    }
}

fn text_mut<'a>(root: &'a mut Folder, target: &TextTarget) -> Result<&'a mut String, EditError> {
    body_mut(root, target)?
        .text_mut()
        .ok_or_else(|| EditError::NotText(target.to_string()))
}

impl std::fmt::Display for TextTarget {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Pou(pou) => write!(f, "'{pou}'"),
            Self::Method { pou, method } => write!(f, "method '{pou}.{method}'"),
            Self::Property { pou, property, get } => {
                let accessor = if *get { "Get" } else { "Set" };
                write!(f, "property '{pou}.{property}.{accessor}'")
            }
            Self::Action { pou, action } => write!(f, "action '{pou}.{action}'"),
            Self::Transition { pou, transition } => {
                write!(f, "transition '{pou}.{transition}'")
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::GlobalVarList;

    fn gvl(name: &str) -> Node {
        Node::Object(Object::Gvl(GlobalVarList {
            name: name.into(),
            ..GlobalVarList::default()
        }))
    }

    fn folder(name: &str, children: Vec<Node>) -> Node {
        Node::Folder(Folder {
            name: name.into(),
            children,
        })
    }

    fn project() -> Project {
        let mut project = Project::default();
        project.application.children = vec![gvl("GVL_A"), folder("Motion", vec![gvl("GVL_B")])];
        project
    }

    #[track_caller]
    fn refused(edit: TreeEdit, expected: EditError) {
        let mut edited = project();
        assert_eq!(Edit::Tree(edit).apply(&mut edited), Err(expected));
        assert_eq!(edited, project(), "a refused edit changed the project");
    }

    #[test]
    fn setting_the_dialect_is_undone_by_the_edit_it_returns() {
        let mut edited = project();
        let undo = Edit::SetDialect(Dialect::IecStrict)
            .apply(&mut edited)
            .unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(edited.dialect, Dialect::IecStrict);
        assert_eq!(undo, Edit::SetDialect(Dialect::Codesys));
        undo.apply(&mut edited).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(edited, project());
    }

    #[test]
    fn names_that_clash_are_refused_without_regard_to_case() {
        let insert = |node| TreeEdit::Insert {
            folder: vec!["Motion".into()],
            index: 0,
            node,
        };
        refused(
            insert(gvl("gvl_a")),
            EditError::DuplicateName("gvl_a".into()),
        );
        refused(
            insert(folder(
                "X",
                vec![folder("Sub", vec![]), folder("SUB", vec![])],
            )),
            EditError::DuplicateName("SUB".into()),
        );
        refused(insert(gvl("1st")), EditError::InvalidName("1st".into()));
        refused(
            TreeEdit::Rename {
                folder: Vec::new(),
                index: 0,
                name: "GVL_b".into(),
            },
            EditError::DuplicateName("GVL_b".into()),
        );
    }

    #[test]
    fn a_folder_cannot_move_into_itself() {
        refused(
            TreeEdit::Move {
                from_folder: Vec::new(),
                from_index: 1,
                to_folder: vec!["Motion".into()],
                to_index: 0,
            },
            EditError::MoveIntoItself,
        );
    }

    #[test]
    fn an_object_moves_between_folders_and_back() {
        let mut edited = project();
        let inverse = Edit::Tree(TreeEdit::Move {
            from_folder: Vec::new(),
            from_index: 0,
            to_folder: vec!["Motion".into()],
            to_index: 1,
        })
        .apply(&mut edited)
        .unwrap();
        assert_eq!(
            edited.application.locate("GVL_A"),
            Some((vec!["Motion".into()], 1))
        );
        inverse.apply(&mut edited).unwrap();
        assert_eq!(edited, project());
    }
}
