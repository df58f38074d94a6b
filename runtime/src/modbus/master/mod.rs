//! The runtime as a Modbus master (`docs/modbus-master.md` §4, §6): the devices of an image's
//! section 14 read and written in rounds on a thread of their own, `rivet-modbus-master` (a
//! current-thread tokio runtime, one task per TCP device and one per serial line), and exchanged with the scheduler
//! through per-device buffers the scheduler only ever tries to lock.
//!
//! - [`exchange`]: the input image, output image and cycle-end counter of one device.
//! - [`copier`]: the scheduler's side: what a cycle of the I/O task copies in and out.
//! - [`resolve`]: the section's paths as places in the program's memory, checked at load.
//! - [`status`]: counters, state, `MB_ErrorCodes` and the status variable's bytes.
//! - `round.rs`, `device_round.rs`, `due.rs`, `backoff.rs`: the rounds on the master's thread;
//!   `link_tcp.rs` a TCP device's task, `line_rtu.rs` a serial line's (every device of a port
//!   in turn) over `line_port.rs`, the transport that keeps the silence and drops unasked input.
//! - `wake.rs`: the `rivet-modbus-wake` thread between the scheduler and the tokio tasks.

mod backoff;
mod connect_error;
pub mod copier;
mod device_round;
mod due;
pub mod exchange;
mod line_port;
mod line_rtu;
mod link_tcp;
pub mod resolve;
mod resolve_problem;
mod round;
pub mod status;
mod wake;

use std::sync::{Arc, Mutex, PoisonError};
use std::thread::{JoinHandle, Thread};
use std::time::Duration;

use program_image::modbus_master::{Link, MasterSection, Schedule};
use program_image::{ProgramImage, TaskKind};

pub use copier::{DeviceCopier, ProgramMemory};
pub use exchange::DeviceExchange;
pub use resolve::{DevicePlaces, ResolveError, resolve_section};
pub use resolve_problem::ResolveProblem;
pub use status::{DeviceState, DeviceStatus, error_codes};

use device_round::DeviceRound;
use due::Due;
use line_rtu::{LineDevice, RtuLine};
use link_tcp::TcpDevice;
use wake::{Wake, WakeTarget};

/// How an every-cycle device is polled while its task has no cycles and is not cyclic.
const IDLE_POLL: Duration = Duration::from_millis(100);

/// Where the line of a device's change of state goes (`docs/modbus-master.md` §4.2):
/// `rivet-runtime` writes it on its standard error.
pub type StateLines = Arc<dyn Fn(&str) + Send + Sync>;

/// How the master runs; fixed for the runtime's life (`docs/modbus-master.md` §6.11).
#[derive(Clone)]
pub struct MasterOptions {
    /// Whether the master runs; off, every device reports state 5 and nothing is copied.
    pub enabled: bool,
    /// Device files replacing those of the image's serial ports, by port name
    /// (`--serial-port NAME=PATH`).
    pub serial_ports: Vec<(String, String)>,
    /// Receives one line per change of a device's state; `None` drops them (the studio's
    /// simulator shows states through the online service instead).
    pub state_lines: Option<StateLines>,
}

impl std::fmt::Debug for MasterOptions {
    fn fmt(&self, formatter: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        formatter
            .debug_struct("MasterOptions")
            .field("enabled", &self.enabled)
            .field("serial_ports", &self.serial_ports)
            .field("state_lines", &self.state_lines.is_some())
            .finish()
    }
}

impl Default for MasterOptions {
    /// The master on, the serial ports as the image names them.
    fn default() -> Self {
        Self {
            enabled: true,
            serial_ports: Vec::new(),
            state_lines: None,
        }
    }
}

