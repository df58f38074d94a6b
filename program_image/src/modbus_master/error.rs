//! Why a Modbus master section is refused at load: the place (serial port, device, channel),
//! the field, and what was expected (`docs/modbus-master.md` §5.2).

use std::fmt;

use crate::{Elementary, ModbusTable};

use super::Direction;

/// A refusal of the section, naming the device, the channel's number and the field.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{place}, field {field}: {problem}")]
pub struct MasterSectionError {
    /// Where the problem lies.
    pub place: MasterPlace,
    /// The field of [`crate::modbus_master`]'s structures that holds the wrong value, by its
    /// name in `docs/modbus-master.md` §5.1 (`function_code`, `link.host`).
    pub field: &'static str,
    /// What is wrong.
    pub problem: MasterProblem,
}

/// A place in the section.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum MasterPlace {
    /// The section as a whole.
    Section,
    /// A serial port.
    SerialPort {
        /// Its index in the section (0-based).
        index: usize,
        /// Its name.
        name: String,
    },
    /// A device.
    Device {
        /// Its name.
        name: String,
    },
    /// A channel of a device.
    Channel {
        /// The device's name.
        device: String,
        /// The channel's number, counted from 1 as the project's editors count.
        number: usize,
        /// The channel's variable path.
        variable: String,
    },
}

/// What is wrong with a field.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum MasterProblem {
    /// A list is longer than the runtime accepts.
    #[error("{count} entries, at most {max} are accepted")]
    TooMany {
        /// The entries in the image.
        count: usize,
        /// The most accepted.
        max: usize,
    },
    /// An index names nothing.
    #[error("index {index}, but the image has {count} {of}")]
    IndexOutOfRange {
        /// The index in the image.
        index: u32,
        /// How many there are.
        count: usize,
        /// What it indexes, in the plural: `tasks`, `serial ports`.
        of: &'static str,
    },
    /// A text that must say something is empty.
    #[error("it is empty, expected {expected}")]
    Empty {
        /// What it should hold.
        expected: &'static str,
    },
    /// Another entry already has this name.
    #[error("'{name}' is also the name of {other}")]
    NameTaken {
        /// The name.
        name: String,
        /// The entry that has it first.
        other: String,
    },
    /// A number outside its range.
    #[error("{value} is outside {min} to {max}")]
    OutOfRange {
        /// The number in the image.
        value: u64,
        /// The smallest accepted.
        min: u64,
        /// The largest accepted.
        max: u64,
    },
    /// A number that is not one of those accepted.
    #[error("{value} is not accepted, expected {allowed}")]
    NotAllowed {
        /// The number in the image.
        value: u64,
        /// The values accepted, in words.
        allowed: &'static str,
    },
    /// A type the channel's table cannot hold.
    #[error(
        "{} cannot hold {}; coils and discrete inputs hold BOOL, registers INT, UINT, DINT, UDINT, LINT, ULINT, REAL or LREAL",
        a_table(*.table),
        .value_type.name()
    )]
    TypeNotInTable {
        /// The channel's table.
        table: ModbusTable,
        /// The channel's type.
        value_type: Elementary,
    },
    /// A function code that does not fit the table and direction.
    #[error(
        "function code {code} does not {} {}: expected {}",
        verb(*.direction),
        a_table(*.table),
        expected_codes(*.direction, *.table)
    )]
    FunctionCode {
        /// The code in the image.
        code: u8,
        /// The channel's table.
        table: ModbusTable,
        /// The channel's direction.
        direction: Direction,
    },
    /// A single-write code on a channel of more than one coil or register.
    #[error(
        "function code {code} writes one coil or register, but the channel takes {span}: use {}",
        if *.code == 5 { 15 } else { 16 }
    )]
    SingleWriteOfMany {
        /// The code, 5 or 6.
        code: u8,
        /// The coils or registers the channel takes.
        span: u32,
    },
    /// A channel larger than one request.
    #[error("the channel takes {span} coils or registers, but one request may {} at most {max}", verb(*.direction))]
    LargerThanRequest {
        /// The coils or registers the channel takes.
        span: u32,
        /// The channel's direction.
        direction: Direction,
        /// The most one request carries.
        max: u32,
    },
    /// A channel beyond the last address.
    #[error(
        "the channel at address {address} takes {span} coils or registers and passes address 65535"
    )]
    PastLastAddress {
        /// The channel's first address.
        address: u16,
        /// The coils or registers it takes.
        span: u32,
    },
    /// `on_error` set to zero on a write channel, whose variable the master never writes.
    #[error(
        "set to zero (1) applies to a read channel's variable after a failed request; the master never writes a write channel's variable: expected keep last value (0)"
    )]
    SetToZeroOnWrite,
    /// Two channels of one table share addresses.
    #[error("the channel overlaps channel {other} ({other_variable}) in the same table")]
    Overlap {
        /// The earlier channel's number, counted from 1.
        other: usize,
        /// The earlier channel's variable path.
        other_variable: String,
    },
}

impl fmt::Display for MasterPlace {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Section => write!(f, "the Modbus master section"),
            Self::SerialPort { index, name } => write!(f, "serial port {index} ('{name}')"),
            Self::Device { name } => write!(f, "Modbus device '{name}'"),
            Self::Channel {
                device,
                number,
                variable,
            } => write!(f, "Modbus device '{device}', channel {number} ({variable})"),
        }
    }
}

/// The table's name with its article, for messages: `a coil`, `an input register`.
fn a_table(table: ModbusTable) -> &'static str {
    match table {
        ModbusTable::Coils => "a coil",
        ModbusTable::DiscreteInputs => "a discrete input",
        ModbusTable::InputRegisters => "an input register",
        ModbusTable::HoldingRegisters => "a holding register",
    }
}

/// What a request of `direction` does, as a verb.
fn verb(direction: Direction) -> &'static str {
    match direction {
        Direction::Read => "read",
        Direction::Write => "write",
    }
}

/// The function codes a channel of `direction` on `table` may use, in words.
fn expected_codes(direction: Direction, table: ModbusTable) -> &'static str {
    match (direction, table) {
        (Direction::Read, ModbusTable::Coils) => "1",
        (Direction::Read, ModbusTable::DiscreteInputs) => "2",
        (Direction::Read, ModbusTable::HoldingRegisters) => "3",
        (Direction::Read, ModbusTable::InputRegisters) => "4",
        (Direction::Write, ModbusTable::Coils) => "5 or 15",
        (Direction::Write, ModbusTable::HoldingRegisters) => "6 or 16",
        (Direction::Write, _) => "none: discrete inputs and input registers cannot be written",
    }
}
