//! Modbus RTU framing: the CRC, and cutting the bytes a serial port delivers into frames
//! (`docs/modbus-master.md` §7).

use std::io;
use std::time::Duration;

use tokio::io::{AsyncRead, AsyncReadExt};

/// The longest RTU frame: address, a PDU of at most 253 bytes, and the two CRC bytes.
pub const MAX_RTU_FRAME_BYTES: usize = 256;

/// The shortest RTU frame: address, function code and the two CRC bytes.
const MIN_RTU_FRAME_BYTES: usize = 4;

/// How long a frame that is known to be incomplete (it holds fewer bytes than its function
/// code implies) may pause before it is dropped (`docs/modbus-master.md` §7): USB adapters
/// deliver bytes in batches (an FTDI chip every 16 ms, its latency timer), so a pause longer
/// than the 3.5-character silence inside such a frame is the adapter's, not the master's.
pub const INCOMPLETE_FRAME_PATIENCE: Duration = Duration::from_millis(50);

/// The Modbus CRC-16 of `bytes` (polynomial 0xA001 reflected, initial value 0xFFFF); it travels
/// low byte first.
pub fn crc16(bytes: &[u8]) -> u16 {
    let mut crc: u16 = 0xFFFF;
    for &byte in bytes {
        crc ^= u16::from(byte);
        for _ in 0..8 {
            crc = if crc & 1 == 1 {
                (crc >> 1) ^ 0xA001
            } else {
                crc >> 1
            };
        }
    }
    crc
}

/// The whole frame of `address` and `pdu`: address, PDU, CRC low byte first.
pub fn rtu_frame(address: u8, pdu: &[u8]) -> Vec<u8> {
    let mut frame = Vec::with_capacity(pdu.len() + 3);
    frame.push(address);
    frame.extend_from_slice(pdu);
    let crc = crc16(&frame);
    frame.extend_from_slice(&crc.to_le_bytes());
    frame
}

/// What one frame on the line turned out to be.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum RtuFrame {
    /// A frame whose CRC matches: its address and its PDU (function code first, CRC removed).
    Request {
        /// The slave addressed; 0 is broadcast.
        address: u8,
        /// The request PDU.
        pdu: Vec<u8>,
    },
    /// A frame dropped without an answer.
    Dropped(DroppedFrame),
}

/// Why a frame was dropped.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DroppedFrame {
    /// Its CRC does not match its bytes, or it is shorter than the 4 bytes of any frame.
    BadCrc,
    /// It ran past [`MAX_RTU_FRAME_BYTES`] before a silence.
    TooLong,
}

/// Cuts the bytes read from a serial port into RTU frames.
///
/// A silence of `silence` (3.5 characters) ends a frame. A frame also ends as soon as it holds
/// as many bytes as its function code implies and its CRC matches, because adapters and
/// pseudo-terminals deliver bytes in chunks in which the time between bytes means nothing;
/// for the same reason a frame holding fewer bytes than its function code implies ends only
/// at a pause of [`INCOMPLETE_FRAME_PATIENCE`]. Lives as long as the port is open.
#[derive(Debug)]
pub struct RtuFrameReader<Port> {
    /// The port read from.
    port: Port,
    /// The bytes of the frame being received, and any that followed a frame complete by its
    /// length in the same chunk.
    buffer: Vec<u8>,
    /// Whether the frame being received has run past [`MAX_RTU_FRAME_BYTES`]: its bytes are
    /// discarded until the silence.
    overflowing: bool,
    /// The silence that ends a frame.
    silence: Duration,
}

impl<Port: AsyncRead + Unpin> RtuFrameReader<Port> {
    /// A reader of `port` whose frames end at a silence of `silence`.
    pub fn new(port: Port, silence: Duration) -> Self {
        Self {
            port,
            buffer: Vec::with_capacity(MAX_RTU_FRAME_BYTES),
            overflowing: false,
            silence,
        }
    }

