//! The documents that hold Structured Text: POUs (declarations as text or as a table above the
//! implementation; methods, actions and property accessors one at a time) and global variable
//! lists. Text is edited with `editor::StEditor`; every change goes to the model as an edit
//! after the frame, typing merged into one undo step per run.

mod body;
mod declarations;
mod diagnostics;
mod documents;
mod frame_inline;
mod inline;
mod live_check;
mod part;
mod pou_document;
mod services;

pub(crate) use declarations::gvl_document_ui;
pub use documents::TextDocuments;
pub(crate) use documents::table_texts;
pub(crate) use pou_document::pou_document_ui;
