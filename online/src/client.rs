//! An async client of one target: each method is one service of `docs/protocol.md` (or a
//! sequence of them), with the target's refusals turned into [`OnlineError`]s. Requests are
//! encoded and responses decoded only by `online_protocol`.

use std::borrow::Cow;
use std::net::SocketAddr;
use std::time::Duration;

use online_protocol::{
    CHUNK_HEADER_BYTES, DecodeError, Enumeration, FUNCTION_CODE, Fault, Identity, MAX_COUNT,
    MAX_PAYLOAD_BYTES, PLACE_BYTES, PROTOCOL_VERSION, Place, Refusal, Request, ResetKind, Resolved,
    Response, Snapshot, Status, TOKEN_BYTES, TRACE_ADD_PLACES, TRACE_CONFIGURE_PLACES, TargetState,
    TaskInfo, TraceSample, TraceStatus, TriggerKind,
};
use sha2::{Digest, Sha256};
use tokio_modbus::client::{Client as _, Context};
use tokio_modbus::{Request as ModbusRequest, Response as ModbusResponse};

use crate::error::OnlineError;

mod modbus_devices;
mod online_change;

/// How long one request may take before the client gives up.
pub const REQUEST_TIMEOUT: Duration = Duration::from_secs(5);

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

/// Places with the values to write or force at them.
type PlaceValues = Vec<(Place, Vec<u8>)>;

/// The bytes of a `READ` answer before its values: the cycle and one bitmap byte.
const READ_FIXED_BYTES: usize = 9;
/// The bytes of a `WRITE`, `FORCE` or `UNFORCE` request before its places: the token (in the
/// payload's limit) and the count.
const VALUES_FIXED_BYTES: usize = TOKEN_BYTES + 1;

