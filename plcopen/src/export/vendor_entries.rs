//! Another tool's `addData` entries, kept in the project's vendor data, written back where they
//! came from (`docs/plcopen-xml.md` §5.5).

use std::collections::BTreeMap;

use project_model::{ElementId, Network};

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
    /// `BODY/element:ID`) that `networks` still hold as they were imported, by element id, each
    /// entry's XML as it was. An entry whose element is gone or was changed (its signature is
    /// not the element's: an edit gave the id to another element, or changed the element) is
    /// left out, so it is written with the leftovers, never into another element (§5.5).
    pub(super) fn element_entries(
        &self,
        body_place: &str,
        networks: &[Network],
    ) -> BTreeMap<u64, Vec<String>> {
        let prefix = format!("{body_place}/element:");
        let mut entries: BTreeMap<u64, Vec<String>> = BTreeMap::new();
        for entry in &self.project.vendor_data.entries {
            let Some(id) = entry
                .place
                .strip_prefix(&prefix)
                .and_then(|id| id.parse::<u32>().ok())
            else {
                continue;
            };
            let element = networks
                .iter()
                .find_map(|network| network.element(ElementId(id)));
            if element.is_some_and(|element| entry.fits(element)) {
                entries
                    .entry(u64::from(id))
                    .or_default()
                    .push(entry.xml.clone());
            }
        }
        entries
    }

    /// Records which entries of the elements of the body at `body_place` went into their
    /// elements: those of the elements in `written` (ids) that fit them, as
    /// [`Self::element_entries`] chose them.
    pub(super) fn mark_element_entries_written(
        &mut self,
        body_place: &str,
        networks: &[Network],
        written: &[u64],
    ) {
        let prefix = format!("{body_place}/element:");
        for (index, entry) in self.project.vendor_data.entries.iter().enumerate() {
            let Some(id) = entry
                .place
                .strip_prefix(&prefix)
                .and_then(|id| id.parse::<u32>().ok())
            else {
                continue;
            };
            if !written.contains(&u64::from(id)) {
                continue;
            }
            let element = networks
                .iter()
                .find_map(|network| network.element(ElementId(id)));
            if element.is_some_and(|element| entry.fits(element)) {
                self.written_element_entries.insert(index);
            }
        }
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
        for (index, entry) in project.vendor_data.entries.iter().enumerate() {
            if self.written_places.contains(&entry.place)
                || self.written_element_entries.contains(&index)
            {
                continue;
            }
            self.xml.start(
                "data",
                &[("name", VENDOR_ENTRY), ("handleUnknown", "preserve")],
            )?;
            let mut attributes = vec![("xmlns", RIVET_NAMESPACE), ("place", entry.place.as_str())];
            // An element's entry keeps its element's signature, so that an import of this
            // file does not put it into another element that has its id by then.
            if let Some(signature) = &entry.signature {
                attributes.push(("signature", signature.as_str()));
            }
            self.xml.start("vendor", &attributes)?;
            self.xml.cdata(&entry.xml)?;
            self.xml.end("vendor")?;
            self.xml.end("data")?;
        }
        Ok(())
    }
}
