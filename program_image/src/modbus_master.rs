//! The Modbus master section (section 14, `docs/modbus-master.md` §5): the devices the runtime
//! masters over Modbus TCP and RTU, their channels and the serial ports they use.
//!
//! Plain data mirroring the project model, which this crate may not depend on: the compiler
//! builds a [`MasterSection`] from the project's devices that name an I/O task, the runtime
//! resolves its variable paths at load and plans each device's requests with [`plan`], and the
//! studio's device editor shows the same plan. The fields of every structure are in the order of
//! `docs/modbus-master.md` §5.1, which is their order on the wire (postcard): reordering them
//! changes the format.

mod codec;
mod error;
mod plan;
mod verify;

#[cfg(test)]
mod codec_tests;
#[cfg(test)]
mod plan_tests;

use serde::{Deserialize, Serialize};

use crate::{Elementary, ModbusTable};

pub use codec::{
    CodecError, bits_to_values, registers_to_values, values_to_bits, values_to_registers,
    words_per_value,
};
pub use error::{MasterPlace, MasterProblem, MasterSectionError};
pub use plan::{PlannedRequest, RequestChannel, plan};

/// The most coils or discrete inputs one read request asks for (function codes 1 and 2).
pub const READ_BITS_MAX: u32 = 2000;
/// The most registers one read request asks for (function codes 3 and 4).
pub const READ_REGISTERS_MAX: u32 = 125;
/// The most coils one write request carries (function code 15).
pub const WRITE_BITS_MAX: u32 = 1968;
/// The most registers one write request carries (function code 16).
pub const WRITE_REGISTERS_MAX: u32 = 123;
/// The most devices a section may hold.
pub const MAX_DEVICES: usize = 256;
/// The most channels one device may hold.
pub const MAX_CHANNELS_PER_DEVICE: usize = 1024;
/// The most serial ports a section may hold.
pub const MAX_SERIAL_PORTS: usize = 32;
/// The most unused addresses a read request may bridge (`max_read_gap`).
pub const MAX_READ_GAP: u16 = 125;
/// The longest response timeout in milliseconds.
pub const MAX_TIMEOUT_MS: u32 = 60_000;
/// The longest round interval of [`Schedule::Interval`] in milliseconds (one hour).
pub const MAX_INTERVAL_MS: u32 = 3_600_000;
/// The longest inter-frame delay of a serial port in microseconds (one second).
pub const MAX_INTER_FRAME_DELAY_US: u32 = 1_000_000;
/// The baud rates a serial port may use (`docs/modbus-master.md` §2.3).
pub const BAUD_RATES: [u32; 9] = [1200, 2400, 4800, 9600, 19200, 38400, 57600, 115200, 230400];
/// The shortest silence between two RTU frames, used above 19200 baud, in microseconds (the
/// Modbus serial line standard's fixed value for fast lines).
pub const MIN_SILENT_INTERVAL_US: u32 = 1750;

/// The section: serial ports and runtime devices. Present in an image only when the project
/// has a device with an I/O task; compared whole by an online change to decide whether the
/// master may go on through the switch.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct MasterSection {
    /// The serial ports the devices name, in manifest order; [`Link::Rtu`] indexes this list.
    pub serial_ports: Vec<SerialPortDef>,
    /// The runtime devices in manifest order: the order of `MODBUS_DEVICES` and of the RTU
    /// line's ties.
    pub devices: Vec<DeviceDef>,
}

/// A serial port and its line settings, as `[[serial_port]]` of `rivet.toml` gives them.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct SerialPortDef {
    /// The port's name in the project (`RS485`), which `rivet-runtime --serial-port NAME=PATH`
    /// names to replace its device file.
    pub name: String,
    /// The device file on the target, such as `/dev/ttyUSB0`.
    pub device: String,
    /// Bits per second, one of [`BAUD_RATES`].
    pub baud_rate: u32,
    /// The parity bit.
    pub parity: Parity,
    /// Data bits per character: 8 (Modbus RTU).
    pub data_bits: u8,
    /// Stop bits per character: 1 or 2.
    pub stop_bits: u8,
    /// The silence the master keeps before each request, in microseconds; 0 for the standard's
    /// 3.5 characters ([`SerialPortDef::silent_interval_us`]).
    pub inter_frame_delay_us: u32,
}

/// The parity of a serial line; on the wire its variant index, 0 none, 1 odd, 2 even.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Parity {
    /// No parity bit.
    None,
    /// Odd parity.
    Odd,
    /// Even parity (the Modbus serial line standard's default).
    Even,
}

