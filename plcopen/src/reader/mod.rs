//! The reader: bytes to text, text to a DOM, the DOM to the typed [`Document`].
//!
//! `context.rs` holds what every part of the reading needs (positions, paths, attributes);
//! `project.rs` the headers and instances, `pou.rs` POUs, interfaces and types, `body.rs` bodies and
//! their objects, `checks.rs` the checks across a body and across names, `encoding.rs` bytes to
//! text, `upgrade.rs` the PLCopen v1.0 rules.

mod body;
mod checks;
mod context;
mod encoding;
mod pou;
mod project;
mod upgrade;

#[cfg(test)]
pub(crate) mod corpus_tests;
#[cfg(test)]
mod error_tests;

use std::path::Path;

use crate::document::{Dialect, Document};
use crate::error::{ReadError, ReadErrorKind};
use context::Context;

/// The largest file the reader accepts, 32 MiB. Reading takes about 7.5 bytes of memory per byte
/// of file at its peak (the DOM and the model; a 10 MB file: 76 MB, `docs/plcopen-xml.md` §1.8),
/// so this keeps the reader under about 250 MB; the largest real exports seen are a few
/// megabytes.
pub const MAX_FILE_BYTES: usize = 32 * 1024 * 1024;

/// The most XML nodes the DOM may hold. Real files have one node per 20 to 25 bytes (a 32 MiB file
/// about 1.5 million); a file of nothing but empty elements would have far more, and this limit
/// keeps its DOM as small as a real file's.
const MAX_NODES: u32 = 4 * 1024 * 1024;

/// The deepest nesting of elements the reader accepts. The reader walks types, SFC macro steps
/// and inline bodies by recursion, so a file made of elements nested a million deep would
/// overflow the thread's stack; real files nest a few dozen deep (a macro step's body inside
/// a CODESYS resource's `addData` is about 15).
pub const MAX_DEPTH: usize = 128;

/// Reads a PLCopen XML document from text. `file_name` only names the file in errors.
pub fn read(text: &str, file_name: &str) -> Result<Document, ReadError> {
    if text.len() > MAX_FILE_BYTES {
        return Err(encoding::too_large(file_name, Some(text.len())));
    }
    let options = roxmltree::ParsingOptions {
        allow_dtd: false,
        nodes_limit: MAX_NODES,
        ..roxmltree::ParsingOptions::default()
    };
    let dom = roxmltree::Document::parse_with_options(text, options).map_err(|error| {
        // roxmltree places faults found at the end of the text (a truncated file) at 1:1; the
        // user needs to see where the text stops.
        let (line, column) = match error {
            roxmltree::Error::UnclosedRootNode | roxmltree::Error::UnexpectedEndOfStream => {
                encoding::line_and_column(text.as_bytes())
            }
            _ => (error.pos().row, error.pos().col),
        };
        let kind = match error {
            roxmltree::Error::NodesLimitReached => ReadErrorKind::TooManyNodes { limit: MAX_NODES },
            _ => ReadErrorKind::NotXml(error.to_string()),
        };
        ReadError {
            file: file_name.to_owned(),
            line,
            column,
            path: String::new(),
            kind,
        }
    })?;
    check_depth(&dom, text, file_name)?;
    let root = dom.root_element();
    let dialect = dialect_of(root, file_name, &dom)?;
    let context = Context::new(&dom, text, file_name, dialect);
    let document = project::read_project(&context, root)?;
    checks::check_names(&context, &document)?;
    Ok(document)
}

/// Refuses a document whose elements nest deeper than [`MAX_DEPTH`], at the first element too
/// deep in document order; works out each node's depth from its parent's, without recursion.
fn check_depth(
    dom: &roxmltree::Document<'_>,
    text: &str,
    file_name: &str,
) -> Result<(), ReadError> {
    let mut depths: Vec<u32> = Vec::new();
    for node in dom.descendants() {
        let parent_depth = node
            .parent()
            .and_then(|parent| depths.get(parent.id().get_usize()).copied())
            .unwrap_or(0);
        let depth = parent_depth + u32::from(node.is_element());
        let at = node.id().get_usize();
        if depths.len() <= at {
            depths.resize(at + 1, 0);
        }
        depths[at] = depth;
        if depth as usize > MAX_DEPTH {
            let (line, column) = encoding::line_and_column(&text.as_bytes()[..node.range().start]);
            return Err(ReadError {
                file: file_name.to_owned(),
                line,
                column,
                path: String::new(),
                kind: ReadErrorKind::TooDeep { limit: MAX_DEPTH },
            });
        }
    }
    Ok(())
}

