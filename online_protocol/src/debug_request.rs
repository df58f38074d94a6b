//! The requests of the debugging services (`docs/protocol.md` §6.2), one variant per service,
//! carried by [`crate::Request::Debug`].

use crate::debug_types::{
    BreakpointSpec, DebugOptions, FlowCycle, FlowEntry, FrameRange, HitMode, HitRule, StepKind,
};
use crate::error::DecodeError;
use crate::framing::{MAX_FLOW_ENTRIES, MAX_LINGER_S};
use crate::reader::Reader;
use crate::service::Service;
use crate::writer::first;

/// A debugging request. A changing service carries the token of `LOGIN` first, which
/// [`crate::Request::encode`] writes.
#[derive(Clone, Debug, PartialEq, Eq)]
#[allow(missing_docs)] // The fields are the protocol's, documented in docs/protocol.md §6.2.
pub enum DebugRequest {
    Attach {
        token: u128,
        linger_s: u16,
        options: DebugOptions,
    },
    Detach {
        token: u128,
    },
    BreakSet {
        token: u128,
        breakpoint: BreakpointSpec,
    },
    BreakClear {
        token: u128,
        id: u16,
    },
    BreakList {
        from: u16,
    },
    HaltState {
        from: u8,
    },
    Step {
        token: u128,
        task: u8,
        kind: StepKind,
    },
    RunTo {
        token: u128,
        task: u8,
        pou: u32,
        instruction: u32,
    },
    Continue {
        token: u128,
        task: u8,
    },
    Halt {
        token: u128,
        task: u8,
    },
    Stack {
        task: u8,
        from: u16,
    },
    FrameRead {
        task: u8,
        frame: u16,
        ranges: Vec<FrameRange>,
    },
    FrameWrite {
        token: u128,
        task: u8,
        frame: u16,
        values: Vec<(FrameRange, Vec<u8>)>,
    },
    FlowConfigure {
        token: u128,
        task: u8,
        entries: Vec<FlowEntry>,
    },
    FlowRead {
        entry: u8,
        which: FlowCycle,
        from: u32,
    },
}

impl DebugRequest {
    /// The request's service.
    pub fn service(&self) -> Service {
        use DebugRequest::*;
        match self {
            Attach { .. } => Service::DebugAttach,
            Detach { .. } => Service::DebugDetach,
            BreakSet { .. } => Service::BreakSet,
            BreakClear { .. } => Service::BreakClear,
            BreakList { .. } => Service::BreakList,
            HaltState { .. } => Service::HaltState,
            Step { .. } => Service::Step,
            RunTo { .. } => Service::RunTo,
            Continue { .. } => Service::Continue,
            Halt { .. } => Service::Halt,
            Stack { .. } => Service::Stack,
            FrameRead { .. } => Service::FrameRead,
            FrameWrite { .. } => Service::FrameWrite,
            FlowConfigure { .. } => Service::FlowConfigure,
            FlowRead { .. } => Service::FlowRead,
        }
    }

    /// The token of a service that sets, steps, halts, resumes or writes; `None` for a
    /// read-only one.
    pub fn token(&self) -> Option<u128> {
        use DebugRequest::*;
        match self {
            Attach { token, .. }
            | Detach { token }
            | BreakSet { token, .. }
            | BreakClear { token, .. }
            | Step { token, .. }
            | RunTo { token, .. }
            | Continue { token, .. }
            | Halt { token, .. }
            | FrameWrite { token, .. }
            | FlowConfigure { token, .. } => Some(*token),
            BreakList { .. }
            | HaltState { .. }
            | Stack { .. }
            | FrameRead { .. }
            | FlowRead { .. } => None,
        }
    }