/// One device the runtime masters.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct DeviceDef {
    /// The device's name in the project, in messages and in `MODBUS_DEVICES`.
    pub name: String,
    /// How the master reaches it.
    pub link: Link,
    /// The Modbus unit id (slave address): 1 to 247 on a serial line, any on TCP.
    pub unit_id: u8,
    /// The response timeout in milliseconds, 1 to [`MAX_TIMEOUT_MS`].
    pub timeout_ms: u32,
    /// The index of its I/O task in the image's task table.
    pub task: u32,
    /// When its rounds are due.
    pub schedule: Schedule,
    /// How values wider than one register are laid out.
    pub word_order: WordOrder,
    /// How many unused addresses a read request may bridge, 0 to [`MAX_READ_GAP`].
    pub max_read_gap: u16,
    /// The path of its `MODBUS_DEVICE_STATUS` variable, if the project names one.
    pub status: Option<String>,
    /// The channels in the project's order; messages number them from 1.
    pub channels: Vec<ChannelDef>,
}

/// How the master reaches a device.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Link {
    /// Modbus TCP, one connection of its own.
    Tcp {
        /// The host name or IP address.
        host: String,
        /// The TCP port.
        port: u16,
    },
    /// Modbus RTU on a serial port, shared with the port's other devices.
    Rtu {
        /// The index of the port in [`MasterSection::serial_ports`].
        serial_port: u32,
    },
}

/// When a device's rounds are due (`docs/modbus-master.md` §6.3).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Schedule {
    /// A round every `interval_ms` from the master's start.
    Interval {
        /// The round interval in milliseconds, 1 to [`MAX_INTERVAL_MS`].
        interval_ms: u32,
    },
    /// A round after each cycle of the I/O task.
    EveryCycle,
}

/// The order of the registers of a value wider than one register; on the wire its variant
/// index, 0 high first, 1 low first.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum WordOrder {
    /// The most significant word first ("ABCD", the Modbus convention).
    HighFirst,
    /// The least significant word first ("CDAB").
    LowFirst,
}

/// One channel: consecutive values of a device bound to a variable (a `binding` of the project).
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct ChannelDef {
    /// The bound variable's path, resolved by the runtime at load.
    pub variable: String,
    /// The Modbus table.
    pub table: ModbusTable,
    /// The zero-based address of the first coil or register.
    pub address: u16,
    /// The type of each value: BOOL in a bit table; INT, UINT, DINT, UDINT, LINT, ULINT, REAL
    /// or LREAL in a register table. On the wire its tag (`docs/program-image.md` §4).
    pub value_type: Elementary,
    /// How many consecutive values (at least 1); more than 1 binds an array.
    pub count: u16,
    /// Read from the device or written to it.
    pub direction: Direction,
    /// The function code of its requests: 1, 2, 3 or 4 for a read; 5, 6, 15 or 16 for a write.
    pub function_code: u8,
    /// When it is sent or read.
    pub trigger: Trigger,
    /// What a read channel's variable holds after its request failed.
    pub on_error: OnError,
    /// The path of a BOOL that is TRUE while the channel's last request failed.
    pub error_flag: Option<String>,
}

/// The direction of a channel; on the wire its variant index, 0 read, 1 write.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Direction {
    /// From the device into the variable.
    Read,
    /// From the variable to the device.
    Write,
}

/// When a channel is transferred.
#[derive(Clone, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Trigger {
    /// In every round.
    Cyclic,
    /// Once per rising edge of a BOOL.
    RisingEdge {
        /// The BOOL's path.
        variable: String,
    },
}

/// What a read channel's variable holds after its request failed; on the wire its variant
/// index, 0 keep last value, 1 set to zero.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum OnError {
    /// The value of the last request that succeeded.
    KeepLastValue,
    /// Zero bytes: FALSE, 0, 0.0.
    SetToZero,
}

impl SerialPortDef {
    /// The silence before each request in microseconds: [`SerialPortDef::inter_frame_delay_us`],
    /// or for 0 the standard's 3.5 characters of 11 bits at the port's baud rate.
    pub fn silent_interval_us(&self) -> u32 {
        if self.inter_frame_delay_us == 0 {
            silent_interval_us(self.baud_rate)
        } else {
            self.inter_frame_delay_us
        }
    }
}