/// Reads a PLCopen XML document from the bytes of a file: UTF-8 with or without a byte order mark,
/// or UTF-16 with one; files over [`MAX_FILE_BYTES`] are refused before anything is decoded.
pub fn read_bytes(bytes: &[u8], file_name: &str) -> Result<Document, ReadError> {
    let text = encoding::decode(bytes, file_name)?;
    read(&text, file_name)
}

/// Reads a PLCopen XML file; the file name in errors is the path as given. A file over
/// [`MAX_FILE_BYTES`] is refused from its metadata, before it is read into memory; a file whose
/// metadata gives no size (a pipe, a device) is read up to one byte past the limit and no
/// further, so no file makes the reader hold more than the limit.
pub fn read_file(path: &Path) -> Result<Document, ReadFileError> {
    use std::io::Read as _;

    let file_name = path.display().to_string();
    let io_error = |source| ReadFileError::Io {
        file: file_name.clone(),
        source,
    };
    let file = std::fs::File::open(path).map_err(io_error)?;
    let size_bytes = file.metadata().map_err(io_error)?.len();
    let size_bytes = usize::try_from(size_bytes).unwrap_or(usize::MAX);
    if size_bytes > MAX_FILE_BYTES {
        return Err(ReadFileError::Read(encoding::too_large(
            &file_name,
            Some(size_bytes),
        )));
    }
    let limit = u64::try_from(MAX_FILE_BYTES).unwrap_or(u64::MAX);
    let mut bytes = Vec::with_capacity(size_bytes);
    if size_bytes == 0 {
        // A pipe or a device has no size: room for the limit up front, so that the buffer's
        // doubling cannot take twice the limit (pages not written are not resident).
        bytes
            .try_reserve_exact(MAX_FILE_BYTES + 1)
            .map_err(|_| io_error(std::io::Error::from(std::io::ErrorKind::OutOfMemory)))?;
    }
    file.take(limit + 1)
        .read_to_end(&mut bytes)
        .map_err(io_error)?;
    if bytes.len() > MAX_FILE_BYTES {
        return Err(ReadFileError::Read(encoding::too_large(&file_name, None)));
    }
    Ok(read_bytes(&bytes, &file_name)?)
}

/// Why [`read_file`] failed: the file could not be read, or its content was refused.
#[derive(Debug, thiserror::Error)]
pub enum ReadFileError {
    /// The file could not be opened or read.
    #[error("{file}: {source}")]
    Io {
        /// The path as given.
        file: String,
        /// The operating system's error.
        source: std::io::Error,
    },
    /// The content is not a PLCopen XML document the reader accepts.
    #[error(transparent)]
    Read(#[from] ReadError),
}

/// The dialect of the root element, or the error for a root that is no PLCopen project.
fn dialect_of(
    root: roxmltree::Node<'_, '_>,
    file_name: &str,
    dom: &roxmltree::Document<'_>,
) -> Result<Dialect, ReadError> {
    let position = dom.text_pos_at(root.range().start);
    let error = |kind| ReadError {
        file: file_name.to_owned(),
        line: position.row,
        column: position.col,
        path: root.tag_name().name().to_owned(),
        kind,
    };
    if root.tag_name().name() != "project" {
        return Err(error(ReadErrorKind::WrongRoot {
            found: root.tag_name().name().to_owned(),
        }));
    }
    let namespace = root.tag_name().namespace().unwrap_or("");
    [Dialect::V201, Dialect::V200, Dialect::V10]
        .into_iter()
        .find(|dialect| dialect.namespace() == namespace)
        .ok_or_else(|| {
            error(ReadErrorKind::WrongNamespace {
                found: namespace.to_owned(),
            })
        })
}
