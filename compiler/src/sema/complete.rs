//! Completion candidates at a position of a body: the members of what stands before a `.`, or
//! every name visible there.

use project_model::{Object, StBody, TypeDefinition};

use super::body::{BodyChecker, Usage};
use super::definition::DefinitionKind;
use super::scope::{GlobalSymbol, Globals, LocalSymbol, Scope, inheritance_chain};
use super::signatures;
use super::stdlib;
use super::ty::Type;
use super::types::Shape;
use crate::syntax::ast::{AstNode, Expr};
use crate::syntax::parse_statements;

/// One completion candidate.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Completion {
    /// The text to insert.
    pub label: String,
    /// What it is.
    pub kind: DefinitionKind,
    /// One line saying what it is.
    pub detail: String,
}

/// Keywords offered at the start of a statement.
const STATEMENT_KEYWORDS: &[&str] = &[
    "IF",
    "THEN",
    "ELSIF",
    "ELSE",
    "END_IF",
    "CASE",
    "OF",
    "END_CASE",
    "FOR",
    "TO",
    "BY",
    "DO",
    "END_FOR",
    "WHILE",
    "END_WHILE",
    "REPEAT",
    "UNTIL",
    "END_REPEAT",
    "EXIT",
    "CONTINUE",
    "RETURN",
    "AND",
    "OR",
    "XOR",
    "NOT",
    "MOD",
    "TRUE",
    "FALSE",
];

/// The candidates at byte `offset` of `body`, filtered by the word being typed there.
pub fn completions(
    project: &project_model::Project,
    body: &StBody<'_>,
    offset: usize,
) -> Vec<Completion> {
    let text = body.text;
    let offset = offset.min(text.len());
    if !text.is_char_boundary(offset) {
        return Vec::new();
    }
    let before = &text[..offset];
    let word_start = before
        .char_indices()
        .rev()
        .take_while(|(_, c)| c.is_alphanumeric() || *c == '_')
        .last()
        .map_or(offset, |(at, _)| at);
    let prefix = before[word_start..].to_lowercase();
    let globals = Globals::new(project);
    let full = parse_statements(text);
    let scope = Scope::for_body(&globals, body.pou, &body.target, &full.syntax());
    let mut found = if before[..word_start].trim_end().ends_with('.') {
        let dot = before[..word_start].trim_end().len() - 1;
        members_before(&globals, &scope, &text[..dot])
    } else {
        visible_names(&scope, project)
    };
    found.retain(|candidate| candidate.label.to_lowercase().starts_with(&prefix));
    found.sort_by_key(|candidate| candidate.label.to_lowercase());
    found.dedup_by(|a, b| a.label.eq_ignore_ascii_case(&b.label));
    found
}

/// The members of the expression that ends `text`.
fn members_before(globals: &Globals<'_>, scope: &Scope<'_, '_>, text: &str) -> Vec<Completion> {
    // The statement being typed is incomplete; closing it lets its last expression parse.
    let probe = format!("{text};");
    let parse = parse_statements(&probe);
    let end = text.len();
    let expression = parse
        .syntax()
        .descendants()
        .filter_map(Expr::cast)
        .filter(|expression| {
            usize::from(expression.syntax().text_range().end()) == end
                && matches!(
                    expression,
                    Expr::NameExpr(_)
                        | Expr::FieldExpr(_)
                        | Expr::IndexExpr(_)
                        | Expr::DerefExpr(_)
                        | Expr::CallExpr(_)
                        | Expr::ParenExpr(_)
                )
        })
        .min_by_key(|expression| expression.syntax().text_range().start());
    let Some(expression) = expression else {
        return Vec::new();
    };
    let mut usage = Usage::new();
    let mut checker = BodyChecker::new(scope, &mut usage);
    let ty = checker.type_of(&expression);
    members_of_type(globals, &ty)
}

