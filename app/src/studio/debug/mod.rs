//! The studio's side of debugging (`docs/debugging.md`): the breakpoints the user set, kept per
//! project in the settings; the halted tasks, their call stacks and the flow-control marks as
//! the online session reports them; and the commands the Debug menu sends to the online layer.
//! Everything here is plain data and pure functions, drawn by the editors and the Breakpoints
//! and Call stack panes.

mod breakpoint;
mod breakpoints;
mod command;
mod condition_cache;
mod flow_entries;
mod graphical_place;
mod halt;
mod reported;
mod target_breakpoint;

pub use breakpoint::{Breakpoint, BreakpointPlace, HitMode};
pub use breakpoints::{Breakpoints, statement_line, statement_lines, statement_of_place};
pub use command::{DebugCommand, DebugTarget};
pub use condition_cache::{ConditionCache, ConditionKey, compile_condition};
pub use flow_entries::flow_entries;
pub use graphical_place::{BodyLines, GraphicalPlace, body_name, body_target, place_at_line};
pub use halt::{Beneath, DebugState, HaltedTask, StackFrame};
pub use reported::{flow_lines, halted_tasks};
pub use target_breakpoint::{breakpoint_spec_with, breakpoint_statement, condition_key};