    /// Appends the payload after the token. Lists longer than their one-byte count allows are
    /// cut; whether the frame fits a PDU is for the sender to check.
    pub(crate) fn encode_fields(&self, out: &mut Vec<u8>) {
        use DebugRequest::*;
        match self {
            Attach {
                linger_s, options, ..
            } => {
                out.extend_from_slice(&linger_s.to_le_bytes());
                out.push(options.bits());
            }
            Detach { .. } => {}
            BreakSet { breakpoint, .. } => {
                out.extend_from_slice(&breakpoint.pou.to_le_bytes());
                out.extend_from_slice(&breakpoint.instruction.to_le_bytes());
                out.extend_from_slice(&breakpoint.instance.to_le_bytes());
                out.push(breakpoint.task);
                out.push(breakpoint.hit.mode as u8);
                out.extend_from_slice(&breakpoint.hit.target.to_le_bytes());
                let condition = first(&breakpoint.condition);
                out.push(condition.len() as u8);
                out.extend_from_slice(condition);
            }
            BreakClear { id, .. } => out.extend_from_slice(&id.to_le_bytes()),
            BreakList { from } => out.extend_from_slice(&from.to_le_bytes()),
            HaltState { from } => out.push(*from),
            Step { task, kind, .. } => {
                out.push(*task);
                out.push(*kind as u8);
            }
            RunTo {
                task,
                pou,
                instruction,
                ..
            } => {
                out.push(*task);
                out.extend_from_slice(&pou.to_le_bytes());
                out.extend_from_slice(&instruction.to_le_bytes());
            }
            Continue { task, .. } | Halt { task, .. } => out.push(*task),
            Stack { task, from } => {
                out.push(*task);
                out.extend_from_slice(&from.to_le_bytes());
            }
            FrameRead {
                task,
                frame,
                ranges,
            } => {
                out.push(*task);
                out.extend_from_slice(&frame.to_le_bytes());
                let ranges = first(ranges);
                out.push(ranges.len() as u8);
                for range in ranges {
                    put_range(out, range);
                }
            }
            FrameWrite {
                task,
                frame,
                values,
                ..
            } => {
                out.push(*task);
                out.extend_from_slice(&frame.to_le_bytes());
                let values = first(values);
                out.push(values.len() as u8);
                for (range, bytes) in values {
                    put_range(out, range);
                    out.extend_from_slice(bytes);
                }
            }
            FlowConfigure { task, entries, .. } => {
                out.push(*task);
                let entries = first(entries);
                out.push(entries.len() as u8);
                for entry in entries {
                    out.extend_from_slice(&entry.pou.to_le_bytes());
                    out.extend_from_slice(&entry.instance.to_le_bytes());
                }
            }
            FlowRead { entry, which, from } => {
                out.push(*entry);
                out.push(*which as u8);
                out.extend_from_slice(&from.to_le_bytes());
            }
        }
    }

