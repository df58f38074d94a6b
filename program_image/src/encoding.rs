//! The container of `docs/program-image.md` §2: header, sections, SHA-256 trailer.

use serde::Serialize;
use serde::de::DeserializeOwned;
use sha2::{Digest, Sha256};

use crate::ProgramImage;

/// The first eight bytes of every image.
pub const MAGIC: &[u8; 8] = b"RIVETIMG";

/// The format version this crate writes and reads.
pub const FORMAT_VERSION: u16 = 1;

/// The largest image accepted. Decoded, an image takes several times its encoded size (every
/// one-byte `Return` becomes an instruction of tens of bytes, then an engine closure), so the
/// limit keeps a hostile image from costing gigabytes; real images are far smaller (a
/// 50,000-line project compiles to a few megabytes).
pub const MAX_IMAGE_BYTES: usize = 16 * 1024 * 1024;

/// The SHA-256 of an image's bytes before the trailer: its identity.
pub type ImageHash = [u8; 32];

/// Why bytes are not a program image.
#[derive(Debug, thiserror::Error, PartialEq, Eq)]
pub enum ImageError {
    /// Fewer bytes than a header and trailer.
    #[error("the image is truncated: {0} bytes is shorter than any image")]
    TooShort(usize),
    /// Larger than [`MAX_IMAGE_BYTES`].
    #[error("the image is {0} bytes, more than the {MAX_IMAGE_BYTES} accepted")]
    TooLarge(usize),
    /// Not starting with [`MAGIC`].
    #[error("not a Rivet program image (the first bytes are not \"RIVETIMG\")")]
    BadMagic,
    /// Another format version.
    #[error(
        "the image has format version {found}, this runtime reads version {FORMAT_VERSION}; rebuild the project with a matching Rivet"
    )]
    WrongVersion {
        /// The version in the image.
        found: u16,
    },
    /// Header flags this version does not know.
    #[error("the image header has unknown flags {0:#06x}")]
    UnknownFlags(u16),
    /// The trailer does not match the content.
    #[error("the image is corrupted: its SHA-256 does not match its content")]
    HashMismatch,
    /// A section's length runs past the end.
    #[error("section {id} is truncated: it says {length} bytes, {available} remain")]
    SectionTruncated {
        /// The section id.
        id: u16,
        /// The length it announces.
        length: u32,
        /// The bytes left.
        available: usize,
    },
    /// Sections out of order or repeated.
    #[error("section {id} is out of order or appears twice")]
    SectionOrder {
        /// The section id.
        id: u16,
    },
    /// A critical section this version does not know.
    #[error("the image needs section {id}, which this runtime does not know")]
    UnknownCriticalSection {
        /// The section id.
        id: u16,
    },
    /// A required section is absent.
    #[error("the image has no '{0}' section")]
    MissingSection(&'static str),
    /// A section's payload does not decode.
    #[error("section '{section}' is malformed: {message}")]
    Malformed {
        /// The section name.
        section: &'static str,
        /// What the decoder said.
        message: String,
    },
    /// Bytes after the sections and before the trailer.
    #[error("{0} unexpected bytes after the last section")]
    TrailingBytes(usize),
    /// The decoded image is inconsistent (a reference out of range, code that would misbehave).
    #[error("the image is inconsistent: {0}")]
    Invalid(String),
    /// The Modbus master section is inconsistent (`docs/modbus-master.md` §5.2).
    #[error("the image is inconsistent: {0}")]
    ModbusMaster(#[from] crate::modbus_master::MasterSectionError),
}

/// Section ids (§3), in the order they appear.
const SECTIONS: [(u16, &str, bool); 14] = [
    (1, "types", true),
    (2, "layout", true),
    (3, "initial", true),
    (4, "symbols", true),
    (5, "code", true),
    (6, "constants", true),
    (7, "tasks", true),
    (8, "retain", true),
    (9, "sources", false),
    (10, "info", false),
    // Critical: a reader that skipped it would serve the wrong addresses.
    (11, "modbus_map", true),
    // Critical: without it the motion function blocks would run without their axes.
    (12, "motion", true),
    // Not critical: only the debugger reads it (`docs/protocol.md` §6).
    (13, "debug", false),
    // Critical: running the program without its remote I/O would look like a working machine
    // that does nothing.
    (14, "modbus_master", true),
];

const HEADER_BYTES: usize = 16;
const SECTION_HEADER_BYTES: usize = 8;
const CRITICAL: u16 = 1;

fn payload<T: Serialize>(value: &T) -> Vec<u8> {
    // Serialising plain data to a vector cannot fail; an empty payload would be refused when
    // read, so a failure here could never produce an image that runs.
    postcard::to_allocvec(value).unwrap_or_default()
}

impl ProgramImage {
    /// The image as bytes: header, sections, trailer.
    pub fn encode(&self) -> Vec<u8> {
        let sections: [Vec<u8>; 14] = [
            payload(&self.types),
            payload(&self.layout),
            payload(&self.initial),
            payload(&self.symbols),
            payload(&self.pous),
            payload(&self.constants),
            payload(&self.tasks),
            payload(&self.retain),
            payload(&self.sources),
            payload(&self.info),
            self.modbus_map.as_ref().map(payload).unwrap_or_default(),
            self.motion.as_ref().map(payload).unwrap_or_default(),
            self.debug.as_ref().map(payload).unwrap_or_default(),
            self.modbus_master.as_ref().map(payload).unwrap_or_default(),
        ];
        let mut bytes = Vec::new();
        bytes.extend_from_slice(MAGIC);
        bytes.extend_from_slice(&FORMAT_VERSION.to_le_bytes());
        bytes.extend_from_slice(&0u16.to_le_bytes());
        // The Modbus map section is written only when the project has its own map, the motion
        // section only when it has axes or cams, the debug section only when the compiler wrote it,
        // the Modbus master section only when the project has a runtime device.
        let present = |id: u16| match id {
            11 => self.modbus_map.is_some(),
            12 => self.motion.is_some(),
            13 => self.debug.is_some(),
            14 => self.modbus_master.is_some(),
            _ => true,
        };
        let count = SECTIONS.iter().filter(|(id, _, _)| present(*id)).count();
        bytes.extend_from_slice(&(count as u32).to_le_bytes());
        for ((id, _, critical), body) in SECTIONS.iter().zip(&sections) {
            if !present(*id) {
                continue;
            }
            bytes.extend_from_slice(&id.to_le_bytes());
            bytes.extend_from_slice(&(if *critical { CRITICAL } else { 0 }).to_le_bytes());
            bytes.extend_from_slice(&(body.len() as u32).to_le_bytes());
            bytes.extend_from_slice(body);
        }
        let hash = Sha256::digest(&bytes);
        bytes.extend_from_slice(&hash);
        bytes
    }

    /// Reads an image, checking the container, every section and the consistency of the whole
    /// ([`ProgramImage::verify`]).
    pub fn decode(bytes: &[u8]) -> Result<Self, ImageError> {
        if bytes.len() > MAX_IMAGE_BYTES {
            return Err(ImageError::TooLarge(bytes.len()));
        }
        if bytes.len() < HEADER_BYTES + 32 {
            return Err(ImageError::TooShort(bytes.len()));
        }
        if &bytes[..8] != MAGIC {
            return Err(ImageError::BadMagic);
        }
        let version = u16::from_le_bytes([bytes[8], bytes[9]]);
        if version != FORMAT_VERSION {
            return Err(ImageError::WrongVersion { found: version });
        }
        let flags = u16::from_le_bytes([bytes[10], bytes[11]]);
        if flags != 0 {
            return Err(ImageError::UnknownFlags(flags));
        }
        let (content, trailer) = bytes.split_at(bytes.len() - 32);
        if Sha256::digest(content).as_slice() != trailer {
            return Err(ImageError::HashMismatch);
        }
        let count = u32::from_le_bytes([bytes[12], bytes[13], bytes[14], bytes[15]]);
        let mut found: [Option<&[u8]>; 14] = [None; 14];
        let mut rest = &content[HEADER_BYTES..];
        let mut last_id = 0u16;
        for _ in 0..count {
            if rest.len() < SECTION_HEADER_BYTES {
                return Err(ImageError::TooShort(bytes.len()));
            }
            let id = u16::from_le_bytes([rest[0], rest[1]]);
            let section_flags = u16::from_le_bytes([rest[2], rest[3]]);
            let length = u32::from_le_bytes([rest[4], rest[5], rest[6], rest[7]]);
            rest = &rest[SECTION_HEADER_BYTES..];
            if id <= last_id {
                return Err(ImageError::SectionOrder { id });
            }
            last_id = id;
            if length as usize > rest.len() {
                return Err(ImageError::SectionTruncated {
                    id,
                    length,
                    available: rest.len(),
                });
            }
            let (body, after) = rest.split_at(length as usize);
            rest = after;
            match SECTIONS.iter().position(|(known, _, _)| *known == id) {
                Some(index) => found[index] = Some(body),
                None if section_flags & CRITICAL != 0 => {
                    return Err(ImageError::UnknownCriticalSection { id });
                }
                None => {}
            }
        }
        if !rest.is_empty() {
            return Err(ImageError::TrailingBytes(rest.len()));
        }
        let image = Self {
            types: section(&found, 0)?,
            layout: section(&found, 1)?,
            initial: section(&found, 2)?,
            symbols: section(&found, 3)?,
            pous: section(&found, 4)?,
            constants: section(&found, 5)?,
            tasks: section(&found, 6)?,
            retain: section(&found, 7)?,
            sources: optional_section(&found, 8)?,
            info: optional_section(&found, 9)?,
            modbus_map: match found[10] {
                Some(body) => Some(decode_payload(SECTIONS[10].1, body)?),
                None => None,
            },
            motion: match found[11] {
                Some(body) => Some(decode_payload(SECTIONS[11].1, body)?),
                None => None,
            },
            debug: match found[12] {
                Some(body) => Some(decode_payload(SECTIONS[12].1, body)?),
                None => None,
            },
            modbus_master: match found[13] {
                Some(body) => Some(decode_payload(SECTIONS[13].1, body)?),
                None => None,
            },
        };
        image.verify()?;
        Ok(image)
    }

    /// The identity hash of the image as [`ProgramImage::encode`] writes it.
    pub fn identity(&self) -> ImageHash {
        identity_of(&self.encode())
    }
}

/// The identity hash of encoded image bytes (their last 32 bytes, which a decoded image has
/// checked), or of any bytes too short to hold one.
pub fn identity_of(bytes: &[u8]) -> ImageHash {
    let mut hash = [0; 32];
    if bytes.len() >= 32 {
        hash.copy_from_slice(&bytes[bytes.len() - 32..]);
    }
    hash
}

fn section<T: DeserializeOwned>(
    found: &[Option<&[u8]>; 14],
    index: usize,
) -> Result<T, ImageError> {
    let name = SECTIONS[index].1;
    let body = found[index].ok_or(ImageError::MissingSection(name))?;
    decode_payload(name, body)
}

fn optional_section<T: DeserializeOwned + Default>(
    found: &[Option<&[u8]>; 14],
    index: usize,
) -> Result<T, ImageError> {
    match found[index] {
        Some(body) => decode_payload(SECTIONS[index].1, body),
        None => Ok(T::default()),
    }
}

fn decode_payload<T: DeserializeOwned>(name: &'static str, body: &[u8]) -> Result<T, ImageError> {
    match postcard::take_from_bytes::<T>(body) {
        Ok((value, [])) => Ok(value),
        Ok((_, rest)) => Err(ImageError::Malformed {
            section: name,
            message: format!("{} bytes left over", rest.len()),
        }),
        Err(error) => Err(ImageError::Malformed {
            section: name,
            message: error.to_string(),
        }),
    }
}
