//! Online work with a target: login with identity check and download, run control, watched
//! values, writes and forces, task statistics, faults and traces.
//!
//! Everything goes through one [`Link`] (a background session of the `online` crate); the UI
//! calls [`Online::poll`] once per frame to take in what arrived, and never waits.

mod background;
mod devices;
mod link;
mod simulator;
mod trace_run;

use std::collections::{HashMap, HashSet};
use std::sync::Arc;

use project_model::ModbusDevice;
use std::time::{Duration, Instant};

use online::session::{Command, Event, SessionOptions};
use online::{Fault, Identity, Place, Reset, Resolved, TargetState, TaskInfo};
use serde::{Deserialize, Serialize};

use crate::value_text::{describe_place, show};
use background::Background;
use link::Link;
use simulator::Simulator;
pub use trace_run::{TracePhase, TraceRun};

/// How often task statistics, faults and forces are asked for while logged in.
const STATUS_INTERVAL: Duration = Duration::from_millis(500);
/// How often watched values are read.
const POLL_INTERVAL: Duration = Duration::from_millis(100);

/// Wakes the UI when something arrived from the network.
pub type Waker = Arc<dyn Fn() + Send + Sync>;

/// A typed value the studio refused to send: the variable's path and the reason.
pub type Refusal = (String, String);

/// Typed values turned into bytes, by where they go.
#[derive(Default)]
struct Encoded {
    /// Values for the controller, by place.
    target: Vec<(Place, Vec<u8>)>,
    /// Values for Modbus device channels, by bound path.
    devices: Vec<(String, Vec<u8>)>,
    /// Paths for the controller while logged out.
    logged_out: Vec<String>,
}

/// Which target the studio logs in to.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum TargetKind {
    /// The runtime embedded in the studio, on loopback.
    #[default]
    Simulation,
    /// A controller over Modbus TCP at the project's controller address.
    Controller,
}

/// A program built from the project, ready to download.
#[derive(Clone, Debug)]
pub struct BuiltImage {
    /// The encoded image.
    pub bytes: Arc<Vec<u8>>,
    /// Its identity hash.
    pub hash: [u8; 32],
    /// Its task names in image order (a trace names its task by index).
    pub tasks: Vec<String>,
    /// The image itself, whose types show values as the program declares them (enumerations
    /// by name) once the target is known to run it.
    pub program: Arc<program_image::ProgramImage>,
}

/// Where the login is.
#[derive(Clone, Debug, PartialEq)]
pub enum Phase {
    /// Not logged in.
    Offline,
    /// Connecting to the target.
    Connecting,
    /// Connected, but the target runs another program or none: the user decides whether to
    /// download.
    ConfirmDownload {
        /// Why, in words.
        reason: String,
    },
    /// Downloading: bytes sent of the total.
    Downloading {
        /// Bytes sent.
        sent: usize,
        /// Bytes in all.
        total: usize,
    },
    /// Logged in and the target runs the project's program.
    Online,
    /// The connection was lost; the session tries again.
    Lost(String),
}

/// A watched variable's last value.
#[derive(Clone, Debug, PartialEq)]
pub struct LiveValue {
    /// The value as an IEC literal.
    pub text: String,
    /// Whether it is forced.
    pub forced: bool,
    /// Whether it differs from the previous reading.
    pub changed: bool,
}

/// A forced variable as the forces list shows it.
#[derive(Clone, Debug, PartialEq)]
pub struct ForcedValue {
    /// The variable's path, or where it is when no watched path names it.
    pub name: String,
    /// Where the force is held, to release it.
    pub source: ForceSource,
    /// The forced value as text.
    pub value: String,
}

/// Where a force is held.
#[derive(Clone, Debug, PartialEq)]
pub enum ForceSource {
    /// On the controller, at this place.
    Target(Place),
    /// By the studio on a Modbus device's channel.
    Device {
        /// The device's name.
        device: String,
        /// The channel's index.
        channel: usize,
    },
}

/// A message for the messages panel and the status bar.
#[derive(Clone, Debug, PartialEq)]
pub struct OnlineMessage {
    /// What happened.
    pub text: String,
    /// Whether it reports a failure.
    pub is_error: bool,
}

