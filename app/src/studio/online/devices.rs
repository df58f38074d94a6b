//! Third-party Modbus TCP devices of the project, polled while any of their bound variables is
//! watched: their values, writes and forces go through the same panes as the controller's,
//! without a login or a download.

use std::collections::HashMap;
use std::sync::{Arc, mpsc};
use std::time::Duration;

use online::device::Device;
use project_model::ModbusDevice;
use tokio::sync::mpsc as async_mpsc;

use super::{LiveValue, Waker};
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
    Trace(Result<Vec<online::device::DeviceSnapshot>, String>),
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
    trace: Option<Result<Vec<online::device::DeviceSnapshot>, String>>,
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

/// Where a variable path is bound on a device: the device and the channel index.
pub fn binding_of<'d>(
    devices: &'d [ModbusDevice],
    path: &str,
) -> Option<(&'d ModbusDevice, usize)> {
    devices.iter().find_map(|device| {
        device
            .bindings
            .iter()
            .position(|binding| binding.variable.eq_ignore_ascii_case(path))
            .map(|index| (device, index))
    })
}

impl DeviceLinks {
    /// Polls exactly the devices that hold one of `paths`, starting and stopping tasks on
    /// `handle` as needed.
    pub fn keep(
        &mut self,
        handle: &tokio::runtime::Handle,
        devices: &[ModbusDevice],
        paths: &[String],
        wake: &Waker,
    ) {
        // The studio polls TCP devices only: the runtime polls serial lines.
        let wanted: Vec<&ModbusDevice> = devices
            .iter()
            .filter(|device| matches!(device.link, project_model::ModbusLink::Tcp { .. }))
            .filter(|device| {
                paths.iter().any(|path| {
                    device
                        .bindings
                        .iter()
                        .any(|b| b.variable.eq_ignore_ascii_case(path))
                })
            })
            .collect();
        self.links.retain(|name, link| {
            wanted
                .iter()
                .any(|device| device.name == *name && **device == link.config)
        });
        for device in wanted {
            if !self.links.contains_key(&device.name) {
                let link = start(handle, device.clone(), Arc::clone(wake));
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

    /// The last value of a device-bound path, or why there is none.
    pub fn value(
        &self,
        devices: &[ModbusDevice],
        path: &str,
    ) -> Option<Result<&LiveValue, String>> {
        let (device, index) = binding_of(devices, path)?;
        let link = self.links.get(&device.name)?;
        if let Some(problem) = &link.problem {
            return Some(Err(format!("{}: {problem}", device.name)));
        }
        link.values.get(index).and_then(Option::as_ref).map(Ok)
    }

    /// Sends a write or force of a device-bound path's channel.
    pub fn send(
        &mut self,
        devices: &[ModbusDevice],
        path: &str,
        bytes: Vec<u8>,
        force: bool,
        language: Language,
    ) -> Result<(), String> {
        let (device, index) = binding_of(devices, path)
            .ok_or_else(|| Text::BoundToNoDevice.get(language).replace("{path}", path))?;
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
    ) -> Result<(), String> {
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
    ) -> Option<Result<Vec<online::device::DeviceSnapshot>, String>> {
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
                let path = link
                    .config
                    .bindings
                    .get(channel)
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
/// away.
fn start(handle: &tokio::runtime::Handle, config: ModbusDevice, wake: Waker) -> DeviceLink {
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
                    if !report(DeviceEvent::Problem(error.to_string())) {
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
                                if !report(DeviceEvent::Trace(traced.map_err(|e| e.to_string()))) {
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

/// Why a device cannot be written or traced: nothing polls it.
fn not_polled(device: &str, language: Language) -> String {
    Text::DeviceNotPolled
        .get(language)
        .replace("{device}", device)
}

/// Why a device command was refused: the device's queue is full.
fn busy(device: &str, language: Language) -> String {
    Text::DeviceBusy.get(language).replace("{device}", device)
}
