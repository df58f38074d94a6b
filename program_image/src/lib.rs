//! The downloadable artefact that the compiler writes, the runtime loads and `online` downloads.
//!
//! A program image holds target-independent code for every POU, the symbol table (every variable's
//! full path, type, memory offset and size), the task table, the located-variable map, cam data,
//! the identity hash of the whole image and its format version.
//! It depends on no other crate of the workspace, so the client side never needs the runtime.
//!
//! The format is specified in `docs/program-image.md`: [`ProgramImage::encode`] and
//! [`ProgramImage::decode`] implement its container, [`ProgramImage::verify`] its load-time
//! checks, [`code`] its instructions and [`std_blocks`] the instance layouts of the standard
//! function blocks; [`DebugInfo`] is the optional debug section, [`BreakCondition`] a
//! breakpoint's compiled condition with [`ProgramImage::verify_condition`],
//! [`ProgramImage::instance_path`] names an instance by its address, and [`modbus_master`] is the
//! section of the devices the runtime masters over Modbus, with their request plan and value codec.

pub mod code;
mod code_error;
mod condition;
mod debug;
mod elementary;
mod encoding;
mod image;
mod instance_path;
mod listing;
pub mod modbus_master;
pub mod motion;
pub mod std_blocks;
mod types;
mod verify;

pub use code::{BinaryOp, CompareOp, Instr, Operand, StdBlock, StdFunction, Transfer, UnaryOp};
pub use condition::{BreakCondition, ConditionError};
pub use debug::{DebugInfo, FrameVariable, FrameVariableKind, PouDebug, source_hash};
pub use elementary::Elementary;
pub use encoding::{FORMAT_VERSION, ImageError, ImageHash, MAGIC, MAX_IMAGE_BYTES, identity_of};
pub use image::{
    Info, InitRun, InitialValues, Layout, LineEntry, Located, ModbusRange, ModbusTable, Pou,
    PouKind, ProgramCall, ProgramImage, Region, RetainLayout, Symbol, SymbolFlags, Task, TaskKind,
};
pub use listing::listing;
pub use types::{Member, StructKind, TypeDef, TypeId};
pub use verify::MAX_REGION_BYTES;