fn members_of_type(globals: &Globals<'_>, ty: &Type) -> Vec<Completion> {
    let completion = |label: &str, kind, detail: String| Completion {
        label: label.to_owned(),
        kind,
        detail,
    };
    match ty {
        Type::Namespace(name) => match globals.lookup(name) {
            Some(GlobalSymbol::Gvl(gvl)) => gvl
                .variables
                .iter()
                .map(|v| {
                    completion(
                        &v.name,
                        DefinitionKind::Variable,
                        format!("{} : {}", v.name, v.ty),
                    )
                })
                .collect(),
            _ => Vec::new(),
        },
        Type::EnumNamespace(name) => globals
            .member_names(name)
            .into_iter()
            .map(|value| completion(value, DefinitionKind::EnumValue, format!("{name}.{value}")))
            .collect(),
        Type::SfcAction => vec![
            completion(
                "x",
                DefinitionKind::Member,
                "x : BOOL (the action runs this cycle)".to_owned(),
            ),
            completion(
                "_x",
                DefinitionKind::Member,
                "_x : BOOL (the action is active, its Q)".to_owned(),
            ),
        ],
        Type::Step => vec![
            completion(
                "X",
                DefinitionKind::Member,
                "X : BOOL (the step is active)".to_owned(),
            ),
            completion(
                "_x",
                DefinitionKind::Member,
                "_x : BOOL (the step is active in the next cycle)".to_owned(),
            ),
            completion(
                "T",
                DefinitionKind::Member,
                "T : TIME (time since activation)".to_owned(),
            ),
        ],
        Type::Named(name) => match globals.shape(name) {
            Some(Shape::Struct(data_type)) => match &data_type.definition {
                TypeDefinition::Struct { members, .. } | TypeDefinition::Union { members } => {
                    members
                        .iter()
                        .map(|m| {
                            completion(
                                &m.name,
                                DefinitionKind::Member,
                                format!("{} : {}", m.name, m.ty),
                            )
                        })
                        .collect()
                }
                _ => Vec::new(),
            },
            Some(Shape::Pou(pou)) => {
                let mut found = Vec::new();
                for current in inheritance_chain(globals, pou) {
                    for variable in &current.variables {
                        found.push(completion(
                            &variable.name,
                            DefinitionKind::Member,
                            format!("{} : {}", variable.name, variable.ty),
                        ));
                    }
                    for method in &current.methods {
                        found.push(completion(
                            &method.name,
                            DefinitionKind::Method,
                            format!("METHOD {}", method.name),
                        ));
                    }
                    for property in &current.properties {
                        found.push(completion(
                            &property.name,
                            DefinitionKind::Property,
                            format!("PROPERTY {} : {}", property.name, property.ty),
                        ));
                    }
                }
                // From outside, only what is visible outside a function block is offered.
                if pou.kind == project_model::PouKind::FunctionBlock {
                    found.retain(|c| {
                        c.kind != DefinitionKind::Member
                            || globals
                                .member(name, &c.label)
                                .is_some_and(|m| super::scope::is_visible_outside(m.section))
                    });
                }
                found
            }
            Some(Shape::StandardFb(fb)) => fb
                .names()
                .filter_map(|member| {
                    fb.member(member).map(|(ty, _)| {
                        completion(
                            member,
                            DefinitionKind::Member,
                            format!("{name}.{member} : {ty}"),
                        )
                    })
                })
                .collect(),
            Some(Shape::Enum(_)) | None => Vec::new(),
        },
        _ => Vec::new(),
    }
}

/// Every name visible in the body, locals first, then globals, the standard library and keywords.
fn visible_names(scope: &Scope<'_, '_>, project: &project_model::Project) -> Vec<Completion> {
    let mut found: Vec<Completion> = scope
        .local_symbols()
        .into_iter()
        .map(|(name, symbol)| {
            let (kind, detail) = match symbol {
                LocalSymbol::Var(variable) => (
                    DefinitionKind::Variable,
                    format!("{} : {}", variable.name, variable.ty),
                ),
                LocalSymbol::Result(ty) => (DefinitionKind::Result, format!("{name} : {ty}")),
                LocalSymbol::Method(method) => {
                    (DefinitionKind::Method, format!("METHOD {}", method.name))
                }
                LocalSymbol::Property(property) => (
                    DefinitionKind::Property,
                    format!("PROPERTY {} : {}", property.name, property.ty),
                ),
                LocalSymbol::Action => (DefinitionKind::Action, format!("ACTION {name}")),
                LocalSymbol::Step => (DefinitionKind::Step, format!("STEP {name}")),
                LocalSymbol::SfcAction => (DefinitionKind::Step, format!("{name} : SFCActionType")),
                LocalSymbol::TransitionValue => {
                    (DefinitionKind::Step, format!("TRANSITION {name} : BOOL"))
                }
            };
            Completion {
                label: name,
                kind,
                detail,
            }
        })
        .collect();
    for object in project.application.objects() {
        let (kind, detail) = match object {
            Object::Pou(pou) => (
                DefinitionKind::Pou,
                format!("{} {}", pou.kind.keyword(), pou.name),
            ),
            Object::Gvl(gvl) => (
                DefinitionKind::GlobalVarList,
                format!("global variable list {}", gvl.name),
            ),
            Object::DataType(data_type) => {
                (DefinitionKind::DataType, format!("TYPE {}", data_type.name))
            }
            _ => continue,
        };
        found.push(Completion {
            label: object.name().to_owned(),
            kind,
            detail,
        });
        match object {
            Object::Gvl(gvl) => {
                for variable in &gvl.variables {
                    found.push(Completion {
                        label: variable.name.clone(),
                        kind: DefinitionKind::Variable,
                        detail: format!("{} : {} ({})", variable.name, variable.ty, gvl.name),
                    });
                }
            }
            Object::DataType(data_type) => {
                if let TypeDefinition::Enum { values, .. } = &data_type.definition {
                    for value in values {
                        found.push(Completion {
                            label: value.name.clone(),
                            kind: DefinitionKind::EnumValue,
                            detail: format!("{}.{}", data_type.name, value.name),
                        });
                    }
                }
            }
            _ => {}
        }
    }
    for name in stdlib::all_names() {
        let detail = if signatures::function_block(name).is_some() {
            format!("FUNCTION_BLOCK {name}")
        } else {
            format!("FUNCTION {name}")
        };
        found.push(Completion {
            label: name.to_owned(),
            kind: DefinitionKind::Standard,
            detail,
        });
    }
    for keyword in STATEMENT_KEYWORDS {
        found.push(Completion {
            label: (*keyword).to_owned(),
            kind: DefinitionKind::Standard,
            detail: "keyword".to_owned(),
        });
    }
    found
}
