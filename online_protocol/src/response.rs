//! The responses of the protocol, one variant per service, with their encoding
//! (`docs/protocol.md` §3): `service:u8`, `status:u8`, then the answer when the status is 0 or
//! a message for people when it is not.

use crate::answers::{
    Fault, Identity, Resolved, Snapshot, TargetState, TaskInfo, TraceSample, TraceState,
    TraceStatus,
};
use crate::debug_response::DebugResponse;
use crate::debug_types::DebugStatus;
use crate::error::DecodeError;
use crate::framing::{NO_TRIGGER_SAMPLE, SAMPLE_HEADER_BYTES};
use crate::modbus_devices::ModbusDeviceReport;
use crate::online_change::{self, ChangeApplied, ChangeCheck, ChangeDetailEntry};
use crate::place::Place;
use crate::reader::Reader;
use crate::request::Request;
use crate::service::Service;
use crate::status::{Refusal, Status};
use crate::writer::{first, put_place, put_str8};

/// What a request gets: the service's answer, or a refusal.
pub type Answer = Result<Response, Refusal>;

/// The answer of a service done (status 0).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Response {
    /// `IDENTIFY`: the target and its program.
    Identify(Identity),
    /// `LOGIN`: the token for changing services.
    Login {
        /// Random and not 0; valid on the connection that logged in, until it logs in again,
        /// logs out or closes.
        token: u128,
    },
    /// `LOGOUT`: the connection's token has ended.
    Logout,
    /// `DOWNLOAD_BEGIN`: the transfer begun.
    DownloadBegin {
        /// The transfer's number, which its chunks name.
        transfer: u16,
        /// The most bytes a chunk may carry.
        chunk_size: u16,
    },
    /// `DOWNLOAD_CHUNK`: the chunk written.
    DownloadChunk {
        /// The distinct bytes received so far.
        received: u32,
    },
    /// `DOWNLOAD_COMMIT`: the image loaded.
    DownloadCommit {
        /// Whether RETAIN and PERSISTENT values were carried over.
        retained: bool,
    },
    /// `DOWNLOAD_ABORT`: the transfer dropped.
    DownloadAbort,
    /// `ONLINE_CHANGE_CHECK`: the verdict and the counts (§7).
    OnlineChangeCheck(ChangeCheck),
    /// `ONLINE_CHANGE_DETAILS`: the details from the request's index on (§7).
    OnlineChangeDetails {
        /// How many details the check found.
        total: u16,
        /// As many details as fit one response.
        details: Vec<ChangeDetailEntry>,
    },
    /// `ONLINE_CHANGE_APPLY`: what the switch did (§7).
    OnlineChangeApply(ChangeApplied),
    /// `START`: the state after starting.
    Start {
        /// The target's state.
        state: TargetState,
    },
    /// `STOP`: the state after stopping.
    Stop {
        /// The target's state.
        state: TargetState,
    },
    /// `RESET`: the state after the reset.
    Reset {
        /// The target's state.
        state: TargetState,
    },
    /// `RESOLVE`: where the variable is and what type it has.
    Resolve(Resolved),
    /// `READ`: the values of the request's places, in its order.
    Read(Snapshot),
    /// `WRITE`: the values written.
    Write,
    /// `FORCE`: the values forced.
    Force,
    /// `UNFORCE`: the forces released.
    Unforce,
    /// `FORCES`: the forces from the request's index on.
    Forces {
        /// How many forces there are in all.
        total: u16,
        /// The forced places with their values, as many as fit one response.
        forces: Vec<(Place, Vec<u8>)>,
    },
    /// `ENUMERATION`: the values of the variable's enumeration type from the request's index on.
    Enumeration {
        /// The elementary tag of the integer type the enumeration is stored as.
        base: u8,
        /// How many values the type has.
        total: u16,
        /// The values' names and numbers in declaration order, as many as fit one response.
        values: Vec<(String, i64)>,
    },
    /// `TRACE_CONFIGURE`: the trace configured.
    TraceConfigure {
        /// The bytes of one sample's values.
        sample_bytes: u16,
    },
    /// `TRACE_ARM`: recording started.
    TraceArm,
    /// `TRACE_STATUS`: where the trace is.
    TraceStatus(TraceStatus),
    /// `TRACE_UPLOAD`: samples from the request's index on, oldest first; none at the end.
    TraceUpload {
        /// As many samples as fit one response, all of one size.
        samples: Vec<TraceSample>,
    },
    /// `TRACE_ADD`: the places added.
    TraceAdd {
        /// The bytes of one sample's values, with the added places.
        sample_bytes: u16,
    },
    /// `TASKS`: the tasks that fit one response.
    Tasks {
        /// Their statistics, in the image's order.
        tasks: Vec<TaskInfo>,
    },
    /// `FAULTS`: the faults from the request's index on.
    Faults {
        /// How many faults the target keeps.
        total: u16,
        /// The faults, as many as fit one response.
        faults: Vec<Fault>,
    },
    /// `MODBUS_DEVICES`: the devices the runtime masters from the request's index on
    /// (`docs/modbus-master.md` §9.1); the runtime builds it with
    /// [`crate::modbus_devices_page`].
    ModbusDevices {
        /// How many devices the runtime masters (0 without a program or runtime devices).
        total: u8,
        /// Their reports in the image's order, as many as fit one response.
        devices: Vec<ModbusDeviceReport>,
    },
    /// A debugging service's answer (version 3, §6).
    Debug(DebugResponse),
}

