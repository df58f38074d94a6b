//! What every part of the reading needs: positions, element paths, attributes, children, text.

use crate::add_data::{AddData, AddDataEntry, HandleUnknown};
use crate::document::Dialect;
use crate::error::{ReadError, ReadErrorKind};
use crate::header::Point;
use crate::text::{FormattedText, TextMarkup};

/// An element or other node of the DOM.
pub(super) type Node<'a, 'input> = roxmltree::Node<'a, 'input>;

/// The reader's result.
pub(super) type Read<T> = Result<T, ReadError>;

/// The document being read and the file it came from.
pub(super) struct Context<'a, 'input> {
    dom: &'a roxmltree::Document<'input>,
    text: &'input str,
    /// The file name given to the reader.
    pub file_name: &'a str,
    /// Byte offset of the start of every line: roxmltree's `text_pos_at` scans from the start of
    /// the text, which made reading a 10 MB file quadratic.
    line_starts: Vec<usize>,
    /// The number of characters before every [`CHARACTER_CHECKPOINT_BYTES`]th byte: a column
    /// counted from the start of its line made a file written on one line quadratic (4 s for
    /// 4.8 MB), so a column is the difference of two character indices found from here.
    characters_before_checkpoint: Vec<usize>,
    /// The schema version, for the v1.0 upgrade rules.
    pub dialect: Dialect,
}

impl<'a, 'input> Context<'a, 'input> {
    /// A context for one document.
    pub fn new(
        dom: &'a roxmltree::Document<'input>,
        text: &'input str,
        file_name: &'a str,
        dialect: Dialect,
    ) -> Self {
        let line_starts = std::iter::once(0)
            .chain(
                text.bytes()
                    .enumerate()
                    .filter(|(_, byte)| *byte == b'\n')
                    .map(|(offset, _)| offset + 1),
            )
            .collect();
        let characters_before_checkpoint = std::iter::once(0)
            .chain(text.as_bytes().chunks(CHARACTER_CHECKPOINT_BYTES).scan(
                0,
                |characters, chunk| {
                    *characters += character_starts(chunk);
                    Some(*characters)
                },
            ))
            .collect();
        Context {
            dom,
            text,
            file_name,
            line_starts,
            characters_before_checkpoint,
            dialect,
        }
    }

    /// Line and column (1-based, the column in characters) of a byte offset. Takes time
    /// bounded by twice [`CHARACTER_CHECKPOINT_BYTES`] and the logarithm of the number of
    /// lines, however long the line is.
    fn position(&self, offset: usize) -> (u32, u32) {
        let offset = offset.min(self.text.len());
        let line_index = self
            .line_starts
            .partition_point(|start| *start <= offset)
            .saturating_sub(1);
        let line_start = self.line_starts.get(line_index).copied().unwrap_or(0);
        // Most lines are short: counting their characters is cheaper than two lookups.
        let column = if offset.saturating_sub(line_start) <= CHARACTER_CHECKPOINT_BYTES {
            self.text
                .as_bytes()
                .get(line_start..offset)
                .map_or(0, character_starts)
        } else {
            self.character_index(offset) - self.character_index(line_start)
        };
        (
            u32::try_from(line_index + 1).unwrap_or(u32::MAX),
            u32::try_from(column + 1).unwrap_or(u32::MAX),
        )
    }

    /// The number of characters before byte `offset` (at most the text's length), counted from
    /// the checkpoint before it.
    fn character_index(&self, offset: usize) -> usize {
        let checkpoint = offset / CHARACTER_CHECKPOINT_BYTES;
        let checkpoint_offset = checkpoint * CHARACTER_CHECKPOINT_BYTES;
        let before_checkpoint = self
            .characters_before_checkpoint
            .get(checkpoint)
            .copied()
            .unwrap_or(0);
        let since_checkpoint = self
            .text
            .as_bytes()
            .get(checkpoint_offset..offset)
            .map_or(0, character_starts);
        before_checkpoint + since_checkpoint
    }

    /// An error at byte `offset`, inside `node`.
    pub fn error_at(&self, offset: usize, node: Node<'_, '_>, kind: ReadErrorKind) -> ReadError {
        let (line, column) = self.position(offset);
        ReadError {
            file: self.file_name.to_owned(),
            line,
            column,
            path: element_path(node),
            kind,
        }
    }

