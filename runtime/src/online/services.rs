//! The online services on a scheduler, as the Modbus server's hook for function code 0x64.

use std::collections::VecDeque;
use std::hash::{BuildHasher, Hasher};
use std::sync::{Arc, Mutex, MutexGuard, PoisonError};
use std::time::{Duration, Instant};

use program_image::{Region, TypeDef};
use sha2::{Digest, Sha256};

use super::codec::{
    self, FUNCTION_CODE, MAX_PAYLOAD_BYTES, PROTOCOL_VERSION, Refusal, Request, Status,
    TraceConfig, TriggerKind, put_place, put_str8,
};
use super::download::{CHUNK_BYTES, Transfer};
use super::place::{NO_BIT, WirePlace};
use super::trace::{MAX_TRACE_BYTES, Trace};
use crate::engine::ResetKind;
use crate::modbus::{
    ConnectionClosed, CustomFunctions, ExceptionCode, MapSlot, ModbusMap, current_connection,
};
use crate::retain::RetainRestore;
use crate::scheduler::{Between, Scheduler, SchedulerError, SchedulerState};
use crate::value;

/// The most tokens kept; a login beyond them forgets the oldest, so that logins cannot fill
/// the memory.
pub const MAX_TOKENS: usize = 256;

/// How long after a wrong password every login is refused unchecked, so passwords can be
/// guessed at most five times a second, without holding up the server.
pub const WRONG_PASSWORD_DELAY: Duration = Duration::from_millis(200);

/// The online services of one runtime: lives as long as its Modbus server; nothing of it is
/// saved (tokens end with the process).
pub struct OnlineServices {
    scheduler: Arc<Scheduler>,
    /// The password that changing services need; `None` lets everyone change the target.
    password: Option<String>,
    /// The tokens given out by `LOGIN` with the password, oldest first (at most
    /// [`MAX_TOKENS`]); without a password none are kept, as any token is accepted.
    tokens: Mutex<VecDeque<u32>>,
    /// The download in progress, if any.
    transfer: Mutex<Option<Transfer>>,
    /// When the last wrong password came.
    last_wrong_password: Mutex<Option<Instant>>,
    /// The number of the last transfer begun.
    last_transfer: Mutex<u16>,
    /// The Modbus server's map, replaced by the downloaded image's; `None` keeps the server's.
    map: Option<Arc<MapSlot>>,
}

impl OnlineServices {
    /// The services on `scheduler`, with `password` required for the changing ones if given.
    pub fn new(scheduler: Arc<Scheduler>, password: Option<String>) -> Self {
        Self {
            scheduler,
            password,
            tokens: Mutex::new(VecDeque::new()),
            transfer: Mutex::new(None),
            last_wrong_password: Mutex::new(None),
            last_transfer: Mutex::new(0),
            map: None,
        }
    }

    /// The same services, replacing the map in `slot` with a downloaded image's own map (or
    /// the default map) when the image is loaded.
    pub fn with_map(mut self, slot: Arc<MapSlot>) -> Self {
        self.map = Some(slot);
        self
    }

    /// The hook for [`crate::modbus::ServerOptions::custom`]: function code 0x64 goes to
    /// [`OnlineServices::respond`], any other gets exception 1.
    pub fn handler(self: &Arc<Self>) -> CustomFunctions {
        let services = Arc::clone(self);
        Arc::new(move |function, data| {
            if function != FUNCTION_CODE {
                return Err(ExceptionCode::IllegalFunction);
            }
            services.respond(data)
        })
    }

    /// The hook for [`crate::modbus::ServerOptions::closed`]: a transfer ends with the
    /// connection that began it.
    pub fn closed_handler(self: &Arc<Self>) -> ConnectionClosed {
        let services = Arc::clone(self);
        Arc::new(move |connection| {
            let mut transfer = lock(&services.transfer);
            if transfer
                .as_ref()
                .is_some_and(|active| active.owner == Some(connection))
            {
                *transfer = None;
            }
        })
    }

    /// The response (after the function code) to a request (after the function code).
    ///
    /// A request without a service byte gets exception 3. For [`WRONG_PASSWORD_DELAY`] after a
    /// wrong password, logins are refused without being checked.
    pub fn respond(&self, request: &[u8]) -> Result<Vec<u8>, ExceptionCode> {
        let Some((&service, payload)) = request.split_first() else {
            return Err(ExceptionCode::IllegalDataValue);
        };
        let answer = codec::parse_request(service, payload).and_then(|request| {
            if let Some(token) = request.token() {
                self.authorize(token)?;
            }
            self.serve(request)
        });
        let mut body = match answer {
            Ok(payload) => codec::done(service, &payload),
            Err(refusal) => codec::refused(service, &refusal),
        };
        if body.len() > MAX_PAYLOAD_BYTES + 2 {
            body = codec::refused(
                service,
                &codec::bad("the answer does not fit one response".to_owned()),
            );
        }
        Ok(body)
    }

