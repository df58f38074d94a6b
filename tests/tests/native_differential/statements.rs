//! Statements over the expressions of one scope: assignments, IF, CASE, bounded loops, calls
//! of the function block, pointers to array elements.
//!
//! A statement at depth `d` holds statements of depth `d - 1` only, and the loop at depth `d`
//! counts with the `d`-th counter (`scope::FOR_COUNTERS`, `scope::WHILE_COUNTERS`), which no
//! generated assignment writes: nested loops never share a counter and every loop ends after
//! a few iterations.

use proptest::prelude::*;
use proptest::strategy::Union;

use super::expressions::Expressions;
use super::scope::{FOR_COUNTERS, Scope, WHILE_COUNTERS};
use super::types::{self, ALL, INTEGERS, Ty};

/// The statement strategies of one scope, by depth and by whether they sit in a loop.
pub struct Statements {
    /// `levels[d][in_loop as usize]`: one statement at most `d` levels deep.
    levels: Vec<[BoxedStrategy<String>; 2]>,
}

impl Statements {
    /// The statements of `scope` over `expressions`, nested at most `depth` levels.
    pub fn new(scope: Scope, expressions: &Expressions, depth: usize) -> Self {
        let simple = [false, true].map(|in_loop| simple(scope, expressions, in_loop));
        let mut levels = vec![simple.clone()];
        for level in 1..=depth {
            let below = levels[level - 1].clone();
            let next = [false, true].map(|in_loop| {
                let body = |in_loop: bool| list(below[usize::from(in_loop)].clone(), 1..=3);
                let condition = || expressions.of(Ty::Bool);
                Union::new_weighted(vec![
                    (4, simple[usize::from(in_loop)].clone()),
                    (1, if_statement(condition(), body(in_loop))),
                    (1, case_statement(expressions, body(in_loop))),
                    (1, for_statement(level, expressions, body(true))),
                    (1, while_statement(level, condition(), body(true))),
                    (1, repeat_statement(level, condition(), body(true))),
                ])
                .boxed()
            });
            levels.push(next);
        }
        Self { levels }
    }

    /// A list of `count` statements outside any loop, as deep as this table goes.
    pub fn list(&self, count: std::ops::RangeInclusive<usize>) -> BoxedStrategy<String> {
        let top = &self.levels[self.levels.len() - 1];
        list(top[0].clone(), count)
    }
}

/// `count` statements of `statement`, one after the other.
fn list(
    statement: BoxedStrategy<String>,
    count: std::ops::RangeInclusive<usize>,
) -> BoxedStrategy<String> {
    proptest::collection::vec(statement, count)
        .prop_map(|statements| statements.join("\n"))
        .boxed()
}

/// `text` indented by two spaces, line by line.
fn indented(text: &str) -> String {
    text.lines()
        .map(|line| format!("  {line}\n"))
        .collect::<String>()
}