/// The studio's online state.
pub struct Online {
    background: Option<Background>,
    simulator: Option<Simulator>,
    link: Option<Link>,
    phase: Phase,
    target_state: Option<TargetState>,
    target_identity: Option<Identity>,
    image: Option<BuiltImage>,
    resolved: HashMap<String, Result<Resolved, String>>,
    resolving: HashSet<String>,
    /// The paths whose places were last sent as the watch list, in that order.
    watched: Vec<String>,
    wanted: Vec<String>,
    values: HashMap<String, LiveValue>,
    cycle: u64,
    forces: Vec<(Place, Vec<u8>)>,
    tasks: Vec<TaskInfo>,
    /// Counts the task statistics received, so their history is extended once per answer.
    tasks_generation: u64,
    faults: Vec<Fault>,
    trace: TraceRun,
    messages: Vec<OnlineMessage>,
    last_status: Option<Instant>,
    devices: devices::DeviceLinks,
    /// The device whose polling trace is under way.
    device_trace: Option<String>,
    /// The project's Modbus devices as of the last [`Online::set_watch`].
    project_devices: Vec<ModbusDevice>,
    waker: Option<Waker>,
}

impl Default for Online {
    fn default() -> Self {
        Self::new()
    }
}

impl Online {
    /// An offline state; nothing runs until the first login.
    pub fn new() -> Self {
        Self {
            background: None,
            simulator: None,
            link: None,
            phase: Phase::Offline,
            target_state: None,
            target_identity: None,
            image: None,
            resolved: HashMap::new(),
            resolving: HashSet::new(),
            watched: Vec::new(),
            wanted: Vec::new(),
            values: HashMap::new(),
            cycle: 0,
            forces: Vec::new(),
            tasks: Vec::new(),
            tasks_generation: 0,
            faults: Vec::new(),
            trace: TraceRun::default(),
            messages: Vec::new(),
            last_status: None,
            devices: devices::DeviceLinks::default(),
            device_trace: None,
            project_devices: Vec::new(),
            waker: None,
        }
    }

    /// Where the login is.
    pub fn phase(&self) -> &Phase {
        &self.phase
    }

    /// Whether a session exists (logged in, connecting or reconnecting).
    pub fn is_logged_in(&self) -> bool {
        self.link.is_some()
    }

    /// Whether values can be read and written now.
    pub fn is_online(&self) -> bool {
        self.phase == Phase::Online
    }

    /// The target's state as last reported.
    pub fn target_state(&self) -> Option<TargetState> {
        self.target_state
    }

    /// What the target said about itself at the last connection.
    pub fn target_identity(&self) -> Option<&Identity> {
        self.target_identity.as_ref()
    }

    /// The cycle count of the last snapshot.
    pub fn cycle(&self) -> u64 {
        self.cycle
    }

    /// Task statistics as last reported.
    pub fn tasks(&self) -> &[TaskInfo] {
        &self.tasks
    }

    /// How many task statistics answers arrived so far.
    pub fn tasks_generation(&self) -> u64 {
        self.tasks_generation
    }

    /// The target's fault log as last reported.
    pub fn faults(&self) -> &[Fault] {
        &self.faults
    }

    /// The trace being recorded or uploaded.
    pub fn trace(&self) -> &TraceRun {
        &self.trace
    }

    /// Messages since the last call, oldest first.
    pub fn take_messages(&mut self) -> Vec<OnlineMessage> {
        std::mem::take(&mut self.messages)
    }

