//! Places in graphical bodies as `rivet check` prints them, `FILE:POU:NETWORK[:ELEMENT]`
//! (`application/Interlock.pou.toml:Interlock:2:7`), to statement starts and back. A body is
//! compiled as Structured Text with each element's statement on a line of its own, so an
//! element's place is a line of that text (`docs/debugging.md` §3).

use compiler::lower::{ElementPlace, LoweredBody, lower_project};
use compiler::origin::Origin;
use program_image::ProgramImage;
use project_model::Project;

use crate::debug_places::{PlaceError, Statement};

/// The graphical bodies of a project with the element each line of their text comes from;
/// empty for a program made from one `.st` file.
#[derive(Clone, Debug, Default)]
pub struct GraphicalBodies {
    bodies: Vec<GraphicalBody>,
}

/// One lowered body.
#[derive(Clone, Debug)]
struct GraphicalBody {
    /// The POU's `.pou.toml` file, relative to the project folder.
    file: String,
    /// The name the image's sources give the lowered text.
    text_file: String,
    /// Line by line (from line 1), the element the line's statement comes from, as the place
    /// `rivet check` prints; `None` for lines of no element.
    lines: Vec<Option<ElementPlace>>,
}

impl GraphicalBodies {
    /// The graphical bodies of `project`, lowered as the compiler lowers them.
    pub fn of_project(project: &Project) -> Self {
        Self::of_lowered(&lower_project(project).bodies)
    }

    /// The graphical bodies of a project lowered already (the studio keeps its lowering).
    pub fn of_lowered(lowered: &[LoweredBody]) -> Self {
        let bodies = lowered
            .iter()
            .map(|body| {
                let count = body.text.lines().count();
                let lines = (1..=count as u32)
                    .map(|line| match body.origin_at_line(line)? {
                        Origin::Element {
                            network, element, ..
                        } => Some(ElementPlace {
                            pou: body.pou.clone(),
                            target: body.target.clone(),
                            network,
                            element,
                            pin: None,
                        }),
                        Origin::Text { .. } => None,
                    })
                    .collect();
                GraphicalBody {
                    file: body.file.to_string_lossy().replace('\\', "/"),
                    text_file: body.text_file.to_string_lossy().into_owned(),
                    lines,
                }
            })
            .collect();
        Self { bodies }
    }

    /// The statement a graphical place names: the first statement of the network, or the
    /// element's. `None` when `place` is not written as `FILE:POU:NETWORK[:ELEMENT]` or names
    /// no graphical body's file, so that it is read as `FILE:LINE`.
    pub fn statement_at(
        &self,
        image: &ProgramImage,
        place: &str,
    ) -> Option<Result<Statement, PlaceError>> {
        let (file, pou, network, element) = parse(place.trim())?;
        self.bodies_in(file).next()?;
        Some(
            self.statement_of(image, file, pou, network - 1, element)
                .ok_or_else(|| PlaceError::NoElementStatement(place.trim().to_owned())),
        )
    }

    /// The first statement of network `network` (from 0) of the body named `body` (`Main`,
    /// `FB.Reset`) in `file`, or of its element `element`; `None` when none is there.
    pub fn statement_of(
        &self,
        image: &ProgramImage,
        file: &str,
        body: &str,
        network: usize,
        element: Option<u32>,
    ) -> Option<Statement> {
        for graphical in self.bodies_in(file) {
            let Some(source) = image.sources.iter().position(|s| *s == graphical.text_file) else {
                continue;
            };
            for (at, origin) in graphical.lines.iter().enumerate() {
                let Some(origin) = origin else { continue };
                let name = origin.to_string();
                let Some((origin_pou, _)) = name.split_once(':') else {
                    continue;
                };
                let same = origin_pou.eq_ignore_ascii_case(body)
                    && origin.network == network
                    && element.is_none_or(|element| origin.element.map(|e| e.0) == Some(element));
                if !same {
                    continue;
                }
                if let Some(statement) = statement_on_line(image, source as u32, at as u32 + 1) {
                    return Some(statement);
                }
            }
        }
        None
    }

