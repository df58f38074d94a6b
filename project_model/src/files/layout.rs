//! Where each part of a project lives in its folder.

use std::path::PathBuf;

use thiserror::Error;

use super::APPLICATION_DIR;
use super::canonical::to_canonical_toml;
use crate::{Body, Folder, Node, Object, ObjectKind, Pou, Project};

/// The path, relative to the project folder, of the file of an object named `name` of `kind`
/// in the application folder `folder`.
pub(crate) fn object_file(folder: &[String], name: &str, kind: ObjectKind) -> PathBuf {
    let mut path = folder_dir(folder);
    path.push(format!("{name}{}", kind.file_suffix()));
    path
}

/// The directory, relative to the project folder, of the application folder `folder`.
pub(crate) fn folder_dir(folder: &[String]) -> PathBuf {
    let mut path = PathBuf::from(APPLICATION_DIR);
    path.extend(folder);
    path
}

/// The manifest entry of an object: its path below `application/` with `/` separators.
pub(crate) fn object_entry(folder: &[String], name: &str, kind: ObjectKind) -> String {
    let mut entry = folder_entry(folder);
    entry.push_str(name);
    entry.push_str(kind.file_suffix());
    entry
}

/// The manifest entry of a folder: its path below `application/` ending in `/`.
pub(crate) fn folder_entry(folder: &[String]) -> String {
    folder.iter().map(|name| format!("{name}/")).collect()
}

/// A place in a POU that holds a body, and the suffix of its text file.
pub(crate) struct BodySlot<'a> {
    /// The file name suffix after the POU's name, such as `.st`, `.Reset.st` or `.il` (the
    /// extension follows the body's language; non-textual bodies get `.st`, unused).
    pub suffix: String,
    /// The body.
    pub body: &'a Body,
    /// What the body belongs to, as messages name it: `POU 'Main'`, `POU 'Main', method
    /// 'Reset'`, `POU 'Main', property 'Speed' (get)` or `POU 'Main', action 'Stop'`.
    pub owner: String,
}

/// Every body of a POU with the suffix of its text file (`.st`, or `.il` for an IL body), in a
/// fixed order.
pub(crate) fn body_slots(pou: &Pou) -> Vec<BodySlot<'_>> {
    let pou_owner = format!("POU '{}'", pou.name);
    let suffix =
        |base: String, body: &Body| format!("{base}.{}", body.text_extension().unwrap_or("st"));
    let mut slots = vec![BodySlot {
        suffix: suffix(String::new(), &pou.body),
        body: &pou.body,
        owner: pou_owner.clone(),
    }];
    for method in &pou.methods {
        slots.push(BodySlot {
            suffix: suffix(format!(".{}", method.name), &method.body),
            body: &method.body,
            owner: format!("{pou_owner}, method '{}'", method.name),
        });
    }
    for property in &pou.properties {
        for (accessor, which) in [(&property.get, "get"), (&property.set, "set")] {
            if let Some(accessor) = accessor {
                slots.push(BodySlot {
                    suffix: suffix(format!(".{}.{which}", property.name), &accessor.body),
                    body: &accessor.body,
                    owner: format!("{pou_owner}, property '{}' ({which})", property.name),
                });
            }
        }
    }
    for action in &pou.actions {
        slots.push(BodySlot {
            suffix: suffix(format!(".{}", action.name), &action.body),
            body: &action.body,
            owner: format!("{pou_owner}, action '{}'", action.name),
        });
    }
    for transition in &pou.transitions {
        slots.push(BodySlot {
            suffix: suffix(format!(".{}", transition.name), &transition.body),
            body: &transition.body,
            owner: format!("{pou_owner}, transition '{}'", transition.name),
        });
    }
    slots
}

/// Every mutable body of a POU, in the same order as [`body_slots`].
pub(crate) fn bodies_mut(pou: &mut Pou) -> Vec<&mut Body> {
    let mut bodies = vec![&mut pou.body];
    bodies.extend(pou.methods.iter_mut().map(|m| &mut m.body));
    for property in &mut pou.properties {
        if let Some(get) = &mut property.get {
            bodies.push(&mut get.body);
        }
        if let Some(set) = &mut property.set {
            bodies.push(&mut set.body);
        }
    }
    bodies.extend(pou.actions.iter_mut().map(|a| &mut a.body));
    bodies.extend(pou.transitions.iter_mut().map(|t| &mut t.body));
    bodies
}

