//! The checks across a body (unique `localId`s, links to existing objects) and across the
//! document (unique POU and data type names).

use std::collections::HashMap;

use super::context::{Context, Node, Read, elements};
use crate::body_object::BodyObject;
use crate::document::Document;
use crate::error::{ReadError, ReadErrorKind};

/// The elements that open a body of their own: connections inside them belong to that body.
const BODY_ELEMENTS: &[&str] = &["ST", "IL", "FBD", "LD", "SFC", "CFC"];

/// Checks that the objects of one body have distinct `localId`s and that every `connection` of
/// the body names one of them.
pub(super) fn check_body(
    context: &Context<'_, '_>,
    language: Node<'_, '_>,
    objects: &[BodyObject],
) -> Read<()> {
    let mut lines_by_id: HashMap<u64, u32> = HashMap::with_capacity(objects.len());
    for (object, element) in objects.iter().zip(elements(language)) {
        if let Some(first_line) = lines_by_id.insert(object.local_id, object.line) {
            return Err(context.attribute_error(
                element,
                "localId",
                ReadErrorKind::DuplicateLocalId {
                    local_id: object.local_id,
                    first_line,
                },
            ));
        }
    }
    for connection in language
        .descendants()
        .filter(|node| node.tag_name().name() == "connection")
        .filter(|node| belongs_to(*node, language))
    {
        let ref_local_id = context.required_u64(connection, "refLocalId")?;
        if !lines_by_id.contains_key(&ref_local_id) {
            return Err(context.attribute_error(
                connection,
                "refLocalId",
                ReadErrorKind::DanglingReference { ref_local_id },
            ));
        }
    }
    Ok(())
}

/// True when the nearest body element above `node` is `language` and no `addData` stands
/// between them (vendor data is not checked).
fn belongs_to(node: Node<'_, '_>, language: Node<'_, '_>) -> bool {
    for ancestor in node.ancestors().skip(1) {
        if ancestor == language {
            return true;
        }
        let name = ancestor.tag_name().name();
        if name == "addData" || BODY_ELEMENTS.contains(&name) {
            return false;
        }
    }
    false
}

/// Checks that no two POUs or data types share a name (IEC names ignore case; POUs and types
/// share one namespace).
pub(super) fn check_names(context: &Context<'_, '_>, document: &Document) -> Read<()> {
    let mut first_declarations: HashMap<String, (&'static str, u32)> = HashMap::new();
    let declarations = document
        .data_types
        .iter()
        .map(|data_type| ("data type", data_type.name.as_str(), data_type.line))
        .chain(
            document
                .pous
                .iter()
                .map(|pou| ("POU", pou.name.as_str(), pou.line)),
        );
    for (what, name, line) in declarations {
        if let Some(first) = first_declarations.insert(name.to_ascii_uppercase(), (what, line)) {
            return Err(duplicate_name(context, what, name, line, first));
        }
    }
    Ok(())
}

/// The error for the declaration of `name` on `line`, found by line since the document no longer
/// has its nodes; `first` is what the first declaration of the name is and its line.
fn duplicate_name(
    context: &Context<'_, '_>,
    what: &'static str,
    name: &str,
    line: u32,
    (first_what, first_line): (&'static str, u32),
) -> ReadError {
    let kind = ReadErrorKind::DuplicateName {
        what,
        name: name.to_owned(),
        first_what,
        first_line,
    };
    let element = if what == "POU" { "pou" } else { "dataType" };
    match context.find_element(element, name, line) {
        Some(node) => context.attribute_error(node, "name", kind),
        None => context.error(context.root(), kind),
    }
}
