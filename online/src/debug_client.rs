//! The debugging services of `docs/protocol.md` §6 as methods of [`Client`]: one per service,
//! the listing ones asking again from where an answer ended until they have everything, and
//! every refusal an [`OnlineError::DebugRefused`] naming the service, the status and the
//! target's words.

use online_protocol::{
    ALL_BREAKPOINTS, BreakpointInfo, BreakpointSpec, DebugOptions, DebugRequest, DebugResponse,
    FRAME_RANGE_BYTES, FlowCycle, FlowEntry, FrameRange, HaltState, MAX_CONDITION_BYTES, MAX_COUNT,
    MAX_FLOW_ENTRIES, MAX_PAYLOAD_BYTES, Refusal, Request, Response, Service, StackFrame, Status,
    StepKind, TOKEN_BYTES,
};

use crate::client::{Client, unexpected};
use crate::error::OnlineError;

/// What `DEBUG_ATTACH` found.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Attached {
    /// Whether a lingering session was taken over (with its breakpoints and halts).
    pub took_over: bool,
    /// How many tasks are halted now.
    pub halted: u8,
    /// How many breakpoints are set now.
    pub breakpoints: u16,
}

/// A POU's flow bitmap as `FLOW_READ` gives it, gathered over as many requests as it needs.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FlowBitmap {
    /// The task's cycle count the bitmap belongs to; 0 when none was recorded yet.
    pub cycle: u64,
    /// How many statements (line-table entries) the POU has: the bitmap's bits.
    pub statements: u32,
    /// Bit `i mod 8` of byte `i / 8` is set when the statement of line-table entry `i` ran.
    pub bitmap: Vec<u8>,
}

impl FlowBitmap {
    /// Whether the statement of line-table entry `index` ran.
    pub fn ran(&self, index: usize) -> bool {
        self.bitmap
            .get(index / 8)
            .is_some_and(|byte| byte & (1 << (index % 8)) != 0)
    }
}

/// The bytes of a `FRAME_READ` request before its ranges: task, frame and count.
const FRAME_READ_FIXED_BYTES: usize = 1 + 2 + 1;
/// The bytes of a `FRAME_WRITE` request before its values: token, task, frame and count.
const FRAME_WRITE_FIXED_BYTES: usize = TOKEN_BYTES + FRAME_READ_FIXED_BYTES;
/// The most value bytes one `FRAME_WRITE` of a single range carries.
const FRAME_WRITE_PIECE_BYTES: usize =
    MAX_PAYLOAD_BYTES - FRAME_WRITE_FIXED_BYTES - FRAME_RANGE_BYTES;

impl Client {
    /// One debugging service: its answer, or the error naming its refusal.
    async fn debug(&mut self, request: DebugRequest) -> Result<DebugResponse, OnlineError> {
        match self.call(&Request::Debug(request)).await? {
            Response::Debug(answer) => Ok(answer),
            other => Err(unexpected(&other)),
        }
    }

    /// `DEBUG_ATTACH`: creates the debug session or takes a lingering one over; it lingers
    /// `linger_s` seconds (at most 300) after this connection closes. Sent again on an attached
    /// connection, it changes the linger and the options.
    pub async fn debug_attach(
        &mut self,
        linger_s: u16,
        options: DebugOptions,
    ) -> Result<Attached, OnlineError> {
        let request = DebugRequest::Attach {
            token: self.token,
            linger_s: linger_s.min(online_protocol::MAX_LINGER_S),
            options,
        };
        match self.debug(request).await? {
            DebugResponse::Attach {
                took_over,
                halted,
                breakpoints,
            } => Ok(Attached {
                took_over,
                halted,
                breakpoints,
            }),
            other => Err(unexpected_debug(&other)),
        }
    }

    /// `DEBUG_DETACH`: the session ends at once, every breakpoint goes and every halted task
    /// goes on.
    pub async fn debug_detach(&mut self) -> Result<(), OnlineError> {
        let request = DebugRequest::Detach { token: self.token };
        self.debug(request).await.map(drop)
    }

    /// `BREAK_SET`: returns the breakpoint's id and whether it replaced one at the same place,
    /// instance and task. A condition longer than the frame carries is refused before sending.
    pub async fn break_set(
        &mut self,
        breakpoint: &BreakpointSpec,
    ) -> Result<(u16, bool), OnlineError> {
        if breakpoint.condition.len() > MAX_CONDITION_BYTES {
            return Err(OnlineError::ConditionTooLong {
                bytes: breakpoint.condition.len(),
                limit: MAX_CONDITION_BYTES,
            });
        }
        let request = DebugRequest::BreakSet {
            token: self.token,
            breakpoint: breakpoint.clone(),
        };
        match self.debug(request).await? {
            DebugResponse::BreakSet { id, replaced } => Ok((id, replaced)),
            other => Err(unexpected_debug(&other)),
        }
    }