    /// Logs in to `target` (at `address` for a controller) with the program `image`: connects,
    /// compares identities and, when they differ, asks before downloading.
    pub fn login(
        &mut self,
        target: TargetKind,
        address: Option<std::net::SocketAddr>,
        password: Option<String>,
        image: BuiltImage,
        wake: impl Fn() + Send + 'static,
    ) {
        self.logout();
        if !self.start_background() {
            return;
        }
        let Some(background) = &self.background else {
            return;
        };
        let address = match (target, address) {
            (TargetKind::Simulation, _) => {
                if self.simulator.is_none() {
                    match Simulator::start(background.handle()) {
                        Ok(simulator) => self.simulator = Some(simulator),
                        Err(error) => {
                            self.error(error.to_string());
                            return;
                        }
                    }
                }
                match &self.simulator {
                    Some(simulator) => simulator.address(),
                    None => return,
                }
            }
            (TargetKind::Controller, Some(address)) => address,
            (TargetKind::Controller, None) => {
                self.error("the controller has no address: set its host and port".to_owned());
                return;
            }
        };
        self.image = Some(image);
        self.link = Some(Link::open(
            background.handle(),
            SessionOptions {
                address,
                password,
                poll_interval: POLL_INTERVAL,
                reconnect_interval: Duration::from_secs(1),
            },
            wake,
        ));
        self.phase = Phase::Connecting;
    }

    /// Starts the network thread if it is not running; `false` (with a message) when it cannot.
    fn start_background(&mut self) -> bool {
        if self.background.is_none() {
            match Background::start() {
                Ok(background) => self.background = Some(background),
                Err(error) => {
                    self.error(format!("the online thread did not start: {error}"));
                    return false;
                }
            }
        }
        true
    }

    /// Sets what wakes the UI when something arrives from the network.
    pub fn set_waker(&mut self, waker: Waker) {
        self.waker = Some(waker);
    }

    /// Whether values can be written or forced now: logged in, or polling a Modbus device.
    pub fn can_write(&self) -> bool {
        self.is_online() || !self.devices.is_empty()
    }

    /// Ends the session; the target keeps running as it is.
    pub fn logout(&mut self) {
        self.link = None;
        self.phase = Phase::Offline;
        self.target_state = None;
        self.forget_program();
        self.tasks.clear();
        self.faults.clear();
    }

    /// Forgets everything that belongs to the program on the target (after a download or when
    /// another program is found).
    fn forget_program(&mut self) {
        self.resolved.clear();
        self.resolving.clear();
        self.watched.clear();
        self.values.clear();
        self.forces.clear();
        self.trace = TraceRun::default();
    }

    /// The user agreed to download the project's program.
    pub fn confirm_download(&mut self) {
        let Some(image) = &self.image else { return };
        let bytes = image.bytes.as_ref().clone();
        let total = bytes.len();
        if self.command(Command::Download {
            image: bytes,
            start: false,
        }) {
            self.phase = Phase::Downloading { sent: 0, total };
        }
    }

    /// The user declined the download: log out again.
    pub fn cancel_download(&mut self) {
        self.logout();
        self.info("login cancelled; nothing was downloaded".to_owned());
    }

    /// Starts the program.
    pub fn start(&mut self) {
        self.command(Command::Start);
    }

    /// Stops the program.
    pub fn stop(&mut self) {
        self.command(Command::Stop);
    }

    /// Resets the program's memory.
    pub fn reset(&mut self, kind: Reset) {
        self.command(Command::Reset(kind));
    }

    /// Sets the variables whose values are read every poll; unknown ones are resolved first.
    pub fn set_watch(&mut self, paths: Vec<String>, devices: &[ModbusDevice]) {
        if devices != self.project_devices.as_slice() {
            self.project_devices = devices.to_vec();
        }
        let on_device = |path: &String| devices::binding_of(devices, path).is_some();
        // Devices are polled only while one of their variables is watched.
        let needs_devices = paths.iter().any(on_device) || !self.devices.is_empty();
        if needs_devices
            && self.start_background()
            && let (Some(background), Some(waker)) = (&self.background, &self.waker)
        {
            self.devices
                .keep(background.handle(), devices, &paths, waker);
        }
        self.wanted = paths.into_iter().filter(|path| !on_device(path)).collect();
        self.refresh_watch();
    }

    /// The last value of a watched variable, from its Modbus device when it is bound to one.
    pub fn value(&self, path: &str) -> Option<&LiveValue> {
        match self.devices.value(&self.project_devices, path) {
            Some(Ok(value)) => Some(value),
            Some(Err(_)) => None,
            None => self.values.get(path),
        }
    }

