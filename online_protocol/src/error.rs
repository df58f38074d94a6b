//! What can be wrong with a frame, and where.

use crate::status::Status;

/// Why a request or response could not be decoded; `at` is the byte of the frame (after the
/// function code, the service being byte 0) where the trouble is.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum DecodeError {
    /// Not even a service byte.
    #[error("the frame is empty: a service byte is expected")]
    Empty,
    /// A service number protocol version 3 does not have.
    #[error("service {0:#04x} is unknown to protocol version 3")]
    UnknownService(u8),
    /// The frame ends inside a field.
    #[error(
        "the frame is too short: the {field} at byte {at} needs {needed} bytes, {left} are left"
    )]
    TooShort {
        /// The field being read.
        field: &'static str,
        /// Where it starts.
        at: usize,
        /// The bytes it needs.
        needed: usize,
        /// The bytes that were left.
        left: usize,
    },
    /// Bytes after the last field.
    #[error("{count} bytes are left over at byte {at}, after the last field")]
    LeftOver {
        /// Where they start.
        at: usize,
        /// How many.
        count: usize,
    },
    /// A text that is not UTF-8.
    #[error("the {field} at byte {at} is not UTF-8")]
    NotUtf8 {
        /// The text's field.
        field: &'static str,
        /// Where its length byte is.
        at: usize,
    },
    /// A field with a value it may not have.
    #[error("the {field} at byte {at} is {value}, but {expected} is expected")]
    OutOfRange {
        /// The field.
        field: &'static str,
        /// Where it is.
        at: usize,
        /// What it holds.
        value: u64,
        /// What it may hold.
        expected: &'static str,
    },
    /// A value in `WRITE` or `FORCE` longer than the rest of the frame.
    #[error("the value at byte {at} of {size} bytes does not fit the {left} bytes left")]
    ValueTooLong {
        /// Where the value starts.
        at: usize,
        /// The size its place gives.
        size: usize,
        /// The bytes that were left.
        left: usize,
    },
    /// A response with a status number version 3 does not have.
    #[error("the status at byte 1 is {0}, which protocol version 3 does not have")]
    UnknownStatus(u8),
    /// A response to another service than the request's.
    #[error("the answer at byte 0 is for service {found:#04x}, not {expected:#04x}")]
    OtherService {
        /// The request's service.
        expected: u8,
        /// The response's.
        found: u8,
    },
    /// A `TRACE_UPLOAD` answer whose samples cannot all have one size.
    #[error("the {count} trace samples from byte {at} cannot share the {bytes} bytes left")]
    UnevenSamples {
        /// Where the first sample starts.
        at: usize,
        /// How many samples the answer says it holds.
        count: usize,
        /// The bytes the samples take.
        bytes: usize,
    },
}

impl DecodeError {
    /// The status the runtime answers a request with that fails so: an unknown service is
    /// status 1, a value too long for the frame status 5, anything else a bad request.
    pub fn status(&self) -> Status {
        match self {
            Self::UnknownService(_) => Status::UnknownService,
            Self::ValueTooLong { .. } => Status::BadPlace,
            _ => Status::BadRequest,
        }
    }
}
