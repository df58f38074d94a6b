//! F9 and "Toggle breakpoint" in a graphical editor: the selected network or element as a
//! breakpoint place of the body's `.pou.toml` file, refused with the reason when it has no
//! statement of its own.

use compiler::lower::LoweredBody;
use project_model::{Object, Project, TextTarget};

use crate::studio::command::{Command, Commands};
use crate::studio::debug::{BreakpointPlace, GraphicalPlace, has_statement};
use crate::studio::i18n::{DebugText, Language};

/// The `.pou.toml` file of the POU named `pou`, relative to the project folder with `/`
/// between folders, as `rivet check` and the breakpoints name it; empty when there is none.
pub(super) fn pou_file(project: &Project, pou: &str) -> String {
    project_model::object_files(project)
        .into_iter()
        .find(|(_, object)| matches!(object, Object::Pou(found) if found.name == pou))
        .map(|(file, _)| file.to_string_lossy().replace('\\', "/"))
        .unwrap_or_default()
}

/// Queues the toggle of the breakpoint on `place` of the body `target` in `file`, or, when
/// `lowered` (the body's lowered text) shows no statement comes from it, says why in the
/// status line: an operator box is computed inside the statement of what it feeds.
pub(super) fn toggle_breakpoint(
    commands: &mut Commands,
    target: &TextTarget,
    file: &str,
    place: editor::BodyPlace,
    lowered: Option<&LoweredBody>,
    language: Language,
) {
    let graphical = GraphicalPlace::of_editor(target, place);
    if lowered.is_some_and(|body| !has_statement(body, place)) {
        let what = graphical.command_line();
        commands.error(DebugText::NoElementStatement.fill(language, &[("place", &what)]));
        return;
    }
    commands.push(Command::ToggleBreakpoint(BreakpointPlace::graphical(
        file, graphical,
    )));
}
