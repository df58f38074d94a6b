//! Expressions: the `Expr` enum and the accessors of each expression node.

use super::support::{child, children, nth_node, token, tokens};
use super::*;
use crate::syntax::SyntaxToken;

/// Defines an enum over wrapper types, one variant per type, with its `AstNode` impl.
macro_rules! ast_enum {
    ($(#[doc = $doc:literal])+ $name:ident { $($(#[doc = $vdoc:literal])+ $variant:ident,)* }) => {
        $(#[doc = $doc])+
        #[derive(Clone, Debug, PartialEq, Eq, Hash)]
        pub enum $name {
            $($(#[doc = $vdoc])+ $variant($variant),)*
        }

        impl AstNode for $name {
            fn can_cast(kind: SyntaxKind) -> bool {
                $($variant::can_cast(kind))||*
            }

            fn cast(node: SyntaxNode) -> Option<Self> {
                $(if $variant::can_cast(node.kind()) {
                    return $variant::cast(node).map(Self::$variant);
                })*
                None
            }

            fn syntax(&self) -> &SyntaxNode {
                match self {
                    $(Self::$variant(node) => node.syntax(),)*
                }
            }
        }
    };
}
pub(super) use ast_enum;

ast_enum! {
    /// Any node the grammar puts where an expression goes.
    ///
    /// An array value (`[1, 2]`) and an error node (input past the nesting limits) stand where
    /// an operand would, so they are expressions too: the checker still looks inside them.
    Expr {
        /// `42`.
        Literal,
        /// `INT#5`.
        TypedLiteral,
        /// `(inner)`.
        ParenExpr,
        /// `lhs op rhs`.
        BinaryExpr,
        /// `NOT x`.
        UnaryExpr,
        /// `x`.
        NameExpr,
        /// `base.member`.
        FieldExpr,
        /// `base[i]`.
        IndexExpr,
        /// `base^`.
        DerefExpr,
        /// `callee(args)`.
        CallExpr,
        /// `%IX0.1`.
        AddressExpr,
        /// `[1, 2]`.
        ArrayInit,
        /// Input the parser gave up on.
        ErrorNode,
    }
}

impl Literal {
    /// The literal's token: a number, string, time, date, `TRUE` or `FALSE`.
    pub fn token(&self) -> Option<SyntaxToken> {
        tokens(&self.0).next()
    }
}

impl TypedLiteral {
    /// The type prefix before `#`: `INT` in `INT#5`, `E_State` in `E_State#Idle`.
    pub fn type_name(&self) -> Option<SyntaxToken> {
        tokens(&self.0)
            .next()
            .filter(|t| t.kind() != SyntaxKind::HASH)
    }

    /// The value after `#` (and after a `-`): `5`, `Idle`.
    pub fn value(&self) -> Option<SyntaxToken> {
        let mut after_hash = tokens(&self.0).skip_while(|t| t.kind() != SyntaxKind::HASH);
        after_hash.next()?;
        after_hash.filter(|t| t.kind() != SyntaxKind::MINUS).last()
    }

    /// Whether the value is written negative, `INT#-5`.
    pub fn is_negative(&self) -> bool {
        token(&self.0, SyntaxKind::MINUS).is_some()
    }
}

impl ParenExpr {
    /// The expression inside the parentheses.
    pub fn inner(&self) -> Option<Expr> {
        child(&self.0)
    }
}

impl BinaryExpr {
    /// The left operand.
    pub fn lhs(&self) -> Option<Expr> {
        nth_node(&self.0, 0)
    }

    /// The operator token (`+`, `AND`, `<=`, …).
    pub fn op(&self) -> Option<SyntaxToken> {
        tokens(&self.0).next()
    }

    /// The right operand; `None` when the operator is the last thing written.
    pub fn rhs(&self) -> Option<Expr> {
        nth_node(&self.0, 1)
    }
}

impl UnaryExpr {
    /// The operator token: `NOT`, `-` or `+`.
    pub fn op(&self) -> Option<SyntaxToken> {
        tokens(&self.0).next()
    }

    /// The operand.
    pub fn operand(&self) -> Option<Expr> {
        child(&self.0)
    }
}

impl NameExpr {
    /// The name: the identifier, or the operator keyword of `MOD(a, b)`; `None` for `THIS`
    /// and `SUPER`.
    pub fn name(&self) -> Option<SyntaxToken> {
        tokens(&self.0).find(|t| {
            matches!(
                t.kind(),
                SyntaxKind::IDENT
                    | SyntaxKind::MOD
                    | SyntaxKind::AND
                    | SyntaxKind::OR
                    | SyntaxKind::XOR
            )
        })
    }

    /// The identifier, if the name is one (not `THIS`, `SUPER` or an operator keyword).
    pub fn ident(&self) -> Option<SyntaxToken> {
        token(&self.0, SyntaxKind::IDENT)
    }

    /// The first token: an identifier, `THIS`, `SUPER`, the `.` of a global or an operator
    /// keyword.
    pub fn first_token(&self) -> Option<SyntaxToken> {
        tokens(&self.0).next()
    }

    /// Whether the name is written `.name`: the global, even where a local hides it.
    pub fn is_global(&self) -> bool {
        self.first_token()
            .is_some_and(|t| t.kind() == SyntaxKind::DOT)
    }
}

impl FieldExpr {
    /// The expression before the `.`.
    pub fn base(&self) -> Option<Expr> {
        child(&self.0)
    }

    /// The member after the `.`: an identifier, or a bit number (`x.3`, `x.%X3`).
    pub fn member(&self) -> Option<SyntaxToken> {
        tokens(&self.0)
            .filter(|t| {
                matches!(
                    t.kind(),
                    SyntaxKind::IDENT | SyntaxKind::INT_NUMBER | SyntaxKind::DIRECT_ADDRESS
                )
            })
            .last()
    }
}

impl IndexExpr {
    /// The expression indexed.
    pub fn base(&self) -> Option<Expr> {
        nth_node(&self.0, 0)
    }

    /// The indices between the brackets, one per dimension.
    pub fn indices(&self) -> impl Iterator<Item = Expr> + use<> {
        children::<Expr>(&self.0).skip(1)
    }
}

impl DerefExpr {
    /// The pointer or reference dereferenced.
    pub fn base(&self) -> Option<Expr> {
        child(&self.0)
    }
}

impl CallExpr {
    /// What is called: a name, a member (`fb.Method`), or anything else written before `(`.
    pub fn callee(&self) -> Option<Expr> {
        nth_node(&self.0, 0)
    }

    /// The argument list.
    pub fn arg_list(&self) -> Option<ArgList> {
        child(&self.0)
    }

    /// The arguments, in the order written; none when the list is missing.
    pub fn args(&self) -> impl Iterator<Item = Arg> + use<> {
        self.arg_list().into_iter().flat_map(|list| list.args())
    }
}

impl ArgList {
    /// The arguments, in the order written.
    pub fn args(&self) -> AstChildren<Arg> {
        children(&self.0)
    }
}

/// How an argument is passed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ArgKind {
    /// By position: `f(x)`.
    Positional,
    /// To an input by name: `f(IN := x)`.
    Input,
    /// From an output by name: `fb(Q => x)`.
    Output,
}

impl Arg {
    /// The formal parameter's name, before `:=` or `=>`.
    pub fn name(&self) -> Option<SyntaxToken> {
        let parts: Vec<SyntaxToken> = tokens(&self.0).collect();
        let arrow = parts
            .iter()
            .position(|t| matches!(t.kind(), SyntaxKind::ASSIGN | SyntaxKind::OUTPUT_ASSIGN))?;
        parts.get(arrow.checked_sub(1)?).cloned()
    }

    /// Whether the argument is positional, an input by name or an output.
    pub fn kind(&self) -> ArgKind {
        match tokens(&self.0)
            .find(|t| matches!(t.kind(), SyntaxKind::ASSIGN | SyntaxKind::OUTPUT_ASSIGN))
        {
            Some(arrow) if arrow.kind() == SyntaxKind::OUTPUT_ASSIGN => ArgKind::Output,
            Some(_) => ArgKind::Input,
            None => ArgKind::Positional,
        }
    }

    /// Whether an output is connected negated, `NOT Q => x`.
    pub fn is_negated(&self) -> bool {
        self.kind() == ArgKind::Output
            && tokens(&self.0)
                .next()
                .is_some_and(|t| t.kind() == SyntaxKind::NOT)
    }

    /// The value passed, or the place an output is written to; `None` for an unconnected
    /// output `Q =>`.
    pub fn value(&self) -> Option<Expr> {
        child(&self.0)
    }
}

impl AddressExpr {
    /// The direct address token, `%IX0.1`.
    pub fn address(&self) -> Option<SyntaxToken> {
        tokens(&self.0).next()
    }
}

impl ArrayInit {
    /// The values in the brackets (or after `:=` in the bracketless form), in order.
    pub fn elements(&self) -> AstChildren<InitValue> {
        children(&self.0)
    }
}

impl ErrorNode {
    /// The nodes the parser kept inside the error, which may still hold names to check.
    pub fn nodes(&self) -> impl Iterator<Item = SyntaxNode> + use<> {
        self.0.children()
    }
}
