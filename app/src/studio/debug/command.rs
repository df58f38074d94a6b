//! The Debug menu's commands for the online layer, and the door it implements.

use super::breakpoint::{Breakpoint, BreakpointPlace};

/// A debugging request of the Debug menu, its keys or the editors, for the halted task or the
/// target (`docs/debugging.md` §4); the online layer turns each into the session's calls.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum DebugCommand {
    /// Let the halted task run on to the next breakpoint (F5 while halted).
    Continue,
    /// Run the statement, calls in it whole, and halt at the next one of the body (F10).
    StepOver,
    /// Run the statement and halt at the next one reached, in a callee too (F8).
    StepInto,
    /// Run the rest of the body and halt in the caller (Shift+F10).
    StepOut,
    /// Run until the halted task reaches this statement.
    RunToCursor(BreakpointPlace),
    /// Halt the task at its next statement.
    Halt(String),
    /// Halt every task.
    HaltAll,
    /// Turn flow control on or off for the open editors.
    SetFlowControl(bool),
    /// Send the project's enabled breakpoints again (after a change to the list).
    SyncBreakpoints(Vec<Breakpoint>),
}

impl DebugCommand {
    /// Whether the command needs a halted task (stepping, continuing, running to the cursor).
    pub fn needs_halt(&self) -> bool {
        matches!(
            self,
            DebugCommand::Continue
                | DebugCommand::StepOver
                | DebugCommand::StepInto
                | DebugCommand::StepOut
                | DebugCommand::RunToCursor(_)
        )
    }
}

/// What the online layer offers the debugger: it queues each command for the session and
/// returns at once (the UI never waits on the network); the halts, call stacks and flow marks
/// come back through [`super::DebugState`].
pub trait DebugTarget {
    /// Queues `command`; returns false when there is no session able to take it (logged out,
    /// or a runtime started with `--debug off`), so the studio says so.
    fn debug(&mut self, command: DebugCommand) -> bool;
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_flow_commands_need_a_halted_task() {
        assert!(DebugCommand::StepOver.needs_halt());
        assert!(DebugCommand::Continue.needs_halt());
        assert!(!DebugCommand::HaltAll.needs_halt());
        assert!(!DebugCommand::SetFlowControl(true).needs_halt());
        assert!(!DebugCommand::SyncBreakpoints(Vec::new()).needs_halt());
    }
}
