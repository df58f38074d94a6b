//! Third-party Modbus devices: polled by the studio, or mastered by the runtime over TCP and RTU.

use serde::{Deserialize, Serialize};

use crate::modbus_device_file::ModbusDeviceFile;

/// A Modbus server (an I/O block, a drive, another PLC) whose registers variables bind to: over
/// TCP, or as a unit on a serial line (Modbus RTU).
///
/// Without a `task` it is a studio device: the studio polls it (TCP only) so its values can be
/// monitored, written, forced and traced without downloading anything. With a `task` the runtime
/// masters it in that task's cycles (`docs/modbus-master.md`). Saved in the manifest as
/// `[[modbus_device]]`, whose link keys are flat (`host` and `port`, or `serial_port`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(try_from = "ModbusDeviceFile", into = "ModbusDeviceFile")]
pub struct ModbusDevice {
    /// The device's name in the device tree.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::ident()"))]
    pub name: String,
    /// How the device is reached: a TCP host and port, or a serial port.
    pub link: ModbusLink,
    /// The Modbus unit identifier (1 to 247 on a serial line).
    pub unit_id: u8,
    /// How values wider than one register are laid out.
    pub word_order: WordOrder,
    /// How often a round is due, in milliseconds: the runtime's interval with
    /// [`ModbusSchedule::Interval`], and the studio's own poll interval of a TCP device; `None`
    /// only where the device needs none (an RTU device polled every cycle).
    pub poll_interval_ms: Option<u32>,
    /// How long to wait for a response, in milliseconds.
    pub timeout_ms: u32,
    /// The I/O task whose cycles copy the device's values; `None` for a studio device.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::opt_ident()"))]
    pub task: Option<String>,
    /// When the runtime starts a round (only for a runtime device).
    pub schedule: ModbusSchedule,
    /// How many unused addresses a read request may bridge to serve two channels at once.
    pub max_read_gap: u16,
    /// The path of the `MODBUS_DEVICE_STATUS` variable the runtime fills, if any.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::opt_ident()"))]
    pub status: Option<String>,
    /// The registers and coils bound to variables.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::small_vec()"))]
    pub bindings: Vec<ModbusBinding>,
}

/// How a Modbus device is reached.
#[derive(Clone, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
pub enum ModbusLink {
    /// Modbus TCP: a connection to `host` on `port`.
    Tcp {
        /// Host name or IP address.
        #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::ident()"))]
        host: String,
        /// TCP port, 502 by default.
        port: u16,
    },
    /// Modbus RTU: a unit on the project's serial port of that name (`[[serial_port]]`).
    Rtu {
        /// The serial port's name.
        #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::ident()"))]
        serial_port: String,
    },
}

/// When the runtime starts a round of a device it masters.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(rename_all = "snake_case")]
pub enum ModbusSchedule {
    /// A round every `poll_interval_ms`.
    #[default]
    Interval,
    /// A round after each cycle of the I/O task.
    EveryCycle,
}

impl ModbusSchedule {
    /// Whether this is the default, which the manifest leaves out.
    pub fn is_default(&self) -> bool {
        *self == Self::default()
    }
}

impl ModbusDevice {
    /// The poll interval a new device gets, and the one the studio uses for a TCP device that
    /// has none (a problem the device checks report), in milliseconds.
    pub const DEFAULT_POLL_INTERVAL_MS: u32 = 100;

    /// A studio device over TCP at `host` and `port`: unit 1, high word first, polled every
    /// 100 ms with a 500 ms timeout, no channel.
    pub fn tcp(name: impl Into<String>, host: impl Into<String>, port: u16) -> Self {
        Self {
            name: name.into(),
            link: ModbusLink::Tcp {
                host: host.into(),
                port,
            },
            unit_id: 1,
            word_order: WordOrder::HighFirst,
            poll_interval_ms: Some(Self::DEFAULT_POLL_INTERVAL_MS),
            timeout_ms: 500,
            task: None,
            schedule: ModbusSchedule::Interval,
            max_read_gap: 0,
            status: None,
            bindings: Vec::new(),
        }
    }

