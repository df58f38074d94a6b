//! Application objects that failed to load, kept out of the project and left untouched on disk.

use std::path::PathBuf;

/// An application object whose files could not be read into the project.
///
/// A project that loads except for some objects can still be opened and edited: the objects
/// are held back, and a save made with them (`save_project_keeping`) keeps their manifest
/// entries and never writes or removes their files, so nothing the user wrote is lost while
/// they fix the file by hand.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct HeldBackObject {
    /// The object's manifest entry as written, such as `Motion/Main.pou.toml`.
    pub entry: String,
    /// The application folder the entry is in, by name from the root.
    pub folder: Vec<String>,
    /// The object's name, from its file name; no other object may take it while it is held
    /// back.
    pub name: String,
    /// Where the object's files begin, relative to the project folder, such as
    /// `application/Motion/Main.`: every file whose path starts so belongs to it.
    pub file_prefix: PathBuf,
}

impl HeldBackObject {
    /// Whether `file`, relative to the project folder, is one of the object's files.
    pub fn owns(&self, file: &std::path::Path) -> bool {
        file.to_string_lossy()
            .starts_with(self.file_prefix.to_string_lossy().as_ref())
    }
}