    /// Why a watched variable has no value: unknown on the target, or its device unreachable.
    pub fn problem(&self, path: &str) -> Option<String> {
        if devices::binding_of(&self.project_devices, path).is_some() {
            return match self.devices.value(&self.project_devices, path) {
                Some(Err(problem)) => Some(problem),
                _ => None,
            };
        }
        match self.resolved.get(path) {
            Some(Err(reason)) => Some(reason.clone()),
            _ => None,
        }
    }

    /// Whether a path is bound to a Modbus device of the project.
    pub fn is_device_bound(&self, path: &str) -> bool {
        devices::binding_of(&self.project_devices, path).is_some()
    }

    /// Turns typed values into bytes of their variables' types: for the controller by the
    /// places it resolved, for Modbus devices by their channels. Values for the controller
    /// are left out while logged out (`send` refuses them). Each failure names the path and
    /// the reason; nothing is sent when any value is refused.
    fn encode(&self, values: &[(String, String)]) -> Result<Encoded, Vec<Refusal>> {
        let mut encoded = Encoded::default();
        let mut refused = Vec::new();
        for (path, text) in values {
            if let Some((device, index)) = devices::binding_of(&self.project_devices, path) {
                let channels = crate::modbus_devices::channels_of(device);
                let Some(channel) = channels.get(index) else {
                    continue;
                };
                match crate::literal_value::parse(text.trim(), channel.ty as u8, 0) {
                    Ok(bytes) => encoded.devices.push((path.clone(), bytes)),
                    Err(reason) => refused.push((path.clone(), reason)),
                }
                continue;
            }
            if !self.is_online() {
                encoded.logged_out.push(path.clone());
                continue;
            }
            match self.resolved.get(path) {
                Some(Ok(resolved)) => {
                    match crate::literal_value::parse(
                        text.trim(),
                        resolved.type_tag,
                        resolved.length,
                    ) {
                        Ok(bytes) => encoded.target.push((resolved.place, bytes)),
                        Err(reason) => refused.push((path.clone(), reason)),
                    }
                }
                Some(Err(reason)) => refused.push((path.clone(), reason.clone())),
                None => refused.push((path.clone(), "not known on the target yet".to_owned())),
            }
        }
        if refused.is_empty() {
            Ok(encoded)
        } else {
            Err(refused)
        }
    }

    /// Checks a typed value against its variable's type without sending it.
    pub fn check_value(&self, path: &str, text: &str) -> Result<(), String> {
        match self.encode(&[(path.to_owned(), text.to_owned())]) {
            Ok(_) => Ok(()),
            Err(mut refused) => Err(refused.pop().map(|(_, reason)| reason).unwrap_or_default()),
        }
    }

    /// Writes values once (Ctrl+F7). Refused values are returned with the reason.
    pub fn write(&mut self, values: &[(String, String)]) -> Result<(), Vec<Refusal>> {
        self.send(values, false)
    }

    /// Forces values (F7). Refused values are returned with the reason.
    pub fn force(&mut self, values: &[(String, String)]) -> Result<(), Vec<Refusal>> {
        self.send(values, true)
    }

    /// Writes or forces `values`: those bound to Modbus devices on their devices, the others
    /// on the controller. A value its type refuses stops everything (nothing is sent); values
    /// for the controller while logged out are refused on their own, and the devices' values
    /// still go out.
    fn send(&mut self, values: &[(String, String)], force: bool) -> Result<(), Vec<Refusal>> {
        let encoded = self.encode(values)?;
        let mut refused: Vec<Refusal> = encoded
            .logged_out
            .into_iter()
            .map(|path| (path, "log in to write it (Alt+F8)".to_owned()))
            .collect();
        for (path, bytes) in encoded.devices {
            if let Err(reason) = self
                .devices
                .send(&self.project_devices, &path, bytes, force)
            {
                refused.push((path, reason));
            }
        }
        if !encoded.target.is_empty() {
            self.command(if force {
                Command::Force(encoded.target)
            } else {
                Command::Write(encoded.target)
            });
            if force {
                self.command(Command::Forces);
            }
        }
        if refused.is_empty() {
            Ok(())
        } else {
            Err(refused)
        }
    }