/// A connection to one target.
pub struct Client {
    address: SocketAddr,
    context: Context,
    /// The token of `LOGIN`, 0 without a password; the debugging services carry it too.
    pub(crate) token: u128,
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
            let login = Request::Login {
                password: password.to_owned(),
            };
            client.token = match client.call(&login).await? {
                Response::Login { token } => token,
                other => return Err(unexpected(&other)),
            };
        }
        Ok((client, identity))
    }

    /// The address connected to.
    pub fn address(&self) -> SocketAddr {
        self.address
    }

    /// Whether the client holds a token from a login with a password (which `LOGOUT` ends).
    pub fn is_logged_in(&self) -> bool {
        self.token != 0
    }

    /// One service: the request out, the answer of the same service back.
    pub(crate) async fn call(&mut self, request: &Request) -> Result<Response, OnlineError> {
        let frame = request.encode();
        if frame.len() > MAX_PAYLOAD_BYTES + 1 {
            return Err(OnlineError::Protocol(format!(
                "a request of {} bytes does not fit a frame",
                frame.len()
            )));
        }
        let call = self
            .context
            .call(ModbusRequest::Custom(FUNCTION_CODE, Cow::Owned(frame)));
        let answer = match tokio::time::timeout(REQUEST_TIMEOUT, call).await {
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
        let ModbusResponse::Custom(FUNCTION_CODE, bytes) = answer else {
            return Err(OnlineError::Protocol(
                "an answer of another function code".to_owned(),
            ));
        };
        Response::decode(request, &bytes)
            .map_err(protocol_error)?
            .map_err(|refusal| match request {
                Request::Debug(debug) => crate::debug_client::debug_refused(debug, refusal),
                // A runtime older than the service answers it as unknown (status 1).
                Request::ModbusDevices { .. } if refusal.status == Status::UnknownService => {
                    OnlineError::ModbusDevicesNotReported
                }
                _ => refused(refusal),
            })
    }

    /// `IDENTIFY`.
    pub async fn identify(&mut self) -> Result<Identity, OnlineError> {
        let request = Request::Identify {
            protocol: PROTOCOL_VERSION,
        };
        let identity = match self.call(&request).await? {
            Response::Identify(identity) => identity,
            other => return Err(unexpected(&other)),
        };
        if identity.protocol != PROTOCOL_VERSION {
            return Err(OnlineError::VersionMismatch {
                ours: PROTOCOL_VERSION,
                theirs: identity.protocol,
            });
        }
        Ok(identity)
    }

    /// Downloads an image in chunks, calling `progress(sent, total)` after each, then commits
    /// it; `start` starts it once loaded. Returns whether retained values were carried over.
    pub async fn download(
        &mut self,
        image: &[u8],
        start: bool,
        progress: impl FnMut(usize, usize),
    ) -> Result<bool, OnlineError> {
        let transfer = self.transfer(image, progress).await?;
        self.commit(transfer, start).await
    }

    /// `DOWNLOAD_BEGIN` and `DOWNLOAD_CHUNK`s: transfers `image` without loading it, telling
    /// `progress` the bytes sent of all; returns the transfer's number, for
    /// [`Client::commit`] or an online change ([`Client::online_change_check`]).
    pub async fn transfer(
        &mut self,
        image: &[u8],
        mut progress: impl FnMut(usize, usize),
    ) -> Result<u16, OnlineError> {
        let begin = Request::DownloadBegin {
            token: self.token,
            size: image.len() as u32,
            hash: Sha256::digest(image).into(),
        };
        let (transfer, chunk_size) = match self.call(&begin).await? {
            Response::DownloadBegin {
                transfer,
                chunk_size,
            } => (transfer, chunk_size),
            other => return Err(unexpected(&other)),
        };
        let chunk_size = usize::from(chunk_size).clamp(1, MAX_PAYLOAD_BYTES - CHUNK_HEADER_BYTES);
        let mut offset = 0usize;
        progress(0, image.len());
        while offset < image.len() {
            let end = (offset + chunk_size).min(image.len());
            let chunk = Request::DownloadChunk {
                token: self.token,
                transfer,
                offset: offset as u32,
                bytes: image[offset..end].to_vec(),
            };
            self.call(&chunk).await?;
            offset = end;
            progress(offset, image.len());
        }
        Ok(transfer)
    }

    /// `DOWNLOAD_COMMIT` of a transfer: the image replaces the running program (started when
    /// `start`); returns whether RETAIN and PERSISTENT values were carried over.
    pub async fn commit(&mut self, transfer: u16, start: bool) -> Result<bool, OnlineError> {
        let commit = Request::DownloadCommit {
            token: self.token,
            transfer,
            start,
        };
        match self.call(&commit).await? {
            Response::DownloadCommit { retained } => Ok(retained),
            other => Err(unexpected(&other)),
        }
    }

    /// `START`.
    pub async fn start(&mut self) -> Result<TargetState, OnlineError> {
        match self.call(&Request::Start { token: self.token }).await? {
            Response::Start { state } => Ok(state),
            other => Err(unexpected(&other)),
        }
    }

    /// `LOGOUT`: the token of this connection ends; changing the target needs a new
    /// connection with the password. Closing the connection ends it too.
    pub async fn logout(&mut self) -> Result<(), OnlineError> {
        match self.call(&Request::Logout).await? {
            Response::Logout => {
                self.token = 0;
                Ok(())
            }
            other => Err(unexpected(&other)),
        }
    }

    /// `STOP`.
    pub async fn stop(&mut self) -> Result<TargetState, OnlineError> {
        match self.call(&Request::Stop { token: self.token }).await? {
            Response::Stop { state } => Ok(state),
            other => Err(unexpected(&other)),
        }
    }

    /// `RESET`.
    pub async fn reset(&mut self, kind: ResetKind) -> Result<TargetState, OnlineError> {
        let request = Request::Reset {
            token: self.token,
            kind,
        };
        match self.call(&request).await? {
            Response::Reset { state } => Ok(state),
            other => Err(unexpected(&other)),
        }
    }

    /// `RESOLVE`: where the variable `path` is and what type it has.
    pub async fn resolve(&mut self, path: &str) -> Result<Resolved, OnlineError> {
        let request = Request::Resolve {
            path: path.to_owned(),
        };
        match self.call(&request).await? {
            Response::Resolve(resolved) => Ok(resolved),
            other => Err(unexpected(&other)),
        }
    }

    /// `ENUMERATION`: the values of the enumeration type of the variable `path` (one whose
    /// `RESOLVE` type is [`online_protocol::TYPE_ENUM`]), gathered over as many requests as
    /// they need.
    pub async fn enumeration(&mut self, path: &str) -> Result<Enumeration, OnlineError> {
        let mut all = Enumeration {
            base: 0,
            values: Vec::new(),
        };
        loop {
            let request = Request::Enumeration {
                path: path.to_owned(),
                from: u16::try_from(all.values.len()).unwrap_or(u16::MAX),
            };
            let (base, total, values) = match self.call(&request).await? {
                Response::Enumeration {
                    base,
                    total,
                    values,
                } => (base, total, values),
                other => return Err(unexpected(&other)),
            };
            all.base = base;
            let before = all.values.len();
            all.values.extend(values);
            if all.values.len() >= usize::from(total) || all.values.len() == before {
                return Ok(all);
            }
        }
    }

    /// `READ`: one snapshot of `places`, split over several requests when they do not fit
    /// one (each part is then its own snapshot).
    pub async fn read(&mut self, places: &[Place]) -> Result<Snapshot, OnlineError> {
        let mut snapshot = Snapshot {
            cycle: 0,
            values: Vec::new(),
        };
        for batch in batches(places, Place::value_bytes, READ_FIXED_BYTES, PLACE_BYTES) {
            let request = Request::Read {
                places: batch.to_vec(),
            };
            let part = match self.call(&request).await? {
                Response::Read(part) => part,
                other => return Err(unexpected(&other)),
            };
            snapshot.cycle = snapshot.cycle.max(part.cycle);
            snapshot.values.extend(part.values);
        }
        Ok(snapshot)
    }

    /// `WRITE` or `FORCE` of `values`, split over as many requests as they need.
    async fn place_values(
        &mut self,
        request: fn(u128, PlaceValues) -> Request,
        values: &[(Place, Vec<u8>)],
    ) -> Result<(), OnlineError> {
        let size =
            |(place, value): &(Place, Vec<u8>)| PLACE_BYTES + value.len().min(place.value_bytes());
        for batch in batches(values, size, VALUES_FIXED_BYTES, 0) {
            self.call(&request(self.token, batch.to_vec())).await?;
        }
        Ok(())
    }

    /// `WRITE`: each value written once, between two cycles.
    pub async fn write(&mut self, values: &[(Place, Vec<u8>)]) -> Result<(), OnlineError> {
        let write = |token, values| Request::Write { token, values };
        self.place_values(write, values).await
    }

    /// `FORCE`: each value held before and after every cycle until released.
    pub async fn force(&mut self, values: &[(Place, Vec<u8>)]) -> Result<(), OnlineError> {
        let force = |token, values| Request::Force { token, values };
        self.place_values(force, values).await
    }

    /// `UNFORCE`: releases the forces of `places`, or every force when `places` is empty.
    pub async fn unforce(&mut self, places: &[Place]) -> Result<(), OnlineError> {
        if places.is_empty() {
            let all = Request::Unforce {
                token: self.token,
                places: Vec::new(),
            };
            self.call(&all).await?;
            return Ok(());
        }
        for batch in batches(places, |_| PLACE_BYTES, VALUES_FIXED_BYTES, 0) {
            let request = Request::Unforce {
                token: self.token,
                places: batch.to_vec(),
            };
            self.call(&request).await?;
        }
        Ok(())
    }

    /// `FORCES`: every forced place with its value.
    pub async fn forces(&mut self) -> Result<Vec<(Place, Vec<u8>)>, OnlineError> {
        let mut all = Vec::new();
        loop {
            let request = Request::Forces {
                from: all.len() as u16,
            };
            let (total, forces) = match self.call(&request).await? {
                Response::Forces { total, forces } => (total, forces),
                other => return Err(unexpected(&other)),
            };
            let before = all.len();
            all.extend(forces);
            if all.len() >= usize::from(total) || all.len() == before {
                return Ok(all);
            }
        }
    }

    /// `TRACE_CONFIGURE`, and `TRACE_ADD` for the places that do not fit its frame: returns the
    /// bytes of one sample's values.
    pub async fn trace_configure(&mut self, config: &TraceConfig) -> Result<u16, OnlineError> {
        let (trigger, trigger_place) = match config.trigger {
            Trigger::None => (TriggerKind::None, None),
            Trigger::Rising(place) => (TriggerKind::Rising, Some(place)),
            Trigger::Falling(place) => (TriggerKind::Falling, Some(place)),
            Trigger::Level(place) => (TriggerKind::WhileTrue, Some(place)),
        };
        // Without a trigger the place is sent all the same, and ignored.
        let trigger_place = trigger_place.unwrap_or(Place {
            region: 0,
            offset: 0,
            bit: None,
            size: 1,
        });
        let first = config.places.len().min(TRACE_CONFIGURE_PLACES);
        let configure = Request::TraceConfigure {
            token: self.token,
            config: online_protocol::TraceConfig {
                task: config.task,
                every: config.every.max(1),
                samples: config.samples,
                pretrigger: config.pretrigger_percent.min(100),
                trigger,
                trigger_place,
                places: config.places[..first].to_vec(),
            },
        };
        let mut sample_bytes = match self.call(&configure).await? {
            Response::TraceConfigure { sample_bytes } => sample_bytes,
            other => return Err(unexpected(&other)),
        };
        for batch in config.places[first..].chunks(TRACE_ADD_PLACES) {
            let add = Request::TraceAdd {
                token: self.token,
                places: batch.to_vec(),
            };
            sample_bytes = match self.call(&add).await? {
                Response::TraceAdd { sample_bytes } => sample_bytes,
                other => return Err(unexpected(&other)),
            };
        }
        Ok(sample_bytes)
    }

    /// `TRACE_ARM`: recording starts.
    pub async fn trace_arm(&mut self) -> Result<(), OnlineError> {
        self.call(&Request::TraceArm { token: self.token })
            .await
            .map(|_| ())
    }

    /// `TRACE_STATUS`.
    pub async fn trace_status(&mut self) -> Result<TraceStatus, OnlineError> {
        match self.call(&Request::TraceStatus).await? {
            Response::TraceStatus(status) => Ok(status),
            other => Err(unexpected(&other)),
        }
    }

    /// `TRACE_UPLOAD`: every recorded sample, oldest first; `places` are the configured ones.
    pub async fn trace_upload(
        &mut self,
        places: &[Place],
        mut progress: impl FnMut(usize),
    ) -> Result<Vec<Sample>, OnlineError> {
        let mut samples = Vec::new();
        loop {
            let uploaded = self.trace_upload_from(places, samples.len() as u32).await?;
            let count = uploaded.len();
            samples.extend(uploaded);
            progress(samples.len());
            if count == 0 {
                return Ok(samples);
            }
        }
    }

    /// One `TRACE_UPLOAD`: the recorded samples from the `from`-th on that fit one answer
    /// (none when there are no more yet), so that a trace still recording can be fetched as it
    /// grows; `places` are the configured ones.
    pub async fn trace_upload_from(
        &mut self,
        places: &[Place],
        from: u32,
    ) -> Result<Vec<Sample>, OnlineError> {
        let uploaded = match self.call(&Request::TraceUpload { from }).await? {
            Response::TraceUpload { samples } => samples,
            other => return Err(unexpected(&other)),
        };
        uploaded
            .into_iter()
            .map(|sample| split_sample(sample, places))
            .collect()
    }

    /// `TASKS`.
    pub async fn tasks(&mut self) -> Result<Vec<TaskInfo>, OnlineError> {
        match self.call(&Request::Tasks).await? {
            Response::Tasks { tasks } => Ok(tasks),
            other => Err(unexpected(&other)),
        }
    }

    /// `FAULTS`: every fault the target recorded.
    pub async fn faults(&mut self) -> Result<Vec<Fault>, OnlineError> {
        let mut all = Vec::new();
        loop {
            let request = Request::Faults {
                from: all.len() as u16,
            };
            let (total, faults) = match self.call(&request).await? {
                Response::Faults { total, faults } => (total, faults),
                other => return Err(unexpected(&other)),
            };
            let before = all.len();
            all.extend(faults);
            if all.len() >= usize::from(total) || all.len() == before {
                return Ok(all);
            }
        }
    }
}

