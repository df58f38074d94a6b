//! Third-party Modbus TCP devices of the project, polled while any of their bound variables is
//! watched: their values, writes and forces go through the same panes as the controller's,
//! without a login or a download. A device the runtime masters (one with an I/O task) is read
//! through the runtime instead while logged in ([`source_of`], `docs/modbus-master.md` §9.2).

use std::collections::HashMap;
use std::sync::{Arc, mpsc};
use std::time::Duration;

use online::device::Device;
use project_model::{ModbusDevice, ModbusLink};
use tokio::sync::mpsc as async_mpsc;

use super::device_problem::DeviceProblem;
use super::{LiveValue, Waker};
use crate::modbus_devices::{ConnectError, channel_index, polled_bindings};
use crate::studio::i18n::{Language, Text};
use crate::value_text::{describe_elementary, hex};

/// What the UI asks a device's task to do.
#[derive(Debug)]
enum DeviceCommand {
    Write(usize, Vec<u8>),
    Force(usize, Vec<u8>),
    Unforce(Option<usize>),
    /// Poll `samples` times, `interval` apart, and report every poll.
    Trace(usize, Duration),
}

/// What a device's task reports.
#[derive(Debug)]
enum DeviceEvent {
    /// One poll: each channel's bytes, and the forced channels.
    Values(Vec<Vec<u8>>, Vec<usize>),
    /// The device cannot be reached or refused something; the task tries again.
    Problem(String),
    /// A trace by polling ended: every poll with its time, or why it stopped.
    Trace(Result<Vec<online::device::DeviceSnapshot>, online::OnlineError>),
}

/// One device being polled.
struct DeviceLink {
    /// The configuration the task was started with; a changed device node restarts it.
    config: ModbusDevice,
    commands: async_mpsc::Sender<DeviceCommand>,
    events: mpsc::Receiver<DeviceEvent>,
    values: Vec<Option<LiveValue>>,
    forced: Vec<usize>,
    problem: Option<String>,
    /// A finished trace, until it is taken.
    trace: Option<Result<Vec<online::device::DeviceSnapshot>, online::OnlineError>>,
    task: tokio::task::JoinHandle<()>,
}

impl Drop for DeviceLink {
    fn drop(&mut self) {
        self.task.abort();
    }
}

/// Every device being polled, by device name.
#[derive(Default)]
pub struct DeviceLinks {
    links: HashMap<String, DeviceLink>,
}

/// A forced device channel, for the forces list.
#[derive(Clone, Debug, PartialEq)]
pub struct DeviceForce {
    /// The device.
    pub device: String,
    /// The channel's index.
    pub channel: usize,
    /// The bound variable's path.
    pub path: String,
    /// The forced value.
    pub value: String,
}

/// Who serves the variables bound to a Modbus device: read, written, forced and traced
/// (`docs/modbus-master.md` §9.2).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DeviceSource {
    /// The studio's own poll: a studio device (no I/O task) over TCP, logged in or not, or a
    /// runtime device over TCP while not logged in.
    StudioPoll,
    /// The runtime, as the program variables they are: a device with an I/O task while logged
    /// in. The studio never polls such a device then, so it does not get two masters.
    Runtime,
    /// Nobody: a device on a serial port while not logged in. Only the runtime reaches a serial
    /// line; the value shows once logged in.
    RuntimeWhenLoggedIn,
}

/// Who serves the variables bound to `device`, given whether the studio is logged in to a
/// runtime. The one decision every reader of device-bound variables follows: the watch list,
/// inline values, writes, forces and traces.
pub fn source_of(device: &ModbusDevice, logged_in: bool) -> DeviceSource {
    match (&device.link, logged_in) {
        (ModbusLink::Rtu { .. }, false) => DeviceSource::RuntimeWhenLoggedIn,
        // An RTU device without a task is a project problem the build refuses; its variables
        // are still the program's while logged in.
        (ModbusLink::Rtu { .. }, true) => DeviceSource::Runtime,
        (ModbusLink::Tcp { .. }, true) if device.is_runtime_device() => DeviceSource::Runtime,
        (ModbusLink::Tcp { .. }, _) => DeviceSource::StudioPoll,
    }
}