    fn authorize(&self, token: u32) -> Result<(), Refusal> {
        if self.password.is_none() {
            return Ok(());
        }
        if token == 0 {
            return Err(Refusal {
                status: Status::PasswordRequired,
                message: "the runtime has a password: log in first".to_owned(),
            });
        }
        if lock(&self.tokens).contains(&token) {
            Ok(())
        } else {
            Err(Refusal {
                status: Status::WrongPassword,
                message: "the token is not valid: log in again".to_owned(),
            })
        }
    }

    fn serve(&self, request: Request) -> Result<Vec<u8>, Refusal> {
        match request {
            Request::Identify { protocol } => self.identify(protocol),
            Request::Login { password } => self.login(&password),
            Request::DownloadBegin { size, hash, .. } => {
                let mut last = lock(&self.last_transfer);
                *last = last.wrapping_add(1).max(1);
                let mut transfer = Transfer::begin(*last, size, hash, Instant::now())?;
                transfer.owner = current_connection();
                *lock(&self.transfer) = Some(transfer);
                let mut out = last.to_le_bytes().to_vec();
                out.extend_from_slice(&CHUNK_BYTES.to_le_bytes());
                Ok(out)
            }
            Request::DownloadChunk {
                transfer,
                offset,
                bytes,
                ..
            } => {
                let mut current = lock(&self.transfer);
                let active = current_transfer(&mut current, transfer)?;
                let received = active.chunk(offset, &bytes, Instant::now())?;
                Ok(received.to_le_bytes().to_vec())
            }
            Request::DownloadCommit {
                transfer, start, ..
            } => self.commit(transfer, start),
            Request::DownloadAbort { transfer, .. } => {
                let mut current = lock(&self.transfer);
                if current.as_ref().is_some_and(|active| active.id == transfer) {
                    *current = None;
                }
                Ok(Vec::new())
            }
            Request::Start { .. } => {
                self.scheduler.start().map_err(scheduler_refusal)?;
                Ok(vec![self.state()])
            }
            Request::Stop { .. } => {
                self.scheduler.stop().map_err(scheduler_refusal)?;
                Ok(vec![self.state()])
            }
            Request::Reset { kind, .. } => {
                let kind = match kind {
                    0 => ResetKind::Warm,
                    1 => ResetKind::Cold,
                    2 => ResetKind::Origin,
                    other => {
                        return Err(codec::bad(format!("reset kind {other}: 0 to 2 expected")));
                    }
                };
                self.scheduler.reset(kind).map_err(scheduler_refusal)?;
                Ok(vec![self.state()])
            }
            Request::Resolve { path } => self.between(move |between| resolve(between, &path)),
            Request::Read { places } => self.between(move |between| read(between, &places)),
            Request::Write { values, .. } => self.between(move |between| {
                let memory = between.memory.as_mut().ok_or_else(no_program)?;
                for (place, _) in &values {
                    memory.check(*place)?;
                }
                for (place, value) in &values {
                    memory.write(*place, value);
                }
                Ok(Vec::new())
            }),
            Request::Force { values, .. } => self.between(move |between| {
                let memory = between.memory.as_mut().ok_or_else(no_program)?;
                for (place, _) in &values {
                    memory.check(*place)?;
                }
                for (place, value) in values {
                    memory.write(place, &value);
                    between.forces.set(place, value);
                }
                Ok(Vec::new())
            }),
            Request::Unforce { places, .. } => self.between(move |between| {
                if places.is_empty() {
                    between.forces.clear();
                }
                for place in places {
                    between.forces.release(place);
                }
                Ok(Vec::new())
            }),
            Request::Forces { from } => self.between(move |between| {
                let entries = between.forces.entries();
                let mut out = u16::try_from(entries.len())
                    .unwrap_or(u16::MAX)
                    .to_le_bytes()
                    .to_vec();
                out.push(0);
                let mut count = 0u8;
                for (place, value) in entries.iter().skip(usize::from(from)) {
                    if out.len() + 8 + value.len() > MAX_PAYLOAD_BYTES || count == u8::MAX {
                        break;
                    }
                    put_place(&mut out, *place);
                    out.extend_from_slice(value);
                    count += 1;
                }
                out[2] = count;
                Ok(out)
            }),
            Request::TraceConfigure { config, .. } => {
                self.between(move |between| configure_trace(between, config))
            }
            Request::TraceAdd { places, .. } => self.between(move |between| {
                // More places than one TRACE_CONFIGURE frame holds are added before arming.
                let mut config = between
                    .trace
                    .pending_config()
                    .cloned()
                    .ok_or_else(|| not_now("configure the trace before adding places"))?;
                config.places.extend(places);
                configure_trace(between, config)
            }),
            Request::TraceArm { .. } => self.between(|between| {
                if between.trace.arm() {
                    Ok(Vec::new())
                } else {
                    Err(not_now("the trace is not configured"))
                }
            }),
            Request::TraceStatus => self.between(|between| {
                let (state, recorded, trigger) = between.trace.status();
                let mut out = vec![state as u8];
                out.extend_from_slice(&recorded.to_le_bytes());
                out.extend_from_slice(&trigger.unwrap_or(u32::MAX).to_le_bytes());
                Ok(out)
            }),
            Request::TraceUpload { from } => {
                self.between(move |between| Ok(upload(between.trace, from)))
            }
            Request::Tasks => Ok(self.tasks()),
            Request::Faults { from } => Ok(self.faults(from)),
        }
    }

