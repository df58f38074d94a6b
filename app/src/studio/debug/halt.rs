//! What the online session reports while debugging: the halted tasks with their call stacks,
//! the frame the user looks at, and the statements that ran in the last cycle.

use super::breakpoints::Breakpoints;
use super::graphical_place::BodyLines;

/// One frame of a halted task's call stack, innermost first (`docs/debugging.md` §4).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct StackFrame {
    /// The POU (`FB_Conveyor`, `FB_Conveyor.Reset` for a method or action).
    pub pou: String,
    /// The instance it runs on by path (`Main.fbConveyor`); `None` for a function.
    pub instance: Option<String>,
    /// The body's file, as the line table names it (`application/FB_Conveyor.st`).
    pub file: String,
    /// The line of the halt (the first frame) or of the call (the others), from 1.
    pub line: u32,
}

/// A task that is halted, or that waits beneath a halted one (§2.1).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct HaltedTask {
    /// The task's name.
    pub task: String,
    /// What this task waits beneath, if it is not halted itself.
    pub beneath: Option<Beneath>,
    /// Its frames, innermost first.
    pub frames: Vec<StackFrame>,
}

/// What a waiting task waits beneath, as exactly as the target's reports tell it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Beneath {
    /// The one halted task (with a single halted task there is no other it could wait for).
    Task(String),
    /// One of several halted tasks: `HALT_STATE` does not say in which order their cycles
    /// nest on the scheduler thread, so the studio names none rather than guess.
    AHaltedTask,
}

/// The debugging state of the session, replaced as the online layer reports; lives while the
/// studio runs and is never saved (a logout ends every halt).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct DebugState {
    /// The halted (and waiting) tasks.
    halted: Vec<HaltedTask>,
    /// The task and frame index the call stack pane shows (and the editor marks).
    shown: Option<(String, usize)>,
    /// Whether flow control is on for the open editors.
    pub flow_control: bool,
    /// The statements that ran in the last cycle: each body's file and its lines (from 1).
    flow: Vec<(String, Vec<u32>)>,
}

impl DebugState {
    /// Takes the halted tasks as the session reports them; the shown frame stays when its task
    /// is still halted, else the first halted task's innermost frame is shown.
    pub fn set_halted(&mut self, halted: Vec<HaltedTask>) {
        let still = self.shown.as_ref().is_some_and(|(task, frame)| {
            halted
                .iter()
                .any(|h| &h.task == task && *frame < h.frames.len())
        });
        if !still {
            self.shown = halted
                .iter()
                .find(|task| task.beneath.is_none())
                .or(halted.first())
                .map(|task| (task.task.clone(), 0));
        }
        self.halted = halted;
    }

    /// Shows the first halted task's innermost frame from the next [`DebugState::set_halted`]
    /// on (a new halt reported, rather than the same halt again).
    pub fn show_innermost(&mut self) {
        self.shown = None;
    }

    /// The halted and waiting tasks.
    pub fn halted(&self) -> &[HaltedTask] {
        &self.halted
    }

    /// Whether any task is halted (F5 continues rather than starts).
    pub fn is_halted(&self) -> bool {
        self.halted.iter().any(|task| task.beneath.is_none())
    }

    /// Shows frame `frame` of `task` (a click in the call stack).
    pub fn show_frame(&mut self, task: &str, frame: usize) {
        self.shown = Some((task.to_owned(), frame));
    }

    /// The task and frame index shown.
    pub fn shown(&self) -> Option<(&str, usize)> {
        self.shown
            .as_ref()
            .map(|(task, frame)| (task.as_str(), *frame))
    }

    /// The frame shown, if its task is still halted.
    pub fn shown_frame(&self) -> Option<&StackFrame> {
        let (task, frame) = self.shown.as_ref()?;
        self.halted
            .iter()
            .find(|halted| &halted.task == task)?
            .frames
            .get(*frame)
    }

    /// Takes the flow-control lines of the last cycle, per body file.
    pub fn set_flow(&mut self, flow: Vec<(String, Vec<u32>)>) {
        self.flow = flow;
    }

    /// Forgets every halt and flow mark (logout, or the target lost).
    pub fn end_session(&mut self) {
        self.halted.clear();
        self.shown = None;
        self.flow.clear();
    }

