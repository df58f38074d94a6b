//! What is wrong with a retain file that cannot be restored; its text is the reason the
//! runtime gives for not restoring it.

use super::VERSION;

/// Why the content of a retain file is refused.
#[derive(Debug, thiserror::Error)]
pub(super) enum RetainFileError {
    /// Shorter than a header and checksum.
    #[error("it is truncated: {length_bytes} bytes")]
    Truncated {
        /// The file's length in bytes.
        length_bytes: usize,
    },
    /// Not starting with the retain file's magic.
    #[error("it does not start with \"RIVETRET\"")]
    BadMagic,
    /// Another format version.
    #[error("it has format version {found}, this runtime reads version {VERSION}")]
    WrongVersion {
        /// The version in the file.
        found: u16,
    },
    /// The SHA-256 at the end does not match.
    #[error("it is corrupted: its SHA-256 does not match its content")]
    Corrupted,
    /// The byte count in the header differs from the bytes that follow it.
    #[error("it announces {announced} bytes and holds {held}")]
    WrongLength {
        /// The byte count in the header.
        announced: u32,
        /// The bytes actually there.
        held: usize,
    },
}
