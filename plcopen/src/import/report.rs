//! The import report: what the conversion did with every part of the document.

/// Every object converted, every vendor element kept opaque and every object not converted,
/// in document order.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct ImportReport {
    /// The entries in document order.
    pub entries: Vec<ReportEntry>,
}

/// One line of the report.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ReportEntry {
    /// What happened to the part.
    pub outcome: Outcome,
    /// What the part is, such as `POU 'Main'` or `addData 'http://…/objectid'`.
    pub what: String,
    /// The element path of the part (the format of error messages).
    pub path: String,
    /// Line of the element in the file (1-based; that of the nearest element the model keeps a
    /// line for).
    pub line: u32,
    /// Why, or what changed on the way, when there is more to say; empty otherwise.
    pub note: String,
}

/// What happened to a part of the document.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Outcome {
    /// It is part of the project.
    Converted,
    /// Rivet does not model it; it is kept as written for the export (vendor `addData`).
    KeptOpaque,
    /// It is not part of the project.
    NotConverted,
}

impl ImportReport {
    /// Adds an entry.
    pub(super) fn push(
        &mut self,
        outcome: Outcome,
        what: String,
        path: &str,
        line: u32,
        note: impl Into<String>,
    ) {
        self.entries.push(ReportEntry {
            outcome,
            what,
            path: path.to_owned(),
            line,
            note: note.into(),
        });
    }

    /// The entries with `outcome`.
    pub fn with_outcome(&self, outcome: Outcome) -> impl Iterator<Item = &ReportEntry> {
        self.entries
            .iter()
            .filter(move |entry| entry.outcome == outcome)
    }

    /// The entry about `what` (such as `POU 'Main'`), if any.
    pub fn entry(&self, what: &str) -> Option<&ReportEntry> {
        self.entries.iter().find(|entry| entry.what == what)
    }
}
