//! From declared type text to [`Type`], and the shapes of user-defined types: the members of a
//! structure or function block, the values of an enumeration, the constants of the project.

use project_model::{DataType, Pou, PouKind, TypeDefinition, VarSection};

use super::constant::{Const, Constants, MAX_CONSTANT_DEPTH, evaluate, parse_expression};
use super::scope::{GlobalSymbol, Globals, inheritance_chain};
use super::signatures;
use super::ty::{DEFAULT_STRING_LENGTH, Generic, Type};
use crate::elementary::Elementary;
use crate::syntax::ast::{AstNode, Expr, SourceFile, TypeExpr};
use crate::syntax::parse_type;

/// The type written as `text`; [`Type::Error`] when it does not parse or names nothing (the
/// declaration check reports that).
pub(crate) fn resolve_type_text(globals: &Globals<'_>, text: &str) -> Type {
    let constants =
        |name: &str, container: Option<&str>, depth: u32| globals.constant(name, container, depth);
    resolve_text_at(globals, text, 0, &constants)
}

/// [`resolve_type_text`] with the constants of a POU visible in array bounds and lengths.
pub(crate) fn resolve_type_text_with(
    globals: &Globals<'_>,
    text: &str,
    constants: &Constants<'_>,
) -> Type {
    resolve_text_at(globals, text, 0, constants)
}

fn resolve_text_at(
    globals: &Globals<'_>,
    text: &str,
    depth: u32,
    constants: &Constants<'_>,
) -> Type {
    let parse = parse_type(text);
    if !parse.errors().is_empty() {
        return Type::Error;
    }
    match SourceFile::cast(parse.syntax()).and_then(|file| file.type_expr()) {
        Some(node) => resolve_type_node(globals, &node, depth, constants),
        None => Type::Error,
    }
}

/// The type a type node of a declaration stands for.
pub(crate) fn resolve_type_node(
    globals: &Globals<'_>,
    node: &TypeExpr,
    depth: u32,
    constants: &Constants<'_>,
) -> Type {
    if depth > MAX_CONSTANT_DEPTH {
        return Type::Error;
    }
    let constant =
        |expression: Option<Expr>| evaluate(&expression?, constants, 0).and_then(Const::as_int);
    let inner = |target: Option<TypeExpr>| {
        target.map_or(Type::Error, |target| {
            resolve_type_node(globals, &target, depth + 1, constants)
        })
    };
    match node {
        TypeExpr::NamedType(named) => {
            let Some(name) = named.name() else {
                return Type::Error;
            };
            let named_type = resolve_name(globals, &name.text(), depth, constants);
            if let Some(subrange) = named.subrange()
                && let (Some(base), Some(low), Some(high)) = (
                    named_type.as_elementary(),
                    constant(subrange.low()),
                    constant(subrange.high()),
                )
            {
                return Type::Subrange { base, low, high };
            }
            named_type
        }
        TypeExpr::StringType(string) => {
            let wide = string
                .name()
                .is_some_and(|name| name.text().eq_ignore_ascii_case("WSTRING"));
            let length = constant(string.length())
                .and_then(|length| u32::try_from(length).ok())
                .unwrap_or(DEFAULT_STRING_LENGTH);
            Type::String { wide, length }
        }
        TypeExpr::ArrayType(array) => {
            let dims = array
                .ranges()
                .map(
                    |range| match (constant(range.low()), constant(range.high())) {
                        (Some(low), Some(high)) => Some((low, high)),
                        _ => None,
                    },
                )
                .collect();
            Type::Array {
                element: Box::new(inner(array.element_type())),
                dims,
            }
        }
        TypeExpr::PointerType(pointer) => Type::Pointer(Box::new(inner(pointer.target()))),
        TypeExpr::ReferenceType(reference) => {
            let target = Box::new(inner(reference.target()));
            // IEC's REF_TO is dereferenced with '^' like a pointer; CODESYS's REFERENCE TO is
            // used as the variable it refers to.
            if reference.is_ref_to() {
                Type::Pointer(target)
            } else {
                Type::Reference(target)
            }
        }
        TypeExpr::TypeRef(type_ref) => inner(type_ref.ty()),
        TypeExpr::EnumType(_) => Type::Error,
    }
}