    /// `BREAK_CLEAR`: clears the breakpoint `id`, or every breakpoint when `id` is `None`.
    pub async fn break_clear(&mut self, id: Option<u16>) -> Result<(), OnlineError> {
        let request = DebugRequest::BreakClear {
            token: self.token,
            id: id.unwrap_or(ALL_BREAKPOINTS),
        };
        self.debug(request).await.map(drop)
    }

    /// `BREAK_LIST`: every breakpoint of the session (none without a session).
    pub async fn break_list(&mut self) -> Result<Vec<BreakpointInfo>, OnlineError> {
        let mut all = Vec::new();
        loop {
            let from = u16::try_from(all.len()).unwrap_or(u16::MAX);
            let (total, breakpoints) = match self.debug(DebugRequest::BreakList { from }).await? {
                DebugResponse::BreakList { total, breakpoints } => (total, breakpoints),
                other => return Err(unexpected_debug(&other)),
            };
            let before = all.len();
            all.extend(breakpoints);
            if all.len() >= usize::from(total) || all.len() == before {
                return Ok(all);
            }
        }
    }

    /// `HALT_STATE`: the session and every task. When the state changes between two pages
    /// (its `generation` grows), it is read again from the first task, so the tasks listed
    /// all belong to one state.
    pub async fn halt_state(&mut self) -> Result<HaltState, OnlineError> {
        // A state that changes on every page is read at most this often; the last is kept.
        const ATTEMPTS: usize = 4;
        let mut state = self.halt_state_from(0).await?;
        for _ in 0..ATTEMPTS {
            let mut changed = false;
            while state.tasks.len() < usize::from(state.total) {
                let from = u8::try_from(state.tasks.len()).unwrap_or(u8::MAX);
                let page = self.halt_state_from(from).await?;
                if page.generation != state.generation {
                    changed = true;
                    state = self.halt_state_from(0).await?;
                    break;
                }
                if page.tasks.is_empty() {
                    break;
                }
                state.tasks.extend(page.tasks);
            }
            if !changed {
                break;
            }
        }
        Ok(state)
    }

    /// One `HALT_STATE` page from task `from` on.
    async fn halt_state_from(&mut self, from: u8) -> Result<HaltState, OnlineError> {
        match self.debug(DebugRequest::HaltState { from }).await? {
            DebugResponse::HaltState(state) => Ok(state),
            other => Err(unexpected_debug(&other)),
        }
    }

    /// `STEP`: the halted `task` steps into, over or out; the step's end shows in
    /// [`Client::halt_state`].
    pub async fn step(&mut self, task: u8, kind: StepKind) -> Result<(), OnlineError> {
        let request = DebugRequest::Step {
            token: self.token,
            task,
            kind,
        };
        self.debug(request).await.map(drop)
    }

    /// `RUN_TO`: the halted `task` runs until it reaches the statement starting at
    /// `instruction` of `pou`, or a breakpoint before.
    pub async fn run_to(
        &mut self,
        task: u8,
        pou: u32,
        instruction: u32,
    ) -> Result<(), OnlineError> {
        let request = DebugRequest::RunTo {
            token: self.token,
            task,
            pou,
            instruction,
        };
        self.debug(request).await.map(drop)
    }

    /// `CONTINUE`: `task` runs on until a breakpoint; [`online_protocol::ALL_TASKS`] ends
    /// "halt all" and lets every task go on.
    pub async fn continue_task(&mut self, task: u8) -> Result<(), OnlineError> {
        let request = DebugRequest::Continue {
            token: self.token,
            task,
        };
        self.debug(request).await.map(drop)
    }

    /// `HALT`: `task` halts at the next statement it runs; [`online_protocol::ALL_TASKS`]
    /// starts "halt all".
    pub async fn halt(&mut self, task: u8) -> Result<(), OnlineError> {
        let request = DebugRequest::Halt {
            token: self.token,
            task,
        };
        self.debug(request).await.map(drop)
    }

