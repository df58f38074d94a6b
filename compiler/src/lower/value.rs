//! A value flowing through a network while it is lowered: its text, how tightly it binds and
//! whether it may be read again later without being stored first.

use project_model::ElementId;

use super::fragment::{Fragment, frag};

/// Binding strength of ST operators, loosest first, as the parser groups them.
pub(crate) mod prec {
    /// `OR`.
    pub const OR: u8 = 1;
    /// `XOR`.
    pub const XOR: u8 = 2;
    /// `AND`.
    pub const AND: u8 = 3;
    /// `=` and `<>`.
    pub const EQUALITY: u8 = 4;
    /// `<`, `>`, `<=`, `>=`.
    pub const COMPARISON: u8 = 5;
    /// `+` and `-`.
    pub const ADDITIVE: u8 = 6;
    /// `*`, `/`, `MOD`.
    pub const MULTIPLICATIVE: u8 = 7;
    /// `NOT` and unary minus.
    pub const UNARY: u8 = 8;
    /// A name, literal, call or parenthesised expression.
    pub const PRIMARY: u8 = 10;
}

/// What a value's text reads, which decides whether it can be used again later.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Kind {
    /// The left power rail: TRUE, and folded away where it is ANDed.
    Rail,
    /// A read of something no later statement of the network changes: a hidden temporary, a
    /// trigger's or instance's output, a literal.
    Stable,
    /// An expression over the user's variables: used once where it is computed, else stored.
    Expr,
}

/// A value flowing through a network.
#[derive(Clone, Debug)]
pub(crate) struct Value {
    /// The text.
    pub frag: Fragment,
    /// How tightly the text binds.
    pub prec: u8,
    /// Whether it may be read again later.
    pub kind: Kind,
    /// The value is a BOOL (power flow), so it can be stored in a BOOL temporary.
    pub boolean: bool,
    /// The element whose output it is, which names its temporary when it is stored.
    pub owner: Option<ElementId>,
}

impl Value {
    /// The left power rail.
    pub fn rail() -> Self {
        Self {
            frag: Fragment::plain("TRUE"),
            prec: prec::PRIMARY,
            kind: Kind::Rail,
            boolean: true,
            owner: None,
        }
    }

    /// A name or literal that no later statement changes.
    pub fn stable(frag: Fragment, boolean: bool, owner: Option<ElementId>) -> Self {
        Self {
            frag,
            prec: prec::PRIMARY,
            kind: Kind::Stable,
            boolean,
            owner,
        }
    }

    /// Whether this is the left rail.
    pub fn is_rail(&self) -> bool {
        self.kind == Kind::Rail
    }

    /// The text as an operand of an operator of strength `outer`; `right` for the right-hand
    /// operand, which needs parentheses at equal strength too.
    pub fn operand(&self, outer: u8, right: bool) -> Fragment {
        if self.prec > outer || (self.prec == outer && !right) {
            self.frag.clone()
        } else {
            frag!("(", self.frag.clone(), ")")
        }
    }

    /// `NOT self`.
    pub fn not(&self) -> Self {
        Self {
            frag: frag!("NOT ", self.operand(prec::UNARY, true)),
            prec: prec::UNARY,
            kind: if self.kind == Kind::Expr {
                Kind::Expr
            } else {
                Kind::Stable
            },
            boolean: self.boolean,
            owner: self.owner,
        }
    }

    /// `self AND other`, with the rail folded away.
    pub fn and(self, other: Value) -> Value {
        if self.is_rail() {
            return other;
        }
        if other.is_rail() {
            return self;
        }
        binary(self, "AND", prec::AND, other)
    }

    /// `self OR other`; the rail on either side makes the rail.
    pub fn or(self, other: Value) -> Value {
        if self.is_rail() || other.is_rail() {
            return Value::rail();
        }
        binary(self, "OR", prec::OR, other)
    }
}

/// `lhs op rhs` for a left-associative operator of strength `strength`.
pub(crate) fn binary(lhs: Value, op: &str, strength: u8, rhs: Value) -> Value {
    let boolean = lhs.boolean && rhs.boolean;
    Value {
        frag: frag!(
            lhs.operand(strength, false),
            format!(" {op} "),
            rhs.operand(strength, true)
        ),
        prec: strength,
        kind: Kind::Expr,
        boolean,
        owner: rhs.owner.or(lhs.owner),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn name(text: &str) -> Value {
        Value {
            frag: Fragment::plain(text),
            prec: prec::PRIMARY,
            kind: Kind::Expr,
            boolean: true,
            owner: None,
        }
    }

    #[test]
    fn operators_are_parenthesised_only_where_the_parser_needs_it() {
        let value = name("a").and(name("b").not()).or(name("c"));
        assert_eq!(value.frag.text, "a AND NOT b OR c");
        let value = name("a").and(name("b").or(name("c")));
        assert_eq!(value.frag.text, "a AND (b OR c)");
        let value = name("a").and(name("b").and(name("c")));
        assert_eq!(value.frag.text, "a AND (b AND c)");
        assert_eq!(Value::rail().and(name("x")).frag.text, "x");
        assert!(name("x").or(Value::rail()).is_rail());
    }
}
