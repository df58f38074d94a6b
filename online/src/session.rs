//! A session with one target on a background task: commands in over a bounded channel,
//! events and value snapshots out, so a UI never waits on the network.
//!
//! The session connects, identifies and logs in; while a watch list is set it reads it every
//! `poll_interval` and sends a [`Event::Snapshot`]. When the connection fails it says so
//! ([`Event::Disconnected`]) and tries again every `reconnect_interval`; on reconnecting it
//! identifies again (the program may have changed) before anything else. When it ends
//! ([`Command::Close`], or the command sender dropped) it logs out before closing the
//! connection, so that its token ends at once.
//!
//! Debugging ([`Command::Debug`], `session/debug.rs`): once attached it polls `HALT_STATE`
//! a few times a second and reports each change with the call stacks ([`Event::Halted`]), and
//! the flow bitmaps while flow recording is configured ([`Event::Flow`]); it detaches before
//! logging out.

mod debug;
mod online_change;

pub use debug::{DebugCommand, FLOW_POLL_INTERVAL, HALT_POLL_INTERVAL, HaltedTask};
pub use online_change::ChangeCommand;

use std::net::SocketAddr;
use std::time::Duration;

use tokio::sync::mpsc;

use crate::client::{Client, Sample, TraceConfig};
use crate::debug_client::{Attached, FlowBitmap};
use crate::error::OnlineError;
use crate::{
    ChangeApplied, ChangeCheck, ChangeDetailEntry, Fault, FlowEntry, Identity, ModbusDeviceReport,
    Place, Reset, Resolved, Snapshot, TargetState, TaskInfo, TraceStatus,
};

/// What a session is asked to do.
#[derive(Debug)]
pub enum Command {
    /// Read these places every poll (an empty list stops polling).
    Watch(Vec<Place>),
    /// Download an image; `start` starts it once loaded, otherwise the target's program is
    /// stopped before the load and the new one stays stopped (as CODESYS's download does).
    Download {
        /// The encoded image.
        image: Vec<u8>,
        /// Start it once loaded; without it the target is stopped before the load.
        start: bool,
    },
    /// Start the program.
    Start,
    /// Stop the program.
    Stop,
    /// Reset the program's memory.
    Reset(Reset),
    /// Write values once.
    Write(Vec<(Place, Vec<u8>)>),
    /// Force values.
    Force(Vec<(Place, Vec<u8>)>),
    /// Release forces (all when empty).
    Unforce(Vec<Place>),
    /// Resolve variable paths on the target; answered by [`Event::Resolved`].
    Resolve(Vec<String>),
    /// Ask for the forced places; answered by [`Event::Forces`].
    Forces,
    /// Ask for task statistics; answered by [`Event::Tasks`].
    Tasks,
    /// Ask for the fault log; answered by [`Event::Faults`].
    Faults,
    /// Ask for the Modbus devices the target's master polls (`MODBUS_DEVICES`); answered by
    /// [`Event::ModbusDevices`].
    ModbusDevices,
    /// Configure a trace and arm it; answered by [`Event::Done`].
    TraceStart(TraceConfig),
    /// Ask where the trace is; answered by [`Event::TraceStatus`].
    TraceStatus,
    /// Upload the recorded samples; answered by [`Event::TraceSamples`] after
    /// [`Event::TraceProgress`] events.
    TraceUpload,
    /// A step of an online change (`docs/protocol.md` §7).
    OnlineChange(ChangeCommand),
    /// A debugging step (`docs/protocol.md` §6).
    Debug(DebugCommand),
    /// End the session: `LOGOUT` (waiting at most [`LOGOUT_TIMEOUT`]) and close.
    Close,
}

