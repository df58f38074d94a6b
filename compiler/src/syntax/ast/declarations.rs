//! Declarations: variables, types and initial values.

use super::expressions::ast_enum;
use super::support::{child, children, nth_node, token, tokens};
use super::*;
use crate::syntax::SyntaxToken;

ast_enum! {
    /// A type as written in a declaration.
    TypeExpr {
        /// `INT`, `FB_Conveyor`, `INT(0..100)`.
        NamedType,
        /// `STRING(20)`.
        StringType,
        /// `ARRAY[1..3] OF REAL`.
        ArrayType,
        /// `POINTER TO T`.
        PointerType,
        /// `REFERENCE TO T`, `REF_TO T`.
        ReferenceType,
        /// `(Idle, Running)`.
        EnumType,
        /// A type wrapping another.
        TypeRef,
    }
}

impl SourceFile {
    /// The type of a text parsed with `parse_type`.
    pub fn type_expr(&self) -> Option<TypeExpr> {
        child(&self.0)
    }
}

impl VarDecl {
    /// The list of names before `:` (`None` for a nameless located variable `AT %IX0.0 : BOOL`).
    pub fn name_list(&self) -> Option<VarNameList> {
        child(&self.0)
    }

    /// The names declared, in order (dotted instance paths in `VAR_CONFIG`).
    pub fn names(&self) -> impl Iterator<Item = Name> + use<> {
        self.name_list().into_iter().flat_map(|list| list.names())
    }

    /// The `AT %…` address.
    pub fn address(&self) -> Option<Address> {
        child(&self.0)
    }

    /// The declared type (for an access path, the path; the type follows it).
    pub fn ty(&self) -> Option<TypeExpr> {
        child(&self.0)
    }

    /// The initial value after `:=`.
    pub fn initializer(&self) -> Option<Initializer> {
        child(&self.0)
    }
}

impl VarNameList {
    /// The names, in order.
    pub fn names(&self) -> AstChildren<Name> {
        children(&self.0)
    }
}

impl Address {
    /// The direct address token, `%IX0.0`.
    pub fn address(&self) -> Option<SyntaxToken> {
        token(&self.0, SyntaxKind::DIRECT_ADDRESS)
    }
}

impl NamedType {
    /// The type's name.
    pub fn name(&self) -> Option<NameRef> {
        child(&self.0)
    }

    /// The subrange, `(0..100)` in `INT(0..100)`.
    pub fn subrange(&self) -> Option<Subrange> {
        child(&self.0)
    }

    /// The initialisation arguments of an FB instance, `FB_Logger(TestResults)`.
    pub fn arg_list(&self) -> Option<ArgList> {
        child(&self.0)
    }
}

impl Subrange {
    /// The lower bound.
    pub fn low(&self) -> Option<Expr> {
        nth_node(&self.0, 0)
    }

    /// The upper bound.
    pub fn high(&self) -> Option<Expr> {
        nth_node(&self.0, 1)
    }
}

impl StringType {
    /// `STRING` or `WSTRING`.
    pub fn name(&self) -> Option<NameRef> {
        child(&self.0)
    }

    /// The length in brackets.
    pub fn length(&self) -> Option<Expr> {
        child(&self.0)
    }
}

impl ArrayType {
    /// The dimensions, in order.
    pub fn ranges(&self) -> AstChildren<ArrayRange> {
        children(&self.0)
    }

    /// The element type after `OF`.
    pub fn element_type(&self) -> Option<TypeExpr> {
        child(&self.0)
    }
}

impl ArrayRange {
    /// The lower bound; `None` for `*`.
    pub fn low(&self) -> Option<Expr> {
        nth_node(&self.0, 0)
    }

    /// The upper bound; `None` for `*` and for an open upper bound `1..`.
    pub fn high(&self) -> Option<Expr> {
        nth_node(&self.0, 1)
    }

    /// Whether the dimension is `*`, the open dimension of a parameter.
    pub fn is_star(&self) -> bool {
        token(&self.0, SyntaxKind::STAR).is_some()
    }
}

impl PointerType {
    /// The type pointed to.
    pub fn target(&self) -> Option<TypeExpr> {
        child(&self.0)
    }
}

impl ReferenceType {
    /// The type referred to.
    pub fn target(&self) -> Option<TypeExpr> {
        child(&self.0)
    }

    /// Whether it is written `REF_TO` (IEC, dereferenced with `^`) rather than `REFERENCE TO`
    /// (CODESYS, used as the variable it refers to).
    pub fn is_ref_to(&self) -> bool {
        tokens(&self.0)
            .next()
            .is_some_and(|t| t.kind() == SyntaxKind::REF_TO)
    }
}

impl TypeRef {
    /// The type inside.
    pub fn ty(&self) -> Option<TypeExpr> {
        child(&self.0)
    }
}

impl EnumType {
    /// The values, in order.
    pub fn values(&self) -> AstChildren<EnumValue> {
        children(&self.0)
    }

    /// The base type written after the values, `DINT` in `(Idle, Run) DINT`.
    pub fn base(&self) -> Option<NamedType> {
        child(&self.0)
    }
}

impl EnumValue {
    /// The value's name.
    pub fn name(&self) -> Option<Name> {
        child(&self.0)
    }

    /// The number given after `:=`.
    pub fn value(&self) -> Option<Expr> {
        child(&self.0)
    }
}

/// A value in an initialiser: an expression, a structure value or a repetition.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum InitValue {
    /// `(x := 1, y := 2)`.
    Struct(StructInit),
    /// `3(0)`.
    Repeat(RepeatInit),
    /// An expression, an array value `[1, 2]` among them.
    Expr(Expr),
}

impl AstNode for InitValue {
    fn can_cast(kind: SyntaxKind) -> bool {
        StructInit::can_cast(kind) || RepeatInit::can_cast(kind) || Expr::can_cast(kind)
    }

    fn cast(node: SyntaxNode) -> Option<Self> {
        match node.kind() {
            SyntaxKind::STRUCT_INIT => StructInit::cast(node).map(Self::Struct),
            SyntaxKind::REPEAT_INIT => RepeatInit::cast(node).map(Self::Repeat),
            _ => Expr::cast(node).map(Self::Expr),
        }
    }

    fn syntax(&self) -> &SyntaxNode {
        match self {
            Self::Struct(node) => node.syntax(),
            Self::Repeat(node) => node.syntax(),
            Self::Expr(node) => node.syntax(),
        }
    }
}

impl Initializer {
    /// The value after `:=` (an array value for the bracketless `:= 1, 2, 3`).
    pub fn value(&self) -> Option<InitValue> {
        child(&self.0)
    }
}

impl RepeatInit {
    /// How many times the value is repeated; `None` when the count is not a number.
    pub fn count(&self) -> Option<usize> {
        token(&self.0, SyntaxKind::INT_NUMBER).and_then(|t| t.text().parse().ok())
    }

    /// The value repeated; `None` for `3()`, which repeats the default.
    pub fn value(&self) -> Option<InitValue> {
        child(&self.0)
    }
}

impl StructInit {
    /// The members given, in order.
    pub fn fields(&self) -> AstChildren<FieldInit> {
        children(&self.0)
    }
}

impl FieldInit {
    /// The member's name.
    pub fn name(&self) -> Option<Name> {
        child(&self.0)
    }

    /// The member's value.
    pub fn value(&self) -> Option<InitValue> {
        child(&self.0)
    }
}
