//! Breakpoint conditions (`docs/protocol.md` §6.2, "Conditions"): a BOOL expression the user
//! typed, checked and compiled in the scope of the breakpoint's POU into a
//! `program_image::BreakCondition` whose temporaries, constants and result live in a scratch
//! area after the POU's frame, verified as the runtime will verify it.

use std::ops::Range;
use std::path::Path;

use program_image::{
    BreakCondition, ConditionError, Elementary as IE, ImageHash, Instr, Operand, Pou as ImagePou,
};
use project_model::{PouKind, Project};

use super::CompileError;
use super::body::{BodyGen, Gen};
use super::error::CodegenError;
use super::program::BodyOrigin;
use super::program::{Build, Unit, unit_frame};
use crate::diagnostic::Diagnostic;
use crate::sema::scope::{Globals, Scope};
use crate::sema::ty::Type;
use crate::syntax::ast::{AstNode, Expr, SourceFile, Stmt};
use crate::syntax::parse_statements;
use crate::{Severity, SourceProject};

/// What the user typed is wrapped in an IF so the parser and checker see a BOOL condition.
const PREFIX: &str = "IF ";
const SUFFIX: &str = " THEN END_IF;";

/// Where the first pass puts the constants, far from any temporary, so the second pass knows
/// how many bytes the temporaries take.
const FAR_OFFSET: u32 = 1 << 24;

/// A breakpoint condition compiled for one POU of a program.
#[derive(Clone, Debug, PartialEq)]
pub struct CompiledCondition {
    /// The POU's index in the image's code section (`BREAK_SET`'s `pou`).
    pub pou: u32,
    /// The condition; [`BreakCondition::encode`] gives the bytes `BREAK_SET` carries.
    pub condition: BreakCondition,
    /// The identity of the image the condition belongs to: a client sends it only to a target
    /// running that image.
    pub image: ImageHash,
}

/// Why a condition does not compile; each says what is wrong with the expression.
#[derive(Debug, thiserror::Error)]
pub enum ConditionCompileError {
    /// The project itself does not compile.
    #[error("the project does not compile: {0}")]
    Project(CompileError),
    /// No POU of that name is compiled.
    #[error("'{0}' is no POU of the program (a method or action is named 'FB_Name.Member')")]
    UnknownPou(String),
    /// The text is empty, not one expression, or more than one.
    #[error("'{0}' is not one expression: a condition is a BOOL expression such as x > 100")]
    NotAnExpression(String),
    /// The checker's errors, with ranges in the expression's text.
    #[error("the condition has errors: {}", .0.iter().map(|d| d.message.as_str()).collect::<Vec<_>>().join("; "))]
    Diagnostics(Vec<Diagnostic>),
    /// The expression is not BOOL.
    #[error(
        "the condition '{expression}' is {found}, not BOOL: compare it, as in {expression} <> 0"
    )]
    NotBool {
        /// What was typed.
        expression: String,
        /// Its type.
        found: String,
    },
    /// The expression calls a function, function block, method or property, which could
    /// change the program.
    #[error(
        "the condition '{0}' calls a function, method or property: a condition may only read variables and use operators"
    )]
    Calls(String),
    /// The code generator cannot compile it.
    #[error("the condition cannot be compiled: {0}")]
    Codegen(CodegenError),
    /// The compiled code is refused by the image's condition verifier.
    #[error("the condition is refused: {0}")]
    Refused(ConditionError),
}

/// Compiles `expression`, a BOOL expression over what the POU named `pou` sees (its variables,
/// its instance's, the globals), into a breakpoint condition of the image `project` compiles
/// to. `pou` is the image's name of the POU: `FB_Counter`, or `FB_Counter.Reset` for a method
/// or action.
pub fn compile_condition(
    project: &Project,
    pou: &str,
    expression: &str,
) -> Result<CompiledCondition, ConditionCompileError> {
    let origin = |file: &Path| (file.to_string_lossy().into_owned(), 1);
    condition_with(project, &origin, pou, expression)
}

/// [`compile_condition`] for a project made from one source file, whose image
/// [`crate::compile_source`] gives with the same `file_name`.
pub fn compile_source_condition(
    source: &SourceProject,
    file_name: &str,
    pou: &str,
    expression: &str,
) -> Result<CompiledCondition, ConditionCompileError> {
    let origin = |file: &Path| {
        (
            file_name.to_owned(),
            source.body_first_line(file).unwrap_or(1),
        )
    };
    condition_with(&source.project, &origin, pou, expression)
}

