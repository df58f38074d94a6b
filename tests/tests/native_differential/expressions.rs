//! Typed expression trees, written as Structured Text.
//!
//! An expression of type `T` at depth `d` is a leaf (a variable or a literal) or an operator
//! whose operands are expressions of depth `d - 1` of the types the operator needs, so every
//! tree is well typed by construction. Operands always have the operator's own type and every
//! change of type is an explicit `*_TO_*`, so the checker's implicit conversions play no part.
//! The strategies of each depth and type are built once and shared (`Expressions`), which
//! keeps building them linear in the depth.

use proptest::prelude::*;
use proptest::strategy::Union;

use super::scope::Scope;
use super::types::{self, ALL, INTEGERS, Ty};

/// The expression strategies of one scope, by depth and type.
pub struct Expressions {
    /// `levels[d][ty.index()]`: expressions of type `ty` at most `d` operators deep.
    levels: Vec<Vec<BoxedStrategy<String>>>,
}

impl Expressions {
    /// The strategies of `scope` up to `depth` operators deep.
    pub fn new(scope: Scope, depth: usize) -> Self {
        let mut levels = vec![ALL.iter().map(|ty| leaf(scope, *ty)).collect::<Vec<_>>()];
        for _ in 0..depth {
            let below = levels.last().cloned().unwrap_or_default();
            let level = ALL
                .iter()
                .map(|ty| {
                    Union::new_weighted(vec![
                        (2, leaf(scope, *ty)),
                        (5, compound(scope, *ty, &below)),
                    ])
                    .boxed()
                })
                .collect();
            levels.push(level);
        }
        Self { levels }
    }

    /// Expressions of type `ty` as deep as this table goes.
    pub fn of(&self, ty: Ty) -> BoxedStrategy<String> {
        self.at(ty, self.levels.len() - 1)
    }

    /// Expressions of type `ty` at most `depth` operators deep.
    pub fn at(&self, ty: Ty, depth: usize) -> BoxedStrategy<String> {
        self.levels[depth.min(self.levels.len() - 1)][ty.index()].clone()
    }

    /// An index into the array `r_{element}` (see [`index`]) from expressions of this table.
    pub fn index(&self, element: Ty) -> BoxedStrategy<String> {
        let top = &self.levels[self.levels.len() - 1];
        index(element, top)
    }
}

/// A variable of the scope or a literal of `ty`; a real may also be NaN or an infinity.
fn leaf(scope: Scope, ty: Ty) -> BoxedStrategy<String> {
    let variables = proptest::sample::select(scope.readable(ty)).boxed();
    let mut choices = vec![(3, variables), (2, types::literal(ty))];
    if ty.is_real() {
        choices.push((1, types::special_real(ty)));
    }
    Union::new_weighted(choices).boxed()
}

/// An operator of type `ty` over the expressions `below` (indexed by type).
fn compound(scope: Scope, ty: Ty, below: &[BoxedStrategy<String>]) -> BoxedStrategy<String> {
    let e = |t: Ty| below[t.index()].clone();
    let mut choices: Vec<(u32, BoxedStrategy<String>)> = vec![
        (1, call("SEL", vec![e(Ty::Bool), e(ty), e(ty)])),
        (1, mux(e(ty), below)),
        (1, call_of_two(&["MIN", "MAX"], e(ty), e(ty))),
        (1, call("LIMIT", vec![e(ty), e(ty), e(ty)])),
        (2, conversion_into(ty, below)),
        (2, element(ty, below)),
    ];
    if scope.has_pointers() {
        choices.push((1, Just(format!("p_{}^", ty.suffix())).boxed()));
    }
    if scope.has_instances() {
        let suffix = ty.suffix();
        choices.push((
            1,
            proptest::sample::select(vec![format!("fb1.b_{suffix}"), format!("fb2.b_{suffix}")])
                .boxed(),
        ));
    }
    match ty {
        Ty::Bool => choices.extend(boolean(scope, below)),
        Ty::Time => choices.extend(duration(below)),
        Ty::Real | Ty::Lreal => choices.extend(real(scope, ty, below)),
        integer => choices.extend(integer_operators(scope, integer, below)),
    }
    Union::new_weighted(choices).boxed()
}

