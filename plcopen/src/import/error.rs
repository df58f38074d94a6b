//! The conversion's error: what could not become part of a Rivet project, and where it stands.

use std::fmt;

/// A document the conversion refused, with the place of the element at fault.
///
/// `Display` gives `FILE:LINE:COLUMN: PATH: message`, the format of [`crate::ReadError`].
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub struct ImportError {
    /// The file name the document was read from.
    pub file: String,
    /// Line of the element (1-based).
    pub line: u32,
    /// Column of the element (1-based, in characters).
    pub column: u32,
    /// The element path, such as `project/types/pous/pou[@name='Main']`.
    pub path: String,
    /// What could not be converted (boxed, so results that carry the error stay small).
    pub kind: Box<ImportErrorKind>,
}

impl fmt::Display for ImportError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}:{}:{}: {}: {}",
            self.file, self.line, self.column, self.path, self.kind
        )
    }
}

/// The faults the conversion finds.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum ImportErrorKind {
    /// Two objects of the application, or two tasks, have names equal without regard to case.
    #[error(
        "the {what} `{name}` has the name of `{first}` (line {first_line}); IEC 61131-3 names ignore case"
    )]
    DuplicateName {
        /// What the second one is (`POU`, `data type`, `global variable list`, `task`).
        what: &'static str,
        /// Its name.
        name: String,
        /// The name of the first one, as written.
        first: String,
        /// Line of the first one.
        first_line: u32,
    },
    /// A type Rivet cannot write where it stands (a structure declared inside a variable).
    #[error("{0}")]
    InexpressibleType(String),
    /// A task interval that is not a duration Rivet can run.
    #[error(
        "the interval `{0}` is not a duration (`T#100ms`, `T#1s500ms` or `PT0.2S`) of 1 µs to 71 minutes"
    )]
    BadInterval(String),
    /// A name that is not an IEC identifier, which Rivet needs for an object or task.
    #[error("`{0}` is not an IEC 61131-3 identifier")]
    BadName(String),
    /// Rivet's own `addData` entry (`docs/plcopen-xml.md` §5.4) that cannot be read back.
    #[error("Rivet's data cannot be read: {0}")]
    RivetData(crate::rivet_data::RivetDataError),
    /// An LD or FBD body Rivet cannot turn into networks (`docs/plcopen-xml.md` §3.6).
    #[error("{0}")]
    Network(#[from] super::network_error::NetworkError),
    /// An SFC body that Rivet's structured chart cannot hold, or that is incomplete (no initial
    /// step, a transition leading nowhere); the message names the element.
    #[error("{0}")]
    BadSfc(String),
    /// A CFC or FBD graph that cannot become a chart (a wire from an object that is not in the
    /// body, two wires into one pin); the message names the element.
    #[error("{0}")]
    BadCfc(String),
}
