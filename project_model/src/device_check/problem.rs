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
        width: u32,
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
    /// An RTU device whose serial port is not chosen.
    #[error("the serial port is empty: choose one of the project's serial ports")]
    EmptySerialPort,
    /// An RTU device naming a serial port the project does not have.
    #[error("there is no serial port named '{0}': add it under the controller or choose another")]
    NoSuchSerialPort(String),
    /// An RTU device without an I/O task, which nothing would poll.
    #[error(
        "a Modbus RTU device needs an I/O task: the studio does not poll serial ports, the runtime does"
    )]
    RtuWithoutTask,
    /// An RTU device's unit id outside 1 to 247.
    #[error("unit id {0} cannot be used on a serial line: enter 1 to 247")]
    RtuUnitId(u8),
    /// A timeout above 60000 ms.
    #[error("the timeout is {0} ms; it is at most 60000 ms")]
    TimeoutTooLong(u32),
    /// A poll interval above one hour.
    #[error("the poll interval is {0} ms; it is at most 3600000 ms (one hour)")]
    PollIntervalTooLong(u32),
    /// No poll interval where the device needs one.
    #[error(
        "the poll interval is missing: every device needs one but a Modbus RTU device polled every cycle"
    )]
    MissingPollInterval,
    /// A read gap above 125.
    #[error("the maximum read gap is {0}; it is at most 125")]
    ReadGapTooLarge(u16),
    /// A channel of no value.
    #[error("channel {row} has a count of 0: bind at least 1 value")]
    ZeroCount {
        /// The channel's number, from 1.
        row: usize,
    },
    /// A channel larger than one request carries.
    #[error(
        "channel {row}: {count} values take {span} coils or registers, more than one request carries ({limit})"
    )]
    ChannelTooLong {
        /// The channel's number, from 1.
        row: usize,
        /// The channel's count.
        count: u16,
        /// The coils or registers the channel takes.
        span: u32,
        /// The most one request of its table and direction carries.
        limit: u32,
    },
    /// A write channel on a table that cannot be written.
    #[error(
        "channel {row} writes to the {} table, which is read-only: only coils and holding registers can be written",
        table_name(*table)
    )]
    WriteToReadOnlyTable {
        /// The channel's number, from 1.
        row: usize,
        /// The table.
        table: ModbusTable,
    },
    /// A function code on a read channel, whose code follows from its table.
    #[error(
        "channel {row} reads, so it takes no function code ({code}): a read uses its table's code"
    )]
    FunctionCodeOnRead {
        /// The channel's number, from 1.
        row: usize,
        /// The code given.
        code: u8,
    },
    /// A function code that cannot write the channel's table.
    #[error(
        "channel {row}: function code {code} cannot write the {} table; use 5 or 15 for coils, 6 or 16 for holding registers",
        table_name(*table)
    )]
    FunctionCodeMisfit {
        /// The channel's number, from 1.
        row: usize,
        /// The code given.
        code: u8,
        /// The channel's table.
        table: ModbusTable,
    },
    /// A single-write function code (5 or 6) on a channel of more than one coil or register.
    #[error(
        "channel {row}: function code {code} writes one coil or register, but the channel takes {span}; use 15 or 16"
    )]
    SingleWriteTooWide {
        /// The channel's number, from 1.
        row: usize,
        /// The code given.
        code: u8,
        /// The coils or registers the channel takes.
        span: u32,
    },
    /// A trigger variable on a cyclic channel.
    #[error(
        "channel {row} has a trigger variable but a cyclic trigger: choose the rising edge trigger or remove the variable"
    )]
    TriggerVariableWithoutEdge {
        /// The channel's number, from 1.
        row: usize,
    },
    /// A rising edge trigger without its variable.
    #[error(
        "channel {row} is triggered by a rising edge but has no trigger variable: enter the path of a BOOL"
    )]
    EdgeWithoutTriggerVariable {
        /// The channel's number, from 1.
        row: usize,
    },
    /// An error action on a write channel, which has no value to keep or zero.
    #[error(
        "channel {row} writes, so 'on error' does not apply: it chooses what a read channel's variable holds"
    )]
    OnErrorOnWrite {
        /// The channel's number, from 1.
        row: usize,
    },
    /// A serial port without a device file.
    #[error("the device file is empty: enter the port's device, such as /dev/ttyUSB0")]
    EmptyDevice,
    /// A baud rate the runtime does not offer.
    #[error(
        "{0} baud is not offered: choose 1200, 2400, 4800, 9600, 19200, 38400, 57600, 115200 or 230400"
    )]
    UnsupportedBaudRate(u32),
    /// Data bits other than 7 or 8.
    #[error("{0} data bits cannot be used: enter 8 (Modbus RTU sends 8 data bits)")]
    UnsupportedDataBits(u8),
    /// Stop bits other than 1 or 2.
    #[error("{0} stop bits cannot be used: enter 1 or 2")]
    UnsupportedStopBits(u8),
    /// An inter-frame delay above one second.
    #[error("the inter-frame delay is {0} µs; it is at most 1000000 µs (1 s)")]
    InterFrameDelayTooLong(u32),
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
