//! The attributes of Rivet's small `addData` entries (docs/plcopen-xml.md §4.4, §5.4): an entry named
//! `https://rivet-plc.dev/plcopen/1/WHAT` holding one element `WHAT` of Rivet's namespace.

use std::collections::HashMap;

use crate::add_data::AddData;
use crate::rivet_data::RIVET_NAMESPACE;

/// The attributes of the element `what` in Rivet's entry `…/what` of `add_data`, if the entry
/// is there and well formed.
pub(super) fn rivet_attributes(add_data: &AddData, what: &str) -> Option<HashMap<String, String>> {
    let name = format!("{RIVET_NAMESPACE}/{what}");
    let entry = add_data.entries.iter().find(|entry| entry.name == name)?;
    // The entry's text lost its ancestors' namespace declarations; a wrapper declares the
    // prefixes an exporter may have used, so the text parses either way.
    let wrapped = format!(
        "<wrapper xmlns:rivet=\"{RIVET_NAMESPACE}\" xmlns:xhtml=\"http://www.w3.org/1999/xhtml\">{}</wrapper>",
        entry.xml
    );
    let document = roxmltree::Document::parse(&wrapped).ok()?;
    let element = document
        .descendants()
        .find(|node| node.is_element() && node.tag_name().name() == what)?;
    Some(
        element
            .attributes()
            .map(|attribute| (attribute.name().to_owned(), attribute.value().to_owned()))
            .collect(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::add_data::{AddDataEntry, HandleUnknown};

    #[test]
    fn reads_the_attributes_of_rivets_element_with_or_without_a_prefix() {
        for xml in [
            r#"<data name="https://rivet-plc.dev/plcopen/1/step" handleUnknown="preserve"><step xmlns="https://rivet-plc.dev/plcopen/1" minTime="T#1s"/></data>"#,
            r#"<data name="https://rivet-plc.dev/plcopen/1/step" handleUnknown="preserve"><rivet:step minTime="T#1s"/></data>"#,
        ] {
            let add_data = AddData {
                entries: vec![AddDataEntry {
                    name: "https://rivet-plc.dev/plcopen/1/step".to_owned(),
                    handle_unknown: HandleUnknown::Preserve,
                    xml: xml.to_owned(),
                }],
            };
            let attributes = rivet_attributes(&add_data, "step");
            assert_eq!(
                attributes
                    .and_then(|map| map.get("minTime").cloned())
                    .as_deref(),
                Some("T#1s")
            );
            assert!(rivet_attributes(&add_data, "language").is_none());
        }
    }
}