/// The type called `name`: elementary, generic, a standard function block or a type of the
/// project, aliases followed.
fn resolve_name(globals: &Globals<'_>, name: &str, depth: u32, constants: &Constants<'_>) -> Type {
    if let Some(elementary) = Elementary::from_name(name) {
        return Type::elementary(elementary);
    }
    if let Some(generic) = Generic::from_name(name) {
        return Type::Generic(generic);
    }
    if let Some(data_type) = globals.data_type(name) {
        return match &data_type.definition {
            TypeDefinition::Alias { ty, .. } => resolve_text_at(globals, ty, depth + 1, constants),
            _ => Type::Named(data_type.name.clone()),
        };
    }
    if let Some(pou) = globals.pou(name) {
        return Type::Named(pou.name.clone());
    }
    if signatures::function_block(name).is_some() {
        return Type::Named(name.to_ascii_uppercase());
    }
    match name.to_ascii_uppercase().as_str() {
        // CODESYS's platform-sized integers.
        "__XWORD" => Type::Elementary(Elementary::Lword),
        "__UXINT" => Type::Elementary(Elementary::Ulint),
        "__XINT" => Type::Elementary(Elementary::Lint),
        "BIT" => Type::BOOL,
        _ => Type::Error,
    }
}

/// What a member of a named type is.
#[derive(Clone, Debug)]
pub(crate) struct Member {
    /// The member's type.
    pub(crate) ty: Type,
    /// The variable section for members of function blocks and programs; `Var` for structure
    /// members.
    pub(crate) section: VarSection,
    /// A method: callable, its type is its result.
    pub(crate) is_method: bool,
    /// A constant: cannot be written.
    pub(crate) constant: bool,
}

