//! Reading a project folder into a [`Project`], collecting every problem on the way.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

use serde::de::DeserializeOwned;
use toml::Spanned;

use super::held_back::HeldBackObject;
use super::layout::{Entry, bodies_mut, body_slots, folder_dir, object_file, parse_entry};
use super::manifest::{Manifest, VersionProbe};
use super::older_versions::{OlderFailure, pou_from_older};
use super::problem::{LoadError, LoadProblem, Severity, line_of, toml_problem};
use super::{APPLICATION_DIR, FORMAT_VERSION, MANIFEST_FILE_NAME, VENDOR_DATA_FILE_NAME};
use crate::modbus_device_file::ModbusDeviceFile;
use crate::validate::{body_problems, member_problem};
use crate::{
    Body, Folder, ModbusDevice, Node, Object, ObjectKind, Pou, Project, VendorData, same_identifier,
};

/// A project read from disk.
#[derive(Clone, Debug, PartialEq)]
pub struct LoadedProject {
    /// The project.
    pub project: Project,
    /// Things in the folder that are not part of the project, such as unlisted files.
    pub warnings: Vec<LoadProblem>,
    /// The files the project was read from, relative to its folder. Saving removes those of
    /// them that the project no longer needs, and never touches any other file.
    pub files: BTreeSet<PathBuf>,
    /// The objects that failed to load, in manifest order: empty for a project that loaded
    /// whole. Their files are not in `files`; pass them to `save_project_keeping`.
    pub held_back: Vec<HeldBackObject>,
}

/// Reads the project in folder `dir`.
///
/// Nothing on disk is changed. On failure every problem found is returned, each naming its file
/// and, where it has one, its line. When only some application objects failed (a file that
/// is not valid TOML, a broken LD/FBD body…) and the manifest is sound, the error also holds
/// the rest of the project in `partial`, with those objects held back, so it can be opened
/// and edited.
pub fn load_project(dir: &Path) -> Result<LoadedProject, LoadError> {
    let mut loader = Loader {
        dir,
        problems: Vec::new(),
        files: BTreeSet::new(),
        held_back: Vec::new(),
        object_errors: 0,
        version: FORMAT_VERSION,
    };
    let project = loader.load();
    let errors = loader
        .problems
        .iter()
        .filter(|problem| problem.severity == Severity::Error)
        .count();
    let Some(project) = project else {
        return Err(LoadError {
            problems: loader.problems,
            partial: None,
        });
    };
    if errors > 0 && errors != loader.object_errors {
        return Err(LoadError {
            problems: loader.problems,
            partial: None,
        });
    }
    loader.report_unlisted_files();
    let Loader {
        problems,
        mut files,
        held_back,
        ..
    } = loader;
    files.retain(|file| !held_back.iter().any(|object| object.owns(file)));
    let warnings: Vec<LoadProblem> = problems
        .iter()
        .filter(|problem| problem.severity == Severity::Warning)
        .cloned()
        .collect();
    let loaded = LoadedProject {
        project,
        warnings,
        files,
        held_back,
    };
    if errors == 0 {
        Ok(loaded)
    } else {
        Err(LoadError {
            problems,
            partial: Some(Box::new(loaded)),
        })
    }
}

struct Loader<'a> {
    dir: &'a Path,
    problems: Vec<LoadProblem>,
    files: BTreeSet<PathBuf>,
    /// The objects that failed to load.
    held_back: Vec<HeldBackObject>,
    /// How many of the errors belong to held-back objects; when they are all the errors,
    /// the rest of the project is sound.
    object_errors: usize,
    /// The format version of the manifest, which decides how POU files are read.
    version: u32,
}

