//! The edits a typed declaration part makes: the editors parse the text (with
//! `compiler::ide::parse_declarations`) and this module decides what it changes in the model.

use crate::{Edit, GlobalVarList, Object, Pou, Variable};

/// A declaration part as typed and parsed.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TypedDeclarations {
    /// The header (`FUNCTION_BLOCK FB_Motor EXTENDS …`, `METHOD Start : BOOL`); `None` for a
    /// global variable list.
    pub header: Option<TypedHeader>,
    /// The comment lines before the header.
    pub comment: String,
    /// The variables in the order written.
    pub variables: Vec<Variable>,
}

/// The header of a typed declaration part.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TypedHeader {
    /// The name written in the header.
    pub name: String,
    /// The return type as written.
    pub return_type: Option<String>,
    /// The base function block of `EXTENDS`.
    pub extends: Option<String>,
    /// The interfaces of `IMPLEMENTS`.
    pub implements: Vec<String>,
}

/// What a typed declaration part changes.
#[derive(Clone, Debug, PartialEq)]
pub enum DeclarationsChange {
    /// Nothing: the text says what the model says.
    Unchanged,
    /// The header names another POU or method; names change in the device tree only.
    Renamed,
    /// The object changes.
    Changed {
        /// The edit that replaces the object (boxed: an edit is large beside the other cases).
        edit: Box<Edit>,
        /// The declaration text the model will render once the edit is applied.
        rendered: String,
    },
}

/// What the typed declarations of `pou` (or of its method `method`) change.
pub fn pou_declarations_change(
    pou: &Pou,
    method: Option<&str>,
    typed: TypedDeclarations,
) -> DeclarationsChange {
    let renamed = typed.header.as_ref().is_some_and(|header| {
        !header
            .name
            .eq_ignore_ascii_case(method.unwrap_or(&pou.name))
    });
    if renamed {
        return DeclarationsChange::Renamed;
    }
    let mut changed = pou.clone();
    let rendered = match method {
        Some(method) => {
            let Some(m) = changed.methods.iter_mut().find(|m| m.name == method) else {
                return DeclarationsChange::Unchanged;
            };
            m.variables = typed.variables;
            if let Some(header) = typed.header {
                m.return_type = header.return_type;
            }
            m.declaration_text()
        }
        None => {
            changed.variables = typed.variables;
            changed.comment = typed.comment;
            if let Some(header) = typed.header {
                changed.return_type = header.return_type;
                changed.extends = header.extends;
                changed.implements = header.implements;
            }
            changed.declaration_text()
        }
    };
    if changed == *pou {
        return DeclarationsChange::Unchanged;
    }
    DeclarationsChange::Changed {
        edit: Box::new(Edit::ReplaceObject(Object::Pou(changed))),
        rendered,
    }
}

/// What the typed declarations of a global variable list change (a header is ignored: a list
/// has none).
pub fn gvl_declarations_change(
    gvl: &GlobalVarList,
    typed: TypedDeclarations,
) -> DeclarationsChange {
    let changed = GlobalVarList {
        variables: typed.variables,
        comment: typed.comment,
        ..gvl.clone()
    };
    if changed == *gvl {
        return DeclarationsChange::Unchanged;
    }
    DeclarationsChange::Changed {
        rendered: changed.declaration_text(),
        edit: Box::new(Edit::ReplaceObject(Object::Gvl(changed))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Body, Method, PouKind};

    fn motor() -> Pou {
        Pou {
            name: "FB_Motor".into(),
            kind: PouKind::FunctionBlock,
            return_type: None,
            extends: None,
            implements: Vec::new(),
            comment: String::new(),
            variables: vec![Variable::new("xRun", "BOOL")],
            body: Body::st(""),
            methods: vec![Method {
                name: "Start".into(),
                return_type: None,
                access: Default::default(),
                is_abstract: false,
                comment: String::new(),
                variables: Vec::new(),
                body: Body::st(""),
            }],
            properties: Vec::new(),
            actions: Vec::new(),
            transitions: Vec::new(),
        }
    }

    fn header(name: &str) -> Option<TypedHeader> {
        Some(TypedHeader {
            name: name.into(),
            ..TypedHeader::default()
        })
    }

    #[track_caller]
    fn changed_pou(change: DeclarationsChange) -> (Pou, String) {
        match change {
            DeclarationsChange::Changed { edit, rendered } => match *edit {
                Edit::ReplaceObject(Object::Pou(pou)) => (pou, rendered),
                other => panic!("expected a replaced POU, got {other:?}"),
            },
            other => panic!("expected a changed POU, got {other:?}"),
        }
    }

    #[test]
    fn typed_variables_replace_the_pous_and_the_rendered_text_follows() {
        let typed = TypedDeclarations {
            header: header("fb_motor"),
            comment: "Drives the belt.".into(),
            variables: vec![
                Variable::new("xRun", "BOOL"),
                Variable::new("rSpeed", "REAL"),
            ],
        };
        let (pou, rendered) = changed_pou(pou_declarations_change(&motor(), None, typed));
        assert_eq!(pou.variables.len(), 2);
        assert_eq!(pou.comment, "Drives the belt.");
        assert_eq!(rendered, pou.declaration_text());
    }

    #[test]
    fn a_header_with_another_name_is_a_rename_and_changes_nothing() {
        let typed = TypedDeclarations {
            header: header("FB_Drive"),
            ..TypedDeclarations::default()
        };
        assert_eq!(
            pou_declarations_change(&motor(), None, typed),
            DeclarationsChange::Renamed
        );
    }

    #[test]
    fn a_methods_declarations_change_only_that_method() {
        let typed = TypedDeclarations {
            header: Some(TypedHeader {
                name: "Start".into(),
                return_type: Some("BOOL".into()),
                ..TypedHeader::default()
            }),
            comment: "ignored for methods".into(),
            variables: vec![Variable::new("xForce", "BOOL")],
        };
        let (pou, rendered) = changed_pou(pou_declarations_change(&motor(), Some("Start"), typed));
        assert_eq!(pou.variables, motor().variables);
        assert_eq!(pou.comment, "");
        assert_eq!(pou.methods[0].return_type.as_deref(), Some("BOOL"));
        assert_eq!(pou.methods[0].variables.len(), 1);
        assert_eq!(rendered, pou.methods[0].declaration_text());
    }

    #[test]
    fn the_same_declarations_change_nothing() {
        let typed = TypedDeclarations {
            header: header("FB_Motor"),
            comment: String::new(),
            variables: motor().variables,
        };
        assert_eq!(
            pou_declarations_change(&motor(), None, typed),
            DeclarationsChange::Unchanged
        );
    }

    #[test]
    fn a_global_variable_lists_declarations_replace_its_variables() {
        let gvl = GlobalVarList {
            name: "GVL_Io".into(),
            comment: String::new(),
            variables: Vec::new(),
        };
        let typed = TypedDeclarations {
            header: None,
            comment: String::new(),
            variables: vec![Variable::new("xDoor", "BOOL")],
        };
        match gvl_declarations_change(&gvl, typed) {
            DeclarationsChange::Changed { edit, rendered } => match *edit {
                Edit::ReplaceObject(Object::Gvl(changed)) => {
                    assert_eq!(changed.variables.len(), 1);
                    assert_eq!(rendered, changed.declaration_text());
                }
                other => panic!("expected a replaced list, got {other:?}"),
            },
            other => panic!("expected a changed list, got {other:?}"),
        }
        let same = TypedDeclarations::default();
        assert_eq!(
            gvl_declarations_change(&gvl, same),
            DeclarationsChange::Unchanged
        );
    }
}