    fn identify(&self, protocol: u16) -> Result<Vec<u8>, Refusal> {
        if protocol != PROTOCOL_VERSION {
            return Err(Refusal {
                status: Status::VersionMismatch,
                message: format!(
                    "the client speaks protocol version {protocol}, this runtime version {PROTOCOL_VERSION}"
                ),
            });
        }
        let project = self.between(|between| {
            Ok(between
                .memory
                .as_ref()
                .map(|memory| memory.engine.image().info.project.clone())
                .unwrap_or_default())
        })?;
        let status = self.scheduler.status();
        let mut out = PROTOCOL_VERSION.to_le_bytes().to_vec();
        put_str8(&mut out, env!("CARGO_PKG_VERSION"));
        out.push(self.state());
        out.extend_from_slice(&status.image.unwrap_or([0; 32]));
        put_str8(&mut out, &project);
        out.push(u8::from(self.password.is_some()));
        Ok(out)
    }

    fn login(&self, password: &str) -> Result<Vec<u8>, Refusal> {
        let Some(expected) = &self.password else {
            return Ok(random_token().to_le_bytes().to_vec());
        };
        // Comparing digests takes the same time whatever the password and its length.
        let given: [u8; 32] = Sha256::digest(password.as_bytes()).into();
        let expected: [u8; 32] = Sha256::digest(expected.as_bytes()).into();
        let difference = given
            .iter()
            .zip(&expected)
            .fold(0u8, |difference, (a, b)| difference | (a ^ b));
        let mut last_wrong = lock(&self.last_wrong_password);
        if last_wrong.is_some_and(|at| at.elapsed() < WRONG_PASSWORD_DELAY) {
            return Err(Refusal {
                status: Status::WrongPassword,
                message: "too soon after a wrong password; try again in a moment".to_owned(),
            });
        }
        if difference != 0 {
            *last_wrong = Some(Instant::now());
            return Err(Refusal {
                status: Status::WrongPassword,
                message: "wrong password".to_owned(),
            });
        }
        let mut tokens = lock(&self.tokens);
        let token = loop {
            let token = random_token();
            if !tokens.contains(&token) {
                break token;
            }
        };
        if tokens.len() >= MAX_TOKENS {
            tokens.pop_front();
        }
        tokens.push_back(token);
        Ok(token.to_le_bytes().to_vec())
    }

    fn commit(&self, transfer: u16, start: bool) -> Result<Vec<u8>, Refusal> {
        let active = {
            let mut current = lock(&self.transfer);
            current_transfer(&mut current, transfer)?;
            current.take()
        };
        let image = active
            .ok_or_else(|| not_now("no download is in progress"))?
            .finish()?;
        let refused = |message: String| Refusal {
            status: Status::ImageRefused,
            message,
        };
        // The map is checked before loading, so that a refused map changes nothing.
        let map = ModbusMap::for_image(&image)
            .map_err(|error| refused(format!("the image's Modbus map is refused: {error}")))?;
        let report = self
            .scheduler
            .load(image)
            .map_err(|error| refused(error.to_string()))?;
        if let Some(slot) = &self.map {
            slot.set(map);
        }
        if start {
            self.scheduler.start().map_err(scheduler_refusal)?;
        }
        let retained =
            report.carried > 0 || matches!(report.retain, Some(RetainRestore::Restored { .. }));
        Ok(vec![u8::from(retained)])
    }