/// How the studio reaches a variable bound to a Modbus device.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Bound<'d> {
    /// The studio polls it: the device and the channel's index among
    /// [`crate::modbus_devices::channels_of`].
    Polled(&'d ModbusDevice, usize),
    /// The studio would poll the device, but the binding holds `count` values, which its poll
    /// does not read (see [`crate::modbus_devices::polled_bindings`]).
    SeveralValues(&'d ModbusDevice, u16),
    /// Through the runtime, as any program variable.
    Runtime,
    /// Not now: its device is on a serial port and the studio is not logged in.
    RuntimeWhenLoggedIn,
}

/// How the studio reaches `path` when it is bound to one of `devices`; `None` for a variable
/// bound to no device, which only the runtime has.
pub fn bound<'d>(devices: &'d [ModbusDevice], path: &str, logged_in: bool) -> Option<Bound<'d>> {
    devices.iter().find_map(|device| {
        let index = device
            .bindings
            .iter()
            .position(|binding| binding.variable.eq_ignore_ascii_case(path))?;
        Some(match source_of(device, logged_in) {
            DeviceSource::Runtime => Bound::Runtime,
            DeviceSource::RuntimeWhenLoggedIn => Bound::RuntimeWhenLoggedIn,
            DeviceSource::StudioPoll => match channel_index(device, index) {
                Some(channel) => Bound::Polled(device, channel),
                None => Bound::SeveralValues(device, device.bindings[index].count),
            },
        })
    })
}

/// The devices the studio polls for `paths`: those its own poll serves ([`source_of`]) that
/// hold one of `paths` on a channel it reads.
fn devices_to_poll<'d>(
    devices: &'d [ModbusDevice],
    paths: &[String],
    logged_in: bool,
) -> Vec<&'d ModbusDevice> {
    devices
        .iter()
        .filter(|device| source_of(device, logged_in) == DeviceSource::StudioPoll)
        .filter(|device| {
            paths
                .iter()
                .any(|path| polled_bindings(device).any(|b| b.variable.eq_ignore_ascii_case(path)))
        })
        .collect()
}

impl DeviceLinks {
    /// Polls exactly the devices the studio serves ([`source_of`]) that hold one of `paths`,
    /// starting and stopping tasks on `handle` as needed; a device's problems are worded in
    /// `language`.
    pub fn keep(
        &mut self,
        handle: &tokio::runtime::Handle,
        devices: &[ModbusDevice],
        paths: &[String],
        logged_in: bool,
        wake: &Waker,
        language: Language,
    ) {
        let wanted = devices_to_poll(devices, paths, logged_in);
        self.links.retain(|name, link| {
            wanted
                .iter()
                .any(|device| device.name == *name && **device == link.config)
        });
        for device in wanted {
            if !self.links.contains_key(&device.name) {
                let link = start(handle, device.clone(), Arc::clone(wake), language);
                self.links.insert(device.name.clone(), link);
            }
        }
    }

    /// Whether any device is polled.
    pub fn is_empty(&self) -> bool {
        self.links.is_empty()
    }

    /// Takes in what the device tasks reported.
    pub fn poll(&mut self) {
        for link in self.links.values_mut() {
            for event in link.events.try_iter().collect::<Vec<_>>() {
                match event {
                    DeviceEvent::Values(values, forced) => {
                        link.problem = None;
                        let channels = crate::modbus_devices::channels_of(&link.config);
                        let mut shown = Vec::with_capacity(values.len());
                        for (index, bytes) in values.iter().enumerate() {
                            let text = match channels.get(index) {
                                Some(channel) => describe_elementary(channel.ty, bytes),
                                None => format!("16#{}", hex(bytes)),
                            };
                            let changed = link
                                .values
                                .get(index)
                                .and_then(Option::as_ref)
                                .is_some_and(|old| old.text != text);
                            shown.push(Some(LiveValue {
                                text,
                                forced: forced.contains(&index),
                                changed,
                            }));
                        }
                        link.values = shown;
                        link.forced = forced;
                    }
                    DeviceEvent::Problem(problem) => link.problem = Some(problem),
                    DeviceEvent::Trace(result) => link.trace = Some(result),
                }
            }
        }
    }

