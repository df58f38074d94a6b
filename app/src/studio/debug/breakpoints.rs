//! The breakpoints of one project, and where a line's breakpoint goes.

use serde::{Deserialize, Serialize};

use super::breakpoint::{Breakpoint, BreakpointPlace};
use crate::debug_bodies::GraphicalBodies;
use crate::debug_places::Statement;

/// The breakpoints of one project, in the order they were set; saved with the settings.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(transparent)]
pub struct Breakpoints {
    /// The breakpoints, one per place.
    list: Vec<Breakpoint>,
}

impl Breakpoints {
    /// Every breakpoint, in the order they were set.
    pub fn all(&self) -> &[Breakpoint] {
        &self.list
    }

    /// Whether there is none.
    pub fn is_empty(&self) -> bool {
        self.list.is_empty()
    }

    /// The breakpoint on `place`, if any.
    pub fn at(&self, place: &BreakpointPlace) -> Option<&Breakpoint> {
        self.list
            .iter()
            .find(|breakpoint| &breakpoint.place == place)
    }

    /// The breakpoints in `file`.
    pub fn in_file<'a>(&'a self, file: &'a str) -> impl Iterator<Item = &'a Breakpoint> + 'a {
        self.list
            .iter()
            .filter(move |breakpoint| breakpoint.place.file == file)
    }

    /// Sets a plain breakpoint on `place`, or removes the one there (F9); returns whether a
    /// breakpoint is there now.
    pub fn toggle(&mut self, place: BreakpointPlace) -> bool {
        if let Some(index) = self.index_of(&place) {
            self.list.remove(index);
            false
        } else {
            self.list.push(Breakpoint::at(place));
            true
        }
    }

    /// Replaces the breakpoint on `breakpoint.place` (the dialog's or the check box's change);
    /// a breakpoint removed meanwhile is not brought back.
    pub fn update(&mut self, breakpoint: Breakpoint) {
        if let Some(index) = self.index_of(&breakpoint.place) {
            self.list[index] = breakpoint;
        }
    }

    /// Removes the breakpoint on `place`.
    pub fn remove(&mut self, place: &BreakpointPlace) {
        self.list.retain(|breakpoint| &breakpoint.place != place);
    }

    /// Removes every breakpoint.
    pub fn clear(&mut self) {
        self.list.clear();
    }

    fn index_of(&self, place: &BreakpointPlace) -> Option<usize> {
        self.list
            .iter()
            .position(|breakpoint| &breakpoint.place == place)
    }
}

/// The lines (from 1, sorted, without repeats) where statements of the body in `file` start,
/// from the line table of a built image: the places a breakpoint can go (`docs/debugging.md`
/// §3; ELSIF conditions and loop tests are in the table too).
pub fn statement_lines(image: &program_image::ProgramImage, file: &str) -> Vec<u32> {
    let Some(file_index) = image.sources.iter().position(|source| source == file) else {
        return Vec::new();
    };
    let mut lines: Vec<u32> = image
        .pous
        .iter()
        .flat_map(|pou| pou.lines.iter())
        .filter(|entry| entry.file as usize == file_index)
        .map(|entry| entry.line)
        .collect();
    lines.sort_unstable();
    lines.dedup();
    lines
}

/// The line where F9 on `line` puts a breakpoint, given the body's statement lines: the line
/// itself when a statement starts there, else the next line that starts one (as CODESYS moves
/// a breakpoint from a comment or an `END_IF` to the next statement); `None` after the last.
/// Without a line table (never built) the line is taken as it is.
pub fn statement_line(statement_lines: &[u32], line: u32) -> Option<u32> {
    if statement_lines.is_empty() {
        return Some(line);
    }
    let at = statement_lines.partition_point(|&start| start < line);
    statement_lines.get(at).copied()
}