fn condition_with(
    project: &Project,
    origin: BodyOrigin<'_>,
    pou: &str,
    expression: &str,
) -> Result<CompiledCondition, ConditionCompileError> {
    let mut job = ConditionJob {
        pou: pou.to_owned(),
        expression: expression.to_owned(),
        outcome: None,
    };
    let image = super::compile_with(project, origin, Some(&mut job))
        .map_err(ConditionCompileError::Project)?;
    let (index, condition) = job
        .outcome
        .unwrap_or_else(|| Err(ConditionCompileError::UnknownPou(pou.to_owned())))?;
    image
        .verify_condition(index, &condition)
        .map_err(|error| match error {
            ConditionError::Refused { .. } if condition.code.iter().any(is_call) => {
                ConditionCompileError::Calls(expression.trim().to_owned())
            }
            error => ConditionCompileError::Refused(error),
        })?;
    Ok(CompiledCondition {
        pou: index,
        condition,
        image: image.identity(),
    })
}

/// A condition to compile while an image is built, and what came of it.
pub(crate) struct ConditionJob {
    pou: String,
    expression: String,
    outcome: Option<Result<(u32, BreakCondition), ConditionCompileError>>,
}

/// The constants of a condition, which live in its scratch area rather than in the image's
/// pool: from frame offset `base` on, filled by the condition's `init`.
#[derive(Debug)]
pub(crate) struct ScratchConstants {
    base: u32,
    bytes: Vec<u8>,
}

impl ScratchConstants {
    /// A frame operand holding `bytes`, each constant aligned to 8 bytes.
    pub(crate) fn add(&mut self, bytes: &[u8]) -> Operand {
        let at = self.bytes.len().next_multiple_of(8);
        self.bytes.resize(at, 0);
        self.bytes.extend_from_slice(bytes);
        Operand::Frame(self.base + at as u32)
    }
}

