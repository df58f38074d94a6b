//! The types the checker reasons about, and the IEC rules between them: which value may go
//! where without an explicit conversion, and what an operator gives.

use std::fmt;

use crate::elementary::Elementary;
use crate::elementary::Elementary as E;

/// A type as the checker sees it. User-defined types are referred to by name and looked up in
/// the project when their shape matters.
#[derive(Clone, Debug, PartialEq)]
pub enum Type {
    /// Something already reported (an unknown name, a bad expression): it fits everywhere, so
    /// one mistake is reported once.
    Error,
    /// No value: a function without a result, an FB call.
    Void,
    /// An elementary type other than the strings.
    Elementary(Elementary),
    /// `STRING(length)` or `WSTRING(length)`; the default length is 80.
    String {
        /// `WSTRING`.
        wide: bool,
        /// The maximum length in characters.
        length: u32,
    },
    /// An integer literal not yet given a type: it takes the type of where it goes.
    IntLiteral(Option<i128>),
    /// A real literal not yet given a type.
    RealLiteral,
    /// An array.
    Array {
        /// The element type.
        element: Box<Type>,
        /// Bounds per dimension; `None` for an open bound `*` of a VAR_IN_OUT.
        dims: Vec<Option<(i128, i128)>>,
    },
    /// An integer type restricted to a range.
    Subrange {
        /// The integer type.
        base: Elementary,
        /// The lowest value.
        low: i128,
        /// The highest value.
        high: i128,
    },
    /// `POINTER TO T`.
    Pointer(Box<Type>),
    /// `REFERENCE TO T` or `REF_TO T`.
    Reference(Box<Type>),
    /// A structure, union, enumeration, function block, interface or program of the project or
    /// the standard library, by its declared spelling.
    Named(String),
    /// A generic class such as `ANY_NUM`, as the parameters of standard functions have.
    Generic(Generic),
    /// A global variable list used as a namespace, `GVL.x`.
    Namespace(String),
    /// An enumeration type used as a namespace, `E_State.Idle`.
    EnumNamespace(String),
    /// A step of a textual SFC: `Step.x`, `Step._x` and `Step.t`.
    Step,
    /// The flags of an IEC action of a textual SFC: `_Action.x` and `_Action._x`.
    SfcAction,
}

/// The generic type classes of IEC 61131-3.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Generic {
    /// Anything.
    Any,
    /// Elementary types.
    Elementary,
    /// Numbers and durations.
    Magnitude,
    /// Integers and reals.
    Num,
    /// `REAL`, `LREAL`.
    Real,
    /// Integers.
    Int,
    /// Bit strings, `BOOL` included.
    Bit,
    /// `STRING`, `WSTRING`.
    String,
    /// Dates and times of day.
    Date,
    /// `TIME`, `LTIME`.
    Duration,
}

impl Generic {
    /// The class called `name` (`ANY_NUM`), if it is one.
    pub fn from_name(name: &str) -> Option<Self> {
        Some(match name.to_ascii_uppercase().as_str() {
            "ANY" | "ANY_DERIVED" => Self::Any,
            "ANY_ELEMENTARY" => Self::Elementary,
            "ANY_MAGNITUDE" => Self::Magnitude,
            "ANY_NUM" => Self::Num,
            "ANY_REAL" => Self::Real,
            "ANY_INT" | "ANY_SIGNED" | "ANY_UNSIGNED" | "__XINT" | "__UXINT" => Self::Int,
            "ANY_BIT" | "__XWORD" => Self::Bit,
            "ANY_STRING" | "ANY_CHARS" | "ANY_CHAR" => Self::String,
            "ANY_DATE" => Self::Date,
            "ANY_DURATION" => Self::Duration,
            _ => return None,
        })
    }

