//! A breakpoint of the studio as the target takes it (`BREAK_SET`): its statement found
//! through the image the studio logged in with, its instance and task filters, its hit rule
//! and its condition compiled against the very project that image was built from.

use online::{ALL_TASKS, BreakpointSpec, HitRule};
use program_image::{ImageHash, ProgramImage};

use super::breakpoint::{Breakpoint, BreakpointPlace, HitMode};
use super::breakpoints::statement_of_place;
use super::condition_cache::{ConditionKey, ConditionOutcome};
use crate::debug_bodies::GraphicalBodies;
use crate::debug_places::{PlaceError, Statement, instance_owner, statement_at};
use crate::studio::i18n::{DebugText, Language};

/// The pointer value of the data region's first byte (`docs/program-image.md` §5.2).
const DATA_POINTER: u64 = 1 << 56;

/// Why a breakpoint is not sent; each names the breakpoint's place.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum BreakpointError {
    /// No statement starts on its line or after it, or the file is not in the program.
    Place {
        /// The breakpoint's place.
        place: BreakpointPlace,
        /// The lookup's reason.
        reason: String,
    },
    /// Its condition does not compile.
    Condition {
        /// The breakpoint's place.
        place: BreakpointPlace,
        /// The condition as the user wrote it.
        condition: String,
        /// The compiler's message.
        reason: String,
    },
    /// Its instance filter names no instance the statement's code runs on.
    Instance {
        /// The breakpoint's place.
        place: BreakpointPlace,
        /// The instance path as the user wrote it.
        instance: String,
    },
    /// Its condition compiled for another program than the one logged in with.
    OtherBuild {
        /// The breakpoint's place.
        place: BreakpointPlace,
    },
    /// Its task filter names no task of the program.
    Task {
        /// The breakpoint's place.
        place: BreakpointPlace,
        /// The task as the user wrote it.
        task: String,
    },
}

impl BreakpointError {
    /// The error as the user reads it, in `language`.
    pub fn text(&self, language: Language) -> String {
        match self {
            Self::Place { place, reason } => DebugText::BreakpointNotSet
                .fill(language, &[("place", &place.label()), ("reason", reason)]),
            Self::Condition {
                place,
                condition,
                reason,
            } => DebugText::BreakpointConditionError.fill(
                language,
                &[
                    ("place", &place.label()),
                    ("condition", condition),
                    ("reason", reason),
                ],
            ),
            Self::Instance { place, instance } => DebugText::BreakpointNoInstance.fill(
                language,
                &[("place", &place.label()), ("instance", instance)],
            ),
            Self::OtherBuild { place } => {
                DebugText::BreakpointOtherBuild.fill(language, &[("place", &place.label())])
            }
            Self::Task { place, task } => DebugText::BreakpointNoTask
                .fill(language, &[("place", &place.label()), ("task", task)]),
        }
    }
}

/// The statement a breakpoint's place names in `image`: the one starting on its line, or the
/// next one of the same file; for a graphical place, the first statement of its network or
/// element in `bodies` (the project's lowered graphical bodies, made once by the caller for
/// all its breakpoints). The one place where a breakpoint's place becomes the target's
/// `(pou, instruction)`, for setting it and for running to the cursor.
pub fn breakpoint_statement(
    image: &ProgramImage,
    bodies: &GraphicalBodies,
    place: &BreakpointPlace,
) -> Result<Statement, PlaceError> {
    if place.graphical.is_some() {
        return statement_of_place(place, image, bodies)
            .ok_or_else(|| PlaceError::NoElementStatement(place.label()));
    }
    statement_at(image, &place.label())
}

