//! The downloadable artefact that the compiler writes, the runtime loads and `online` downloads.
//!
//! A program image holds target-independent code for every POU, the symbol table (every variable's
//! full path, type, memory offset and size), the task table, the located-variable map, cam data,
//! the identity hash of the whole image and its format version.
//! It depends on no other crate of the workspace, so the client side never needs the runtime.
//!
//! The image format is specified in `docs/program-image.md` (written with the code generator).

mod elementary;

pub use elementary::Elementary;
