//! A thin layer over quick-xml's writer: elements with attributes, escaped text and CDATA, with
//! every text checked for characters XML cannot carry.

use std::borrow::Cow;

use quick_xml::Writer;
use quick_xml::events::{BytesCData, BytesDecl, BytesEnd, BytesStart, BytesText, Event};

use super::error::ExportError;

/// The document being written: UTF-8, two-space indent, one element a line except text.
pub(super) struct XmlWriter {
    /// quick-xml's writer into memory.
    writer: Writer<Vec<u8>>,
    /// What the texts written belong to, for the error of a character XML cannot carry.
    pub context: String,
}

impl XmlWriter {
    /// A writer that has written the XML declaration.
    pub fn new() -> Result<Self, ExportError> {
        let mut writer = Writer::new_with_indent(Vec::new(), b' ', 2);
        writer.write_event(Event::Decl(BytesDecl::new("1.0", Some("utf-8"), None)))?;
        Ok(Self {
            writer,
            context: String::new(),
        })
    }

    /// The bytes written, ending with a line feed.
    pub fn finish(self) -> Vec<u8> {
        let mut bytes = self.writer.into_inner();
        bytes.push(b'\n');
        bytes
    }

    /// Opens `name` with `attributes` (values escaped here).
    pub fn start(&mut self, name: &str, attributes: &[(&str, &str)]) -> Result<(), ExportError> {
        let element = self.element(name, attributes)?;
        self.writer.write_event(Event::Start(element))?;
        Ok(())
    }

    /// Closes `name`.
    pub fn end(&mut self, name: &str) -> Result<(), ExportError> {
        self.writer.write_event(Event::End(BytesEnd::new(name)))?;
        Ok(())
    }

    /// Writes `<name …/>`.
    pub fn empty(&mut self, name: &str, attributes: &[(&str, &str)]) -> Result<(), ExportError> {
        let element = self.element(name, attributes)?;
        self.writer.write_event(Event::Empty(element))?;
        Ok(())
    }

    /// Writes `<name …>text</name>` with the text escaped.
    pub fn text_element(
        &mut self,
        name: &str,
        attributes: &[(&str, &str)],
        text: &str,
    ) -> Result<(), ExportError> {
        self.start(name, attributes)?;
        self.text(text)?;
        self.end(name)
    }

    /// Writes escaped text; a carriage return is written as a character reference, since a
    /// reader would turn a literal one into a line feed.
    pub fn text(&mut self, text: &str) -> Result<(), ExportError> {
        self.check(text)?;
        let escaped = escape(text, false);
        self.writer
            .write_event(Event::Text(BytesText::from_escaped(escaped)))?;
        Ok(())
    }

    /// Writes text as CDATA (as Beremiz writes ST), split where it holds `]]>`; a text holding
    /// a carriage return is escaped instead, since CDATA cannot keep one.
    pub fn cdata(&mut self, text: &str) -> Result<(), ExportError> {
        self.check(text)?;
        if text.contains('\r') {
            return self.text(text);
        }
        let mut rest = text;
        while let Some(at) = rest.find("]]>") {
            // `]]` closes one section and `>` opens the next, so no section holds `]]>`.
            self.writer
                .write_event(Event::CData(BytesCData::new(&rest[..at + 2])))?;
            rest = &rest[at + 2..];
        }
        self.writer
            .write_event(Event::CData(BytesCData::new(rest)))?;
        Ok(())
    }

    /// Writes a fragment of XML kept from an imported file as it was, on a line of its own.
    pub fn raw(&mut self, xml: &str) -> Result<(), ExportError> {
        self.writer.write_indent()?;
        self.writer.get_mut().extend_from_slice(xml.as_bytes());
        Ok(())
    }

    fn element<'a>(
        &self,
        name: &'a str,
        attributes: &[(&str, &str)],
    ) -> Result<BytesStart<'a>, ExportError> {
        let mut element = BytesStart::new(name);
        for (key, value) in attributes {
            self.check(value)?;
            let escaped = escape(value, true);
            element.push_attribute((key.as_bytes(), escaped.as_bytes()));
        }
        Ok(element)
    }

    fn check(&self, text: &str) -> Result<(), ExportError> {
        match text.chars().find(|&c| !is_xml_char(c)) {
            Some(bad) => Err(ExportError::UnwritableCharacter {
                object: self.context.clone(),
                code: u32::from(bad),
            }),
            None => Ok(()),
        }
    }
}

/// True for the characters XML 1.0 allows in a document.
fn is_xml_char(c: char) -> bool {
    matches!(c, '\t' | '\n' | '\r' | '\u{20}'..='\u{D7FF}' | '\u{E000}'..='\u{FFFD}' | '\u{10000}'..)
}

/// `text` with the markup characters escaped; in an attribute also the white space a reader
/// would turn into spaces.
pub(super) fn escape(text: &str, attribute: bool) -> Cow<'_, str> {
    let needs = |c: char| {
        matches!(c, '<' | '>' | '&' | '\r') || (attribute && matches!(c, '"' | '\n' | '\t'))
    };
    if !text.chars().any(needs) {
        return Cow::Borrowed(text);
    }
    let mut escaped = String::with_capacity(text.len() + 8);
    for c in text.chars() {
        match c {
            '<' => escaped.push_str("&lt;"),
            '>' => escaped.push_str("&gt;"),
            '&' => escaped.push_str("&amp;"),
            '\r' => escaped.push_str("&#13;"),
            '"' if attribute => escaped.push_str("&quot;"),
            '\n' if attribute => escaped.push_str("&#10;"),
            '\t' if attribute => escaped.push_str("&#9;"),
            other => escaped.push(other),
        }
    }
    Cow::Owned(escaped)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn written(write: impl FnOnce(&mut XmlWriter) -> Result<(), ExportError>) -> String {
        let mut writer = XmlWriter::new().unwrap();
        write(&mut writer).unwrap();
        String::from_utf8(writer.finish()).unwrap()
    }

    #[test]
    fn attributes_keep_quotes_line_feeds_and_tabs() {
        let xml = written(|w| w.empty("a", &[("v", "x\"<\n\t&")]));
        assert!(
            xml.ends_with("<a v=\"x&quot;&lt;&#10;&#9;&amp;\"/>\n"),
            "{xml}"
        );
    }

    #[test]
    fn cdata_is_split_where_the_text_holds_its_end() {
        let xml = written(|w| {
            w.start("p", &[])?;
            w.cdata("a]]>b")?;
            w.end("p")
        });
        assert!(
            xml.contains("<p><![CDATA[a]]]]><![CDATA[>b]]></p>"),
            "{xml}"
        );
        let document = roxmltree::Document::parse(&xml).unwrap();
        assert_eq!(document.root_element().text(), Some("a]]>b"));
    }

    #[test]
    fn a_carriage_return_survives_a_reader() {
        let xml = written(|w| {
            w.start("p", &[])?;
            w.cdata("a\r\nb")?;
            w.end("p")
        });
        let document = roxmltree::Document::parse(&xml).unwrap();
        assert_eq!(document.root_element().text(), Some("a\r\nb"));
    }

    #[test]
    fn a_control_character_is_refused_naming_the_object() {
        let mut writer = XmlWriter::new().unwrap();
        writer.context = "POU 'Main', comment".into();
        let error = writer.text("a\u{1}").unwrap_err();
        assert_eq!(
            error.to_string(),
            "POU 'Main', comment: the text holds the character U+0001, which XML cannot carry"
        );
    }
}
