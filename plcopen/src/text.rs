//! Formatted text (`formattedText`: ST and IL bodies, documentation, comments).

/// The text of a `formattedText` element and the markup it was written in.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct FormattedText {
    /// The concatenated text of every descendant, entities and CDATA resolved. Indentation between
    /// the element and its first child element (`<ST>\n  <xhtml:p>`) is formatting, not text, and
    /// is left out.
    pub text: String,
    /// How the text was wrapped, so an export can write the same dialect.
    pub markup: TextMarkup,
    /// True when the text stood in a CDATA section (Beremiz) rather than escaped (CODESYS).
    pub cdata: bool,
}

/// The wrapper around a formatted text.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum TextMarkup {
    /// The text stands directly in the element (PLCopen v1.0, matiec).
    #[default]
    Bare,
    /// The text is inside `xhtml:p` (Beremiz, OpenPLC).
    XhtmlParagraph,
    /// The text is inside an `xhtml` element in the XHTML namespace (CODESYS).
    XhtmlElement,
}
