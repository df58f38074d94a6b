//! Unsaved changes kept safe: while a project has changes that are not saved, a copy is written
//! to a recovery folder outside the project (never over the user's files). After a crash or a
//! quit without saving, opening the project offers the copy back.

use std::collections::BTreeSet;
use std::collections::hash_map::DefaultHasher;
use std::hash::{Hash as _, Hasher as _};
use std::path::{Path, PathBuf};
use std::time::SystemTime;

use project_model::{Project, load_project, save_project};

/// The file in a recovery slot that names the project folder it belongs to.
const ORIGIN_FILE: &str = "origin.txt";
/// The folder in a recovery slot that holds the copy of the project.
const PROJECT_FOLDER: &str = "project";

/// Unsaved changes found for a project.
#[derive(Clone, Debug)]
pub struct Recovered {
    /// The project as it was when the copy was written.
    pub project: Project,
    /// When the copy was written.
    pub written: SystemTime,
}

/// The recovery folder: one slot per project folder.
#[derive(Clone, Debug)]
pub struct Recovery {
    root: PathBuf,
}

impl Recovery {
    /// Keeps recovery copies under `root`.
    pub fn new(root: PathBuf) -> Self {
        Self { root }
    }

    /// The recovery folder of the studio: in the platform's data folder for Rivet.
    pub fn default_location() -> Option<Self> {
        eframe::storage_dir("rivet").map(|dir| Self::new(dir.join("recovery")))
    }

    /// The slot of a project folder, named by a hash of its absolute path.
    fn slot(&self, project_dir: &Path) -> PathBuf {
        let absolute = project_dir
            .canonicalize()
            .unwrap_or_else(|_| project_dir.to_owned());
        let mut hasher = DefaultHasher::new();
        absolute.hash(&mut hasher);
        self.root.join(format!("{:016x}", hasher.finish()))
    }

    /// Writes a copy of `project`, which belongs to `project_dir`. The copy is written beside
    /// the previous one and swapped in, so a crash while writing leaves the previous copy.
    pub fn write(&self, project_dir: &Path, project: &Project) -> std::io::Result<()> {
        let slot = self.slot(project_dir);
        let fresh = slot.join(format!("{PROJECT_FOLDER}.new"));
        if fresh.exists() {
            std::fs::remove_dir_all(&fresh)?;
        }
        std::fs::create_dir_all(&fresh)?;
        save_project(project, &fresh, &BTreeSet::new())
            .map_err(|error| std::io::Error::other(error.to_string()))?;
        std::fs::write(slot.join(ORIGIN_FILE), project_dir.display().to_string())?;
        let current = slot.join(PROJECT_FOLDER);
        if current.exists() {
            std::fs::remove_dir_all(&current)?;
        }
        std::fs::rename(&fresh, &current)
    }

    /// Forgets the copy of `project_dir` (after a save, or when the user discards it).
    pub fn clear(&self, project_dir: &Path) {
        let slot = self.slot(project_dir);
        if slot.exists() {
            // A copy that cannot be removed is offered again next time, which is harmless.
            let _ = std::fs::remove_dir_all(slot);
        }
    }

    /// The copy of `project_dir`'s unsaved changes, if there is one that loads.
    pub fn find(&self, project_dir: &Path) -> Option<Recovered> {
        let folder = self.slot(project_dir).join(PROJECT_FOLDER);
        let written = std::fs::metadata(&folder).and_then(|m| m.modified()).ok()?;
        let loaded = load_project(&folder).ok()?;
        Some(Recovered {
            project: loaded.project,
            written,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_copy_is_found_for_its_folder_only_and_cleared() {
        let root = tempfile::tempdir().unwrap_or_else(|error| panic!("{error}"));
        let recovery = Recovery::new(root.path().to_owned());
        let example = assets::example_project_dir();
        let mut project = load_project(&example)
            .map(|loaded| loaded.project)
            .unwrap_or_else(|error| panic!("{error}"));
        project.description = "changed, not saved".to_owned();
        assert!(recovery.find(&example).is_none());
        recovery
            .write(&example, &project)
            .unwrap_or_else(|error| panic!("{error}"));
        // Writing again replaces the copy.
        recovery
            .write(&example, &project)
            .unwrap_or_else(|error| panic!("{error}"));
        let found = recovery.find(&example).map(|found| found.project);
        assert_eq!(
            found.as_ref().map(|p| p.description.as_str()),
            Some("changed, not saved")
        );
        assert!(recovery.find(root.path()).is_none());
        recovery.clear(&example);
        assert!(recovery.find(&example).is_none());
    }
}
