//! The Modbus devices the target's master polls, as `MODBUS_DEVICES` last reported them
//! (`docs/modbus-master.md` §9.1, §9.2): asked for once a second while logged in to a target
//! that runs the project's program with runtime devices, one question at a time, forgotten at
//! logout.

use std::time::{Duration, Instant};

use online::session::{Command, ModbusDevicesAnswer};
use online::{MAX_MODBUS_DEVICE_NAME_BYTES, ModbusDeviceReport, cut};
use program_image::modbus_master::DeviceDef;
use project_model::same_identifier;

use super::{Online, Phase, TargetKind};

/// How often the Modbus devices' states and counters are asked for while logged in.
pub(super) const MODBUS_DEVICES_INTERVAL: Duration = Duration::from_secs(1);

/// Why the studio has no reports of the target's Modbus devices although it asked.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ModbusReportsProblem {
    /// The target does not know `MODBUS_DEVICES` (an older runtime).
    NotReported,
    /// The target refused the question; the words are its reason.
    Refused(String),
}

/// What the studio knows of the target's Modbus devices. Lives as long as the login; nothing
/// of it is saved.
#[derive(Debug, Default)]
pub(super) struct ModbusReports {
    /// Every device of the last answer, in the image's order.
    reports: Vec<ModbusDeviceReport>,
    /// Whether reports came since the login (of devices other than one not reported, too).
    answered: bool,
    /// Why the last question had no answer; cleared by the next answer.
    problem: Option<ModbusReportsProblem>,
    /// When the question was last asked, so it is asked once per [`MODBUS_DEVICES_INTERVAL`].
    last_asked: Option<Instant>,
    /// Whether a question was sent and neither its answer nor the end of its connection came
    /// yet: a slow target gets one question at a time rather than a full queue.
    in_flight: bool,
}

/// Everything that decides whether the Modbus devices' question is asked now; made each frame.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ModbusQuestion {
    /// Logged in ([`Phase::Online`]).
    pub online: bool,
    /// The target runs the project's program, whose image names the devices.
    pub runs_project: bool,
    /// That program's image has devices the runtime masters.
    pub has_runtime_devices: bool,
    /// The last question has not been answered yet.
    pub in_flight: bool,
    /// The target said it does not know the question (an older runtime): not asked again
    /// before the next login.
    pub not_reported: bool,
    /// [`MODBUS_DEVICES_INTERVAL`] passed since the last question, or none was asked.
    pub interval_passed: bool,
}

impl ModbusQuestion {
    /// Whether the question is due.
    pub(crate) fn is_due(self) -> bool {
        self.online
            && self.runs_project
            && self.has_runtime_devices
            && !self.in_flight
            && !self.not_reported
            && self.interval_passed
    }
}

impl Online {
    /// Asks for the Modbus devices' reports when they are due ([`ModbusQuestion::is_due`]).
    /// A full command queue is not reported: the question comes back at the next second.
    pub(super) fn ask_modbus_devices_when_due(&mut self, now: Instant) {
        let reports = &self.modbus_reports;
        let question = ModbusQuestion {
            online: self.phase == Phase::Online,
            runs_project: self.runs_project(),
            has_runtime_devices: self.runtime_device_count() > 0,
            in_flight: reports.in_flight,
            not_reported: reports.problem == Some(ModbusReportsProblem::NotReported),
            interval_passed: reports
                .last_asked
                .is_none_or(|last| now.duration_since(last) >= MODBUS_DEVICES_INTERVAL),
        };
        if !question.is_due() {
            return;
        }
        self.modbus_reports.last_asked = Some(now);
        let sent = self
            .link
            .as_ref()
            .is_some_and(|link| link.send(Command::ModbusDevices));
        self.modbus_reports.in_flight = sent;
    }

