//! Values known at compile time (literals, named constants, enumeration values, initialisers)
//! and their bytes in memory.

use program_image::Elementary as IE;

use crate::literal;
use crate::sema::constant::{Const, evaluate};
use crate::sema::scope::Globals;
use crate::syntax::ast::Expr;
use crate::syntax::{SyntaxKind, SyntaxToken};

/// A value known at compile time.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Value {
    Int(i128),
    Real(f64),
    Bool(bool),
    /// A duration, date or time of day in nanoseconds (dates since 1970-01-01).
    Nanos(i128),
    /// A string's characters.
    Text(Vec<u16>),
}

/// The value of a literal token.
fn token_value(token: &SyntaxToken) -> Option<Value> {
    let text = token.text();
    Some(match token.kind() {
        SyntaxKind::INT_NUMBER => {
            Value::Int(i128::try_from(literal::parse_integer(text).ok()?).ok()?)
        }
        SyntaxKind::REAL_NUMBER => Value::Real(literal::parse_real(text).ok()?),
        SyntaxKind::TRUE => Value::Bool(true),
        SyntaxKind::FALSE => Value::Bool(false),
        SyntaxKind::TIME_LITERAL => Value::Nanos(literal::parse_duration(text).ok()?),
        SyntaxKind::DATE_LITERAL => {
            let prefix = text
                .split('#')
                .next()
                .unwrap_or_default()
                .to_ascii_uppercase();
            match prefix.as_str() {
                "D" | "DATE" | "LD" | "LDATE" => {
                    Value::Nanos(i128::from(literal::parse_date(text).ok()?) * 86_400_000_000_000)
                }
                "TOD" | "TIME_OF_DAY" | "LTOD" | "LTIME_OF_DAY" => {
                    Value::Nanos(literal::parse_time_of_day(text).ok()?)
                }
                _ => Value::Nanos(literal::parse_date_and_time(text).ok()?),
            }
        }
        SyntaxKind::STRING | SyntaxKind::WSTRING => Value::Text(string_value(text)),
        _ => return None,
    })
}

/// The characters of a string literal, with `$` escapes resolved.
fn string_value(text: &str) -> Vec<u16> {
    let inner = text
        .get(1..text.len().saturating_sub(1))
        .unwrap_or_default();
    // IEC 61131-3: `$hh` in a STRING, `$hhhh` in a WSTRING (written between double quotes).
    let hex_digits = if text.starts_with('"') { 4 } else { 2 };
    let mut out = Vec::new();
    let mut chars = inner.chars().peekable();
    while let Some(c) = chars.next() {
        if c != '$' {
            let mut buffer = [0u16; 2];
            out.extend_from_slice(c.encode_utf16(&mut buffer));
            continue;
        }
        match chars.next() {
            Some('L' | 'l' | 'N' | 'n') => out.push(10),
            Some('R' | 'r') => out.push(13),
            Some('T' | 't') => out.push(9),
            Some('P' | 'p') => out.push(12),
            Some(hex) if hex.is_ascii_hexdigit() => {
                let mut digits = String::from(hex);
                while digits.len() < hex_digits && chars.peek().is_some_and(char::is_ascii_hexdigit)
                {
                    digits.extend(chars.next());
                }
                out.push(u16::from_str_radix(&digits, 16).unwrap_or(0));
            }
            Some(other) => out.push(other as u16),
            None => {}
        }
    }
    out
}

/// The value of a constant expression, or `None` when it is not constant.
pub(crate) fn evaluate_node(node: &Expr, globals: &Globals<'_>) -> Option<Value> {
    match node {
        Expr::Literal(literal) => return token_value(&literal.token()?),
        Expr::TypedLiteral(literal) => {
            if let Some(value) = literal.value()
                && value.kind() != SyntaxKind::IDENT
            {
                let value = token_value(&value)?;
                return Some(if literal.is_negative() {
                    negate(value)?
                } else {
                    value
                });
            }
        }
        Expr::ParenExpr(paren) => return evaluate_node(&paren.inner()?, globals),
        Expr::UnaryExpr(unary) => {
            if unary.op()?.kind() == SyntaxKind::MINUS
                && let Some(Value::Nanos(ns)) = evaluate_node(&unary.operand()?, globals)
            {
                return Some(Value::Nanos(-ns));
            }
        }
        _ => {}
    }
    let constants =
        |name: &str, container: Option<&str>, depth: u32| globals.constant(name, container, depth);
    match evaluate(node, &constants, 0)? {
        Const::Int(v) => Some(Value::Int(v)),
        Const::Real(v) => Some(Value::Real(v)),
        Const::Bool(v) => Some(Value::Bool(v)),
    }
}

fn negate(value: Value) -> Option<Value> {
    Some(match value {
        Value::Int(v) => Value::Int(-v),
        Value::Real(v) => Value::Real(-v),
        Value::Nanos(v) => Value::Nanos(-v),
        _ => return None,
    })
}

/// The raw bits of `value` stored as a `ty`, or `None` when it is no value of that type.
pub(crate) fn raw_of(value: &Value, ty: IE) -> Option<u64> {
    let bits = ty.size_bytes() * 8;
    let mask = if bits == 64 {
        u64::MAX
    } else {
        (1u64 << bits) - 1
    };
    let integer = |v: i128| (v as u64) & mask;
    Some(match (value, ty) {
        (Value::Bool(b), _) => u64::from(*b),
        (Value::Int(v), IE::Real) => u64::from((*v as f32).to_bits()),
        (Value::Int(v), IE::Lreal) => (*v as f64).to_bits(),
        (Value::Real(v), IE::Real) => u64::from((*v as f32).to_bits()),
        (Value::Real(v), IE::Lreal) => v.to_bits(),
        (Value::Int(v), _) => integer(*v),
        (Value::Real(v), _) => integer(v.round() as i128),
        (Value::Nanos(ns), _) => integer(match ty {
            IE::Time | IE::TimeOfDay => ns / 1_000_000,
            IE::Date | IE::DateAndTime => ns / 1_000_000_000,
            _ => *ns,
        }),
        (Value::Text(chars), IE::Char | IE::Wchar) => u64::from(*chars.first()?),
        (Value::Text(_), _) => return None,
    })
}

/// The bytes of a string value in a STRING or WSTRING of `length` characters (cut to fit).
pub(crate) fn text_bytes(chars: &[u16], wide: bool, length: u32) -> Vec<u8> {
    let kept = &chars[..chars.len().min(length as usize)];
    if wide {
        let mut bytes: Vec<u8> = kept.iter().flat_map(|c| c.to_le_bytes()).collect();
        bytes.resize(2 * (length as usize + 1), 0);
        bytes
    } else {
        let mut bytes: Vec<u8> = kept.iter().map(|&c| c as u8).collect();
        bytes.resize(length as usize + 1, 0);
        bytes
    }
}