    fn tasks(&self) -> Vec<u8> {
        let status = self.scheduler.status();
        let mut out = vec![0];
        for task in status.tasks.iter().take(usize::from(u8::MAX)) {
            let mut entry = Vec::new();
            put_str8(&mut entry, &task.name);
            for number in [
                task.cycles,
                task.last_cycle_ns,
                task.min_cycle_ns,
                task.max_cycle_ns,
                task.average_cycle_ns(),
                task.max_jitter_ns,
            ] {
                entry.extend_from_slice(&number.to_le_bytes());
            }
            entry.push(u8::from(task.faulted));
            // The tasks that do not fit one response are left out.
            if out.len() + entry.len() > MAX_PAYLOAD_BYTES {
                break;
            }
            out.extend_from_slice(&entry);
            out[0] += 1;
        }
        out
    }

    fn faults(&self, from: u16) -> Vec<u8> {
        let status = self.scheduler.status();
        let mut out = u16::try_from(status.faults.len())
            .unwrap_or(u16::MAX)
            .to_le_bytes()
            .to_vec();
        out.push(0);
        for fault in status.faults.iter().skip(usize::from(from)) {
            let mut entry = Vec::new();
            // Texts are cut so that one fault always fits a response.
            for text in [
                fault.task.as_str(),
                &fault.kind.to_string(),
                &fault.pou,
                fault.file.as_deref().unwrap_or(""),
            ] {
                put_str8(&mut entry, cut(text, 48));
            }
            entry.extend_from_slice(&fault.line.unwrap_or(0).to_le_bytes());
            entry.extend_from_slice(&fault.cycle.to_le_bytes());
            if out.len() + entry.len() > MAX_PAYLOAD_BYTES || out[2] == u8::MAX {
                break;
            }
            out.extend_from_slice(&entry);
            out[2] += 1;
        }
        out
    }

    /// The state as `IDENTIFY` and run control send it.
    fn state(&self) -> u8 {
        let status = self.scheduler.status();
        match (status.image, status.state) {
            (None, _) => 0,
            (Some(_), SchedulerState::Stopped) => 1,
            (Some(_), SchedulerState::Running) => 2,
            (Some(_), SchedulerState::Faulted) => 3,
        }
    }

    /// Runs `action` between two cycles.
    fn between<T: Send + 'static>(
        &self,
        action: impl FnOnce(&mut Between<'_>) -> Result<T, Refusal> + Send + 'static,
    ) -> Result<T, Refusal> {
        self.scheduler.between(action).map_err(scheduler_refusal)?
    }
}

/// The transfer `id`, dropping one that has expired.
fn current_transfer(current: &mut Option<Transfer>, id: u16) -> Result<&mut Transfer, Refusal> {
    if current
        .as_ref()
        .is_some_and(|active| active.expired(Instant::now()))
    {
        *current = None;
    }
    match current {
        Some(active) if active.id == id => Ok(active),
        _ => Err(not_now(&format!(
            "transfer {id} does not exist (expired, aborted or replaced): begin again"
        ))),
    }
}

fn resolve(between: &mut Between<'_>, path: &str) -> Result<Vec<u8>, Refusal> {
    let memory = between.memory.as_ref().ok_or_else(no_program)?;
    let image = memory.engine.image();
    let place = value::resolve(image, path).map_err(|error| Refusal {
        status: Status::UnknownSymbol,
        message: error.to_string(),
    })?;
    let ty = image.types.get(place.ty as usize);
    let (tag, length) = match ty {
        Some(TypeDef::Elementary(elementary)) => (*elementary as u8, 0),
        Some(TypeDef::String { length }) => (0x20, *length),
        Some(TypeDef::WString { length }) => (0x21, *length),
        _ => (0xFF, 0),
    };
    let size = match (place.bit, ty) {
        (Some(_), _) => 1,
        (None, Some(ty)) => ty.size_bytes(&image.types),
        (None, None) => 0,
    };
    let region = match place.region {
        Region::Data => 0,
        Region::Input => 1,
        Region::Output => 2,
        Region::Memory => 3,
    };
    let mut out = Vec::new();
    put_place(
        &mut out,
        WirePlace {
            region,
            offset: u32::try_from(place.offset).unwrap_or(u32::MAX),
            bit: place.bit.unwrap_or(NO_BIT),
            // A value larger than a u16 cannot be read in one piece anyway.
            size: u16::try_from(size).unwrap_or(u16::MAX),
        },
    );
    out.push(tag);
    out.extend_from_slice(&u16::try_from(length).unwrap_or(u16::MAX).to_le_bytes());
    Ok(out)
}