/// Why the master could not start.
#[derive(Debug, thiserror::Error)]
pub enum MasterError {
    /// The section's paths do not fit the program.
    #[error(transparent)]
    Resolve(#[from] ResolveError),
    /// A thread could not be started.
    #[error("the Modbus master's threads cannot be started: {0}")]
    Thread(#[from] std::io::Error),
}

/// The Modbus master: [`Master::start`] gives a [`MasterHandle`].
pub struct Master;

/// What the master's thread is told before its devices' tasks begin.
enum Signal {
    /// Begin polling.
    Go,
    /// End without polling (the handle went away first).
    Stop,
}

impl Master {
    /// Resolves `image`'s section and, unless `options` turn it off, starts the master's
    /// threads, which poll nothing until [`MasterStarter::go`] (so a new master can be prepared
    /// on the caller's thread while the old one still has the serial ports). An image without
    /// a section gives a handle without devices and without threads.
    ///
    /// The threads run with normal scheduling even when the caller runs at real-time
    /// priority (`docs/scheduler.md` §6): a slow name lookup or a busy line never competes
    /// with the tasks.
    pub fn start(
        image: &ProgramImage,
        options: &MasterOptions,
    ) -> Result<MasterHandle, MasterError> {
        let section = image.modbus_master.clone().unwrap_or_default();
        let places = resolve_section(image, &section)?;
        // `--serial-port NAME=PATH`: this machine's device file of a port, by its name. The
        // section itself stays as the image has it, for an online change to compare.
        let mut serial_ports = section.serial_ports.clone();
        for (name, path) in &options.serial_ports {
            for port in &mut serial_ports {
                if port.name.eq_ignore_ascii_case(name) {
                    port.device.clone_from(path);
                }
            }
        }
        let exchanges: Vec<Arc<DeviceExchange>> = section
            .devices
            .iter()
            .map(|device| Arc::new(DeviceExchange::new(device)))
            .collect();
        let off = !options.enabled;
        let statuses: Vec<Arc<Mutex<DeviceStatus>>> = section
            .devices
            .iter()
            .map(|device| Arc::new(Mutex::new(DeviceStatus::new(&device.name, off))))
            .collect();
        let mut handle = MasterHandle {
            section,
            places,
            exchanges,
            statuses,
            wake: None,
            thread: None,
            shutdown: Arc::new(tokio::sync::Notify::new()),
            signals: None,
        };
        if off || handle.section.devices.is_empty() {
            return Ok(handle);
        }
        let mut tcp = Vec::new();
        let mut lines: Vec<Vec<LineDevice>> = serial_ports.iter().map(|_| Vec::new()).collect();
        let mut targets = Vec::new();
        for (index, device) in handle.section.devices.iter().enumerate() {
            let exchange = Arc::clone(&handle.exchanges[index]);
            targets.push(WakeTarget {
                exchange: Arc::clone(&exchange),
                every_cycle: device.schedule == Schedule::EveryCycle,
            });
            let idle = image
                .tasks
                .get(device.task as usize)
                .filter(|task| task.kind == TaskKind::Cyclic && task.interval_ns > 0)
                .map_or(IDLE_POLL, |task| Duration::from_nanos(task.interval_ns));
            let due = Due::new(device.schedule, Arc::clone(&exchange), idle);
            let round = DeviceRound::new(
                device.clone(),
                exchange,
                Arc::clone(&handle.statuses[index]),
                options.state_lines.clone(),
            );
            match &device.link {
                Link::Tcp { .. } => tcp.push(TcpDevice::new(round, due)),
                Link::Rtu { serial_port } => {
                    // Verification has checked the index.
                    if let Some(line) = lines.get_mut(*serial_port as usize) {
                        line.push(LineDevice { round, due });
                    }
                }
            }
        }
        let lines: Vec<RtuLine> = serial_ports
            .into_iter()
            .zip(lines)
            .filter(|(_, devices)| !devices.is_empty())
            .map(|(port, devices)| RtuLine::new(port, devices))
            .collect();
        handle.wake = Some(Wake::spawn(targets)?);
        let shutdown = Arc::clone(&handle.shutdown);
        // tokio's blocking threads (name lookups) are started by the master's thread, but
        // each gives up a real-time policy itself too, whoever starts it.
        let runtime = tokio::runtime::Builder::new_current_thread()
            .enable_all()
            .thread_name("rivet-modbus-blocking")
            .on_thread_start(become_normal)
            .build()?;
        let (signals, received) = std::sync::mpsc::channel();
        handle.signals = Some(signals);
        handle.thread = Some(
            std::thread::Builder::new()
                .name("rivet-modbus-master".to_owned())
                .spawn(move || {
                    become_normal();
                    if !matches!(received.recv(), Ok(Signal::Go)) {
                        runtime.shutdown_background();
                        return;
                    }
                    for device in tcp {
                        runtime.spawn(device.run());
                    }
                    for line in lines {
                        runtime.spawn(line.run());
                    }
                    runtime.block_on(shutdown.notified());
                    // Ending the runtime ends the devices' tasks and closes their connections
                    // and ports; a name lookup still running on a blocking thread is left to
                    // finish on its own rather than waited for.
                    runtime.shutdown_background();
                })?,
        );
        Ok(handle)
    }
}

/// Gives up a real-time policy the calling thread inherited (`docs/modbus-master.md` §6.1).
fn become_normal() {
    // Giving up a real-time policy needs no privilege; should the system refuse anyway, the
    // thread runs as it is, which is what it did before this call.
    let _ = crate::scheduler::make_current_thread_normal();
}

/// Lets a prepared master's devices begin polling; kept by whoever drops the master it
/// replaces, so that the old one's serial ports are closed first.
pub struct MasterStarter {
    /// The master thread's signals; `None` for a master without threads.
    signals: Option<std::sync::mpsc::Sender<Signal>>,
}

impl MasterStarter {
    /// Lets the devices begin polling (nothing when the master has no threads, or its handle
    /// has already gone away).
    pub fn go(self) {
        if let Some(signals) = &self.signals {
            // A thread already told to stop has ended and drops nothing here.
            let _ = signals.send(Signal::Go);
        }
    }
}

/// The running master of one image. Dropping it stops it: its connections are closed and its
/// threads end.
pub struct MasterHandle {
    /// The section the master runs, as the image has it.
    section: MasterSection,
    /// Per device, its places in the program's memory.
    places: Vec<DevicePlaces>,
    /// Per device, its exchange with the scheduler.
    exchanges: Vec<Arc<DeviceExchange>>,
    /// Per device, its counters and state, shared with the online service.
    statuses: Vec<Arc<Mutex<DeviceStatus>>>,
    /// The `rivet-modbus-wake` thread, for a master with devices.
    wake: Option<Wake>,
    /// The `rivet-modbus-master` thread, for a master with devices.
    thread: Option<JoinHandle<()>>,
    /// Ends the devices' tasks (the master's thread waits for it).
    shutdown: Arc<tokio::sync::Notify>,
    /// Tells the master's thread to begin polling, or to end before it began.
    signals: Option<std::sync::mpsc::Sender<Signal>>,
}

impl MasterHandle {
    /// The section the master runs.
    pub fn section(&self) -> &MasterSection {
        &self.section
    }

    /// Whether the master runs devices (it is on and the image has some).
    pub fn active(&self) -> bool {
        self.thread.is_some()
    }

    /// What lets the devices begin polling (see [`Master::start`]).
    pub fn starter(&self) -> MasterStarter {
        MasterStarter {
            signals: self.signals.clone(),
        }
    }

    /// Per device, its places in the program's memory (resolved when the master started).
    pub fn places(&self) -> &[DevicePlaces] {
        &self.places
    }

    /// The scheduler's side of every device, for a running master; none when it is off.
    pub fn copiers(&self) -> Vec<DeviceCopier> {
        if !self.active() {
            return Vec::new();
        }
        self.exchanges
            .iter()
            .zip(&self.places)
            .map(|(exchange, places)| DeviceCopier::new(Arc::clone(exchange), places.clone()))
            .collect()
    }

    /// The thread the scheduler unparks after a cycle end of an I/O task.
    pub fn waker(&self) -> Option<Thread> {
        self.wake.as_ref().and_then(Wake::thread)
    }

    /// Tells the devices whether the program runs (called between cycles).
    pub fn set_running(&self, running: bool) {
        for exchange in &self.exchanges {
            exchange.set_running(running);
        }
    }

    /// Every device's state and counters, in the image's order (for `MODBUS_DEVICES`).
    pub fn snapshot(&self) -> Vec<online_protocol::ModbusDeviceReport> {
        self.statuses
            .iter()
            .map(|status| lock(status).snapshot())
            .collect()
    }

    /// A handle on the devices' counters that outlives the master's threads (for the online
    /// service, which asks the scheduler's status rather than the scheduler).
    pub fn statuses(&self) -> Vec<Arc<Mutex<DeviceStatus>>> {
        self.statuses.clone()
    }

    /// Stops the master: its tasks end and its connections close before this returns.
    pub fn stop(self) {
        drop(self);
    }
}

impl Drop for MasterHandle {
    fn drop(&mut self) {
        if let Some(signals) = self.signals.take() {
            // A thread that has not begun polling ends; one that has waits for `shutdown`.
            let _ = signals.send(Signal::Stop);
        }
        self.shutdown.notify_one();
        if let Some(thread) = self.thread.take() {
            // A panic there has been reported by the panic hook; nothing is left to do.
            let _ = thread.join();
        }
        self.wake = None;
    }
}

fn lock<T>(mutex: &Mutex<T>) -> std::sync::MutexGuard<'_, T> {
    mutex.lock().unwrap_or_else(PoisonError::into_inner)
}

#[cfg(test)]
mod tests {
    use program_image::modbus_master::{ChannelDef, DeviceDef, WordOrder};