/// 3.5 characters of 11 bits at `baud_rate`, rounded up to whole microseconds, up to 19200
/// baud; [`MIN_SILENT_INTERVAL_US`] above (4011 µs at 9600, 2006 µs at 19200).
/// A baud rate of 0, which no verified port has, gives the longest delay accepted.
pub fn silent_interval_us(baud_rate: u32) -> u32 {
    if baud_rate > 19200 {
        return MIN_SILENT_INTERVAL_US;
    }
    // 3.5 × 11 bits = 38.5 bits, so the delay is 38,500,000 / baud µs.
    38_500_000u32
        .checked_add(baud_rate.saturating_sub(1))
        .and_then(|bits| bits.checked_div(baud_rate))
        .unwrap_or(MAX_INTER_FRAME_DELAY_US)
}

impl ChannelDef {
    /// Coils or registers one value takes: 1 in a bit table; 1, 2 or 4 registers by its type
    /// (1 for a type no register table holds, which verification refuses).
    pub fn width(&self) -> u32 {
        if table_holds_bits(self.table) {
            1
        } else {
            words_per_value(self.value_type).unwrap_or(1)
        }
    }

    /// Coils or registers the whole channel takes: `count × width`.
    pub fn span(&self) -> u32 {
        u32::from(self.count) * self.width()
    }

    /// Bytes its values take in the program's memory (a BOOL takes one byte).
    pub fn value_bytes(&self) -> u32 {
        u32::from(self.count) * self.value_type.size_bytes()
    }
}

/// Whether `table` holds bits (coils and discrete inputs) rather than registers.
pub fn table_holds_bits(table: ModbusTable) -> bool {
    matches!(table, ModbusTable::Coils | ModbusTable::DiscreteInputs)
}

/// The most coils or registers one request of `direction` on `table` may carry (the Modbus
/// limits: 2000 bits or 125 registers read, 1968 bits or 123 registers written).
pub fn request_limit(direction: Direction, table: ModbusTable) -> u32 {
    match (direction, table_holds_bits(table)) {
        (Direction::Read, true) => READ_BITS_MAX,
        (Direction::Read, false) => READ_REGISTERS_MAX,
        (Direction::Write, true) => WRITE_BITS_MAX,
        (Direction::Write, false) => WRITE_REGISTERS_MAX,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_default_silence_is_three_and_a_half_characters_up_to_19200_baud() {
        assert_eq!(silent_interval_us(9600), 4011);
        assert_eq!(silent_interval_us(19200), 2006);
        assert_eq!(silent_interval_us(1200), 32084);
        assert_eq!(silent_interval_us(38400), MIN_SILENT_INTERVAL_US);
        assert_eq!(silent_interval_us(0), MAX_INTER_FRAME_DELAY_US);
        let mut port = SerialPortDef {
            name: "RS485".to_owned(),
            device: "/dev/ttyS1".to_owned(),
            baud_rate: 9600,
            parity: Parity::Even,
            data_bits: 8,
            stop_bits: 1,
            inter_frame_delay_us: 0,
        };
        assert_eq!(port.silent_interval_us(), 4011);
        // A Delta DVP-15MC wants 5 ms, whatever the baud rate.
        port.inter_frame_delay_us = 5000;
        assert_eq!(port.silent_interval_us(), 5000);
    }

    #[test]
    fn a_channel_takes_count_times_its_width_and_its_values_bytes() {
        let mut channel = ChannelDef {
            variable: "GVL.arValues".to_owned(),
            table: ModbusTable::HoldingRegisters,
            address: 0,
            value_type: Elementary::Lreal,
            count: 3,
            direction: Direction::Read,
            function_code: 3,
            trigger: Trigger::Cyclic,
            on_error: OnError::KeepLastValue,
            error_flag: None,
        };
        assert_eq!(
            (channel.width(), channel.span(), channel.value_bytes()),
            (4, 12, 24)
        );
        channel.value_type = Elementary::Uint;
        assert_eq!(
            (channel.width(), channel.span(), channel.value_bytes()),
            (1, 3, 6)
        );
        channel.table = ModbusTable::Coils;
        channel.value_type = Elementary::Bool;
        assert_eq!(
            (channel.width(), channel.span(), channel.value_bytes()),
            (1, 3, 3)
        );
        assert_eq!(request_limit(Direction::Write, ModbusTable::Coils), 1968);
        assert_eq!(
            request_limit(Direction::Read, ModbusTable::InputRegisters),
            125
        );
    }
}
