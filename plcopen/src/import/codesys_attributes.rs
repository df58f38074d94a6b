//! CODESYS's attributes of a declaration (`addData/data[…/attributes]/Attributes/Attribute`).

use crate::add_data::AddData;

/// The value of the CODESYS attribute `name` in `add_data`, if the element has one.
///
/// The entry is XML the reader checked when it read the document, so a parse failure here only
/// means there is no attribute to find.
pub(super) fn codesys_attribute(add_data: &AddData, name: &str) -> Option<String> {
    let entry = add_data.entry_ending_with("/attributes")?;
    let tree = roxmltree::Document::parse(&entry.xml).ok()?;
    tree.descendants()
        .filter(|node| node.tag_name().name() == "Attribute")
        .find(|node| node.attribute("Name") == Some(name))
        .and_then(|node| node.attribute("Value"))
        .map(str::to_owned)
}

#[cfg(test)]
mod tests {
    use super::codesys_attribute;
    use crate::add_data::{AddData, AddDataEntry, HandleUnknown};

    #[test]
    fn attributes_are_found_by_name() {
        let add_data = AddData {
            entries: vec![AddDataEntry {
                name: "http://www.3s-software.com/plcopenxml/attributes".into(),
                handle_unknown: HandleUnknown::Implementation,
                xml: r#"<data name="http://www.3s-software.com/plcopenxml/attributes" handleUnknown="implementation"><Attributes><Attribute Name="variable_length_array" Value="ARRAY[*] OF LTIME" /></Attributes></data>"#.into(),
            }],
        };
        assert_eq!(
            codesys_attribute(&add_data, "variable_length_array").as_deref(),
            Some("ARRAY[*] OF LTIME")
        );
        assert_eq!(codesys_attribute(&add_data, "Dimensions"), None);
        assert_eq!(codesys_attribute(&AddData::default(), "x"), None);
    }
}