    /// `STACK`: every frame of a halted (or waiting) task, innermost first.
    pub async fn stack(&mut self, task: u8) -> Result<Vec<StackFrame>, OnlineError> {
        let mut all = Vec::new();
        loop {
            let from = u16::try_from(all.len()).unwrap_or(u16::MAX);
            let (total, frames) = match self.debug(DebugRequest::Stack { task, from }).await? {
                DebugResponse::Stack { total, frames } => (total, frames),
                other => return Err(unexpected_debug(&other)),
            };
            let before = all.len();
            all.extend(frames);
            if all.len() >= usize::from(total) || all.len() == before {
                return Ok(all);
            }
        }
    }

    /// `FRAME_READ`: the bytes of each range of frame `frame` of a halted task, in the order
    /// of `ranges`, over as many requests as they need (each its own read of a task that does
    /// not move while halted).
    pub async fn frame_read(
        &mut self,
        task: u8,
        frame: u16,
        ranges: &[FrameRange],
    ) -> Result<Vec<Vec<u8>>, OnlineError> {
        let pieces = pieces_of(ranges, MAX_PAYLOAD_BYTES);
        let mut bytes = Vec::new();
        for batch in read_batches(&pieces) {
            let request = DebugRequest::FrameRead {
                task,
                frame,
                ranges: batch.iter().map(|(_, range)| *range).collect(),
            };
            let answer = match self.debug(request).await? {
                DebugResponse::FrameRead { bytes } => bytes,
                other => return Err(unexpected_debug(&other)),
            };
            let wanted: usize = batch.iter().map(|(_, range)| usize::from(range.size)).sum();
            if answer.len() != wanted {
                return Err(OnlineError::Protocol(format!(
                    "FRAME_READ answered {} bytes for {wanted} asked",
                    answer.len()
                )));
            }
            bytes.extend(answer);
        }
        let mut values = vec![Vec::new(); ranges.len()];
        let mut rest = bytes.as_slice();
        for (index, range) in &pieces {
            let (piece, after) = rest.split_at(usize::from(range.size));
            values[*index].extend_from_slice(piece);
            rest = after;
        }
        Ok(values)
    }

    /// `FRAME_WRITE`: writes each value at its offset of frame `frame` of a halted task; a
    /// value's length is its size.
    pub async fn frame_write(
        &mut self,
        task: u8,
        frame: u16,
        values: &[(u32, Vec<u8>)],
    ) -> Result<(), OnlineError> {
        let mut pieces = Vec::new();
        for (offset, bytes) in values {
            for (at, chunk) in (0u32..)
                .step_by(FRAME_WRITE_PIECE_BYTES)
                .zip(bytes.chunks(FRAME_WRITE_PIECE_BYTES))
            {
                let range = FrameRange {
                    offset: offset.saturating_add(at),
                    size: chunk.len() as u16,
                };
                pieces.push((range, chunk.to_vec()));
            }
        }
        let mut batch: Vec<(FrameRange, Vec<u8>)> = Vec::new();
        let mut used = FRAME_WRITE_FIXED_BYTES;
        for (range, bytes) in pieces {
            let cost = FRAME_RANGE_BYTES + bytes.len();
            if !batch.is_empty() && (used + cost > MAX_PAYLOAD_BYTES || batch.len() == MAX_COUNT) {
                self.frame_write_batch(task, frame, std::mem::take(&mut batch))
                    .await?;
                used = FRAME_WRITE_FIXED_BYTES;
            }
            used += cost;
            batch.push((range, bytes));
        }
        if !batch.is_empty() {
            self.frame_write_batch(task, frame, batch).await?;
        }
        Ok(())
    }

    /// One `FRAME_WRITE` that fits a frame.
    async fn frame_write_batch(
        &mut self,
        task: u8,
        frame: u16,
        values: Vec<(FrameRange, Vec<u8>)>,
    ) -> Result<(), OnlineError> {
        let request = DebugRequest::FrameWrite {
            token: self.token,
            task,
            frame,
            values,
        };
        self.debug(request).await.map(drop)
    }

    /// `FLOW_CONFIGURE`: records, in each cycle of `task`, which statements of each entry's
    /// POU ran (at most [`MAX_FLOW_ENTRIES`]); no entries end the recording.
    pub async fn flow_configure(
        &mut self,
        task: u8,
        entries: &[FlowEntry],
    ) -> Result<(), OnlineError> {
        if entries.len() > MAX_FLOW_ENTRIES {
            return Err(OnlineError::Protocol(format!(
                "flow control records at most {MAX_FLOW_ENTRIES} POUs at a time, not {}",
                entries.len()
            )));
        }
        let request = DebugRequest::FlowConfigure {
            token: self.token,
            task,
            entries: entries.to_vec(),
        };
        self.debug(request).await.map(drop)
    }