    /// Whether a value of type `ty` belongs to the class.
    pub fn admits(self, ty: &Type) -> bool {
        let elementary = match ty {
            Type::Error => return true,
            Type::IntLiteral(_) => {
                return matches!(
                    self,
                    Self::Any
                        | Self::Elementary
                        | Self::Magnitude
                        | Self::Num
                        | Self::Int
                        | Self::Bit
                );
            }
            Type::RealLiteral => {
                return matches!(
                    self,
                    Self::Any | Self::Elementary | Self::Magnitude | Self::Num | Self::Real
                );
            }
            Type::String { .. } => {
                return matches!(self, Self::Any | Self::Elementary | Self::String);
            }
            Type::Subrange { base, .. } => *base,
            Type::Elementary(elementary) => *elementary,
            _ => return self == Self::Any,
        };
        let e = elementary;
        match self {
            Self::Any | Self::Elementary => true,
            Self::Magnitude => {
                e.is_integer() || e.is_real() || matches!(e, Elementary::Time | Elementary::Ltime)
            }
            Self::Num => e.is_integer() || e.is_real(),
            Self::Real => e.is_real(),
            Self::Int => e.is_integer(),
            // CODESYS applies the bit operations (AND, SHL, ROL…) to integers as well.
            Self::Bit => e.is_bit_string() || e.is_integer(),
            Self::String => matches!(e, Elementary::Char | Elementary::Wchar),
            Self::Date => matches!(
                e,
                Elementary::Date
                    | Elementary::Ldate
                    | Elementary::TimeOfDay
                    | Elementary::LtimeOfDay
                    | Elementary::DateAndTime
                    | Elementary::LdateAndTime
            ),
            Self::Duration => matches!(e, Elementary::Time | Elementary::Ltime),
        }
    }

    fn name(self) -> &'static str {
        match self {
            Self::Any => "ANY",
            Self::Elementary => "ANY_ELEMENTARY",
            Self::Magnitude => "ANY_MAGNITUDE",
            Self::Num => "ANY_NUM",
            Self::Real => "ANY_REAL",
            Self::Int => "ANY_INT",
            Self::Bit => "ANY_BIT",
            Self::String => "ANY_STRING",
            Self::Date => "ANY_DATE",
            Self::Duration => "ANY_DURATION",
        }
    }
}

impl Type {
    /// The type of an elementary name, strings as `STRING(80)`.
    pub fn elementary(elementary: Elementary) -> Self {
        match elementary {
            Elementary::String => Self::String {
                wide: false,
                length: DEFAULT_STRING_LENGTH,
            },
            Elementary::Wstring => Self::String {
                wide: true,
                length: DEFAULT_STRING_LENGTH,
            },
            other => Self::Elementary(other),
        }
    }

    /// `BOOL`.
    pub const BOOL: Self = Self::Elementary(Elementary::Bool);

    /// The elementary type this is or is restricted from, if any.
    pub fn as_elementary(&self) -> Option<Elementary> {
        match self {
            Self::Elementary(e) | Self::Subrange { base: e, .. } => Some(*e),
            _ => None,
        }
    }

    /// Whether this is `BOOL` (or an error, which fits anywhere).
    pub fn is_bool_like(&self) -> bool {
        matches!(self, Self::Error | Self::Elementary(Elementary::Bool))
    }

    /// Whether this is an integer (typed or literal) or an error.
    pub fn is_integer_like(&self) -> bool {
        match self {
            Self::Error | Self::IntLiteral(_) | Self::Subrange { .. } => true,
            Self::Elementary(e) => e.is_integer(),
            _ => false,
        }
    }

    /// Whether this is a number (integer or real, typed or literal).
    pub fn is_numeric(&self) -> bool {
        match self {
            Self::Error | Self::IntLiteral(_) | Self::RealLiteral | Self::Subrange { .. } => true,
            Self::Elementary(e) => e.is_integer() || e.is_real(),
            _ => false,
        }
    }

    /// Whether this is an integer or bit string usable as a set of bits.
    pub fn is_bits(&self) -> bool {
        match self {
            Self::Error | Self::IntLiteral(_) | Self::Subrange { .. } => true,
            Self::Elementary(e) => e.is_integer() || e.is_bit_string(),
            _ => false,
        }
    }
}

