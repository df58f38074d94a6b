//! The elementary types the generator writes expressions in, and their literals.

use proptest::prelude::*;
use proptest::strategy::Union;

/// An elementary type of the generated programs (`docs/native-engine.md` §11.2).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Ty {
    /// 8-bit signed integer.
    Sint,
    /// 16-bit signed integer.
    Int,
    /// 32-bit signed integer.
    Dint,
    /// 64-bit signed integer.
    Lint,
    /// 8-bit unsigned integer.
    Usint,
    /// 16-bit unsigned integer.
    Uint,
    /// 32-bit unsigned integer.
    Udint,
    /// 64-bit unsigned integer.
    Ulint,
    /// Boolean.
    Bool,
    /// 32-bit IEEE 754 real.
    Real,
    /// 64-bit IEEE 754 real.
    Lreal,
    /// Duration in milliseconds, stored as a DINT.
    Time,
}

/// Every type, in the order of [`Ty::index`].
pub const ALL: [Ty; 12] = [
    Ty::Sint,
    Ty::Int,
    Ty::Dint,
    Ty::Lint,
    Ty::Usint,
    Ty::Uint,
    Ty::Udint,
    Ty::Ulint,
    Ty::Bool,
    Ty::Real,
    Ty::Lreal,
    Ty::Time,
];

/// The integer types, signed and unsigned.
pub const INTEGERS: [Ty; 8] = [
    Ty::Sint,
    Ty::Int,
    Ty::Dint,
    Ty::Lint,
    Ty::Usint,
    Ty::Uint,
    Ty::Udint,
    Ty::Ulint,
];

impl Ty {
    /// The type's position in [`ALL`], used to index tables of strategies.
    pub fn index(self) -> usize {
        ALL.iter()
            .position(|ty| *ty == self)
            .unwrap_or_else(|| unreachable!("{self:?} is in ALL"))
    }

    /// The IEC name, as declarations, typed literals and conversions spell it.
    pub fn name(self) -> &'static str {
        match self {
            Ty::Sint => "SINT",
            Ty::Int => "INT",
            Ty::Dint => "DINT",
            Ty::Lint => "LINT",
            Ty::Usint => "USINT",
            Ty::Uint => "UINT",
            Ty::Udint => "UDINT",
            Ty::Ulint => "ULINT",
            Ty::Bool => "BOOL",
            Ty::Real => "REAL",
            Ty::Lreal => "LREAL",
            Ty::Time => "TIME",
        }
    }

    /// The lower-case name that ends the generated variables' names (`a_sint`).
    pub fn suffix(self) -> String {
        self.name().to_ascii_lowercase()
    }

    /// Whether this is a signed integer type.
    pub fn is_signed(self) -> bool {
        matches!(self, Ty::Sint | Ty::Int | Ty::Dint | Ty::Lint)
    }

    /// Whether this is REAL or LREAL.
    pub fn is_real(self) -> bool {
        matches!(self, Ty::Real | Ty::Lreal)
    }

    /// The smallest and largest value of an integer type (TIME as its DINT milliseconds).
    pub fn range(self) -> (i128, i128) {
        match self {
            Ty::Sint => (i8::MIN.into(), i8::MAX.into()),
            Ty::Int => (i16::MIN.into(), i16::MAX.into()),
            Ty::Dint | Ty::Time => (i32::MIN.into(), i32::MAX.into()),
            Ty::Lint => (i64::MIN.into(), i64::MAX.into()),
            Ty::Usint => (0, u8::MAX.into()),
            Ty::Uint => (0, u16::MAX.into()),
            Ty::Udint => (0, u32::MAX.into()),
            Ty::Ulint => (0, u64::MAX.into()),
            Ty::Bool => (0, 1),
            Ty::Real | Ty::Lreal => unreachable!("a real has no integer range"),
        }
    }

    /// The width in bits of an integer type.
    pub fn width_bits(self) -> u32 {
        let (_, max) = self.range();
        if self.is_signed() {
            max.count_ones() + 1
        } else {
            max.count_ones()
        }
    }

    /// Whether `value` is a value of this integer type.
    pub fn holds(self, value: i128) -> bool {
        let (min, max) = self.range();
        (min..=max).contains(&value)
    }

    /// The bounds `lo..hi` of the array of this element type every scope declares: low
    /// bounds of every sign and size, so `Element` subtracts something else each time.
    pub fn array_bounds(self) -> (i64, i64) {
        match self {
            Ty::Sint => (-3, 4),
            Ty::Int => (1, 8),
            Ty::Dint => (-5, 2),
            Ty::Lint => (0, 5),
            Ty::Usint => (10, 14),
            Ty::Uint => (2, 6),
            Ty::Udint => (0, 3),
            Ty::Ulint => (1, 4),
            Ty::Bool => (-1, 6),
            Ty::Real => (0, 7),
            Ty::Lreal => (-2, 2),
            Ty::Time => (100, 103),
        }
    }
}

