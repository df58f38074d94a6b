//! Names with `__`: IEC 61131-3 does not allow two underscores in a row in an identifier, and
//! Rivet keeps them for the names it generates (the hidden variables of LD and FBD bodies), so
//! a user's name can never clash with a generated one.

use project_model::{Object, Project, TypeDefinition};

use super::ProjectDiagnostic;
use crate::diagnostic::{Code, Diagnostic};

/// Every declared name of `project` (objects, variables, members, methods, properties,
/// actions, enumeration values) that contains `__`.
pub(super) fn reserved_names(project: &Project) -> Vec<ProjectDiagnostic> {
    let mut found = Vec::new();
    for (file, object) in project_model::object_files(project) {
        let mut names: Vec<(&str, &str)> = vec![(object.name(), "object")];
        match object {
            Object::Pou(pou) => {
                names.extend(pou.variables.iter().map(|v| (v.name.as_str(), "variable")));
                for method in &pou.methods {
                    names.push((&method.name, "method"));
                    names.extend(
                        method
                            .variables
                            .iter()
                            .map(|v| (v.name.as_str(), "variable")),
                    );
                }
                for property in &pou.properties {
                    names.push((&property.name, "property"));
                    for accessor in property.get.iter().chain(&property.set) {
                        names.extend(
                            accessor
                                .variables
                                .iter()
                                .map(|v| (v.name.as_str(), "variable")),
                        );
                    }
                }
                names.extend(pou.actions.iter().map(|a| (a.name.as_str(), "action")));
            }
            Object::Gvl(gvl) => {
                names.extend(gvl.variables.iter().map(|v| (v.name.as_str(), "variable")));
            }
            Object::DataType(data_type) => match &data_type.definition {
                TypeDefinition::Struct { members, .. } | TypeDefinition::Union { members } => {
                    names.extend(members.iter().map(|m| (m.name.as_str(), "member")));
                }
                TypeDefinition::Enum { values, .. } => {
                    names.extend(
                        values
                            .iter()
                            .map(|v| (v.name.as_str(), "enumeration value")),
                    );
                }
                TypeDefinition::Alias { .. } => {}
            },
            Object::CamTable(_) | Object::Trace(_) | Object::WatchList(_) => {}
        }
        for (name, what) in names {
            if name.contains("__") {
                found.push(ProjectDiagnostic {
                    file: file.clone(),
                    declaration: Some(name.to_owned()),
                    element: None,
                    diagnostic: Diagnostic::new(
                        Code::ReservedName,
                        0..0,
                        format!(
                            "the {what} name '{name}' contains '__', which IEC 61131-3 does not allow in names and Rivet keeps for the names it generates"
                        ),
                    ),
                });
            }
        }
    }
    found
}

/// Every name with `__` written in an ST body of `project` (before lowering, so the generated
/// names of LD and FBD bodies are not seen): an ST body cannot reach a hidden variable.
pub(super) fn reserved_references(project: &Project) -> Vec<ProjectDiagnostic> {
    let mut found = Vec::new();
    for body in project_model::st_body_files(project) {
        // Most bodies have no `__` at all, and need no second look.
        if !body.text.contains("__") {
            continue;
        }
        let (tokens, _) = crate::syntax::tokenize(body.text);
        let mut start = 0;
        for token in tokens {
            let end = start + token.len as usize;
            let text = body.text.get(start..end).unwrap_or_default();
            // CODESYS's own `__ISVALIDREF`, `__XWORD`… are standard names, not the user's.
            let standard =
                super::stdlib::is_function(text) || super::stdlib::is_built_in_type(text);
            if token.kind == crate::syntax::SyntaxKind::IDENT && text.contains("__") && !standard {
                found.push(ProjectDiagnostic {
                    file: body.file.clone(),
                    declaration: None,
                    element: None,
                    diagnostic: Diagnostic::new(
                        Code::ReservedName,
                        start..end,
                        format!(
                            "'{text}' contains '__', which IEC 61131-3 does not allow in names and Rivet keeps for the names it generates"
                        ),
                    ),
                });
            }
            start = end;
        }
    }
    found
}
