//! Answering the frames of one open serial port.

use std::io;
use std::sync::Mutex;
use std::time::Duration;

use tokio::io::{AsyncRead, AsyncWrite, AsyncWriteExt};

use crate::areas::LocatedAreas;
use crate::modbus::map_slot::MapSlot;
use crate::modbus::pdu::serve_pdu;
use crate::modbus::rtu_slave::counters::RtuSlaveCounters;
use crate::modbus::rtu_slave::frame::{RtuFrame, RtuFrameReader, rtu_frame};
use crate::modbus::write_policy::WritePolicy;

/// The broadcast address: every slave runs the write, none answers.
const BROADCAST: u8 = 0;

/// The bit an exception answer sets in the function code; no request has it.
const EXCEPTION_BIT: u8 = 0x80;

/// How the RTU slave answers; fixed while a port is served.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RtuSlaveOptions {
    /// The slave's address on the line, 1 to 247.
    pub unit_id: u8,
    /// The silence of 3.5 characters that ends a frame and comes before each answer
    /// (`runtime::serial::SerialSettings::silence`).
    pub silence: Duration,
    /// What the standard function codes may write, as for the TCP server.
    pub writes: WritePolicy,
}

/// Serves the RTU frames arriving on `port` until its end of file (`Ok`) or an I/O error.
///
/// A request for `options.unit_id` is answered with [`serve_pdu`] after a silence, with the
/// address and a CRC; a function code the areas do not serve (such as 100, the online
/// services, which belong to TCP connections) gets exception 1. A broadcast write runs without
/// an answer; a broadcast read, a frame for another slave, an answer (function code 0x80 or
/// above, an exception) and a damaged frame get none either, and each is counted in
/// `counters`.
pub async fn serve_rtu<Port: AsyncRead + AsyncWrite + Unpin>(
    port: Port,
    areas: &Mutex<LocatedAreas>,
    map: &MapSlot,
    options: &RtuSlaveOptions,
    counters: &RtuSlaveCounters,
) -> io::Result<()> {
    let mut frames = RtuFrameReader::new(port, options.silence);
    while let Some(frame) = frames.next_frame().await? {
        let (address, pdu) = match frame {
            RtuFrame::Request { address, pdu } => (address, pdu),
            RtuFrame::Dropped(dropped) => {
                counters.count_dropped(dropped);
                continue;
            }
        };
        // An answer or an exception is another slave's (or our own, echoed by an adapter):
        // answering it with an exception could make two slaves answer each other for ever.
        if pdu
            .first()
            .is_some_and(|&function| function >= EXCEPTION_BIT)
        {
            counters.count_ignored();
            continue;
        }
        if address == BROADCAST {
            if is_broadcast_write(&pdu) {
                serve_pdu(areas, &map.get(), &options.writes, &pdu);
                counters.count_broadcast();
            } else {
                counters.count_ignored();
            }
            continue;
        }
        if address != options.unit_id {
            counters.count_ignored();
            continue;
        }
        let response = serve_pdu(areas, &map.get(), &options.writes, &pdu);
        // The master may still be turning its line round to receive.
        tokio::time::sleep(options.silence).await;
        let port = frames.port_mut();
        // No flush: tokio-serial's flush is tcdrain, which blocks the thread until the bytes
        // are on the wire, and rivet-runtime runs every task on one thread, so each answer
        // would freeze Modbus TCP, the online services and the signals for its whole
        // transmission. The kernel sends the queued bytes in order anyway, and nothing here
        // needs to know when they have left (no RTS to turn round: the adapter does that).
        port.write_all(&rtu_frame(address, &response)).await?;
        counters.count_answered();
    }
    Ok(())
}

/// Whether a broadcast of `pdu` is a write, which every slave runs: function codes 5, 6, 15
/// and 16 (23 reads too, so it is not broadcast).
fn is_broadcast_write(pdu: &[u8]) -> bool {
    matches!(pdu.first(), Some(5 | 6 | 15 | 16))
}

#[cfg(test)]
mod tests;
