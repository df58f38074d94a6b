//! What `rivet export` and the studio's File ▸ Export PLCopen XML… share
//! (`docs/plcopen-xml.md` §6.4): exporting a project and writing the file so that a failure
//! half-way leaves an earlier file of that name as it was.

use std::ffi::OsString;
use std::io::Write;
use std::path::{Path, PathBuf};

/// Why a project was not exported to a file. Nothing was written; an earlier file of that name
/// is as it was.
#[derive(Debug, thiserror::Error)]
pub enum ExportFailure {
    /// The export refused the project; the error names the object at fault.
    #[error(transparent)]
    Export(#[from] plcopen::ExportError),
    /// The path does not end in a file name (`..`, `/`).
    #[error("{0}: not a file name")]
    NotAFileName(PathBuf),
    /// The file system refused to write or rename the file.
    #[error("{path}: cannot be written: {source}")]
    Write {
        /// The file asked for.
        path: PathBuf,
        /// The operating system's error.
        source: std::io::Error,
    },
}

/// Exports `project` (`docs/plcopen-xml.md` §5) and writes the document to `path` through a
/// new hidden sibling file of a name no other file has (`.NAME.XXXXXX.partial`), synced to disk
/// and renamed onto `path` at the end: a file of the user's is never overwritten but `path`, and
/// a crash leaves `path` whole (old or new), never empty. Gives the number of bytes written.
pub fn write_export(project: &project_model::Project, path: &Path) -> Result<usize, ExportFailure> {
    let xml = plcopen::export(project)?;
    let file_name = path
        .file_name()
        .ok_or_else(|| ExportFailure::NotAFileName(path.to_owned()))?;
    let folder = match path.parent() {
        Some(parent) if !parent.as_os_str().is_empty() => parent,
        _ => Path::new("."),
    };
    let mut prefix = OsString::from(".");
    prefix.push(file_name);
    prefix.push(".");
    let failed = |source: std::io::Error| ExportFailure::Write {
        path: path.to_owned(),
        source,
    };
    // The temporary file removes itself when dropped, so every failure below leaves the
    // folder as it was.
    let mut temporary = tempfile::Builder::new()
        .prefix(&prefix)
        .suffix(".partial")
        .tempfile_in(folder)
        .map_err(failed)?;
    temporary.write_all(&xml).map_err(failed)?;
    // A temporary file is private (0600); the export gets the permissions of the file it
    // replaces, or those of a new file (0644, as the usual umask gives).
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt as _;
        let permissions = std::fs::metadata(path).map_or_else(
            |_| std::fs::Permissions::from_mode(0o644),
            |existing| existing.permissions(),
        );
        temporary
            .as_file()
            .set_permissions(permissions)
            .map_err(failed)?;
    }
    temporary.as_file().sync_all().map_err(failed)?;
    temporary
        .persist(path)
        .map_err(|error| failed(error.error))?;
    Ok(xml.len())
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)] // A panic is a failed test.

    use super::*;

    #[cfg(unix)]
    #[test]
    fn the_export_keeps_the_permissions_of_the_file_it_replaces_or_gets_0644() {
        use std::os::unix::fs::PermissionsExt as _;
        let dir = tempfile::tempdir().unwrap();
        let new = dir.path().join("new.xml");
        write_export(&example(), &new).unwrap();
        let mode = |path: &Path| std::fs::metadata(path).unwrap().permissions().mode() & 0o777;
        assert_eq!(mode(&new), 0o644);
        let old = dir.path().join("old.xml");
        std::fs::write(&old, "earlier").unwrap();
        std::fs::set_permissions(&old, std::fs::Permissions::from_mode(0o640)).unwrap();
        write_export(&example(), &old).unwrap();
        assert_eq!(mode(&old), 0o640);
    }

    fn example() -> project_model::Project {
        project_model::load_project(&assets::example_project_dir())
            .unwrap()
            .project
    }

    #[test]
    fn the_file_holds_the_export_and_no_partial_file_is_left() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("machine.xml");
        std::fs::write(&path, "older").unwrap();
        let project = example();
        let bytes = write_export(&project, &path).unwrap();
        let written = std::fs::read(&path).unwrap();
        assert_eq!(written.len(), bytes);
        assert_eq!(written, plcopen::export(&project).unwrap());
        let names: Vec<_> = std::fs::read_dir(dir.path())
            .unwrap()
            .map(|entry| entry.unwrap().file_name())
            .collect();
        assert_eq!(names, vec![OsString::from("machine.xml")]);
    }

    #[test]
    fn a_users_file_named_like_a_partial_file_is_left_as_it_was() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("machine.xml");
        let users = dir.path().join(".machine.xml.partial");
        std::fs::write(&users, "mine").unwrap();
        write_export(&example(), &path).unwrap();
        assert_eq!(std::fs::read_to_string(&users).unwrap(), "mine");
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 2);
    }

    #[test]
    fn a_folder_that_does_not_exist_is_named_and_nothing_is_written() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("missing").join("machine.xml");
        let error = write_export(&example(), &path).unwrap_err();
        assert!(matches!(error, ExportFailure::Write { .. }), "{error:?}");
        assert!(
            error
                .to_string()
                .starts_with(&format!("{}: cannot be written: ", path.display())),
            "{error}"
        );
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0);
    }

    #[test]
    fn a_rename_onto_a_folder_fails_and_leaves_the_folder_and_no_partial_file() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("taken.xml");
        std::fs::create_dir(&path).unwrap();
        std::fs::write(path.join("inside.txt"), "mine").unwrap();
        let error = write_export(&example(), &path).unwrap_err();
        assert!(matches!(error, ExportFailure::Write { .. }), "{error:?}");
        assert!(path.join("inside.txt").is_file());
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 1);
    }

    #[test]
    fn a_path_without_a_file_name_is_refused() {
        let error = write_export(&example(), Path::new("/")).unwrap_err();
        assert!(matches!(error, ExportFailure::NotAFileName(_)), "{error:?}");
        assert_eq!(error.to_string(), "/: not a file name");
    }
}
