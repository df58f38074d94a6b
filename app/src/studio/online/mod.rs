//! Online work with a target: login with identity check and download, run control, watched
//! values, writes and forces, task statistics, faults and traces.
//!
//! Everything goes through one [`Link`] (a background session of the `online` crate); the UI
//! calls [`Online::poll`] once per frame to take in what arrived, and never waits.

mod background;
mod debug_target;
mod device_problem;
pub(crate) mod devices;
mod events;
mod frame_locals;
mod link;
mod login_change;
mod login_choice;
pub(crate) mod modbus_reports;
mod simulator;
mod trace_problem;
mod trace_run;
mod tracing;
mod writes;

use std::collections::{HashMap, HashSet};
use std::sync::Arc;

use project_model::ModbusDevice;
use std::time::{Duration, Instant};

use online::session::{ChangeCommand, Command, SessionOptions};
use online::{Fault, Identity, Place, Reset, Resolved, TargetState, TaskInfo};
use serde::{Deserialize, Serialize};

use super::i18n::{Language, LoginText, Text};
use background::Background;
use link::Link;
pub use login_choice::{ChangeKind, ChangeOffer, ChangeRefusal, LoginChoice, grouped};
use simulator::{Simulator, SimulatorError};
pub use trace_run::{TracePhase, TraceRun};

/// How often task statistics, faults and forces are asked for while logged in.
pub(super) const STATUS_INTERVAL: Duration = Duration::from_millis(500);
/// How often watched values are read.
const POLL_INTERVAL: Duration = Duration::from_millis(100);

/// Wakes the UI when something arrived from the network.
pub type Waker = Arc<dyn Fn() + Send + Sync>;

/// A typed value the studio refused to send: the variable's path and the reason.
pub type Refusal = (String, String);

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
    /// The project it was built from, which a breakpoint's condition is compiled against so
    /// that it belongs to this very image.
    pub project: Arc<project_model::Project>,
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
    /// Connected to a target that runs another program: sending the project's program and
    /// asking whether it can take over online (`docs/debugging.md` §6); bytes sent of the total.
    CheckingChange {
        /// Bytes sent.
        sent: usize,
        /// Bytes in all.
        total: usize,
    },
    /// The check came back: the user chooses how to log in ([`LoginChoice`]).
    ChooseLogin(ChangeOffer),
    /// The online change is being applied between two cycles.
    ApplyingChange,
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
    resolved: HashMap<String, Result<Resolved, online::OnlineError>>,
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
    /// The language of the messages, set by the studio every frame.
    language: Language,
    /// The debug session on the target.
    debugging: debug_target::Debugging,
    /// The locals of the halted function or method the studio shows.
    frame_locals: frame_locals::FrameLocals,
    /// The target's Modbus devices as `MODBUS_DEVICES` last reported them.
    modbus_reports: modbus_reports::ModbusReports,
    /// The kind of target of the last login, which the status line names.
    logged_in_target: Option<TargetKind>,
}