    /// Takes in the target's answer to `MODBUS_DEVICES`. A failure is kept to be shown; it is
    /// not a message, since the question comes back every second. An answer that arrives when
    /// the target no longer runs the project's program (another program was found, or the
    /// user logged in without change) is dropped: its devices are not the project's.
    pub(super) fn modbus_devices_answered(&mut self, answer: ModbusDevicesAnswer) {
        self.modbus_reports.in_flight = false;
        if !self.logged_in_to_project() {
            return;
        }
        match answer {
            ModbusDevicesAnswer::Reports { reports, state } => {
                self.modbus_reports.reports = reports;
                self.modbus_reports.answered = true;
                self.modbus_reports.problem = None;
                // Asked with the reports, so that a start, a stop or a fault from elsewhere
                // shows on the devices within a second.
                self.target_state = Some(state);
            }
            ModbusDevicesAnswer::NotReported => {
                self.modbus_reports.reports.clear();
                self.modbus_reports.problem = Some(ModbusReportsProblem::NotReported);
            }
            // The reports are dropped rather than shown stale beside a refusal nobody sees.
            ModbusDevicesAnswer::Refused(reason) => {
                self.modbus_reports.reports.clear();
                self.modbus_reports.problem = Some(ModbusReportsProblem::Refused(reason));
            }
        }
    }

    /// The connection was made or lost: a question sent on it will get no answer.
    pub(super) fn modbus_question_ended(&mut self) {
        self.modbus_reports.in_flight = false;
    }

    /// Forgets the reports (at logout, or when the target's program changes).
    pub(super) fn forget_modbus_reports(&mut self) {
        self.modbus_reports = ModbusReports::default();
    }

    /// Whether the studio is logged in to a target that runs the project's program: only then
    /// are the target's devices the project's.
    fn logged_in_to_project(&self) -> bool {
        self.phase == Phase::Online && self.runs_project()
    }

    /// The devices of the Modbus master section of the program logged in with, while the
    /// target runs it.
    fn runtime_devices(&self) -> Option<&[DeviceDef]> {
        if !self.logged_in_to_project() {
            return None;
        }
        let image = self.image.as_ref()?;
        let section = image.program.modbus_master.as_ref()?;
        Some(&section.devices)
    }

    /// The number of devices the program logged in with has its runtime master poll: the
    /// devices of its image's Modbus master section; 0 when not logged in to a target that
    /// runs that program.
    pub fn runtime_device_count(&self) -> usize {
        self.runtime_devices().map_or(0, <[DeviceDef]>::len)
    }

    /// The last report of the runtime device `name`, while logged in to a target that runs the
    /// project's program.
    pub fn modbus_device_report(&self, name: &str) -> Option<&ModbusDeviceReport> {
        report_of(self.runtime_devices()?, &self.modbus_reports.reports, name)
    }

    /// Whether the target answered `MODBUS_DEVICES` with reports since the login, so a device
    /// missing from them is not in its program.
    pub fn modbus_reports_answered(&self) -> bool {
        self.logged_in_to_project() && self.modbus_reports.answered
    }

    /// Why the last `MODBUS_DEVICES` question had no answer, while logged in to a target that
    /// runs the project's program.
    pub fn modbus_reports_problem(&self) -> Option<&ModbusReportsProblem> {
        if !self.logged_in_to_project() {
            return None;
        }
        self.modbus_reports.problem.as_ref()
    }

    /// Which kind of target the studio is logged in to; `None` when not logged in.
    pub fn logged_in_target(&self) -> Option<TargetKind> {
        self.link.as_ref().and(self.logged_in_target)
    }
}

/// The report of the device the project names `name` among `reports`, which the runtime lists
/// in the order of the image's `devices`: the device is found in the image as the project finds
/// names (without case), and its report is the one at the same place, provided it carries the
/// image's name as the runtime sends it (cut to [`MAX_MODBUS_DEVICE_NAME_BYTES`]).
fn report_of<'a>(
    devices: &[DeviceDef],
    reports: &'a [ModbusDeviceReport],
    name: &str,
) -> Option<&'a ModbusDeviceReport> {
    let index = devices
        .iter()
        .position(|device| same_identifier(&device.name, name))?;
    let report = reports.get(index)?;
    let sent_name = cut(&devices[index].name, MAX_MODBUS_DEVICE_NAME_BYTES);
    (report.name == sent_name).then_some(report)
}

#[cfg(test)]
#[path = "modbus_reports_tests.rs"]
mod tests;
