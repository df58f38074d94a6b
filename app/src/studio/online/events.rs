//! What arrives from the target: events of the session, taken in once per frame.

use std::time::Instant;

use online::Resolved;
use online::session::{Command, Event};

use super::{LiveValue, Online, OnlineMessage, Phase, STATUS_INTERVAL, devices};
use crate::studio::i18n::{DebugText, LoginText, Text, fill_template};
use crate::value_text::show;

impl Online {
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
                        // The trace was recorded by the studio's own poll, which serves the
                        // devices it polls as when not logged in (`devices::source_of`).
                        .filter_map(|(path, _)| {
                            match devices::bound(&self.project_devices, path, false) {
                                Some(devices::Bound::Polled(_, index)) => Some(index),
                                _ => None,
                            }
                        })
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
                    let text = self.text(Text::DeviceTrace);
                    self.error(format!("{text}: {reason}"));
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
        self.attach_when_online();
        self.poll_conditions();
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
        self.ask_modbus_devices_when_due(now);
    }

    fn handle(&mut self, event: Event) {
        match event {
            Event::Connected(identity) => {
                self.debug_connection_ended();
                self.modbus_question_ended();
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
                            None => self.text(Text::TargetNoProgram).to_owned(),
                            Some(_) => self
                                .text(Text::TargetOtherProgram)
                                .replace("{project}", &identity.project),
                        },
                    }
                };
                if !same && identity.image_hash.is_some() {
                    // Another program runs: whether the project's can take over online is
                    // the target's to say, so the program is sent and checked first.
                    self.check_online_change();
                }
                self.target_identity = Some(identity);
                self.last_status = None;
                self.watched.clear();
                self.refresh_watch();
            }
            Event::Disconnected(reason) => {
                if self.phase != Phase::Connecting || self.target_identity.is_some() {
                    let text = self.text(Text::TargetNotReachable);
                    self.error(text.replace("{reason}", &reason));
                }
                self.phase = Phase::Lost(reason);
                self.debug_connection_ended();
                self.modbus_question_ended();
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
            Event::DownloadProgress(sent, total) => match self.phase {
                Phase::Downloading { .. } => self.phase = Phase::Downloading { sent, total },
                Phase::CheckingChange { .. } => {
                    self.phase = Phase::CheckingChange { sent, total };
                }
                _ => {}
            },
            Event::ChangeChecked {
                transfer,
                check,
                details,
            } => self.change_checked(transfer, check, details),
            Event::ChangeApplied(applied, state) => self.change_applied(applied, state),
            Event::Done(state) => {
                self.target_state = Some(state);
                if matches!(self.phase, Phase::Downloading { .. }) {
                    self.forget_program();
                    if let (Some(identity), Some(image)) = (&mut self.target_identity, &self.image)
                    {
                        identity.image_hash = Some(image.hash);
                    }
                    self.phase = Phase::Online;
                    self.info(self.text(Text::DownloadComplete).to_owned());
                    self.refresh_watch();
                }
                self.trace.command_done();
            }
            Event::Failed(reason) => {
                let failed = match self.phase {
                    Phase::Downloading { .. } => Some(self.text(Text::DownloadFailed)),
                    Phase::CheckingChange { .. } => Some(self.login_text(LoginText::CheckFailed)),
                    Phase::ApplyingChange => Some(self.login_text(LoginText::ApplyFailed)),
                    _ => None,
                };
                if let Some(failed) = failed {
                    // A full download is still possible: the dialog offers it with the reason.
                    self.phase = Phase::ConfirmDownload {
                        reason: fill_template(failed, &[("reason", &reason)]),
                    };
                }
                self.trace.command_failed();
                self.error(reason);
            }
            Event::Resolved(answers) => {
                for (path, answer) in answers {
                    self.resolving.remove(&path);
                    // The studio shows a refusal in the target's words, as the session's
                    // error says them.
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
            Event::ModbusDevices(answer) => self.modbus_devices_answered(answer),
            Event::TraceStatus(status) => self.trace.status(status),
            Event::TraceProgress(received, total) => self.trace.progress(received, total),
            Event::DebugAttached(_) => self.debug_attached(),
            Event::Halted(tasks) => self.debug_halted(tasks),
            Event::Flow { bitmaps, .. } => self.debug_flow(&bitmaps),
            Event::BreakpointsSet(ids) => self.breakpoints_set(
                ids.into_iter()
                    .map(|id| id.map_err(|error| error.to_string()))
                    .collect(),
            ),
            Event::FrameRead {
                task,
                frame,
                values,
            } => self.frame_read(task, frame, &values),
            Event::DebugFailed(reason) => {
                let text = DebugText::DebugRefused.fill(self.language, &[("reason", &reason)]);
                self.error(text);
            }
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
            && self.runs_project()
            && let Ok(place) = runtime::value::resolve(&image.program, path)
            && place.bit.is_none()
        {
            return runtime::value::decode(&image.program, place.ty, bytes).to_string();
        }
        show(resolved, bytes)
    }

    /// Asks the target for the places of paths not known or asked for yet.
    pub(super) fn resolve(&mut self, paths: &[String]) {
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
    pub(super) fn refresh_watch(&mut self) {
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

    pub(super) fn command(&mut self, command: Command) -> bool {
        let sent = self.link.as_ref().is_some_and(|link| link.send(command));
        if !sent {
            let reason = if self.link.is_none() {
                Text::NotLoggedIn
            } else {
                Text::TargetBusy
            };
            self.error(self.text(reason).to_owned());
        }
        sent
    }

    pub(super) fn error(&mut self, text: String) {
        self.messages.push(OnlineMessage {
            text,
            is_error: true,
        });
    }

    pub(super) fn info(&mut self, text: String) {
        self.messages.push(OnlineMessage {
            text,
            is_error: false,
        });
    }
}
