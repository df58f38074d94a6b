//! The IEC 61131-3 front end and code generator of Rivet.
//!
//! It owns the resilient Structured Text parser (a lossless tree plus errors, never a failure),
//! name resolution, type checking, diagnostics with stable codes, the lowering of graphical
//! networks to the same tree, code generation into a `program_image`, and the `ide` facade that
//! the editors use.
//! It reads the project model and never changes it.
//!
//! Today it holds the lexer and the resilient parser ([`syntax::parse`]), the project checker
//! ([`sema::check_project`]: names, types, calls, declarations, warnings), one source file as a
//! project ([`source_project`]), the diagnostic codes ([`Code`]), the syntax-level IDE facade
//! ([`ide`]), literal values ([`literal`]), the elementary types with their implicit
//! conversions ([`elementary`]) and the lowering of LD and FBD bodies into Structured Text
//! ([`lower`]).

pub mod codegen;
mod declaration_parts;
pub mod diagnostic;
pub mod elementary;
pub mod ide;
pub mod library;
pub mod literal;
pub mod lower;
pub mod origin;
pub mod sema;
pub mod sfc_chart;
pub mod source_project;
pub mod syntax;

pub use codegen::{
    CompileError, CompiledCondition, ConditionCompileError, compile_condition, compile_project,
    compile_source, compile_source_condition,
};
pub use diagnostic::{Code, Diagnostic, Severity};
pub use source_project::SourceProject;