    /// The last value of channel `index` of a polled `device`, or why there is none.
    pub fn value(
        &self,
        device: &ModbusDevice,
        index: usize,
    ) -> Option<Result<&LiveValue, DeviceProblem>> {
        let link = self.links.get(&device.name)?;
        if let Some(problem) = &link.problem {
            return Some(Err(DeviceProblem::Unreachable {
                device: device.name.clone(),
                problem: problem.clone(),
            }));
        }
        link.values.get(index).and_then(Option::as_ref).map(Ok)
    }

    /// Sends a write or force of channel `index` of a polled `device`.
    pub fn send(
        &mut self,
        device: &ModbusDevice,
        index: usize,
        bytes: Vec<u8>,
        force: bool,
        language: Language,
    ) -> Result<(), DeviceProblem> {
        let link = self
            .links
            .get(&device.name)
            .ok_or_else(|| not_polled(&device.name, language))?;
        let command = if force {
            DeviceCommand::Force(index, bytes)
        } else {
            DeviceCommand::Write(index, bytes)
        };
        link.commands
            .try_send(command)
            .map_err(|_| busy(&device.name, language))
    }

    /// Starts a trace of a polled device: `samples` polls, `interval` apart.
    pub fn trace(
        &mut self,
        device: &str,
        samples: usize,
        interval: Duration,
        language: Language,
    ) -> Result<(), DeviceProblem> {
        let link = self
            .links
            .get_mut(device)
            .ok_or_else(|| not_polled(device, language))?;
        link.trace = None;
        link.commands
            .try_send(DeviceCommand::Trace(samples, interval))
            .map_err(|_| busy(device, language))
    }

    /// A finished trace of `device`, once.
    pub fn take_trace(
        &mut self,
        device: &str,
    ) -> Option<Result<Vec<online::device::DeviceSnapshot>, online::OnlineError>> {
        self.links
            .get_mut(device)
            .and_then(|link| link.trace.take())
    }

    /// Releases one device channel's force, or every device force with `None`.
    pub fn unforce(&mut self, target: Option<(&str, usize)>) {
        for (name, link) in &self.links {
            match target {
                Some((device, channel)) if device == name => {
                    let _ = link
                        .commands
                        .try_send(DeviceCommand::Unforce(Some(channel)));
                }
                Some(_) => {}
                None => {
                    let _ = link.commands.try_send(DeviceCommand::Unforce(None));
                }
            }
        }
    }

    /// Every forced device channel.
    pub fn forces(&self) -> Vec<DeviceForce> {
        let mut out = Vec::new();
        for (name, link) in &self.links {
            for &channel in &link.forced {
                let path = polled_bindings(&link.config)
                    .nth(channel)
                    .map(|b| b.variable.clone())
                    .unwrap_or_default();
                let value = link
                    .values
                    .get(channel)
                    .and_then(Option::as_ref)
                    .map(|v| v.text.clone())
                    .unwrap_or_default();
                out.push(DeviceForce {
                    device: name.clone(),
                    channel,
                    path,
                    value,
                });
            }
        }
        out.sort_by(|a, b| (&a.device, a.channel).cmp(&(&b.device, b.channel)));
        out
    }
}

