//! The whole document.

use crate::add_data::AddData;
use crate::data_type::DataTypeDecl;
use crate::header::{ContentHeader, FileHeader};
use crate::instances::Configuration;
use crate::pou::Pou;
use crate::text::FormattedText;

/// A PLCopen TC6 XML document as read.
#[derive(Clone, Debug, PartialEq)]
pub struct Document {
    /// The file name given to the reader, for the conversion's messages.
    pub file_name: String,
    /// The schema version the file was written for, from the root's namespace.
    pub dialect: Dialect,
    /// `fileHeader`.
    pub file_header: FileHeader,
    /// `contentHeader`.
    pub content_header: ContentHeader,
    /// `types/dataTypes`, in document order.
    pub data_types: Vec<DataTypeDecl>,
    /// Every POU: those of `types/pous` first, in document order, then those CODESYS writes in a
    /// resource's `addData` (their [`Pou::location`] says which resource).
    pub pous: Vec<Pou>,
    /// `instances/configurations`.
    pub configurations: Vec<Configuration>,
    /// The project's own `addData`.
    pub add_data: AddData,
    /// The project's documentation.
    pub documentation: Option<FormattedText>,
    /// XML comments outside `addData` (those inside stay in the entries' raw text), with where
    /// they sit, so `<!--ObjectVersion: LD1-->` survives a round trip.
    pub xml_comments: Vec<XmlComment>,
}

/// The schema version of a document, told by the root element's namespace.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dialect {
    /// `http://www.plcopen.org/xml/tc6_0201` (Beremiz, OpenPLC).
    V201,
    /// `http://www.plcopen.org/xml/tc6_0200` (CODESYS V3.5).
    V200,
    /// `http://www.plcopen.org/xml/tc6.xsd` (v1.0; matiec), upgraded while reading.
    V10,
}

impl Dialect {
    /// The namespace URI of the root element.
    pub fn namespace(self) -> &'static str {
        match self {
            Dialect::V201 => "http://www.plcopen.org/xml/tc6_0201",
            Dialect::V200 => "http://www.plcopen.org/xml/tc6_0200",
            Dialect::V10 => "http://www.plcopen.org/xml/tc6.xsd",
        }
    }
}

/// An XML comment (`<!-- … -->`) and the place it stands.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct XmlComment {
    /// The comment's text, without `<!--` and `-->`.
    pub text: String,
    /// The element path of the element it stands in (the format of error messages).
    pub parent_path: String,
    /// How many element children of that parent come before it.
    pub elements_before: usize,
    /// Line of the comment in the file (1-based).
    pub line: u32,
}