    use super::*;
    use crate::test_images::{TestTask, image};

    /// The scheduling policy of each of this process's threads whose name starts with
    /// `prefix` (`/proc/self/task/*/stat`, field 41: 0 is `SCHED_OTHER`).
    fn policies(prefix: &str) -> Vec<(String, u32)> {
        let mut found = Vec::new();
        for task in std::fs::read_dir("/proc/self/task").unwrap().flatten() {
            let Ok(stat) = std::fs::read_to_string(task.path().join("stat")) else {
                continue;
            };
            let (Some(open), Some(close)) = (stat.find('('), stat.rfind(')')) else {
                continue;
            };
            let name = stat[open + 1..close].to_owned();
            // The fields after the name start with field 3.
            let policy = stat[close + 1..]
                .split_whitespace()
                .nth(41 - 3)
                .and_then(|field| field.parse().ok());
            if let (true, Some(policy)) = (name.starts_with(prefix), policy) {
                found.push((name, policy));
            }
        }
        found
    }

    #[cfg(target_os = "linux")]
    #[test]
    fn a_master_started_by_a_realtime_thread_runs_its_threads_with_normal_scheduling() {
        let mut image = image(&[TestTask::cyclic(1_000_000, 1)], &[]);
        image.modbus_master = Some(MasterSection {
            serial_ports: Vec::new(),
            devices: vec![DeviceDef {
                name: "Named".to_owned(),
                // A host name, so that tokio resolves it on a blocking thread.
                link: Link::Tcp {
                    host: "localhost".to_owned(),
                    port: 1,
                },
                unit_id: 1,
                timeout_ms: 100,
                task: 0,
                schedule: Schedule::Interval { interval_ms: 10 },
                word_order: WordOrder::HighFirst,
                max_read_gap: 0,
                status: None,
                // A request, so that the device connects: a read of one coil into the
                // image's located BOOL.
                channels: vec![ChannelDef {
                    variable: "Trigger".to_owned(),
                    table: program_image::ModbusTable::Coils,
                    address: 0,
                    value_type: program_image::Elementary::Bool,
                    count: 1,
                    direction: program_image::modbus_master::Direction::Read,
                    function_code: 1,
                    trigger: program_image::modbus_master::Trigger::Cyclic,
                    on_error: program_image::modbus_master::OnError::KeepLastValue,
                    error_flag: None,
                }],
            }],
        });
        // Started by a SCHED_FIFO thread (when the system grants it), as the scheduler's
        // thread with `--realtime-priority` would.
        let handle = std::thread::spawn(move || {
            let _ = crate::scheduler::realtime::make_current_thread_realtime(10);
            let handle = Master::start(&image, &MasterOptions::default()).unwrap();
            handle.starter().go();
            handle
        })
        .join()
        .unwrap();
        // The device tries to connect, which resolves its host on a blocking thread.
        let deadline = std::time::Instant::now() + Duration::from_secs(10);
        while handle.snapshot()[0].errors == 0 && std::time::Instant::now() < deadline {
            std::thread::sleep(Duration::from_millis(10));
        }
        let threads = policies("rivet-modbus-");
        let names: Vec<&str> = threads.iter().map(|(name, _)| name.as_str()).collect();
        assert!(names.contains(&"rivet-modbus-ma"), "{names:?}");
        assert!(names.contains(&"rivet-modbus-wa"), "{names:?}");
        assert!(names.contains(&"rivet-modbus-bl"), "{names:?}");
        // Whether or not the system granted SCHED_FIFO to the starting thread, every thread of
        // the master runs with SCHED_OTHER.
        assert!(
            threads.iter().all(|(_, policy)| *policy == 0),
            "{threads:?}"
        );
        drop(handle);
    }
}
