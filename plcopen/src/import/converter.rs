//! The state of one conversion: the project so far, the report, and the names already taken.

use std::collections::HashMap;

use project_model::{Node, Object, Project};

use super::error::{ImportError, ImportErrorKind};
use super::report::{ImportReport, Outcome};
use crate::add_data::AddData;
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

    /// Lists every `addData` entry of an element as kept opaque.
    pub fn opaque(&mut self, add_data: &AddData, path: &str, line: u32) {
        // Rivet's own entries are read back, not kept (§5.4).
        for entry in add_data
            .entries
            .iter()
            .filter(|entry| !is_rivet_entry(&entry.name))
        {
            self.report.push(
                Outcome::KeptOpaque,
                format!("addData '{}'", entry.name),
                &format!("{path}/addData/data[@name='{}']", entry.name),
                line,
                "",
            );
        }
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