    /// An error at the start of `node`.
    pub fn error(&self, node: Node<'_, '_>, kind: ReadErrorKind) -> ReadError {
        self.error_at(node.range().start, node, kind)
    }

    /// An error at the attribute `name` of `node` (at the element when it has no such attribute).
    pub fn attribute_error(
        &self,
        node: Node<'_, '_>,
        name: &str,
        kind: ReadErrorKind,
    ) -> ReadError {
        let offset = node
            .attributes()
            .find(|attribute| attribute.name() == name)
            .map_or(node.range().start, |attribute| attribute.range().start);
        self.error_at(offset, node, kind)
    }

    /// The root element.
    pub fn root(&self) -> Node<'a, 'input> {
        self.dom.root_element()
    }

    /// The element `element` named `name` on `line`.
    pub fn find_element(&self, element: &str, name: &str, line: u32) -> Option<Node<'a, 'input>> {
        self.dom.descendants().find(|node| {
            node.tag_name().name() == element
                && node.attribute("name") == Some(name)
                && self.line(*node) == line
        })
    }

    /// Line (1-based) of a node.
    pub fn line(&self, node: Node<'_, '_>) -> u32 {
        self.position(node.range().start).0
    }

    /// Line and column (1-based) of a node.
    pub fn line_column(&self, node: Node<'_, '_>) -> (u32, u32) {
        self.position(node.range().start)
    }

