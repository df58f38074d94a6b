//! Operator boxes written as the ST operators a user writes (`ADD` as `+`, `GT` as `>`).

use super::value::{Value, binary, prec};

/// An operator box written as the ST operator a user would write.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Operator {
    /// A left-associative infix operator, for two or more inputs (`+`, `AND`).
    Infix(&'static str, u8, bool),
    /// A comparison of exactly two inputs (`>`).
    Comparison(&'static str, u8),
    /// `NOT`, of one input.
    Not,
    /// `MOVE`: the input itself.
    Move,
}

impl Operator {
    /// The operator box named `name`, if it is one.
    pub fn of(name: &str) -> Option<Self> {
        use prec::*;
        Some(match name.trim().to_ascii_uppercase().as_str() {
            "ADD" => Self::Infix("+", ADDITIVE, true),
            "SUB" => Self::Infix("-", ADDITIVE, false),
            "MUL" => Self::Infix("*", MULTIPLICATIVE, true),
            "DIV" => Self::Infix("/", MULTIPLICATIVE, false),
            "MOD" => Self::Infix("MOD", MULTIPLICATIVE, false),
            "AND" => Self::Infix("AND", AND, true),
            "OR" => Self::Infix("OR", OR, true),
            "XOR" => Self::Infix("XOR", XOR, true),
            "GT" => Self::Comparison(">", COMPARISON),
            "GE" => Self::Comparison(">=", COMPARISON),
            "LT" => Self::Comparison("<", COMPARISON),
            "LE" => Self::Comparison("<=", COMPARISON),
            "EQ" => Self::Comparison("=", EQUALITY),
            "NE" => Self::Comparison("<>", EQUALITY),
            "NOT" => Self::Not,
            "MOVE" => Self::Move,
            _ => return None,
        })
    }

    /// Whether the operator form takes `inputs` inputs; otherwise the box is called as a
    /// function.
    pub fn fits(self, inputs: usize) -> bool {
        match self {
            Self::Infix(_, _, extensible) => inputs == 2 || (extensible && inputs > 2),
            Self::Comparison(..) => inputs == 2,
            Self::Not | Self::Move => inputs == 1,
        }
    }

    /// The expression over `values` (as many as [`Operator::fits`] allows).
    pub fn apply(self, values: Vec<Value>) -> Value {
        let mut values = values.into_iter();
        let Some(first) = values.next() else {
            return Value::rail();
        };
        match self {
            Self::Infix(op, strength, _) | Self::Comparison(op, strength) => {
                let logical = matches!(op, "AND" | "OR" | "XOR");
                let mut value = values.fold(first, |lhs, rhs| binary(lhs, op, strength, rhs));
                // Arithmetic gives a number; a logical operator a BOOL only of BOOLs.
                value.boolean = matches!(self, Self::Comparison(..)) || logical && value.boolean;
                value
            }
            Self::Not => first.not(),
            Self::Move => first,
        }
    }
}
