//! Constant folding: the values of expressions that array bounds, subranges, string lengths and
//! CASE labels need at compile time.

use crate::literal;
use crate::syntax::ast::{AssignStmt, AstNode, Expr};
use crate::syntax::{SyntaxKind, SyntaxToken, parse_statements};

/// A value known at compile time.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Const {
    /// An integer, an enumeration value or a bit string.
    Int(i128),
    /// A real number.
    Real(f64),
    /// `TRUE` or `FALSE`.
    Bool(bool),
}

impl Const {
    /// The integer, if this is one.
    pub(crate) fn as_int(self) -> Option<i128> {
        match self {
            Self::Int(value) => Some(value),
            _ => None,
        }
    }
}

/// A named constant's value: `(name, container, depth)`, `None` when the name is no constant.
pub(crate) type Constants<'c> = dyn Fn(&str, Option<&str>, u32) -> Option<Const> + 'c;

/// How deeply constants may refer to other constants; deeper (or circular) chains are not
/// constant.
pub(crate) const MAX_CONSTANT_DEPTH: u32 = 16;

/// The value of the expression `node`, where `name` gives the value of a named constant (at
/// the given depth) or `None` when the name is not a constant.
pub(crate) fn evaluate(node: &Expr, name: &Constants<'_>, depth: u32) -> Option<Const> {
    if depth > MAX_CONSTANT_DEPTH {
        return None;
    }
    match node {
        Expr::Literal(literal) => literal_value(&literal.token()?),
        Expr::TypedLiteral(literal) => {
            let value = literal.value()?;
            if value.kind() == SyntaxKind::IDENT {
                // `E_State#Idle`: an enumeration value.
                return name(value.text(), Some(literal.type_name()?.text()), depth + 1);
            }
            let value = literal_value(&value)?;
            Some(if literal.is_negative() {
                negate(value)?
            } else {
                value
            })
        }
        Expr::ParenExpr(paren) => evaluate(&paren.inner()?, name, depth + 1),
        Expr::NameExpr(expr) => name(expr.ident()?.text(), None, depth + 1),
        Expr::FieldExpr(field) => {
            // `E_State.Idle` or `GVL.cMax`.
            let Expr::NameExpr(base) = field.base()? else {
                return None;
            };
            let container = base.syntax().text().to_string();
            let member = field.member().filter(|t| t.kind() == SyntaxKind::IDENT)?;
            name(member.text(), Some(container.trim()), depth + 1)
        }
        Expr::UnaryExpr(unary) => {
            let operator = unary.op()?.kind();
            let operand = evaluate(&unary.operand()?, name, depth + 1)?;
            match operator {
                SyntaxKind::MINUS => negate(operand),
                SyntaxKind::PLUS => Some(operand),
                SyntaxKind::NOT => match operand {
                    Const::Bool(value) => Some(Const::Bool(!value)),
                    _ => None,
                },
                _ => None,
            }
        }
        Expr::BinaryExpr(binary_expr) => {
            let left = evaluate(&binary_expr.lhs()?, name, depth + 1)?;
            let right = evaluate(&binary_expr.rhs()?, name, depth + 1)?;
            binary(binary_expr.op()?.kind(), left, right)
        }
        _ => None,
    }
}

fn literal_value(token: &SyntaxToken) -> Option<Const> {
    match token.kind() {
        SyntaxKind::INT_NUMBER => integer_value(token.text()).map(Const::Int),
        SyntaxKind::REAL_NUMBER => literal::parse_real(token.text()).ok().map(Const::Real),
        SyntaxKind::TRUE => Some(Const::Bool(true)),
        SyntaxKind::FALSE => Some(Const::Bool(false)),
        _ => None,
    }
}

/// The value of an integer literal (`1_000`, `16#FF`), if it fits an `i128`.
pub(crate) fn integer_value(text: &str) -> Option<i128> {
    literal::parse_integer(text)
        .ok()
        .and_then(|value| i128::try_from(value).ok())
}

