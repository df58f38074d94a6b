//! What `rivet import` and the studio's File ▸ Import PLCopen XML… share
//! (`docs/plcopen-xml.md` §6): reading and converting a file, and writing an imported project
//! into a new folder so that a failure half-way leaves nothing behind.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

use plcopen::{Dialect, Document, Imported, Outcome};

/// A PLCopen XML file read and converted.
#[derive(Clone, Debug)]
pub struct ImportedFile {
    /// What the file holds, for the preview.
    pub summary: FileSummary,
    /// The converted project and the report.
    pub imported: Imported,
}

/// What a PLCopen XML file holds, in counts.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FileSummary {
    /// The file name as given.
    pub file: String,
    /// The namespace the file is written in.
    pub dialect: Dialect,
    /// The tool that wrote it and its version, from the file header (`CODESYS V3.5 SP16`).
    pub product: String,
    /// The data types declared.
    pub data_types: usize,
    /// The POUs (those CODESYS writes in a resource's `addData` included).
    pub pous: usize,
    /// The configurations.
    pub configurations: usize,
    /// The tasks of every resource.
    pub tasks: usize,
}

/// Why a file could not be imported; `Display` gives `FILE:LINE:COLUMN: PATH: message` (or
/// `FILE: message` when the file cannot be read at all).
#[derive(Debug, thiserror::Error)]
pub enum ImportFailure {
    /// The file could not be read, or is not a PLCopen XML document the reader accepts.
    #[error(transparent)]
    Read(#[from] plcopen::ReadFileError),
    /// The document could not be converted into a project.
    #[error(transparent)]
    Convert(#[from] plcopen::ImportError),
}

/// Why an imported project was not written into a new folder. Nothing was written.
#[derive(Debug, thiserror::Error)]
pub enum NewProjectError {
    /// The target exists and holds files.
    #[error("{0}: the folder is not empty; nothing was written")]
    NotEmpty(PathBuf),
    /// The target exists and is not a folder.
    #[error("{0}: it is not a folder; nothing was written")]
    NotAFolder(PathBuf),
    /// The file system refused a step.
    #[error("{path}: {source}; nothing was written")]
    Io {
        /// The file or folder of the failed step.
        path: PathBuf,
        /// The operating system's error.
        source: std::io::Error,
    },
    /// The project could not be saved.
    #[error("{0}; nothing was written")]
    Save(#[from] project_model::SaveError),
}

/// Reads `path` and converts it into a project in memory; nothing is written.
pub fn import_file(path: &Path) -> Result<ImportedFile, ImportFailure> {
    let document = plcopen::read_file(path)?;
    let imported = plcopen::import(&document)?;
    Ok(ImportedFile {
        summary: FileSummary::of(&document),
        imported,
    })
}

impl FileSummary {
    /// The summary of `document`.
    pub fn of(document: &Document) -> Self {
        let header = &document.file_header;
        // CODESYS repeats its name in the version (`CODESYS`, `CODESYS V3.5 SP18`).
        let product = if header.product_version.starts_with(&header.product_name) {
            header.product_version.clone()
        } else {
            format!("{} {}", header.product_name, header.product_version)
        };
        Self {
            file: document.file_name.clone(),
            dialect: document.dialect,
            product: product.trim().to_owned(),
            data_types: document.data_types.len(),
            pous: document.pous.len(),
            configurations: document.configurations.len(),
            tasks: document
                .configurations
                .iter()
                .flat_map(|configuration| &configuration.resources)
                .map(|resource| resource.tasks.len())
                .sum(),
        }
    }

    /// The dialect's usual name: `PLCopen TC6 v2.01`, `… v2.00 (CODESYS)`, `… v1.0`.
    pub fn dialect_name(&self) -> &'static str {
        match self.dialect {
            Dialect::V201 => "PLCopen TC6 v2.01",
            Dialect::V200 => "PLCopen TC6 v2.00 (CODESYS)",
            Dialect::V10 => "PLCopen TC6 v1.0",
        }
    }
}

/// How many entries of the report have each outcome: converted, kept opaque, not converted.
pub fn outcome_counts(imported: &Imported) -> [usize; 3] {
    let count = |outcome| imported.report.with_outcome(outcome).count();
    [
        count(Outcome::Converted),
        count(Outcome::KeptOpaque),
        count(Outcome::NotConverted),
    ]
}

/// Writes `project` into `dir`, which must not exist or be an empty folder. The project is
/// saved into a hidden sibling folder first and renamed to `dir` at the end, so a failure
/// half-way leaves neither `dir` nor the sibling behind.
pub fn write_new_project(
    project: &project_model::Project,
    dir: &Path,
) -> Result<(), NewProjectError> {
    let io = |path: &Path| {
        let path = path.to_owned();
        move |source| NewProjectError::Io { path, source }
    };
    match std::fs::metadata(dir) {
        Ok(metadata) if !metadata.is_dir() => {
            return Err(NewProjectError::NotAFolder(dir.to_owned()));
        }
        Ok(_) => {
            if std::fs::read_dir(dir).map_err(io(dir))?.next().is_some() {
                return Err(NewProjectError::NotEmpty(dir.to_owned()));
            }
        }
        Err(error) if error.kind() == std::io::ErrorKind::NotFound => {}
        Err(error) => return Err(io(dir)(error)),
    }
    let staging = staging_folder(dir);
    std::fs::create_dir_all(&staging).map_err(io(&staging))?;
    let written = project_model::save_project(project, &staging, &BTreeSet::new())
        .map_err(NewProjectError::from)
        .and_then(|_| move_into_place(&staging, dir).map_err(io(dir)));
    if written.is_err() {
        // The staging folder is ours alone; nothing of the user's is in it.
        let _ = std::fs::remove_dir_all(&staging);
    }
    written
}

/// Renames `staging` to `dir`. POSIX renames a folder onto an empty one; where the system
/// refuses that (Windows), the empty target is removed first and the rename tried again.
fn move_into_place(staging: &Path, dir: &Path) -> std::io::Result<()> {
    match std::fs::rename(staging, dir) {
        Err(error) if dir.is_dir() => {
            std::fs::remove_dir(dir).map_err(|_| error)?;
            std::fs::rename(staging, dir)
        }
        result => result,
    }
}

/// A fresh hidden sibling of `dir` to save into before the rename.
fn staging_folder(dir: &Path) -> PathBuf {
    let name = dir
        .file_name()
        .map(|name| name.to_string_lossy().into_owned())
        .unwrap_or_else(|| "project".to_owned());
    let parent = dir.parent().unwrap_or_else(|| Path::new("."));
    let mut attempt = 0u32;
    loop {
        let candidate = parent.join(format!(
            ".{name}.rivet-import-{}-{attempt}",
            std::process::id()
        ));
        if !candidate.exists() {
            return candidate;
        }
        attempt += 1;
    }
}

#[cfg(test)]
#[path = "plcopen_import_tests.rs"]
mod tests;
