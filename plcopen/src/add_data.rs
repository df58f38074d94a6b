//! Vendor extensions (`addData/data`), kept opaque.

/// The `addData` of an element: every `data` entry in document order, none interpreted.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct AddData {
    /// The entries as written.
    pub entries: Vec<AddDataEntry>,
}

impl AddData {
    /// True when the element had no `addData` entry.
    pub fn is_empty(&self) -> bool {
        self.entries.is_empty()
    }

    /// The first entry whose `name` ends with `suffix` (vendors name entries by URI, such as
    /// `http://www.3s-software.com/plcopenxml/cfc`).
    pub fn entry_ending_with(&self, suffix: &str) -> Option<&AddDataEntry> {
        self.entries
            .iter()
            .find(|entry| entry.name.ends_with(suffix))
    }
}

/// One `addData/data` element.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct AddDataEntry {
    /// The `name` attribute, a URI naming the vendor's extension.
    pub name: String,
    /// What a tool that does not understand the entry must do with it.
    pub handle_unknown: HandleUnknown,
    /// The whole `data` element as it stands in the file, from `<data` to `</data>`, so it can be
    /// written back unchanged (namespace declarations of its ancestors are not part of it).
    pub xml: String,
}

/// The `handleUnknown` attribute of an `addData/data` entry.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum HandleUnknown {
    /// Keep the entry on export.
    Preserve,
    /// The entry may be dropped.
    Discard,
    /// The entry belongs to the implementation that wrote it; keep it opaquely.
    Implementation,
}

impl HandleUnknown {
    /// The value as written in the file.
    pub fn as_str(self) -> &'static str {
        match self {
            HandleUnknown::Preserve => "preserve",
            HandleUnknown::Discard => "discard",
            HandleUnknown::Implementation => "implementation",
        }
    }

    /// The value of an attribute, or `None` when it is not one of the three.
    pub fn parse(text: &str) -> Option<HandleUnknown> {
        match text {
            "preserve" => Some(HandleUnknown::Preserve),
            "discard" => Some(HandleUnknown::Discard),
            "implementation" => Some(HandleUnknown::Implementation),
            _ => None,
        }
    }
}
