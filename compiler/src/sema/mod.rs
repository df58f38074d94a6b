//! Semantic checks over a whole project: name resolution of every identifier in every ST body,
//! of every type in every declaration, and of the programs the tasks call.
//!
//! The type checker proper builds on the same scopes; this first layer already finds
//! misspelt variables, types and programs, with a suggestion where one is close.

mod scope;
mod stdlib;

use std::collections::HashSet;
use std::path::PathBuf;

use project_model::{DataType, Object, PouKind, Project, TypeDefinition, Variable};

use crate::diagnostic::{Code, Diagnostic};
use crate::syntax::{SyntaxKind, SyntaxNode, parse_statements, parse_type};
use scope::{Globals, Scope};

pub use stdlib::{is_built_in_type, is_function, is_function_block};

/// A finding about a project: where it is and what it is.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ProjectDiagnostic {
    /// The file, relative to the project folder.
    pub file: PathBuf,
    /// For a finding in a declaration stored as data (a variable's type in a `.pou.toml`), the
    /// declared name; `None` when `diagnostic.range` is a range of the file's text.
    pub declaration: Option<String>,
    /// The finding.
    pub diagnostic: Diagnostic,
}

/// Checks every ST body and declaration of `project`.
pub fn check_project(project: &Project) -> Vec<ProjectDiagnostic> {
    let globals = Globals::new(project);
    let mut found = Vec::new();
    for body in project_model::st_body_files(project) {
        let parse = parse_statements(body.text);
        for error in parse.errors() {
            found.push(ProjectDiagnostic {
                file: body.file.clone(),
                declaration: None,
                diagnostic: error.clone(),
            });
        }
        let scope = Scope::for_body(&globals, body.pou, &body.target, &parse.syntax());
        for diagnostic in resolve_names(&parse.syntax(), &scope) {
            found.push(ProjectDiagnostic {
                file: body.file.clone(),
                declaration: None,
                diagnostic,
            });
        }
    }
    for (file, object) in project_model::object_files(project) {
        let mut report = |name: &str, diagnostic: Diagnostic| {
            found.push(ProjectDiagnostic {
                file: file.clone(),
                declaration: Some(name.to_owned()),
                diagnostic,
            });
        };
        match object {
            Object::Pou(pou) => {
                check_variables(&globals, &pou.variables, &mut report);
                if let Some(ty) = &pou.return_type {
                    check_type(&globals, &pou.name, ty, &mut report);
                }
                for base in pou.extends.iter().chain(&pou.implements) {
                    if !globals.is_pou(base) {
                        report(
                            &pou.name,
                            unknown(
                                Code::UnknownType,
                                "function block or interface",
                                base,
                                &globals,
                            ),
                        );
                    }
                }
                for method in &pou.methods {
                    check_variables(&globals, &method.variables, &mut report);
                    if let Some(ty) = &method.return_type {
                        check_type(&globals, &method.name, ty, &mut report);
                    }
                }
                for property in &pou.properties {
                    check_type(&globals, &property.name, &property.ty, &mut report);
                    for accessor in property.get.iter().chain(&property.set) {
                        check_variables(&globals, &accessor.variables, &mut report);
                    }
                }
            }
            Object::Gvl(gvl) => check_variables(&globals, &gvl.variables, &mut report),
            Object::DataType(data_type) => check_data_type(&globals, data_type, &mut report),
            Object::CamTable(_) | Object::Trace(_) | Object::WatchList(_) => {}
        }
    }
    for task in &project.tasks {
        for program in &task.programs {
            let is_program = project.application.object(program).is_some_and(
                |object| matches!(object, Object::Pou(pou) if pou.kind == PouKind::Program),
            );
            if !is_program {
                let message = format!(
                    "task '{}' calls '{program}', which is not a PROGRAM of the project",
                    task.name
                );
                found.push(ProjectDiagnostic {
                    file: PathBuf::from(project_model::MANIFEST_FILE_NAME),
                    declaration: Some(task.name.clone()),
                    diagnostic: Diagnostic::new(Code::UnknownProgram, 0..0, message),
                });
            }
        }
    }
    found
}

/// Reports every name in `root` that is neither declared in `scope` nor known globally.
fn resolve_names(root: &SyntaxNode, scope: &Scope<'_>) -> Vec<Diagnostic> {
    let mut found = Vec::new();
    found.extend(resolve_members(root, scope));
    for node in root
        .descendants()
        .filter(|node| node.kind() == SyntaxKind::NAME_EXPR)
    {
        // The arguments of an SFC action association are qualifiers and times, not variables.
        if node.ancestors().any(|a| a.kind() == SyntaxKind::STEP_DECL)
            && node.ancestors().any(|a| a.kind() == SyntaxKind::ARG_LIST)
        {
            continue;
        }
        let mut tokens = node
            .children_with_tokens()
            .filter_map(|element| element.into_token())
            .filter(|token| !token.kind().is_trivia());
        let Some(first) = tokens.next() else { continue };
        let (token, global_only) = match first.kind() {
            SyntaxKind::IDENT => (first, false),
            // `.name` is a global even where a local hides it.
            SyntaxKind::DOT => match tokens.next() {
                Some(token) if token.kind() == SyntaxKind::IDENT => (token, true),
                _ => continue,
            },
            _ => continue,
        };
        let name = token.text();
        let known = if global_only {
            scope.globals.knows(name)
        } else {
            scope.knows(name)
        };
        if !known {
            let range = token.text_range();
            let mut diagnostic = unknown(Code::UnknownName, "name", name, scope.globals);
            if let Some(suggestion) = scope.suggest(name) {
                diagnostic.message = format!("unknown name '{name}'; did you mean '{suggestion}'?");
            }
            diagnostic.range = usize::from(range.start())..usize::from(range.end());
            found.push(diagnostic);
        }
    }
    found.sort_by_key(|diagnostic| diagnostic.range.start);
    found
}

