//! The session's debugging commands (`docs/protocol.md` §6) and what it watches while attached:
//! `HALT_STATE` a few times a second (comparing its `generation`, and reading the call stacks
//! only when it changed), and the flow bitmaps while flow recording is configured.

use std::time::Duration;

use online_protocol::{
    BreakpointSpec, DebugOptions, FlowCycle, FlowEntry, FrameRange, StackFrame, StepKind,
    TaskDebugState, TaskHalt,
};

use super::Event;
use crate::client::Client;
use crate::debug_client::{Attached, FlowBitmap};
use crate::error::OnlineError;

/// How often an attached session asks whether a task halted or went on.
pub const HALT_POLL_INTERVAL: Duration = Duration::from_millis(200);
/// How often the flow bitmaps are read while flow recording is configured.
pub const FLOW_POLL_INTERVAL: Duration = Duration::from_millis(100);

/// A debugging step of the session.
#[derive(Debug)]
pub enum DebugCommand {
    /// `DEBUG_ATTACH` with a linger of 0 (closing the connection ends the session) and "halt
    /// all" off; answered by [`Event::DebugAttached`], after which the halts are watched.
    Attach,
    /// `DEBUG_DETACH`: every breakpoint goes and every task runs on.
    Detach,
    /// Replaces the session's breakpoints: `BREAK_CLEAR` of all, then a `BREAK_SET` of each;
    /// answered by [`Event::BreakpointsSet`].
    SetBreakpoints(Vec<BreakpointSpec>),
    /// `STEP` of a halted task.
    Step {
        /// The task.
        task: u8,
        /// Into, over or out.
        kind: StepKind,
    },
    /// `RUN_TO`: the halted task runs to the statement starting at `instruction` of `pou`.
    RunTo {
        /// The task.
        task: u8,
        /// The POU's index in the image.
        pou: u32,
        /// The statement's first instruction.
        instruction: u32,
    },
    /// `CONTINUE` of a task ([`online_protocol::ALL_TASKS`] for every task).
    Continue(u8),
    /// `HALT` of a task ([`online_protocol::ALL_TASKS`] for "halt all").
    Halt(u8),
    /// `FLOW_CONFIGURE`: records which statements of these POUs run in each cycle of `task`,
    /// read about ten times a second into [`Event::Flow`]; replaces `task`'s list only (each
    /// task records its own), and no entries end `task`'s recording.
    Flow {
        /// The task whose cycles are recorded.
        task: u8,
        /// The POUs (and instances) recorded.
        entries: Vec<FlowEntry>,
    },
    /// `FRAME_READ` of frame `frame` of a halted task; answered by [`Event::FrameRead`].
    FrameRead {
        /// The task.
        task: u8,
        /// The frame's index, 0 for the innermost.
        frame: u16,
        /// The ranges of the frame to read.
        ranges: Vec<FrameRange>,
    },
}

/// A task that is halted, or waits beneath a halted one, with its call stack.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct HaltedTask {
    /// What `HALT_STATE` says about it.
    pub halt: TaskHalt,
    /// Its frames, innermost first, as `STACK` gives them.
    pub frames: Vec<StackFrame>,
}

/// What the session watches while attached.
#[derive(Debug, Default)]
pub(super) struct DebugWatch {
    /// Whether the session is attached, so halts are polled.
    pub(super) attached: bool,
    /// The `generation` of the last `HALT_STATE` reported; `None` before the first.
    generation: Option<u32>,
    /// Each recording task with its entries, in task order (the order `FLOW_READ` numbers
    /// the entries in); none empty.
    pub(super) flow: Vec<(u8, Vec<FlowEntry>)>,
    /// The tasks halted or waiting beneath a halted task at the last change of the halts:
    /// their flow is read from the cycle in progress.
    stopped: Vec<u8>,
}

impl DebugWatch {
    /// Whether flow bitmaps are read.
    pub(super) fn records_flow(&self) -> bool {
        self.attached && !self.flow.is_empty()
    }

    /// Replaces `task`'s flow entries, keeping the tasks in order.
    fn configure_flow(&mut self, task: u8, entries: Vec<FlowEntry>) {
        self.flow.retain(|(known, _)| *known != task);
        if !entries.is_empty() {
            let at = self.flow.partition_point(|(known, _)| *known < task);
            self.flow.insert(at, (task, entries));
        }
    }
}

