//! The Modbus TCP server of the soft PLC, and its RTU slave on a serial port.
//!
//! Clients reach the located areas through the standard function codes 1, 2, 3, 4, 5, 6, 15, 16
//! and 23, with addresses translated by a [`ModbusMap`]; the default map and the exceptions are
//! specified in `docs/modbus-map.md`. Other function codes go to a hook in [`ServerOptions`],
//! where Rivet's online services will live.
//!
//! [`handle_pdu`] serves one request without sockets (the fuzz target calls it); [`serve`] runs
//! the TCP server with its own small MBAP framing, so that a malformed frame is answered with an
//! exception or closes its connection and nothing else. [`rtu_slave`] serves the same map on a
//! serial port as a Modbus RTU slave (`docs/modbus-master.md` §7).

mod backoff;
mod connections;
mod exception;
mod frame;
mod map;
mod map_slot;
pub mod master;
mod pdu;
pub mod rtu_slave;
mod server;
mod write_policy;

pub use backoff::Backoff;
pub use exception::ExceptionCode;
pub use frame::{FrameError, HEADER_BYTES, MbapHeader};
pub use map::{BitLocation, MapError, MapRange, ModbusMap, RegisterLocation, Table, WordOrder};
pub use map_slot::MapSlot;
pub use pdu::{
    MAX_PDU_BYTES, MAX_READ_BITS, MAX_READ_REGISTERS, MAX_READ_WRITE_REGISTERS, MAX_WRITE_BITS,
    MAX_WRITE_REGISTERS, handle_pdu, is_standard_function, serve_pdu,
};
pub use server::{
    ConnectionClosed, CustomFunctions, DEFAULT_FRAME_TIMEOUT, DEFAULT_IDLE_TIMEOUT, ServerOptions,
    current_connection, current_peer, delay_answer, serve,
};
pub use write_policy::{
    REFUSED_WRITE, WritableRange, WritableTable, WritePolicy, WritePolicyError,
};
