//! What a name in a body refers to, as plain data: the answer to hover, go to definition and
//! find references.

use std::ops::Range;

/// The kind of a declaration a name refers to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum DefinitionKind {
    /// A variable of a POU, method, accessor or global variable list.
    Variable,
    /// The result of a function, method or property inside its own body.
    Result,
    /// A program, function block, function or interface.
    Pou,
    /// A method.
    Method,
    /// A property.
    Property,
    /// An action.
    Action,
    /// A step of a textual SFC.
    Step,
    /// A global variable list used as a namespace.
    GlobalVarList,
    /// A data type.
    DataType,
    /// A value of an enumeration.
    EnumValue,
    /// A member of a structure or a variable of a function block reached through an instance.
    Member,
    /// A function or function block of the standard library.
    Standard,
    /// A motion axis of the device tree.
    Axis,
    /// A cam table of the application.
    CamTable,
}

/// A declaration a name refers to.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Definition {
    /// What it is.
    pub kind: DefinitionKind,
    /// The project object that declares it (POU, global variable list, data type); `None` for
    /// the standard library and axes.
    pub object: Option<String>,
    /// The method or property inside `object` that declares it, for their own variables.
    pub container: Option<String>,
    /// The declared name.
    pub name: String,
    /// One line saying what it is, such as `iCount : INT` or `FUNCTION F_Scale : REAL`.
    pub detail: String,
}

impl Definition {
    /// Whether two definitions are the same declaration (names compare without case).
    pub fn same_declaration(&self, other: &Self) -> bool {
        let same = |a: &Option<String>, b: &Option<String>| match (a, b) {
            (Some(a), Some(b)) => a.eq_ignore_ascii_case(b),
            (None, None) => true,
            _ => false,
        };
        self.kind == other.kind
            && same(&self.object, &other.object)
            && same(&self.container, &other.container)
            && self.name.eq_ignore_ascii_case(&other.name)
    }
}

/// A name in a body and what it refers to.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Resolution {
    /// The name's byte range in the body.
    pub range: Range<usize>,
    /// The declaration.
    pub definition: Definition,
    /// The type of the name's value there, as written in messages (`INT`, `TON`).
    pub ty: String,
}