    /// The source text of a node, as written.
    pub fn source(&self, node: Node<'_, '_>) -> &'input str {
        self.text.get(node.range()).unwrap_or("")
    }

    /// A required attribute.
    pub fn required<'n>(&self, node: Node<'n, '_>, name: &'static str) -> Read<&'n str> {
        node.attribute(name)
            .ok_or_else(|| self.error(node, ReadErrorKind::MissingAttribute { attribute: name }))
    }

    /// An optional attribute, owned.
    pub fn optional(&self, node: Node<'_, '_>, name: &str) -> Option<String> {
        node.attribute(name).map(str::to_owned)
    }

    /// An optional attribute of a type `parse` reads; `expected` says the type in words.
    pub fn optional_parsed<T>(
        &self,
        node: Node<'_, '_>,
        name: &'static str,
        expected: &'static str,
        parse: impl Fn(&str) -> Option<T>,
    ) -> Read<Option<T>> {
        match node.attribute(name) {
            None => Ok(None),
            Some(value) => parse(value.trim()).map(Some).ok_or_else(|| {
                self.attribute_error(
                    node,
                    name,
                    ReadErrorKind::BadAttribute {
                        attribute: name,
                        value: value.to_owned(),
                        expected,
                    },
                )
            }),
        }
    }

    /// A required attribute of a type `parse` reads.
    pub fn required_parsed<T>(
        &self,
        node: Node<'_, '_>,
        name: &'static str,
        expected: &'static str,
        parse: impl Fn(&str) -> Option<T>,
    ) -> Read<T> {
        self.required(node, name)?;
        self.optional_parsed(node, name, expected, parse)?
            .ok_or_else(|| self.error(node, ReadErrorKind::MissingAttribute { attribute: name }))
    }

    /// An optional `xsd:boolean` attribute.
    pub fn optional_bool(&self, node: Node<'_, '_>, name: &'static str) -> Read<Option<bool>> {
        self.optional_parsed(node, name, "true or false", |value| match value {
            "true" | "1" => Some(true),
            "false" | "0" => Some(false),
            _ => None,
        })
    }

    /// An optional `xsd:unsignedLong` attribute.
    pub fn optional_u64(&self, node: Node<'_, '_>, name: &'static str) -> Read<Option<u64>> {
        self.optional_parsed(node, name, "an unsigned integer", |value| {
            value.parse().ok()
        })
    }

    /// A required `xsd:unsignedLong` attribute.
    pub fn required_u64(&self, node: Node<'_, '_>, name: &'static str) -> Read<u64> {
        self.required_parsed(node, name, "an unsigned integer", |value| {
            value.parse().ok()
        })
    }

    /// An optional `xsd:decimal` attribute.
    pub fn optional_decimal(&self, node: Node<'_, '_>, name: &'static str) -> Read<Option<f64>> {
        self.optional_parsed(node, name, "a decimal number", parse_decimal)
    }

    /// A point from the `x` and `y` attributes of `node`.
    pub fn point(&self, node: Node<'_, '_>) -> Read<Point> {
        Ok(Point {
            x: self.required_parsed(node, "x", "a decimal number", parse_decimal)?,
            y: self.required_parsed(node, "y", "a decimal number", parse_decimal)?,
        })
    }

    /// The point of the child element `name`, when there is one.
    pub fn child_point(&self, node: Node<'_, '_>, name: &str) -> Read<Option<Point>> {
        child(node, name).map(|point| self.point(point)).transpose()
    }

    /// A required child element.
    pub fn required_child<'n>(
        &self,
        node: Node<'n, 'input>,
        name: &'static str,
    ) -> Read<Node<'n, 'input>> {
        child(node, name)
            .ok_or_else(|| self.error(node, ReadErrorKind::MissingElement { element: name }))
    }

    /// The `addData` child of `node`, its entries kept as raw XML.
    pub fn add_data(&self, node: Node<'_, '_>) -> Read<AddData> {
        let Some(add_data) = child(node, "addData") else {
            return Ok(AddData::default());
        };
        let mut entries = Vec::new();
        for data in elements(add_data) {
            if data.tag_name().name() != "data" {
                return Err(self.error(
                    data,
                    ReadErrorKind::UnexpectedElement {
                        element: data.tag_name().name().to_owned(),
                        context: "addData, which holds only data elements",
                    },
                ));
            }
            let handle_unknown = self.required_parsed(
                data,
                "handleUnknown",
                "preserve, discard or implementation",
                HandleUnknown::parse,
            )?;
            entries.push(AddDataEntry {
                name: self.required(data, "name")?.to_owned(),
                handle_unknown,
                xml: self.source(data).to_owned(),
            });
        }
        Ok(AddData { entries })
    }

    /// The `documentation` child of `node`, when there is one.
    pub fn documentation(&self, node: Node<'_, '_>) -> Option<FormattedText> {
        child(node, "documentation").map(|documentation| self.formatted_text(documentation))
    }

    /// The text of a `formattedText` element (`docs/plcopen-xml.md` §1.4).
    pub fn formatted_text(&self, node: Node<'_, '_>) -> FormattedText {
        let first_element = elements(node).next();
        let markup = match first_element {
            None => TextMarkup::Bare,
            Some(element) if element.tag_name().name() == "p" => TextMarkup::XhtmlParagraph,
            Some(_) => TextMarkup::XhtmlElement,
        };
        let mut text = String::new();
        let mut cdata = false;
        for descendant in node.descendants().filter(|descendant| descendant.is_text()) {
            let content = descendant.text().unwrap_or("");
            let formatting = first_element.is_some()
                && descendant.parent() == Some(node)
                && content.trim().is_empty();
            if formatting {
                continue;
            }
            cdata |= self.source(descendant).contains("<![CDATA[");
            text.push_str(content);
        }
        FormattedText {
            text,
            markup,
            cdata,
        }
    }

    /// The text of a simple element such as `expression` or `variable`, as written.
    pub fn simple_text(&self, node: Node<'_, '_>) -> String {
        node.descendants()
            .filter(|descendant| descendant.is_text())
            .filter_map(|descendant| descendant.text())
            .collect()
    }

    /// Refuses a child element of `node` that is not in `allowed` (nor `addData` or
    /// `documentation`, which every element may have), so nothing is dropped unseen.
    pub fn only_children(
        &self,
        node: Node<'_, '_>,
        allowed: &[&str],
        context: &'static str,
    ) -> Read<()> {
        match elements(node).find(|element| {
            let name = element.tag_name().name();
            name != "addData" && name != "documentation" && !allowed.contains(&name)
        }) {
            Some(element) => Err(self.unexpected(element, context)),
            None => Ok(()),
        }
    }

    /// An error for an element that does not belong where it stands.
    pub fn unexpected(&self, node: Node<'_, '_>, context: &'static str) -> ReadError {
        self.error(
            node,
            ReadErrorKind::UnexpectedElement {
                element: node.tag_name().name().to_owned(),
                context,
            },
        )
    }
}

