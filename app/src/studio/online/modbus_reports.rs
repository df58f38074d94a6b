//! The Modbus devices the target's master polls, as `MODBUS_DEVICES` last reported them
//! (`docs/modbus-master.md` §9.1, §9.2): asked for once a second while logged in to a target
//! that runs a program with runtime devices, forgotten at logout.

use std::time::{Duration, Instant};

use online::ModbusDeviceReport;
use online::session::{Command, ModbusDevicesAnswer};

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
}

impl Online {
    /// Asks for the Modbus devices' reports when they are due: logged in to a target that runs
    /// the project's program, and only when that program has runtime devices.
    pub(super) fn ask_modbus_devices_when_due(&mut self, now: Instant) {
        if self.phase != Phase::Online || self.runtime_device_count() == 0 {
            return;
        }
        let due = self
            .modbus_reports
            .last_asked
            .is_none_or(|last| now.duration_since(last) >= MODBUS_DEVICES_INTERVAL);
        if due {
            self.modbus_reports.last_asked = Some(now);
            self.command(Command::ModbusDevices);
        }
    }

    /// Takes in the target's answer to `MODBUS_DEVICES`. A failure is kept to be shown; it is
    /// not a message, since the question comes back every second.
    pub(super) fn modbus_devices_answered(&mut self, answer: ModbusDevicesAnswer) {
        match answer {
            ModbusDevicesAnswer::Reports(reports) => {
                self.modbus_reports.reports = reports;
                self.modbus_reports.answered = true;
                self.modbus_reports.problem = None;
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

    /// Forgets the reports (at logout, or when the target's program changes).
    pub(super) fn forget_modbus_reports(&mut self) {
        self.modbus_reports = ModbusReports::default();
    }

    /// The number of devices the program logged in with has its runtime master poll: the
    /// devices of its image's Modbus master section; 0 when not logged in.
    pub fn runtime_device_count(&self) -> usize {
        if self.link.is_none() {
            return 0;
        }
        self.image
            .as_ref()
            .and_then(|image| image.program.modbus_master.as_ref())
            .map_or(0, |section| section.devices.len())
    }

    /// The last report of the runtime device `name`, while logged in to a target that runs the
    /// project's program; the runtime names devices as the project does, without case.
    pub fn modbus_device_report(&self, name: &str) -> Option<&ModbusDeviceReport> {
        if self.phase != Phase::Online {
            return None;
        }
        self.modbus_reports
            .reports
            .iter()
            .find(|report| report.name.eq_ignore_ascii_case(name))
    }

    /// Whether the target answered `MODBUS_DEVICES` with reports since the login, so a device
    /// missing from them is not in its program.
    pub fn modbus_reports_answered(&self) -> bool {
        self.phase == Phase::Online && self.modbus_reports.answered
    }

    /// Why the last `MODBUS_DEVICES` question had no answer, while logged in.
    pub fn modbus_reports_problem(&self) -> Option<&ModbusReportsProblem> {
        if self.phase != Phase::Online {
            return None;
        }
        self.modbus_reports.problem.as_ref()
    }

    /// Which kind of target the studio is logged in to; `None` when not logged in.
    pub fn logged_in_target(&self) -> Option<TargetKind> {
        self.link.as_ref().and(self.logged_in_target)
    }
}