/// What the condition of `breakpoint` depends on, for the cache, in `image` whose identity
/// is `identity`; `None` without a condition or when its place names no statement of `image`
/// (which [`breakpoint_spec_with`] reports).
pub fn condition_key(
    image: &ProgramImage,
    identity: ImageHash,
    bodies: &GraphicalBodies,
    breakpoint: &Breakpoint,
) -> Option<ConditionKey> {
    let condition = breakpoint.condition.trim();
    if condition.is_empty() {
        return None;
    }
    let statement = breakpoint_statement(image, bodies, &breakpoint.place).ok()?;
    Some(ConditionKey {
        image: identity,
        pou: statement.pou_name,
        condition: condition.to_owned(),
    })
}

/// The breakpoint as `BREAK_SET` takes it, for `image` whose identity is `identity` (its
/// encoding's hash, which the caller knows) and whose lowered graphical bodies are `bodies`,
/// with its condition's outcome from `condition` (the studio's [`super::ConditionCache`],
/// compiled against the project `image` was built from), given the key [`condition_key`]
/// names.
pub fn breakpoint_spec_with(
    image: &ProgramImage,
    identity: ImageHash,
    bodies: &GraphicalBodies,
    breakpoint: &Breakpoint,
    condition: &mut dyn FnMut(&ConditionKey) -> ConditionOutcome,
) -> Result<BreakpointSpec, BreakpointError> {
    let compile = condition;
    let place = &breakpoint.place;
    let statement =
        breakpoint_statement(image, bodies, place).map_err(|error| BreakpointError::Place {
            place: place.clone(),
            reason: error.to_string(),
        })?;
    let instance = match breakpoint.instance.trim() {
        "" => 0,
        path => {
            instance_pointer(image, &statement, path).ok_or_else(|| BreakpointError::Instance {
                place: place.clone(),
                instance: path.to_owned(),
            })?
        }
    };
    let task = match breakpoint.task.trim() {
        "" => ALL_TASKS,
        name => image
            .tasks
            .iter()
            .position(|task| task.name.eq_ignore_ascii_case(name))
            .and_then(|index| u8::try_from(index).ok())
            .ok_or_else(|| BreakpointError::Task {
                place: place.clone(),
                task: name.to_owned(),
            })?,
    };
    let condition = match breakpoint.condition.trim() {
        "" => Vec::new(),
        expression => {
            let failed = |reason: String| BreakpointError::Condition {
                place: place.clone(),
                condition: expression.to_owned(),
                reason,
            };
            let key = ConditionKey {
                image: identity,
                pou: statement.pou_name.clone(),
                condition: expression.to_owned(),
            };
            let compiled = compile(&key).map_err(|error| failed(error.to_string()))?;
            if compiled.pou != statement.pou || compiled.image != key.image {
                return Err(BreakpointError::OtherBuild {
                    place: place.clone(),
                });
            }
            compiled.bytes
        }
    };
    Ok(BreakpointSpec {
        pou: statement.pou,
        instruction: statement.instruction,
        instance,
        task,
        hit: hit_rule(breakpoint.hit_mode, breakpoint.hit_target),
        condition,
    })
}

/// The pointer value of the instance at `path`, if it is one the code of the statement's POU
/// runs on.
fn instance_pointer(image: &ProgramImage, statement: &Statement, path: &str) -> Option<u64> {
    let owner = instance_owner(image, statement.pou)?;
    let place = runtime::value::resolve(image, path).ok()?;
    if place.region != program_image::Region::Data || place.bit.is_some() {
        return None;
    }
    let pointer = DATA_POINTER | place.offset;
    image.instance_path(pointer, Some(owner)).map(|_| pointer)
}

/// The protocol's hit rule of a hit mode and its target.
fn hit_rule(mode: HitMode, target: u32) -> HitRule {
    let mode = match mode {
        HitMode::Always => return HitRule::ALWAYS,
        HitMode::Equal => online::HitMode::Equal,
        HitMode::MultipleOf => online::HitMode::Multiple,
        HitMode::AtLeast => online::HitMode::AtLeast,
    };
    HitRule {
        mode,
        target: target.max(1),
    }
}

#[cfg(test)]
#[path = "target_breakpoint_tests.rs"]
mod tests;
