//! `rivet-runtime` as a Modbus RTU slave on a serial port (`docs/modbus-master.md` §7): the
//! same map, answers and write policy as the TCP server (`docs/modbus-map.md`), framed by our
//! own code rather than tokio-modbus's RTU server, whose request decoder panics on some
//! malformed frames.
//!
//! [`RtuFrameReader`] cuts the port's bytes into frames, [`serve_rtu`] answers them over any
//! byte stream, [`serve_rtu_port`] keeps a serial port open by its path, and
//! [`DamagedFrameReports`] says how often damaged frames are worth a line on standard error.

mod counters;
mod damage_reports;
mod frame;
mod port;
mod serve;

pub use counters::{RtuSlaveCounters, RtuSlaveCounts};
pub use damage_reports::{DAMAGED_FRAMES_REPORT_INTERVAL, DamagedFrameReports};
pub use frame::{
    DroppedFrame, INCOMPLETE_FRAME_PATIENCE, MAX_RTU_FRAME_BYTES, RtuFrame, RtuFrameReader, crc16,
    rtu_frame,
};
pub use port::{RtuPortEvent, serve_rtu_port};
pub use serve::{RtuSlaveOptions, serve_rtu};
