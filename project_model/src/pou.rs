//! Program organisation units: programs, function blocks, functions and interfaces.

use serde::{Deserialize, Serialize};

use crate::{CfcChart, Network, SfcChart, Variable};

/// A program organisation unit.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(deny_unknown_fields)]
pub struct Pou {
    /// The POU's name; it is the file name, not stored in the file.
    #[serde(skip)]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::ident()"))]
    pub name: String,
    /// Program, function block, function or interface.
    pub kind: PouKind,
    /// The return type of a function as written, such as `INT`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[cfg_attr(
        feature = "proptest",
        proptest(strategy = "proptest::option::of(crate::arb::ident())")
    )]
    pub return_type: Option<String>,
    /// The function block or interface this one extends.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[cfg_attr(
        feature = "proptest",
        proptest(strategy = "proptest::option::of(crate::arb::ident())")
    )]
    pub extends: Option<String>,
    /// The interfaces a function block implements.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::ident_vec()"))]
    pub implements: Vec<String>,
    /// What the POU does.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::text()"))]
    pub comment: String,
    /// The declarations, in order.
    #[serde(default, rename = "variable", skip_serializing_if = "Vec::is_empty")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::small_vec()"))]
    pub variables: Vec<Variable>,
    /// The implementation.
    pub body: Body,
    /// Methods of a function block or interface.
    #[serde(default, rename = "method", skip_serializing_if = "Vec::is_empty")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::small_vec()"))]
    pub methods: Vec<Method>,
    /// Properties of a function block or interface.
    #[serde(default, rename = "property", skip_serializing_if = "Vec::is_empty")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::small_vec()"))]
    pub properties: Vec<Property>,
    /// Actions of a program or function block (also the actions of SFC steps).
    #[serde(default, rename = "action", skip_serializing_if = "Vec::is_empty")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::small_vec()"))]
    pub actions: Vec<PouAction>,
    /// Transition objects of an SFC program or function block: conditions of any language
    /// that SFC transitions name. A body computes the BOOL by assigning the transition's name
    /// (`Ready := a AND b;`, a coil or an assignment on the name in LD or FBD); an ST body may
    /// also be the expression alone (`a AND b`).
    #[serde(default, rename = "transition", skip_serializing_if = "Vec::is_empty")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::small_vec()"))]
    pub transitions: Vec<PouAction>,
}

/// What kind of POU it is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(rename_all = "snake_case")]
pub enum PouKind {
    /// `PROGRAM`.
    Program,
    /// `FUNCTION_BLOCK`.
    FunctionBlock,
    /// `FUNCTION`.
    Function,
    /// `INTERFACE` (CODESYS): methods and properties without implementation.
    Interface,
}

impl PouKind {
    /// The IEC keyword that opens the POU, such as `FUNCTION_BLOCK`.
    pub fn keyword(self) -> &'static str {
        match self {
            Self::Program => "PROGRAM",
            Self::FunctionBlock => "FUNCTION_BLOCK",
            Self::Function => "FUNCTION",
            Self::Interface => "INTERFACE",
        }
    }
}

/// The implementation language of a body.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Language {
    /// No implementation (interfaces, abstract methods).
    None,
    /// Structured Text.
    St,
    /// Instruction List (IEC 61131-3 ed. 2; deprecated in ed. 3 but found in exported projects).
    Il,
    /// Ladder Diagram.
    Ld,
    /// Function Block Diagram.
    Fbd,
    /// Continuous Function Chart.
    Cfc,
    /// Sequential Function Chart.
    Sfc,
}

/// The implementation of a POU, method, property accessor or action.
///
/// In files, the text of an ST body lives in a `.st` file of its own beside the object's file,
/// that of an IL body in a `.il` file (see `docs/project-format.md`); graphical bodies are
/// stored inline.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(tag = "language", rename_all = "snake_case", deny_unknown_fields)]
pub enum Body {
    /// No implementation.
    None,
    /// Structured Text.
    St {
        /// The statements, exactly as written.
        #[serde(skip)]
        #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::text()"))]
        text: String,
    },
    /// Instruction List: one instruction per line (`docs/instruction-list.md`).
    Il {
        /// The instructions, exactly as written; stored in a `.il` file like ST's `.st`.
        #[serde(skip)]
        #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::text()"))]
        text: String,
    },
    /// Ladder Diagram: rungs.
    Ld {
        /// The networks in order.
        #[serde(default, rename = "network", skip_serializing_if = "Vec::is_empty")]
        #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::networks()"))]
        networks: Vec<Network>,
    },
    /// Function Block Diagram: networks.
    Fbd {
        /// The networks in order.
        #[serde(default, rename = "network", skip_serializing_if = "Vec::is_empty")]
        #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::networks()"))]
        networks: Vec<Network>,
    },
    /// Continuous Function Chart: elements placed freely, run in their execution order.
    Cfc {
        /// The chart.
        #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::cfc_chart()"))]
        chart: CfcChart,
    },
    /// Sequential Function Chart: steps and transitions from the initial step.
    Sfc {
        /// The chart.
        #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::sfc_chart()"))]
        chart: SfcChart,
    },
}

