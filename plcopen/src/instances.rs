//! Configurations, resources, tasks and instances.

use crate::add_data::AddData;
use crate::data_type::{DataType, Value};
use crate::interface::VarList;
use crate::text::FormattedText;

/// `configuration`.
#[derive(Clone, Debug, PartialEq)]
pub struct Configuration {
    /// `name`.
    pub name: String,
    /// `globalId`.
    pub global_id: Option<String>,
    /// `resource` elements.
    pub resources: Vec<Resource>,
    /// `globalVars` lists.
    pub global_vars: Vec<VarList>,
    /// `accessVars/accessVariable`.
    pub access_vars: Vec<AccessVariable>,
    /// `configVars/configVariable`.
    pub config_vars: Vec<ConfigVariable>,
    /// Vendor data.
    pub add_data: AddData,
    /// Documentation.
    pub documentation: Option<FormattedText>,
    /// Line of the element (1-based), for the conversion's messages.
    pub line: u32,
    /// Column of the element's `<` (1-based, in characters), for the conversion's messages.
    pub column: u32,
}

/// `resource`.
#[derive(Clone, Debug, PartialEq)]
pub struct Resource {
    /// `name`.
    pub name: String,
    /// `globalId`.
    pub global_id: Option<String>,
    /// `task` elements.
    pub tasks: Vec<Task>,
    /// `globalVars` lists.
    pub global_vars: Vec<VarList>,
    /// `pouInstance` elements not bound to a task.
    pub pou_instances: Vec<PouInstance>,
    /// Vendor data (CODESYS writes POUs, libraries and the project structure here).
    pub add_data: AddData,
    /// Documentation.
    pub documentation: Option<FormattedText>,
    /// Line of the element (1-based), for the conversion's messages.
    pub line: u32,
    /// Column of the element's `<` (1-based, in characters), for the conversion's messages.
    pub column: u32,
}

/// `task`.
#[derive(Clone, Debug, PartialEq)]
pub struct Task {
    /// `name`.
    pub name: String,
    /// `priority` (0 to 65535).
    pub priority: u32,
    /// `interval`, as written (`T#100ms`, CODESYS `PT0.2S`; v1.0's `00:00:00.100000` is rewritten
    /// as `T#100ms`).
    pub interval: Option<String>,
    /// `single`: the variable whose rising edge starts the task.
    pub single: Option<String>,
    /// `globalId`.
    pub global_id: Option<String>,
    /// `pouInstance` elements of the task.
    pub pou_instances: Vec<PouInstance>,
    /// Vendor data.
    pub add_data: AddData,
    /// Documentation.
    pub documentation: Option<FormattedText>,
    /// Line of the `task` element (1-based).
    pub line: u32,
    /// Column of the element's `<` (1-based, in characters), for the conversion's messages.
    pub column: u32,
}

/// `pouInstance`: a program instance.
#[derive(Clone, Debug, PartialEq)]
pub struct PouInstance {
    /// `name`.
    pub name: String,
    /// `typeName` (v1.0 `type`; CODESYS writes `""`).
    pub type_name: String,
    /// `globalId`.
    pub global_id: Option<String>,
    /// Vendor data.
    pub add_data: AddData,
    /// Documentation.
    pub documentation: Option<FormattedText>,
}

/// `accessVariable`.
#[derive(Clone, Debug, PartialEq)]
pub struct AccessVariable {
    /// `alias`.
    pub alias: String,
    /// `instancePathAndName`.
    pub instance_path_and_name: String,
    /// `direction` (`readWrite`, `readOnly`).
    pub direction: Option<String>,
    /// `type`.
    pub data_type: Option<DataType>,
}

/// `configVariable`.
#[derive(Clone, Debug, PartialEq)]
pub struct ConfigVariable {
    /// `instancePathAndName`.
    pub instance_path_and_name: String,
    /// `address`.
    pub address: Option<String>,
    /// `type`.
    pub data_type: Option<DataType>,
    /// `initialValue`.
    pub initial_value: Option<Value>,
}
