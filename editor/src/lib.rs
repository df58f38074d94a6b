//! Rivet's document editors: the Structured Text editor, the LD, FBD, CFC and SFC canvases and
//! the variable declaration table.
//!
//! Editors draw from the project model and never change it while drawing: they emit edits that
//! the app applies after the frame. They see the compiler only through its `ide` facade.
//!
//! Today the crate offers [`StEditor`], the editable Structured Text editor (tree-sitter
//! highlighting, folding, diagnostics, find and replace, completion, inline values); the
//! [`VariableTable`] that edits declarations in place; the I/O mapping view ([`io_mapping_ui`])
//! that lists each channel of the controller's I/O areas and of the Modbus TCP devices with the
//! variables bound to it; the device editors ([`controller_editor_ui`], [`io_area_editor_ui`],
//! [`modbus_device_editor_ui`], [`axis_editor_ui`]); the combined LD/FBD [`DiagramEditor`] on a
//! canvas with automatic layout ([`ld_layout`], [`fbd_layout`]); the [`CfcEditor`] with free
//! placement, routed wires and the execution order; the [`SfcEditor`] of structured SFC charts
//! laid out by [`sfc_layout`]; and the read-only [`CodeView`]
//! with lexical highlighting.

mod body_debug_marks;
mod cfc;
mod code_view;
mod device_editors;
mod diagram;
mod io_mapping;
mod palette;
mod sfc;
mod st_editor;
mod st_highlight;
mod table_texts;
mod variable_table;

pub use body_debug_marks::{BodyBreakpointMark, BodyDebugMarks, BodyPlace};
pub use cfc::{
    CfcChange, CfcDiagnostic, CfcEditor, CfcOrderCommand, CfcOutput, CfcRefusal, CfcSelection,
    CfcTexts, CfcTool, VariableDragPayload,
};
pub use code_view::CodeView;
pub use device_editors::{
    DeviceEdit, DeviceEditorState, DeviceTexts, ModbusOnlinePart, Refusal, RefusalWords,
    StandardSilence, axis_editor_ui, controller_editor_ui, io_area_editor_ui,
    modbus_device_editor_ui, modbus_online_ui, serial_port_editor_ui,
};
pub use diagram::{
    BlockSignature, DiagramChange, DiagramCommand, DiagramEditor, DiagramOnline, DiagramOutput,
    DiagramRefusal, DiagramSelection, DiagramServices, DiagramTexts, DiagramView,
    ElementDiagnostic, InsertPoint, InsertTarget, InstanceDeclaration, NetworkLayout, OnlineValue,
    PinMark, PlacedElement, Power, PreparedOperand, Shape, ToolboxBlock, ToolboxItem, Wire,
    fbd_layout, ld_layout,
};
pub use io_mapping::{IoMappingOutput, io_mapping_ui};
pub use palette::{EditorPalette, SyntaxColors};
pub use sfc::{
    ActionBox, SfcChange, SfcCommand, SfcDiagnostic, SfcEditor, SfcLayout, SfcLine, SfcOnline,
    SfcOnlineCommand, SfcOutput, SfcPlaced, SfcRefusalWords, SfcShape, SfcStepOnline, SfcTexts,
    sfc_layout,
};
pub use st_editor::{
    BreakpointLook, BreakpointMark, CompletionItem, CompletionKind, EditorDiagnostic, EditorTexts,
    Gesture, Highlight, InlineValue, KeywordCompletions, LanguageServices, Severity, StDebugMarks,
    StEditor, StEditorOutput, TextBuffer, TextChange,
};
pub use st_highlight::{TokenClass, classify_tokens};
pub use table_texts::TableTexts;
pub use variable_table::{VariableTable, VariableTableOutput, overlap_warnings};