impl ConditionJob {
    /// Compiles the condition with the build's layouts and constants, once every unit is
    /// compiled (`pous`, index for index with `units`), and keeps the outcome. The build is
    /// left as it was found: no constant and no type is added to the image.
    pub(crate) fn run<'g, 'p>(
        &mut self,
        build: &mut Build<'g, 'p>,
        globals: &'g Globals<'p>,
        units: &[Unit<'p>],
        pous: &[ImagePou],
    ) {
        let types_before = build.layouts.types.len();
        let outcome = self.compile(build, globals, units, pous);
        build.scratch_constants = None;
        build.layouts.types.truncate(types_before);
        self.outcome = Some(outcome);
    }

    fn compile<'g, 'p>(
        &self,
        build: &mut Build<'g, 'p>,
        globals: &'g Globals<'p>,
        units: &[Unit<'p>],
        pous: &[ImagePou],
    ) -> Result<(u32, BreakCondition), ConditionCompileError> {
        let expression = self.expression.trim();
        let index = units
            .iter()
            .position(|unit| unit.image_name().eq_ignore_ascii_case(self.pou.trim()))
            .ok_or_else(|| ConditionCompileError::UnknownPou(self.pou.clone()))?;
        let unit = &units[index];
        let scratch_start = pous.get(index).map_or(0, |pou| pou.frame_size);
        let text = format!("{PREFIX}{expression}{SUFFIX}");
        let condition = condition_of(&text, expression)?;
        let root = condition
            .syntax()
            .ancestors()
            .last()
            .unwrap_or_else(|| condition.syntax().clone());
        let scope = Scope::for_body(globals, unit.pou, &unit.target, &root);
        let (types, diagnostics) = crate::sema::expression_check(&scope, &root);
        let ty = types
            .get(condition.syntax())
            .cloned()
            .unwrap_or(Type::Error);
        if ty != Type::Error && ty != Type::BOOL {
            return Err(ConditionCompileError::NotBool {
                expression: expression.to_owned(),
                found: ty.to_string(),
            });
        }
        let errors: Vec<Diagnostic> = diagnostics
            .into_iter()
            .filter(|d| d.severity == Severity::Error)
            .map(|d| Diagnostic {
                range: in_expression(&d.range, expression.len()),
                ..d
            })
            .collect();
        if !errors.is_empty() || ty == Type::Error {
            return Err(ConditionCompileError::Diagnostics(errors));
        }
        let codegen = ConditionJob::codegen;
        // The first pass learns how many bytes the temporaries take; the second puts the
        // constants right after them. Generation is deterministic, so both agree.
        let first = codegen(
            build,
            globals,
            unit,
            &text,
            &condition,
            scratch_start,
            FAR_OFFSET,
        )
        .map_err(ConditionCompileError::Codegen)?;
        let base = first.temporaries_end.next_multiple_of(8);
        let second = codegen(build, globals, unit, &text, &condition, scratch_start, base)
            .map_err(ConditionCompileError::Codegen)?;
        // The temporaries need no initial value, but the constants after them do: `init`
        // reaches to their end.
        let mut init = vec![0; (base - scratch_start) as usize];
        init.extend_from_slice(&second.constants);
        let scratch_bytes = init.len() as u32;
        Ok((
            index as u32,
            BreakCondition {
                scratch_bytes: scratch_bytes.max(second.temporaries_end - scratch_start),
                init,
                code: second.code,
                result: second.result,
            },
        ))
    }

    /// Generates the condition's code with its temporaries from `scratch_start` on and its
    /// new constants from `constants_at` on.
    #[allow(clippy::too_many_arguments)]
    fn codegen<'g, 'p>(
        build: &mut Build<'g, 'p>,
        globals: &'g Globals<'p>,
        unit: &Unit<'p>,
        text: &str,
        condition: &Expr,
        scratch_start: u32,
        constants_at: u32,
    ) -> Gen<Generated> {
        let pou = unit.pou;
        let root = condition
            .syntax()
            .ancestors()
            .last()
            .unwrap_or_else(|| condition.syntax().clone());
        let scope = Scope::for_body(globals, pou, &unit.target, &root);
        let (types, _) = crate::sema::expression_check(&scope, &root);
        let instance = match pou.kind {
            PouKind::Program | PouKind::FunctionBlock => Some(build.layouts.instance(pou)?),
            _ => None,
        };
        let frame = unit_frame(build, unit)?;
        build.scratch_constants = Some(ScratchConstants {
            base: constants_at,
            bytes: Vec::new(),
        });
        let mut generator = BodyGen::new(build, scope, pou, types, instance, frame, 0, text, 0);
        generator.start_temporaries_at(scratch_start.next_multiple_of(8));
        let value = generator.expr_as(condition, &Type::BOOL)?;
        let result = generator.temp(1);
        generator.emit(Instr::Move {
            ty: IE::Bool,
            dst: result,
            src: value,
        });
        let Operand::Frame(result) = result else {
            return Err("a condition's result is not in its frame".into());
        };
        let code = std::mem::take(&mut generator.code);
        let temporaries_end = generator.frame_max;
        let constants = build
            .scratch_constants
            .take()
            .map(|scratch| scratch.bytes)
            .unwrap_or_default();
        Ok(Generated {
            code,
            result,
            temporaries_end,
            constants,
        })
    }
}

/// One pass of generation.
struct Generated {
    code: Vec<Instr>,
    result: u32,
    temporaries_end: u32,
    constants: Vec<u8>,
}

/// The condition of the one IF that `text` (the expression in [`PREFIX`] and [`SUFFIX`]) is,
/// when the expression is exactly one expression.
fn condition_of(text: &str, expression: &str) -> Result<Expr, ConditionCompileError> {
    let not_one = || ConditionCompileError::NotAnExpression(expression.to_owned());
    if expression.is_empty() {
        return Err(not_one());
    }
    let parse = parse_statements(text);
    if !parse.errors().is_empty() {
        let errors = parse
            .errors()
            .iter()
            .map(|d| Diagnostic {
                range: in_expression(&d.range, expression.len()),
                ..d.clone()
            })
            .collect();
        return Err(ConditionCompileError::Diagnostics(errors));
    }
    let mut statements = SourceFile::cast(parse.syntax())
        .and_then(|file| file.statement_list())
        .map(|list| list.statements().collect::<Vec<_>>())
        .unwrap_or_default()
        .into_iter();
    let (Some(Stmt::IfStmt(statement)), None) = (statements.next(), statements.next()) else {
        return Err(not_one());
    };
    let condition = statement.condition().ok_or_else(not_one)?;
    // Text such as `a THEN x := 1; END_IF; IF b` parses, but is no expression.
    let range = condition.syntax().text_range();
    let whole = usize::from(range.start()) == PREFIX.len()
        && usize::from(range.end()) == PREFIX.len() + expression.len();
    let empty_body = statement
        .then_branch()
        .is_none_or(|body| body.statements().next().is_none());
    if !whole
        || !empty_body
        || statement.elsif_branches().next().is_some()
        || statement.else_branch().is_some()
    {
        return Err(not_one());
    }
    Ok(condition)
}

/// A range of the wrapped text as a range of the expression, clamped to it.
fn in_expression(range: &Range<usize>, length: usize) -> Range<usize> {
    let start = range.start.saturating_sub(PREFIX.len()).min(length);
    let end = range.end.saturating_sub(PREFIX.len()).clamp(start, length);
    start..end
}

/// Whether `instr` calls code, which the condition verifier refuses.
fn is_call(instr: &Instr) -> bool {
    matches!(
        instr,
        Instr::CallFunction { .. }
            | Instr::CallBlock { .. }
            | Instr::CallStdBlock { .. }
            | Instr::CallVirtual { .. }
            | Instr::Native { .. }
    )
}

#[cfg(test)]
#[path = "condition_tests.rs"]
mod tests;