impl Response {
    /// The service this answers.
    pub fn service(&self) -> Service {
        use Response::*;
        match self {
            Identify(_) => Service::Identify,
            Login { .. } => Service::Login,
            Logout => Service::Logout,
            DownloadBegin { .. } => Service::DownloadBegin,
            DownloadChunk { .. } => Service::DownloadChunk,
            DownloadCommit { .. } => Service::DownloadCommit,
            DownloadAbort => Service::DownloadAbort,
            OnlineChangeCheck(_) => Service::OnlineChangeCheck,
            OnlineChangeDetails { .. } => Service::OnlineChangeDetails,
            OnlineChangeApply(_) => Service::OnlineChangeApply,
            Start { .. } => Service::Start,
            Stop { .. } => Service::Stop,
            Reset { .. } => Service::Reset,
            Resolve(_) => Service::Resolve,
            Read(_) => Service::Read,
            Write => Service::Write,
            Force => Service::Force,
            Unforce => Service::Unforce,
            Forces { .. } => Service::Forces,
            Enumeration { .. } => Service::Enumeration,
            TraceConfigure { .. } => Service::TraceConfigure,
            TraceArm => Service::TraceArm,
            TraceStatus(_) => Service::TraceStatus,
            TraceUpload { .. } => Service::TraceUpload,
            TraceAdd { .. } => Service::TraceAdd,
            Tasks { .. } => Service::Tasks,
            Faults { .. } => Service::Faults,
            ModbusDevices { .. } => Service::ModbusDevices,
            Debug(response) => response.service(),
        }
    }

