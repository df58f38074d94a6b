//! An open project: the model, its undo history and the files it came from.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use project_model::{
    HeldBackObject, History, LoadError, LoadProblem, MANIFEST_FILE_NAME, Project, SaveError,
    SaveReport, load_project, save_project_keeping,
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
    /// Problems from loading: warnings, such as files in the folder that are not part of the
    /// project, and the errors of the objects that could not be loaded.
    pub load_problems: Vec<LoadProblem>,
    /// The objects that could not be loaded: left out of `project`, and kept unchanged on disk
    /// and in the manifest by every save to the same folder, so nothing the user wrote is lost
    /// while they fix the file.
    pub held_back: Vec<HeldBackObject>,
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
    /// Loads the project in `dir`. A project whose manifest is sound opens even when some of its
    /// objects fail to load: they are held back and their errors listed. Nothing on disk
    /// changes, whatever the outcome.
    pub fn open(dir: &Path) -> Result<Self, LoadError> {
        let (loaded, load_problems) = match load_project(dir) {
            Ok(loaded) => {
                let warnings = loaded.warnings.clone();
                (loaded, warnings)
            }
            Err(LoadError {
                problems,
                partial: Some(partial),
            }) => (*partial, problems),
            Err(error) => return Err(error),
        };
        Ok(Self {
            dir: dir.to_owned(),
            saved: Arc::new(loaded.project.clone()),
            project: loaded.project,
            history: History::new(),
            files: loaded.files,
            load_problems,
            held_back: loaded.held_back,
        })
    }

    /// Saves the project to its folder; files whose content did not change are not rewritten.
    pub fn save(&mut self) -> Result<SaveReport, SaveError> {
        let report = save_project_keeping(&self.project, &self.dir, &self.files, &self.held_back)?;
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
        // Objects that could not be loaded go along as their files were, byte for byte, so a
        // copy of a partly loaded project loses nothing.
        copy_held_back_files(&self.held_back, &self.dir, dir)?;
        let report = save_project_keeping(&self.project, dir, &BTreeSet::new(), &self.held_back)?;
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

/// Copies the files of the held-back objects from the project folder `from` into `to`,
/// unchanged.
fn copy_held_back_files(
    held_back: &[HeldBackObject],
    from: &Path,
    to: &Path,
) -> Result<(), SaveError> {
    let io = |path: PathBuf| move |source| SaveError::Io { path, source };
    for object in held_back {
        let folder = object.file_prefix.parent().unwrap_or(Path::new(""));
        let Ok(entries) = std::fs::read_dir(from.join(folder)) else {
            continue;
        };
        for entry in entries {
            let file = folder.join(entry.map_err(io(from.join(folder)))?.file_name());
            if object.owns(&file) && from.join(&file).is_file() {
                std::fs::create_dir_all(to.join(folder)).map_err(io(to.join(folder)))?;
                std::fs::copy(from.join(&file), to.join(&file)).map_err(io(to.join(&file)))?;
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A project with an ST program and an LD program whose body repeats an element id, so the
    /// LD program cannot be loaded.
    fn project_with_a_broken_object(dir: &Path) -> String {
        let broken = "kind = \"program\"\n\n[body]\nlanguage = \"ld\"\n\n[[body.network]]\nrung = [\n    { type = \"operand\", id = 1, text = \"a\" },\n    { type = \"operand\", id = 1, text = \"b\" },\n]\n";
        std::fs::create_dir_all(dir.join("application")).unwrap();
        std::fs::write(
            dir.join(MANIFEST_FILE_NAME),
            "format_version = 3\nname = \"Partly\"\napplication = [\"Good.pou.toml\", \"Broken.pou.toml\"]\ncontroller = { name = \"PLC\", host = \"127.0.0.1\", port = 502 }\n",
        )
        .unwrap();
        std::fs::write(
            dir.join("application/Good.pou.toml"),
            "kind = \"program\"\n\n[body]\nlanguage = \"st\"\n",
        )
        .unwrap();
        std::fs::write(dir.join("application/Good.st"), "").unwrap();
        std::fs::write(dir.join("application/Broken.pou.toml"), broken).unwrap();
        broken.to_owned()
    }

    #[test]
    fn a_project_opens_without_the_objects_that_fail_and_saving_keeps_their_files() {
        let folder = tempfile::tempdir().unwrap();
        let dir = folder.path().join("project");
        let broken = project_with_a_broken_object(&dir);

        let mut session = Session::open(&dir).unwrap();
        assert!(session.project.application.object("Good").is_some());
        assert!(session.project.application.object("Broken").is_none());
        assert_eq!(session.held_back.len(), 1);
        let problems = session
            .load_problems
            .iter()
            .map(ToString::to_string)
            .collect::<Vec<_>>()
            .join("\n");
        assert!(
            problems.contains("Broken.pou.toml") && problems.contains("element 1"),
            "{problems}"
        );

        // A change saved to the same folder, then a copy to another: the broken file goes
        // along unchanged and stays in the manifest.
        session.project.name = "Partly changed".into();
        session.save().unwrap();
        let copy = folder.path().join("copy");
        session.save_as(&copy).unwrap();
        for dir in [&dir, &copy] {
            let kept = std::fs::read_to_string(dir.join("application/Broken.pou.toml")).unwrap();
            assert_eq!(kept, broken);
            let manifest = std::fs::read_to_string(dir.join(MANIFEST_FILE_NAME)).unwrap();
            assert!(manifest.contains("Broken.pou.toml"), "{manifest}");
        }
    }
}