impl Loader<'_> {
    fn load(&mut self) -> Option<Project> {
        let manifest_file = PathBuf::from(MANIFEST_FILE_NAME);
        let text = self.read_text(&manifest_file)?;
        let display = self.dir.join(&manifest_file);
        if !self.check_version(&display, &text) {
            return None;
        }
        let manifest: Manifest = self.parse(&manifest_file, &text)?;
        let mut application = Folder::default();
        for entry in &manifest.application {
            let line = line_of(&text, entry.span().start);
            self.load_entry(&mut application, entry.get_ref(), &display, line);
        }
        let modbus_devices = self.modbus_devices(manifest.modbus_devices, &display, &text);
        let vendor_data = self.load_vendor_data()?;
        Some(Project {
            vendor_data,
            name: manifest.name,
            description: manifest.description,
            controller: manifest.controller,
            tasks: manifest.tasks,
            io_areas: manifest.io_areas,
            serial_ports: manifest.serial_ports,
            modbus_devices,
            axes: manifest.axes,
            dialect: manifest.dialect,
            application,
        })
    }

    /// The devices of the manifest's `[[modbus_device]]` tables; a table whose link is wrong
    /// (both `host`/`port` and `serial_port`, or neither) is reported at its own line and left out.
    fn modbus_devices(
        &mut self,
        tables: Vec<Spanned<ModbusDeviceFile>>,
        manifest: &Path,
        text: &str,
    ) -> Vec<ModbusDevice> {
        let mut devices = Vec::with_capacity(tables.len());
        for table in tables {
            let line = line_of(text, table.span().start);
            match ModbusDevice::try_from(table.into_inner()) {
                Ok(device) => devices.push(device),
                Err(error) => {
                    self.problems
                        .push(LoadProblem::error(manifest, Some(line), error.to_string()))
                }
            }
        }
        devices
    }

    /// The vendor data of `plcopen.toml`, empty when the file is absent; `None` (with the
    /// problem reported) when it cannot be read.
    fn load_vendor_data(&mut self) -> Option<VendorData> {
        let file = PathBuf::from(VENDOR_DATA_FILE_NAME);
        if !self.dir.join(&file).exists() {
            return Some(VendorData::default());
        }
        let text = self.read_text(&file)?;
        self.parse(&file, &text)
    }

    /// Reports a missing or foreign format version; returns whether loading can go on.
    fn check_version(&mut self, display: &Path, text: &str) -> bool {
        let probe = match toml::from_str::<VersionProbe>(text) {
            Ok(probe) => probe,
            Err(error) => {
                self.problems
                    .push(toml_problem(display.into(), text, &error));
                return false;
            }
        };
        let Some(version) = probe.format_version else {
            self.problems.push(LoadProblem::error(
                display,
                Some(1),
                format!("missing 'format_version'; expected 'format_version = {FORMAT_VERSION}'"),
            ));
            return false;
        };
        let line = line_of(text, version.span().start);
        let found = *version.get_ref();
        if let Ok(known) = u32::try_from(found)
            && (1..=FORMAT_VERSION).contains(&known)
        {
            self.version = known;
            return true;
        }
        let message = if found > i64::from(FORMAT_VERSION) {
            format!(
                "format_version {found} was written by a newer Rivet; this one reads version \
                 {FORMAT_VERSION}"
            )
        } else {
            format!(
                "format_version {found} is not a Rivet project format; expected 1 to \
                 {FORMAT_VERSION}"
            )
        };
        self.problems
            .push(LoadProblem::error(display, Some(line), message));
        false
    }

    fn load_entry(&mut self, root: &mut Folder, entry: &str, manifest: &Path, line: usize) {
        let entry_error = |message: String| LoadProblem::error(manifest, Some(line), message);
        let parsed = match parse_entry(entry) {
            Ok(parsed) => parsed,
            Err(error) => return self.problems.push(entry_error(error.to_string())),
        };
        let folder_path: Vec<String> = match &parsed {
            Entry::Folder(path) => path[..path.len().saturating_sub(1)].to_vec(),
            Entry::Object { folder, .. } => folder.clone(),
        };
        let folder_path = &folder_path[..];
        let Some(parent) = root.folder(folder_path) else {
            return self.problems.push(entry_error(format!(
                "'{entry}' is in folder '{}', which is not listed before it; list the folder \
                 first, as '{}/'",
                folder_path.join("/"),
                folder_path.join("/")
            )));
        };
        match parsed {
            Entry::Folder(path) => {
                let Some(name) = path.last() else {
                    return self
                        .problems
                        .push(entry_error("'/' is not a folder; name the folder".into()));
                };
                let duplicate = parent.children.iter().any(|node| {
                    matches!(node, Node::Folder(folder) if same_identifier(&folder.name, name))
                });
                if duplicate {
                    return self
                        .problems
                        .push(entry_error(format!("folder '{entry}' is listed twice")));
                }
                let folder = Folder {
                    name: name.clone(),
                    children: Vec::new(),
                };
                if let Some(parent) = root.folder_mut(folder_path) {
                    parent.children.push(Node::Folder(folder));
                }
                // An empty folder has no directory on disk: git keeps no empty directories.
            }
            Entry::Object { folder, name, kind } => {
                let other = root
                    .object(&name)
                    .map(|other| other.name().to_owned())
                    .or_else(|| {
                        self.held_back
                            .iter()
                            .find(|held| same_identifier(&held.name, &name))
                            .map(|held| held.name.clone())
                    });
                if let Some(other) = other {
                    return self.problems.push(entry_error(format!(
                        "'{entry}': the name '{name}' is already used by '{other}' (names are \
                         compared without case)"
                    )));
                }
                let errors_before = self.problems.len();
                let Some(object) = self.load_object(&folder, &name, kind) else {
                    self.object_errors += self.problems[errors_before..]
                        .iter()
                        .filter(|problem| problem.severity == Severity::Error)
                        .count();
                    let mut file_prefix = folder_dir(&folder);
                    file_prefix.push(format!("{name}."));
                    self.held_back.push(HeldBackObject {
                        entry: entry.to_owned(),
                        folder,
                        name,
                        file_prefix,
                    });
                    return;
                };
                if let Some(parent) = root.folder_mut(&folder) {
                    parent.children.push(Node::Object(object));
                }
            }
        }
    }

    fn load_object(&mut self, folder: &[String], name: &str, kind: ObjectKind) -> Option<Object> {
        let file = object_file(folder, name, kind);
        let text = self.read_text(&file)?;
        let mut object = match kind {
            ObjectKind::Pou if self.version < FORMAT_VERSION => {
                Object::Pou(self.parse_pou_older(&file, name, &text)?)
            }
            ObjectKind::Pou => Object::Pou(self.parse(&file, &text)?),
            ObjectKind::Gvl => Object::Gvl(self.parse(&file, &text)?),
            ObjectKind::DataType => Object::DataType(self.parse(&file, &text)?),
            ObjectKind::CamTable => Object::CamTable(self.parse(&file, &text)?),
            ObjectKind::Trace => Object::Trace(self.parse(&file, &text)?),
            ObjectKind::WatchList => Object::WatchList(self.parse(&file, &text)?),
        };
        object.set_name(name.to_owned());
        if let Some(problem) = member_problem(&object) {
            self.problems
                .push(LoadProblem::error(self.dir.join(&file), None, problem));
            return None;
        }
        if let Object::Pou(pou) = &mut object {
            self.load_st_bodies(folder, pou, &file)?;
        }
        let problems = body_problems(&object);
        if !problems.is_empty() {
            for problem in problems {
                self.problems
                    .push(LoadProblem::error(self.dir.join(&file), None, problem));
            }
            return None;
        }
        Some(object)
    }

    /// Fills the text of every ST and IL body of `pou` from its `.st` or `.il` file.
    fn load_st_bodies(&mut self, folder: &[String], pou: &mut Pou, pou_file: &Path) -> Option<()> {
        let suffixes: Vec<Option<String>> = body_slots(pou)
            .into_iter()
            .map(|slot| slot.body.text_extension().map(|_| slot.suffix))
            .collect();
        let pou_name = pou.name.clone();
        let mut complete = true;
        for (body, suffix) in bodies_mut(pou).into_iter().zip(suffixes) {
            let Some(suffix) = suffix else { continue };
            let mut st_file = folder_dir(folder);
            st_file.push(format!("{pou_name}{suffix}"));
            if !self.dir.join(&st_file).is_file() {
                self.problems.push(LoadProblem::error(
                    self.dir.join(&st_file),
                    None,
                    format!(
                        "file not found; {} declares a {} body, whose text belongs in this file",
                        self.dir.join(pou_file).display(),
                        if matches!(body, Body::Il { .. }) {
                            "Instruction List"
                        } else {
                            "Structured Text"
                        }
                    ),
                ));
                complete = false;
                continue;
            }
            match self.read_text(&st_file) {
                Some(read) => {
                    if let Some(text) = body.text_mut() {
                        *text = read;
                    }
                }
                None => complete = false,
            }
        }
        complete.then_some(())
    }

    /// Reads a UTF-8 file and records it as part of the project.
    fn read_text(&mut self, file: &Path) -> Option<String> {
        let path = self.dir.join(file);
        let bytes = match std::fs::read(&path) {
            Ok(bytes) => bytes,
            Err(error) if error.kind() == std::io::ErrorKind::NotFound => {
                let message = if file == Path::new(MANIFEST_FILE_NAME) {
                    format!("file not found; a Rivet project folder holds a {MANIFEST_FILE_NAME}")
                } else {
                    "file not found; it is listed in the manifest".into()
                };
                self.problems.push(LoadProblem::error(path, None, message));
                return None;
            }
            Err(error) => {
                self.problems.push(LoadProblem::error(
                    path,
                    None,
                    format!("cannot read: {error}"),
                ));
                return None;
            }
        };
        self.files.insert(file.to_owned());
        match String::from_utf8(bytes) {
            Ok(text) => Some(text),
            Err(error) => {
                let valid = error.utf8_error().valid_up_to();
                let bytes = error.as_bytes();
                let line = bytes[..valid].iter().filter(|&&b| b == b'\n').count() + 1;
                self.problems.push(LoadProblem::error(
                    path,
                    Some(line),
                    format!("not UTF-8 text (invalid byte at offset {valid}); save it as UTF-8"),
                ));
                None
            }
        }
    }

    /// Reads a POU file of an older format version, converting its graphical bodies.
    fn parse_pou_older(&mut self, file: &Path, name: &str, text: &str) -> Option<Pou> {
        match pou_from_older(self.version, name, text) {
            Ok(pou) => Some(pou),
            Err(OlderFailure::Toml(error)) => {
                self.problems
                    .push(toml_problem(self.dir.join(file), text, &error));
                None
            }
            Err(OlderFailure::Networks(messages)) => {
                for message in messages {
                    self.problems
                        .push(LoadProblem::error(self.dir.join(file), None, message));
                }
                None
            }
        }
    }

    fn parse<T: DeserializeOwned>(&mut self, file: &Path, text: &str) -> Option<T> {
        match toml::from_str(text) {
            Ok(value) => Some(value),
            Err(error) => {
                self.problems
                    .push(toml_problem(self.dir.join(file), text, &error));
                None
            }
        }
    }

    /// Warns about files under `application/` that the project does not use, so a file added
    /// by hand or left by a merge is not silently ignored.
    fn report_unlisted_files(&mut self) {
        let mut pending = vec![PathBuf::from(APPLICATION_DIR)];
        while let Some(relative) = pending.pop() {
            let Ok(entries) = std::fs::read_dir(self.dir.join(&relative)) else {
                continue;
            };
            let mut names: Vec<_> = entries.filter_map(Result::ok).collect();
            names.sort_by_key(|entry| entry.file_name());
            for entry in names {
                let path = relative.join(entry.file_name());
                if entry.file_type().is_ok_and(|t| t.is_dir()) {
                    pending.push(path);
                } else if !self.files.contains(&path)
                    && !self.held_back.iter().any(|object| object.owns(&path))
                {
                    self.problems.push(LoadProblem::warning(
                        self.dir.join(&path),
                        "not part of the project: it is not listed in rivet.toml and belongs to \
                         no listed object; it is left untouched",
                    ));
                }
            }
        }
    }
}
