//! Traces: started on the target, or recorded by polling a Modbus device, and uploaded.

use std::time::Duration;

use online::session::Command;
use online::{Place, Resolved};

use super::Online;
use super::devices::Bound;
use super::trace_problem::TraceProblem;
use crate::studio::i18n::Text;

impl Online {
    /// Configures and arms a trace of `config` on the target, or, when its variables are the
    /// channels of one Modbus device the studio polls, records it by polling that device (a
    /// runtime device's variables while logged in are the program's, traced on the target).
    pub fn trace_start(&mut self, config: &project_model::TraceConfig) {
        if config
            .variables
            .iter()
            .any(|v| self.is_polled_by_studio(&v.path))
        {
            if let Err(reason) = self.device_trace_start(config) {
                self.error(format!("{}: {reason}", self.trace_named(&config.name)));
            }
            return;
        }
        let Some(image) = &self.image else {
            let text = self.text(Text::LogInFirst);
            self.error(format!("{}: {text}", self.trace_named(&config.name)));
            return;
        };
        match self.trace.prepare(config, &image.tasks, self.language) {
            Ok(paths) => {
                self.resolve(&paths);
                self.advance_trace();
            }
            Err(reason) => self.error(format!("{}: {reason}", self.trace_named(&config.name))),
        }
    }

    /// Starts recording a trace of device channels by polling the device.
    fn device_trace_start(
        &mut self,
        config: &project_model::TraceConfig,
    ) -> Result<(), TraceProblem> {
        let language = self.language;
        let mut device_name = None;
        let mut variables = Vec::new();
        for variable in &config.variables {
            let (device, index) = match self.bound(&variable.path) {
                Some(Bound::Polled(device, index)) => (device, index),
                Some(Bound::SeveralValues(_, count)) => {
                    return Err(TraceProblem::SeveralValues {
                        path: variable.path.clone(),
                        count,
                        language,
                    });
                }
                _ => {
                    return Err(TraceProblem::NotBoundToDevice {
                        path: variable.path.clone(),
                        language,
                    });
                }
            };
            if device_name.get_or_insert_with(|| device.name.clone()) != &device.name {
                return Err(TraceProblem::DifferentDevices { language });
            }
            let channels = crate::modbus_devices::channels_of(device);
            let channel = channels
                .get(index)
                .ok_or(TraceProblem::BindingNoChannel { language })?;
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
            return Err(TraceProblem::DeviceTraceNoTrigger { language });
        }
        let device_name = device_name.ok_or(TraceProblem::NoVariables { language })?;
        let device = self
            .project_devices
            .iter()
            .find(|d| d.name == device_name)
            .ok_or(TraceProblem::DeviceGone { language })?;
        let interval = Duration::from_millis(
            u64::from(device.studio_poll_interval_ms().max(10))
                * u64::from(config.every_n_cycles.max(1)),
        );
        let samples = usize::try_from(config.record_count)
            .unwrap_or(usize::MAX)
            .min(100_000);
        self.devices
            .trace(&device_name, samples, interval, self.language)?;
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

    /// Sends the trace configuration once all its paths are resolved.
    pub(super) fn advance_trace(&mut self) {
        match self.trace.configuration(&self.resolved, self.language) {
            Ok(Some(config)) => {
                if self.command(Command::TraceStart(config)) {
                    self.trace.armed();
                }
            }
            Ok(None) => {}
            Err(reason) => {
                self.trace.command_failed();
                let text = self.text(Text::TraceWord);
                self.error(format!("{text}: {reason}"));
            }
        }
    }

    /// `trace 'name'` in the messages' language.
    pub(super) fn trace_named(&self, name: &str) -> String {
        self.text(Text::TraceNamed).replace("{name}", name)
    }
}