/// A typed literal of `ty` (`SINT#-128`, `LREAL#9.223372036854776e18`, `T#-5ms`), drawn so
/// that the edges of the type (its extremes, 0, ±1, the reals' halves, ±2⁶³, −0.0) come as
/// often as values from the whole range.
pub fn literal(ty: Ty) -> BoxedStrategy<String> {
    match ty {
        Ty::Bool => prop_oneof![Just("TRUE".to_owned()), Just("FALSE".to_owned())].boxed(),
        Ty::Real => real_value()
            .prop_map(|value| format!("REAL#{value:?}"))
            .boxed(),
        Ty::Lreal => lreal_value()
            .prop_map(|value| format!("LREAL#{value:?}"))
            .boxed(),
        Ty::Time => integer_value(ty).prop_map(|ms| format!("T#{ms}ms")).boxed(),
        integer => integer_value(integer)
            .prop_map(move |value| format!("{}#{value}", integer.name()))
            .boxed(),
    }
}

/// An integer literal of `ty` holding `value`, which must fit it.
pub fn integer_literal(ty: Ty, value: i128) -> String {
    debug_assert!(ty.holds(value), "{value} is not a {ty:?}");
    match ty {
        Ty::Time => format!("T#{value}ms"),
        other => format!("{}#{value}", other.name()),
    }
}

/// A value of the integer type `ty`: its edges, small values and any value of its range.
fn integer_value(ty: Ty) -> BoxedStrategy<i128> {
    let (min, max) = ty.range();
    let mut edges = vec![0, 1, 2, min, max, min + 1, max - 1];
    if ty.is_signed() || ty == Ty::Time {
        edges.extend([-1, -2]);
    }
    if ty == Ty::Ulint {
        // Around 2⁶³, where an index or a conversion changes sign when read as signed.
        edges.extend([1 << 63, (1 << 63) - 1, (1 << 63) + 1]);
    }
    let small_min = min.max(-16);
    Union::new_weighted(vec![
        (3, proptest::sample::select(edges).boxed()),
        (3, (small_min..=16).boxed()),
        (2, (min..=max).boxed()),
    ])
    .boxed()
}

/// A finite LREAL: the edges of §6.2 (±0.5, ±2⁶³, the largest value below 2⁶³, 2⁶⁴, the
/// halves the integer types round), −0.0, extremes and ordinary values.
fn lreal_value() -> BoxedStrategy<f64> {
    let two_63 = 9_223_372_036_854_775_808.0_f64;
    let edges = vec![
        0.0,
        -0.0,
        1.0,
        -1.0,
        0.5,
        -0.5,
        1.5,
        -1.5,
        2.5,
        -2.5,
        0.499_999_999_999_999_94,
        127.5,
        -128.5,
        255.5,
        32_767.5,
        65_535.5,
        2_147_483_647.5,
        -2_147_483_648.5,
        4_294_967_295.5,
        two_63,
        -two_63,
        two_63 - 1024.0,
        two_63 + 2048.0,
        18_446_744_073_709_551_616.0,
        1e300,
        -1e300,
        f64::MAX,
        f64::MIN_POSITIVE,
        5e-324,
    ];
    Union::new_weighted(vec![
        (3, proptest::sample::select(edges).boxed()),
        (2, (-100.0..100.0f64).boxed()),
        (1, proptest::num::f64::NORMAL.boxed()),
    ])
    .boxed()
}

/// A finite REAL, chosen as [`lreal_value`]'s edges that a REAL holds.
fn real_value() -> BoxedStrategy<f32> {
    let two_63 = 9_223_372_036_854_775_808.0_f32;
    let edges = vec![
        0.0,
        -0.0,
        1.0,
        -1.0,
        0.5,
        -0.5,
        1.5,
        -1.5,
        2.5,
        -2.5,
        0.499_999_97,
        127.5,
        -128.5,
        255.5,
        32_767.5,
        65_535.5,
        8_388_607.5,
        2_147_483_648.0,
        -2_147_483_648.0,
        two_63,
        -two_63,
        9_223_371_487_098_961_920.0,
        18_446_744_073_709_551_616.0,
        f32::MAX,
        f32::MIN_POSITIVE,
        1e-45,
    ];
    Union::new_weighted(vec![
        (3, proptest::sample::select(edges).boxed()),
        (2, (-100.0..100.0f32).boxed()),
        (1, proptest::num::f32::NORMAL.boxed()),
    ])
    .boxed()
}

/// A REAL or LREAL expression that is not a literal: NaN, +∞ or −∞, written as the divisions
/// that make them (ST has no literal for them).
pub fn special_real(ty: Ty) -> BoxedStrategy<String> {
    let name = ty.name();
    proptest::sample::select(vec![
        format!("({name}#0.0 / {name}#0.0)"),
        format!("({name}#1.0 / {name}#0.0)"),
        format!("({name}#-1.0 / {name}#0.0)"),
        format!("(-({name}#0.0 / {name}#0.0))"),
    ])
    .boxed()
}
