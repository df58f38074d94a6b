//! The type of a `*_TO_BCD` result that goes where a bit string type is given. On its own the
//! result is the bit string of its argument's width (`signatures::bcd_conversion`: `INT_TO_BCD`
//! gives a WORD), which is its type inside an operator, a comparison or a generic function's
//! argument. Assigned, or passed to an input of another bit string type, it takes that type
//! instead, or of an integer type (`iOut := INT_TO_BCD(iIn)`): the argument is converted to
//! it (a narrower type keeps the low bits, as `*_TO_<type>` does) and coded there, so
//! `dw := INT_TO_BCD(12345)` and `d := INT_TO_BCD(12345)` (a DINT) code all five digits. That is what the code generator did before the result had a width of its own, and
//! CODESYS's `INT_TO_BCD` is assigned to a BYTE or WORD alike.

use rowan::TextRange;

use super::BodyChecker;
use crate::elementary::Elementary;
use crate::sema::ty::Type;
use crate::syntax::SyntaxNode;
use crate::syntax::ast::{AstNode, Expr};

impl BodyChecker<'_, '_, '_> {
    /// Notes that the standard call at `range` is a `*_TO_BCD`, whose result follows a bit
    /// string target.
    pub(super) fn note_bcd_call(&mut self, range: TextRange) {
        self.bcd_calls.insert(range);
    }

    /// Whether `value` (of type `value_ty`, its `Expr` node `node`) is a `*_TO_BCD` call, in
    /// parentheses or not, going where the bit string `expected` is copied; if it is, the call
    /// (and each pair of parentheses around it) is recorded with type `expected`, which the code
    /// generator then codes it in.
    pub(super) fn bcd_call_takes_target(
        &mut self,
        node: &SyntaxNode,
        value_ty: &Type,
        expected: &Type,
    ) -> bool {
        let is_code_type = |ty: &Type| {
            ty.as_elementary()
                .is_some_and(|e| e.is_bit_string() && e != Elementary::Bool)
        };
        // An integer target is coded in too (`iOut := INT_TO_BCD(iIn)`, a common idiom): the
        // code is then the integer's bits, with every digit that fits, and no conversion of a
        // bit string into an integer for the checker to warn about.
        let takes_code =
            |ty: &Type| is_code_type(ty) || ty.as_elementary().is_some_and(Elementary::is_integer);
        if !is_code_type(value_ty) || !takes_code(expected) || value_ty == expected {
            return false;
        }
        let mut levels = Vec::new();
        let mut at = Expr::cast(node.clone());
        while let Some(Expr::ParenExpr(paren)) = &at {
            levels.push(paren.syntax().clone());
            at = paren.inner();
        }
        let Some(Expr::CallExpr(call)) = at else {
            return false;
        };
        if !self.bcd_calls.contains(&call.syntax().text_range()) {
            return false;
        }
        levels.push(call.syntax().clone());
        if let Some(types) = &mut self.types {
            for level in &levels {
                types.insert(level, expected.clone());
            }
        }
        true
    }
}