/// The length of a `STRING` declared without one.
pub const DEFAULT_STRING_LENGTH: u32 = 80;

impl fmt::Display for Type {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Error => f.write_str("?"),
            Self::Void => f.write_str("no value"),
            Self::Elementary(e) => f.write_str(e.name()),
            Self::String { wide, length } => {
                let name = if *wide { "WSTRING" } else { "STRING" };
                if *length == DEFAULT_STRING_LENGTH {
                    f.write_str(name)
                } else {
                    write!(f, "{name}({length})")
                }
            }
            Self::IntLiteral(_) => f.write_str("an integer literal"),
            Self::RealLiteral => f.write_str("a real literal"),
            Self::Array { element, dims } => {
                f.write_str("ARRAY[")?;
                for (i, dim) in dims.iter().enumerate() {
                    if i > 0 {
                        f.write_str(", ")?;
                    }
                    match dim {
                        Some((low, high)) => write!(f, "{low}..{high}")?,
                        None => f.write_str("*")?,
                    }
                }
                write!(f, "] OF {element}")
            }
            Self::Subrange { base, low, high } => write!(f, "{}({low}..{high})", base.name()),
            Self::Pointer(target) => write!(f, "POINTER TO {target}"),
            Self::Reference(target) => write!(f, "REFERENCE TO {target}"),
            Self::Named(name) | Self::EnumNamespace(name) => f.write_str(name),
            Self::Generic(generic) => f.write_str(generic.name()),
            Self::Namespace(name) => write!(f, "global variable list {name}"),
            Self::Step => f.write_str("an SFC step"),
            Self::SfcAction => f.write_str("the flags of an SFC action"),
        }
    }
}

/// Whether `value` fits the integer range of `ty`.
pub fn fits(value: i128, ty: Elementary) -> bool {
    ty.integer_range()
        .is_some_and(|(low, high)| (low..=high).contains(&value))
}

/// Whether a value of type `from` goes into a place of type `to` without an explicit
/// conversion (both already stripped of aliases and references by the caller).
pub fn implicitly_converts(from: &Type, to: &Type) -> bool {
    use Type::*;
    match (from, to) {
        (Error, _) | (_, Error) => true,
        (_, Generic(generic)) => generic.admits(from),
        (IntLiteral(value), Elementary(e)) => {
            if e.is_real() {
                true
            } else if e.is_integer() || (e.is_bit_string() && *e != E::Bool) {
                value.is_none_or(|v| fits(v, *e))
            } else if *e == E::Bool {
                matches!(value, None | Some(0 | 1))
            } else {
                false
            }
        }
        (IntLiteral(value), Subrange { low, high, .. }) => {
            value.is_none_or(|v| (*low..=*high).contains(&v))
        }
        (RealLiteral, Elementary(e)) => e.is_real(),
        (Elementary(a), Elementary(b)) => a.widens_to(*b),
        (Subrange { base, .. }, Elementary(b)) => base.widens_to(*b),
        // A value is checked against the range when it is stored, as CODESYS does.
        (Elementary(a), Subrange { base, .. }) => a.widens_to(*base),
        (Subrange { base: a, .. }, Subrange { base: b, .. }) => a.widens_to(*b),
        (String { wide: a, .. }, String { wide: b, .. }) => a == b,
        (Elementary(E::Char), String { wide: false, .. }) => true,
        (Elementary(E::Wchar), String { wide: true, .. }) => true,
        (
            Array {
                element: a,
                dims: da,
            },
            Array {
                element: b,
                dims: db,
            },
        ) => {
            da.len() == db.len()
                && da.iter().zip(db).all(|(x, y)| match (x, y) {
                    (Some((l1, h1)), Some((l2, h2))) => h1 - l1 == h2 - l2,
                    _ => true,
                })
                && (a == b || implicitly_converts(a, b) && implicitly_converts(b, a))
        }
        // `ADR` gives a pointer to anything; pointers convert when their targets agree.
        (Pointer(a), Pointer(b)) => {
            matches!(**a, Error | Void) || matches!(**b, Error | Void) || same_type(a, b)
        }
        (IntLiteral(Some(0)), Pointer(_) | Reference(_)) => true,
        (Named(a), Named(b)) => a.eq_ignore_ascii_case(b),
        _ => false,
    }
}