/// What a session reports.
#[derive(Debug)]
pub enum Event {
    /// Connected (again), with what the target says about itself.
    Connected(Identity),
    /// The connection failed; the session tries again.
    Disconnected(String),
    /// The watched places, read in one go.
    Snapshot(Snapshot),
    /// Download progress: bytes sent of the total.
    DownloadProgress(usize, usize),
    /// A command finished; the target's state after it.
    Done(TargetState),
    /// A command failed; nothing changed on the target.
    Failed(String),
    /// The answer to [`ChangeCommand::Check`]: the open transfer, the verdict and
    /// everything the change would do.
    ChangeChecked {
        /// The transfer to apply, commit or abort.
        transfer: u16,
        /// The verdict and its counts.
        check: ChangeCheck,
        /// What will change, in the protocol's order.
        details: Vec<ChangeDetailEntry>,
    },
    /// The answer to [`ChangeCommand::Apply`]: what the switch did, and the target's
    /// state after it.
    ChangeApplied(ChangeApplied, TargetState),
    /// The answer to [`Command::Resolve`]: each path with what the target said about it.
    Resolved(Vec<(String, Result<Resolved, OnlineError>)>),
    /// The answer to [`Command::Forces`]: every forced place with its value.
    Forces(Vec<(Place, Vec<u8>)>),
    /// The answer to [`Command::Tasks`].
    Tasks(Vec<TaskInfo>),
    /// The answer to [`Command::Faults`].
    Faults(Vec<Fault>),
    /// The answer to [`Command::ModbusDevices`]; a refusal is reported here rather than as
    /// [`Event::Failed`], since the question is asked every second and its failure changes
    /// nothing on the target.
    ModbusDevices(ModbusDevicesAnswer),
    /// The answer to [`Command::TraceStatus`].
    TraceStatus(TraceStatus),
    /// Trace upload progress: samples received of the total.
    TraceProgress(usize, usize),
    /// The answer to [`Command::TraceUpload`]: the samples, with the trigger's index if it came.
    TraceSamples {
        /// The samples in recording order.
        samples: Vec<Sample>,
        /// The sample at the trigger.
        trigger_sample: Option<u32>,
    },
    /// The answer to [`DebugCommand::Attach`]: the session is attached and its halts watched.
    DebugAttached(Attached),
    /// The halted tasks (and those waiting beneath them) with their call stacks, sent when the
    /// target's halt state changed; empty when no task is halted any more.
    Halted(Vec<HaltedTask>),
    /// The flow bitmaps of every recording task, one per configured entry: of the task's
    /// last complete cycle, or of its cycle so far while it is halted or waits beneath a
    /// halted task.
    Flow {
        /// Each entry with its task and bitmap, in task order, then in the order configured.
        bitmaps: Vec<(u8, FlowEntry, FlowBitmap)>,
    },
    /// The answer to [`DebugCommand::SetBreakpoints`]: each breakpoint's id or why the target
    /// refused it, in the order given.
    BreakpointsSet(Vec<Result<u16, OnlineError>>),
    /// The answer to [`DebugCommand::FrameRead`]: the bytes of each range asked for.
    FrameRead {
        /// The task.
        task: u8,
        /// The frame.
        frame: u16,
        /// The bytes of each range, in the order asked.
        values: Vec<Vec<u8>>,
    },
    /// A debugging command failed; the words name the service and the target's reason.
    DebugFailed(String),
}

/// What a target said to [`Command::ModbusDevices`].
#[derive(Clone, Debug, PartialEq)]
pub enum ModbusDevicesAnswer {
    /// Every device its master polls, in the image's order, with the target's state asked right
    /// after them (`IDENTIFY`): whether the program runs decides whether the devices' values
    /// reach it, and a start or stop from elsewhere is seen no later than the next question.
    Reports {
        /// The devices' reports, in the image's order.
        reports: Vec<ModbusDeviceReport>,
        /// The target's state when they were read.
        state: TargetState,
    },
    /// The target does not know the service (an older runtime).
    NotReported,
    /// The target refused the question: its reason in its own words, or the failure's.
    Refused(String),
}

/// How a session behaves.
#[derive(Clone, Debug)]
pub struct SessionOptions {
    /// The target.
    pub address: SocketAddr,
    /// Its password, if it has one.
    pub password: Option<String>,
    /// How often watched places are read.
    pub poll_interval: Duration,
    /// How long to wait before connecting again after a failure.
    pub reconnect_interval: Duration,
}

