//! F9 and "Toggle breakpoint" in a graphical editor: the selected network or element as a
//! breakpoint place of the body's `.pou.toml` file, refused with the reason when it has no
//! statement of its own.

use project_model::{Object, Project, TextTarget};

use crate::studio::command::{Command, Commands};
use crate::studio::debug::{BreakpointPlace, Breakpoints, GraphicalPlace, body_name};
use crate::studio::i18n::{DebugText, Language};
use crate::studio::view::StudioView;

use super::documents::LoweringCache;

/// The debugger's marks of the body `target` of the POU `pou` at `revision`: its breakpoints
/// and, while a task is halted or flow control is on, the halted and flowed elements through
/// the body's lowered text (breakpoints alone need no lowering). Also gives the POU's file.
pub(super) fn body_marks(
    view: &StudioView<'_>,
    lowering: &mut LoweringCache,
    project: &Project,
    revision: u64,
    pou: &str,
    target: &TextTarget,
) -> (String, editor::BodyDebugMarks) {
    let file = lowering.pou_file(project, revision, pou).to_owned();
    let debugging = !view.debug.halted().is_empty() || view.debug.flow_control;
    let lines = if debugging {
        lowering.body_lines(project, revision, target)
    } else {
        None
    };
    let no_breakpoints = Breakpoints::default();
    let marks = view.debug.body_marks_for(
        &file,
        &body_name(target),
        lines,
        view.breakpoints().unwrap_or(&no_breakpoints),
    );
    (file, marks)
}

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
/// the body's lowered text (of `project` at `revision`) shows no statement comes from it, says
/// why in the status line: an operator box is computed inside the statement of what it feeds.
pub(super) fn toggle_breakpoint(
    commands: &mut Commands,
    target: &TextTarget,
    file: &str,
    place: editor::BodyPlace,
    lowering: &mut LoweringCache,
    (project, revision): (&Project, u64),
    language: Language,
) {
    let lines = lowering.body_lines(project, revision, target);
    let graphical = GraphicalPlace::of_editor(target, place);
    if lines.is_some_and(|lines| !lines.has_statement(place)) {
        let what = crate::studio::panes::graphical_place_text(language, Some(project), &graphical);
        commands.error(DebugText::NoElementStatement.fill(language, &[("place", &what)]));
        return;
    }
    commands.push(Command::ToggleBreakpoint(BreakpointPlace::graphical(
        file, graphical,
    )));
}

/// The breakpoint place of the selection `selected` of the editor of the body `target` in
/// `file`, when that editor has the keyboard focus (`focused`).
pub(super) fn focused_place(
    focused: bool,
    selected: Option<editor::BodyPlace>,
    target: &TextTarget,
    file: &str,
) -> Option<BreakpointPlace> {
    let selected = selected.filter(|_| focused)?;
    Some(BreakpointPlace::graphical(
        file,
        GraphicalPlace::of_editor(target, selected),
    ))
}
