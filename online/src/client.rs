//! An async client of one target: each method is one service of `docs/protocol.md` (or a
//! sequence of them), with the target's refusals turned into [`OnlineError`]s.

use std::borrow::Cow;
use std::net::SocketAddr;
use std::time::Duration;

use sha2::{Digest, Sha256};
use tokio_modbus::client::{Client as _, Context};
use tokio_modbus::{Request, Response};

use crate::error::OnlineError;
use crate::protocol::{
    FUNCTION_CODE, MAX_PAYLOAD, PROTOCOL_VERSION, Place, Reader, put_str8, service, status,
};

/// How long one request may take before the client gives up.
pub const REQUEST_TIMEOUT: Duration = Duration::from_secs(5);

/// What the target says about itself.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Identity {
    /// The protocol version it speaks.
    pub protocol: u16,
    /// Its runtime version.
    pub runtime_version: String,
    /// Its state.
    pub state: TargetState,
    /// The identity hash of its program, `None` without one.
    pub image_hash: Option<[u8; 32]>,
    /// The project name of its program.
    pub project: String,
    /// Whether changing services need a password.
    pub password_required: bool,
}

/// The state of a target.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TargetState {
    /// No program loaded.
    NoProgram,
    /// A program, not running.
    Stopped,
    /// Running.
    Running,
    /// Running, with at least one task stopped by a fault.
    Faulted,
}

impl TargetState {
    fn from_byte(byte: u8) -> Result<Self, OnlineError> {
        Ok(match byte {
            0 => Self::NoProgram,
            1 => Self::Stopped,
            2 => Self::Running,
            3 => Self::Faulted,
            other => return Err(OnlineError::Protocol(format!("unknown state {other}"))),
        })
    }

    /// The state in words.
    pub fn describe(self) -> &'static str {
        match self {
            Self::NoProgram => "no program",
            Self::Stopped => "stopped",
            Self::Running => "running",
            Self::Faulted => "running with a faulted task",
        }
    }
}

/// How the target's memory is reset.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Reset {
    /// Everything but RETAIN and PERSISTENT.
    Warm,
    /// Everything but PERSISTENT.
    Cold,
    /// Everything.
    Origin,
}

/// A variable resolved on the target.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Resolved {
    /// Where it is.
    pub place: Place,
    /// Its elementary type tag (`docs/program-image.md` §4), 0x20 STRING, 0x21 WSTRING, 0xFF
    /// anything else.
    pub type_tag: u8,
    /// The characters of a string, else 0.
    pub length: u16,
}

/// A place's bytes and whether it is forced.
pub type Value = (Vec<u8>, bool);

/// A consistent snapshot of some places.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Snapshot {
    /// Cycles run so far when it was taken.
    pub cycle: u64,
    /// Each place's bytes, and whether it is forced.
    pub values: Vec<Value>,
}

/// Statistics of one task.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TaskInfo {
    /// The task's name.
    pub name: String,
    /// Cycles run.
    pub cycles: u64,
    /// The last cycle's time.
    pub last_ns: u64,
    /// The shortest cycle.
    pub min_ns: u64,
    /// The longest cycle.
    pub max_ns: u64,
    /// The average cycle.
    pub average_ns: u64,
    /// The largest start jitter.
    pub jitter_max_ns: u64,
    /// Whether a fault stopped it.
    pub faulted: bool,
}

/// A fault the target recorded.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Fault {
    /// The task it stopped.
    pub task: String,
    /// What happened.
    pub kind: String,
    /// The POU.
    pub pou: String,
    /// The source file, if known.
    pub file: String,
    /// The line, 0 when unknown.
    pub line: u32,
    /// The task's cycle count.
    pub cycle: u64,
}

/// How a trace starts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Trigger {
    /// At once: the first samples are kept.
    None,
    /// On a rising edge of a BOOL.
    Rising(Place),
    /// On a falling edge of a BOOL.
    Falling(Place),
    /// While a BOOL is TRUE.
    Level(Place),
}

