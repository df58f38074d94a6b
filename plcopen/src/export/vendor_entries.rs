//! Another tool's `addData` entries, kept in the project's vendor data, written back where they
//! came from (`docs/plcopen-xml.md` §5.5).

use std::collections::BTreeMap;

use super::error::ExportError;
use super::project_writer::ProjectWriter;
use crate::rivet_data::{RIVET_NAMESPACE, VENDOR_ENTRY};

impl ProjectWriter<'_> {
    /// True when the vendor data has entries at `place`.
    pub(super) fn has_vendor_entries(&self, place: &str) -> bool {
        self.project.vendor_data.at(place).next().is_some()
    }

    /// Writes the vendor entries of `place` as they were (inside an `addData` the caller opened).
    pub(super) fn vendor_entries(&mut self, place: &str) -> Result<(), ExportError> {
        let project = self.project;
        for entry in project.vendor_data.at(place) {
            self.xml.raw(&entry.xml)?;
        }
        self.written_places.insert(place.to_owned());
        Ok(())
    }

    /// The vendor entries of the elements of the body at `body_place` (places
    /// `BODY/element:ID`), by element id, each entry's XML as it was.
    pub(super) fn element_entries(&self, body_place: &str) -> BTreeMap<u64, Vec<String>> {
        let prefix = format!("{body_place}/element:");
        let mut entries: BTreeMap<u64, Vec<String>> = BTreeMap::new();
        for entry in &self.project.vendor_data.entries {
            if let Some(id) = entry
                .place
                .strip_prefix(&prefix)
                .and_then(|id| id.parse::<u64>().ok())
            {
                entries.entry(id).or_default().push(entry.xml.clone());
            }
        }
        entries
    }

    /// Writes an `addData` with the vendor entries of `place`, when there are any.
    pub(super) fn vendor_add_data(&mut self, place: &str) -> Result<(), ExportError> {
        if !self.has_vendor_entries(place) {
            return Ok(());
        }
        self.xml.start("addData", &[])?;
        self.vendor_entries(place)?;
        self.xml.end("addData")
    }

    /// Writes the vendor entries whose place the document did not have (a POU Rivet did not
    /// convert, a variable since deleted) in Rivet's `…/vendor` entries, so an import gives
    /// them back with their place.
    pub(super) fn leftover_vendor_entries(&mut self) -> Result<(), ExportError> {
        let project = self.project;
        self.xml.context = "the vendor data".into();
        for entry in &project.vendor_data.entries {
            if self.written_places.contains(&entry.place) {
                continue;
            }
            self.xml.start(
                "data",
                &[("name", VENDOR_ENTRY), ("handleUnknown", "preserve")],
            )?;
            self.xml.start(
                "vendor",
                &[("xmlns", RIVET_NAMESPACE), ("place", &entry.place)],
            )?;
            self.xml.cdata(&entry.xml)?;
            self.xml.end("vendor")?;
            self.xml.end("data")?;
        }
        Ok(())
    }
}
