//! Third-party Modbus TCP devices that Rivet polls.

use serde::{Deserialize, Serialize};

/// A Modbus TCP server (an I/O block, a drive, another PLC) whose registers variables bind to, so
/// they can be monitored, written, forced and traced without downloading anything.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(deny_unknown_fields)]
pub struct ModbusDevice {
    /// The device's name in the device tree.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::ident()"))]
    pub name: String,
    /// Host name or IP address.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::ident()"))]
    pub host: String,
    /// TCP port, 502 by default.
    pub port: u16,
    /// The Modbus unit identifier.
    pub unit_id: u8,
    /// How values wider than one register are laid out.
    #[serde(default)]
    pub word_order: WordOrder,
    /// How often the bindings are polled, in milliseconds.
    pub poll_interval_ms: u32,
    /// How long to wait for a response, in milliseconds.
    pub timeout_ms: u32,
    /// The registers and coils bound to variables.
    #[serde(default, rename = "binding", skip_serializing_if = "Vec::is_empty")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::small_vec()"))]
    pub bindings: Vec<ModbusBinding>,
}

/// Word order of 32- and 64-bit values spread over several 16-bit registers.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(rename_all = "snake_case")]
pub enum WordOrder {
    /// The most significant word comes first (the Modbus convention, "ABCD").
    #[default]
    HighFirst,
    /// The least significant word comes first ("CDAB").
    LowFirst,
}

/// One channel of a Modbus device bound to a variable.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(deny_unknown_fields)]
pub struct ModbusBinding {
    /// The variable's path, such as `GVL_Io.rPressure`.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::ident()"))]
    pub variable: String,
    /// Which table the channel lies in.
    pub table: ModbusTable,
    /// The zero-based address of the first coil or register.
    pub address: u16,
    /// How the registers are read.
    pub data_type: ModbusDataType,
    /// The comment shown in the I/O mapping.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::text()"))]
    pub comment: String,
}

/// The four Modbus data tables.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(rename_all = "snake_case")]
pub enum ModbusTable {
    /// Read-write bits (function codes 1, 5, 15).
    Coil,
    /// Read-only bits (function code 2).
    DiscreteInput,
    /// Read-write registers (function codes 3, 6, 16, 23).
    HoldingRegister,
    /// Read-only registers (function code 4).
    InputRegister,
}

/// How a channel's registers are decoded.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(rename_all = "snake_case")]
pub enum ModbusDataType {
    /// One coil or discrete input.
    Bool,
    /// One register as a signed 16-bit integer.
    Int16,
    /// One register as an unsigned 16-bit integer.
    Uint16,
    /// Two registers as a signed 32-bit integer.
    Int32,
    /// Two registers as an unsigned 32-bit integer.
    Uint32,
    /// Four registers as a signed 64-bit integer.
    Int64,
    /// Four registers as an unsigned 64-bit integer.
    Uint64,
    /// Two registers as an IEEE 754 single (REAL).
    Real,
    /// Four registers as an IEEE 754 double (LREAL).
    Lreal,
}

impl ModbusDataType {
    /// How many coils or registers a value of this type occupies.
    pub fn width(self) -> u16 {
        match self {
            Self::Bool | Self::Int16 | Self::Uint16 => 1,
            Self::Int32 | Self::Uint32 | Self::Real => 2,
            Self::Int64 | Self::Uint64 | Self::Lreal => 4,
        }
    }
}

impl ModbusDataType {
    /// Every data type, in the order editors offer them.
    pub const ALL: [Self; 9] = [
        Self::Bool,
        Self::Int16,
        Self::Uint16,
        Self::Int32,
        Self::Uint32,
        Self::Int64,
        Self::Uint64,
        Self::Real,
        Self::Lreal,
    ];

    /// The IEC elementary type a value of this type is read as: `BOOL`, `INT`, `UINT`, `DINT`,
    /// `UDINT`, `LINT`, `ULINT`, `REAL` or `LREAL`.
    pub fn iec_name(self) -> &'static str {
        match self {
            Self::Bool => "BOOL",
            Self::Int16 => "INT",
            Self::Uint16 => "UINT",
            Self::Int32 => "DINT",
            Self::Uint32 => "UDINT",
            Self::Int64 => "LINT",
            Self::Uint64 => "ULINT",
            Self::Real => "REAL",
            Self::Lreal => "LREAL",
        }
    }
}

impl ModbusTable {
    /// Every table, in the order editors offer them.
    pub const ALL: [Self; 4] = [
        Self::Coil,
        Self::DiscreteInput,
        Self::HoldingRegister,
        Self::InputRegister,
    ];

    /// Whether the table holds bits (coils and discrete inputs) rather than 16-bit registers.
    pub fn holds_bits(self) -> bool {
        matches!(self, Self::Coil | Self::DiscreteInput)
    }
}