/// The statements that hold no other: assignments, pointers set, the block called, and in a
/// loop a conditional EXIT or CONTINUE.
fn simple(scope: Scope, expressions: &Expressions, in_loop: bool) -> BoxedStrategy<String> {
    let assignments = ALL
        .iter()
        .map(|ty| {
            (target(scope, expressions, *ty), expressions.of(*ty))
                .prop_map(|(target, value)| format!("{target} := {value};"))
                .boxed()
        })
        .collect::<Vec<_>>();
    // One bit of an integer variable set (the `SetBit` instruction).
    let bits = Union::new(INTEGERS.iter().map(|ty| {
        let width = ty.width_bits();
        (
            // Variables only: not the function's result.
            proptest::sample::select(
                scope
                    .writable(*ty)
                    .into_iter()
                    .filter(|name| name.contains('_'))
                    .collect::<Vec<_>>(),
            ),
            0..width,
            expressions.of(Ty::Bool),
        )
            .prop_map(|(variable, bit, value)| format!("{variable}.{bit} := {value};"))
            .boxed()
    }));
    // A conversion into BCD (the `TO_BCD` instruction) kept whole: its code is the bit string
    // of the argument's width, converted explicitly into the integer of that width (as every
    // change of type the generator writes is explicit); inside expressions it is written by
    // `expressions.rs`.
    let to_bcd = Union::new(INTEGERS.iter().map(|ty| {
        let name = format!("{}_TO_BCD", ty.name());
        let code = match ty.width_bits() {
            8 => "BYTE",
            16 => "WORD",
            32 => "DWORD",
            _ => "LWORD",
        };
        let back = format!("{code}_TO_{}", ty.name());
        (
            proptest::sample::select(scope.writable(*ty)),
            expressions.of(*ty),
        )
            .prop_map(move |(target, value)| format!("{target} := {back}({name}({value}));"))
            .boxed()
    }));
    let mut choices = vec![
        (8, Union::new(assignments).boxed()),
        (1, bits.boxed()),
        (1, to_bcd.boxed()),
    ];
    if scope.has_pointers() {
        let pointers = ALL
            .iter()
            .map(|ty| {
                let suffix = ty.suffix();
                expressions
                    .index(*ty)
                    .prop_map(move |index| format!("p_{suffix} := ADR(r_{suffix}[{index}]);"))
                    .boxed()
            })
            .collect::<Vec<_>>();
        choices.push((1, Union::new(pointers).boxed()));
    }
    if scope.has_instances() {
        choices.push((2, block_call(expressions)));
    }
    if in_loop {
        choices.push((
            1,
            (
                expressions.of(Ty::Bool),
                proptest::sample::select(vec!["EXIT", "CONTINUE"]),
            )
                .prop_map(|(condition, jump)| format!("IF {condition} THEN {jump}; END_IF;"))
                .boxed(),
        ));
    }
    Union::new_weighted(choices).boxed()
}

/// A place of type `ty` to assign: a variable, an array element (by an index that may fall
/// outside) or, in the program, what a pointer points to.
fn target(scope: Scope, expressions: &Expressions, ty: Ty) -> BoxedStrategy<String> {
    let suffix = ty.suffix();
    let array = format!("r_{suffix}");
    let mut choices = vec![
        (3, proptest::sample::select(scope.writable(ty)).boxed()),
        (
            2,
            expressions
                .index(ty)
                .prop_map(move |index| format!("{array}[{index}]"))
                .boxed(),
        ),
    ];
    if scope.has_pointers() {
        choices.push((1, Just(format!("p_{suffix}^")).boxed()));
    }
    Union::new_weighted(choices).boxed()
}

/// A call of `fb1` or `fb2`: an integer input, another input, and an output read back, each
/// there or not.
fn block_call(expressions: &Expressions) -> BoxedStrategy<String> {
    let input = |types: &[Ty]| {
        Union::new(types.iter().map(|ty| {
            let suffix = ty.suffix();
            expressions
                .of(*ty)
                .prop_map(move |value| format!("a_{suffix} := {value}"))
                .boxed()
        }))
        .boxed()
    };
    let output = proptest::sample::select(ALL.to_vec())
        .prop_map(|ty| format!("b_{0} => c_{0}", ty.suffix()))
        .boxed();
    (
        proptest::sample::select(vec!["fb1", "fb2"]),
        proptest::option::of(input(&INTEGERS)),
        proptest::option::of(input(&[Ty::Bool, Ty::Real, Ty::Lreal, Ty::Time])),
        proptest::option::of(output),
    )
        .prop_map(|(instance, first, second, output)| {
            let arguments = [first, second, output]
                .into_iter()
                .flatten()
                .collect::<Vec<_>>();
            format!("{instance}({});", arguments.join(", "))
        })
        .boxed()
}

/// `IF … THEN … ELSIF … ELSE … END_IF;` with up to two ELSIFs and maybe an ELSE.
fn if_statement(
    condition: BoxedStrategy<String>,
    body: BoxedStrategy<String>,
) -> BoxedStrategy<String> {
    (
        condition.clone(),
        body.clone(),
        proptest::collection::vec((condition, body.clone()), 0..=2),
        proptest::option::of(body),
    )
        .prop_map(|(condition, then, elsifs, otherwise)| {
            let mut text = format!("IF {condition} THEN\n{}", indented(&then));
            for (condition, body) in elsifs {
                text.push_str(&format!("ELSIF {condition} THEN\n{}", indented(&body)));
            }
            if let Some(body) = otherwise {
                text.push_str(&format!("ELSE\n{}", indented(&body)));
            }
            text.push_str("END_IF;");
            text
        })
        .boxed()
}

