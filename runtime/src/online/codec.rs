//! The online protocol's requests and responses as bytes (`docs/protocol.md`): pure functions
//! that never panic, whatever the bytes.

use program_image::ImageHash;

use super::place::WirePlace;

/// The function code that carries the online services.
pub const FUNCTION_CODE: u8 = 0x64;
/// The protocol version this runtime speaks.
pub const PROTOCOL_VERSION: u16 = 1;
/// The most payload bytes a response carries.
pub const MAX_PAYLOAD_BYTES: usize = 250;

/// A status of a response (`docs/protocol.md` §4).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u8)]
pub enum Status {
    /// Done.
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
    /// An unknown symbol.
    UnknownSymbol = 6,
    /// No program, or the state forbids it.
    NotNow = 7,
    /// The downloaded image is refused.
    ImageRefused = 8,
    /// Another protocol version.
    VersionMismatch = 9,
}

/// A refusal: a status other than [`Status::Done`] and a message for people.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Refusal {
    /// Why.
    pub status: Status,
    /// What happened, in English.
    pub message: String,
}

/// The trace trigger of a `TRACE_CONFIGURE`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TriggerKind {
    /// No trigger: record until the samples are complete.
    None,
    /// The trigger place goes from FALSE to TRUE.
    Rising,
    /// The trigger place goes from TRUE to FALSE.
    Falling,
    /// The trigger place is TRUE.
    WhileTrue,
}

/// A `TRACE_CONFIGURE` request without its token.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TraceConfig {
    /// The task index.
    pub task: u8,
    /// Sample every n-th cycle, at least 1.
    pub every: u16,
    /// How many samples to keep, at least 1.
    pub samples: u32,
    /// Percent of the samples kept before the trigger, 0 to 100.
    pub pretrigger: u8,
    /// The trigger.
    pub trigger: TriggerKind,
    /// The place the trigger looks at (ignored without a trigger).
    pub trigger_place: WirePlace,
    /// The places sampled.
    pub places: Vec<WirePlace>,
}

/// A parsed request.
#[derive(Clone, Debug, PartialEq, Eq)]
#[allow(missing_docs)] // The fields are the protocol's, documented in `docs/protocol.md`.
pub enum Request {
    Identify {
        protocol: u16,
    },
    Login {
        password: String,
    },
    DownloadBegin {
        token: u32,
        size: u32,
        hash: ImageHash,
    },
    DownloadChunk {
        token: u32,
        transfer: u16,
        offset: u32,
        bytes: Vec<u8>,
    },
    DownloadCommit {
        token: u32,
        transfer: u16,
        start: bool,
    },
    DownloadAbort {
        token: u32,
        transfer: u16,
    },
    Start {
        token: u32,
    },
    Stop {
        token: u32,
    },
    Reset {
        token: u32,
        kind: u8,
    },
    Resolve {
        path: String,
    },
    Read {
        places: Vec<WirePlace>,
    },
    Write {
        token: u32,
        values: Vec<(WirePlace, Vec<u8>)>,
    },
    Force {
        token: u32,
        values: Vec<(WirePlace, Vec<u8>)>,
    },
    Unforce {
        token: u32,
        places: Vec<WirePlace>,
    },
    Forces {
        from: u16,
    },
    TraceAdd {
        token: u32,
        places: Vec<WirePlace>,
    },
    TraceConfigure {
        token: u32,
        config: TraceConfig,
    },
    TraceArm {
        token: u32,
    },
    TraceStatus,
    TraceUpload {
        from: u32,
    },
    Tasks,
    Faults {
        from: u16,
    },
}

impl Request {
    /// The token of a service that changes the target, `None` for a read-only one.
    pub fn token(&self) -> Option<u32> {
        use Request::*;
        match self {
            DownloadBegin { token, .. }
            | DownloadChunk { token, .. }
            | DownloadCommit { token, .. }
            | DownloadAbort { token, .. }
            | Start { token }
            | Stop { token }
            | Reset { token, .. }
            | Write { token, .. }
            | Force { token, .. }
            | Unforce { token, .. }
            | TraceConfigure { token, .. }
            | TraceAdd { token, .. }
            | TraceArm { token } => Some(*token),
            Identify { .. }
            | Login { .. }
            | Resolve { .. }
            | Read { .. }
            | Forces { .. }
            | TraceStatus
            | TraceUpload { .. }
            | Tasks
            | Faults { .. } => None,
        }
    }
}

