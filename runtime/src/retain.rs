//! RETAIN and PERSISTENT variables kept in the runtime's data directory, across restarts of the
//! runtime (`docs/program-image.md` §10).
//!
//! The retained bytes (every RETAIN range of the data region, then every PERSISTENT range, in
//! the image's order) are saved to `retain.bin` in the data directory, together with the image's
//! [layout hash](layout_hash), so they are restored only into an image whose retained layout is
//! identical. A save writes a temporary file, flushes it to the disk and renames it over the old
//! one, so a crash leaves either the old or the new data, never a mixture.
//!
//! The file is `RIVETRET`, a `u16` format version (1), the 32-byte layout hash, a `u32` byte
//! count, the retained bytes, and the SHA-256 of everything before it; integers little-endian.

use std::fs;
use std::io::{self, Write};
use std::path::{Path, PathBuf};

use program_image::{ProgramImage, Region};
use sha2::{Digest, Sha256};

use crate::engine::Engine;

mod file_error;
use file_error::RetainFileError;

/// The SHA-256 that says whether saved retain data fits an image: see [`layout_hash`].
pub type LayoutHash = [u8; 32];

/// The name of the retain file in the data directory.
pub const RETAIN_FILE: &str = "retain.bin";

/// The retain data of one data directory, with what was last saved there.
///
/// It lives as long as the runtime uses the directory; only the file is saved.
#[derive(Debug)]
pub struct RetainStore {
    /// The data directory.
    dir: PathBuf,
    /// The layout hash and bytes last saved or restored, so an unchanged state is not written
    /// again.
    last: Option<(LayoutHash, Vec<u8>)>,
}

/// The retained bytes of an engine at one moment, with its layout hash: what a save writes.
///
/// Taking one is a copy of the retained ranges, cheap enough between two cycles; writing it can
/// then happen on another thread.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RetainSnapshot {
    /// The layout hash of the engine's image.
    pub layout_hash: LayoutHash,
    /// The RETAIN ranges' bytes, then the PERSISTENT ranges' bytes.
    pub bytes: Vec<u8>,
}

impl RetainSnapshot {
    /// The retained values of `engine`, or `None` when its image has no retained variables.
    pub fn of(engine: &Engine) -> Option<Self> {
        Self::of_data(engine.image(), engine.region(Region::Data))
    }

    /// The retained values in `data`, the data region of an engine running `image` (also
    /// inside a halted cycle).
    pub fn of_data(image: &ProgramImage, data: &[u8]) -> Option<Self> {
        let ranges = retained_ranges(image);
        if ranges.is_empty() {
            return None;
        }
        let mut bytes = Vec::new();
        for (offset, length) in ranges {
            let start = offset as usize;
            bytes.extend_from_slice(data.get(start..start + length as usize).unwrap_or(&[]));
        }
        Some(Self {
            layout_hash: layout_hash(image),
            bytes,
        })
    }
}

/// What [`RetainStore::restore`] did.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum RetainRestore {
    /// The saved values were restored.
    Restored {
        /// The file they came from.
        path: PathBuf,
    },
    /// The image has no RETAIN or PERSISTENT variables.
    NoRetainedVariables,
    /// There is no retain file yet.
    NothingSaved {
        /// The data directory.
        dir: PathBuf,
    },
    /// The saved data belongs to an image with another retained layout.
    LayoutChanged {
        /// The file.
        path: PathBuf,
    },
    /// The file cannot be read or is damaged.
    Unreadable {
        /// The file.
        path: PathBuf,
        /// What is wrong with it.
        reason: String,
    },
}

/// Why retain data cannot be saved or deleted.
#[derive(Debug, thiserror::Error)]
#[error("cannot {action} retain data {}: {source}", path.display())]
pub struct RetainError {
    /// `write` or `delete`.
    action: &'static str,
    /// The file or directory concerned.
    path: PathBuf,
    /// What the system said.
    source: io::Error,
}