    /// How often the studio polls the device, in milliseconds: its poll interval, or
    /// [`Self::DEFAULT_POLL_INTERVAL_MS`] when it has none.
    pub fn studio_poll_interval_ms(&self) -> u32 {
        self.poll_interval_ms
            .unwrap_or(Self::DEFAULT_POLL_INTERVAL_MS)
    }

    /// Whether the runtime masters the device (it names an I/O task).
    pub fn is_runtime_device(&self) -> bool {
        self.task.is_some()
    }

    /// The serial port an RTU device is on; `None` for a TCP device.
    pub fn serial_port(&self) -> Option<&str> {
        match &self.link {
            ModbusLink::Tcp { .. } => None,
            ModbusLink::Rtu { serial_port } => Some(serial_port),
        }
    }

    /// Whether §2.1 of `docs/modbus-master.md` asks for a poll interval: every device but an RTU
    /// device polled every cycle.
    pub fn needs_poll_interval(&self) -> bool {
        !(matches!(self.link, ModbusLink::Rtu { .. })
            && self.schedule == ModbusSchedule::EveryCycle)
    }
}

impl std::fmt::Display for ModbusLink {
    /// Formats as `host:port` or as the serial port's name, as the device tree shows the link.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Tcp { host, port } => write!(f, "{host}:{port}"),
            Self::Rtu { serial_port } => f.write_str(serial_port),
        }
    }
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

/// One channel of a Modbus device bound to a variable: `count` values of `data_type` at
/// consecutive addresses, read from the device or written to it.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(deny_unknown_fields)]
pub struct ModbusBinding {
    /// The variable's path, such as `GVL_Io.rPressure` (an array of `count` elements when
    /// `count` is above 1).
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::ident()"))]
    pub variable: String,
    /// Which table the channel lies in.
    pub table: ModbusTable,
    /// The zero-based address of the first coil or register.
    pub address: u16,
    /// How the registers are read.
    pub data_type: ModbusDataType,
    /// How many consecutive values the channel holds; 1 binds a plain variable.
    #[serde(default = "one", skip_serializing_if = "is_one")]
    pub count: u16,
    /// Whether the channel is read from the device or written to it.
    #[serde(default, skip_serializing_if = "ChannelDirection::is_default")]
    pub direction: ChannelDirection,
    /// The function code a write channel asks for (5, 6, 15 or 16); `None` for the multiple
    /// write of its table, or for a read, whose code follows from its table.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub function_code: Option<u8>,
    /// When the channel is sent or read: in every round, or on a rising edge.
    #[serde(default, skip_serializing_if = "ChannelTrigger::is_default")]
    pub trigger: ChannelTrigger,
    /// The BOOL whose rising edge triggers a [`ChannelTrigger::RisingEdge`] channel.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::opt_ident()"))]
    pub trigger_variable: Option<String>,
    /// What a read channel's variable holds after its request failed.
    #[serde(default, skip_serializing_if = "ChannelErrorAction::is_default")]
    pub on_error: ChannelErrorAction,
    /// The path of a BOOL that is TRUE while the channel's last request failed.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::opt_ident()"))]
    pub error_flag: Option<String>,
    /// The comment shown in the I/O mapping.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::text()"))]
    pub comment: String,
}

/// Whether a channel is read from the device or written to it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(rename_all = "snake_case")]
pub enum ChannelDirection {
    /// The device's values are copied into the variable.
    #[default]
    Read,
    /// The variable's value is sent to the device.
    Write,
}

/// When a channel is sent or read.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(rename_all = "snake_case")]
pub enum ChannelTrigger {
    /// In every round.
    #[default]
    Cyclic,
    /// Once per rising edge of the channel's `trigger_variable`.
    RisingEdge,
}

/// What a read channel's variable holds after its request failed.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(rename_all = "snake_case")]
pub enum ChannelErrorAction {
    /// Its last value.
    #[default]
    KeepLastValue,
    /// Zero: FALSE, 0 or 0.0 in every element.
    SetToZero,
}

impl ChannelDirection {
    /// Whether this is the default, which the manifest leaves out.
    pub fn is_default(&self) -> bool {
        *self == Self::default()
    }
}