    /// The marks of the ST editor of the body in `file`: its breakpoints, the shown frame's
    /// line (the yellow arrow for the halt, a hollow one for a caller) and, while flow control
    /// is on, the lines that ran.
    pub fn marks_for(&self, file: &str, breakpoints: &Breakpoints) -> editor::StDebugMarks {
        let frame = self
            .shown_frame()
            .filter(|frame| frame.file == file && frame.line > 0);
        editor::StDebugMarks {
            breakpoints: breakpoints
                .in_file(file)
                .filter(|breakpoint| {
                    breakpoint.place.graphical.is_none() && breakpoint.place.line > 0
                })
                .map(|breakpoint| editor::BreakpointMark {
                    line: breakpoint.place.line as usize - 1,
                    look: breakpoint.look(),
                })
                .collect(),
            halt_line: frame.map(|frame| frame.line as usize - 1),
            halt_is_caller: self.shown().is_some_and(|(_, index)| index > 0),
            flow_lines: if self.flow_control {
                self.flow
                    .iter()
                    .filter(|(flow_file, _)| flow_file == file)
                    .flat_map(|(_, lines)| lines.iter())
                    .filter(|line| **line > 0)
                    .map(|line| *line as usize - 1)
                    .collect()
            } else {
                Vec::new()
            },
        }
    }
}

