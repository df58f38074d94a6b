//! Why a setting of the device tree cannot be stored as it is.

use thiserror::Error;

use crate::{IoDirection, ModbusDataType, ModbusTable};

/// One problem of a device tree node's settings; its text names the field and says what is
/// expected.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum DeviceProblem {
    /// A name that is not an identifier.
    #[error(
        "the {kind} name '{name}' is not an identifier: use letters, digits and '_', starting with a letter or '_'"
    )]
    InvalidName {
        /// What is named: `controller`, `I/O area`, `Modbus device` or `axis`.
        kind: &'static str,
        /// The name.
        name: String,
    },
    /// A name another node of the same list has.
    #[error("the name '{name}' is already used by another {kind}")]
    DuplicateName {
        /// What is named.
        kind: &'static str,
        /// The name.
        name: String,
    },
    /// An empty host.
    #[error("the host is empty: enter a host name or an IP address")]
    EmptyHost,
    /// Port 0, which no server listens on.
    #[error("port 0 cannot be used: enter a port from 1 to 65535")]
    ZeroPort,
    /// A Modbus map range without an address in the located areas.
    #[error("range {row} of the Modbus map has no located address: enter one such as %MW0")]
    EmptyRangeAddress {
        /// The range's number, from 1.
        row: usize,
    },
    /// A Modbus map range of no coil or register.
    #[error("range {row} of the Modbus map has a count of 0: map at least 1")]
    EmptyRange {
        /// The range's number, from 1.
        row: usize,
    },
    /// A Modbus map range past the last Modbus address.
    #[error("range {row} of the Modbus map runs from {start} for {count} and passes address 65535")]
    RangePastEnd {
        /// The range's number, from 1.
        row: usize,
        /// The first address.
        start: u16,
        /// The number of coils or registers.
        count: u16,
    },
    /// Two Modbus map ranges of the same table sharing addresses.
    #[error("range {row} of the Modbus map overlaps range {other} of the same table")]
    RangesOverlap {
        /// The range's number, from 1.
        row: usize,
        /// The other range's number, from 1.
        other: usize,
    },
    /// An I/O area of no byte.
    #[error("the size of an I/O area is at least 1 byte")]
    ZeroSize,
    /// An I/O area past the end of its located area.
    #[error(
        "start byte {start_byte} with a size of {size_bytes} bytes passes the end of the area ({limit} bytes)"
    )]
    AreaPastEnd {
        /// The first byte.
        start_byte: u32,
        /// The size in bytes.
        size_bytes: u32,
        /// The size of the located area.
        limit: u32,
    },
    /// Two I/O areas of the same direction sharing bytes.
    #[error("{} the I/O area '{other}'", overlapping_bytes(*direction, *first, *last))]
    AreasOverlap {
        /// The direction both areas have.
        direction: IoDirection,
        /// The first shared byte.
        first: u32,
        /// The last shared byte.
        last: u32,
        /// The other area's name.
        other: String,
    },
    /// A poll interval of 0 ms.
    #[error("the poll interval is at least 1 ms")]
    ZeroPollInterval,
    /// A timeout of 0 ms.
    #[error("the timeout is at least 1 ms")]
    ZeroTimeout,
    /// A channel without a variable.
    #[error("channel {row} has no variable: enter its path, such as GVL_IO.rSpeed")]
    EmptyVariable {
        /// The channel's number, from 1.
        row: usize,
    },
    /// A channel whose variable is not a path of identifiers.
    #[error("channel {row}: '{variable}' is not a variable path such as GVL_IO.rSpeed")]
    InvalidVariable {
        /// The channel's number, from 1.
        row: usize,
        /// The text given.
        variable: String,
    },
    /// A channel past the last Modbus address.
    #[error("channel {row} at address {address} takes {width} and passes address 65535")]
    ChannelPastEnd {
        /// The channel's number, from 1.
        row: usize,
        /// Its first address.
        address: u16,
        /// How many coils or registers it takes.
        width: u16,
    },
    /// Two channels of the same table sharing addresses.
    #[error(
        "channel {row} ({variable}) overlaps channel {other} ({other_variable}) in the same table"
    )]
    ChannelsOverlap {
        /// The channel's number, from 1.
        row: usize,
        /// Its variable.
        variable: String,
        /// The other channel's number, from 1.
        other: usize,
        /// The other channel's variable.
        other_variable: String,
    },
    /// A data type the channel's table cannot hold.
    #[error(
        "channel {row}: a {} cannot hold {}; coils and discrete inputs hold BOOL, registers every other type",
        table_name(*table),
        type_name(*data_type)
    )]
    TableTypeMismatch {
        /// The channel's number, from 1.
        row: usize,
        /// The table.
        table: ModbusTable,
        /// The data type.
        data_type: ModbusDataType,
    },
    /// An axis updated by a task that does not exist.
    #[error("there is no task named '{0}' to update the axis")]
    NoSuchTask(String),
    /// An axis without a unit.
    #[error("the unit is empty: enter one such as mm or deg")]
    EmptyUnit,
    /// A number that is not finite.
    #[error("the {field} is not a finite number")]
    NotFinite {
        /// The field.
        field: &'static str,
    },
    /// A modulo period of zero or less.
    #[error("the modulo period is {0}; it must be greater than 0")]
    ModuloNotPositive(f64),
    /// Enabled software limits whose minimum is not below their maximum.
    #[error("the negative software limit {min} must be below the positive limit {max}")]
    LimitsInverted {
        /// The negative limit.
        min: f64,
        /// The positive limit.
        max: f64,
    },
    /// A velocity, acceleration, deceleration or jerk limit of zero or less.
    #[error("the {field} limit is {value}; it must be greater than 0")]
    DynamicLimitNotPositive {
        /// Which limit.
        field: &'static str,
        /// The value given.
        value: f64,
    },
    /// A scaling numerator or denominator of zero.
    #[error("the scaling {field} is 0: increments per unit would be undefined")]
    ZeroScaling {
        /// `numerator` or `denominator`.
        field: &'static str,
    },
}

/// The table's name in a sentence, for [`DeviceProblem::TableTypeMismatch`].
fn table_name(table: ModbusTable) -> &'static str {
    match table {
        ModbusTable::Coil => "coil",
        ModbusTable::DiscreteInput => "discrete input",
        ModbusTable::HoldingRegister => "holding register",
        ModbusTable::InputRegister => "input register",
    }
}

/// The IEC name of the type a channel decodes to, for [`DeviceProblem::TableTypeMismatch`].
fn type_name(data_type: ModbusDataType) -> &'static str {
    data_type.iec_name()
}

/// The shared bytes of [`DeviceProblem::AreasOverlap`] with their verb: `byte %QB1 overlaps`,
/// `bytes %QB1 to %QB3 overlap`.
fn overlapping_bytes(direction: IoDirection, first: u32, last: u32) -> String {
    let letter = direction.area_letter();
    if first == last {
        format!("byte %{letter}B{first} overlaps")
    } else {
        format!("bytes %{letter}B{first} to %{letter}B{last} overlap")
    }
}