    /// Releases every force, on the controller and on the devices (Alt+F7).
    pub fn unforce_all(&mut self) {
        self.devices.unforce(None);
        if self.link.is_some() {
            self.command(Command::Unforce(Vec::new()));
            self.command(Command::Forces);
        }
    }

    /// Releases one force.
    pub fn unforce(&mut self, source: &ForceSource) {
        match source {
            ForceSource::Target(place) => {
                self.command(Command::Unforce(vec![*place]));
                self.command(Command::Forces);
            }
            ForceSource::Device { device, channel } => {
                self.devices.unforce(Some((device, *channel)));
            }
        }
    }

    /// The place of a resolved path.
    pub fn place(&self, path: &str) -> Option<Place> {
        match self.resolved.get(path) {
            Some(Ok(resolved)) => Some(resolved.place),
            _ => None,
        }
    }

    /// Every forced variable, named by its path when a resolved path has its place.
    pub fn forced_values(&self) -> Vec<ForcedValue> {
        let on_devices = self.devices.forces().into_iter().map(|force| ForcedValue {
            name: force.path,
            source: ForceSource::Device {
                device: force.device,
                channel: force.channel,
            },
            value: force.value,
        });
        self.forces
            .iter()
            .map(|(place, bytes)| {
                let named = self
                    .resolved
                    .iter()
                    .find_map(|(path, resolved)| match resolved {
                        Ok(resolved) if resolved.place == *place => Some((path, resolved)),
                        _ => None,
                    });
                match named {
                    Some((path, resolved)) => ForcedValue {
                        name: path.clone(),
                        source: ForceSource::Target(*place),
                        value: show(resolved, bytes),
                    },
                    None => ForcedValue {
                        name: describe_place(place),
                        source: ForceSource::Target(*place),
                        value: format!("16#{}", crate::value_text::hex(bytes)),
                    },
                }
            })
            .chain(on_devices)
            .collect()
    }

    /// Configures and arms a trace of `config` on the target, or, when its variables are the
    /// channels of one Modbus device, records it by polling that device.
    pub fn trace_start(&mut self, config: &project_model::TraceConfig) {
        if config
            .variables
            .iter()
            .any(|v| self.is_device_bound(&v.path))
        {
            if let Err(reason) = self.device_trace_start(config) {
                self.error(format!("trace '{}': {reason}", config.name));
            }
            return;
        }
        let Some(image) = &self.image else {
            self.error(format!("trace '{}': log in first (Alt+F8)", config.name));
            return;
        };
        match self.trace.prepare(config, &image.tasks) {
            Ok(paths) => {
                self.resolve(&paths);
                self.advance_trace();
            }
            Err(reason) => self.error(format!("trace '{}': {reason}", config.name)),
        }
    }

    /// Starts recording a trace of device channels by polling the device.
    fn device_trace_start(&mut self, config: &project_model::TraceConfig) -> Result<(), String> {
        let mut device_name = None;
        let mut variables = Vec::new();
        for variable in &config.variables {
            let (device, index) = devices::binding_of(&self.project_devices, &variable.path)
                .ok_or_else(|| {
                    format!(
                        "{} is not bound to a Modbus device; a trace records one device's channels or the controller's variables, not both",
                        variable.path
                    )
                })?;
            if device_name.get_or_insert_with(|| device.name.clone()) != &device.name {
                return Err(
                    "its variables are on different devices; trace one device at a time".to_owned(),
                );
            }
            let channels = crate::modbus_devices::channels_of(device);
            let channel = channels.get(index).ok_or("the binding has no channel")?;
            let resolved = Resolved {
                place: Place {
                    region: 0,
                    offset: u32::from(channel.address),
                    bit: None,
                    size: channel.ty.size_bytes() as u16,
                },
                type_tag: channel.ty as u8,
                length: 0,
            };
            variables.push((variable.path.clone(), resolved));
        }
        if config.trigger.is_some() {
            return Err(
                "a device is traced by polling and records at once; remove the trigger".to_owned(),
            );
        }
        let device_name = device_name.ok_or("no variables to record; add some first")?;
        let device = self
            .project_devices
            .iter()
            .find(|d| d.name == device_name)
            .ok_or("the device is gone")?;
        let interval = Duration::from_millis(
            u64::from(device.poll_interval_ms.max(10)) * u64::from(config.every_n_cycles.max(1)),
        );
        let samples = usize::try_from(config.record_count)
            .unwrap_or(usize::MAX)
            .min(100_000);
        self.devices.trace(&device_name, samples, interval)?;
        self.device_trace = Some(device_name);
        self.trace.device(config, variables);
        Ok(())
    }

