//! An open project: the model, its undo history and the files it came from.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use project_model::{
    History, LoadError, LoadProblem, MANIFEST_FILE_NAME, Project, SaveError, SaveReport,
    load_project, save_project,
};
use thiserror::Error;

/// A project open in the studio.
///
/// It lives from opening the project until another is opened or the studio closes. The project
/// is changed only through `history`, so the dirty flag and undo stay right.
pub struct Session {
    /// The project folder.
    pub dir: PathBuf,
    /// The project model, the ground truth every view draws from.
    pub project: Project,
    /// Undo and redo; its save point tells whether there are unsaved changes.
    pub history: History,
    /// The files the project was loaded from or last saved to, relative to `dir`.
    pub files: BTreeSet<PathBuf>,
    /// Warnings from loading, such as files in the folder that are not part of the project.
    pub warnings: Vec<LoadProblem>,
    /// The project as last loaded or saved, which the device tree compares nodes with to mark
    /// the changed ones. Shared, so a view can tell cheaply whether it was replaced.
    pub saved: Arc<Project>,
}

/// Why "Save as" refused or failed.
#[derive(Debug, Error)]
pub enum SaveAsError {
    /// The chosen folder already holds another project, which would be overwritten.
    #[error("{0} already holds a project ({MANIFEST_FILE_NAME}); choose an empty folder")]
    FolderHoldsProject(PathBuf),
    /// Writing failed.
    #[error(transparent)]
    Save(#[from] SaveError),
}

impl Session {
    /// Loads the project in `dir`. Nothing on disk changes, whatever the outcome.
    pub fn open(dir: &Path) -> Result<Self, LoadError> {
        let loaded = load_project(dir)?;
        Ok(Self {
            dir: dir.to_owned(),
            saved: Arc::new(loaded.project.clone()),
            project: loaded.project,
            history: History::new(),
            files: loaded.files,
            warnings: loaded.warnings,
        })
    }

    /// Saves the project to its folder; files whose content did not change are not rewritten.
    pub fn save(&mut self) -> Result<SaveReport, SaveError> {
        let report = save_project(&self.project, &self.dir, &self.files)?;
        self.files = report.files.clone();
        self.history.mark_saved();
        self.saved = Arc::new(self.project.clone());
        Ok(report)
    }

    /// Saves the project into another folder, which becomes the project's folder.
    ///
    /// A folder that already holds a project is refused, so no one's work is overwritten.
    pub fn save_as(&mut self, dir: &Path) -> Result<SaveReport, SaveAsError> {
        let same_folder = dir.canonicalize().ok() == self.dir.canonicalize().ok();
        if same_folder {
            return Ok(self.save()?);
        }
        if dir.join(MANIFEST_FILE_NAME).exists() {
            return Err(SaveAsError::FolderHoldsProject(dir.to_owned()));
        }
        let report = save_project(&self.project, dir, &BTreeSet::new())?;
        self.dir = dir.to_owned();
        self.files = report.files.clone();
        self.history.mark_saved();
        self.saved = Arc::new(self.project.clone());
        Ok(report)
    }

    /// The folder's name, for the window title when the project has no name.
    pub fn title(&self) -> String {
        if self.project.name.is_empty() {
            self.dir
                .file_name()
                .map(|name| name.to_string_lossy().into_owned())
                .unwrap_or_default()
        } else {
            self.project.name.clone()
        }
    }
}
