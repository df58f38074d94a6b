//! The export of a Rivet project as a PLCopen TC6 XML v2.01 document (`docs/plcopen-xml.md` §5).
//!
//! The document is written with quick-xml's streaming writer straight from the project: the
//! reader's `Document` model says what a file holds, while the export only needs to say what the
//! project holds, and a writer needs no tree.

mod cfc_graph;
mod data_types;
mod error;
mod graph_bodies;
mod network_graph;
mod pous;
mod project_writer;

pub(crate) use project_writer::CREATION_DATE_TIME;
mod rivet_entries;
mod sfc_graph;
mod type_xml;
mod variables;
mod vendor_entries;
mod xml_writer;

#[cfg(test)]
mod export_tests;
#[cfg(test)]
mod round_trip_tests;

pub use error::ExportError;

/// The document `project` exports to: UTF-8 bytes of a v2.01 document that the schema accepts.
///
/// The same project always gives the same bytes: nothing is taken from the clock or the
/// machine. What the schema has no place for is written as Rivet's `addData` (§5.4), so
/// [`crate::import`] gives the project back.
pub fn export(project: &project_model::Project) -> Result<Vec<u8>, ExportError> {
    export_with(project, ExportOptions::default())
}

/// What an export writes beyond PLCopen's own elements.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ExportOptions {
    /// Write each POU's, data type's and list's Rivet entry (§5.4), from which Rivet's import
    /// restores the object whole. Without them an import converts the PLCopen elements, as it
    /// would another tool's file: the tests of the graphical import use it.
    pub object_entries: bool,
}

impl Default for ExportOptions {
    fn default() -> Self {
        Self {
            object_entries: true,
        }
    }
}

/// The document `project` exports to with `options`; see [`export`].
pub fn export_with(
    project: &project_model::Project,
    options: ExportOptions,
) -> Result<Vec<u8>, ExportError> {
    project_writer::ProjectWriter::new(project, options)?.write()
}
