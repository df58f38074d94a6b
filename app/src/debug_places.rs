//! Places of a program as a user writes them (`FB_Counter.st:12`, `FB_Counter:12`) and as the
//! runtime takes them (a POU index and the instruction where a statement starts), both ways,
//! through the image's line table (`docs/program-image.md` §11, `docs/debugging.md` §7).

use std::fmt;

use program_image::{PouKind, ProgramImage};

/// A statement start of a program, with where its text is.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Statement {
    /// The POU's index in the image's code section.
    pub pou: u32,
    /// The instruction where the statement starts.
    pub instruction: u32,
    /// The POU's name (`FB_Counter`, `FB_Counter.Reset`).
    pub pou_name: String,
    /// The source file as the image names it.
    pub file: String,
    /// The 1-based line of the statement in that file.
    pub line: u32,
}

impl fmt::Display for Statement {
    /// `pous/FB_Counter.st:12 (FB_Counter)`, as `rivet break` and `rivet stack` print it.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{} ({})", self.file, self.line, self.pou_name)
    }
}

/// Why a place names no statement; each says what was written and what would do.
#[derive(Debug, PartialEq, Eq, thiserror::Error)]
pub enum PlaceError {
    /// Not written as `FILE:LINE`, `POU:LINE` or `FILE:POU:NETWORK[:ELEMENT]`.
    #[error(
        "'{0}' is no place: write FILE:LINE (FB_Counter.st:12), POU:LINE (FB_Counter:12) or, in a graphical body, FILE:POU:NETWORK[:ELEMENT] (Interlock.pou.toml:Interlock:2:7)"
    )]
    Syntax(String),
    /// No source file ends so and no POU has the name.
    #[error("'{written}' names no source file and no POU of the program; its files are {known}")]
    Unknown {
        /// What was written before the line.
        written: String,
        /// The program's source files, comma-separated.
        known: String,
    },
    /// Several source files end so.
    #[error("'{written}' ends several source files ({matches}): write more of the path")]
    Ambiguous {
        /// What was written before the line.
        written: String,
        /// The files it ends, comma-separated.
        matches: String,
    },
    /// No statement of a graphical body's network or element can halt.
    #[error(
        "{0}: no statement of this network or element can halt (an operator box such as ADD has none); choose a coil, a box or an assignment"
    )]
    NoElementStatement(String),
    /// No statement starts on the line or after it.
    #[error(
        "{file}:{line}: no statement starts on this line or after it (the last statement of the file is on line {last})"
    )]
    NoStatement {
        /// The file.
        file: String,
        /// The line asked for.
        line: u32,
        /// The last line with a statement.
        last: u32,
    },
}

/// The statement a place names: on its line, or the next one after it in the same file (so a
/// line of a comment or a declaration names the statement after it).
///
/// A place is `FILE:LINE`, where FILE is a unique end of a source file's path, or
/// `POU:LINE`, a POU's name with a line of the file it is written in.
pub fn statement_at(image: &ProgramImage, place: &str) -> Result<Statement, PlaceError> {
    let syntax = || PlaceError::Syntax(place.to_owned());
    let (written, line) = place.trim().rsplit_once(':').ok_or_else(syntax)?;
    let line: u32 = line.trim().parse().map_err(|_| syntax())?;
    let written = written.trim();
    if written.is_empty() || line == 0 {
        return Err(syntax());
    }
    let (file, pou) = file_of(image, written)?;
    let mut best: Option<(u32, u32, u32)> = None;
    for (index, candidate) in image.pous.iter().enumerate() {
        if pou.is_some_and(|pou| pou != index) {
            continue;
        }
        for entry in &candidate.lines {
            if entry.file != file || entry.line < line {
                continue;
            }
            let key = (entry.line, index as u32, entry.index);
            if best.is_none_or(|best| key < best) {
                best = Some(key);
            }
        }
    }
    let file_name = image.sources[file as usize].clone();
    let Some((line, pou, instruction)) = best else {
        let last = image
            .pous
            .iter()
            .flat_map(|pou| &pou.lines)
            .filter(|entry| entry.file == file)
            .map(|entry| entry.line)
            .max()
            .unwrap_or(0);
        return Err(PlaceError::NoStatement {
            file: file_name,
            line,
            last,
        });
    };
    Ok(Statement {
        pou,
        instruction,
        pou_name: image.pous[pou as usize].name.clone(),
        file: file_name,
        line,
    })
}

/// The statement instruction `instruction` of POU `pou` belongs to: the last line-table
/// entry at or before it. `None` for a POU the image does not have or code before any entry.
pub fn statement_of(image: &ProgramImage, pou: u32, instruction: u32) -> Option<Statement> {
    let code = image.pous.get(pou as usize)?;
    let entry = code
        .lines
        .iter()
        .take_while(|entry| entry.index <= instruction)
        .last()?;
    Some(Statement {
        pou,
        instruction: entry.index,
        pou_name: code.name.clone(),
        file: image.sources.get(entry.file as usize)?.clone(),
        line: entry.line,
    })
}

/// The name of the function block or program whose instance a POU's code runs on (the part
/// before the member's name for a method or action), as `ProgramImage::instance_path` takes
/// it; `None` for a function, which runs on no instance of its own.
pub fn instance_owner(image: &ProgramImage, pou: u32) -> Option<&str> {
    let code = image.pous.get(pou as usize)?;
    match code.kind {
        PouKind::Function => None,
        PouKind::Program | PouKind::FunctionBlock => Some(&code.name),
        PouKind::Method | PouKind::Action => Some(
            code.name
                .split_once('.')
                .map_or(&*code.name, |(owner, _)| owner),
        ),
    }
}

/// The source file `written` names (a unique end of its path) or, when none does, the file of
/// the POU it names with that POU's index.
fn file_of(image: &ProgramImage, written: &str) -> Result<(u32, Option<usize>), PlaceError> {
    let normal = |path: &str| path.replace('\\', "/");
    let wanted = normal(written);
    let matches: Vec<usize> = image
        .sources
        .iter()
        .enumerate()
        .filter(|(_, source)| {
            let source = normal(source);
            source == wanted || source.ends_with(&format!("/{wanted}"))
        })
        .map(|(index, _)| index)
        .collect();
    match matches.as_slice() {
        [one] => return Ok((*one as u32, None)),
        [] => {}
        several => {
            return Err(PlaceError::Ambiguous {
                written: written.to_owned(),
                matches: several
                    .iter()
                    .map(|&index| image.sources[index].as_str())
                    .collect::<Vec<_>>()
                    .join(", "),
            });
        }
    }
    let pou = image
        .pous
        .iter()
        .position(|pou| pou.name.eq_ignore_ascii_case(written));
    match pou.and_then(|index| Some((image.pous[index].lines.first()?.file, index))) {
        Some((file, index)) => Ok((file, Some(index))),
        None => Err(PlaceError::Unknown {
            written: written.to_owned(),
            known: image.sources.join(", "),
        }),
    }
}

#[cfg(test)]
#[path = "debug_places_tests.rs"]
mod tests;
