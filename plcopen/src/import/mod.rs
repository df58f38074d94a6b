//! The conversion of a [`Document`] into a Rivet project (`docs/plcopen-xml.md` §2 and §3).

mod body_fault;
mod cfc_chart;
mod cfc_order;
mod codesys_attributes;
mod converter;
mod data_types;
mod duration;
mod error;
mod globals;
mod network_build;
mod network_dominators;
mod network_elements;
mod network_error;
mod network_gates;
mod network_graph;
mod network_groups;
mod network_import;
#[cfg(test)]
pub(crate) use network_import::number_elements;
mod network_series_parallel;
mod pou_objects;
mod pous;
mod report;
mod rivet_attributes;
mod rivet_data;
mod sfc_chart;
mod sfc_condition;
mod sfc_nested;
mod sfc_step;
mod tasks;
mod type_text;
mod unconverted_body;
mod variables;
mod vendor_places;

#[cfg(test)]
mod bad_input_tests;
#[cfg(test)]
mod cfc_tests;
#[cfg(test)]
pub(crate) mod corpus_tests;
#[cfg(test)]
mod import_tests;
#[cfg(test)]
mod mutation_tests;
#[cfg(test)]
mod network_corpus_tests;
#[cfg(test)]
mod network_tests;
#[cfg(test)]
mod sfc_tests;

use crate::document::Document;
use converter::Converter;

pub use duration::parse_interval_us;
pub use error::{ImportError, ImportErrorKind};
pub use network_error::NetworkError;
pub use report::{ImportReport, Outcome, ReportEntry};

/// A project converted from a document, with the report of what became of each part.
#[derive(Clone, Debug, PartialEq)]
pub struct Imported {
    /// The project, built in memory only: data types, POUs and global variable lists in the
    /// application folder in document order, and the tasks.
    pub project: project_model::Project,
    /// Every object converted, every vendor element kept opaque and every object not converted.
    pub report: ImportReport,
}

/// Converts `document` into a project; nothing is written anywhere.
///
/// ST and IL bodies keep their text; LD and FBD bodies become networks (§3 of
/// `docs/plcopen-xml.md`, an FBD graph that is not a set of networks a CFC chart), SFC bodies
/// charts and CFC bodies (CODESYS's, and FBD bodies Rivet marked as CFC) charts (§4).
pub fn import(document: &Document) -> Result<Imported, ImportError> {
    let mut converter = Converter::new(document);
    converter.project.name = document.content_header.name.clone();
    converter.project.description = document.content_header.comment.clone().unwrap_or_default();
    converter.opaque(
        &document.content_header.add_data,
        "project/contentHeader",
        1,
    );
    converter.data_types()?;
    converter.pous()?;
    converter.globals()?;
    // A document Rivet wrote carries its tasks (with what PLCopen cannot say) in its own data.
    match converter.rivet_project()? {
        Some(entry) => converter.apply_rivet_project(entry)?,
        None => converter.tasks()?,
    }
    converter.opaque(&document.add_data, "project", 1);
    converter.keep_header(document);
    // XML comments (`<!--ObjectVersion: LD1-->`) carry no data and describe the other tool's
    // copy of an element, so the export does not write them back (§5.5); the report says so.
    for comment in &document.xml_comments {
        converter.report.push(
            Outcome::NotConverted,
            format!("XML comment '{}'", comment.text.trim()),
            &comment.parent_path,
            comment.line,
            "an XML comment carries no data and describes the other tool's copy of the element; it is not written back on export",
        );
    }
    Ok(Imported {
        project: converter.project,
        report: converter.report,
    })
}