/// The shape of a named type, as far as member access needs it.
pub(crate) enum Shape<'p> {
    /// A structure or union of the project.
    Struct(&'p DataType),
    /// An enumeration of the project.
    Enum(&'p DataType),
    /// A function block, interface or program of the project.
    Pou(&'p Pou),
    /// A standard function block.
    StandardFb(&'static signatures::FunctionBlockSig),
}

impl<'p> Globals<'p> {
    /// What the named type `name` is, if the project or the standard library defines it.
    pub(crate) fn shape(&self, name: &str) -> Option<Shape<'p>> {
        if let Some(data_type) = self.data_type(name) {
            return match &data_type.definition {
                TypeDefinition::Struct { .. } | TypeDefinition::Union { .. } => {
                    Some(Shape::Struct(data_type))
                }
                TypeDefinition::Enum { .. } => Some(Shape::Enum(data_type)),
                TypeDefinition::Alias { .. } => None,
            };
        }
        if let Some(pou) = self.pou(name) {
            return Some(Shape::Pou(pou));
        }
        signatures::function_block(name).map(Shape::StandardFb)
    }

    /// The member `member` of the named type `name`, inherited members included.
    pub(crate) fn member(&self, name: &str, member: &str) -> Option<Member> {
        match self.shape(name)? {
            Shape::Struct(data_type) => self.struct_member(data_type, member, 0),
            Shape::Enum(_) => None,
            Shape::Pou(pou) => {
                for current in inheritance_chain(self, pou) {
                    if let Some(variable) = current
                        .variables
                        .iter()
                        .find(|v| v.name.eq_ignore_ascii_case(member))
                    {
                        return Some(Member {
                            ty: self.resolve_type(&variable.ty),
                            section: variable.section,
                            is_method: false,
                            constant: variable.constant,
                        });
                    }
                    if let Some(method) = current
                        .methods
                        .iter()
                        .find(|m| m.name.eq_ignore_ascii_case(member))
                    {
                        return Some(Member {
                            ty: method
                                .return_type
                                .as_deref()
                                .map_or(Type::Void, |ty| self.resolve_type(ty)),
                            section: VarSection::VarOutput,
                            is_method: true,
                            constant: false,
                        });
                    }
                    if let Some(property) = current
                        .properties
                        .iter()
                        .find(|p| p.name.eq_ignore_ascii_case(member))
                    {
                        return Some(Member {
                            ty: self.resolve_type(&property.ty),
                            // A property without a setter reads like an output.
                            section: if property.set.is_some() {
                                VarSection::VarInput
                            } else {
                                VarSection::VarOutput
                            },
                            is_method: false,
                            constant: false,
                        });
                    }
                    if current
                        .actions
                        .iter()
                        .any(|a| a.name.eq_ignore_ascii_case(member))
                    {
                        return Some(Member {
                            ty: Type::Void,
                            section: VarSection::VarOutput,
                            is_method: true,
                            constant: false,
                        });
                    }
                }
                None
            }
            Shape::StandardFb(fb) => fb.member(member).map(|(ty, output)| Member {
                ty,
                section: if output {
                    VarSection::VarOutput
                } else {
                    VarSection::VarInput
                },
                is_method: false,
                constant: false,
            }),
        }
    }

    fn struct_member(&self, data_type: &DataType, member: &str, depth: usize) -> Option<Member> {
        let (members, extends) = match &data_type.definition {
            TypeDefinition::Struct { members, extends } => (members, extends.as_deref()),
            TypeDefinition::Union { members } => (members, None),
            _ => return None,
        };
        if let Some(found) = members.iter().find(|m| m.name.eq_ignore_ascii_case(member)) {
            return Some(Member {
                ty: self.resolve_type(&found.ty),
                section: VarSection::Var,
                is_method: false,
                constant: false,
            });
        }
        let base = self.data_type(extends?)?;
        if depth >= super::scope::MAX_INHERITANCE {
            return None;
        }
        self.struct_member(base, member, depth + 1)
    }

    /// Every member name of the named type, for suggestions.
    pub(crate) fn member_names_of(&self, name: &str) -> Vec<String> {
        match self.shape(name) {
            Some(Shape::Struct(data_type) | Shape::Enum(data_type)) => self
                .member_names(&data_type.name)
                .into_iter()
                .map(str::to_owned)
                .collect(),
            Some(Shape::Pou(pou)) => inheritance_chain(self, pou)
                .into_iter()
                .flat_map(|p| {
                    p.variables
                        .iter()
                        .map(|v| v.name.clone())
                        .chain(p.methods.iter().map(|m| m.name.clone()))
                        .chain(p.properties.iter().map(|m| m.name.clone()))
                })
                .collect(),
            Some(Shape::StandardFb(fb)) => fb.names().map(str::to_owned).collect(),
            None => Vec::new(),
        }
    }

    /// The value of the named constant `name` (in `container`, a global variable list or an
    /// enumeration, when given): a `VAR_GLOBAL CONSTANT` with an initial value or an
    /// enumeration value.
    pub(crate) fn constant(
        &self,
        name: &str,
        container: Option<&str>,
        depth: u32,
    ) -> Option<Const> {
        if depth > MAX_CONSTANT_DEPTH {
            return None;
        }
        let symbol = match container {
            None => self.lookup(name)?,
            Some(container) => match self.lookup(container)? {
                GlobalSymbol::Gvl(gvl) => GlobalSymbol::Var(
                    gvl.variables
                        .iter()
                        .find(|v| v.name.eq_ignore_ascii_case(name))?,
                ),
                GlobalSymbol::DataType(data_type) => GlobalSymbol::EnumValue(data_type),
                _ => return None,
            },
        };
        match symbol {
            GlobalSymbol::Var(variable) if variable.constant => {
                let expression = parse_expression(variable.initial.as_deref()?)?;
                evaluate(&expression, &|n, c, d| self.constant(n, c, d), depth + 1)
            }
            GlobalSymbol::EnumValue(data_type) => self.enum_value(data_type, name, depth),
            _ => None,
        }
    }

    /// The integer value of `value` in the enumeration: its explicit value, or one more than
    /// the value before it (the first is 0).
    pub(crate) fn enum_value(
        &self,
        data_type: &DataType,
        value: &str,
        depth: u32,
    ) -> Option<Const> {
        let TypeDefinition::Enum { values, .. } = &data_type.definition else {
            return None;
        };
        let mut next = 0i128;
        for candidate in values {
            let current = match &candidate.value {
                Some(text) => {
                    let expression = parse_expression(text)?;
                    evaluate(&expression, &|n, c, d| self.constant(n, c, d), depth + 1)?.as_int()?
                }
                None => next,
            };
            if candidate.name.eq_ignore_ascii_case(value) {
                return Some(Const::Int(current));
            }
            next = current.checked_add(1)?;
        }
        None
    }

    /// Whether the POU is a function block or program: something with instances and members.
    pub(crate) fn is_instance_type(&self, name: &str) -> bool {
        match self.shape(name) {
            Some(Shape::Pou(pou)) => pou.kind != PouKind::Function,
            Some(Shape::StandardFb(_)) => true,
            _ => false,
        }
    }
}