fn negate(value: Const) -> Option<Const> {
    match value {
        Const::Int(value) => value.checked_neg().map(Const::Int),
        Const::Real(value) => Some(Const::Real(-value)),
        Const::Bool(_) => None,
    }
}

fn binary(operator: SyntaxKind, left: Const, right: Const) -> Option<Const> {
    use SyntaxKind::*;
    match (left, right) {
        (Const::Int(a), Const::Int(b)) => Some(match operator {
            PLUS => Const::Int(a.checked_add(b)?),
            MINUS => Const::Int(a.checked_sub(b)?),
            STAR => Const::Int(a.checked_mul(b)?),
            // IEC integer division truncates toward zero, as Rust's does.
            SLASH => Const::Int(a.checked_div(b)?),
            MOD => Const::Int(a.checked_rem(b)?),
            AND | AMP => Const::Int(a & b),
            OR => Const::Int(a | b),
            XOR => Const::Int(a ^ b),
            EQ => Const::Bool(a == b),
            NEQ => Const::Bool(a != b),
            LT => Const::Bool(a < b),
            LE => Const::Bool(a <= b),
            GT => Const::Bool(a > b),
            GE => Const::Bool(a >= b),
            _ => return None,
        }),
        (Const::Bool(a), Const::Bool(b)) => Some(Const::Bool(match operator {
            AND | AMP | AND_THEN => a && b,
            OR | OR_ELSE => a || b,
            XOR => a != b,
            EQ => a == b,
            NEQ => a != b,
            _ => return None,
        })),
        (Const::Real(_) | Const::Int(_), Const::Real(_) | Const::Int(_)) => {
            let a = as_real(left);
            let b = as_real(right);
            Some(match operator {
                PLUS => Const::Real(a + b),
                MINUS => Const::Real(a - b),
                STAR => Const::Real(a * b),
                SLASH => Const::Real(a / b),
                _ => return None,
            })
        }
        _ => None,
    }
}

fn as_real(value: Const) -> f64 {
    match value {
        // Precision loss past 2^53 is acceptable for compile-time real arithmetic.
        #[allow(clippy::cast_precision_loss)]
        Const::Int(value) => value as f64,
        Const::Real(value) => value,
        Const::Bool(value) => f64::from(u8::from(value)),
    }
}

/// The expression written as `text` (an initial value, an enumeration value), parsed alone.
/// `None` when it is not a single expression.
pub(crate) fn parse_expression(text: &str) -> Option<Expr> {
    let parse = parse_statements(&format!("__value := {text};"));
    if !parse.errors().is_empty() {
        return None;
    }
    let statement = parse.syntax().descendants().find_map(AssignStmt::cast)?;
    statement.value()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn value(text: &str) -> Option<Const> {
        let node = parse_expression(text)?;
        let constants = |name: &str, container: Option<&str>, _depth: u32| match (name, container) {
            ("N", None) => Some(Const::Int(10)),
            ("Run", Some("E_State")) => Some(Const::Int(1)),
            _ => None,
        };
        evaluate(&node, &constants, 0)
    }

    #[test]
    fn constant_expressions_fold() {
        assert_eq!(value("N * 2 - 1"), Some(Const::Int(19)));
        assert_eq!(value("-(16#10 + 1)"), Some(Const::Int(-17)));
        assert_eq!(value("INT#-5"), Some(Const::Int(-5)));
        assert_eq!(value("E_State.Run + 1"), Some(Const::Int(2)));
        assert_eq!(value("7 MOD 3"), Some(Const::Int(1)));
        assert_eq!(value("NOT TRUE OR FALSE"), Some(Const::Bool(false)));
        assert_eq!(value("1.5 * 2"), Some(Const::Real(3.0)));
        assert_eq!(value("x + 1"), None);
        assert_eq!(value("1 / 0"), None);
    }
}