/// Starts a session on the current tokio runtime: commands go in through the returned sender,
/// events come out of the returned receiver (both bounded).
pub fn spawn(options: SessionOptions) -> (mpsc::Sender<Command>, mpsc::Receiver<Event>) {
    let (commands, command_rx) = mpsc::channel(64);
    let (event_tx, events) = mpsc::channel(256);
    tokio::spawn(run(options, command_rx, event_tx));
    (commands, events)
}

async fn run(
    options: SessionOptions,
    mut commands: mpsc::Receiver<Command>,
    events: mpsc::Sender<Event>,
) {
    let mut watch: Vec<Place> = Vec::new();
    // The places of the last trace configured, which an upload needs to split samples.
    let mut trace_places: Vec<Place> = Vec::new();
    'connect: loop {
        let mut client = match Client::connect(options.address, options.password.as_deref()).await {
            Ok((client, identity)) => {
                if events.send(Event::Connected(identity)).await.is_err() {
                    return;
                }
                client
            }
            Err(error) => {
                if events
                    .send(Event::Disconnected(error.to_string()))
                    .await
                    .is_err()
                {
                    return;
                }
                // Commands wait while the target is away; Close ends the session at once.
                let deadline = tokio::time::sleep(options.reconnect_interval);
                tokio::pin!(deadline);
                loop {
                    tokio::select! {
                        () = &mut deadline => continue 'connect,
                        command = commands.recv() => match command {
                            None | Some(Command::Close) => return,
                            Some(Command::Watch(places)) => watch = places,
                            // Asked every second while logged in, and again once connected:
                            // its failure is no news for the user.
                            Some(Command::ModbusDevices) => {}
                            Some(_) => {
                                let _ = events.send(Event::Failed(format!("{error}; not connected"))).await;
                            }
                        },
                    }
                }
            }
        };
        let mut poll = tokio::time::interval(options.poll_interval);
        // A new connection has no debug session: the user's side attaches again.
        let mut debugging = debug::DebugWatch::default();
        let mut halt_poll = tokio::time::interval(HALT_POLL_INTERVAL);
        let mut flow_poll = tokio::time::interval(FLOW_POLL_INTERVAL);
        loop {
            tokio::select! {
                _ = halt_poll.tick(), if debugging.attached => {
                    match debug::poll_halts(&mut client, &mut debugging).await {
                        Ok(Some(event)) => {
                            if events.send(event).await.is_err() {
                                return;
                            }
                        }
                        Ok(None) => {}
                        Err(error @ (OnlineError::Io(..) | OnlineError::Timeout(..))) => {
                            let _ = events.send(Event::Disconnected(error.to_string())).await;
                            continue 'connect;
                        }
                        Err(error) => {
                            // The session is gone (taken over, or the program replaced): the
                            // halts are no longer this session's to watch.
                            debugging.attached = false;
                            let _ = events.send(Event::DebugFailed(error.to_string())).await;
                        }
                    }
                }
                _ = flow_poll.tick(), if debugging.records_flow() => {
                    match debug::read_flow(&mut client, &debugging).await {
                        Ok(Some(event)) => {
                            if events.send(event).await.is_err() {
                                return;
                            }
                        }
                        Ok(None) => {}
                        Err(error @ (OnlineError::Io(..) | OnlineError::Timeout(..))) => {
                            let _ = events.send(Event::Disconnected(error.to_string())).await;
                            continue 'connect;
                        }
                        Err(error) => {
                            debugging.flow.clear();
                            let _ = events.send(Event::DebugFailed(error.to_string())).await;
                        }
                    }
                }
                _ = poll.tick(), if !watch.is_empty() => {
                    match client.read(&watch).await {
                        Ok(snapshot) => {
                            if events.send(Event::Snapshot(snapshot)).await.is_err() {
                                return;
                            }
                        }
                        Err(error) => {
                            let _ = events.send(Event::Disconnected(error.to_string())).await;
                            continue 'connect;
                        }
                    }
                }
                command = commands.recv() => {
                    let Some(command) = command else {
                        detach(&mut client, &debugging).await;
                        log_out(&mut client).await;
                        return;
                    };
                    let outcome = match command {
                        Command::Close => {
                            detach(&mut client, &debugging).await;
                            log_out(&mut client).await;
                            return;
                        }
                        Command::Debug(step) => {
                            match debug::run(&mut client, step, &mut debugging).await {
                                Ok(Some(event)) => {
                                    if events.send(event).await.is_err() {
                                        return;
                                    }
                                }
                                Ok(None) => {}
                                Err(error @ (OnlineError::Io(..) | OnlineError::Timeout(..))) => {
                                    let _ = events.send(Event::Disconnected(error.to_string())).await;
                                    continue 'connect;
                                }
                                Err(error) => {
                                    if events.send(Event::DebugFailed(error.to_string())).await.is_err() {
                                        return;
                                    }
                                }
                            }
                            continue;
                        }
                        Command::Watch(places) => {
                            watch = places;
                            continue;
                        }
                        Command::Download { image, start } => {
                            let progress = events.clone();
                            let sent = client
                                .transfer(&image, |sent, total| {
                                    let _ = progress.try_send(Event::DownloadProgress(sent, total));
                                })
                                .await;
                            let result = match sent {
                                Ok(transfer) => {
                                    online_change::commit(&mut client, transfer, start).await
                                }
                                Err(error) => Err(error),
                            };
                            match result {
                                Ok(()) => client.identify().await.map(|identity| identity.state),
                                Err(error) => Err(error),
                            }
                        }
                        Command::OnlineChange(step) => {
                            match online_change::run(&mut client, step, &events).await {
                                Ok(Some(event)) => {
                                    if events.send(event).await.is_err() {
                                        return;
                                    }
                                    continue;
                                }
                                Ok(None) => client.identify().await.map(|identity| identity.state),
                                Err(error) => Err(error),
                            }
                        }
                        Command::Resolve(paths) => {
                            let mut answers = Vec::with_capacity(paths.len());
                            let mut lost = None;
                            for path in paths {
                                match client.resolve(&path).await {
                                    Ok(resolved) => answers.push((path, Ok(resolved))),
                                    Err(error @ (OnlineError::Io(..) | OnlineError::Timeout(..))) => {
                                        lost = Some(error);
                                        break;
                                    }
                                    Err(error) => answers.push((path, Err(error))),
                                }
                            }
                            match lost {
                                Some(error) => Err(error),
                                None => {
                                    if events.send(Event::Resolved(answers)).await.is_err() {
                                        return;
                                    }
                                    continue;
                                }
                            }
                        }
                        Command::Forces => match client.forces().await {
                            Ok(forces) => {
                                if events.send(Event::Forces(forces)).await.is_err() {
                                    return;
                                }
                                continue;
                            }
                            Err(error) => Err(error),
                        },
                        Command::Tasks => match client.tasks().await {
                            Ok(tasks) => {
                                if events.send(Event::Tasks(tasks)).await.is_err() {
                                    return;
                                }
                                continue;
                            }
                            Err(error) => Err(error),
                        },
                        Command::Faults => match client.faults().await {
                            Ok(faults) => {
                                if events.send(Event::Faults(faults)).await.is_err() {
                                    return;
                                }
                                continue;
                            }
                            Err(error) => Err(error),
                        },
                        Command::ModbusDevices => {
                            let asked = match client.modbus_devices().await {
                                Ok(reports) => client
                                    .identify()
                                    .await
                                    .map(|identity| (reports, identity.state)),
                                Err(error) => Err(error),
                            };
                            let answer = match asked {
                                Ok((reports, state)) => ModbusDevicesAnswer::Reports { reports, state },
                                Err(OnlineError::ModbusDevicesNotReported) => {
                                    ModbusDevicesAnswer::NotReported
                                }
                                // A lost connection is the session's to handle, as for any
                                // command.
                                Err(error @ (OnlineError::Io(..) | OnlineError::Timeout(..))) => {
                                    let _ = events.send(Event::Disconnected(error.to_string())).await;
                                    continue 'connect;
                                }
                                // The target's own words: the studio says whose they are.
                                Err(OnlineError::Rejected(reason)) => {
                                    ModbusDevicesAnswer::Refused(reason)
                                }
                                Err(error) => ModbusDevicesAnswer::Refused(error.to_string()),
                            };
                            if events.send(Event::ModbusDevices(answer)).await.is_err() {
                                return;
                            }
                            continue;
                        }
                        Command::TraceStart(config) => {
                            trace_places.clone_from(&config.places);
                            let result = match client.trace_configure(&config).await {
                                Ok(_) => client.trace_arm().await,
                                Err(error) => Err(error),
                            };
                            finish(&mut client, result).await
                        }
                        Command::TraceStatus => match client.trace_status().await {
                            Ok(status) => {
                                if events.send(Event::TraceStatus(status)).await.is_err() {
                                    return;
                                }
                                continue;
                            }
                            Err(error) => Err(error),
                        },
                        Command::TraceUpload => {
                            let result = trace_upload(&mut client, &trace_places, &events).await;
                            match result {
                                Ok(event) => {
                                    if events.send(event).await.is_err() {
                                        return;
                                    }
                                    continue;
                                }
                                Err(error) => Err(error),
                            }
                        }
                        Command::Start => client.start().await,
                        Command::Stop => client.stop().await,
                        Command::Reset(kind) => client.reset(kind).await,
                        Command::Write(values) => {
                            let result = client_write(&mut client, values, false).await;
                            finish(&mut client, result).await
                        }
                        Command::Force(values) => {
                            let result = client_write(&mut client, values, true).await;
                            finish(&mut client, result).await
                        }
                        Command::Unforce(places) => {
                            let result = client.unforce(&places).await;
                            finish(&mut client, result).await
                        }
                    };
                    let lost = matches!(outcome, Err(OnlineError::Io(..) | OnlineError::Timeout(..)));
                    let event = match outcome {
                        Ok(state) => Event::Done(state),
                        Err(error) => Event::Failed(error.to_string()),
                    };
                    if events.send(event).await.is_err() {
                        return;
                    }
                    if lost {
                        continue 'connect;
                    }
                }
            }
        }
    }
}

