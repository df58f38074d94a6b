//! What can stop an export.

/// An export refused: something of the project cannot be written as XML.
#[derive(Debug, thiserror::Error)]
pub enum ExportError {
    /// A text holds a character XML 1.0 cannot carry (a control character other than tab, line
    /// feed and carriage return); `object` names where it stands.
    #[error("{object}: the text holds the character U+{code:04X}, which XML cannot carry")]
    UnwritableCharacter {
        /// The object and field, such as `POU 'Main', comment`.
        object: String,
        /// The character's code point.
        code: u32,
    },
    /// Rivet's own data of an object could not be written as TOML.
    #[error("{object}: its Rivet data cannot be written: {message}")]
    RivetData {
        /// The object, such as `cam 'CAM_Knife'`.
        object: String,
        /// What the TOML writer said.
        message: String,
    },
    /// Writing into memory failed (the writer's `io::Error`; not expected for a `Vec`).
    #[error("the XML writer failed: {0}")]
    Write(#[from] std::io::Error),
}