/// Checks `Container.member` where the container is a global variable list or an enumeration,
/// whose members are known without types: `GVL_IO.xStart`, `E_State.Idle`.
fn resolve_members(root: &SyntaxNode, scope: &Scope<'_>) -> Vec<Diagnostic> {
    let mut found = Vec::new();
    for field in root
        .descendants()
        .filter(|node| node.kind() == SyntaxKind::FIELD_EXPR)
    {
        let Some(base) = field
            .children()
            .next()
            .filter(|base| base.kind() == SyntaxKind::NAME_EXPR)
        else {
            continue;
        };
        let container = base.text().to_string();
        let container = container.trim();
        if scope.is_local(container) {
            continue;
        }
        let Some(members) = scope.globals.members(container) else {
            continue;
        };
        let Some(member) = field
            .children_with_tokens()
            .filter_map(|element| element.into_token())
            .filter(|token| token.kind() == SyntaxKind::IDENT)
            .last()
        else {
            continue;
        };
        let name = member.text();
        if !members
            .iter()
            .any(|known| project_model::same_identifier(known, name))
        {
            let range = member.text_range();
            let message = match closest(name, members.iter().copied()) {
                Some(suggestion) => {
                    format!("'{container}' has no member '{name}'; did you mean '{suggestion}'?")
                }
                None => format!("'{container}' has no member '{name}'"),
            };
            let mut diagnostic = Diagnostic::new(Code::UnknownName, 0..0, message);
            diagnostic.range = usize::from(range.start())..usize::from(range.end());
            found.push(diagnostic);
        }
    }
    found
}

fn check_variables(
    globals: &Globals<'_>,
    variables: &[Variable],
    report: &mut impl FnMut(&str, Diagnostic),
) {
    for variable in variables {
        check_type(globals, &variable.name, &variable.ty, report);
    }
}

fn check_data_type(
    globals: &Globals<'_>,
    data_type: &DataType,
    report: &mut impl FnMut(&str, Diagnostic),
) {
    match &data_type.definition {
        TypeDefinition::Struct { extends, members } => {
            if let Some(base) = extends
                && !globals.is_type(base)
            {
                report(
                    &data_type.name,
                    unknown(Code::UnknownType, "type", base, globals),
                );
            }
            for member in members {
                check_type(globals, &member.name, &member.ty, report);
            }
        }
        TypeDefinition::Union { members } => {
            for member in members {
                check_type(globals, &member.name, &member.ty, report);
            }
        }
        TypeDefinition::Enum { base, .. } => {
            if let Some(base) = base {
                check_type(globals, &data_type.name, base, report);
            }
        }
        TypeDefinition::Alias { ty, .. } => check_type(globals, &data_type.name, ty, report),
    }
}

/// Parses a type written as text and reports syntax errors and unknown type names.
fn check_type(
    globals: &Globals<'_>,
    declared: &str,
    text: &str,
    report: &mut impl FnMut(&str, Diagnostic),
) {
    let parse = parse_type(text);
    if let Some(error) = parse.errors().first() {
        let message = format!(
            "{declared}: the type '{text}' is not valid: {}",
            error.message
        );
        report(
            declared,
            Diagnostic::new(error.code, error.range.clone(), message),
        );
        return;
    }
    for node in parse.syntax().descendants() {
        if !matches!(
            node.kind(),
            SyntaxKind::NAMED_TYPE | SyntaxKind::STRING_TYPE
        ) {
            continue;
        }
        let Some(name_ref) = node
            .children()
            .find(|child| child.kind() == SyntaxKind::NAME_REF)
        else {
            continue;
        };
        let name = name_ref.text().to_string();
        if !globals.is_type(name.trim()) {
            let mut diagnostic = unknown(Code::UnknownType, "type", name.trim(), globals);
            diagnostic.message = format!("{declared}: {}", diagnostic.message);
            report(declared, diagnostic);
        }
    }
}

/// "unknown type 'X'" with a suggestion from the project's names when one is close.
fn unknown(code: Code, what: &str, name: &str, globals: &Globals<'_>) -> Diagnostic {
    let message = match globals.suggest(name) {
        Some(suggestion) => format!("unknown {what} '{name}'; did you mean '{suggestion}'?"),
        None => format!("unknown {what} '{name}'"),
    };
    Diagnostic::new(code, 0..0, message)
}

/// The Levenshtein distance of two names compared without case.
fn edit_distance(a: &str, b: &str) -> usize {
    let a: Vec<char> = a.chars().flat_map(char::to_lowercase).collect();
    let b: Vec<char> = b.chars().flat_map(char::to_lowercase).collect();
    let mut previous: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.iter().enumerate() {
        let mut current = vec![i + 1];
        for (j, cb) in b.iter().enumerate() {
            let substitution = previous[j] + usize::from(ca != cb);
            current.push(substitution.min(previous[j + 1] + 1).min(current[j] + 1));
        }
        previous = current;
    }
    previous[b.len()]
}

/// The closest of `candidates` to `name`, if close enough to be a likely typo.
fn closest<'a>(name: &str, candidates: impl Iterator<Item = &'a str>) -> Option<&'a str> {
    let limit = (name.chars().count() / 3).clamp(1, 3);
    let mut seen = HashSet::new();
    candidates
        .filter(|candidate| seen.insert(candidate.to_lowercase()))
        .map(|candidate| (edit_distance(name, candidate), candidate))
        .filter(|(distance, _)| *distance <= limit)
        .min_by_key(|(distance, candidate)| (*distance, candidate.len()))
        .map(|(_, candidate)| candidate)
}

#[cfg(test)]
mod tests;
