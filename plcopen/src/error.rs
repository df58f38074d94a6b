//! The reader's error: where in which file, and what was wrong.

use std::fmt;

/// A document the reader refused, with the place of the fault.
///
/// `Display` gives `FILE:LINE:COLUMN: PATH: message` (`docs/plcopen-xml.md` §1.9); the path is left
/// out when the fault is not inside an element (the file is not XML, too large, not UTF-8).
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub struct ReadError {
    /// The file name given to the reader.
    pub file: String,
    /// Line of the fault (1-based).
    pub line: u32,
    /// Column of the fault (1-based, in characters).
    pub column: u32,
    /// The element path, such as
    /// `project/types/pous/pou[@name='Main']/body/FBD/block[@localId='7']`.
    pub path: String,
    /// What was wrong.
    pub kind: ReadErrorKind,
}

impl fmt::Display for ReadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.path.is_empty() {
            write!(
                f,
                "{}:{}:{}: {}",
                self.file, self.line, self.column, self.kind
            )
        } else {
            write!(
                f,
                "{}:{}:{}: {}: {}",
                self.file, self.line, self.column, self.path, self.kind
            )
        }
    }
}

/// The faults the reader finds.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum ReadErrorKind {
    /// The file is larger than the reader accepts.
    #[error("{}", too_large_message(*.size_bytes, *.limit_bytes))]
    TooLarge {
        /// The file's size; `None` when the file does not say it (a pipe, a device) and the
        /// reader stopped reading past the limit.
        size_bytes: Option<usize>,
        /// [`crate::MAX_FILE_BYTES`].
        limit_bytes: usize,
    },
    /// The bytes are not UTF-8 (nor UTF-16 with a byte order mark).
    #[error("the file is not UTF-8 text (an invalid byte sequence starts here)")]
    NotUtf8,
    /// UTF-16 text whose code units do not pair up.
    #[error("the file is not valid UTF-16 text")]
    NotUtf16,
    /// The file holds more XML nodes than the reader builds a tree of.
    #[error(
        "the file holds more than {limit} XML elements and texts, more than a PLCopen file of this size can have"
    )]
    TooManyNodes {
        /// The reader's limit.
        limit: u32,
    },
    /// Elements nest deeper than the reader follows.
    #[error("elements nest more than {limit} deep, deeper than a PLCopen file has")]
    TooDeep {
        /// The reader's limit.
        limit: usize,
    },
    /// The XML parser refused the text.
    #[error("not well-formed XML: {0}")]
    NotXml(String),
    /// The root element is not `project`.
    #[error("the root element is `{found}`, not the `project` of a PLCopen XML file")]
    WrongRoot {
        /// The root's local name.
        found: String,
    },
    /// The root's namespace is none of those accepted.
    #[error("{}", wrong_namespace_message(.found))]
    WrongNamespace {
        /// The root's namespace, empty when it has none.
        found: String,
    },
    /// A required child element is missing.
    #[error("the required element `{element}` is missing")]
    MissingElement {
        /// The missing element's local name.
        element: &'static str,
    },
    /// A required attribute is missing.
    #[error("the required attribute `{attribute}` is missing")]
    MissingAttribute {
        /// The attribute's name.
        attribute: &'static str,
    },
    /// An attribute's value has the wrong type.
    #[error("attribute `{attribute}` is `{value}`, not {expected}")]
    BadAttribute {
        /// The attribute's name.
        attribute: &'static str,
        /// The value as written.
        value: String,
        /// What the schema wants, in words (`an unsigned integer`, `true or false`).
        expected: &'static str,
    },
    /// An element the schema does not allow where it stands.
    #[error("unexpected element `{element}` in {context}")]
    UnexpectedElement {
        /// The element's local name.
        element: String,
        /// Where it stands, in words.
        context: &'static str,
    },
    /// Two objects of one body have the same `localId`.
    #[error("localId {local_id} is already used in this body by the element on line {first_line}")]
    DuplicateLocalId {
        /// The id.
        local_id: u64,
        /// Line of the first object with the id.
        first_line: u32,
    },
    /// A `connection` names no object of its body.
    #[error("connection refers to localId {ref_local_id}, which no element of this body has")]
    DanglingReference {
        /// The `refLocalId`.
        ref_local_id: u64,
    },
    /// Two POUs or data types have the same name (IEC names ignore case).
    #[error(
        "the {what} `{name}` has the name of the {first_what} on line {first_line}; IEC 61131-3 names ignore case"
    )]
    DuplicateName {
        /// `POU` or `data type`.
        what: &'static str,
        /// The name.
        name: String,
        /// What the first declaration is: `POU` or `data type`.
        first_what: &'static str,
        /// Line of the first declaration.
        first_line: u32,
    },
}

/// The message of [`ReadErrorKind::TooLarge`]: the size in bytes and MiB when it is known.
fn too_large_message(size_bytes: Option<usize>, limit_bytes: usize) -> String {
    const MIB: f64 = 1024.0 * 1024.0;
    let limit_mib = limit_bytes as f64 / MIB;
    match size_bytes {
        Some(size_bytes) => format!(
            "the file has {size_bytes} bytes ({:.1} MiB), more than the {limit_mib} MiB a PLCopen XML file may have",
            size_bytes as f64 / MIB
        ),
        None => format!("the file has more than the {limit_mib} MiB a PLCopen XML file may have"),
    }
}

/// The message of [`ReadErrorKind::WrongNamespace`], naming the namespaces accepted.
fn wrong_namespace_message(found: &str) -> String {
    use crate::document::Dialect;
    let accepted = format!(
        "{} (v2.01), {} (CODESYS) or {} (v1.0)",
        Dialect::V201.namespace(),
        Dialect::V200.namespace(),
        Dialect::V10.namespace()
    );
    if found.is_empty() {
        format!(
            "the root element `project` has no namespace; a PLCopen TC6 file declares {accepted}"
        )
    } else {
        format!(
            "namespace `{found}` is not a PLCopen TC6 namespace; a PLCopen TC6 file declares {accepted}"
        )
    }
}