    /// `FLOW_READ`: the whole bitmap of the configured entry `entry`, of the last complete
    /// cycle or of the current one so far.
    pub async fn flow_read(
        &mut self,
        entry: u8,
        which: FlowCycle,
    ) -> Result<FlowBitmap, OnlineError> {
        let mut all = FlowBitmap {
            cycle: 0,
            statements: 0,
            bitmap: Vec::new(),
        };
        loop {
            let from = u32::try_from(all.bitmap.len() * 8).unwrap_or(u32::MAX);
            let request = DebugRequest::FlowRead { entry, which, from };
            let (cycle, statements, bitmap) = match self.debug(request).await? {
                DebugResponse::FlowRead {
                    cycle,
                    statements,
                    bitmap,
                } => (cycle, statements, bitmap),
                other => return Err(unexpected_debug(&other)),
            };
            if from == 0 {
                all.cycle = cycle;
                all.statements = statements;
            }
            let done = bitmap.is_empty();
            all.bitmap.extend(bitmap);
            if done || all.bitmap.len() * 8 >= all.statements as usize {
                all.bitmap.truncate((all.statements as usize).div_ceil(8));
                return Ok(all);
            }
        }
    }
}

/// A refusal of a debugging service as the error naming it; the password's refusals keep
/// the errors every service gives for them.
pub(crate) fn debug_refused(request: &DebugRequest, refusal: Refusal) -> OnlineError {
    let Refusal { status, message } = refusal;
    match status {
        Status::PasswordRequired => OnlineError::PasswordRequired,
        Status::WrongPassword => OnlineError::WrongPassword(message),
        status => OnlineError::DebugRefused {
            service: service_name(request.service()),
            status: status.number(),
            message,
        },
    }
}

/// A debugging service's name as `docs/protocol.md` §6.2 writes it.
fn service_name(service: Service) -> &'static str {
    match service {
        Service::DebugAttach => "DEBUG_ATTACH",
        Service::DebugDetach => "DEBUG_DETACH",
        Service::BreakSet => "BREAK_SET",
        Service::BreakClear => "BREAK_CLEAR",
        Service::BreakList => "BREAK_LIST",
        Service::HaltState => "HALT_STATE",
        Service::Step => "STEP",
        Service::RunTo => "RUN_TO",
        Service::Continue => "CONTINUE",
        Service::Halt => "HALT",
        Service::Stack => "STACK",
        Service::FrameRead => "FRAME_READ",
        Service::FrameWrite => "FRAME_WRITE",
        Service::FlowConfigure => "FLOW_CONFIGURE",
        Service::FlowRead => "FLOW_READ",
        _ => "a debugging service",
    }
}

/// An answer of another debugging service than asked.
fn unexpected_debug(answer: &DebugResponse) -> OnlineError {
    OnlineError::Protocol(format!(
        "an answer of service {:?} where another was expected",
        answer.service()
    ))
}

/// The ranges cut into pieces of at most `most` bytes, each with the index of its range.
fn pieces_of(ranges: &[FrameRange], most: usize) -> Vec<(usize, FrameRange)> {
    let most = most.clamp(1, usize::from(u16::MAX));
    let mut pieces = Vec::new();
    for (index, range) in ranges.iter().enumerate() {
        let mut offset = range.offset;
        let mut left = usize::from(range.size);
        while left > 0 {
            let size = left.min(most);
            pieces.push((
                index,
                FrameRange {
                    offset,
                    size: size as u16,
                },
            ));
            offset = offset.saturating_add(size as u32);
            left -= size;
        }
    }
    pieces
}

/// Runs of pieces whose request and answer each fit one frame.
fn read_batches(pieces: &[(usize, FrameRange)]) -> Vec<&[(usize, FrameRange)]> {
    let mut batches = Vec::new();
    let mut start = 0;
    let mut request = FRAME_READ_FIXED_BYTES;
    let mut answer = 0;
    for (index, (_, range)) in pieces.iter().enumerate() {
        let size = usize::from(range.size);
        let full = request + FRAME_RANGE_BYTES > MAX_PAYLOAD_BYTES
            || answer + size > MAX_PAYLOAD_BYTES
            || index - start == MAX_COUNT;
        if index > start && full {
            batches.push(&pieces[start..index]);
            start = index;
            request = FRAME_READ_FIXED_BYTES;
            answer = 0;
        }
        request += FRAME_RANGE_BYTES;
        answer += size;
    }
    if start < pieces.len() {
        batches.push(&pieces[start..]);
    }
    batches
}

#[cfg(test)]
#[path = "debug_client_tests.rs"]
mod tests;
