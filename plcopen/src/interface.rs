//! A POU's interface: variable lists and variables.

use crate::add_data::AddData;
use crate::data_type::{DataType, Value};
use crate::text::FormattedText;

/// `interface`: the return type and the variable lists in document order.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Interface {
    /// `returnType` of a function or method.
    pub return_type: Option<DataType>,
    /// The variable lists in document order.
    pub var_lists: Vec<VarList>,
    /// Vendor data.
    pub add_data: AddData,
    /// Documentation.
    pub documentation: Option<FormattedText>,
}

/// Which section a variable list declares.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum VarListKind {
    /// `localVars`.
    Local,
    /// `tempVars`.
    Temp,
    /// `inputVars`.
    Input,
    /// `outputVars`.
    Output,
    /// `inOutVars`.
    InOut,
    /// `externalVars`.
    External,
    /// `globalVars`.
    Global,
    /// `accessVars`.
    Access,
}

impl VarListKind {
    /// The kind of an element's local name, or `None` when it names no variable list.
    pub fn from_element(name: &str) -> Option<VarListKind> {
        Some(match name {
            "localVars" => VarListKind::Local,
            "tempVars" => VarListKind::Temp,
            "inputVars" => VarListKind::Input,
            "outputVars" => VarListKind::Output,
            "inOutVars" => VarListKind::InOut,
            "externalVars" => VarListKind::External,
            "globalVars" => VarListKind::Global,
            "accessVars" => VarListKind::Access,
            _ => return None,
        })
    }
}

/// A variable list (`varList`) with its attributes.
#[derive(Clone, Debug, PartialEq)]
pub struct VarList {
    /// The section.
    pub kind: VarListKind,
    /// `name` (a global variable list's name).
    pub name: Option<String>,
    /// `constant`.
    pub constant: bool,
    /// `retain`.
    pub retain: bool,
    /// `nonretain`.
    pub nonretain: bool,
    /// `persistent`.
    pub persistent: bool,
    /// `nonpersistent`.
    pub nonpersistent: bool,
    /// The variables in order.
    pub variables: Vec<Variable>,
    /// Vendor data.
    pub add_data: AddData,
    /// Documentation.
    pub documentation: Option<FormattedText>,
    /// Line of the element (1-based), for the conversion's messages.
    pub line: u32,
    /// Column of the element's `<` (1-based, in characters), for the conversion's messages.
    pub column: u32,
}

/// A variable (`variable`), also a structure member.
#[derive(Clone, Debug, PartialEq)]
pub struct Variable {
    /// `name`.
    pub name: String,
    /// `address` (`%IX0.0`), when located.
    pub address: Option<String>,
    /// `globalId`.
    pub global_id: Option<String>,
    /// `type`.
    pub data_type: DataType,
    /// `initialValue`.
    pub initial_value: Option<Value>,
    /// Vendor data (CODESYS attributes and pragmas).
    pub add_data: AddData,
    /// Documentation (the comment beside the declaration).
    pub documentation: Option<FormattedText>,
    /// Line of the `variable` element (1-based).
    pub line: u32,
    /// Column of the element's `<` (1-based, in characters), for the conversion's messages.
    pub column: u32,
}