/// The distance in bytes between two checkpoints of [`Context`]'s character index: a position
/// counts the characters of at most this many bytes, and the index takes 8 bytes per this many
/// bytes of text (128 KiB for a 32 MiB file).
const CHARACTER_CHECKPOINT_BYTES: usize = 2048;

/// The number of characters that start in `bytes` of UTF-8 text: every byte but the
/// continuation bytes (`10xxxxxx`), so a slice may begin or end inside a character.
fn character_starts(bytes: &[u8]) -> usize {
    bytes
        .iter()
        .filter(|byte| (**byte & 0b1100_0000) != 0b1000_0000)
        .count()
}

/// The element children of a node.
pub(super) fn elements<'a, 'input>(
    node: Node<'a, 'input>,
) -> impl Iterator<Item = Node<'a, 'input>> {
    node.children().filter(Node::is_element)
}

/// The first element child with the local name `name`.
pub(super) fn child<'a, 'input>(node: Node<'a, 'input>, name: &str) -> Option<Node<'a, 'input>> {
    elements(node).find(|element| element.tag_name().name() == name)
}

/// The element children with the local name `name`.
pub(super) fn children_named<'a, 'input>(
    node: Node<'a, 'input>,
    name: &'a str,
) -> impl Iterator<Item = Node<'a, 'input>> {
    elements(node).filter(move |element| element.tag_name().name() == name)
}

/// The path of an element from the root, each step its local name with `name`, `localId` or
/// `formalParameter` (pins) as a predicate: `project/types/pous/pou[@name='Main']/body/FBD/block[@localId='7']`.
pub(super) fn element_path(node: Node<'_, '_>) -> String {
    let mut steps: Vec<String> = node
        .ancestors()
        .filter(Node::is_element)
        .map(|element| {
            let name = element.tag_name().name();
            if let Some(value) = element.attribute("name") {
                format!("{name}[@name='{value}']")
            } else if let Some(value) = element.attribute("localId") {
                format!("{name}[@localId='{value}']")
            } else if let Some(value) = element.attribute("formalParameter") {
                format!("{name}[@formalParameter='{value}']")
            } else {
                name.to_owned()
            }
        })
        .collect();
    steps.reverse();
    steps.join("/")
}

/// An `xsd:decimal` (also accepting exponents, which some exporters write).
fn parse_decimal(text: &str) -> Option<f64> {
    text.parse::<f64>().ok().filter(|value| value.is_finite())
}

#[cfg(test)]
mod tests {
    use super::{CHARACTER_CHECKPOINT_BYTES, Context};
    use crate::document::Dialect;

    /// Checks the position of every character of `text` (and of its end) against one counted
    /// character by character from the start.
    #[track_caller]
    fn check_every_offset(text: &str) {
        let dom = roxmltree::Document::parse(text).unwrap_or_else(|error| panic!("{error}"));
        let context = Context::new(&dom, text, "t.xml", Dialect::V201);
        let (mut line, mut column) = (1, 1);
        for (offset, character) in text.char_indices() {
            assert_eq!(context.position(offset), (line, column), "at byte {offset}");
            if character == '\n' {
                (line, column) = (line + 1, 1);
            } else {
                column += 1;
            }
        }
        assert_eq!(context.position(text.len()), (line, column), "at the end");
    }

    #[test]
    fn positions_on_a_long_line_of_several_byte_characters_count_characters() {
        // Two- to four-byte characters straddle every checkpoint of the index.
        let long_line = "aé中😀".repeat(CHARACTER_CHECKPOINT_BYTES / 2);
        check_every_offset(&format!(
            "<r>\n<a b=\"{long_line}\"/>{long_line}\n\n<c/>{long_line}</r>"
        ));
    }

    #[test]
    fn positions_of_short_lines_count_from_the_line_start() {
        check_every_offset("<r>\r\n  <a/>\n\t<b>é</b>\n</r>\n");
    }
}