/// Starts the task that connects to a device and polls it, retrying once a second when it is
/// away; a failed connection is worded in `language`.
fn start(
    handle: &tokio::runtime::Handle,
    config: ModbusDevice,
    wake: Waker,
    language: Language,
) -> DeviceLink {
    let (commands, mut command_rx) = async_mpsc::channel::<DeviceCommand>(32);
    let (event_tx, events) = mpsc::channel();
    let device = config.clone();
    let task = handle.spawn(async move {
        let report = |event: DeviceEvent| {
            let sent = event_tx.send(event).is_ok();
            wake();
            sent
        };
        let interval = Duration::from_millis(u64::from(device.studio_poll_interval_ms().max(10)));
        loop {
            let mut connected: Device = match crate::modbus_devices::connect(&device).await {
                Ok(connected) => connected,
                Err(error) => {
                    if !report(DeviceEvent::Problem(connect_problem(&error, language))) {
                        return;
                    }
                    tokio::time::sleep(Duration::from_secs(1)).await;
                    continue;
                }
            };
            let mut ticker = tokio::time::interval(interval);
            loop {
                tokio::select! {
                    _ = ticker.tick() => {
                        match connected.poll().await {
                            Ok(snapshot) => {
                                let forced = connected.forces().into_iter().map(|(i, _)| i).collect();
                                if !report(DeviceEvent::Values(snapshot.values, forced)) {
                                    return;
                                }
                            }
                            Err(error) => {
                                if !report(DeviceEvent::Problem(error.to_string())) {
                                    return;
                                }
                                break;
                            }
                        }
                    }
                    command = command_rx.recv() => {
                        let result = match command {
                            None => return,
                            Some(DeviceCommand::Write(index, bytes)) => connected.write(index, &bytes).await,
                            Some(DeviceCommand::Force(index, bytes)) => connected.force(index, bytes).await,
                            Some(DeviceCommand::Unforce(index)) => {
                                connected.unforce(index);
                                Ok(())
                            }
                            Some(DeviceCommand::Trace(samples, every)) => {
                                let traced = connected.trace(samples, every).await;
                                let failed = traced.is_err();
                                if !report(DeviceEvent::Trace(traced)) {
                                    return;
                                }
                                if failed {
                                    break;
                                }
                                Ok(())
                            }
                        };
                        if let Err(error) = result
                            && !report(DeviceEvent::Problem(error.to_string()))
                        {
                            return;
                        }
                    }
                }
            }
            tokio::time::sleep(Duration::from_secs(1)).await;
        }
    });
    DeviceLink {
        config,
        commands,
        events,
        values: Vec::new(),
        forced: Vec::new(),
        problem: None,
        trace: None,
        task,
    }
}

/// Why the studio could not connect to a device, in `language`.
fn connect_problem(error: &ConnectError, language: Language) -> String {
    match error {
        ConnectError::OnSerialPort(device) => {
            Text::DeviceOnSerialPort.fill(language, &[("device", device)])
        }
        ConnectError::NotAnAddress { device, address } => {
            Text::DeviceNotAnAddress.fill(language, &[("device", device), ("address", address)])
        }
        // The connection's own errors come from the `online` crate, in English, as every
        // other transport error the studio shows.
        ConnectError::Online(error) => error.to_string(),
    }
}

/// Why a device cannot be written or traced: nothing polls it.
fn not_polled(device: &str, language: Language) -> DeviceProblem {
    DeviceProblem::NotPolled {
        device: device.to_owned(),
        language,
    }
}

/// Why a device command was refused: the device's queue is full.
fn busy(device: &str, language: Language) -> DeviceProblem {
    DeviceProblem::Busy {
        device: device.to_owned(),
        language,
    }
}

#[cfg(test)]
mod tests {
    use project_model::{ModbusBinding, ModbusDataType, ModbusTable};

    use super::*;

    /// A device named `name` with one INT channel bound to each of `variables`.
    fn device(name: &str, variables: &[&str]) -> ModbusDevice {
        ModbusDevice {
            bindings: variables
                .iter()
                .zip(0..)
                .map(|(variable, address)| {
                    ModbusBinding::new(
                        *variable,
                        ModbusTable::HoldingRegister,
                        address,
                        ModbusDataType::Int16,
                    )
                })
                .collect(),
            ..ModbusDevice::tcp(name, "127.0.0.1", 502)
        }
    }