/// Whether two types are the same type.
pub fn same_type(a: &Type, b: &Type) -> bool {
    match (a, b) {
        (Type::Named(x), Type::Named(y)) => x.eq_ignore_ascii_case(y),
        (Type::Pointer(x), Type::Pointer(y)) | (Type::Reference(x), Type::Reference(y)) => {
            same_type(x, y)
        }
        (Type::String { wide: x, .. }, Type::String { wide: y, .. }) => x == y,
        _ => a == b,
    }
}

/// The type of `base ** exponent` and of `EXPT(base, exponent)`, one rule for both: CODESYS
/// gives a real ("Permitted data types for the return value: REAL and LREAL", its operator
/// EXPT), REAL when every typed operand is REAL and LREAL otherwise (an integer power needs
/// LREAL's 53 bits; TwinCAT's manual states `EXPT(real, INT#2)` is LREAL); two literals give a
/// real literal. `None` when an operand is not a number.
pub fn power_type(base: &Type, exponent: &Type) -> Option<Type> {
    use Elementary::{Lreal, Real};
    if !(base.is_numeric() && exponent.is_numeric()) {
        return None;
    }
    let literal = |t: &Type| matches!(t, Type::IntLiteral(_) | Type::RealLiteral);
    Some(match (literal(base), literal(exponent)) {
        (true, true) => Type::RealLiteral,
        _ if [base, exponent]
            .iter()
            .all(|t| literal(t) || t.as_elementary() == Some(Real)) =>
        {
            Type::Elementary(Real)
        }
        _ => Type::Elementary(Lreal),
    })
}

/// The type both operands of an arithmetic or comparison operator take: the wider of the two
/// when one widens to the other, the typed one when the other is a fitting literal.
pub fn common_type(a: &Type, b: &Type) -> Option<Type> {
    use Type::*;
    match (a, b) {
        (Error, _) | (_, Error) => Some(Error),
        (IntLiteral(_), IntLiteral(_)) => Some(IntLiteral(None)),
        (RealLiteral | IntLiteral(_), RealLiteral) | (RealLiteral, IntLiteral(_)) => {
            Some(RealLiteral)
        }
        (literal @ (IntLiteral(_) | RealLiteral), typed)
        | (typed, literal @ (IntLiteral(_) | RealLiteral)) => {
            let typed = strip_subrange(typed);
            implicitly_converts(literal, &typed).then_some(typed)
        }
        _ => {
            let (a, b) = (strip_subrange(a), strip_subrange(b));
            if implicitly_converts(&a, &b) {
                Some(b)
            } else if implicitly_converts(&b, &a) {
                Some(a)
            } else {
                None
            }
        }
    }
}

/// The type CODESYS V3.5 computes `a + b` (and `-`, `*`, `/`, `MOD` and the comparisons) in
/// when one operand is a signed and the other an unsigned integer and neither widens to the
/// other (`INT + UINT`, `DINT * UDINT`, `SINT < USINT`): the smallest signed integer whose
/// range holds both operands' ranges (`DINT`, `LINT`, `INT`), so every result is the
/// mathematical one, as CODESYS's register-width computation gives it ("computes temporary
/// results always with the native size", its operators overview). `None` for other operands,
/// and for a 64-bit integer with one of the other sign, which no type holds.
pub fn mixed_sign_type(a: &Type, b: &Type) -> Option<Type> {
    let (Type::Elementary(a), Type::Elementary(b)) = (strip_subrange(a), strip_subrange(b)) else {
        return None;
    };
    let mixed = (a.is_signed_integer() && b.is_unsigned_integer())
        || (a.is_unsigned_integer() && b.is_signed_integer());
    if !mixed || a.widens_to(b) || b.widens_to(a) {
        return None;
    }
    [E::Int, E::Dint, E::Lint]
        .into_iter()
        .find(|wide| a.widens_to(*wide) && b.widens_to(*wide))
        .map(Type::Elementary)
}