impl Request {
    /// The service number.
    pub fn service(&self) -> u8 {
        use Request::*;
        match self {
            Identify { .. } => 0x01,
            Login { .. } => 0x02,
            DownloadBegin { .. } => 0x10,
            DownloadChunk { .. } => 0x11,
            DownloadCommit { .. } => 0x12,
            DownloadAbort { .. } => 0x13,
            Start { .. } => 0x20,
            Stop { .. } => 0x21,
            Reset { .. } => 0x22,
            Resolve { .. } => 0x30,
            Read { .. } => 0x31,
            Write { .. } => 0x32,
            Force { .. } => 0x33,
            Unforce { .. } => 0x34,
            Forces { .. } => 0x35,
            TraceConfigure { .. } => 0x40,
            TraceArm { .. } => 0x41,
            TraceStatus => 0x42,
            TraceUpload { .. } => 0x43,
            TraceAdd { .. } => 0x44,
            Tasks => 0x50,
            Faults { .. } => 0x51,
        }
    }

    /// The request's bytes after the function code (service and payload), as a client sends
    /// them. Texts and lists longer than their u8 count allows are cut.
    pub fn encode(&self) -> Vec<u8> {
        use Request::*;
        let mut out = vec![self.service()];
        match self {
            Identify { protocol } => out.extend_from_slice(&protocol.to_le_bytes()),
            Login { password } => put_str8(&mut out, password),
            DownloadBegin { token, size, hash } => {
                out.extend_from_slice(&token.to_le_bytes());
                out.extend_from_slice(&size.to_le_bytes());
                out.extend_from_slice(hash);
            }
            DownloadChunk {
                token,
                transfer,
                offset,
                bytes,
            } => {
                out.extend_from_slice(&token.to_le_bytes());
                out.extend_from_slice(&transfer.to_le_bytes());
                out.extend_from_slice(&offset.to_le_bytes());
                out.extend_from_slice(bytes);
            }
            DownloadCommit {
                token,
                transfer,
                start,
            } => {
                out.extend_from_slice(&token.to_le_bytes());
                out.extend_from_slice(&transfer.to_le_bytes());
                out.push(u8::from(*start));
            }
            DownloadAbort { token, transfer } => {
                out.extend_from_slice(&token.to_le_bytes());
                out.extend_from_slice(&transfer.to_le_bytes());
            }
            Start { token } | Stop { token } | TraceArm { token } => {
                out.extend_from_slice(&token.to_le_bytes());
            }
            Reset { token, kind } => {
                out.extend_from_slice(&token.to_le_bytes());
                out.push(*kind);
            }
            Resolve { path } => put_str8(&mut out, path),
            Read { places } => put_places(&mut out, places),
            Write { token, values } | Force { token, values } => {
                out.extend_from_slice(&token.to_le_bytes());
                let values = &values[..values.len().min(255)];
                out.push(values.len() as u8);
                for (place, value) in values {
                    put_place(&mut out, *place);
                    out.extend_from_slice(value);
                }
            }
            Unforce { token, places } | TraceAdd { token, places } => {
                out.extend_from_slice(&token.to_le_bytes());
                put_places(&mut out, places);
            }
            Forces { from } | Faults { from } => out.extend_from_slice(&from.to_le_bytes()),
            TraceConfigure { token, config } => {
                out.extend_from_slice(&token.to_le_bytes());
                out.push(config.task);
                out.extend_from_slice(&config.every.to_le_bytes());
                out.extend_from_slice(&config.samples.to_le_bytes());
                out.push(config.pretrigger);
                out.push(match config.trigger {
                    TriggerKind::None => 0,
                    TriggerKind::Rising => 1,
                    TriggerKind::Falling => 2,
                    TriggerKind::WhileTrue => 3,
                });
                put_place(&mut out, config.trigger_place);
                put_places(&mut out, &config.places);
            }
            TraceStatus | Tasks => {}
            TraceUpload { from } => out.extend_from_slice(&from.to_le_bytes()),
        }
        out
    }
}