/// A trace to record on the target.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TraceConfig {
    /// The task whose cycles are sampled (its index in the image's task table).
    pub task: u8,
    /// Sample every n-th cycle (1: every cycle).
    pub every: u16,
    /// How many samples to keep.
    pub samples: u32,
    /// The percentage of samples kept before the trigger.
    pub pretrigger_percent: u8,
    /// When recording starts.
    pub trigger: Trigger,
    /// The places sampled.
    pub places: Vec<Place>,
}

/// Where a trace is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TraceStatus {
    /// 0 unconfigured, 1 configured, 2 armed, 3 triggered, 4 complete.
    pub state: u8,
    /// Samples recorded so far.
    pub recorded: u32,
    /// The index of the sample at the trigger, if it came.
    pub trigger_sample: Option<u32>,
}

/// One sample of a trace.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Sample {
    /// The task's cycle count.
    pub cycle: u64,
    /// The task clock in nanoseconds.
    pub time_ns: u64,
    /// Each place's bytes, in the configured order.
    pub values: Vec<Vec<u8>>,
}

/// A connection to one target.
pub struct Client {
    address: SocketAddr,
    context: Context,
    token: u32,
}

impl Client {
    /// Connects, checks the protocol version and logs in when a password is given.
    pub async fn connect(
        address: SocketAddr,
        password: Option<&str>,
    ) -> Result<(Self, Identity), OnlineError> {
        let context = match tokio::time::timeout(
            REQUEST_TIMEOUT,
            tokio_modbus::client::tcp::connect(address),
        )
        .await
        {
            Err(_) => {
                return Err(OnlineError::Timeout(
                    address,
                    REQUEST_TIMEOUT.as_millis() as u64,
                ));
            }
            Ok(Err(error)) if error.kind() == std::io::ErrorKind::ConnectionRefused => {
                return Err(OnlineError::Refused(address));
            }
            Ok(Err(error)) => return Err(OnlineError::Io(address, error)),
            Ok(Ok(context)) => context,
        };
        let mut client = Self {
            address,
            context,
            token: 0,
        };
        let identity = client.identify().await?;
        if let Some(password) = password {
            let mut payload = Vec::new();
            put_str8(&mut payload, password);
            let answer = client.call(service::LOGIN, &payload).await?;
            client.token = Reader::new(&answer).u32().map_err(OnlineError::Protocol)?;
        }
        Ok((client, identity))
    }

    /// The address connected to.
    pub fn address(&self) -> SocketAddr {
        self.address
    }

    /// One service: the request's payload in, the answer's payload out.
    async fn call(&mut self, id: u8, payload: &[u8]) -> Result<Vec<u8>, OnlineError> {
        let mut pdu = Vec::with_capacity(payload.len() + 1);
        pdu.push(id);
        pdu.extend_from_slice(payload);
        if pdu.len() > MAX_PAYLOAD + 1 {
            return Err(OnlineError::Protocol(format!(
                "a request of {} bytes does not fit a frame",
                pdu.len()
            )));
        }
        let request = Request::Custom(FUNCTION_CODE, Cow::Owned(pdu));
        let answer = match tokio::time::timeout(REQUEST_TIMEOUT, self.context.call(request)).await {
            Err(_) => {
                return Err(OnlineError::Timeout(
                    self.address,
                    REQUEST_TIMEOUT.as_millis() as u64,
                ));
            }
            Ok(Err(error)) => {
                return Err(OnlineError::Io(
                    self.address,
                    std::io::Error::other(error.to_string()),
                ));
            }
            Ok(Ok(Err(exception))) => {
                return Err(match exception {
                    tokio_modbus::ExceptionCode::IllegalFunction => {
                        OnlineError::NotRivet(self.address)
                    }
                    other => OnlineError::Exception(format!("{other:?}")),
                });
            }
            Ok(Ok(Ok(response))) => response,
        };
        let Response::Custom(FUNCTION_CODE, bytes) = answer else {
            return Err(OnlineError::Protocol(
                "an answer of another function code".to_owned(),
            ));
        };
        let mut reader = Reader::new(&bytes);
        let echoed = reader.u8().map_err(OnlineError::Protocol)?;
        let code = reader.u8().map_err(OnlineError::Protocol)?;
        if echoed != id {
            return Err(OnlineError::Protocol(format!(
                "the answer is for service {echoed}, not {id}"
            )));
        }
        if code == status::DONE {
            return Ok(reader.rest().to_vec());
        }
        let message = reader.str8().unwrap_or_default();
        Err(match code {
            status::PASSWORD_REQUIRED => OnlineError::PasswordRequired,
            status::WRONG_PASSWORD => OnlineError::WrongPassword(message),
            status::IMAGE_REFUSED => OnlineError::ImageRefused(message),
            status::UNKNOWN_SYMBOL => OnlineError::UnknownSymbol(message),
            status::VERSION_MISMATCH => OnlineError::Rejected(message),
            _ => OnlineError::Rejected(message),
        })
    }

