//! A typed model of a PLCopen TC6 XML document (v2.01, CODESYS's `tc6_0200` and v1.0) and a reader
//! that turns the XML text into it, refusing bad input with the file, line, column and element path.
//!
//! [`import`] converts a document into a `project_model::Project` in memory, with a report of
//! what became of each part. The rules of both are written in `docs/plcopen-xml.md`. The crate is
//! pure: of the workspace it knows only `project_model`, and its only I/O is the [`read_file`]
//! convenience.

mod add_data;
mod body;
mod body_object;
mod connection;
mod data_type;
mod document;
mod error;
mod export;
mod fbd;
mod header;
mod import;
mod instances;
mod interface;
mod ld;
mod pou;
mod reader;
mod rivet_data;
mod sfc;
mod text;

pub use add_data::{AddData, AddDataEntry, HandleUnknown};
pub use body::{Body, BodyContent};
pub use body_object::{BodyObject, ObjectKind, Size};
pub use connection::{Connection, ConnectionPointIn, ConnectionPointOut};
pub use data_type::{DataType, DataTypeDecl, Dimension, EnumValue, Value, ValueItem};
pub use document::{Dialect, Document, XmlComment};
pub use error::{ReadError, ReadErrorKind};
pub use export::{ExportError, ExportOptions, export, export_with};
pub use fbd::{
    Block, BlockPin, Connector, Continuation, InOutVariable, InVariable, Jump, Label, OutVariable,
    Return, VendorElement,
};
pub use header::{ContentHeader, CoordinateInfo, FileHeader, Point};
pub use import::{
    ImportError, ImportErrorKind, ImportReport, Imported, NetworkError, Outcome, ReportEntry,
    import, parse_interval_us,
};
pub use instances::{AccessVariable, ConfigVariable, Configuration, PouInstance, Resource, Task};
pub use interface::{Interface, VarList, VarListKind, Variable};
pub use ld::{Coil, Contact, Edge, LeftPowerRail, RightPowerRail, Storage};
pub use pou::{Action, Method, Pou, PouLocation, PouType, Transition};
pub use reader::{MAX_DEPTH, MAX_FILE_BYTES, ReadFileError, read, read_bytes, read_file};
pub use rivet_data::{RIVET_NAMESPACE, RivetDataError};
pub use sfc::{
    ActionBlock, ActionBlockAction, ActionContent, Condition, ConditionForm, Convergence,
    Divergence, JumpStep, MacroStep, Qualifier, SfcTransition, Step,
};
pub use text::{FormattedText, TextMarkup};