/// Appends `count:u8` and the places (at most 255).
fn put_places(out: &mut Vec<u8>, places: &[WirePlace]) {
    let places = &places[..places.len().min(255)];
    out.push(places.len() as u8);
    for place in places {
        put_place(out, *place);
    }
}

/// Parses `service` and its `payload` (the request PDU after the function code and service).
pub fn parse_request(service: u8, payload: &[u8]) -> Result<Request, Refusal> {
    let mut r = Reader::new(payload);
    let request = match service {
        0x01 => Request::Identify { protocol: r.u16()? },
        0x02 => Request::Login {
            password: r.str8()?,
        },
        0x10 => Request::DownloadBegin {
            token: r.u32()?,
            size: r.u32()?,
            hash: r.hash()?,
        },
        0x11 => Request::DownloadChunk {
            token: r.u32()?,
            transfer: r.u16()?,
            offset: r.u32()?,
            bytes: r.rest().to_vec(),
        },
        0x12 => Request::DownloadCommit {
            token: r.u32()?,
            transfer: r.u16()?,
            start: r.u8()? == 1,
        },
        0x13 => Request::DownloadAbort {
            token: r.u32()?,
            transfer: r.u16()?,
        },
        0x20 => Request::Start { token: r.u32()? },
        0x21 => Request::Stop { token: r.u32()? },
        0x22 => Request::Reset {
            token: r.u32()?,
            kind: r.u8()?,
        },
        0x30 => Request::Resolve { path: r.str8()? },
        0x31 => Request::Read {
            places: r.places()?,
        },
        0x32 => Request::Write {
            token: r.u32()?,
            values: r.values()?,
        },
        0x33 => Request::Force {
            token: r.u32()?,
            values: r.values()?,
        },
        0x34 => Request::Unforce {
            token: r.u32()?,
            places: r.places()?,
        },
        0x35 => Request::Forces { from: r.u16()? },
        0x40 => {
            let token = r.u32()?;
            let task = r.u8()?;
            let every = r.u16()?;
            let samples = r.u32()?;
            let pretrigger = r.u8()?;
            let trigger = match r.u8()? {
                0 => TriggerKind::None,
                1 => TriggerKind::Rising,
                2 => TriggerKind::Falling,
                3 => TriggerKind::WhileTrue,
                other => return Err(bad(format!("trigger {other} is not 0 to 3"))),
            };
            let trigger_place = r.place()?;
            let places = r.places()?;
            if every == 0 || samples == 0 || pretrigger > 100 {
                return Err(bad(
                    "every and samples must be at least 1, pretrigger at most 100".to_owned(),
                ));
            }
            Request::TraceConfigure {
                token,
                config: TraceConfig {
                    task,
                    every,
                    samples,
                    pretrigger,
                    trigger,
                    trigger_place,
                    places,
                },
            }
        }
        0x41 => Request::TraceArm { token: r.u32()? },
        0x42 => Request::TraceStatus,
        0x43 => Request::TraceUpload { from: r.u32()? },
        0x44 => Request::TraceAdd {
            token: r.u32()?,
            places: r.places()?,
        },
        0x50 => Request::Tasks,
        0x51 => Request::Faults { from: r.u16()? },
        other => {
            return Err(Refusal {
                status: Status::UnknownService,
                message: format!("service {other:#04x} is unknown to protocol version 1"),
            });
        }
    };
    if !r.rest().is_empty() {
        return Err(bad(format!(
            "{} bytes left over after the request",
            r.rest().len()
        )));
    }
    Ok(request)
}

/// The response PDU body (after the function code) of a successful `service`.
pub fn done(service: u8, payload: &[u8]) -> Vec<u8> {
    let mut body = Vec::with_capacity(2 + payload.len());
    body.push(service);
    body.push(Status::Done as u8);
    body.extend_from_slice(payload);
    body
}

/// The response PDU body (after the function code) of a refused `service`.
pub fn refused(service: u8, refusal: &Refusal) -> Vec<u8> {
    let mut body = vec![service, refusal.status as u8];
    put_str8(&mut body, &refusal.message);
    body
}