/// Runs one debugging command; the answer is its own event (a refusal is an error naming
/// the service). A command that lets a task move is followed by a look at the halts at once,
/// so its end is reported without waiting for the next poll.
pub(super) async fn run(
    client: &mut Client,
    command: DebugCommand,
    watch: &mut DebugWatch,
) -> Result<Option<Event>, OnlineError> {
    match command {
        DebugCommand::Attach => {
            let attached: Attached = client
                .debug_attach(
                    0,
                    DebugOptions {
                        halt_all_on_halt: false,
                    },
                )
                .await?;
            watch.attached = true;
            watch.generation = None;
            Ok(Some(Event::DebugAttached(attached)))
        }
        DebugCommand::Detach => {
            watch.attached = false;
            watch.flow.clear();
            watch.stopped.clear();
            client.debug_detach().await?;
            // Every halt ended with the session.
            watch.generation = None;
            Ok(Some(Event::Halted(Vec::new())))
        }
        DebugCommand::SetBreakpoints(specs) => {
            client.break_clear(None).await?;
            let mut ids = Vec::with_capacity(specs.len());
            for spec in &specs {
                match client.break_set(spec).await {
                    Ok((id, _)) => ids.push(Ok(id)),
                    Err(error @ (OnlineError::Io(..) | OnlineError::Timeout(..))) => {
                        return Err(error);
                    }
                    Err(error) => ids.push(Err(error)),
                }
            }
            Ok(Some(Event::BreakpointsSet(ids)))
        }
        DebugCommand::Step { task, kind } => {
            client.step(task, kind).await?;
            poll_halts(client, watch).await
        }
        DebugCommand::RunTo {
            task,
            pou,
            instruction,
        } => {
            client.run_to(task, pou, instruction).await?;
            poll_halts(client, watch).await
        }
        DebugCommand::Continue(task) => {
            client.continue_task(task).await?;
            poll_halts(client, watch).await
        }
        DebugCommand::Halt(task) => {
            client.halt(task).await?;
            poll_halts(client, watch).await
        }
        DebugCommand::Flow { task, entries } => {
            client.flow_configure(task, &entries).await?;
            watch.configure_flow(task, entries);
            Ok(None)
        }
        DebugCommand::FrameRead {
            task,
            frame,
            ranges,
        } => {
            let values = client.frame_read(task, frame, &ranges).await?;
            Ok(Some(Event::FrameRead {
                task,
                frame,
                values,
            }))
        }
    }
}

/// Reads `HALT_STATE`; when its generation changed since the last report, reads the stack of
/// every halted or waiting task and reports them all ([`Event::Halted`], empty when no task
/// is halted).
pub(super) async fn poll_halts(
    client: &mut Client,
    watch: &mut DebugWatch,
) -> Result<Option<Event>, OnlineError> {
    let state = client.halt_state().await?;
    if watch.generation == Some(state.generation) {
        return Ok(None);
    }
    let mut halted = Vec::new();
    for halt in state.tasks {
        if !matches!(halt.state, TaskDebugState::Halted | TaskDebugState::Waiting) {
            continue;
        }
        let frames = client.stack(halt.task).await?;
        halted.push(HaltedTask { halt, frames });
    }
    watch.stopped = halted.iter().map(|task| task.halt.task).collect();
    watch.generation = Some(state.generation);
    Ok(Some(Event::Halted(halted)))
}

/// Reads the bitmap of every configured flow entry of every recording task: the last
/// complete cycle's, or the cycle so far of a task that is halted or waits beneath a halted
/// task (`docs/debugging.md` §5).
pub(super) async fn read_flow(
    client: &mut Client,
    watch: &DebugWatch,
) -> Result<Option<Event>, OnlineError> {
    if watch.flow.is_empty() {
        return Ok(None);
    }
    let mut bitmaps: Vec<(u8, FlowEntry, FlowBitmap)> = Vec::new();
    // `FLOW_READ` numbers the entries through every task's list in task order.
    let mut index: u8 = 0;
    for (task, entries) in &watch.flow {
        let which = if watch.stopped.contains(task) {
            FlowCycle::Current
        } else {
            FlowCycle::LastComplete
        };
        for entry in entries {
            let bitmap = client.flow_read(index, which).await?;
            bitmaps.push((*task, *entry, bitmap));
            index = index.saturating_add(1);
        }
    }
    Ok(Some(Event::Flow { bitmaps }))
}

#[cfg(test)]
#[path = "debug_tests.rs"]
mod tests;