    /// The bodies whose `.pou.toml` file is `file` or ends with it after a `/`.
    fn bodies_in<'a>(&'a self, file: &str) -> impl Iterator<Item = &'a GraphicalBody> + 'a {
        let wanted = file.replace('\\', "/");
        self.bodies
            .iter()
            .filter(move |body| body.file == wanted || body.file.ends_with(&format!("/{wanted}")))
    }

    /// The graphical place of `statement` (`application/Interlock.pou.toml:Interlock:2:7`);
    /// `None` for a statement of a Structured Text body.
    pub fn place_of(&self, statement: &Statement) -> Option<String> {
        let body = self
            .bodies
            .iter()
            .find(|body| body.text_file == statement.file)?;
        let origin = body
            .lines
            .get(statement.line.checked_sub(1)? as usize)?
            .as_ref()?;
        Some(format!("{}:{origin}", body.file))
    }
}

/// `FILE:POU:NETWORK[:ELEMENT]` in its parts; `None` for any other form.
fn parse(place: &str) -> Option<(&str, &str, usize, Option<u32>)> {
    let parts: Vec<&str> = place.split(':').collect();
    let number = |text: &str| text.trim().parse::<u32>().ok();
    let n = parts.len();
    let (pou_at, network, element) = if n >= 4
        && let (Some(network), Some(element)) = (number(parts[n - 2]), number(parts[n - 1]))
        && number(parts[n - 3]).is_none()
    {
        (n - 3, network, Some(element))
    } else if n >= 3
        && let Some(network) = number(parts[n - 1])
    {
        (n - 2, network, None)
    } else {
        return None;
    };
    let file_end = parts[..pou_at]
        .iter()
        .map(|p| p.len() + 1)
        .sum::<usize>()
        .checked_sub(1)?;
    let file = &place[..file_end];
    let pou = parts[pou_at].trim();
    (network >= 1 && !file.is_empty() && !pou.is_empty()).then_some((
        file,
        pou,
        network as usize,
        element,
    ))
}

/// The first statement starting on `line` of source file `file`.
pub(crate) fn statement_on_line(image: &ProgramImage, file: u32, line: u32) -> Option<Statement> {
    let (pou, instruction) = image
        .pous
        .iter()
        .enumerate()
        .flat_map(|(pou, code)| code.lines.iter().map(move |entry| (pou, entry)))
        .filter(|(_, entry)| entry.file == file && entry.line == line)
        .map(|(pou, entry)| (pou as u32, entry.index))
        .min()?;
    Some(Statement {
        pou,
        instruction,
        pou_name: image.pous[pou as usize].name.clone(),
        file: image.sources[file as usize].clone(),
        line,
    })
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, clippy::expect_used)] // A panic is a failed test.

    use super::*;

    #[test]
    fn a_network_or_element_of_a_ladder_body_names_its_statement_and_prints_back() {
        let project = project_model::load_project(&assets::example_project_dir())
            .unwrap()
            .project;
        let image = compiler::compile_project(&project).unwrap();
        let bodies = GraphicalBodies::of_project(&project);
        let network = bodies
            .statement_at(&image, "Interlock.pou.toml:Interlock:2")
            .unwrap()
            .unwrap();
        assert_eq!(network.pou_name, "Interlock");
        let place = bodies.place_of(&network).unwrap();
        assert!(
            place.starts_with("application/Interlock.pou.toml:Interlock:2:"),
            "{place}"
        );
        // The element printed is a place of its own that names the same statement.
        let element = bodies.statement_at(&image, &place).unwrap().unwrap();
        assert_eq!(element, network);
        let error = bodies
            .statement_at(&image, "Interlock.pou.toml:Interlock:99")
            .unwrap()
            .unwrap_err();
        assert!(error.to_string().contains("Interlock:99"), "{error}");
        // Other forms are left to `FILE:LINE`.
        assert!(bodies.statement_at(&image, "Main.st:3").is_none());
        assert!(bodies.statement_at(&image, "Nope.pou.toml:X:1").is_none());
    }
}
