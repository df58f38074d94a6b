//! The constants and byte layouts of `docs/protocol.md` (version 1) as the client sees them:
//! requests it writes, responses it reads.

/// The Modbus function code that carries the online services.
pub const FUNCTION_CODE: u8 = 0x64;

/// The protocol version this client speaks.
pub const PROTOCOL_VERSION: u16 = 1;

/// The most payload bytes one request or response carries (a PDU is at most 253 bytes).
pub const MAX_PAYLOAD: usize = 250;

/// Service identifiers.
#[allow(missing_docs)] // Each is the service of the same name in docs/protocol.md.
pub mod service {
    pub const IDENTIFY: u8 = 0x01;
    pub const LOGIN: u8 = 0x02;
    pub const DOWNLOAD_BEGIN: u8 = 0x10;
    pub const DOWNLOAD_CHUNK: u8 = 0x11;
    pub const DOWNLOAD_COMMIT: u8 = 0x12;
    pub const DOWNLOAD_ABORT: u8 = 0x13;
    pub const START: u8 = 0x20;
    pub const STOP: u8 = 0x21;
    pub const RESET: u8 = 0x22;
    pub const RESOLVE: u8 = 0x30;
    pub const READ: u8 = 0x31;
    pub const WRITE: u8 = 0x32;
    pub const FORCE: u8 = 0x33;
    pub const UNFORCE: u8 = 0x34;
    pub const FORCES: u8 = 0x35;
    pub const TRACE_CONFIGURE: u8 = 0x40;
    pub const TRACE_ARM: u8 = 0x41;
    pub const TRACE_STATUS: u8 = 0x42;
    pub const TRACE_UPLOAD: u8 = 0x43;
    pub const TRACE_ADD: u8 = 0x44;
    pub const TASKS: u8 = 0x50;
    pub const FAULTS: u8 = 0x51;
}

/// Status codes of responses (§4).
#[allow(missing_docs)]
pub mod status {
    pub const DONE: u8 = 0;
    pub const UNKNOWN_SERVICE: u8 = 1;
    pub const BAD_REQUEST: u8 = 2;
    pub const PASSWORD_REQUIRED: u8 = 3;
    pub const WRONG_PASSWORD: u8 = 4;
    pub const BAD_PLACE: u8 = 5;
    pub const UNKNOWN_SYMBOL: u8 = 6;
    pub const NOT_NOW: u8 = 7;
    pub const IMAGE_REFUSED: u8 = 8;
    pub const VERSION_MISMATCH: u8 = 9;
}

/// Where a variable is on the target: region, byte offset, bit of a located BOOL, size.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Place {
    /// 0 data, 1 `%I`, 2 `%Q`, 3 `%M`.
    pub region: u8,
    /// Byte offset in the region.
    pub offset: u32,
    /// The bit of a located BOOL, or `None`.
    pub bit: Option<u8>,
    /// Bytes.
    pub size: u16,
}

impl Place {
    /// The 8 bytes of the place in a request.
    pub fn encode(&self, out: &mut Vec<u8>) {
        out.push(self.region);
        out.extend_from_slice(&self.offset.to_le_bytes());
        out.push(self.bit.unwrap_or(0xFF));
        out.extend_from_slice(&self.size.to_le_bytes());
    }

    /// A place read from a response.
    pub fn decode(reader: &mut Reader<'_>) -> Result<Self, String> {
        let region = reader.u8()?;
        let offset = reader.u32()?;
        let bit = reader.u8()?;
        let size = reader.u16()?;
        Ok(Self {
            region,
            offset,
            bit: (bit != 0xFF).then_some(bit),
            size,
        })
    }

    /// Bytes its value takes in a request or response (one for a bit).
    pub fn value_bytes(&self) -> usize {
        if self.bit.is_some() {
            1
        } else {
            usize::from(self.size)
        }
    }
}

/// Reads the fields of a response in order, with an error naming what was missing.
pub struct Reader<'a> {
    bytes: &'a [u8],
}

impl<'a> Reader<'a> {
    /// A reader over `bytes`.
    pub fn new(bytes: &'a [u8]) -> Self {
        Self { bytes }
    }

    /// The next `n` bytes.
    pub fn take(&mut self, n: usize) -> Result<&'a [u8], String> {
        if self.bytes.len() < n {
            return Err(format!(
                "the response ends {} bytes early",
                n - self.bytes.len()
            ));
        }
        let (taken, rest) = self.bytes.split_at(n);
        self.bytes = rest;
        Ok(taken)
    }

    /// A u8.
    pub fn u8(&mut self) -> Result<u8, String> {
        Ok(self.take(1)?[0])
    }

    /// A little-endian u16.
    pub fn u16(&mut self) -> Result<u16, String> {
        let b = self.take(2)?;
        Ok(u16::from_le_bytes([b[0], b[1]]))
    }

    /// A little-endian u32.
    pub fn u32(&mut self) -> Result<u32, String> {
        let b = self.take(4)?;
        Ok(u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
    }

    /// A little-endian u64.
    pub fn u64(&mut self) -> Result<u64, String> {
        let mut array = [0u8; 8];
        array.copy_from_slice(self.take(8)?);
        Ok(u64::from_le_bytes(array))
    }

    /// An `str8`.
    pub fn str8(&mut self) -> Result<String, String> {
        let length = usize::from(self.u8()?);
        Ok(String::from_utf8_lossy(self.take(length)?).into_owned())
    }

    /// A 32-byte hash.
    pub fn hash(&mut self) -> Result<[u8; 32], String> {
        let mut hash = [0u8; 32];
        hash.copy_from_slice(self.take(32)?);
        Ok(hash)
    }

    /// Whatever is left.
    pub fn rest(&mut self) -> &'a [u8] {
        std::mem::take(&mut self.bytes)
    }
}

/// Appends an `str8` (cut to 255 bytes at a character boundary).
pub fn put_str8(out: &mut Vec<u8>, text: &str) {
    let mut end = text.len().min(255);
    while !text.is_char_boundary(end) {
        end -= 1;
    }
    out.push(end as u8);
    out.extend_from_slice(&text.as_bytes()[..end]);
}