/// The type CODESYS V3.5 computes `a * b` (and `+`, `-`, `/` and the comparisons) in when one
/// operand is an integer and the other a `REAL` or `LREAL` (`UDINT * REAL`, `i < r`): the real
/// operand's type, the integer converted to it first. IEC 61131-3 refuses the mix; CODESYS
/// compiles it (`codesys_code_execution_speedTests.xml` computes `UDINT * REAL`). `None` for
/// other operands.
pub fn integer_real_type(a: &Type, b: &Type) -> Option<Type> {
    let (Type::Elementary(a), Type::Elementary(b)) = (strip_subrange(a), strip_subrange(b)) else {
        return None;
    };
    match (a.is_integer(), a.is_real(), b.is_integer(), b.is_real()) {
        (true, _, _, true) => Some(Type::Elementary(b)),
        (_, true, true, _) => Some(Type::Elementary(a)),
        _ => None,
    }
}

/// The unsigned integer a bit string counts as in CODESYS arithmetic (`BYTE` as `USINT`);
/// `None` for `BOOL` and everything that is not a bit string.
pub fn bit_string_counterpart(ty: Elementary) -> Option<Elementary> {
    Some(match ty {
        E::Byte => E::Usint,
        E::Word => E::Uint,
        E::Dword => E::Udint,
        E::Lword => E::Ulint,
        _ => return None,
    })
}

/// The type of `a + b` (and `-`, `*`, `/`, `MOD`) when an operand is a bit string, as CODESYS
/// V3.5 computes it: a bit string counts as the unsigned integer of its width, the operands
/// take their common type, and a result of a bit string's width is that bit string
/// (`BYTE + 1` is `BYTE`, `BYTE + INT` is `INT`). `None` when no operand is a bit string or
/// the operands have no common type.
pub fn bit_string_arithmetic(a: &Type, b: &Type) -> Option<Type> {
    let bit_string = |ty: &Type| match ty {
        Type::Elementary(e) => bit_string_counterpart(*e).map(|number| (*e, number)),
        _ => None,
    };
    let (left, right) = (bit_string(a), bit_string(b));
    if left.is_none() && right.is_none() {
        return None;
    }
    let as_number = |ty: &Type, bits: Option<(Elementary, Elementary)>| match bits {
        Some((_, number)) => Some(Type::Elementary(number)),
        None if ty.is_numeric() => Some(ty.clone()),
        None => None,
    };
    let (a_number, b_number) = (as_number(a, left)?, as_number(b, right)?);
    let common =
        common_type(&a_number, &b_number).or_else(|| mixed_sign_type(&a_number, &b_number))?;
    for (bits, number) in [left, right].into_iter().flatten() {
        if common == Type::Elementary(number) {
            return Some(Type::Elementary(bits));
        }
    }
    Some(common)
}

/// Whether a value of type `from` going into `to` is an integer conversion IEC refuses and
/// CODESYS V3.5 performs with a warning (C0195, C0196): a narrowing or a change of sign
/// between integers and bit strings other than `BOOL`, or an integer constant outside the
/// target's range. The value keeps its low bits.
pub fn lenient_integer_conversion(from: &Type, to: &Type) -> bool {
    let Type::Elementary(to) = to else {
        return false;
    };
    let integer = |e: Elementary| e.is_integer() || (e.is_bit_string() && e != E::Bool);
    if !integer(*to) {
        return false;
    }
    match from {
        Type::IntLiteral(Some(_)) => true,
        Type::Elementary(e) | Type::Subrange { base: e, .. } => integer(*e),
        _ => false,
    }
}

