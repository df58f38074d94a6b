//! The tool panes at the bottom of the studio: messages, watch lists, forces, trace, tasks.

mod forces;
mod messages;
mod tasks;
mod trace;
mod watch;

pub(crate) use forces::forces_ui;
pub(crate) use messages::{message_count, messages_ui};
pub(crate) use tasks::tasks_ui;
pub(crate) use trace::{TracePaneState, trace_ui};
pub(crate) use watch::{WatchPaneState, watch_ui};
