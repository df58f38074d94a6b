//! The state of one conversion: the project so far, the report, and the names already taken.

use std::collections::{HashMap, HashSet};

use project_model::{Node, Object, Project, VendorEntry};

use super::error::{ImportError, ImportErrorKind};
use super::report::{ImportReport, Outcome};
use super::vendor_places::vendor_place;
use crate::add_data::{AddData, AddDataEntry};
use crate::data_type::DataType;
use crate::document::Document;
use crate::text::FormattedText;

/// One conversion in progress.
pub(super) struct Converter<'d> {
    /// The document converted.
    pub document: &'d Document,
    /// The project built so far.
    pub project: Project,
    /// The report so far.
    pub report: ImportReport,
    /// The objects of the application by their lower-case name: the name as written and its line.
    object_names: HashMap<String, (String, u32)>,
    /// The lower-case names of the document's structure types, which a block with one unnamed
    /// output or input composes or selects (docs/plcopen-xml.md §4.5).
    pub structures: HashSet<String>,
    /// The paths of the `addData` entries of converted objects reported so far: an object in
    /// both a wired condition and its SFC body, or read by two conditions, is reported once.
    pub reported_object_data: HashSet<String>,
}

/// Where an element stands, for errors and the report.
#[derive(Clone, Debug)]
pub(super) struct Place {
    /// The element path.
    pub path: String,
    /// Line (1-based).
    pub line: u32,
    /// Column (1-based).
    pub column: u32,
}

impl<'d> Converter<'d> {
    /// A conversion of `document` into an empty project.
    pub fn new(document: &'d Document) -> Self {
        Self {
            document,
            project: Project::default(),
            report: ImportReport::default(),
            object_names: HashMap::new(),
            structures: document
                .data_types
                .iter()
                .filter(|declared| matches!(declared.base_type, DataType::Struct { .. }))
                .map(|declared| declared.name.trim().to_lowercase())
                .collect(),
            reported_object_data: HashSet::new(),
        }
    }

    /// The error `kind` at `place`.
    pub fn error(&self, place: &Place, kind: ImportErrorKind) -> ImportError {
        ImportError {
            file: self.document.file_name.clone(),
            line: place.line,
            column: place.column,
            path: place.path.clone(),
            kind: Box::new(kind),
        }
    }

    /// Adds `object` to the application folder, refusing a name already taken (without regard to
    /// case) or one that is not an identifier.
    pub fn add_object(
        &mut self,
        what: &'static str,
        object: Object,
        place: &Place,
    ) -> Result<(), ImportError> {
        let name = object.name().to_owned();
        if !project_model::is_valid_identifier(&name) {
            return Err(self.error(place, ImportErrorKind::BadName(name)));
        }
        let key = name.to_lowercase();
        if let Some((first, first_line)) = self.object_names.get(&key) {
            return Err(self.error(
                place,
                ImportErrorKind::DuplicateName {
                    what,
                    name,
                    first: first.clone(),
                    first_line: *first_line,
                },
            ));
        }
        self.object_names.insert(key, (name, place.line));
        self.project.application.children.push(Node::Object(object));
        Ok(())
    }

    /// Keeps every `addData` entry of an element in the project's vendor data and lists it as
    /// kept opaque.
    pub fn opaque(&mut self, add_data: &AddData, path: &str, line: u32) {
        // Rivet's own entries are read back, not kept (§5.4).
        for entry in add_data
            .entries
            .iter()
            .filter(|entry| !is_rivet_entry(&entry.name))
        {
            self.keep_vendor_entry(entry, path, line);
        }
    }

    /// Keeps one entry of the element at `path` in the project's vendor data (§2.6), or reports
    /// it not converted when its XML cannot stand alone.
    pub fn keep_vendor_entry(&mut self, entry: &AddDataEntry, path: &str, line: u32) {
        self.keep_vendor_entry_at(entry, path, line, vendor_place(path), None);
    }

    /// Keeps one entry of the element at `path` at `place` in the project's vendor data, or
    /// reports it not converted when its XML cannot stand alone.
    pub fn keep_vendor_entry_at(
        &mut self,
        entry: &AddDataEntry,
        path: &str,
        line: u32,
        place: String,
        signature: Option<String>,
    ) {
        let what = format!("addData '{}'", entry.name);
        let entry_path = format!("{path}/addData/data[@name='{}']", entry.name);
        // The entry's text leaves out its ancestors' namespace declarations; the export
        // declares only `xhtml`, so an entry using another prefix from outside cannot go back.
        let standalone = format!(
            "<r xmlns:xhtml=\"http://www.w3.org/1999/xhtml\">{}</r>",
            entry.xml
        );
        if let Err(error) = roxmltree::Document::parse(&standalone) {
            let note = format!("its XML cannot be written back on its own: {error}");
            self.report
                .push(Outcome::NotConverted, what, &entry_path, line, note);
            return;
        }
        self.project.vendor_data.entries.push(VendorEntry {
            place,
            xml: entry.xml.clone(),
            signature,
        });
        self.report
            .push(Outcome::KeptOpaque, what, &entry_path, line, "");
    }
}

/// True for the entries of Rivet's own data, which the import reads rather than keeps.
pub(super) fn is_rivet_entry(name: &str) -> bool {
    name.starts_with(crate::rivet_data::RIVET_NAMESPACE)
}

/// The comment of a documentation: its text without the blank lines and spaces around it.
pub(super) fn comment(documentation: Option<&FormattedText>) -> String {
    documentation.map_or_else(String::new, |text| text.text.trim().to_owned())
}