/// Whether a value of type `from` going into `to` is an integer converted to a real that
/// may not hold it exactly (`DINT` into `REAL`), which IEC refuses and CODESYS V3.5 performs
/// with a warning (its C0197): the real nearest the integer is stored.
pub fn lenient_real_conversion(from: &Type, to: &Type) -> bool {
    let (Some(from), Type::Elementary(to)) = (from.as_elementary(), to) else {
        return false;
    };
    to.is_real() && (from.is_integer() || (from.is_bit_string() && from != E::Bool))
}

/// Whether a value of type `from` going into `to` is a real converted to an integer or bit
/// string (`i := EXPT(2, 10)`, `i := x ** 4`, `i := r`), which IEC refuses and CODESYS V3.5
/// performs with a warning (its C0197 message, "Implicit conversion from … : possible loss of
/// information"), as the `TO_` conversion it inserts: the real rounded to the nearest
/// integer, halves away from zero, like `REAL_TO_INT`.
pub fn lenient_real_to_integer(from: &Type, to: &Type) -> bool {
    let Type::Elementary(to) = to else {
        return false;
    };
    let real =
        matches!(from, Type::RealLiteral) || from.as_elementary().is_some_and(|e| e.is_real());
    real && (to.is_integer() || (to.is_bit_string() && *to != E::Bool))
}

/// `value` as stored in an integer or bit string `ty`: its low bits, read with the type's sign.
pub fn wrapped(value: i128, ty: Elementary) -> i128 {
    let bits = ty.size_bits();
    if bits == 0 || bits >= 128 {
        return value;
    }
    let low = value & ((1i128 << bits) - 1);
    if ty.is_signed_integer() && low >= 1i128 << (bits - 1) {
        low - (1i128 << bits)
    } else {
        low
    }
}