/// The layout hash of `image`: the SHA-256 of the postcard encodings of its `types`, `layout`
/// and `retain` fields, one after the other.
///
/// Those encodings are exactly the payloads of the image's `types`, `layout` and `retain`
/// sections, so this is the hash of those three sections' bytes that the format specifies.
pub fn layout_hash(image: &ProgramImage) -> LayoutHash {
    let mut hasher = Sha256::new();
    // Encoding plain data into a vector cannot fail; if it ever did, the empty payload would
    // still hash the other two fields, and the retained sizes are checked on restore anyway.
    hasher.update(postcard::to_allocvec(&image.types).unwrap_or_default());
    hasher.update(postcard::to_allocvec(&image.layout).unwrap_or_default());
    hasher.update(postcard::to_allocvec(&image.retain).unwrap_or_default());
    hasher.finalize().into()
}

impl RetainStore {
    /// The retain data of `dir`, which need not exist yet.
    pub fn new(dir: impl Into<PathBuf>) -> Self {
        Self {
            dir: dir.into(),
            last: None,
        }
    }

    /// The retain file.
    pub fn path(&self) -> PathBuf {
        self.dir.join(RETAIN_FILE)
    }

    /// Restores the saved RETAIN and PERSISTENT values into `engine` when they were saved from
    /// an image with the same layout hash; otherwise leaves its memory as it is and says why.
    pub fn restore(&mut self, engine: &mut Engine) -> RetainRestore {
        let path = self.path();
        let ranges = retained_ranges(engine.image());
        if ranges.is_empty() {
            return RetainRestore::NoRetainedVariables;
        }
        let bytes = match fs::read(&path) {
            Ok(bytes) => bytes,
            Err(error) if error.kind() == io::ErrorKind::NotFound => {
                return RetainRestore::NothingSaved {
                    dir: self.dir.clone(),
                };
            }
            Err(error) => {
                return RetainRestore::Unreadable {
                    path,
                    reason: error.to_string(),
                };
            }
        };
        let hash = layout_hash(engine.image());
        let saved = match parse(&bytes) {
            Ok((saved_hash, _)) if saved_hash != hash => {
                return RetainRestore::LayoutChanged { path };
            }
            Ok((_, saved)) => saved,
            Err(error) => {
                return RetainRestore::Unreadable {
                    path,
                    reason: error.to_string(),
                };
            }
        };
        let expected: usize = ranges.iter().map(|&(_, length)| length as usize).sum();
        if saved.len() != expected {
            return RetainRestore::Unreadable {
                path,
                reason: format!(
                    "it holds {} bytes, the image retains {expected}",
                    saved.len()
                ),
            };
        }
        let data = engine.region_mut(Region::Data);
        let mut rest = saved;
        for (offset, length) in ranges {
            let (bytes, after) = rest.split_at(length as usize);
            let start = offset as usize;
            if let Some(place) = data.get_mut(start..start + bytes.len()) {
                place.copy_from_slice(bytes);
            }
            rest = after;
        }
        self.last = Some((hash, saved.to_vec()));
        RetainRestore::Restored { path }
    }

    /// Saves the retained values of `engine` when they differ from what this store last saved
    /// or restored; returns whether it wrote. An image without retained variables writes
    /// nothing, so it does not destroy data saved for another image.
    pub fn save(&mut self, engine: &Engine) -> Result<bool, RetainError> {
        match RetainSnapshot::of(engine) {
            Some(snapshot) => self.write(snapshot),
            None => Ok(false),
        }
    }

    /// Writes `snapshot` when it differs from what this store last saved or restored; returns
    /// whether it wrote.
    pub fn write(&mut self, snapshot: RetainSnapshot) -> Result<bool, RetainError> {
        if self
            .last
            .as_ref()
            .is_some_and(|(hash, bytes)| *hash == snapshot.layout_hash && *bytes == snapshot.bytes)
        {
            return Ok(false);
        }
        self.write_atomically(&encode(&snapshot.layout_hash, &snapshot.bytes))?;
        self.last = Some((snapshot.layout_hash, snapshot.bytes));
        Ok(true)
    }

    /// Deletes the saved data (an origin reset); a missing file is not an error.
    pub fn delete(&mut self) -> Result<(), RetainError> {
        self.last = None;
        let path = self.path();
        match fs::remove_file(&path) {
            Ok(()) => Ok(()),
            Err(error) if error.kind() == io::ErrorKind::NotFound => Ok(()),
            Err(source) => Err(RetainError {
                action: "delete",
                path,
                source,
            }),
        }
    }