/// Serialises an object to the text of its TOML file, or gives the serialiser's error.
pub(crate) fn object_toml(object: &Object) -> Result<String, toml_edit::ser::Error> {
    match object {
        Object::Pou(pou) => to_canonical_toml(pou),
        Object::Gvl(gvl) => to_canonical_toml(gvl),
        Object::DataType(data_type) => to_canonical_toml(data_type),
        Object::CamTable(cam) => to_canonical_toml(cam),
        Object::Trace(trace) => to_canonical_toml(trace),
        Object::WatchList(watch) => to_canonical_toml(watch),
    }
}

/// Splits a manifest entry into its folder path and, for an object, its name and kind.
pub(crate) enum Entry {
    /// A folder, given by its full path.
    Folder(Vec<String>),
    /// An object in a folder.
    Object {
        /// The folder path.
        folder: Vec<String>,
        /// The object's name, from its file name.
        name: String,
        /// The object's kind, from its file suffix.
        kind: ObjectKind,
    },
}

/// Why a manifest entry names no folder or object; the text ends by saying what was expected.
#[derive(Debug, Error)]
pub(crate) enum EntryError {
    /// The entry is an empty string.
    #[error("empty entry; expected a path below application/ such as 'Main.pou.toml' or 'Motion/'")]
    Empty,
    /// A folder of the entry's path is not an identifier.
    #[error(
        "'{folder}' in '{entry}' is not a valid folder name (letters, digits and '_'); expected \
         a path below application/ such as 'Main.pou.toml' or 'Motion/'"
    )]
    BadFolderName {
        /// The folder name that is not an identifier.
        folder: String,
        /// The whole entry.
        entry: String,
    },
    /// The file name ends in none of the object suffixes.
    #[error(
        "'{entry}' has no known object suffix; expected one of .pou.toml, .gvl.toml, \
         .type.toml, .cam.toml, .trace.toml, .watch.toml, or '/' for a folder"
    )]
    UnknownSuffix {
        /// The whole entry.
        entry: String,
    },
    /// The object's name, the file name without its suffix, is not an identifier.
    #[error("'{name}' in '{entry}' is not a valid object name (letters, digits and '_')")]
    BadObjectName {
        /// The object name that is not an identifier.
        name: String,
        /// The whole entry.
        entry: String,
    },
}

/// Parses a manifest entry, or explains what is wrong with it.
pub(crate) fn parse_entry(entry: &str) -> Result<Entry, EntryError> {
    if entry.is_empty() {
        return Err(EntryError::Empty);
    }
    let (folder_part, file_part) = match entry.strip_suffix('/') {
        Some(folder) => (folder, None),
        None => match entry.rsplit_once('/') {
            Some((folder, file)) => (folder, Some(file)),
            None => ("", Some(entry)),
        },
    };
    let folder: Vec<String> = if folder_part.is_empty() {
        Vec::new()
    } else {
        folder_part.split('/').map(str::to_owned).collect()
    };
    if let Some(bad) = folder.iter().find(|name| !crate::is_valid_identifier(name)) {
        return Err(EntryError::BadFolderName {
            folder: bad.clone(),
            entry: entry.to_owned(),
        });
    }
    let Some(file) = file_part else {
        return Ok(Entry::Folder(folder));
    };
    let Some((kind, name)) = ObjectKind::ALL.iter().find_map(|kind| {
        file.strip_suffix(kind.file_suffix())
            .map(|name| (*kind, name))
    }) else {
        return Err(EntryError::UnknownSuffix {
            entry: entry.to_owned(),
        });
    };
    if !crate::is_valid_identifier(name) {
        return Err(EntryError::BadObjectName {
            name: name.to_owned(),
            entry: entry.to_owned(),
        });
    }
    Ok(Entry::Object {
        folder,
        name: name.to_owned(),
        kind,
    })
}

/// A textual body (Structured Text or Instruction List) of a project with where it is stored.
#[derive(Clone, Debug)]
pub struct StBody<'a> {
    /// The `.st` (or `.il`) file, relative to the project folder.
    pub file: PathBuf,
    /// The POU it belongs to.
    pub pou: &'a Pou,
    /// Which body of the POU it is.
    pub target: crate::TextTarget,
    /// The text.
    pub text: &'a str,
}