    /// The request of the debugging `service` whose payload `r` is at; `None` when `service`
    /// is not a debugging service.
    pub(crate) fn decode_fields(
        service: Service,
        r: &mut Reader<'_>,
    ) -> Result<Option<Self>, DecodeError> {
        Ok(Some(match service {
            Service::DebugAttach => {
                let token = r.u128("token")?;
                let linger_at = r.position();
                let linger_s = r.u16("linger")?;
                if linger_s > MAX_LINGER_S {
                    return Err(out_of_range(
                        "linger",
                        linger_at,
                        linger_s.into(),
                        "0 to 300",
                    ));
                }
                let options_at = r.position();
                let bits = r.u8("options")?;
                let options = DebugOptions::from_bits(bits)
                    .ok_or_else(|| out_of_range("options", options_at, bits.into(), "0 or 1"))?;
                DebugRequest::Attach {
                    token,
                    linger_s,
                    options,
                }
            }
            Service::DebugDetach => DebugRequest::Detach {
                token: r.u128("token")?,
            },
            Service::BreakSet => DebugRequest::BreakSet {
                token: r.u128("token")?,
                breakpoint: breakpoint_spec(r)?,
            },
            Service::BreakClear => DebugRequest::BreakClear {
                token: r.u128("token")?,
                id: r.u16("id")?,
            },
            Service::BreakList => DebugRequest::BreakList {
                from: r.u16("from")?,
            },
            Service::HaltState => DebugRequest::HaltState {
                from: r.u8("from")?,
            },
            Service::Step => DebugRequest::Step {
                token: r.u128("token")?,
                task: r.u8("task")?,
                kind: r.choice("step kind", &StepKind::ALL, "0 to 2")?,
            },
            Service::RunTo => DebugRequest::RunTo {
                token: r.u128("token")?,
                task: r.u8("task")?,
                pou: r.u32("pou")?,
                instruction: r.u32("instruction")?,
            },
            Service::Continue => DebugRequest::Continue {
                token: r.u128("token")?,
                task: r.u8("task")?,
            },
            Service::Halt => DebugRequest::Halt {
                token: r.u128("token")?,
                task: r.u8("task")?,
            },
            Service::Stack => DebugRequest::Stack {
                task: r.u8("task")?,
                from: r.u16("from")?,
            },
            Service::FrameRead => {
                let task = r.u8("task")?;
                let frame = r.u16("frame")?;
                let count = r.u8("count")?;
                let ranges = (0..count)
                    .map(|_| frame_range(r))
                    .collect::<Result<_, _>>()?;
                DebugRequest::FrameRead {
                    task,
                    frame,
                    ranges,
                }
            }
            Service::FrameWrite => {
                let token = r.u128("token")?;
                let task = r.u8("task")?;
                let frame = r.u16("frame")?;
                let count = r.u8("count")?;
                let mut values = Vec::with_capacity(usize::from(count));
                for _ in 0..count {
                    let range = frame_range(r)?;
                    let bytes = r.take("frame value", usize::from(range.size))?.to_vec();
                    values.push((range, bytes));
                }
                DebugRequest::FrameWrite {
                    token,
                    task,
                    frame,
                    values,
                }
            }
            Service::FlowConfigure => {
                let token = r.u128("token")?;
                let task = r.u8("task")?;
                let count_at = r.position();
                let count = r.u8("count")?;
                if usize::from(count) > MAX_FLOW_ENTRIES {
                    return Err(out_of_range("count", count_at, count.into(), "0 to 8"));
                }
                let mut entries = Vec::with_capacity(usize::from(count));
                for _ in 0..count {
                    entries.push(FlowEntry {
                        pou: r.u32("pou")?,
                        instance: r.u64("instance")?,
                    });
                }
                DebugRequest::FlowConfigure {
                    token,
                    task,
                    entries,
                }
            }
            Service::FlowRead => {
                let entry = r.u8("entry")?;
                let which = r.choice("which", &FlowCycle::ALL, "0 or 1")?;
                let from_at = r.position();
                let from = r.u32("from")?;
                if !from.is_multiple_of(8) {
                    return Err(out_of_range(
                        "from",
                        from_at,
                        from.into(),
                        "a multiple of 8",
                    ));
                }
                DebugRequest::FlowRead { entry, which, from }
            }
            _ => return Ok(None),
        }))
    }
}

/// The fields of `BREAK_SET` after the token. The hit target is checked after the condition
/// is read, so that a cut frame is "too short".
fn breakpoint_spec(r: &mut Reader<'_>) -> Result<BreakpointSpec, DecodeError> {
    let pou = r.u32("pou")?;
    let instruction = r.u32("instruction")?;
    let instance = r.u64("instance")?;
    let task = r.u8("task")?;
    let mode = r.choice("hit mode", &HitMode::ALL, "0 to 3")?;
    let target_at = r.position();
    let target = r.u32("hit target")?;
    let length = usize::from(r.u8("condition length")?);
    let condition = r.take("condition", length)?.to_vec();
    if mode != HitMode::Always && target == 0 {
        return Err(out_of_range(
            "hit target",
            target_at,
            0,
            "at least 1 for hit modes 1 to 3",
        ));
    }
    Ok(BreakpointSpec {
        pou,
        instruction,
        instance,
        task,
        hit: HitRule { mode, target },
        condition,
    })
}

fn frame_range(r: &mut Reader<'_>) -> Result<FrameRange, DecodeError> {
    Ok(FrameRange {
        offset: r.u32("frame offset")?,
        size: r.u16("frame size")?,
    })
}

fn put_range(out: &mut Vec<u8>, range: &FrameRange) {
    out.extend_from_slice(&range.offset.to_le_bytes());
    out.extend_from_slice(&range.size.to_le_bytes());
}

fn out_of_range(field: &'static str, at: usize, value: u64, expected: &'static str) -> DecodeError {
    DecodeError::OutOfRange {
        field,
        at,
        value,
        expected,
    }
}

#[cfg(test)]
#[path = "debug_request_tests.rs"]
pub(crate) mod tests;
