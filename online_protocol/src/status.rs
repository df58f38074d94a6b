//! The status of a response and the refusal that any status but "done" carries
//! (`docs/protocol.md` §4).

use crate::framing::MAX_TEXT_BYTES;
use crate::writer::{cut, put_str8};

/// The status of a response.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[repr(u8)]
pub enum Status {
    /// Done: the response carries the service's answer.
    Done = 0,
    /// Unknown service.
    UnknownService = 1,
    /// Too short, too long, or a field out of range.
    BadRequest = 2,
    /// The runtime has a password and the service changes the target.
    PasswordRequired = 3,
    /// Wrong password or token.
    WrongPassword = 4,
    /// A place outside its region, or a value of the wrong size.
    BadPlace = 5,
    /// An unknown symbol (`RESOLVE`).
    UnknownSymbol = 6,
    /// No program, or the state forbids it.
    NotNow = 7,
    /// The downloaded image is refused.
    ImageRefused = 8,
    /// Another protocol version.
    VersionMismatch = 9,
}

impl Status {
    /// Every status, in the order of their numbers.
    pub const ALL: [Status; 10] = [
        Status::Done,
        Status::UnknownService,
        Status::BadRequest,
        Status::PasswordRequired,
        Status::WrongPassword,
        Status::BadPlace,
        Status::UnknownSymbol,
        Status::NotNow,
        Status::ImageRefused,
        Status::VersionMismatch,
    ];

    /// The status's number on the wire.
    pub fn number(self) -> u8 {
        self as u8
    }

    /// The status with `number`, if protocol version 2 has one.
    pub fn from_number(number: u8) -> Option<Self> {
        Self::ALL
            .into_iter()
            .find(|status| status.number() == number)
    }
}

/// A refusal: a status other than [`Status::Done`] and a message for people.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Refusal {
    /// Why.
    pub status: Status,
    /// What happened, in English; cut to [`MAX_TEXT_BYTES`] on the wire.
    pub message: String,
}

impl Refusal {
    /// A refusal with `status` and `message`.
    pub fn new(status: Status, message: impl Into<String>) -> Self {
        Self {
            status,
            message: message.into(),
        }
    }

    /// A bad request (status 2) with `message`.
    pub fn bad(message: impl Into<String>) -> Self {
        Self::new(Status::BadRequest, message)
    }

    /// A refusal because of the state (status 7) with `message`.
    pub fn not_now(message: impl Into<String>) -> Self {
        Self::new(Status::NotNow, message)
    }

    /// The response body (after the function code) refusing `service`: the service number as
    /// the request had it (which may be unknown), the status and the message cut to
    /// [`MAX_TEXT_BYTES`], so that a refusal always fits one response.
    pub fn encode(&self, service: u8) -> Vec<u8> {
        let message = cut(&self.message, MAX_TEXT_BYTES);
        let mut body = Vec::with_capacity(3 + message.len());
        body.push(service);
        body.push(self.status.number());
        put_str8(&mut body, message);
        body
    }
}