/// The operators of an integer type: arithmetic, DIV and MOD, bits, shifts and rotations.
fn integer_operators(
    scope: Scope,
    ty: Ty,
    below: &[BoxedStrategy<String>],
) -> Vec<(u32, BoxedStrategy<String>)> {
    let e = |t: Ty| below[t.index()].clone();
    let mut choices = vec![
        (4, binary(e(ty), &["+", "-", "*"], e(ty))),
        (3, binary(e(ty), &["/", "MOD"], divisor(ty, below))),
        (2, binary(e(ty), &["AND", "OR", "XOR"], e(ty))),
        (1, e(ty).prop_map(|x| format!("(NOT {x})")).boxed()),
        (1, e(ty).prop_map(|x| format!("(-{x})")).boxed()),
        (1, call("ABS", vec![e(ty)])),
        (
            3,
            (
                proptest::sample::select(vec!["SHL", "SHR", "ROL", "ROR"]),
                e(ty),
                shift_count(below),
            )
                .prop_map(|(name, x, n)| format!("{name}({x}, {n})"))
                .boxed(),
        ),
    ];
    if ty == Ty::Dint {
        choices.push((1, call("TRUNC", vec![real_of_either_width(below)])));
    }
    choices.push((2, real_into(ty, below)));
    // From binary-coded decimal (the `FROM_BCD` instruction); most values are no BCD, which
    // the conversion must treat alike in both engines.
    let from_bcd = format!("BCD_TO_{}", ty.name());
    let from = from_bcd.clone();
    choices.push((1, e(ty).prop_map(move |x| format!("{from}({x})")).boxed()));
    // The way there, `*_TO_BCD` (the `TO_BCD` instruction), gives the bit string of its
    // argument's width, so its codes are operands of the bit operators and the result is
    // decoded back into the integer type (negative values code their bits as unsigned).
    let to_bcd = format!("{}_TO_BCD", ty.name());
    choices.push((
        1,
        (
            e(ty),
            proptest::sample::select(vec!["AND", "OR", "XOR"]),
            e(ty),
        )
            .prop_map(move |(x, op, y)| format!("{from_bcd}({to_bcd}({x}) {op} {to_bcd}({y}))"))
            .boxed(),
    ));
    if ty == Ty::Lint && scope.calls_int_function() {
        choices.push((2, int_function_call(below)));
    }
    choices
}

/// The operators of REAL and LREAL: arithmetic, the functions of the C library, EXPT.
fn real(
    scope: Scope,
    ty: Ty,
    below: &[BoxedStrategy<String>],
) -> Vec<(u32, BoxedStrategy<String>)> {
    let e = |t: Ty| below[t.index()].clone();
    let mut choices = vec![
        (5, binary(e(ty), &["+", "-", "*", "/"], e(ty))),
        (1, binary(e(ty), &["**"], e(ty))),
        (1, call("ATAN2", vec![e(ty), e(ty)])),
        (1, e(ty).prop_map(|x| format!("(-{x})")).boxed()),
        (
            2,
            (
                proptest::sample::select(vec!["ABS", "SQRT", "LN", "EXP", "SIN", "ATAN", "ROUND"]),
                e(ty),
            )
                .prop_map(|(name, x)| format!("{name}({x})"))
                .boxed(),
        ),
    ];
    if ty == Ty::Lreal && scope.calls_real_function() {
        choices.push((2, real_function_call(below)));
    }
    choices
}

/// The operators of BOOL: logic, short-circuit logic and comparisons of every type.
fn boolean(scope: Scope, below: &[BoxedStrategy<String>]) -> Vec<(u32, BoxedStrategy<String>)> {
    let e = |t: Ty| below[t.index()].clone();
    let comparisons = ALL
        .iter()
        .map(|ty| binary(e(*ty), &["=", "<>", "<", "<=", ">", ">="], e(*ty)))
        .collect::<Vec<_>>();
    vec![
        (
            3,
            binary(
                e(Ty::Bool),
                &["AND", "OR", "XOR", "AND_THEN", "OR_ELSE"],
                e(Ty::Bool),
            ),
        ),
        (1, e(Ty::Bool).prop_map(|x| format!("(NOT {x})")).boxed()),
        (5, Union::new(comparisons).boxed()),
        (1, bit_of_integer(scope)),
    ]
}

/// One bit of an integer variable (`c_udint.31`, the `GetBit` instruction).
pub fn bit_of_integer(scope: Scope) -> BoxedStrategy<String> {
    Union::new(INTEGERS.iter().map(|ty| {
        let width = ty.width_bits();
        (proptest::sample::select(scope.readable(*ty)), 0..width)
            .prop_map(|(variable, bit)| format!("{variable}.{bit}"))
            .boxed()
    }))
    .boxed()
}

