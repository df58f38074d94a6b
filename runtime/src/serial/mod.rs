//! Serial ports for Modbus RTU: the line settings (baud rate, data bits, parity, stop bits) with
//! the timing they imply, and opening a port by its path as a tokio stream.
//!
//! The runtime's RTU slave (`rivet-runtime --modbus-rtu`, `docs/modbus-master.md` §7) and its
//! Modbus master's serial lines (§6.9) both open their ports here, so the two agree on what a
//! setting means.

mod open;
mod settings;

pub use open::{SerialOpenError, open_port};
pub use settings::{BAUD_RATES, Parity, SerialSettings, SerialSettingsError, StopBits, silence_us};
