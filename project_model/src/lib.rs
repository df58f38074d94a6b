//! The Rivet project as plain data.
//!
//! This crate is the ground truth of the studio: the device tree (controller, tasks, I/O areas,
//! serial ports, Modbus TCP and RTU devices, motion axes) and the application (folders, POUs, global variable lists,
//! data types, cam tables, trace configurations, watch lists).
//! It loads and saves projects as folders of text files (see `docs/project-format.md`), and
//! changes them only through [`Edit`]s, each of which returns its inverse so [`History`] can undo
//! and redo.
//!
//! It depends on no other crate of the workspace, does no network I/O and spawns no threads.

mod application;
mod axis;
mod cam;
mod cfc;
mod cfc_check;
pub mod cfc_edit;
mod chart_replace;
mod data_type;
mod declaration_text;
mod declarations_edit;
mod device_check;
mod dialect;
mod edit;
mod element_caption;
mod files;
mod gvl;
mod history;
mod identifier;
mod io_area;
mod list_edit;
mod merge_plan;
mod modbus_device;
mod modbus_device_file;
mod network;
mod network_check;
mod network_edit;
mod network_normal_form;
mod network_splice;
mod network_walk;
mod pou;
mod project;
mod rename_edits;
mod serial_port;
mod sfc;
mod sfc_check;
pub mod sfc_edit;
mod sfc_fire;
mod sfc_problem;
mod task;
mod trace;
mod validate;
mod variable;
mod vendor_data;
mod watch;

#[cfg(feature = "proptest")]
pub mod arb;

pub use application::{Folder, Node, Object, ObjectKind};
pub use axis::{Axis, AxisKind, AxisLimits, AxisScaling, SoftwareLimits};
pub use cam::{
    CamCompileFormat, CamContinuity, CamKeyPoint, CamPeriod, CamProfile, CamRange, CamSegment,
    CamTable, CamTablePoint, MotionLaw, PointInterpolation, Tappet, TappetAction, TappetTrack,
};
pub use cfc::{CfcBox, CfcChart, CfcElement, CfcElementKind, CfcPin, GridPoint, PinRef, Wire};
pub use cfc_check::{CfcProblem, cfc_input_pins, cfc_output_pins, cfc_pin_matches, cfc_problems};
pub use cfc_edit::CfcEditError;
pub use data_type::{DataType, EnumValue, StructMember, TypeDefinition};
pub use declarations_edit::{
    DeclarationsChange, TypedDeclarations, TypedHeader, gvl_declarations_change,
    pou_declarations_change,
};
pub use device_check::{
    DeviceProblem, LOCATED_AREA_BYTES, MAX_POLL_INTERVAL_MS, MAX_READ_GAP, MAX_TIMEOUT_MS,
    axis_problems, binding_problems, controller_problems, device_problems, io_area_problems,
    map_range_problems, modbus_device_problems, new_problem, request_limit, serial_port_problems,
};
pub use dialect::Dialect;
pub use edit::{Edit, EditError, TextTarget, TreeEdit, VarOwner};
pub use files::{
    APPLICATION_DIR, FORMAT_VERSION, HeldBackObject, LoadError, LoadProblem, LoadedProject,
    MANIFEST_FILE_NAME, SaveError, SaveReport, Severity, StBody, VENDOR_DATA_FILE_NAME,
    load_project, object_files, save_project, save_project_keeping, st_body_files, text_body_files,
};
pub use gvl::GlobalVarList;
pub use history::{History, Transaction};
pub use identifier::{is_valid_identifier, same_identifier};
pub use io_area::{IoArea, IoDirection};
pub use list_edit::ListEdit;
pub use merge_plan::{ClashChoice, IgnoredPart, MergeClash, MergeItem, MergePlan};
pub use modbus_device::{
    ChannelDirection, ChannelErrorAction, ChannelTrigger, ModbusBinding, ModbusDataType,
    ModbusDevice, ModbusLink, ModbusSchedule, ModbusTable, WordOrder,
};
pub use network::{
    BlockCall, BlockInput, BlockOutput, Branch, Coil, CoilKind, EN_PIN, ENO_PIN, Edge, ElementId,
    FlowNode, Network, NetworkOutput, Operand, Parallel,
};
pub use network_check::{MAX_NETWORK_NESTING, NetworkProblem, network_problems};
pub use network_edit::{
    Anchor, BodySplice, HeaderField, NetworkClipboard, NetworkEditError, ParallelSide, Side,
    copy_elements, copy_networks, cycle_modifier, cycle_pin_edge, delete_elements, delete_networks,
    insert_network, insert_output, insert_parallel, insert_series, new_box, new_coil, new_contact,
    new_jump, new_return, paste, set_element_text, set_network_header, set_pin_operand,
    toggle_en_eno, toggle_negation,
};
pub use network_normal_form::{is_nested_too_deeply, normalize_network, normalize_networks};
pub use network_walk::{ElementRef, max_element_id, walk_chain, walk_outputs};
pub use pou::{
    AccessSpecifier, Body, Language, Method, Pou, PouAction, PouKind, Property, PropertyAccessor,
};
pub use project::{Controller, ModbusServerMap, ModbusServerRange, Project};
pub use rename_edits::{serial_port_rename_edits, task_rename_edits};
pub use serial_port::{Parity, SerialPort};
pub use sfc::{
    ActionAssociation, ActionQualifier, Jump, MacroStep, SfcBranches, SfcChart, SfcNode,
    SfcSequence, Step, Transition,
};
pub use sfc_check::{sfc_chart_problems, sfc_problems};
pub use sfc_fire::{TransitionSteps, transition_steps};
pub use sfc_problem::{SfcNodeKind, SfcProblem, SfcProblemKind};
pub use task::{Task, TaskKind, Watchdog};
pub use trace::{TraceConfig, TraceTrigger, TraceTriggerCondition, TraceVariable};
pub use variable::{VarSection, Variable};
pub use vendor_data::{VendorData, VendorEntry, element_signature};
pub use watch::{WatchEntry, WatchList};