/// How long a session that ends waits for the answer to its `LOGOUT` before it closes the
/// connection all the same (which ends the token too, only less explicitly).
pub const LOGOUT_TIMEOUT: Duration = Duration::from_secs(1);

/// Ends an attached debug session with `DEBUG_DETACH` (waiting at most [`LOGOUT_TIMEOUT`]),
/// so every breakpoint goes and every halted task runs on before the session ends; best
/// effort, as a linger of 0 ends it with the connection too.
async fn detach(client: &mut Client, watch: &debug::DebugWatch) {
    if watch.attached {
        let _ = tokio::time::timeout(LOGOUT_TIMEOUT, client.debug_detach()).await;
    }
}

/// Ends the client's token with `LOGOUT` when it logged in with a password, so that the token
/// is of no use from now on even if the connection lingers; best effort, as closing the
/// connection ends it too.
async fn log_out(client: &mut Client) {
    if client.is_logged_in() {
        let _ = tokio::time::timeout(LOGOUT_TIMEOUT, client.logout()).await;
    }
}

async fn client_write(
    client: &mut Client,
    values: Vec<(Place, Vec<u8>)>,
    force: bool,
) -> Result<(), OnlineError> {
    if force {
        client.force(&values).await
    } else {
        client.write(&values).await
    }
}

/// Uploads a trace with progress events; the samples come back as one event.
async fn trace_upload(
    client: &mut Client,
    places: &[Place],
    events: &mpsc::Sender<Event>,
) -> Result<Event, OnlineError> {
    let status = client.trace_status().await?;
    let total = status.recorded as usize;
    let samples = client
        .trace_upload(places, |received| {
            let _ = events.try_send(Event::TraceProgress(received, total));
        })
        .await?;
    Ok(Event::TraceSamples {
        samples,
        trigger_sample: status.trigger_sample,
    })
}

/// The target's state after a command that answers nothing of its own.
async fn finish(
    client: &mut Client,
    result: Result<(), OnlineError>,
) -> Result<TargetState, OnlineError> {
    result?;
    client.identify().await.map(|identity| identity.state)
}

#[cfg(test)]
#[path = "session/modbus_devices_tests.rs"]
mod modbus_devices_tests;