    /// Uploads the recorded samples of the current trace.
    pub fn trace_upload(&mut self) {
        if self.trace.begin_upload() {
            self.command(Command::TraceUpload);
        }
    }

    /// Takes in the events that arrived and asks for fresh statistics when due. Call once per
    /// frame.
    pub fn poll(&mut self, now: Instant) {
        self.devices.poll();
        if let Some(device) = &self.device_trace
            && let Some(result) = self.devices.take_trace(device)
        {
            self.device_trace = None;
            match result {
                Ok(snapshots) => {
                    let channels: Vec<usize> = self
                        .trace
                        .variables()
                        .iter()
                        .filter_map(|(path, _)| devices::binding_of(&self.project_devices, path))
                        .map(|(_, index)| index)
                        .collect();
                    let samples = snapshots
                        .into_iter()
                        .enumerate()
                        .map(|(cycle, snapshot)| online::Sample {
                            cycle: cycle as u64,
                            time_ns: u64::try_from(snapshot.time.as_nanos()).unwrap_or(u64::MAX),
                            values: channels
                                .iter()
                                .map(|&index| {
                                    snapshot.values.get(index).cloned().unwrap_or_default()
                                })
                                .collect(),
                        })
                        .collect();
                    self.trace.received(samples, None);
                }
                Err(reason) => {
                    self.trace.command_failed_always();
                    self.error(format!("device trace: {reason}"));
                }
            }
        }
        let events = match &self.link {
            Some(link) => link.drain(),
            None => return,
        };
        for event in events {
            self.handle(event);
        }
        if self.phase == Phase::Online
            && self
                .last_status
                .is_none_or(|last| now.duration_since(last) >= STATUS_INTERVAL)
        {
            self.last_status = Some(now);
            self.command(Command::Tasks);
            self.command(Command::Faults);
            self.command(Command::Forces);
            if self.trace.is_recording() {
                self.command(Command::TraceStatus);
            }
        }
    }

    fn handle(&mut self, event: Event) {
        match event {
            Event::Connected(identity) => {
                self.target_state = Some(identity.state);
                let ours = self.image.as_ref().map(|image| image.hash);
                let same = ours.is_some() && identity.image_hash == ours;
                let changed = self.target_identity.as_ref().map(|i| i.image_hash)
                    != Some(identity.image_hash);
                if changed {
                    self.forget_program();
                }
                self.phase = if same {
                    Phase::Online
                } else {
                    Phase::ConfirmDownload {
                        reason: match identity.image_hash {
                            None => "The target has no program.".to_owned(),
                            Some(_) => {
                                format!("The target runs another program ('{}').", identity.project)
                            }
                        },
                    }
                };
                self.target_identity = Some(identity);
                self.last_status = None;
                self.watched.clear();
                self.refresh_watch();
            }
            Event::Disconnected(reason) => {
                if self.phase != Phase::Connecting || self.target_identity.is_some() {
                    self.error(format!(
                        "the target is not reachable: {reason}; trying again"
                    ));
                }
                self.phase = Phase::Lost(reason);
                self.watched.clear();
            }
            Event::Snapshot(snapshot) => {
                self.cycle = snapshot.cycle;
                for (path, (bytes, forced)) in self.watched.iter().zip(snapshot.values) {
                    let Some(Ok(resolved)) = self.resolved.get(path) else {
                        continue;
                    };
                    let text = self.show(path, resolved, &bytes);
                    let changed = self.values.get(path).is_some_and(|old| old.text != text);
                    self.values.insert(
                        path.clone(),
                        LiveValue {
                            text,
                            forced,
                            changed,
                        },
                    );
                }
            }
            Event::DownloadProgress(sent, total) => {
                if matches!(self.phase, Phase::Downloading { .. }) {
                    self.phase = Phase::Downloading { sent, total };
                }
            }
            Event::Done(state) => {
                self.target_state = Some(state);
                if matches!(self.phase, Phase::Downloading { .. }) {
                    self.forget_program();
                    if let (Some(identity), Some(image)) = (&mut self.target_identity, &self.image)
                    {
                        identity.image_hash = Some(image.hash);
                    }
                    self.phase = Phase::Online;
                    self.info("download complete".to_owned());
                    self.refresh_watch();
                }
                self.trace.command_done();
            }
            Event::Failed(reason) => {
                if matches!(self.phase, Phase::Downloading { .. }) {
                    self.phase = Phase::ConfirmDownload {
                        reason: format!(
                            "The download failed: {reason}. The target kept its program."
                        ),
                    };
                }
                self.trace.command_failed();
                self.error(reason);
            }
            Event::Resolved(answers) => {
                for (path, answer) in answers {
                    self.resolving.remove(&path);
                    self.resolved.insert(path, answer);
                }
                self.refresh_watch();
                self.advance_trace();
            }
            Event::Forces(forces) => self.forces = forces,
            Event::Tasks(tasks) => {
                self.tasks = tasks;
                self.tasks_generation += 1;
            }
            Event::Faults(faults) => self.faults = faults,
            Event::TraceStatus(status) => self.trace.status(status),
            Event::TraceProgress(received, total) => self.trace.progress(received, total),
            Event::TraceSamples {
                samples,
                trigger_sample,
            } => {
                self.trace.received(samples, trigger_sample);
            }
        }
    }

