//! Writing a [`Project`] to its folder: canonical text, only changed files, each atomically.

use std::collections::{BTreeMap, BTreeSet};
use std::io::Write as _;
use std::path::{Path, PathBuf};

use thiserror::Error;
use toml::Spanned;

use super::canonical::to_canonical_toml;
use super::held_back::HeldBackObject;
use super::layout::{body_slots, folder_dir, folder_entry, object_entry, object_file, object_toml};
use super::manifest::Manifest;
use super::{FORMAT_VERSION, MANIFEST_FILE_NAME, VENDOR_DATA_FILE_NAME};
use crate::modbus_device_file::ModbusDeviceFile;
use crate::validate::object_problem;
use crate::{Folder, Node, Object, Project, is_valid_identifier, same_identifier};

/// What a save did.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct SaveReport {
    /// Files written because they were new or their content changed.
    pub written: Vec<PathBuf>,
    /// Files of the previous version of the project that it no longer needs.
    pub removed: Vec<PathBuf>,
    /// Every file of the project as saved, relative to its folder; pass it to the next save.
    pub files: BTreeSet<PathBuf>,
}

/// Why a project could not be saved.
#[derive(Debug, Error)]
pub enum SaveError {
    /// A file or folder could not be written.
    #[error("{path}: {source}")]
    Io {
        /// The file or folder.
        path: PathBuf,
        /// The operating system's error.
        source: std::io::Error,
    },
    /// The project holds something a file cannot: an invalid or duplicate name.
    #[error("cannot save: {0}")]
    Invalid(String),
    /// Serialisation failed.
    #[error("cannot save {path}: {source}")]
    Serialize {
        /// The file.
        path: PathBuf,
        /// The serialiser's error.
        source: toml_edit::ser::Error,
    },
}

/// Saves `project` into folder `dir`, creating it if needed.
///
/// Every file is rendered before anything is written, so an invalid project writes nothing.
/// Files whose content is unchanged are not rewritten; the others are written beside their
/// target and renamed over it, objects first and the manifest last, so after a crash every file
/// is either wholly old or wholly new and the project still loads. Files in `previous_files`
/// (the files the project was loaded from or last saved to) that the project no longer needs
/// are removed; no other file is touched.
pub fn save_project(
    project: &Project,
    dir: &Path,
    previous_files: &BTreeSet<PathBuf>,
) -> Result<SaveReport, SaveError> {
    save_project_keeping(project, dir, previous_files, &[])
}

/// Saves `project` as [`save_project`] does, keeping the objects that failed to load
/// (`LoadError::partial`'s `held_back`): their manifest entries stay, at the end of their
/// folder's entries, and their files are neither written nor removed. An object of the
/// project that takes the name of a held-back one is refused, as two objects of one name are.
pub fn save_project_keeping(
    project: &Project,
    dir: &Path,
    previous_files: &BTreeSet<PathBuf>,
    held_back: &[HeldBackObject],
) -> Result<SaveReport, SaveError> {
    let rendered = render(project, held_back)?;
    let mut report = SaveReport {
        files: rendered.keys().cloned().collect(),
        ..SaveReport::default()
    };
    let manifest = PathBuf::from(MANIFEST_FILE_NAME);
    let (manifest_files, object_files): (Vec<_>, Vec<_>) =
        rendered.iter().partition(|(path, _)| **path == manifest);
    for (relative, content) in object_files.into_iter().chain(manifest_files) {
        if write_if_changed(&dir.join(relative), content.as_bytes())? {
            report.written.push(relative.clone());
        }
    }
    let removable = previous_files
        .difference(&report.files)
        .filter(|file| !held_back.iter().any(|object| object.owns(file)));
    for relative in removable {
        let path = dir.join(relative);
        match std::fs::remove_file(&path) {
            Ok(()) => report.removed.push(relative.clone()),
            Err(error) if error.kind() == std::io::ErrorKind::NotFound => {}
            Err(source) => return Err(SaveError::Io { path, source }),
        }
        // Drop the directories a removed folder leaves empty; `remove_dir` refuses non-empty
        // ones, so files the project does not know about are kept.
        let mut parent = relative.parent();
        while let Some(directory) = parent.filter(|d| !d.as_os_str().is_empty()) {
            if std::fs::remove_dir(dir.join(directory)).is_err() {
                break;
            }
            parent = directory.parent();
        }
    }
    Ok(report)
}

/// Renders every file of the project, keyed by its path relative to the project folder.
fn render(
    project: &Project,
    held_back: &[HeldBackObject],
) -> Result<BTreeMap<PathBuf, String>, SaveError> {
    let mut files = BTreeMap::new();
    let mut entries = Vec::new();
    check_unique_object_names(&project.application)?;
    render_folder(
        &project.application,
        &mut Vec::new(),
        &mut entries,
        &mut files,
    )?;
    keep_held_back_entries(&project.application, held_back, &mut entries)?;

    let manifest = Manifest {
        format_version: FORMAT_VERSION,
        name: project.name.clone(),
        description: project.description.clone(),
        dialect: project.dialect,
        application: entries
            .into_iter()
            .map(|entry| Spanned::new(0..0, entry))
            .collect(),
        controller: project.controller.clone(),
        tasks: project.tasks.clone(),
        io_areas: project.io_areas.clone(),
        serial_ports: project.serial_ports.clone(),
        modbus_devices: project
            .modbus_devices
            .iter()
            .map(|device| Spanned::new(0..0, ModbusDeviceFile::from(device.clone())))
            .collect(),
        axes: project.axes.clone(),
    };
    let text = to_canonical_toml(&manifest).map_err(|source| SaveError::Serialize {
        path: MANIFEST_FILE_NAME.into(),
        source,
    })?;
    files.insert(PathBuf::from(MANIFEST_FILE_NAME), text);
    if !project.vendor_data.is_empty() {
        let text =
            to_canonical_toml(&project.vendor_data).map_err(|source| SaveError::Serialize {
                path: VENDOR_DATA_FILE_NAME.into(),
                source,
            })?;
        files.insert(PathBuf::from(VENDOR_DATA_FILE_NAME), text);
    }
    Ok(files)
}