/// A bad request with `message`.
pub fn bad(message: String) -> Refusal {
    Refusal {
        status: Status::BadRequest,
        message,
    }
}

/// Appends `text` as an `str8`, cut at a character boundary to 200 bytes so a response fits.
pub fn put_str8(out: &mut Vec<u8>, text: &str) {
    let mut end = text.len().min(200);
    while !text.is_char_boundary(end) {
        end -= 1;
    }
    out.push(end as u8);
    out.extend_from_slice(&text.as_bytes()[..end]);
}

/// Appends a place (8 bytes).
pub fn put_place(out: &mut Vec<u8>, place: WirePlace) {
    out.push(place.region);
    out.extend_from_slice(&place.offset.to_le_bytes());
    out.push(place.bit);
    out.extend_from_slice(&place.size.to_le_bytes());
}

/// A cursor over a request's payload; every read checks the length.
pub struct Reader<'a> {
    bytes: &'a [u8],
}

impl<'a> Reader<'a> {
    /// A reader at the start of `bytes`.
    pub fn new(bytes: &'a [u8]) -> Self {
        Self { bytes }
    }

    /// The next `count` bytes.
    pub fn take(&mut self, count: usize) -> Result<&'a [u8], Refusal> {
        if self.bytes.len() < count {
            return Err(bad(format!(
                "the request is too short: {count} more bytes expected, {} left",
                self.bytes.len()
            )));
        }
        let (taken, rest) = self.bytes.split_at(count);
        self.bytes = rest;
        Ok(taken)
    }

    /// The bytes not read yet (and consumes them).
    pub fn rest(&mut self) -> &'a [u8] {
        std::mem::take(&mut self.bytes)
    }

    fn array<const N: usize>(&mut self) -> Result<[u8; N], Refusal> {
        let mut array = [0; N];
        array.copy_from_slice(self.take(N)?);
        Ok(array)
    }

    /// A u8.
    pub fn u8(&mut self) -> Result<u8, Refusal> {
        Ok(self.array::<1>()?[0])
    }

    /// A little-endian u16.
    pub fn u16(&mut self) -> Result<u16, Refusal> {
        Ok(u16::from_le_bytes(self.array()?))
    }

    /// A little-endian u32.
    pub fn u32(&mut self) -> Result<u32, Refusal> {
        Ok(u32::from_le_bytes(self.array()?))
    }

    /// A little-endian u64.
    pub fn u64(&mut self) -> Result<u64, Refusal> {
        Ok(u64::from_le_bytes(self.array()?))
    }

    /// A 32-byte hash.
    pub fn hash(&mut self) -> Result<ImageHash, Refusal> {
        self.array()
    }

    /// An `str8` that must be UTF-8.
    pub fn str8(&mut self) -> Result<String, Refusal> {
        let length = self.u8()? as usize;
        let bytes = self.take(length)?;
        String::from_utf8(bytes.to_vec()).map_err(|_| bad("a text is not UTF-8".to_owned()))
    }

    /// A place (8 bytes).
    pub fn place(&mut self) -> Result<WirePlace, Refusal> {
        Ok(WirePlace {
            region: self.u8()?,
            offset: self.u32()?,
            bit: self.u8()?,
            size: self.u16()?,
        })
    }

    /// `count:u8` and that many places.
    pub fn places(&mut self) -> Result<Vec<WirePlace>, Refusal> {
        let count = self.u8()?;
        (0..count).map(|_| self.place()).collect()
    }

    /// `count:u8` and that many places, each followed by its value's bytes.
    pub fn values(&mut self) -> Result<Vec<(WirePlace, Vec<u8>)>, Refusal> {
        let count = self.u8()?;
        let mut values = Vec::new();
        for _ in 0..count {
            let place = self.place()?;
            let size = usize::from(place.size);
            if self.bytes.len() < size {
                return Err(Refusal {
                    status: Status::BadPlace,
                    message: format!(
                        "a value of {size} bytes does not fit the {} bytes left",
                        self.bytes.len()
                    ),
                });
            }
            values.push((place, self.take(size)?.to_vec()));
        }
        Ok(values)
    }
}

#[cfg(test)]
#[path = "codec_tests.rs"]
mod tests;