    /// A value as text: by the program's own types when the target runs the project's image,
    /// else by the elementary type the target reports.
    fn show(&self, path: &str, resolved: &Resolved, bytes: &[u8]) -> String {
        if let Some(image) = &self.image
            && self.phase == Phase::Online
            && let Ok(place) = runtime::value::resolve(&image.program, path)
            && place.bit.is_none()
        {
            return runtime::value::decode(&image.program, place.ty, bytes).to_string();
        }
        show(resolved, bytes)
    }

    /// Asks the target for the places of paths not known or asked for yet.
    fn resolve(&mut self, paths: &[String]) {
        let missing: Vec<String> = paths
            .iter()
            .filter(|path| !self.resolved.contains_key(*path) && !self.resolving.contains(*path))
            .cloned()
            .collect();
        if missing.is_empty() || self.phase != Phase::Online {
            return;
        }
        if self.command(Command::Resolve(missing.clone())) {
            self.resolving.extend(missing);
        }
    }

    /// Sends the watch list again when the wanted paths' places changed.
    fn refresh_watch(&mut self) {
        if self.phase != Phase::Online {
            return;
        }
        let wanted = self.wanted.clone();
        self.resolve(&wanted);
        let watch: Vec<String> = wanted
            .into_iter()
            .filter(|path| matches!(self.resolved.get(path), Some(Ok(_))))
            .collect();
        if watch != self.watched {
            let places = watch.iter().filter_map(|path| self.place(path)).collect();
            if self.command(Command::Watch(places)) {
                self.watched = watch;
            }
        }
    }

    /// Sends the trace configuration once all its paths are resolved.
    fn advance_trace(&mut self) {
        match self.trace.configuration(&self.resolved) {
            Ok(Some(config)) => {
                if self.command(Command::TraceStart(config)) {
                    self.trace.armed();
                }
            }
            Ok(None) => {}
            Err(reason) => {
                self.trace.command_failed();
                self.error(format!("trace: {reason}"));
            }
        }
    }

    fn command(&mut self, command: Command) -> bool {
        let sent = self.link.as_ref().is_some_and(|link| link.send(command));
        if !sent {
            let reason = if self.link.is_none() {
                "not logged in"
            } else {
                "the target is busy; try again"
            };
            self.error(reason.to_owned());
        }
        sent
    }

    fn error(&mut self, text: String) {
        self.messages.push(OnlineMessage {
            text,
            is_error: true,
        });
    }

    fn info(&mut self, text: String) {
        self.messages.push(OnlineMessage {
            text,
            is_error: false,
        });
    }
}
