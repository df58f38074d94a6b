//! Places that name no storage of their own: THIS and SUPER (pointers to the running
//! instance) and properties (values of their GET accessor). They cannot be written in part,
//! passed by reference or connected to an output (E0134), as in CODESYS, where a VAR_IN_OUT
//! needs "a variable with write access" (C0041) and "passing properties" to it "is not
//! permitted" (the VAR_IN_OUT page of the CODESYS Online Help). A single bit (`w.3`,
//! `w.%X3`, a BOOL located at `%IX0.1`) has no address of its own, so it cannot be passed by
//! reference either (E0135): "a bit variable cannot be passed directly to VAR_IN_OUT because it
//! needs an intermediate variable" (the same page).

use super::{BodyChecker, range_of, text};
use crate::diagnostic::Code;
use crate::sema::address::parse_address;
use crate::syntax::SyntaxKind;
use crate::syntax::ast::{AstNode, Expr};

/// How a place is used where it must be writable.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum PlaceUse {
    /// The target of `:=`: a whole property is written through its SET accessor.
    Assigned,
    /// Connected to an output (`=>`) or counted by a FOR loop: the place is written, but not
    /// through the setter.
    Connected,
    /// Passed by reference (VAR_IN_OUT, `ADR`, `REF=`): the place's address is needed.
    ByReference,
}

/// What a place is rooted in, when that is no variable.
enum Root {
    /// `THIS` or `SUPER`, as written.
    Instance(String),
    /// A property, as written, and whether the place is the whole property.
    Property { written: String, whole: bool },
}

impl BodyChecker<'_, '_, '_> {
    /// Reports `node` (already checked as an expression) when it is THIS, SUPER, a part of
    /// a property, or a whole property used other than as the target of `:=`; returns
    /// whether it reported.
    pub(super) fn refuse_unwritable_place(&mut self, node: &Expr, usage: PlaceUse) -> bool {
        let message = match self.root_of(node, true) {
            None if usage == PlaceUse::ByReference && self.is_bit(node) => {
                let message = format!(
                    "'{}' is a single bit, which has no address of its own: it cannot be passed to a VAR_IN_OUT, given to ADR or REF=; copy it into a BOOL variable and pass that",
                    text(node.syntax())
                );
                self.error(Code::BitByReference, range_of(node.syntax()), message);
                return true;
            }
            None => return false,
            Some(Root::Property { whole: true, .. }) if usage == PlaceUse::Assigned => {
                return false;
            }
            Some(Root::Instance(keyword)) => format!(
                "'{keyword}' is a pointer to the running instance, not a variable: it cannot be assigned or passed by reference (write '{keyword}^' for the instance)"
            ),
            Some(Root::Property {
                written,
                whole: true,
            }) => format!(
                "'{written}' is a property, whose value its GET accessor gives: it cannot be passed by reference, given to ADR, connected to an output or counted by FOR; read it into a variable first"
            ),
            Some(Root::Property { written, .. }) => format!(
                "'{}' is a part of the property '{written}', whose value its GET accessor gives: writing it would change a copy; read the property into a variable, change that and assign it back",
                text(node.syntax())
            ),
        };
        self.error(Code::UnwritablePlace, range_of(node.syntax()), message);
        true
    }

    /// Whether `node` is one bit of a value or a BOOL located at a bit address.
    fn is_bit(&self, node: &Expr) -> bool {
        if self.bit_nodes.contains(&node.syntax().text_range()) {
            return true;
        }
        match node {
            Expr::ParenExpr(paren) => paren.inner().is_some_and(|inner| self.is_bit(&inner)),
            Expr::FieldExpr(field) => field.member().is_some_and(|member| match member.kind() {
                SyntaxKind::INT_NUMBER => true,
                SyntaxKind::DIRECT_ADDRESS => member.text().to_ascii_uppercase().starts_with("%X"),
                _ => false,
            }),
            Expr::AddressExpr(address) => address.address().is_some_and(
                |token| matches!(parse_address(token.text()), Ok(Some(a)) if a.size_bits == 1),
            ),
            _ => false,
        }
    }

    fn root_of(&self, node: &Expr, whole: bool) -> Option<Root> {
        if self.property_nodes.contains(&node.syntax().text_range()) {
            return Some(Root::Property {
                written: text(node.syntax()),
                whole,
            });
        }
        match node {
            Expr::ParenExpr(paren) => self.root_of(&paren.inner()?, whole),
            Expr::NameExpr(name) => {
                let first = name.first_token()?;
                matches!(first.kind(), SyntaxKind::THIS | SyntaxKind::SUPER)
                    .then(|| Root::Instance(first.text().to_owned()))
            }
            Expr::FieldExpr(field) => self.root_of(&field.base()?, false),
            Expr::IndexExpr(index) => self.root_of(&index.base()?, false),
            // What a pointer points to is storage, wherever the pointer came from.
            _ => None,
        }
    }
}
