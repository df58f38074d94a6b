//! The tool panes at the bottom of the studio: messages, watch lists, forces, trace, tasks.

mod breakpoints;
mod call_stack;
mod forces;
mod messages;
mod tasks;
mod trace;
mod watch;

pub(crate) use breakpoints::{BreakpointsPaneState, breakpoints_ui, graphical_place_text};
pub(crate) use call_stack::call_stack_ui;
pub(crate) use forces::forces_ui;
pub(crate) use messages::{message_count, messages_ui};
pub(crate) use tasks::{fault_place as source_place, tasks_ui};
pub(crate) use trace::{TracePaneState, trace_ui};
pub(crate) use watch::{WatchPaneState, watch_ui};

/// The application objects `pick` accepts, in tree order, and the one chosen by name among
/// them (the first when none is chosen or the chosen one is gone): the watch list or the
/// trace a pane shows.
pub(crate) fn chosen_object<'p, T>(
    session: Option<&'p crate::studio::session::Session>,
    chosen: Option<&str>,
    pick: impl Fn(&'p project_model::Object) -> Option<&'p T>,
) -> (Vec<&'p T>, Option<&'p T>)
where
    T: HasName,
{
    let Some(session) = session else {
        return (Vec::new(), None);
    };
    let all: Vec<&T> = project_model::object_files(&session.project)
        .into_iter()
        .filter_map(|(_, object)| pick(object))
        .collect();
    let current = chosen
        .and_then(|name| all.iter().find(|item| item.name() == name).copied())
        .or_else(|| all.first().copied());
    (all, current)
}

/// Objects a pane chooses among by name.
pub(crate) trait HasName {
    /// The object's name.
    fn name(&self) -> &str;
}

impl HasName for project_model::WatchList {
    fn name(&self) -> &str {
        &self.name
    }
}

impl HasName for project_model::TraceConfig {
    fn name(&self) -> &str {
        &self.name
    }
}