/// A sample's values split by `places`, which must take exactly its bytes.
fn split_sample(sample: TraceSample, places: &[Place]) -> Result<Sample, OnlineError> {
    let needed: usize = places.iter().map(Place::value_bytes).sum();
    if needed != sample.values.len() {
        return Err(OnlineError::Protocol(format!(
            "a trace sample of {} bytes, but the configured places take {needed}",
            sample.values.len()
        )));
    }
    let mut rest = sample.values.as_slice();
    let values = places
        .iter()
        .map(|place| {
            let (value, after) = rest.split_at(place.value_bytes());
            rest = after;
            value.to_vec()
        })
        .collect();
    Ok(Sample {
        cycle: sample.cycle,
        time_ns: sample.time_ns,
        values,
    })
}

/// A response that does not follow the protocol.
fn protocol_error(error: DecodeError) -> OnlineError {
    OnlineError::Protocol(error.to_string())
}

/// A refusal as the error that says what to do about it.
fn refused(refusal: Refusal) -> OnlineError {
    let Refusal { status, message } = refusal;
    match status {
        Status::PasswordRequired => OnlineError::PasswordRequired,
        Status::WrongPassword => OnlineError::WrongPassword(message),
        Status::ImageRefused => OnlineError::ImageRefused(message),
        Status::UnknownSymbol => OnlineError::UnknownSymbol(message),
        _ => OnlineError::Rejected(message),
    }
}