    fn with_task(mut device: ModbusDevice) -> ModbusDevice {
        device.task = Some("MainTask".into());
        device
    }

    fn on_serial_port(mut device: ModbusDevice) -> ModbusDevice {
        device.link = ModbusLink::Rtu {
            serial_port: "RS485".into(),
        };
        device
    }

    #[test]
    fn the_source_follows_the_task_the_link_and_the_login() {
        let studio = device("Drive", &[]);
        let runtime = with_task(device("Drive", &[]));
        let rtu = on_serial_port(with_task(device("Meter", &[])));
        assert_eq!(source_of(&studio, false), DeviceSource::StudioPoll);
        assert_eq!(source_of(&studio, true), DeviceSource::StudioPoll);
        assert_eq!(source_of(&runtime, false), DeviceSource::StudioPoll);
        assert_eq!(source_of(&runtime, true), DeviceSource::Runtime);
        assert_eq!(source_of(&rtu, false), DeviceSource::RuntimeWhenLoggedIn);
        assert_eq!(source_of(&rtu, true), DeviceSource::Runtime);
    }

    #[test]
    fn a_path_is_bound_as_its_device_s_source_says() {
        let mut island = device("Island", &["GVL.iFirst", "GVL.aWords", "GVL.iLast"]);
        island.bindings[1].count = 8;
        let devices = [
            island,
            with_task(device("Drive", &["GVL.rSpeed"])),
            on_serial_port(with_task(device("Meter", &["GVL.rPower"]))),
        ];
        let island = &devices[0];
        assert_eq!(
            bound(&devices, "gvl.ilast", false),
            Some(Bound::Polled(island, 1))
        );
        assert_eq!(
            bound(&devices, "GVL.aWords", true),
            Some(Bound::SeveralValues(island, 8))
        );
        assert_eq!(
            bound(&devices, "GVL.rSpeed", false),
            Some(Bound::Polled(&devices[1], 0))
        );
        assert_eq!(bound(&devices, "GVL.rSpeed", true), Some(Bound::Runtime));
        assert_eq!(
            bound(&devices, "GVL.rPower", false),
            Some(Bound::RuntimeWhenLoggedIn)
        );
        assert_eq!(bound(&devices, "GVL.rPower", true), Some(Bound::Runtime));
        assert_eq!(bound(&devices, "Main.iCount", false), None);
    }

    #[test]
    fn a_runtime_device_is_not_polled_while_logged_in_nor_an_rtu_device_ever() {
        let devices = [
            device("Island", &["GVL.iFirst", "GVL.aWords"]),
            with_task(device("Drive", &["GVL.rSpeed"])),
            on_serial_port(with_task(device("Meter", &["GVL.rPower"]))),
        ];
        let paths: Vec<String> = ["gvl.ifirst", "GVL.rSpeed", "GVL.rPower"]
            .map(String::from)
            .to_vec();
        let names = |logged_in| -> Vec<&str> {
            devices_to_poll(&devices, &paths, logged_in)
                .iter()
                .map(|device| device.name.as_str())
                .collect()
        };
        assert_eq!(names(false), ["Island", "Drive"]);
        assert_eq!(names(true), ["Island"]);
        let mut only_array = devices[0].clone();
        only_array.bindings[1].count = 8;
        let watched = vec!["GVL.aWords".to_owned()];
        assert!(devices_to_poll(&[only_array], &watched, false).is_empty());
    }

    #[test]
    fn a_connection_refusal_is_worded_in_the_user_s_language() {
        let error = ConnectError::OnSerialPort("Meter".into());
        assert_eq!(
            connect_problem(&error, Language::English),
            "device Meter is on a serial port, which only the runtime polls"
        );
        assert!(connect_problem(&error, Language::SimplifiedChinese).contains("串口"));
        let error = ConnectError::NotAnAddress {
            device: "Drive".into(),
            address: "nowhere:502".into(),
        };
        assert!(connect_problem(&error, Language::SimplifiedChinese).contains("nowhere:502"));
    }
}
