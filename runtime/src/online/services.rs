//! The online services on a scheduler, as the Modbus server's hook for function code 0x64.

use std::collections::HashMap;
use std::net::IpAddr;
use std::sync::{Arc, Mutex, MutexGuard, PoisonError};
use std::time::Instant;

use online_protocol::{
    CHUNK_BYTES, DecodeError, FUNCTION_CODE, Fault, Identity, MAX_COUNT, MAX_FAULT_TEXT_BYTES,
    MAX_PAYLOAD_BYTES, MAX_SAMPLE_VALUE_BYTES, MAX_TEXT_BYTES, PLACE_BYTES, PROTOCOL_VERSION,
    Place, Refusal, Request, Resolved, Response, SAMPLE_HEADER_BYTES, Snapshot, Status, TYPE_ENUM,
    TYPE_OTHER, TYPE_STRING, TYPE_WSTRING, TargetState, TaskInfo, TraceConfig, TraceSample,
    TraceStatus, TriggerKind, cut,
};
use program_image::{Region, TypeDef};
use sha2::{Digest, Sha256};

use super::debug::Debugging;
use super::download::Transfer;

mod modbus_devices;
mod online_change;
use super::trace::{MAX_TRACE_BYTES, Trace};
use super::wrong_passwords::WrongPasswords;
use crate::engine::ResetKind;
use crate::modbus::master::MasterError;
use crate::modbus::{
    ConnectionClosed, CustomFunctions, ExceptionCode, MapSlot, ModbusMap, current_connection,
    current_peer, delay_answer,
};
use crate::retain::RetainRestore;
use crate::scheduler::{Between, Scheduler, SchedulerError, SchedulerState};
use crate::value;

/// The online services of one runtime: lives as long as its Modbus server; nothing of it is
/// saved (tokens end with the process).
pub struct OnlineServices {
    scheduler: Arc<Scheduler>,
    /// The password that changing services need; `None` lets everyone change the target.
    password: Option<String>,
    /// The token given out by `LOGIN` with the password to each connection (`None` outside a
    /// Modbus server), valid on that connection only until it logs in again or closes; without
    /// a password none are kept, as any token is accepted.
    tokens: Mutex<HashMap<Option<u64>, u128>>,
    /// The wrong passwords of each client address, which make all its connections wait.
    wrong_passwords: Mutex<WrongPasswords>,
    /// The download in progress, if any.
    transfer: Mutex<Option<Transfer>>,
    /// The transfer last checked for an online change, with its prepared engine and plan.
    checked: Mutex<Option<online_change::CheckedChange>>,
    /// The number of the last transfer begun.
    last_transfer: Mutex<u16>,
    /// The Modbus server's map, replaced by the downloaded image's; `None` keeps the server's.
    map: Option<Arc<MapSlot>>,
    /// The debug session and its services (`docs/protocol.md` §6).
    debug: Debugging,
}

impl OnlineServices {
    /// The services on `scheduler`, with `password` required for the changing ones if given.
    pub fn new(scheduler: Arc<Scheduler>, password: Option<String>) -> Self {
        Self {
            scheduler,
            password,
            tokens: Mutex::new(HashMap::new()),
            wrong_passwords: Mutex::new(WrongPasswords::default()),
            transfer: Mutex::new(None),
            checked: Mutex::new(None),
            last_transfer: Mutex::new(0),
            map: None,
            debug: Debugging::new(true),
        }
    }