impl ChannelTrigger {
    /// Whether this is the default, which the manifest leaves out.
    pub fn is_default(&self) -> bool {
        *self == Self::default()
    }
}

impl ChannelErrorAction {
    /// Whether this is the default, which the manifest leaves out.
    pub fn is_default(&self) -> bool {
        *self == Self::default()
    }
}

impl ModbusBinding {
    /// A channel reading one value of `data_type` at `address` of `table` in every round, with
    /// no comment: what a studio device's channel is.
    pub fn new(
        variable: impl Into<String>,
        table: ModbusTable,
        address: u16,
        data_type: ModbusDataType,
    ) -> Self {
        Self {
            variable: variable.into(),
            table,
            address,
            data_type,
            count: 1,
            direction: ChannelDirection::Read,
            function_code: None,
            trigger: ChannelTrigger::Cyclic,
            trigger_variable: None,
            on_error: ChannelErrorAction::KeepLastValue,
            error_flag: None,
            comment: String::new(),
        }
    }

    /// How many coils or registers one value takes: one bit in a bit table, else its type's
    /// registers.
    pub fn value_width(&self) -> u16 {
        if self.table.holds_bits() {
            1
        } else {
            self.data_type.width()
        }
    }

    /// How many coils or registers the whole channel takes: `count` values.
    pub fn span(&self) -> u32 {
        u32::from(self.count) * u32::from(self.value_width())
    }

    /// The function code the channel uses when it names none (`docs/modbus-master.md` §2.2):
    /// a read uses its table's (1 coils, 2 discrete inputs, 3 holding registers, 4 input
    /// registers), a write the multiple write of its kind of value (15 for bits, 16 for
    /// registers). A write to a read-only table gets one too; the device checks refuse it.
    pub fn default_function_code(&self) -> u8 {
        match (self.direction, self.table) {
            (ChannelDirection::Read, ModbusTable::Coil) => 1,
            (ChannelDirection::Read, ModbusTable::DiscreteInput) => 2,
            (ChannelDirection::Read, ModbusTable::HoldingRegister) => 3,
            (ChannelDirection::Read, ModbusTable::InputRegister) => 4,
            (ChannelDirection::Write, table) if table.holds_bits() => 15,
            (ChannelDirection::Write, _) => 16,
        }
    }
}

/// The default `count` of a channel.
fn one() -> u16 {
    1
}

/// Whether a channel's `count` is the default, which the manifest leaves out.
fn is_one(count: &u16) -> bool {
    *count == 1
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

    /// The type as `rivet.toml` spells it (`int16`), which the build's messages use.
    pub fn file_name(self) -> &'static str {
        match self {
            Self::Bool => "bool",
            Self::Int16 => "int16",
            Self::Uint16 => "uint16",
            Self::Int32 => "int32",
            Self::Uint32 => "uint32",
            Self::Int64 => "int64",
            Self::Uint64 => "uint64",
            Self::Real => "real",
            Self::Lreal => "lreal",
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_data_type_s_file_name_is_how_the_manifest_spells_it() {
        for data_type in ModbusDataType::ALL {
            let written = toml::Value::try_from(data_type).unwrap();
            assert_eq!(written.as_str(), Some(data_type.file_name()));
        }
    }

    #[test]
    fn a_channel_without_a_function_code_reads_by_its_table_and_writes_many() {
        let code = |table, direction| {
            let mut binding = ModbusBinding::new("x", table, 0, ModbusDataType::Int16);
            binding.direction = direction;
            binding.default_function_code()
        };
        let read = ChannelDirection::Read;
        let write = ChannelDirection::Write;
        assert_eq!(code(ModbusTable::Coil, read), 1);
        assert_eq!(code(ModbusTable::DiscreteInput, read), 2);
        assert_eq!(code(ModbusTable::HoldingRegister, read), 3);
        assert_eq!(code(ModbusTable::InputRegister, read), 4);
        assert_eq!(code(ModbusTable::Coil, write), 15);
        assert_eq!(code(ModbusTable::HoldingRegister, write), 16);
    }
}