impl DebugState {
    /// The marks of the graphical editor of the body named `body` (`Interlock`, `FB.Reset`)
    /// in `file` (its `.pou.toml`): its breakpoints, and through `lines` (the places of the
    /// lines of the body's lowered text, which the image's lines count) the shown frame's
    /// element and, while flow control is on, the elements that ran. Without `lines` only the
    /// breakpoints are marked.
    pub fn body_marks_for(
        &self,
        file: &str,
        body: &str,
        lines: Option<&BodyLines>,
        breakpoints: &Breakpoints,
    ) -> editor::BodyDebugMarks {
        let breakpoints = breakpoints
            .in_file(file)
            .filter_map(|breakpoint| {
                let place = breakpoint.place.graphical.as_ref()?;
                place
                    .body
                    .eq_ignore_ascii_case(body)
                    .then(|| editor::BodyBreakpointMark {
                        place: place.in_editor(),
                        look: breakpoint.look(),
                    })
            })
            .collect();
        let Some(lines) = lines else {
            return editor::BodyDebugMarks {
                breakpoints,
                ..Default::default()
            };
        };
        let halt = self
            .shown_frame()
            .filter(|frame| frame.file == lines.text_file)
            .and_then(|frame| lines.place_at(frame.line));
        let flow = if self.flow_control {
            self.flow
                .iter()
                .filter(|(flow_file, _)| *flow_file == lines.text_file)
                .flat_map(|(_, ran)| ran.iter())
                .filter_map(|line| lines.place_at(*line))
                .collect()
        } else {
            Vec::new()
        };
        editor::BodyDebugMarks {
            breakpoints,
            halt,
            halt_is_caller: halt.is_some() && self.shown().is_some_and(|(_, index)| index > 0),
            flow,
        }
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::expect_used)] // A panic is a failed test.

    use super::super::breakpoint::BreakpointPlace;
    use super::super::graphical_place::place_at_line;
    use super::*;

    fn frame(pou: &str, file: &str, line: u32) -> StackFrame {
        StackFrame {
            pou: pou.to_owned(),
            instance: Some(format!("Main.{pou}")),
            file: file.to_owned(),
            line,
        }
    }

    fn halted_fast() -> Vec<HaltedTask> {
        vec![
            HaltedTask {
                task: "Slow".to_owned(),
                beneath: Some(Beneath::Task("Fast".to_owned())),
                frames: vec![frame("Main", "application/Main.st", 2)],
            },
            HaltedTask {
                task: "Fast".to_owned(),
                beneath: None,
                frames: vec![
                    frame("FB_Conveyor", "application/FB_Conveyor.st", 7),
                    frame("Main", "application/Main.st", 4),
                ],
            },
        ]
    }

    #[test]
    fn a_halt_shows_the_halted_tasks_innermost_frame_not_the_waiting_one() {
        let mut state = DebugState::default();
        state.set_halted(halted_fast());
        assert!(state.is_halted());
        assert_eq!(state.shown(), Some(("Fast", 0)));
        let marks = state.marks_for("application/FB_Conveyor.st", &Breakpoints::default());
        assert_eq!(marks.halt_line, Some(6));
        assert!(!marks.halt_is_caller);
        let marks = state.marks_for("application/Main.st", &Breakpoints::default());
        assert_eq!(marks.halt_line, None);
    }

    #[test]
    fn a_callers_frame_is_marked_as_a_caller_and_stays_shown_while_halted() {
        let mut state = DebugState::default();
        state.set_halted(halted_fast());
        state.show_frame("Fast", 1);
        state.set_halted(halted_fast());
        let marks = state.marks_for("application/Main.st", &Breakpoints::default());
        assert_eq!(marks.halt_line, Some(3));
        assert!(marks.halt_is_caller);
        state.end_session();
        assert!(!state.is_halted());
        assert_eq!(state.shown_frame(), None);
    }

    #[test]
    fn breakpoints_and_flow_lines_are_marked_in_their_file_only_with_flow_control_on() {
        let mut breakpoints = Breakpoints::default();
        breakpoints.toggle(BreakpointPlace::text("application/Main.st", 3));
        let mut state = DebugState::default();
        state.set_flow(vec![("application/Main.st".to_owned(), vec![1, 3])]);
        let marks = state.marks_for("application/Main.st", &breakpoints);
        assert_eq!(marks.breakpoints.len(), 1);
        assert_eq!(marks.breakpoints[0].line, 2);
        assert!(marks.flow_lines.is_empty());
        state.flow_control = true;
        let marks = state.marks_for("application/Main.st", &breakpoints);
        assert_eq!(marks.flow_lines, vec![0, 2]);
        let marks = state.marks_for("application/Other.st", &breakpoints);
        assert!(marks.breakpoints.is_empty() && marks.flow_lines.is_empty());
    }

    #[test]
    fn a_graphical_body_marks_its_breakpoints_and_the_element_of_the_halted_line() {
        let project = project_model::load_project(&assets::example_project_dir())
            .map(|loaded| loaded.project)
            .unwrap_or_default();
        let lowered = compiler::lower::lower_project(&project).bodies;
        let body = lowered
            .iter()
            .find(|body| body.pou == "Interlock")
            .expect("the example has the LD program Interlock");
        let text_file = body.text_file.to_string_lossy().into_owned();
        let lines = BodyLines::of(body);
        // Every line has the place the text search gives it.
        for line in 0..=body.text.lines().count() as u32 + 1 {
            assert_eq!(
                lines.place_at(line),
                place_at_line(body, line),
                "line {line}"
            );
        }
        // The first line of the lowered text with an element: where a halt would be.
        let (line, place) = (1..=body.text.lines().count() as u32)
            .find_map(|line| Some((line, place_at_line(body, line)?)))
            .expect("a lowered LD body has element lines");
        let file = "application/Interlock.pou.toml";
        let mut breakpoints = Breakpoints::default();
        breakpoints.toggle(BreakpointPlace::graphical(
            file,
            super::super::graphical_place::GraphicalPlace {
                body: "Interlock".to_owned(),
                network: 0,
                element: None,
            },
        ));
        let mut state = DebugState::default();
        state.set_halted(vec![HaltedTask {
            task: "Main".to_owned(),
            beneath: None,
            frames: vec![frame("Interlock", &text_file, line)],
        }]);
        state.set_flow(vec![(text_file.clone(), vec![line])]);
        let marks = state.body_marks_for(file, "Interlock", Some(&lines), &breakpoints);
        assert_eq!(marks.breakpoints.len(), 1);
        assert_eq!(marks.breakpoints[0].place.network, 0);
        assert_eq!(marks.halt, Some(place));
        assert!(!marks.halt_is_caller);
        assert!(marks.flow.is_empty(), "flow control is off");
        state.flow_control = true;
        let marks = state.body_marks_for(file, "Interlock", Some(&lines), &breakpoints);
        assert_eq!(marks.flow, vec![place]);
        // Another body has none of these; the text editor does not show graphical breakpoints.
        let other = state.body_marks_for(file, "Other", Some(&lines), &breakpoints);
        assert!(other.breakpoints.is_empty());
        assert!(state.marks_for(file, &breakpoints).breakpoints.is_empty());
        // Without the lowering only the breakpoints are known.
        let offline = state.body_marks_for(file, "Interlock", None, &breakpoints);
        assert_eq!(offline.breakpoints.len(), 1);
        assert_eq!(offline.halt, None);
    }
}
