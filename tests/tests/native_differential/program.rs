//! A whole generated source: `FnI`, `FnR`, `FB_Gen` and `PROGRAM main`.

use proptest::prelude::*;

use super::expressions::Expressions;
use super::scope::{FOR_COUNTERS, Scope, WHILE_COUNTERS};
use super::statements::Statements;
use super::types::{self, ALL, Ty};

/// How many operators deep the expressions of each POU go.
const EXPRESSION_DEPTH: usize = 3;

/// How deep statements nest in the program; the function block and the functions nest one
/// level less, so the loops of a call inside a loop stay few.
const PROGRAM_NESTING: usize = 3;

/// The strategy of whole sources, one program each, that the compiler must accept.
pub fn source() -> BoxedStrategy<String> {
    // The lists may shrink to nothing but the program's one statement, so a failing case
    // shrinks to the statements it needs.
    let int_function = pou(Scope::FunctionInt, PROGRAM_NESTING - 1, 0..=4);
    let real_function = pou(Scope::FunctionReal, PROGRAM_NESTING - 1, 0..=4);
    let block = pou(Scope::Block, PROGRAM_NESTING - 1, 0..=5);
    let program = pou(Scope::Program, PROGRAM_NESTING, 1..=8);
    (int_function, real_function, block, program)
        .prop_map(|(int_function, real_function, block, program)| {
            format!("{int_function}\n{real_function}\n{block}\n{program}\n")
        })
        .boxed()
}

/// One POU of `scope`: its declarations with drawn initial values and `count` statements.
fn pou(
    scope: Scope,
    nesting: usize,
    count: std::ops::RangeInclusive<usize>,
) -> BoxedStrategy<String> {
    let expressions = Expressions::new(scope, EXPRESSION_DEPTH);
    let statements = Statements::new(scope, &expressions, nesting);
    let initial_values = ALL
        .iter()
        .map(|ty| {
            (
                types::literal(*ty),
                types::literal(*ty),
                types::literal(*ty),
            )
        })
        .collect::<Vec<_>>();
    let result = match scope {
        Scope::FunctionInt => expressions.of(Ty::Lint).prop_map(Some).boxed(),
        Scope::FunctionReal => expressions.of(Ty::Lreal).prop_map(Some).boxed(),
        Scope::Program | Scope::Block => Just(None).boxed(),
    };
    (initial_values, statements.list(count), result)
        .prop_map(move |(initial_values, body, result)| {
            let mut text = header(scope);
            text.push_str(&declarations(scope, &initial_values));
            if scope.has_pointers() {
                // A pointer starts null; it points into its array before the first use, and
                // then keeps what the statements make of it from cycle to cycle.
                for ty in ALL {
                    let suffix = ty.suffix();
                    let (low, _) = ty.array_bounds();
                    let low = types::integer_literal(Ty::Dint, low.into());
                    text.push_str(&format!(
                        "IF p_{suffix} = 0 THEN p_{suffix} := ADR(r_{suffix}[{low}]); END_IF;\n"
                    ));
                }
            }
            text.push_str(&body);
            text.push('\n');
            if let Some(result) = result {
                text.push_str(&format!("{} := {result};\n", scope.pou_name()));
            }
            text.push_str(match scope {
                Scope::Program => "END_PROGRAM",
                Scope::Block => "END_FUNCTION_BLOCK",
                Scope::FunctionReal | Scope::FunctionInt => "END_FUNCTION",
            });
            text
        })
        .boxed()
}

/// The POU's first line.
fn header(scope: Scope) -> String {
    match scope {
        Scope::Program => "PROGRAM main\n".to_owned(),
        Scope::Block => "FUNCTION_BLOCK FB_Gen\n".to_owned(),
        Scope::FunctionReal => "FUNCTION FnR : LREAL\n".to_owned(),
        Scope::FunctionInt => "FUNCTION FnI : LINT\n".to_owned(),
    }
}

/// The declarations of every variable the generator may name in `scope`, with the initial
/// values drawn for `a_T`, `b_T` and `c_T`.
fn declarations(scope: Scope, initial_values: &[(String, String, String)]) -> String {
    let variable = |prefix: &str, ty: Ty, value: &str| {
        format!("  {prefix}_{} : {} := {value};\n", ty.suffix(), ty.name())
    };
    let mut inputs = String::new();
    let mut outputs = String::new();
    let mut locals = String::new();
    for (ty, (a, b, c)) in ALL.iter().zip(initial_values) {
        let ty = *ty;
        match scope {
            Scope::Program => locals.push_str(&variable("a", ty, a)),
            Scope::Block | Scope::FunctionReal | Scope::FunctionInt => {
                inputs.push_str(&variable("a", ty, a));
            }
        }
        match scope {
            Scope::Block => outputs.push_str(&variable("b", ty, b)),
            _ => locals.push_str(&variable("b", ty, b)),
        }
        locals.push_str(&variable("c", ty, c));
        let (low, high) = ty.array_bounds();
        locals.push_str(&format!(
            "  r_{} : ARRAY[{low}..{high}] OF {};\n",
            ty.suffix(),
            ty.name()
        ));
        if scope.has_pointers() {
            locals.push_str(&format!(
                "  p_{} : POINTER TO {};\n",
                ty.suffix(),
                ty.name()
            ));
        }
    }
    for (name, ty) in FOR_COUNTERS {
        locals.push_str(&format!("  {name} : {};\n", ty.name()));
    }
    for name in WHILE_COUNTERS {
        locals.push_str(&format!("  {name} : DINT;\n"));
    }
    if scope.has_instances() {
        locals.push_str("  fb1 : FB_Gen;\n  fb2 : FB_Gen;\n");
    }
    let mut text = String::new();
    if !inputs.is_empty() {
        text.push_str(&format!("VAR_INPUT\n{inputs}END_VAR\n"));
    }
    if !outputs.is_empty() {
        text.push_str(&format!("VAR_OUTPUT\n{outputs}END_VAR\n"));
    }
    text.push_str(&format!("VAR\n{locals}END_VAR\n"));
    text
}