/// `CASE` over an integer selector of any integer type (often reduced `MOD 6` so its arms
/// are taken) with a single label, a list, a range and maybe ELSE.
fn case_statement(expressions: &Expressions, body: BoxedStrategy<String>) -> BoxedStrategy<String> {
    let selector = Union::new(INTEGERS.iter().map(|ty| {
        let six = types::integer_literal(*ty, 6);
        Union::new(vec![
            expressions.of(*ty),
            expressions
                .of(*ty)
                .prop_map(move |x| format!("({x} MOD {six})"))
                .boxed(),
        ])
        .boxed()
    }));
    (
        selector,
        body.clone(),
        proptest::option::of(body.clone()),
        proptest::option::of(body.clone()),
        proptest::option::of(body),
    )
        .prop_map(|(selector, zero, list, range, otherwise)| {
            let mut text = format!("CASE {selector} OF\n0:\n{}", indented(&zero));
            if let Some(body) = list {
                text.push_str(&format!("1, 2:\n{}", indented(&body)));
            }
            if let Some(body) = range {
                text.push_str(&format!("3..5:\n{}", indented(&body)));
            }
            if let Some(body) = otherwise {
                text.push_str(&format!("ELSE\n{}", indented(&body)));
            }
            text.push_str("END_CASE;");
            text
        })
        .boxed()
}

/// `FOR` with the counter of `level` from a small start to a small end (a literal or an
/// expression clamped by `LIMIT`) by a step of ±1 to ±3, or without `BY`.
fn for_statement(
    level: usize,
    expressions: &Expressions,
    body: BoxedStrategy<String>,
) -> BoxedStrategy<String> {
    let (counter, ty) = FOR_COUNTERS[level - 1];
    let end = Union::new(vec![
        (-4i128..=8)
            .prop_map(move |end| types::integer_literal(ty, end))
            .boxed(),
        expressions
            .of(ty)
            .prop_map(move |x| {
                format!(
                    "LIMIT({}, {x}, {})",
                    types::integer_literal(ty, -4),
                    types::integer_literal(ty, 8)
                )
            })
            .boxed(),
    ]);
    let step = proptest::option::of(proptest::sample::select(vec![1i128, 2, 3, -1, -2, -3]));
    (-4i128..=4, end, step, body)
        .prop_map(move |(start, end, step, body)| {
            let start = types::integer_literal(ty, start);
            let by = step.map_or(String::new(), |step| {
                format!(" BY {}", types::integer_literal(ty, step))
            });
            format!(
                "FOR {counter} := {start} TO {end}{by} DO\n{}END_FOR;",
                indented(&body)
            )
        })
        .boxed()
}

/// `WHILE` that runs at most a few times: its counter (of `level`) is set to 0 before it,
/// tested with the condition and counted first thing in the body, so CONTINUE counts too.
fn while_statement(
    level: usize,
    condition: BoxedStrategy<String>,
    body: BoxedStrategy<String>,
) -> BoxedStrategy<String> {
    let counter = WHILE_COUNTERS[level - 1];
    (0i128..=6, condition, body)
        .prop_map(move |(limit, condition, body)| {
            format!(
                "{counter} := DINT#0;\nWHILE ({counter} < DINT#{limit}) AND {condition} DO\n  {counter} := {counter} + DINT#1;\n{}END_WHILE;",
                indented(&body)
            )
        })
        .boxed()
}

/// `REPEAT` that runs at most a few times, counted as [`while_statement`] counts.
fn repeat_statement(
    level: usize,
    condition: BoxedStrategy<String>,
    body: BoxedStrategy<String>,
) -> BoxedStrategy<String> {
    let counter = WHILE_COUNTERS[level - 1];
    (1i128..=6, condition, body)
        .prop_map(move |(limit, condition, body)| {
            format!(
                "{counter} := DINT#0;\nREPEAT\n  {counter} := {counter} + DINT#1;\n{}UNTIL ({counter} >= DINT#{limit}) OR {condition}\nEND_REPEAT;",
                indented(&body)
            )
        })
        .boxed()
}