/// The operators of TIME: sums and differences, and scaling by a DINT.
fn duration(below: &[BoxedStrategy<String>]) -> Vec<(u32, BoxedStrategy<String>)> {
    let e = |t: Ty| below[t.index()].clone();
    vec![
        (3, binary(e(Ty::Time), &["+", "-"], e(Ty::Time))),
        (1, binary(e(Ty::Time), &["*"], e(Ty::Dint))),
        (1, binary(e(Ty::Time), &["/"], divisor(Ty::Dint, below))),
        (1, e(Ty::Time).prop_map(|x| format!("(-{x})")).boxed()),
    ]
}

/// `a op b` in parentheses, the operator drawn from `operators`.
fn binary(
    a: BoxedStrategy<String>,
    operators: &[&'static str],
    b: BoxedStrategy<String>,
) -> BoxedStrategy<String> {
    (a, proptest::sample::select(operators.to_vec()), b)
        .prop_map(|(a, op, b)| format!("({a} {op} {b})"))
        .boxed()
}

/// A call of the standard function `name` with positional arguments.
fn call(name: &'static str, arguments: Vec<BoxedStrategy<String>>) -> BoxedStrategy<String> {
    arguments
        .prop_map(move |arguments| format!("{name}({})", arguments.join(", ")))
        .boxed()
}

/// A call of one of `names`, each a function of two arguments.
fn call_of_two(
    names: &[&'static str],
    a: BoxedStrategy<String>,
    b: BoxedStrategy<String>,
) -> BoxedStrategy<String> {
    (proptest::sample::select(names.to_vec()), a, b)
        .prop_map(|(name, a, b)| format!("{name}({a}, {b})"))
        .boxed()
}

/// `MUX(k, …)` with two or three inputs of `input`'s type; `k` is often in range, sometimes
/// below 0 or past the end (which select the first and the last input).
fn mux(input: BoxedStrategy<String>, below: &[BoxedStrategy<String>]) -> BoxedStrategy<String> {
    let selector = Union::new_weighted(vec![
        (
            3,
            (
                -1i128..=3,
                proptest::sample::select(vec![Ty::Dint, Ty::Int, Ty::Sint]),
            )
                .prop_map(|(k, ty)| types::integer_literal(ty, k))
                .boxed(),
        ),
        (1, any_integer(below)),
    ]);
    (selector, proptest::collection::vec(input, 2..=3))
        .prop_map(|(k, inputs)| format!("MUX({k}, {})", inputs.join(", ")))
        .boxed()
}

/// A conversion into `ty` from any other type (`REAL_TO_LINT(…)`), or `TRUNC`-like
/// conversions' counterparts; every pair of the twelve types is a standard function.
fn conversion_into(ty: Ty, below: &[BoxedStrategy<String>]) -> BoxedStrategy<String> {
    let conversions = ALL
        .iter()
        .filter(|from| **from != ty)
        .map(|from| {
            let name = format!("{}_TO_{}", from.name(), ty.name());
            below[from.index()]
                .clone()
                .prop_map(move |x| format!("{name}({x})"))
                .boxed()
        })
        .collect::<Vec<_>>();
    Union::new(conversions).boxed()
}

/// A REAL or LREAL converted into the integer type `ty`, half the time straight from a
/// literal, so the edges of §6.2 (halves, ±2⁶³, values past every width) meet every target.
fn real_into(ty: Ty, below: &[BoxedStrategy<String>]) -> BoxedStrategy<String> {
    let conversions = [Ty::Real, Ty::Lreal].map(|from| {
        let name = format!("{}_TO_{}", from.name(), ty.name());
        Union::new(vec![below[from.index()].clone(), types::literal(from)])
            .prop_map(move |x| format!("{name}({x})"))
            .boxed()
    });
    Union::new(conversions).boxed()
}

/// An element of the scope's array of `ty`, by an index that may fall outside it.
fn element(ty: Ty, below: &[BoxedStrategy<String>]) -> BoxedStrategy<String> {
    let name = format!("r_{}", ty.suffix());
    index(ty, below)
        .prop_map(move |index| format!("{name}[{index}]"))
        .boxed()
}

/// An index into the array of `element`: mostly inside its bounds (a literal of some integer
/// type, or an expression clamped by `LIMIT`), sometimes clamped to one past them (mostly just
/// outside), sometimes any integer expression (mostly outside, an `ULINT` possibly above 2⁶³).
pub fn index(element: Ty, below: &[BoxedStrategy<String>]) -> BoxedStrategy<String> {
    let (low, high) = element.array_bounds();
    let (low, high) = (i128::from(low), i128::from(high));
    let inside = (low..=high, proptest::sample::select(INTEGERS.to_vec()))
        .prop_map(|(value, ty)| {
            let ty = if ty.holds(value) { ty } else { Ty::Dint };
            types::integer_literal(ty, value)
        })
        .boxed();
    let clamped = below[Ty::Dint.index()]
        .clone()
        .prop_map(move |x| format!("LIMIT(DINT#{low}, {x}, DINT#{high})"))
        .boxed();
    // The checker refuses a constant index outside the bounds, so the index just outside
    // them is an expression: clamped one past each bound, it is mostly there.
    let edges = below[Ty::Dint.index()]
        .clone()
        .prop_map(move |x| format!("LIMIT(DINT#{}, {x}, DINT#{})", low - 1, high + 1))
        .boxed();
    // Any expression, inside a call the checker does not evaluate, since a constant one
    // outside the bounds is refused as well.
    let any = Union::new(INTEGERS.iter().map(|ty| {
        (below[ty.index()].clone(), below[ty.index()].clone())
            .prop_map(|(a, b)| format!("MAX({a}, {b})"))
            .boxed()
    }))
    .boxed();
    Union::new_weighted(vec![(36, inside), (18, clamped), (1, edges), (1, any)]).boxed()
}

/// A divisor of `ty` for DIV and MOD: mostly one that cannot be 0 (a literal among 1, −1 and
/// the extremes, or an expression forced away from 0), sometimes any expression, 0 included.
fn divisor(ty: Ty, below: &[BoxedStrategy<String>]) -> BoxedStrategy<String> {
    let e = below[ty.index()].clone();
    let (min, max) = ty.range();
    let mut literals = vec![1, 2, 3, 7, max];
    if ty.is_signed() {
        literals.extend([-1, -2, min]);
    }
    let one = types::integer_literal(ty, 1);
    let mut forced = vec![
        e.clone()
            .prop_map({
                let one = one.clone();
                move |x| format!("MAX({x}, {one})")
            })
            .boxed(),
        e.clone()
            .prop_map(move |x| format!("({x} OR {one})"))
            .boxed(),
    ];
    if ty.is_signed() {
        let minus_one = types::integer_literal(ty, -1);
        forced.push(
            e.clone()
                .prop_map(move |x| format!("MIN({x}, {minus_one})"))
                .boxed(),
        );
    }
    Union::new_weighted(vec![
        (
            3,
            proptest::sample::select(literals)
                .prop_map(move |value| types::integer_literal(ty, value))
                .boxed(),
        ),
        (4, Union::new(forced).boxed()),
        (1, e),
    ])
    .boxed()
}

/// A shift or rotation count: a literal from 0 past every width (70), or any integer
/// expression of any integer type.
fn shift_count(below: &[BoxedStrategy<String>]) -> BoxedStrategy<String> {
    Union::new_weighted(vec![
        (
            3,
            (
                0i128..=70,
                proptest::sample::select(vec![Ty::Usint, Ty::Int, Ty::Dint, Ty::Ulint]),
            )
                .prop_map(|(count, ty)| types::integer_literal(ty, count))
                .boxed(),
        ),
        (1, any_integer(below)),
    ])
    .boxed()
}

/// An expression of any integer type.
fn any_integer(below: &[BoxedStrategy<String>]) -> BoxedStrategy<String> {
    Union::new(INTEGERS.iter().map(|ty| below[ty.index()].clone())).boxed()
}

/// An expression of REAL or LREAL.
fn real_of_either_width(below: &[BoxedStrategy<String>]) -> BoxedStrategy<String> {
    Union::new(vec![
        below[Ty::Real.index()].clone(),
        below[Ty::Lreal.index()].clone(),
    ])
    .boxed()
}

/// A call of the generated `FnI : LINT`.
fn int_function_call(below: &[BoxedStrategy<String>]) -> BoxedStrategy<String> {
    (
        below[Ty::Dint.index()].clone(),
        below[Ty::Lreal.index()].clone(),
        below[Ty::Bool.index()].clone(),
    )
        .prop_map(|(d, l, b)| format!("FnI(a_dint := {d}, a_lreal := {l}, a_bool := {b})"))
        .boxed()
}

/// A call of the generated `FnR : LREAL`.
fn real_function_call(below: &[BoxedStrategy<String>]) -> BoxedStrategy<String> {
    (
        below[Ty::Lint.index()].clone(),
        below[Ty::Real.index()].clone(),
        below[Ty::Time.index()].clone(),
    )
        .prop_map(|(l, r, t)| format!("FnR(a_lint := {l}, a_real := {r}, a_time := {t})"))
        .boxed()
}