    /// The response body after the function code: the service, status 0 and the answer.
    /// Texts and lists longer than their one-byte length allows are cut; whether the body
    /// fits a PDU is for the sender to check.
    pub fn encode(&self) -> Vec<u8> {
        use Response::*;
        let mut out = vec![self.service().number(), Status::Done.number()];
        match self {
            Identify(identity) => {
                out.extend_from_slice(&identity.protocol.to_le_bytes());
                put_str8(&mut out, &identity.runtime_version);
                out.push(identity.state as u8);
                out.extend_from_slice(&identity.image_hash.unwrap_or([0; 32]));
                put_str8(&mut out, &identity.project);
                out.push(u8::from(identity.password_required));
                out.push(identity.debug.bits());
            }
            Login { token } => out.extend_from_slice(&token.to_le_bytes()),
            DownloadBegin {
                transfer,
                chunk_size,
            } => {
                out.extend_from_slice(&transfer.to_le_bytes());
                out.extend_from_slice(&chunk_size.to_le_bytes());
            }
            DownloadChunk { received } => out.extend_from_slice(&received.to_le_bytes()),
            DownloadCommit { retained } => out.push(u8::from(*retained)),
            OnlineChangeCheck(check) => check.encode(&mut out),
            OnlineChangeDetails { total, details } => {
                online_change::put_details(&mut out, *total, details);
            }
            OnlineChangeApply(applied) => applied.encode(&mut out),
            Logout | DownloadAbort | Write | Force | Unforce | TraceArm => {}
            Start { state } | Stop { state } | Reset { state } => out.push(*state as u8),
            Resolve(resolved) => {
                put_place(&mut out, &resolved.place);
                out.push(resolved.type_tag);
                out.extend_from_slice(&resolved.length.to_le_bytes());
            }
            Read(snapshot) => {
                out.extend_from_slice(&snapshot.cycle.to_le_bytes());
                let mut forced = vec![0u8; snapshot.values.len().div_ceil(8)];
                for (index, (_, is_forced)) in snapshot.values.iter().enumerate() {
                    if *is_forced {
                        forced[index / 8] |= 1 << (index % 8);
                    }
                }
                out.extend_from_slice(&forced);
                for (bytes, _) in &snapshot.values {
                    out.extend_from_slice(bytes);
                }
            }
            Forces { total, forces } => {
                out.extend_from_slice(&total.to_le_bytes());
                let forces = first(forces);
                out.push(forces.len() as u8);
                for (place, value) in forces {
                    put_place(&mut out, place);
                    out.extend_from_slice(value);
                }
            }
            Enumeration {
                base,
                total,
                values,
            } => {
                out.push(*base);
                out.extend_from_slice(&total.to_le_bytes());
                let values = first(values);
                out.push(values.len() as u8);
                for (name, number) in values {
                    put_str8(&mut out, name);
                    out.extend_from_slice(&number.to_le_bytes());
                }
            }
            TraceConfigure { sample_bytes } | TraceAdd { sample_bytes } => {
                out.extend_from_slice(&sample_bytes.to_le_bytes());
            }
            TraceStatus(status) => {
                out.push(status.state as u8);
                out.extend_from_slice(&status.recorded.to_le_bytes());
                let trigger = status.trigger_sample.unwrap_or(NO_TRIGGER_SAMPLE);
                out.extend_from_slice(&trigger.to_le_bytes());
            }
            TraceUpload { samples } => {
                let samples = first(samples);
                out.push(samples.len() as u8);
                for sample in samples {
                    out.extend_from_slice(&sample.cycle.to_le_bytes());
                    out.extend_from_slice(&sample.time_ns.to_le_bytes());
                    out.extend_from_slice(&sample.values);
                }
            }
            Tasks { tasks } => {
                let tasks = first(tasks);
                out.push(tasks.len() as u8);
                for task in tasks {
                    put_str8(&mut out, &task.name);
                    for number in [
                        task.cycles,
                        task.last_ns,
                        task.min_ns,
                        task.max_ns,
                        task.average_ns,
                        task.jitter_max_ns,
                    ] {
                        out.extend_from_slice(&number.to_le_bytes());
                    }
                    out.push(u8::from(task.faulted));
                }
            }
            Faults { total, faults } => {
                out.extend_from_slice(&total.to_le_bytes());
                let faults = first(faults);
                out.push(faults.len() as u8);
                for fault in faults {
                    for text in [&fault.task, &fault.kind, &fault.pou, &fault.file] {
                        put_str8(&mut out, text);
                    }
                    out.extend_from_slice(&fault.line.to_le_bytes());
                    out.extend_from_slice(&fault.cycle.to_le_bytes());
                }
            }
            ModbusDevices { total, devices } => {
                out.push(*total);
                let devices = first(devices);
                out.push(devices.len() as u8);
                for device in devices {
                    device.encode(&mut out);
                }
            }
            Debug(response) => response.encode_fields(&mut out),
        }
        out
    }