impl Drop for Online {
    /// Quitting logs out: the session is told to close before the background thread stops,
    /// which gives it [`background::LOGOUT_GRACE`] to do so.
    fn drop(&mut self) {
        self.link = None;
    }
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
            language: Language::default(),
            debugging: debug_target::Debugging::default(),
            frame_locals: frame_locals::FrameLocals::default(),
            modbus_reports: modbus_reports::ModbusReports::default(),
            logged_in_target: None,
        }
    }

    /// Puts the messages from now on in `language`.
    pub fn set_language(&mut self, language: Language) {
        self.language = language;
    }

    /// `text` in the messages' language.
    fn text(&self, text: Text) -> &'static str {
        text.get(self.language)
    }

    /// `text` of the online change login in the messages' language.
    fn login_text(&self, text: LoginText) -> &'static str {
        text.get(self.language)
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
                            let (text, reason) = match &error {
                                SimulatorError::Listen(reason) => {
                                    (Text::SimulatorCannotListen, reason.to_string())
                                }
                                SimulatorError::Runtime(reason) => {
                                    (Text::SimulatorDidNotStart, reason.clone())
                                }
                            };
                            self.error(text.fill(self.language, &[("reason", &reason)]));
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
                self.error(self.text(Text::OnlineNoAddress).to_owned());
                return;
            }
        };
        self.image = Some(image);
        self.logged_in_target = Some(target);
        self.link = Some(Link::open(
            background,
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
                    let text = self.text(Text::OnlineThreadFailed);
                    self.error(format!("{text}: {error}"));
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

    /// Ends the session, which logs out of the target in the background (ending its token at
    /// once); the target keeps running as it is.
    pub fn logout(&mut self) {
        self.link = None;
        self.debug_connection_ended();
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
        self.forget_modbus_reports();
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

    /// The user chose how to log in to a target that runs another program; nothing on the
    /// target changed before this.
    pub fn choose_login(&mut self, choice: LoginChoice) {
        let Phase::ChooseLogin(offer) = &self.phase else {
            return;
        };
        if !choice.is_enabled(&offer.check) {
            return;
        }
        let transfer = offer.transfer;
        match choice {
            LoginChoice::OnlineChange => {
                if self.command(Command::OnlineChange(ChangeCommand::Apply(transfer))) {
                    self.phase = Phase::ApplyingChange;
                }
            }
            LoginChoice::Download => {
                let total = self.image.as_ref().map_or(0, |image| image.bytes.len());
                let commit = ChangeCommand::Commit {
                    transfer,
                    start: false,
                };
                if self.command(Command::OnlineChange(commit)) {
                    // The bytes are on the target already; only the commit is left.
                    self.phase = Phase::Downloading { sent: total, total };
                }
            }
            LoginChoice::WithoutChange => {
                if self.command(Command::OnlineChange(ChangeCommand::Abort(transfer))) {
                    self.phase = Phase::Online;
                    self.info(self.login_text(LoginText::LoggedInWithoutChange).to_owned());
                    self.refresh_watch();
                }
            }
        }
    }

    /// The user declined the download: log out again.
    pub fn cancel_download(&mut self) {
        if let Phase::ChooseLogin(offer) = &self.phase {
            // The checked transfer is dropped before the session closes, so the target is
            // left exactly as it was.
            let transfer = offer.transfer;
            self.command(Command::OnlineChange(ChangeCommand::Abort(transfer)));
        }
        self.logout();
        self.info(self.text(Text::LoginCancelled).to_owned());
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
        let logged_in = self.is_logged_in();
        let on_device = |path: &String| {
            matches!(
                devices::bound(devices, path, logged_in),
                Some(devices::Bound::Polled(..))
            )
        };
        // Devices are polled only while one of their variables is watched, and only those the
        // studio serves (`devices::source_of`): never one the runtime masters while logged in.
        let needs_devices = paths.iter().any(on_device) || !self.devices.is_empty();
        if needs_devices
            && self.start_background()
            && let (Some(background), Some(waker)) = (&self.background, &self.waker)
        {
            self.devices.keep(
                background.handle(),
                devices,
                &paths,
                logged_in,
                waker,
                self.language,
            );
        }
        // A device-bound variable is read from the target too: the program computes with its
        // own copy, which is what a diagram's power flow and values must show.
        self.wanted = paths;
        self.refresh_watch();
    }

    /// The last value the target gave for a watched variable, even one bound to a Modbus
    /// device: the value the program computes with, which the LD/FBD views show beside the
    /// power it gives.
    pub fn program_value(&self, path: &str) -> Option<&LiveValue> {
        self.values.get(path)
    }

    /// The last value of a watched variable: from its Modbus device when the studio polls it,
    /// else the runtime's (a runtime device's variable while logged in is a program variable).
    pub fn value(&self, path: &str) -> Option<&LiveValue> {
        match self.bound(path) {
            // The device's own value, never the program's copy read beside it.
            Some(devices::Bound::Polled(device, channel)) => {
                self.devices.value(device, channel).and_then(Result::ok)
            }
            Some(devices::Bound::SeveralValues(..) | devices::Bound::RuntimeWhenLoggedIn) => None,
            Some(devices::Bound::Runtime) | None => self.values.get(path),
        }
    }

    /// Why a watched variable has no value: unknown on the target, its device unreachable, or a
    /// channel of several values, which the studio's poll does not read.
    pub fn problem(&self, path: &str) -> Option<String> {
        match self.bound(path) {
            Some(devices::Bound::Polled(device, channel)) => {
                match self.devices.value(device, channel) {
                    Some(Err(problem)) => Some(problem.to_string()),
                    _ => None,
                }
            }
            Some(devices::Bound::SeveralValues(_, count)) => Some(self.several_values(path, count)),
            Some(devices::Bound::RuntimeWhenLoggedIn) => None,
            Some(devices::Bound::Runtime) | None => match self.resolved.get(path) {
                Some(Err(reason)) => Some(reason.to_string()),
                _ => None,
            },
        }
    }

    /// How the studio reaches a path bound to a Modbus device of the project now; `None` for a
    /// path bound to no device.
    pub fn bound(&self, path: &str) -> Option<devices::Bound<'_>> {
        devices::bound(&self.project_devices, path, self.is_logged_in())
    }

    /// Whether the studio polls a path's device itself, so it is read, written and traced
    /// without a login.
    pub fn is_polled_by_studio(&self, path: &str) -> bool {
        matches!(
            self.bound(path),
            Some(devices::Bound::Polled(..) | devices::Bound::SeveralValues(..))
        )
    }

    /// Why the studio does not read `path`, bound to a channel of `count` values.
    fn several_values(&self, path: &str, count: u16) -> String {
        Text::DeviceArrayChannel.fill(
            self.language,
            &[("path", path), ("count", &count.to_string())],
        )
    }
}