/// The statement a breakpoint's place names in `image`: for a Structured Text place the first
/// statement starting on its line, for a graphical place the first statement of its network or
/// element (through `bodies`, the project's lowered graphical bodies). `None` when no statement
/// is there (an operator box has none of its own, an empty network none at all).
pub fn statement_of_place(
    place: &BreakpointPlace,
    image: &program_image::ProgramImage,
    bodies: &GraphicalBodies,
) -> Option<Statement> {
    match &place.graphical {
        Some(graphical) => bodies.statement_of(
            image,
            &place.file,
            &graphical.body,
            graphical.network,
            graphical.element,
        ),
        None => {
            let file = image
                .sources
                .iter()
                .position(|source| *source == place.file)?;
            crate::debug_bodies::statement_on_line(image, file as u32, place.line)
        }
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, clippy::expect_used)] // A panic is a failed test.

    use super::super::graphical_place::{BodyLines, GraphicalPlace, place_at_line};
    use super::*;
    use program_image::ProgramImage;

    fn interlock() -> (project_model::Project, ProgramImage, GraphicalBodies) {
        let project = project_model::load_project(&assets::example_project_dir())
            .unwrap()
            .project;
        let image = compiler::compile_project(&project).unwrap();
        let bodies = GraphicalBodies::of_project(&project);
        (project, image, bodies)
    }

    #[test]
    fn a_graphical_place_names_the_statement_of_its_network_and_back() {
        let (project, image, bodies) = interlock();
        let network = GraphicalPlace {
            body: "Interlock".to_owned(),
            network: 1,
            element: None,
        };
        let file = "application/Interlock.pou.toml";
        let place = BreakpointPlace::graphical(file, network.clone());
        let statement = statement_of_place(&place, &image, &bodies).unwrap();
        assert_eq!(statement.pou_name, "Interlock");
        // The statement's line leads back to an element of the same network.
        let lowered = compiler::lower::lower_project(&project).bodies;
        let body = lowered
            .iter()
            .find(|body| body.text_file.to_string_lossy() == statement.file)
            .unwrap();
        let at = place_at_line(body, statement.line).unwrap();
        assert_eq!(at.network, 1);
        let element = at.element.unwrap();
        assert!(BodyLines::of(body).has_statement(at));
        // That element is a place of its own naming the same statement.
        let element_place = BreakpointPlace::graphical(
            file,
            GraphicalPlace {
                element: Some(element.0),
                ..network.clone()
            },
        );
        assert_eq!(
            statement_of_place(&element_place, &image, &bodies),
            Some(statement)
        );
        // A network that is not there names nothing.
        let missing = BreakpointPlace::graphical(
            file,
            GraphicalPlace {
                network: 99,
                ..network
            },
        );
        assert_eq!(statement_of_place(&missing, &image, &bodies), None);
        assert!(!BodyLines::of(body).has_statement(editor::BodyPlace {
            network: 99,
            element: None
        }));
    }

    #[test]
    fn a_text_place_names_the_statement_on_its_line() {
        let (_, image, bodies) = interlock();
        let (file, line) = image
            .pous
            .iter()
            .flat_map(|pou| pou.lines.iter())
            .map(|entry| (image.sources[entry.file as usize].clone(), entry.line))
            .find(|(file, _)| file.ends_with(".st"))
            .unwrap();
        let place = BreakpointPlace::text(file.clone(), line);
        let statement = statement_of_place(&place, &image, &bodies).unwrap();
        assert_eq!((statement.file, statement.line), (file, line));
    }

    fn place(line: u32) -> BreakpointPlace {
        BreakpointPlace::text("application/Main.st", line)
    }

    #[test]
    fn toggling_sets_then_clears_the_breakpoint_of_a_place() {
        let mut breakpoints = Breakpoints::default();
        assert!(breakpoints.toggle(place(3)));
        assert!(breakpoints.toggle(place(5)));
        assert_eq!(breakpoints.all().len(), 2);
        assert!(!breakpoints.toggle(place(3)));
        assert_eq!(breakpoints.all(), &[Breakpoint::at(place(5))]);
        assert_eq!(breakpoints.in_file("application/Main.st").count(), 1);
        assert_eq!(breakpoints.in_file("application/Other.st").count(), 0);
    }

    #[test]
    fn an_update_changes_the_breakpoint_of_its_place_only_while_it_exists() {
        let mut breakpoints = Breakpoints::default();
        breakpoints.toggle(place(3));
        let mut changed = Breakpoint::at(place(3));
        changed.condition = "x > 1".to_owned();
        breakpoints.update(changed.clone());
        assert_eq!(breakpoints.at(&place(3)), Some(&changed));
        breakpoints.remove(&place(3));
        breakpoints.update(changed);
        assert!(breakpoints.is_empty());
    }

    #[test]
    fn a_line_without_a_statement_takes_the_next_statement() {
        let lines = [2, 3, 7];
        assert_eq!(statement_line(&lines, 2), Some(2));
        assert_eq!(statement_line(&lines, 1), Some(2));
        assert_eq!(statement_line(&lines, 4), Some(7));
        assert_eq!(statement_line(&lines, 8), None);
        assert_eq!(statement_line(&[], 8), Some(8));
    }

    #[test]
    fn statement_lines_come_from_the_line_table_of_the_file() {
        let pou = |name: &str, lines: &[(u32, u32, u32)]| program_image::Pou {
            name: name.to_owned(),
            kind: program_image::PouKind::Program,
            frame_size: 0,
            frame_init: Vec::new(),
            instance_size: 0,
            code: Vec::new(),
            lines: lines
                .iter()
                .map(|&(index, file, line)| program_image::LineEntry { index, file, line })
                .collect(),
        };
        let image = ProgramImage {
            sources: vec!["application/A.st".to_owned(), "application/B.st".to_owned()],
            pous: vec![
                pou("B", &[(0, 1, 4), (5, 1, 4)]),
                pou("A", &[(3, 0, 2)]),
                pou("B2", &[(9, 1, 1)]),
            ],
            ..Default::default()
        };
        assert_eq!(statement_lines(&image, "application/B.st"), vec![1, 4]);
        assert_eq!(statement_lines(&image, "application/A.st"), vec![2]);
        assert!(statement_lines(&image, "application/C.st").is_empty());
    }
}