fn read(between: &mut Between<'_>, places: &[WirePlace]) -> Result<Vec<u8>, Refusal> {
    let memory = between.memory.as_ref().ok_or_else(no_program)?;
    for place in places {
        memory.check(*place)?;
    }
    let mut out = between.cycles.to_le_bytes().to_vec();
    let mut bitmap = vec![0u8; places.len().div_ceil(8)];
    for (index, place) in places.iter().enumerate() {
        if between.forces.is_forced(*place) {
            bitmap[index / 8] |= 1 << (index % 8);
        }
    }
    out.extend_from_slice(&bitmap);
    for place in places {
        out.extend_from_slice(&memory.read(*place));
    }
    if out.len() > MAX_PAYLOAD_BYTES {
        return Err(codec::bad(format!(
            "the values need {} bytes, more than one response holds",
            out.len()
        )));
    }
    Ok(out)
}

fn configure_trace(between: &mut Between<'_>, config: TraceConfig) -> Result<Vec<u8>, Refusal> {
    let memory = between.memory.as_ref().ok_or_else(no_program)?;
    if usize::from(config.task) >= memory.engine.image().tasks.len() {
        return Err(not_now(&format!("task {} does not exist", config.task)));
    }
    for place in &config.places {
        memory.check(*place)?;
    }
    if config.trigger != TriggerKind::None {
        memory.check(config.trigger_place)?;
    }
    let sample_bytes = Trace::sample_bytes(&config);
    if 1 + 16 + sample_bytes > MAX_PAYLOAD_BYTES {
        return Err(codec::bad(format!(
            "a sample of {sample_bytes} bytes does not fit one upload"
        )));
    }
    if u64::from(config.samples) * (16 + sample_bytes as u64) > MAX_TRACE_BYTES {
        return Err(codec::bad(format!(
            "{} samples need more than the {MAX_TRACE_BYTES} bytes a trace may hold",
            config.samples
        )));
    }
    between.trace.configure(config);
    Ok((sample_bytes as u16).to_le_bytes().to_vec())
}

fn upload(trace: &Trace, from: u32) -> Vec<u8> {
    let mut out = vec![0];
    for sample in trace.samples().skip(from as usize) {
        if out.len() + 16 + sample.values.len() > MAX_PAYLOAD_BYTES || out[0] == u8::MAX {
            break;
        }
        out.extend_from_slice(&sample.cycle.to_le_bytes());
        out.extend_from_slice(&sample.time_ns.to_le_bytes());
        out.extend_from_slice(&sample.values);
        out[0] += 1;
    }
    out
}

fn scheduler_refusal(error: SchedulerError) -> Refusal {
    let status = match error {
        SchedulerError::NoProgram | SchedulerError::Gone => Status::NotNow,
        SchedulerError::Load(_) => Status::ImageRefused,
        // The command was done; only saving the retained values failed.
        SchedulerError::Retain(_) => Status::NotNow,
    };
    Refusal {
        status,
        message: error.to_string(),
    }
}

fn no_program() -> Refusal {
    not_now("no program is loaded")
}

fn not_now(message: &str) -> Refusal {
    Refusal {
        status: Status::NotNow,
        message: message.to_owned(),
    }
}

/// `text` cut at a character boundary to at most `bytes` bytes.
fn cut(text: &str, bytes: usize) -> &str {
    let mut end = text.len().min(bytes);
    while !text.is_char_boundary(end) {
        end -= 1;
    }
    &text[..end]
}

/// A random token, not 0, from the standard library's randomly keyed hasher mixed with the
/// time.
fn random_token() -> u32 {
    loop {
        let mut hasher = std::collections::hash_map::RandomState::new().build_hasher();
        hasher.write_u128(
            std::time::SystemTime::now()
                .duration_since(std::time::UNIX_EPOCH)
                .map(|elapsed| elapsed.as_nanos())
                .unwrap_or(0),
        );
        let token = hasher.finish() as u32;
        if token != 0 {
            return token;
        }
    }
}

fn lock<T>(mutex: &Mutex<T>) -> MutexGuard<'_, T> {
    mutex.lock().unwrap_or_else(PoisonError::into_inner)
}

#[cfg(test)]
#[path = "services_tests.rs"]
mod tests;