fn render_folder(
    folder: &Folder,
    path: &mut Vec<String>,
    entries: &mut Vec<String>,
    files: &mut BTreeMap<PathBuf, String>,
) -> Result<(), SaveError> {
    let mut folder_names: Vec<&str> = Vec::new();
    for node in &folder.children {
        match node {
            Node::Folder(child) => {
                if !is_valid_identifier(&child.name) {
                    return Err(SaveError::Invalid(format!(
                        "'{}' is not a valid folder name",
                        child.name
                    )));
                }
                if folder_names.iter().any(|n| same_identifier(n, &child.name)) {
                    return Err(SaveError::Invalid(format!(
                        "two folders named '{}' in '{}'",
                        child.name,
                        folder_dir(path).display()
                    )));
                }
                folder_names.push(&child.name);
                path.push(child.name.clone());
                entries.push(folder_entry(path));
                render_folder(child, path, entries, files)?;
                path.pop();
            }
            Node::Object(object) => {
                entries.push(object_entry(path, object.name(), object.kind()));
                render_object(object, path, files)?;
            }
        }
    }
    Ok(())
}

fn render_object(
    object: &Object,
    folder: &[String],
    files: &mut BTreeMap<PathBuf, String>,
) -> Result<(), SaveError> {
    let name = object.name();
    if let Some(problem) = object_problem(object) {
        return Err(SaveError::Invalid(problem));
    }
    let file = object_file(folder, name, object.kind());
    let text = object_toml(object).map_err(|source| SaveError::Serialize {
        path: file.clone(),
        source,
    })?;
    files.insert(file, text);
    if let Object::Pou(pou) = object {
        for slot in body_slots(pou) {
            if let Some(text) = slot.body.text() {
                let mut st_file = folder_dir(folder);
                st_file.push(format!("{name}{}", slot.suffix));
                files.insert(st_file, text.to_owned());
            }
        }
    }
    Ok(())
}

/// Puts the entry of every held-back object after the last entry of its folder (at the end
/// when the folder is gone, so the entry is still there to be fixed by hand).
fn keep_held_back_entries(
    root: &Folder,
    held_back: &[HeldBackObject],
    entries: &mut Vec<String>,
) -> Result<(), SaveError> {
    for object in held_back {
        if let Some(other) = root.object(&object.name) {
            return Err(SaveError::Invalid(format!(
                "'{}' takes the name of '{}', which failed to load and is kept as it is on \
                 disk; rename one of them",
                other.name(),
                object.entry
            )));
        }
        let folder = folder_entry(&object.folder);
        let position = if object.folder.is_empty() {
            entries.len()
        } else {
            entries
                .iter()
                .rposition(|entry| entry.starts_with(&folder))
                .map_or(entries.len(), |last| last + 1)
        };
        entries.insert(position, object.entry.clone());
    }
    Ok(())
}

fn check_unique_object_names(root: &Folder) -> Result<(), SaveError> {
    let objects = root.objects();
    for (index, object) in objects.iter().enumerate() {
        if !is_valid_identifier(object.name()) {
            return Err(SaveError::Invalid(format!(
                "'{}' is not a valid object name",
                object.name()
            )));
        }
        if objects[..index]
            .iter()
            .any(|other| same_identifier(other.name(), object.name()))
        {
            return Err(SaveError::Invalid(format!(
                "two objects are named '{}'",
                object.name()
            )));
        }
    }
    Ok(())
}

/// Writes `content` to `path` unless the file already holds exactly that; returns whether it
/// wrote. The new content goes to a temporary file beside the target, is flushed to disk and
/// then renamed over the target, so the target is never half-written.
fn write_if_changed(path: &Path, content: &[u8]) -> Result<bool, SaveError> {
    let io_error = |path: &Path| {
        let path = path.to_owned();
        move |source| SaveError::Io { path, source }
    };
    if std::fs::read(path).is_ok_and(|existing| existing == content) {
        return Ok(false);
    }
    let parent = path.parent().unwrap_or(Path::new("."));
    std::fs::create_dir_all(parent).map_err(io_error(parent))?;
    let file_name = path
        .file_name()
        .map(|name| name.to_string_lossy().into_owned())
        .unwrap_or_default();
    let temporary = parent.join(format!(".{file_name}.rivet-tmp"));
    let mut file = std::fs::File::create(&temporary).map_err(io_error(&temporary))?;
    file.write_all(content).map_err(io_error(&temporary))?;
    file.sync_all().map_err(io_error(&temporary))?;
    drop(file);
    std::fs::rename(&temporary, path).map_err(io_error(path))?;
    Ok(true)
}