    /// `IDENTIFY`.
    pub async fn identify(&mut self) -> Result<Identity, OnlineError> {
        let answer = self
            .call(service::IDENTIFY, &PROTOCOL_VERSION.to_le_bytes())
            .await?;
        let parse = || -> Result<Identity, String> {
            let mut reader = Reader::new(&answer);
            let protocol = reader.u16()?;
            let runtime_version = reader.str8()?;
            let state = reader.u8()?;
            let hash = reader.hash()?;
            let project = reader.str8()?;
            let password_required = reader.u8()? != 0;
            let state = TargetState::from_byte(state).map_err(|e| e.to_string())?;
            Ok(Identity {
                protocol,
                runtime_version,
                state,
                image_hash: (hash != [0; 32]).then_some(hash),
                project,
                password_required,
            })
        };
        let identity = parse().map_err(OnlineError::Protocol)?;
        if identity.protocol != PROTOCOL_VERSION {
            return Err(OnlineError::VersionMismatch {
                ours: PROTOCOL_VERSION,
                theirs: identity.protocol,
            });
        }
        Ok(identity)
    }

    fn with_token(&self, payload: &[u8]) -> Vec<u8> {
        let mut out = self.token.to_le_bytes().to_vec();
        out.extend_from_slice(payload);
        out
    }

    /// Downloads an image in chunks, calling `progress(sent, total)` after each, then commits
    /// it; `start` starts it once loaded. Returns whether retained values were carried over.
    pub async fn download(
        &mut self,
        image: &[u8],
        start: bool,
        mut progress: impl FnMut(usize, usize),
    ) -> Result<bool, OnlineError> {
        let hash: [u8; 32] = Sha256::digest(image).into();
        let mut begin = (image.len() as u32).to_le_bytes().to_vec();
        begin.extend_from_slice(&hash);
        let answer = self
            .call(service::DOWNLOAD_BEGIN, &self.with_token(&begin))
            .await?;
        let mut reader = Reader::new(&answer);
        let transfer = reader.u16().map_err(OnlineError::Protocol)?;
        let chunk_size =
            usize::from(reader.u16().map_err(OnlineError::Protocol)?).clamp(1, MAX_PAYLOAD - 10);
        let mut offset = 0usize;
        progress(0, image.len());
        while offset < image.len() {
            let end = (offset + chunk_size).min(image.len());
            let mut chunk = transfer.to_le_bytes().to_vec();
            chunk.extend_from_slice(&(offset as u32).to_le_bytes());
            chunk.extend_from_slice(&image[offset..end]);
            self.call(service::DOWNLOAD_CHUNK, &self.with_token(&chunk))
                .await?;
            offset = end;
            progress(offset, image.len());
        }
        let mut commit = transfer.to_le_bytes().to_vec();
        commit.push(u8::from(start));
        let answer = self
            .call(service::DOWNLOAD_COMMIT, &self.with_token(&commit))
            .await?;
        Ok(Reader::new(&answer).u8().map_err(OnlineError::Protocol)? != 0)
    }

    async fn control(&mut self, id: u8, extra: &[u8]) -> Result<TargetState, OnlineError> {
        let answer = self.call(id, &self.with_token(extra)).await?;
        TargetState::from_byte(Reader::new(&answer).u8().map_err(OnlineError::Protocol)?)
    }