/// An answer of another service than asked: `Response::decode` never gives one, as it
/// decodes the answer of the request's service, but the client does not rely on it.
pub(crate) fn unexpected(response: &Response) -> OnlineError {
    OnlineError::Protocol(format!(
        "an answer of service {:?} where another was expected",
        response.service()
    ))
}

/// Splits `items` into runs whose encoded size fits one request: `fixed` bytes of header,
/// `overhead` bytes per item on top of `size(item)`.
fn batches<T>(items: &[T], size: impl Fn(&T) -> usize, fixed: usize, overhead: usize) -> Vec<&[T]> {
    let mut out = Vec::new();
    let mut start = 0;
    let mut used = fixed;
    for (index, item) in items.iter().enumerate() {
        let cost = size(item) + overhead;
        if index > start
            && (used + cost > MAX_PAYLOAD_BYTES - TOKEN_BYTES || index - start == MAX_COUNT)
        {
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
        let parts = batches(&items, |s| *s, READ_FIXED_BYTES, PLACE_BYTES);
        assert!(parts.len() > 1);
        for part in &parts {
            assert!(9 + part.len() * 16 <= MAX_PAYLOAD_BYTES);
        }
        assert_eq!(parts.iter().map(|p| p.len()).sum::<usize>(), 100);
        assert!(batches::<usize>(&[], |s| *s, 9, 8).is_empty());
    }
}