    /// The next frame, or `None` at the port's end of file (bytes of an unfinished frame are
    /// then lost). Waits as long as the line is idle.
    ///
    /// Cancel-safe: a frame cut short by dropping the future goes on at the next call.
    pub async fn next_frame(&mut self) -> io::Result<Option<RtuFrame>> {
        // One byte more than a frame, so that a frame that runs past the limit is seen.
        let mut chunk = [0; MAX_RTU_FRAME_BYTES + 1];
        loop {
            if let Some(frame) = self.complete_by_length() {
                return Ok(Some(frame));
            }
            // Only now, so that a frame complete by its length at the front of the buffer is
            // taken even when the bytes after it would make the buffer too long.
            if self.buffer.len() > MAX_RTU_FRAME_BYTES {
                self.buffer.clear();
                self.overflowing = true;
            }
            // Never more than fills the buffer to one byte past a frame: leftovers of the last
            // chunk and a whole next frame then still fit.
            let wanted = if self.overflowing {
                chunk.len()
            } else {
                MAX_RTU_FRAME_BYTES + 1 - self.buffer.len()
            };
            let pause = self.pause_that_ends_the_frame();
            let read = self.port.read(&mut chunk[..wanted]);
            let read = if self.buffer.is_empty() && !self.overflowing {
                read.await
            } else {
                match tokio::time::timeout(pause, read).await {
                    Ok(read) => read,
                    Err(_silence) => return Ok(Some(self.end_at_silence())),
                }
            };
            let count = read?;
            if count == 0 {
                return Ok(None);
            }
            if !self.overflowing {
                self.buffer.extend_from_slice(&chunk[..count]);
            }
        }
    }

    /// The port, to write answers to.
    pub fn port_mut(&mut self) -> &mut Port {
        &mut self.port
    }

    /// The pause that ends the frame being received: the silence, or the longer patience
    /// while the frame is known to be incomplete.
    fn pause_that_ends_the_frame(&self) -> Duration {
        if !self.overflowing && self.buffer.len() < least_length(&self.buffer) {
            INCOMPLETE_FRAME_PATIENCE
        } else {
            self.silence
        }
    }

    /// The request at the front of the buffer when the buffer holds as many bytes as its
    /// function code implies and their CRC matches; the bytes after it stay for the next frame.
    fn complete_by_length(&mut self) -> Option<RtuFrame> {
        let length = implied_length(&self.buffer)?;
        let frame = self.buffer.get(..length)?;
        if !crc_matches(frame) {
            return None;
        }
        let frame: Vec<u8> = self.buffer.drain(..length).collect();
        Some(request(&frame))
    }

    /// The frame the silence has ended, and a fresh start for the next.
    fn end_at_silence(&mut self) -> RtuFrame {
        let frame = std::mem::take(&mut self.buffer);
        if std::mem::take(&mut self.overflowing) {
            return RtuFrame::Dropped(DroppedFrame::TooLong);
        }
        if frame.len() >= MIN_RTU_FRAME_BYTES && crc_matches(&frame) {
            request(&frame)
        } else {
            RtuFrame::Dropped(DroppedFrame::BadCrc)
        }
    }
}

/// The length a request frame starting with `bytes` has by its function code: 8 bytes for
/// 1 to 6, `9 + n` for 15 and 16 and `13 + n` for 23 with byte count `n`; `None` while the
/// bytes do not tell yet, or for other function codes, which end at the silence.
fn implied_length(bytes: &[u8]) -> Option<usize> {
    match bytes.get(1)? {
        1..=6 => Some(8),
        15 | 16 => bytes.get(6).map(|&count| 9 + usize::from(count)),
        23 => bytes.get(10).map(|&count| 13 + usize::from(count)),
        _ => None,
    }
}

/// The fewest bytes a frame starting with `bytes` can have: its implied length when the
/// bytes tell it, the length with a byte count of 0 for function codes 15, 16 and 23 before
/// the count arrives, and the 4 bytes of any frame otherwise.
fn least_length(bytes: &[u8]) -> usize {
    if let Some(length) = implied_length(bytes) {
        return length;
    }
    match bytes.get(1) {
        Some(15 | 16) => 9,
        Some(23) => 13,
        _ => MIN_RTU_FRAME_BYTES,
    }
}

/// Whether the last two bytes of `frame` are the CRC of the others, low byte first.
fn crc_matches(frame: &[u8]) -> bool {
    match frame.len().checked_sub(2) {
        Some(end) => crc16(&frame[..end]).to_le_bytes() == frame[end..],
        None => false,
    }
}

/// The request of a whole frame whose CRC matches.
fn request(frame: &[u8]) -> RtuFrame {
    RtuFrame::Request {
        address: frame[0],
        pdu: frame[1..frame.len() - 2].to_vec(),
    }
}

#[cfg(test)]
mod tests;