impl Body {
    /// An empty Structured Text body.
    pub fn st(text: impl Into<String>) -> Self {
        Self::St { text: text.into() }
    }

    /// The body's language.
    pub fn language(&self) -> Language {
        match self {
            Self::None => Language::None,
            Self::St { .. } => Language::St,
            Self::Il { .. } => Language::Il,
            Self::Ld { .. } => Language::Ld,
            Self::Fbd { .. } => Language::Fbd,
            Self::Cfc { .. } => Language::Cfc,
            Self::Sfc { .. } => Language::Sfc,
        }
    }

    /// The text of an ST body.
    pub fn st_text(&self) -> Option<&str> {
        match self {
            Self::St { text } => Some(text),
            _ => None,
        }
    }

    /// The text of an ST body, mutably.
    pub fn st_text_mut(&mut self) -> Option<&mut String> {
        match self {
            Self::St { text } => Some(text),
            _ => None,
        }
    }

    /// The text of a textual body (ST or IL), the one kept in a file of its own.
    pub fn text(&self) -> Option<&str> {
        match self {
            Self::St { text } | Self::Il { text } => Some(text),
            _ => None,
        }
    }

    /// The text of a textual body (ST or IL), mutably.
    pub fn text_mut(&mut self) -> Option<&mut String> {
        match self {
            Self::St { text } | Self::Il { text } => Some(text),
            _ => None,
        }
    }

    /// The file name extension of a textual body's file: `st` or `il`; `None` for the others.
    pub fn text_extension(&self) -> Option<&'static str> {
        match self {
            Self::St { .. } => Some("st"),
            Self::Il { .. } => Some("il"),
            _ => None,
        }
    }
}

/// Visibility of a method or property.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(rename_all = "snake_case")]
pub enum AccessSpecifier {
    /// Callable from anywhere.
    #[default]
    Public,
    /// Callable from the function block itself.
    Private,
    /// Callable from the function block and those extending it.
    Protected,
    /// Callable from within the same library or application.
    Internal,
}

/// A method of a function block or interface.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(deny_unknown_fields)]
pub struct Method {
    /// The method's name.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::ident()"))]
    pub name: String,
    /// The return type as written, if the method returns a value.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[cfg_attr(
        feature = "proptest",
        proptest(strategy = "proptest::option::of(crate::arb::ident())")
    )]
    pub return_type: Option<String>,
    /// Visibility.
    #[serde(default, skip_serializing_if = "crate::variable::is_default")]
    pub access: AccessSpecifier,
    /// `ABSTRACT`: no body here; extending blocks implement it.
    #[serde(default, skip_serializing_if = "crate::variable::is_false")]
    pub is_abstract: bool,
    /// What the method does.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::text()"))]
    pub comment: String,
    /// The declarations.
    #[serde(default, rename = "variable", skip_serializing_if = "Vec::is_empty")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::small_vec()"))]
    pub variables: Vec<Variable>,
    /// The implementation.
    pub body: Body,
}

/// A property of a function block or interface, with optional getter and setter.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(deny_unknown_fields)]
pub struct Property {
    /// The property's name.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::ident()"))]
    pub name: String,
    /// The property's type as written.
    #[serde(rename = "type")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::ident()"))]
    pub ty: String,
    /// Visibility.
    #[serde(default, skip_serializing_if = "crate::variable::is_default")]
    pub access: AccessSpecifier,
    /// What the property means.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::text()"))]
    pub comment: String,
    /// The `Get` accessor, if the property can be read.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub get: Option<PropertyAccessor>,
    /// The `Set` accessor, if the property can be written.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub set: Option<PropertyAccessor>,
}

/// The getter or setter of a property.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(deny_unknown_fields)]
pub struct PropertyAccessor {
    /// Local declarations of the accessor.
    #[serde(default, rename = "variable", skip_serializing_if = "Vec::is_empty")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::small_vec()"))]
    pub variables: Vec<Variable>,
    /// The implementation.
    pub body: Body,
}

/// An action of a program or function block: a body without declarations of its own.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(deny_unknown_fields)]
pub struct PouAction {
    /// The action's name.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::ident()"))]
    pub name: String,
    /// The implementation.
    pub body: Body,
}
