//! Methods, actions, transitions and properties added to a POU: which POUs take them, which names are free,
//! and the edit that adds one.

use project_model::{
    AccessSpecifier, Edit, EditError, Method, Object, Pou, PouAction, PouKind, Project, Property,
    PropertyAccessor, TextTarget, same_identifier,
};

use super::body_language::BodyLanguage;
use super::names::identifier_problem;
use super::plan_step::Plan;
use super::refusal::Refusal;
use crate::studio::i18n::{Language, Text};
use crate::studio::tree_node::TreeNode;

/// What kind of member is added to a POU.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MemberKind {
    /// A method, with an optional return type.
    Method,
    /// An action: a body without declarations of its own.
    Action,
    /// A transition object: a BOOL body without declarations of its own, which SFC
    /// transitions name as their condition.
    Transition,
    /// A property with a type and both accessors, as CODESYS adds one.
    Property,
}

/// A member the user asked to add, with what the dialog asked about it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct NewMember {
    /// Method, action, transition or property.
    pub kind: MemberKind,
    /// The name, already checked by the dialog.
    pub name: String,
    /// The language of its body (of both accessors for a property).
    pub language: BodyLanguage,
    /// A method's return type (empty for none) or a property's type; actions have none.
    pub type_name: String,
}

impl MemberKind {
    /// Whether a POU of `kind` can have members of this kind. Programs and function blocks
    /// take all four, as in CODESYS; functions have none, and the members of an interface
    /// are prototypes without bodies, which these dialogs do not make.
    pub fn allowed_in(self, kind: PouKind) -> bool {
        matches!(kind, PouKind::Program | PouKind::FunctionBlock)
    }

    /// What the kind is called in undo labels.
    pub fn noun(self) -> Text {
        match self {
            Self::Method => Text::NounMethod,
            Self::Action => Text::NounAction,
            Self::Transition => Text::NounTransition,
            Self::Property => Text::NounProperty,
        }
    }

    /// The context menu item that opens the dialog.
    pub fn menu_text(self) -> Text {
        match self {
            Self::Method => Text::AddMethodMenu,
            Self::Action => Text::AddActionMenu,
            Self::Transition => Text::AddTransitionMenu,
            Self::Property => Text::AddPropertyMenu,
        }
    }

    /// The dialog's heading.
    pub fn heading(self) -> Text {
        match self {
            Self::Method => Text::AddMethod,
            Self::Action => Text::AddAction,
            Self::Transition => Text::AddTransition,
            Self::Property => Text::AddProperty,
        }
    }

    /// The name the dialog proposes before a number is added to make it free.
    pub fn base_name(self) -> &'static str {
        // `Method`, `Action`, `Transition` and `Property` alone are keywords of CODESYS's ST.
        match self {
            Self::Method => "NewMethod",
            Self::Action => "NewAction",
            Self::Transition => "NewTransition",
            Self::Property => "NewProperty",
        }
    }

    /// Whether the dialog asks for a type, and whether it must be given.
    pub fn type_field(self) -> TypeField {
        match self {
            Self::Method => TypeField::Optional,
            Self::Action | Self::Transition => TypeField::None,
            Self::Property => TypeField::Required,
        }
    }
}

/// Whether a member's dialog asks for a type.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TypeField {
    /// No type (actions and transitions, which are BOOL).
    None,
    /// A return type that may stay empty (methods that return nothing).
    Optional,
    /// A type that must be given (properties).
    Required,
}

/// Whether `name` is already used in `pou` by a variable, method, property, action or
/// transition. They share one namespace (the checker reports a clash), and names compare without case.
pub fn member_name_taken(pou: &Pou, name: &str) -> bool {
    pou.variables
        .iter()
        .map(|v| v.name.as_str())
        .chain(pou.methods.iter().map(|m| m.name.as_str()))
        .chain(pou.properties.iter().map(|p| p.name.as_str()))
        .chain(pou.actions.iter().map(|a| a.name.as_str()))
        .chain(pou.transitions.iter().map(|t| t.name.as_str()))
        .any(|other| same_identifier(other, name))
}

/// Why `name` cannot name a new member of `pou`, or `None` when it can.
pub fn member_name_problem(pou: &Pou, name: &str) -> Option<Refusal> {
    identifier_problem(name).or_else(|| {
        member_name_taken(pou, name).then(|| EditError::DuplicateName(name.to_owned()).into())
    })
}

/// Why `member` cannot be added to `pou` as the dialog describes it, or `None` when it can.
pub fn member_problem(pou: &Pou, member: &NewMember) -> Option<Refusal> {
    if !member.kind.allowed_in(pou.kind) {
        return Some(Refusal::NoMembers(pou.name.clone()));
    }
    member_name_problem(pou, &member.name).or_else(|| {
        (member.kind.type_field() == TypeField::Required && member.type_name.trim().is_empty())
            .then_some(Refusal::NoPropertyType)
    })
}

/// The plan that adds `member` to the POU named `pou`, as one edit of the whole POU (undone by
/// putting the POU back), and opens the POU on the new member's body.
pub fn plan_add_member(
    project: &Project,
    pou: &str,
    member: &NewMember,
    language: Language,
) -> Result<Plan, Refusal> {
    let Some(Object::Pou(original)) = project.application.object(pou) else {
        return Err(EditError::NoSuchObject(pou.to_owned()).into());
    };
    if let Some(problem) = member_problem(original, member) {
        return Err(problem);
    }
    if member.language == BodyLanguage::Sfc {
        return Err(Refusal::SfcNotHere);
    }
    let mut pou = original.clone();
    let name = member.name.clone();
    let type_name = member.type_name.trim();
    let body = member.language.empty_body();
    let shown = match member.kind {
        MemberKind::Method => {
            pou.methods.push(Method {
                name: name.clone(),
                return_type: (!type_name.is_empty()).then(|| type_name.to_owned()),
                access: AccessSpecifier::default(),
                is_abstract: false,
                comment: String::new(),
                variables: Vec::new(),
                body,
            });
            TextTarget::Method {
                pou: pou.name.clone(),
                method: name.clone(),
            }
        }
        MemberKind::Action => {
            pou.actions.push(PouAction {
                name: name.clone(),
                body,
            });
            TextTarget::Action {
                pou: pou.name.clone(),
                action: name.clone(),
            }
        }
        MemberKind::Transition => {
            pou.transitions.push(PouAction {
                name: name.clone(),
                body,
            });
            TextTarget::Transition {
                pou: pou.name.clone(),
                transition: name.clone(),
            }
        }
        MemberKind::Property => {
            let accessor = PropertyAccessor {
                variables: Vec::new(),
                body,
            };
            pou.properties.push(Property {
                name: name.clone(),
                ty: type_name.to_owned(),
                access: AccessSpecifier::default(),
                comment: String::new(),
                get: Some(accessor.clone()),
                set: Some(accessor),
            });
            TextTarget::Property {
                pou: pou.name.clone(),
                property: name.clone(),
                get: true,
            }
        }
    };
    let label = Text::UndoAddMember.fill(
        language,
        &[
            ("kind", member.kind.noun().get(language)),
            ("name", &name),
            ("pou", &pou.name),
        ],
    );
    Ok(Plan {
        label,
        open: Some(TreeNode::Object(pou.name.clone())),
        select: None,
        part: Some(shown),
        edits: vec![Edit::ReplaceObject(Object::Pou(pou))],
    })
}