/// A subrange stands for its base type in arithmetic.
fn strip_subrange(ty: &Type) -> Type {
    match ty {
        Type::Subrange { base, .. } => Type::Elementary(*base),
        other => other.clone(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use Elementary::*;

    fn e(elementary: Elementary) -> Type {
        Type::Elementary(elementary)
    }

    #[test]
    fn literals_take_the_type_of_their_place_when_they_fit() {
        assert!(implicitly_converts(&Type::IntLiteral(Some(127)), &e(Sint)));
        assert!(!implicitly_converts(&Type::IntLiteral(Some(128)), &e(Sint)));
        assert!(!implicitly_converts(&Type::IntLiteral(Some(-1)), &e(Uint)));
        assert!(implicitly_converts(&Type::IntLiteral(Some(255)), &e(Byte)));
        assert!(implicitly_converts(&Type::IntLiteral(Some(5)), &e(Real)));
        assert!(!implicitly_converts(&Type::RealLiteral, &e(Int)));
        assert!(!implicitly_converts(&Type::IntLiteral(Some(5)), &e(Time)));
    }

    #[test]
    fn arithmetic_takes_the_wider_operand() {
        assert_eq!(common_type(&e(Int), &e(Dint)), Some(e(Dint)));
        assert_eq!(
            common_type(&e(Int), &Type::IntLiteral(Some(3))),
            Some(e(Int))
        );
        assert_eq!(
            common_type(&e(Real), &Type::IntLiteral(Some(3))),
            Some(e(Real))
        );
        assert_eq!(common_type(&e(Int), &e(Uint)), None);
        assert_eq!(common_type(&e(Dint), &e(Real)), None);
    }

    #[test]
    fn bit_strings_count_as_unsigned_integers_of_their_width_in_codesys_arithmetic() {
        let three = Type::IntLiteral(Some(3));
        assert_eq!(bit_string_arithmetic(&e(Byte), &three), Some(e(Byte)));
        assert_eq!(bit_string_arithmetic(&e(Byte), &e(Word)), Some(e(Word)));
        assert_eq!(bit_string_arithmetic(&e(Byte), &e(Int)), Some(e(Int)));
        assert_eq!(bit_string_arithmetic(&e(Dword), &e(Real)), None);
        assert_eq!(bit_string_arithmetic(&e(Word), &e(Real)), Some(e(Real)));
        // A bit string with a signed integer of its width combines as USINT and SINT do.
        assert_eq!(bit_string_arithmetic(&e(Byte), &e(Sint)), Some(e(Int)));
        assert_eq!(bit_string_arithmetic(&e(Lword), &e(Lint)), None);
        assert_eq!(bit_string_arithmetic(&e(Int), &e(Dint)), None);
        assert_eq!(bit_string_arithmetic(&e(Bool), &three), None);
    }

    #[test]
    fn signed_and_unsigned_integers_meet_in_the_smallest_signed_type_holding_both() {
        assert_eq!(mixed_sign_type(&e(Int), &e(Uint)), Some(e(Dint)));
        assert_eq!(mixed_sign_type(&e(Usint), &e(Sint)), Some(e(Int)));
        assert_eq!(mixed_sign_type(&e(Dint), &e(Udint)), Some(e(Lint)));
        assert_eq!(mixed_sign_type(&e(Sint), &e(Udint)), Some(e(Lint)));
        assert_eq!(mixed_sign_type(&e(Lint), &e(Ulint)), None);
        // Where one widens to the other, the common type is the usual one, not this.
        assert_eq!(mixed_sign_type(&e(Dint), &e(Uint)), None);
        assert_eq!(mixed_sign_type(&e(Int), &e(Word)), None);
    }

    #[test]
    fn an_integer_meets_a_real_in_the_real_type() {
        assert_eq!(integer_real_type(&e(Udint), &e(Real)), Some(e(Real)));
        assert_eq!(integer_real_type(&e(Lreal), &e(Sint)), Some(e(Lreal)));
        assert_eq!(integer_real_type(&e(Real), &e(Lreal)), None);
        assert_eq!(integer_real_type(&e(Dword), &e(Real)), None);
        assert_eq!(integer_real_type(&e(Int), &e(Dint)), None);
    }

    #[test]
    fn lenient_conversions_are_between_integers_or_into_reals_only() {
        assert!(lenient_integer_conversion(&e(Int), &e(Sint)));
        assert!(lenient_integer_conversion(&e(Dint), &e(Word)));
        assert!(lenient_integer_conversion(
            &Type::IntLiteral(Some(128)),
            &e(Sint)
        ));
        assert!(!lenient_integer_conversion(&e(Real), &e(Int)));
        assert!(!lenient_integer_conversion(&e(Int), &e(Bool)));
        assert!(!lenient_integer_conversion(&e(Time), &e(Dint)));
        assert!(lenient_real_conversion(&e(Dint), &e(Real)));
        assert!(!lenient_real_conversion(&e(Bool), &e(Real)));
        assert!(!lenient_real_conversion(&e(Real), &e(Dint)));
        assert!(lenient_real_to_integer(&e(Lreal), &e(Int)));
        assert!(lenient_real_to_integer(&Type::RealLiteral, &e(Word)));
        assert!(!lenient_real_to_integer(&e(Real), &e(Bool)));
        assert!(!lenient_real_to_integer(&e(Dint), &e(Int)));
    }

    #[test]
    fn a_wrapped_value_keeps_its_low_bits_read_with_the_targets_sign() {
        assert_eq!(wrapped(128, Sint), -128);
        assert_eq!(wrapped(4223, Sint), 127);
        assert_eq!(wrapped(-1, Uint), 65535);
        assert_eq!(wrapped(260, Usint), 4);
        assert_eq!(wrapped(-5, Lint), -5);
    }

    #[test]
    fn generic_classes_admit_their_members() {
        assert!(Generic::Num.admits(&e(Lreal)));
        assert!(!Generic::Num.admits(&e(Time)));
        assert!(Generic::Bit.admits(&e(Bool)));
        assert!(Generic::Magnitude.admits(&e(Time)));
        assert!(Generic::String.admits(&Type::elementary(Wstring)));
        assert!(!Generic::Int.admits(&Type::RealLiteral));
    }
}