    /// The same services with the debugging services switched on or off
    /// (`rivet-runtime --debug on|off`).
    pub fn with_debugging(mut self, enabled: bool) -> Self {
        self.debug = Debugging::new(enabled);
        self
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

    /// How many connections hold a token from a login with the password (0 without a
    /// password, where none are kept).
    pub fn logged_in_connections(&self) -> usize {
        lock(&self.tokens).len()
    }

    /// The hook for [`crate::modbus::ServerOptions::closed`]: a transfer and a token end with
    /// the connection that began the one and logged in for the other (the server closes a
    /// connection after its idle timeout, so a token also ends when its client goes silent).
    pub fn closed_handler(self: &Arc<Self>) -> ConnectionClosed {
        let services = Arc::clone(self);
        Arc::new(move |connection| {
            lock(&services.tokens).remove(&Some(connection));
            if let Some(until) =
                services
                    .debug
                    .connection_ended(&services.scheduler, Some(connection), true)
            {
                // The lingering session ends on time even when no request comes: a thread
                // waits for its end (a take-over meanwhile leaves nothing to end).
                let lingering = Arc::clone(&services);
                std::thread::spawn(move || {
                    std::thread::sleep(until.saturating_duration_since(Instant::now()));
                    lingering.debug.expire(&lingering.scheduler, Instant::now());
                });
            }
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
    /// A request without a service byte gets exception 3. The request comes from the Modbus
    /// connection being served ([`current_connection`]), which a token must have been given to.
    pub fn respond(&self, request: &[u8]) -> Result<Vec<u8>, ExceptionCode> {
        self.respond_from(current_connection(), request)
    }

    /// The response to a request that came from `connection` (`None`: not from a Modbus
    /// server), as [`OnlineServices::respond`].
    pub fn respond_from(
        &self,
        connection: Option<u64>,
        request: &[u8],
    ) -> Result<Vec<u8>, ExceptionCode> {
        self.respond_at(connection, current_peer(), Instant::now(), request)
    }

    /// The response to a request that came at `now` from `connection` of the client at `peer`
    /// (`None`: not from a Modbus server, whose wrong passwords are not counted).
    fn respond_at(
        &self,
        connection: Option<u64>,
        peer: Option<IpAddr>,
        now: Instant,
        request: &[u8],
    ) -> Result<Vec<u8>, ExceptionCode> {
        let Some(&service) = request.first() else {
            return Err(ExceptionCode::IllegalDataValue);
        };
        let answer = Request::decode(request)
            .map_err(decode_refusal)
            .and_then(|request| {
                if let Some(token) = request.token() {
                    self.authorize(connection, token)?;
                }
                self.serve(connection, peer, now, request)
            });
        let mut body = match answer {
            Ok(response) => response.encode(),
            Err(refusal) => refusal.encode(service),
        };
        if body.len() > MAX_PAYLOAD_BYTES + 2 {
            body = Refusal::bad("the answer does not fit one response").encode(service);
        }
        Ok(body)
    }

    fn authorize(&self, connection: Option<u64>, token: u128) -> Result<(), Refusal> {
        if self.password.is_none() {
            return Ok(());
        }
        if token == 0 {
            return Err(Refusal {
                status: Status::PasswordRequired,
                message: "the runtime has a password: log in first".to_owned(),
            });
        }
        // A token is valid only on the connection it was given to: one seen on the wire (the
        // link is not encrypted) is of no use on another connection.
        if lock(&self.tokens).get(&connection) == Some(&token) {
            Ok(())
        } else {
            Err(Refusal {
                status: Status::WrongPassword,
                message: "the token is not valid: log in again".to_owned(),
            })
        }
    }

    fn serve(
        &self,
        connection: Option<u64>,
        peer: Option<IpAddr>,
        now: Instant,
        request: Request,
    ) -> Result<Response, Refusal> {
        match request {
            Request::Identify { protocol } => self.identify(protocol),
            Request::Login { password } => self.login(connection, peer, now, &password),
            Request::Logout => {
                lock(&self.tokens).remove(&connection);
                self.debug
                    .connection_ended(&self.scheduler, connection, false);
                Ok(Response::Logout)
            }
            Request::DownloadBegin { size, hash, .. } => {
                let mut last = lock(&self.last_transfer);
                *last = last.wrapping_add(1).max(1);
                let mut transfer = Transfer::begin(*last, size, hash, now)?;
                transfer.owner = connection;
                *lock(&self.transfer) = Some(transfer);
                // A checked change belongs to the transfer it checked.
                *lock(&self.checked) = None;
                Ok(Response::DownloadBegin {
                    transfer: *last,
                    chunk_size: CHUNK_BYTES,
                })
            }
            Request::DownloadChunk {
                transfer,
                offset,
                bytes,
                ..
            } => {
                let mut current = lock(&self.transfer);
                let active = current_transfer(&mut current, transfer)?;
                let received = active.chunk(offset, &bytes, now)?;
                Ok(Response::DownloadChunk { received })
            }
            Request::DownloadCommit {
                transfer, start, ..
            } => self.commit(transfer, start),
            Request::DownloadAbort { transfer, .. } => {
                let mut current = lock(&self.transfer);
                if current.as_ref().is_some_and(|active| active.id == transfer) {
                    *current = None;
                    *lock(&self.checked) = None;
                }
                Ok(Response::DownloadAbort)
            }
            Request::OnlineChangeCheck { transfer, .. } => self.online_change_check(transfer),
            Request::OnlineChangeDetails { transfer, from, .. } => {
                self.online_change_details(transfer, from)
            }
            Request::OnlineChangeApply { transfer, .. } => self.online_change_apply(transfer),
            Request::Start { .. } => {
                self.scheduler.start().map_err(scheduler_refusal)?;
                Ok(Response::Start {
                    state: self.state(),
                })
            }
            Request::Stop { .. } => {
                self.scheduler.stop().map_err(scheduler_refusal)?;
                Ok(Response::Stop {
                    state: self.state(),
                })
            }
            Request::Reset { kind, .. } => {
                let kind = match kind {
                    online_protocol::ResetKind::Warm => ResetKind::Warm,
                    online_protocol::ResetKind::Cold => ResetKind::Cold,
                    online_protocol::ResetKind::Origin => ResetKind::Origin,
                };
                self.scheduler.reset(kind).map_err(scheduler_refusal)?;
                Ok(Response::Reset {
                    state: self.state(),
                })
            }
            Request::Resolve { path } => self.between(move |between| resolve(between, &path)),
            Request::Enumeration { path, from } => {
                self.between(move |between| enumeration(between, &path, from))
            }
            Request::Read { places } => self.between(move |between| read(between, &places)),
            Request::Write { values, .. } => self.between(move |between| {
                let memory = between.memory.as_mut().ok_or_else(no_program)?;
                for (place, _) in &values {
                    memory.check(*place)?;
                }
                for (place, value) in &values {
                    memory.write(*place, value);
                }
                Ok(Response::Write)
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
                Ok(Response::Force)
            }),
            Request::Unforce { places, .. } => self.between(move |between| {
                if places.is_empty() {
                    between.forces.clear();
                }
                for place in places {
                    between.forces.release(place);
                }
                Ok(Response::Unforce)
            }),
            Request::Forces { from } => self.between(move |between| {
                let entries = between.forces.entries();
                let total = u16::try_from(entries.len()).unwrap_or(u16::MAX);
                // The total and the count come first; the forces that do not fit wait for the
                // next request.
                let mut used = 3;
                let mut forces = Vec::new();
                for (place, value) in entries.iter().skip(usize::from(from)) {
                    if used + PLACE_BYTES + value.len() > MAX_PAYLOAD_BYTES
                        || forces.len() == MAX_COUNT
                    {
                        break;
                    }
                    used += PLACE_BYTES + value.len();
                    forces.push((*place, value.clone()));
                }
                Ok(Response::Forces { total, forces })
            }),
            Request::TraceConfigure { config, .. } => self.between(move |between| {
                let sample_bytes = configure_trace(between, config)?;
                Ok(Response::TraceConfigure { sample_bytes })
            }),
            Request::TraceAdd { places, .. } => self.between(move |between| {
                // More places than one TRACE_CONFIGURE frame holds are added before arming.
                let mut config = between
                    .trace
                    .pending_config()
                    .cloned()
                    .ok_or_else(|| not_now("configure the trace before adding places"))?;
                config.places.extend(places);
                let sample_bytes = configure_trace(between, config)?;
                Ok(Response::TraceAdd { sample_bytes })
            }),
            Request::TraceArm { .. } => self.between(|between| {
                if between.trace.arm() {
                    Ok(Response::TraceArm)
                } else {
                    Err(not_now("the trace is not configured"))
                }
            }),
            Request::TraceStatus => self.between(|between| {
                let (state, recorded, trigger_sample) = between.trace.status();
                Ok(Response::TraceStatus(TraceStatus {
                    state,
                    recorded,
                    trigger_sample,
                }))
            }),
            Request::TraceUpload { from } => self.between(move |between| {
                Ok(Response::TraceUpload {
                    samples: upload(between.trace, from),
                })
            }),
            Request::Tasks => Ok(Response::Tasks {
                tasks: self.tasks(),
            }),
            Request::Faults { from } => Ok(self.faults(from)),
            Request::ModbusDevices { from } => Ok(self.modbus_devices(from)),
            Request::Debug(request) => {
                self.debug
                    .serve(&self.scheduler, connection, peer, now, request)
            }
        }
    }

    fn identify(&self, protocol: u16) -> Result<Response, Refusal> {
        if protocol != PROTOCOL_VERSION {
            return Err(Refusal::new(
                Status::VersionMismatch,
                format!(
                    "the client speaks protocol version {protocol}, this runtime version {PROTOCOL_VERSION}"
                ),
            ));
        }
        let project = self.between(|between| {
            Ok(between
                .memory
                .as_ref()
                .map(|memory| memory.engine.image().info.project.clone())
                .unwrap_or_default())
        })?;
        let status = self.scheduler.status();
        Ok(Response::Identify(Identity {
            protocol: PROTOCOL_VERSION,
            runtime_version: cut(env!("CARGO_PKG_VERSION"), MAX_TEXT_BYTES).to_owned(),
            state: self.state(),
            image_hash: status.image,
            project: cut(&project, MAX_TEXT_BYTES).to_owned(),
            password_required: self.password.is_some(),
            debug: self.debug.status(&self.scheduler),
        }))
    }

    /// `LOGIN` from `connection` of the client at `peer`, at `now`.
    ///
    /// A wrong password makes its address wait (`docs/protocol.md` §5): until the wait is
    /// over, no password from any connection of that address is checked, so opening more
    /// connections does not guess faster; other addresses log in at once.
    fn login(
        &self,
        connection: Option<u64>,
        peer: Option<IpAddr>,
        now: Instant,
        password: &str,
    ) -> Result<Response, Refusal> {
        let Some(expected) = &self.password else {
            return Ok(Response::Login {
                token: random_token(),
            });
        };
        if let Some(address) = peer
            && let Some(wait) = lock(&self.wrong_passwords).wait(address, now)
        {
            // The refusal comes when the address may try again, so that the connection does
            // not spin asking.
            delay_answer(wait);
            return Err(Refusal::not_now(format!(
                "too many wrong passwords from {address}: no password from it is checked for \
                 another {} ms",
                wait.as_millis()
            )));
        }
        // Comparing digests takes the same time whatever the password and its length.
        let given: [u8; 32] = Sha256::digest(password.as_bytes()).into();
        let expected: [u8; 32] = Sha256::digest(expected.as_bytes()).into();
        let difference = given
            .iter()
            .zip(&expected)
            .fold(0u8, |difference, (a, b)| difference | (a ^ b));
        if difference != 0 {
            // This connection, and every other of the same address, waits; other addresses
            // log in at once.
            let wait = match peer {
                Some(address) => lock(&self.wrong_passwords).failed(address, now),
                None => super::WRONG_PASSWORD_DELAY,
            };
            delay_answer(wait);
            return Err(Refusal {
                status: Status::WrongPassword,
                message: "wrong password".to_owned(),
            });
        }
        if let Some(address) = peer {
            lock(&self.wrong_passwords).succeeded(address);
        }
        // Logging in again replaces the connection's token.
        let token = random_token();
        // Logging in again ends the connection's debug session.
        self.debug
            .connection_ended(&self.scheduler, connection, false);
        lock(&self.tokens).insert(connection, token);
        Ok(Response::Login { token })
    }

    fn commit(&self, transfer: u16, start: bool) -> Result<Response, Refusal> {
        let active = {
            let mut current = lock(&self.transfer);
            current_transfer(&mut current, transfer)?;
            current.take()
        };
        *lock(&self.checked) = None;
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
        // The load report's native part is not printed or sent: the services run in a library
        // without a console of their own, and protocol version 3 has no field for it
        // (`docs/native-engine.md` §8.2, §13).
        let report = self
            .scheduler
            .load(image)
            .map_err(|error| refused(error.to_string()))?;
        if let Some(slot) = &self.map {
            slot.set(map);
        }
        self.debug.program_loaded(&self.scheduler);
        if start {
            self.scheduler.start().map_err(scheduler_refusal)?;
        }
        let retained =
            report.carried > 0 || matches!(report.retain, Some(RetainRestore::Restored { .. }));
        Ok(Response::DownloadCommit { retained })
    }

    /// The tasks that fit one response, after their count.
    fn tasks(&self) -> Vec<TaskInfo> {
        let status = self.scheduler.status();
        let mut used = 1;
        let mut tasks = Vec::new();
        for task in status.tasks.iter().take(MAX_COUNT) {
            let info = TaskInfo {
                name: cut(&task.name, MAX_TEXT_BYTES).to_owned(),
                cycles: task.cycles,
                last_ns: task.last_cycle_ns,
                min_ns: task.min_cycle_ns,
                max_ns: task.max_cycle_ns,
                average_ns: task.average_cycle_ns(),
                jitter_max_ns: task.max_jitter_ns,
                faulted: task.faulted,
            };
            // The tasks that do not fit one response are left out.
            if used + info.wire_bytes() > MAX_PAYLOAD_BYTES {
                break;
            }
            used += info.wire_bytes();
            tasks.push(info);
        }
        tasks
    }

    fn faults(&self, from: u16) -> Response {
        let status = self.scheduler.status();
        let total = u16::try_from(status.faults.len()).unwrap_or(u16::MAX);
        let mut used = 3;
        let mut faults = Vec::new();
        for fault in status.faults.iter().skip(usize::from(from)) {
            // Texts are cut so that one fault always fits a response.
            let text = |text: &str| cut(text, MAX_FAULT_TEXT_BYTES).to_owned();
            let entry = Fault {
                task: text(&fault.task),
                kind: text(&fault.kind.to_string()),
                pou: text(&fault.pou),
                file: text(fault.file.as_deref().unwrap_or("")),
                line: fault.line.unwrap_or(0),
                cycle: fault.cycle,
            };
            if used + entry.wire_bytes() > MAX_PAYLOAD_BYTES || faults.len() == MAX_COUNT {
                break;
            }
            used += entry.wire_bytes();
            faults.push(entry);
        }
        Response::Faults { total, faults }
    }

    /// The state as `IDENTIFY` and run control send it.
    fn state(&self) -> TargetState {
        let status = self.scheduler.status();
        match (status.image, status.state) {
            (None, _) => TargetState::NoProgram,
            (Some(_), SchedulerState::Stopped) => TargetState::Stopped,
            (Some(_), SchedulerState::Running) => TargetState::Running,
            (Some(_), SchedulerState::Faulted) => TargetState::Faulted,
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

fn resolve(between: &mut Between<'_>, path: &str) -> Result<Response, Refusal> {
    let memory = between.memory.as_ref().ok_or_else(no_program)?;
    let image = memory.engine.image();
    let place = value::resolve(image, path)
        .map_err(|error| Refusal::new(Status::UnknownSymbol, error.to_string()))?;
    let ty = image.types.get(place.ty as usize);
    let (tag, length) = match ty {
        Some(TypeDef::Elementary(elementary)) => (*elementary as u8, 0),
        Some(TypeDef::String { length }) => (TYPE_STRING, *length),
        Some(TypeDef::WString { length }) => (TYPE_WSTRING, *length),
        Some(TypeDef::Enum { .. }) => (TYPE_ENUM, 0),
        _ => (TYPE_OTHER, 0),
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
    Ok(Response::Resolve(Resolved {
        place: Place {
            region,
            offset: u32::try_from(place.offset).unwrap_or(u32::MAX),
            bit: place.bit,
            // A value larger than a u16 cannot be read in one piece anyway.
            size: u16::try_from(size).unwrap_or(u16::MAX),
        },
        type_tag: tag,
        length: u16::try_from(length).unwrap_or(u16::MAX),
    }))
}

/// The values of the enumeration type of the variable at `path`, from the `from`-th on, as
/// many as fit one response; a client asks again from where the answer ended.
fn enumeration(between: &mut Between<'_>, path: &str, from: u16) -> Result<Response, Refusal> {
    let memory = between.memory.as_ref().ok_or_else(no_program)?;
    let image = memory.engine.image();
    let place = value::resolve(image, path)
        .map_err(|error| Refusal::new(Status::UnknownSymbol, error.to_string()))?;
    let Some(TypeDef::Enum { base, values, .. }) = image.types.get(place.ty as usize) else {
        return Err(Refusal::bad(format!(
            "'{path}' is not of an enumeration type"
        )));
    };
    // The base type, the total and the count come first; each value is its name and 8 bytes.
    let mut used = 4;
    let mut page = Vec::new();
    for (name, number) in values.iter().skip(usize::from(from)) {
        // Names are identifiers, far shorter than the cut, which keeps any one value fitting.
        let name = cut(name, MAX_TEXT_BYTES).to_owned();
        let bytes = 1 + name.len() + 8;
        if used + bytes > MAX_PAYLOAD_BYTES || page.len() == MAX_COUNT {
            break;
        }
        used += bytes;
        page.push((name, *number));
    }
    Ok(Response::Enumeration {
        base: *base as u8,
        total: u16::try_from(values.len()).unwrap_or(u16::MAX),
        values: page,
    })
}

fn read(between: &mut Between<'_>, places: &[Place]) -> Result<Response, Refusal> {
    let memory = between.memory.as_ref().ok_or_else(no_program)?;
    for place in places {
        memory.check(*place)?;
    }
    let values: Vec<(Vec<u8>, bool)> = places
        .iter()
        .map(|place| (memory.read(*place), between.forces.is_forced(*place)))
        .collect();
    // The cycle, the forced bitmap and the values.
    let bytes =
        8 + places.len().div_ceil(8) + values.iter().map(|(value, _)| value.len()).sum::<usize>();
    if bytes > MAX_PAYLOAD_BYTES {
        return Err(Refusal::bad(format!(
            "the values need {bytes} bytes, more than one response holds"
        )));
    }
    Ok(Response::Read(Snapshot {
        cycle: between.cycles,
        values,
    }))
}

/// Configures the trace and returns the bytes of one sample's values.
fn configure_trace(between: &mut Between<'_>, config: TraceConfig) -> Result<u16, Refusal> {
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
    if sample_bytes > MAX_SAMPLE_VALUE_BYTES {
        return Err(Refusal::bad(format!(
            "a sample of {sample_bytes} bytes does not fit one upload"
        )));
    }
    if u64::from(config.samples) * (SAMPLE_HEADER_BYTES + sample_bytes) as u64 > MAX_TRACE_BYTES {
        return Err(Refusal::bad(format!(
            "{} samples need more than the {MAX_TRACE_BYTES} bytes a trace may hold",
            config.samples
        )));
    }
    between.trace.configure(config);
    Ok(sample_bytes as u16)
}

/// The samples from `from` on that fit one response, after their count.
fn upload(trace: &Trace, from: u32) -> Vec<TraceSample> {
    let mut used = 1;
    let mut samples = Vec::new();
    for sample in trace.samples().skip(from as usize) {
        let sample = TraceSample {
            cycle: sample.cycle,
            time_ns: sample.time_ns,
            values: sample.values.clone(),
        };
        if used + sample.wire_bytes() > MAX_PAYLOAD_BYTES || samples.len() == MAX_COUNT {
            break;
        }
        used += sample.wire_bytes();
        samples.push(sample);
    }
    samples
}

fn scheduler_refusal(error: SchedulerError) -> Refusal {
    let status = match error {
        SchedulerError::NoProgram
        | SchedulerError::ProgramChanged
        | SchedulerError::Halted
        | SchedulerError::Gone => Status::NotNow,
        SchedulerError::Load(_) => Status::ImageRefused,
        // Paths that do not fit the program refuse the image; threads that cannot be started
        // are a passing condition of the machine.
        SchedulerError::ModbusMaster(MasterError::Resolve(_)) => Status::ImageRefused,
        SchedulerError::ModbusMaster(MasterError::Thread(_)) => Status::NotNow,
        // The command was done; only saving the retained values failed.
        SchedulerError::Retain(_) => Status::NotNow,
    };
    Refusal::new(status, error.to_string())
}

/// The refusal of a request that does not decode, with the status the protocol gives it.
fn decode_refusal(error: DecodeError) -> Refusal {
    Refusal::new(error.status(), error.to_string())
}

fn no_program() -> Refusal {
    not_now("no program is loaded")
}

fn not_now(message: &str) -> Refusal {
    Refusal::not_now(message)
}

/// A random token, not 0, of 128 bits from the operating system's CSPRNG, so that it cannot be
/// guessed or predicted from earlier tokens.
fn random_token() -> u128 {
    loop {
        let mut bytes = [0; 16];
        // Without the operating system's random numbers no token can be trusted; 0 is never
        // accepted as a token when there is a password, so it is retried until one comes.
        if getrandom::fill(&mut bytes).is_ok() {
            let token = u128::from_le_bytes(bytes);
            if token != 0 {
                return token;
            }
        }
    }
}

fn lock<T>(mutex: &Mutex<T>) -> MutexGuard<'_, T> {
    mutex.lock().unwrap_or_else(PoisonError::into_inner)
}

#[cfg(test)]
#[path = "services_tests.rs"]
mod tests;