    /// Writes `bytes` to the retain file through a temporary file that is flushed to the disk
    /// and renamed, then flushes the directory so the rename itself survives a power loss.
    fn write_atomically(&self, bytes: &[u8]) -> Result<(), RetainError> {
        let path = self.path();
        let temporary = self.dir.join(format!("{RETAIN_FILE}.tmp"));
        let failed = |path: &Path| {
            let path = path.to_owned();
            move |source| RetainError {
                action: "write",
                path,
                source,
            }
        };
        fs::create_dir_all(&self.dir).map_err(failed(&self.dir))?;
        let mut file = fs::File::create(&temporary).map_err(failed(&temporary))?;
        file.write_all(bytes).map_err(failed(&temporary))?;
        file.sync_all().map_err(failed(&temporary))?;
        drop(file);
        fs::rename(&temporary, &path).map_err(failed(&path))?;
        if cfg!(unix) {
            fs::File::open(&self.dir)
                .and_then(|dir| dir.sync_all())
                .map_err(failed(&self.dir))?;
        }
        Ok(())
    }
}

impl std::fmt::Display for RetainRestore {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        const FRESH: &str = "RETAIN and PERSISTENT variables start from their initial values";
        match self {
            Self::Restored { path } => write!(
                f,
                "restored RETAIN and PERSISTENT variables from {}",
                path.display()
            ),
            Self::NoRetainedVariables => {
                write!(f, "the program has no RETAIN or PERSISTENT variables")
            }
            Self::NothingSaved { dir } => {
                write!(f, "no retain data saved in {} yet: {FRESH}", dir.display())
            }
            Self::LayoutChanged { path } => write!(
                f,
                "the retain data in {} was saved by a program whose retained variables are laid out differently: {FRESH}",
                path.display()
            ),
            Self::Unreadable { path, reason } => write!(
                f,
                "the retain data in {} cannot be used ({reason}): {FRESH}",
                path.display()
            ),
        }
    }
}

/// The first bytes of a retain file.
const MAGIC: &[u8; 8] = b"RIVETRET";

/// The version of the retain file's format.
const VERSION: u16 = 1;

/// Magic, version, layout hash and byte count.
const HEADER_BYTES: usize = 8 + 2 + 32 + 4;

/// The RETAIN ranges, then the PERSISTENT ones, as (offset, length) in the data region.
fn retained_ranges(image: &ProgramImage) -> Vec<(u32, u32)> {
    image
        .retain
        .retain
        .iter()
        .chain(&image.retain.persistent)
        .copied()
        .collect()
}

fn encode(hash: &LayoutHash, retained: &[u8]) -> Vec<u8> {
    let mut bytes = Vec::with_capacity(HEADER_BYTES + retained.len() + 32);
    bytes.extend_from_slice(MAGIC);
    bytes.extend_from_slice(&VERSION.to_le_bytes());
    bytes.extend_from_slice(hash);
    bytes.extend_from_slice(&(retained.len() as u32).to_le_bytes());
    bytes.extend_from_slice(retained);
    let checksum: [u8; 32] = Sha256::digest(&bytes).into();
    bytes.extend_from_slice(&checksum);
    bytes
}

/// The layout hash and retained bytes of a retain file, or what is wrong with it.
fn parse(bytes: &[u8]) -> Result<(LayoutHash, &[u8]), RetainFileError> {
    if bytes.len() < HEADER_BYTES + 32 {
        return Err(RetainFileError::Truncated {
            length_bytes: bytes.len(),
        });
    }
    if !bytes.starts_with(MAGIC) {
        return Err(RetainFileError::BadMagic);
    }
    let version = u16::from_le_bytes([bytes[8], bytes[9]]);
    if version != VERSION {
        return Err(RetainFileError::WrongVersion { found: version });
    }
    let (content, checksum) = bytes.split_at(bytes.len() - 32);
    if Sha256::digest(content).as_slice() != checksum {
        return Err(RetainFileError::Corrupted);
    }
    let mut hash = [0; 32];
    hash.copy_from_slice(&content[10..42]);
    let length = u32::from_le_bytes([content[42], content[43], content[44], content[45]]);
    let retained = &content[HEADER_BYTES..];
    if retained.len() != length as usize {
        return Err(RetainFileError::WrongLength {
            announced: length,
            held: retained.len(),
        });
    }
    Ok((hash, retained))
}

#[cfg(test)]
mod tests;