/// Every Structured Text body of `project` with its file, in tree order: what a checker reads
/// and reports against.
pub fn st_body_files(project: &Project) -> Vec<StBody<'_>> {
    body_files(project, Body::st_text)
}

/// Every textual body of `project` (Structured Text in `.st` files, Instruction List in `.il`
/// files) with its file, in tree order: what editors show and findings are reported against.
pub fn text_body_files(project: &Project) -> Vec<StBody<'_>> {
    body_files(project, Body::text)
}

/// Every body of `project` whose text `text_of` gives, with its file, in tree order.
fn body_files<'p>(project: &'p Project, text_of: fn(&Body) -> Option<&str>) -> Vec<StBody<'p>> {
    let mut out = Vec::new();
    for (file, object) in object_files(project) {
        let Object::Pou(pou) = object else { continue };
        let folder = file.parent().map(PathBuf::from).unwrap_or_default();
        let targets = body_targets(pou);
        for (slot, target) in body_slots(pou).into_iter().zip(targets) {
            if let Some(text) = text_of(slot.body) {
                out.push(StBody {
                    file: folder.join(format!("{}{}", pou.name, slot.suffix)),
                    pou,
                    target,
                    text,
                });
            }
        }
    }
    out
}

/// The edit targets of a POU's bodies, in the order of [`body_slots`].
fn body_targets(pou: &Pou) -> Vec<crate::TextTarget> {
    use crate::TextTarget;
    let name = || pou.name.clone();
    let mut targets = vec![TextTarget::Pou(name())];
    targets.extend(pou.methods.iter().map(|m| TextTarget::Method {
        pou: name(),
        method: m.name.clone(),
    }));
    for property in &pou.properties {
        for (accessor, get) in [(&property.get, true), (&property.set, false)] {
            if accessor.is_some() {
                targets.push(TextTarget::Property {
                    pou: name(),
                    property: property.name.clone(),
                    get,
                });
            }
        }
    }
    targets.extend(pou.actions.iter().map(|a| TextTarget::Action {
        pou: name(),
        action: a.name.clone(),
    }));
    targets.extend(pou.transitions.iter().map(|t| TextTarget::Transition {
        pou: name(),
        transition: t.name.clone(),
    }));
    targets
}

/// Every application object with the path of its file relative to the project folder, in
/// tree order.
pub fn object_files(project: &Project) -> Vec<(PathBuf, &Object)> {
    fn walk<'a>(folder: &'a Folder, path: &mut Vec<String>, out: &mut Vec<(PathBuf, &'a Object)>) {
        for node in &folder.children {
            match node {
                Node::Folder(child) => {
                    path.push(child.name.clone());
                    walk(child, path, out);
                    path.pop();
                }
                Node::Object(object) => {
                    out.push((object_file(path, object.name(), object.kind()), object));
                }
            }
        }
    }
    let mut out = Vec::new();
    walk(&project.application, &mut Vec::new(), &mut out);
    out
}

#[cfg(test)]
mod tests {
    use super::{EntryError, parse_entry};

    fn refusal(entry: &str) -> String {
        parse_entry(entry)
            .err()
            .map(|error: EntryError| error.to_string())
            .unwrap_or_default()
    }

    #[test]
    fn a_bad_entry_is_explained_word_for_word() {
        let expected = "expected a path below application/ such as 'Main.pou.toml' or 'Motion/'";
        assert_eq!(refusal(""), format!("empty entry; {expected}"));
        assert_eq!(
            refusal("Mo tion/Main.pou.toml"),
            format!(
                "'Mo tion' in 'Mo tion/Main.pou.toml' is not a valid folder name (letters, \
                 digits and '_'); {expected}"
            )
        );
        assert_eq!(
            refusal("Main.txt"),
            "'Main.txt' has no known object suffix; expected one of .pou.toml, .gvl.toml, \
             .type.toml, .cam.toml, .trace.toml, .watch.toml, or '/' for a folder"
        );
        assert_eq!(
            refusal("Motion/1st.pou.toml"),
            "'1st' in 'Motion/1st.pou.toml' is not a valid object name (letters, digits and '_')"
        );
        assert!(parse_entry("Motion/Main.pou.toml").is_ok());
    }
}
