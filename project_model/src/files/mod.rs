//! Loading and saving projects as folders of text files.
//!
//! The format is specified in `docs/project-format.md`: a manifest `rivet.toml` plus one TOML
//! file per application object under `application/`, with ST bodies in `.st` files beside them.
//! Files are written in a canonical form, unchanged files are not rewritten, and each file is
//! replaced atomically.

mod canonical;
mod chart_conversion;
mod graph_chart;
mod held_back;
mod layout;
mod load;
mod manifest;
mod older_charts;
mod older_sfc;
mod older_versions;
mod problem;
mod save;

pub use held_back::HeldBackObject;
pub(crate) use layout::body_slots;
pub use layout::{StBody, object_files, st_body_files, text_body_files};
pub use load::{LoadedProject, load_project};
pub use problem::{LoadError, LoadProblem, Severity};
pub use save::{SaveError, SaveReport, save_project, save_project_keeping};

/// The project format version this build reads and writes.
pub const FORMAT_VERSION: u32 = 3;

/// The name of the manifest file at the root of a project folder.
pub const MANIFEST_FILE_NAME: &str = "rivet.toml";

/// The name of the file beside the manifest that holds the vendor data of an imported PLCopen
/// file, present only when there is some.
pub const VENDOR_DATA_FILE_NAME: &str = "plcopen.toml";

/// The folder, relative to the project folder, that holds the application's objects.
pub const APPLICATION_DIR: &str = "application";