    /// The answer in `frame` (the response body after the function code) to `request`, which
    /// gives the service it must name and, for `READ`, the places whose values it carries.
    pub fn decode(request: &Request, frame: &[u8]) -> Result<Answer, DecodeError> {
        let mut r = Reader::new(frame);
        let expected = request.service();
        let found = r.u8("service")?;
        if found != expected.number() {
            return Err(DecodeError::OtherService {
                expected: expected.number(),
                found,
            });
        }
        let number = r.u8("status")?;
        let status = Status::from_number(number).ok_or(DecodeError::UnknownStatus(number))?;
        if status != Status::Done {
            let message = r.str8("message")?;
            r.finish()?;
            return Ok(Err(Refusal { status, message }));
        }
        let response = decode_answer(request, expected, &mut r)?;
        r.finish()?;
        Ok(Ok(response))
    }
}

/// The answer of `service` done, after the status.
fn decode_answer(
    request: &Request,
    service: Service,
    r: &mut Reader<'_>,
) -> Result<Response, DecodeError> {
    Ok(match service {
        Service::Identify => Response::Identify(Identity {
            protocol: r.u16("protocol")?,
            runtime_version: r.str8("runtime version")?,
            state: target_state(r)?,
            image_hash: Some(r.hash("image hash")?).filter(|hash| *hash != [0; 32]),
            project: r.str8("project")?,
            password_required: r.u8("password required")? != 0,
            debug: DebugStatus::from_bits(r.u8("debug")?),
        }),
        Service::Login => Response::Login {
            token: r.u128("token")?,
        },
        Service::Logout => Response::Logout,
        Service::DownloadBegin => Response::DownloadBegin {
            transfer: r.u16("transfer")?,
            chunk_size: r.u16("chunk size")?,
        },
        Service::DownloadChunk => Response::DownloadChunk {
            received: r.u32("received")?,
        },
        Service::DownloadCommit => Response::DownloadCommit {
            retained: r.u8("retained")? != 0,
        },
        Service::DownloadAbort => Response::DownloadAbort,
        Service::OnlineChangeCheck => Response::OnlineChangeCheck(ChangeCheck::decode(r)?),
        Service::OnlineChangeDetails => {
            let (total, details) = online_change::details(r)?;
            Response::OnlineChangeDetails { total, details }
        }
        Service::OnlineChangeApply => Response::OnlineChangeApply(ChangeApplied::decode(r)?),
        Service::Start => Response::Start {
            state: target_state(r)?,
        },
        Service::Stop => Response::Stop {
            state: target_state(r)?,
        },
        Service::Reset => Response::Reset {
            state: target_state(r)?,
        },
        Service::Resolve => Response::Resolve(Resolved {
            place: r.place("place")?,
            type_tag: r.u8("type")?,
            length: r.u16("length")?,
        }),
        Service::Read => {
            let places: &[Place] = match request {
                Request::Read { places } => first(places),
                _ => &[],
            };
            let cycle = r.u64("cycle")?;
            let forced = r.take("forced bitmap", places.len().div_ceil(8))?;
            let mut values = Vec::with_capacity(places.len());
            for (index, place) in places.iter().enumerate() {
                let bytes = r.take("value", place.value_bytes())?.to_vec();
                values.push((bytes, forced[index / 8] >> (index % 8) & 1 != 0));
            }
            Response::Read(Snapshot { cycle, values })
        }
        Service::Write => Response::Write,
        Service::Force => Response::Force,
        Service::Unforce => Response::Unforce,
        Service::Forces => {
            let total = r.u16("total")?;
            let count = r.u8("count")?;
            let mut forces = Vec::with_capacity(usize::from(count));
            for _ in 0..count {
                let place = r.place("place")?;
                forces.push((place, r.take("value", place.value_bytes())?.to_vec()));
            }
            Response::Forces { total, forces }
        }
        Service::Enumeration => {
            let base = r.u8("base type")?;
            let total = r.u16("total")?;
            let count = r.u8("count")?;
            let mut values = Vec::with_capacity(usize::from(count));
            for _ in 0..count {
                let name = r.str8("value name")?;
                values.push((name, r.u64("value")? as i64));
            }
            Response::Enumeration {
                base,
                total,
                values,
            }
        }
        Service::TraceConfigure => Response::TraceConfigure {
            sample_bytes: r.u16("sample bytes")?,
        },
        Service::TraceArm => Response::TraceArm,
        Service::TraceStatus => Response::TraceStatus(TraceStatus {
            state: r.choice("trace state", &TraceState::ALL, "0 to 4")?,
            recorded: r.u32("recorded")?,
            trigger_sample: Some(r.u32("trigger sample")?)
                .filter(|&sample| sample != NO_TRIGGER_SAMPLE),
        }),
        Service::TraceUpload => Response::TraceUpload {
            samples: samples(r)?,
        },
        Service::TraceAdd => Response::TraceAdd {
            sample_bytes: r.u16("sample bytes")?,
        },
        Service::Tasks => {
            let count = r.u8("count")?;
            let mut tasks = Vec::with_capacity(usize::from(count));
            for _ in 0..count {
                tasks.push(TaskInfo {
                    name: r.str8("task name")?,
                    cycles: r.u64("cycles")?,
                    last_ns: r.u64("last cycle time")?,
                    min_ns: r.u64("shortest cycle time")?,
                    max_ns: r.u64("longest cycle time")?,
                    average_ns: r.u64("average cycle time")?,
                    jitter_max_ns: r.u64("largest jitter")?,
                    faulted: r.u8("faulted")? != 0,
                });
            }
            Response::Tasks { tasks }
        }
        Service::Faults => {
            let total = r.u16("total")?;
            let count = r.u8("count")?;
            let mut faults = Vec::with_capacity(usize::from(count));
            for _ in 0..count {
                faults.push(Fault {
                    task: r.str8("fault task")?,
                    kind: r.str8("fault kind")?,
                    pou: r.str8("fault POU")?,
                    file: r.str8("fault file")?,
                    line: r.u32("fault line")?,
                    cycle: r.u64("fault cycle")?,
                });
            }
            Response::Faults { total, faults }
        }
        Service::ModbusDevices => {
            let total = r.u8("total")?;
            let count = r.u8("count")?;
            let mut devices = Vec::with_capacity(usize::from(count));
            for _ in 0..count {
                devices.push(ModbusDeviceReport::decode(r)?);
            }
            Response::ModbusDevices { total, devices }
        }
        debug => match DebugResponse::decode_fields(request, debug, r)? {
            Some(response) => Response::Debug(response),
            None => return Err(DecodeError::UnknownService(debug.number())),
        },
    })
}

/// The samples of a `TRACE_UPLOAD` answer. Every sample has the same size, so the size is
/// what is left divided by the count; the client splits the values by its places.
fn samples(r: &mut Reader<'_>) -> Result<Vec<TraceSample>, DecodeError> {
    let count = usize::from(r.u8("count")?);
    if count == 0 {
        return Ok(Vec::new());
    }
    let bytes = r.remaining();
    if !bytes.is_multiple_of(count) || bytes / count < SAMPLE_HEADER_BYTES {
        return Err(DecodeError::UnevenSamples {
            at: r.position(),
            count,
            bytes,
        });
    }
    let value_bytes = bytes / count - SAMPLE_HEADER_BYTES;
    (0..count)
        .map(|_| {
            Ok(TraceSample {
                cycle: r.u64("sample cycle")?,
                time_ns: r.u64("sample time")?,
                values: r.take("sample values", value_bytes)?.to_vec(),
            })
        })
        .collect()
}

fn target_state(r: &mut Reader<'_>) -> Result<TargetState, DecodeError> {
    r.choice("state", &TargetState::ALL, "0 to 3")
}

#[cfg(test)]
#[path = "response_tests.rs"]
mod tests;