    /// `START`.
    pub async fn start(&mut self) -> Result<TargetState, OnlineError> {
        self.control(service::START, &[]).await
    }

    /// `STOP`.
    pub async fn stop(&mut self) -> Result<TargetState, OnlineError> {
        self.control(service::STOP, &[]).await
    }

    /// `RESET`.
    pub async fn reset(&mut self, kind: Reset) -> Result<TargetState, OnlineError> {
        let byte = match kind {
            Reset::Warm => 0,
            Reset::Cold => 1,
            Reset::Origin => 2,
        };
        self.control(service::RESET, &[byte]).await
    }

    /// `RESOLVE`: where the variable `path` is and what type it has.
    pub async fn resolve(&mut self, path: &str) -> Result<Resolved, OnlineError> {
        let mut payload = Vec::new();
        put_str8(&mut payload, path);
        let answer = self.call(service::RESOLVE, &payload).await?;
        let mut reader = Reader::new(&answer);
        let parse = |reader: &mut Reader<'_>| -> Result<Resolved, String> {
            Ok(Resolved {
                place: Place::decode(reader)?,
                type_tag: reader.u8()?,
                length: reader.u16()?,
            })
        };
        parse(&mut reader).map_err(OnlineError::Protocol)
    }

    /// `READ`: one snapshot of `places`, split over several requests when they do not fit
    /// one (each part is then its own snapshot).
    pub async fn read(&mut self, places: &[Place]) -> Result<Snapshot, OnlineError> {
        let mut snapshot = Snapshot {
            cycle: 0,
            values: Vec::new(),
        };
        for batch in batches(places, |p| p.value_bytes(), 9, 8) {
            let mut payload = vec![batch.len() as u8];
            for place in batch {
                place.encode(&mut payload);
            }
            let answer = self.call(service::READ, &payload).await?;
            let mut reader = Reader::new(&answer);
            let parse = |reader: &mut Reader<'_>| -> Result<(u64, Vec<Value>), String> {
                let cycle = reader.u64()?;
                let forced = reader.take(batch.len().div_ceil(8))?.to_vec();
                let mut values = Vec::new();
                for (i, place) in batch.iter().enumerate() {
                    let bytes = reader.take(place.value_bytes())?.to_vec();
                    values.push((bytes, forced[i / 8] >> (i % 8) & 1 != 0));
                }
                Ok((cycle, values))
            };
            let (cycle, values) = parse(&mut reader).map_err(OnlineError::Protocol)?;
            snapshot.cycle = snapshot.cycle.max(cycle);
            snapshot.values.extend(values);
        }
        Ok(snapshot)
    }

    async fn place_values(
        &mut self,
        id: u8,
        values: &[(Place, Vec<u8>)],
    ) -> Result<(), OnlineError> {
        for batch in batches(values, |(p, v)| 8 + v.len().min(p.value_bytes()), 5, 0) {
            let mut payload = vec![batch.len() as u8];
            for (place, bytes) in batch {
                place.encode(&mut payload);
                payload.extend_from_slice(bytes);
            }
            self.call(id, &self.with_token(&payload)).await?;
        }
        Ok(())
    }

    /// `WRITE`: each value written once, between two cycles.
    pub async fn write(&mut self, values: &[(Place, Vec<u8>)]) -> Result<(), OnlineError> {
        self.place_values(service::WRITE, values).await
    }

    /// `FORCE`: each value held before and after every cycle until released.
    pub async fn force(&mut self, values: &[(Place, Vec<u8>)]) -> Result<(), OnlineError> {
        self.place_values(service::FORCE, values).await
    }

    /// `UNFORCE`: releases the forces of `places`, or every force when `places` is empty.
    pub async fn unforce(&mut self, places: &[Place]) -> Result<(), OnlineError> {
        if places.is_empty() {
            self.call(service::UNFORCE, &self.with_token(&[0])).await?;
            return Ok(());
        }
        for batch in batches(places, |_| 8, 5, 0) {
            let mut payload = vec![batch.len() as u8];
            for place in batch {
                place.encode(&mut payload);
            }
            self.call(service::UNFORCE, &self.with_token(&payload))
                .await?;
        }
        Ok(())
    }

    /// `FORCES`: every forced place with its value.
    pub async fn forces(&mut self) -> Result<Vec<(Place, Vec<u8>)>, OnlineError> {
        let mut all = Vec::new();
        loop {
            let answer = self
                .call(service::FORCES, &(all.len() as u16).to_le_bytes())
                .await?;
            let mut reader = Reader::new(&answer);
            let parse =
                |reader: &mut Reader<'_>, all: &mut Vec<(Place, Vec<u8>)>| -> Result<u16, String> {
                    let total = reader.u16()?;
                    let count = reader.u8()?;
                    for _ in 0..count {
                        let place = Place::decode(reader)?;
                        let bytes = reader.take(place.value_bytes())?.to_vec();
                        all.push((place, bytes));
                    }
                    Ok(total)
                };
            let before = all.len();
            let total = parse(&mut reader, &mut all).map_err(OnlineError::Protocol)?;
            if all.len() >= usize::from(total) || all.len() == before {
                return Ok(all);
            }
        }
    }

    /// `TRACE_CONFIGURE`: returns the bytes of one sample's values.
    pub async fn trace_configure(&mut self, config: &TraceConfig) -> Result<u16, OnlineError> {
        let mut payload = vec![config.task];
        payload.extend_from_slice(&config.every.max(1).to_le_bytes());
        payload.extend_from_slice(&config.samples.to_le_bytes());
        payload.push(config.pretrigger_percent.min(100));
        let (kind, place) = match config.trigger {
            Trigger::None => (0, None),
            Trigger::Rising(place) => (1, Some(place)),
            Trigger::Falling(place) => (2, Some(place)),
            Trigger::Level(place) => (3, Some(place)),
        };
        payload.push(kind);
        place
            .unwrap_or(Place {
                region: 0,
                offset: 0,
                bit: None,
                size: 1,
            })
            .encode(&mut payload);
        // As many places as fit this frame; the rest follow in TRACE_ADD frames.
        let first = config
            .places
            .len()
            .min((MAX_PAYLOAD - 4 - payload.len() - 1) / 8);
        payload.push(first as u8);
        for place in &config.places[..first] {
            place.encode(&mut payload);
        }
        let answer = self
            .call(service::TRACE_CONFIGURE, &self.with_token(&payload))
            .await?;
        let mut sample_bytes = Reader::new(&answer).u16().map_err(OnlineError::Protocol)?;
        for batch in config.places[first..].chunks((MAX_PAYLOAD - 4 - 1) / 8) {
            let mut payload = vec![batch.len() as u8];
            for place in batch {
                place.encode(&mut payload);
            }
            let answer = self
                .call(service::TRACE_ADD, &self.with_token(&payload))
                .await?;
            sample_bytes = Reader::new(&answer).u16().map_err(OnlineError::Protocol)?;
        }
        Ok(sample_bytes)
    }

    /// `TRACE_ARM`: recording starts.
    pub async fn trace_arm(&mut self) -> Result<(), OnlineError> {
        self.call(service::TRACE_ARM, &self.with_token(&[]))
            .await
            .map(|_| ())
    }

    /// `TRACE_STATUS`.
    pub async fn trace_status(&mut self) -> Result<TraceStatus, OnlineError> {
        let answer = self.call(service::TRACE_STATUS, &[]).await?;
        let mut reader = Reader::new(&answer);
        let parse = |reader: &mut Reader<'_>| -> Result<TraceStatus, String> {
            let state = reader.u8()?;
            let recorded = reader.u32()?;
            let trigger = reader.u32()?;
            Ok(TraceStatus {
                state,
                recorded,
                trigger_sample: (trigger != u32::MAX).then_some(trigger),
            })
        };
        parse(&mut reader).map_err(OnlineError::Protocol)
    }

    /// `TRACE_UPLOAD`: every recorded sample, oldest first; `places` are the configured ones.
    pub async fn trace_upload(
        &mut self,
        places: &[Place],
        mut progress: impl FnMut(usize),
    ) -> Result<Vec<Sample>, OnlineError> {
        let mut samples = Vec::new();
        loop {
            let answer = self
                .call(service::TRACE_UPLOAD, &(samples.len() as u32).to_le_bytes())
                .await?;
            let mut reader = Reader::new(&answer);
            let parse =
                |reader: &mut Reader<'_>, samples: &mut Vec<Sample>| -> Result<u8, String> {
                    let count = reader.u8()?;
                    for _ in 0..count {
                        let cycle = reader.u64()?;
                        let time_ns = reader.u64()?;
                        let values = places
                            .iter()
                            .map(|p| reader.take(p.value_bytes()).map(<[u8]>::to_vec))
                            .collect::<Result<_, _>>()?;
                        samples.push(Sample {
                            cycle,
                            time_ns,
                            values,
                        });
                    }
                    Ok(count)
                };
            let count = parse(&mut reader, &mut samples).map_err(OnlineError::Protocol)?;
            progress(samples.len());
            if count == 0 {
                return Ok(samples);
            }
        }
    }

    /// `TASKS`.
    pub async fn tasks(&mut self) -> Result<Vec<TaskInfo>, OnlineError> {
        let answer = self.call(service::TASKS, &[]).await?;
        let parse = || -> Result<Vec<TaskInfo>, String> {
            let mut reader = Reader::new(&answer);
            let count = reader.u8()?;
            (0..count)
                .map(|_| {
                    Ok(TaskInfo {
                        name: reader.str8()?,
                        cycles: reader.u64()?,
                        last_ns: reader.u64()?,
                        min_ns: reader.u64()?,
                        max_ns: reader.u64()?,
                        average_ns: reader.u64()?,
                        jitter_max_ns: reader.u64()?,
                        faulted: reader.u8()? != 0,
                    })
                })
                .collect()
        };
        parse().map_err(OnlineError::Protocol)
    }

    /// `FAULTS`: every fault the target recorded.
    pub async fn faults(&mut self) -> Result<Vec<Fault>, OnlineError> {
        let mut all = Vec::new();
        loop {
            let answer = self
                .call(service::FAULTS, &(all.len() as u16).to_le_bytes())
                .await?;
            let mut reader = Reader::new(&answer);
            let parse = |reader: &mut Reader<'_>, all: &mut Vec<Fault>| -> Result<u16, String> {
                let total = reader.u16()?;
                let count = reader.u8()?;
                for _ in 0..count {
                    all.push(Fault {
                        task: reader.str8()?,
                        kind: reader.str8()?,
                        pou: reader.str8()?,
                        file: reader.str8()?,
                        line: reader.u32()?,
                        cycle: reader.u64()?,
                    });
                }
                Ok(total)
            };
            let before = all.len();
            let total = parse(&mut reader, &mut all).map_err(OnlineError::Protocol)?;
            if all.len() >= usize::from(total) || all.len() == before {
                return Ok(all);
            }
        }
    }
}

/// Splits `items` into runs whose encoded size fits one request: `fixed` bytes of header,
/// `overhead` bytes per item on top of `size(item)`.
fn batches<T>(items: &[T], size: impl Fn(&T) -> usize, fixed: usize, overhead: usize) -> Vec<&[T]> {
    let mut out = Vec::new();
    let mut start = 0;
    let mut used = fixed;
    for (index, item) in items.iter().enumerate() {
        let cost = size(item) + overhead;
        if index > start && (used + cost > MAX_PAYLOAD - 4 || index - start == 255) {
            out.push(&items[start..index]);
            start = index;
            used = fixed;
        }
        used += cost;
    }
    if start < items.len() {
        out.push(&items[start..]);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn batches_fit_a_frame() {
        let items: Vec<usize> = vec![8; 100];
        let parts = batches(&items, |s| *s, 9, 8);
        assert!(parts.len() > 1);
        for part in &parts {
            assert!(9 + part.len() * 16 <= MAX_PAYLOAD);
        }
        assert_eq!(parts.iter().map(|p| p.len()).sum::<usize>(), 100);
        assert!(batches::<usize>(&[], |s| *s, 9, 8).is_empty());
    }
}
