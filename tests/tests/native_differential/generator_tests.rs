//! The generator writes what §11.2 lists: every construct appears among a few dozen programs,
//! so the property test cannot pass by generating too little.

use proptest::strategy::{Strategy, ValueTree};
use proptest::test_runner::TestRunner;

use super::types::ALL;

/// Programs drawn for the checks below.
const SAMPLES: usize = 40;

/// `SAMPLES` programs from the generator, from a fixed seed.
fn samples() -> Vec<String> {
    let mut runner = TestRunner::deterministic();
    let strategy = super::program::source();
    (0..SAMPLES)
        .map(|_| match strategy.new_tree(&mut runner) {
            Ok(tree) => tree.current(),
            Err(reason) => panic!("the generator gave up: {reason}"),
        })
        .collect()
}

#[test]
fn the_generator_writes_every_construct_the_spec_lists() {
    let programs = samples();
    let mut constructs = vec![
        // Arithmetic, DIV and MOD, bits, logic and comparisons.
        " + ",
        " - ",
        " * ",
        " / ",
        " MOD ",
        " AND ",
        " OR ",
        " XOR ",
        "AND_THEN",
        "OR_ELSE",
        "NOT ",
        "(-",
        " ** ",
        " = ",
        " <> ",
        " < ",
        " <= ",
        " > ",
        " >= ",
        // Shifts, rotations, selections and the other functions.
        "SHL(",
        "SHR(",
        "ROL(",
        "ROR(",
        "MIN(",
        "MAX(",
        "LIMIT(",
        "SEL(",
        "MUX(",
        "ABS(",
        "SQRT(",
        "LN(",
        "EXP(",
        "SIN(",
        "ATAN(",
        "ATAN2(",
        "ROUND(",
        "TRUNC(",
        "_TO_BCD(",
        "BCD_TO_",
        // Conversions, REAL to integer among them.
        "REAL_TO_LINT(",
        "LREAL_TO_ULINT(",
        "REAL_TO_SINT(",
        "TIME_TO_",
        "_TO_TIME(",
        "_TO_BOOL(",
        "BOOL_TO_",
        // Edges among the literals and the specials.
        "REAL#0.0 / REAL#0.0",
        "LREAL#1.0 / LREAL#0.0",
        "LREAL#-1.0 / LREAL#0.0",
        "#-0.0",
        "LREAL#9.223372036854776e18",
        "LINT#9223372036854775807",
        "LINT#-9223372036854775808",
        "ULINT#9223372036854775808",
        "ULINT#18446744073709551615",
        "T#-",
        "TRUE",
        "FALSE",
        // Statements.
        "IF ",
        "ELSIF ",
        "ELSE\n",
        "CASE ",
        "1, 2:",
        "3..5:",
        "FOR ",
        " BY DINT#-",
        " BY INT#-",
        "WHILE ",
        "REPEAT\n",
        "EXIT;",
        "CONTINUE;",
        // Arrays (with a low bound other than 1), calls, pointers.
        "r_dint[",
        "r_time[",
        "LIMIT(DINT#-5, ",
        "FnI(",
        "FnR(",
        "fb1(",
        "fb2(",
        "=> c_",
        "fb1.b_",
        "ADR(r_",
        "p_lreal^",
    ];
    let type_names = ALL.map(|ty| format!("{}#", ty.name()));
    constructs.extend(
        type_names
            .iter()
            .filter(|name| !matches!(name.as_str(), "BOOL#" | "TIME#"))
            .map(String::as_str),
    );
    // One bit of an integer read (`a_dint.5`) and one set (`c_udint.31 := …`).
    let bit = |program: &str, assigned: bool| {
        program.lines().any(|line| {
            line.split(|c: char| !(c.is_alphanumeric() || c == '_' || c == '.'))
                .any(|word| {
                    word.split_once('.').is_some_and(|(name, bit)| {
                        name.contains('_')
                            && bit.parse::<u32>().is_ok()
                            && (!assigned || line.trim_start().starts_with(word))
                    })
                })
        })
    };
    assert!(programs.iter().any(|p| bit(p, false)), "no bit read");
    assert!(programs.iter().any(|p| bit(p, true)), "no bit set");
    // A BCD code inside an operator, decoded again (`BCD_TO_INT(INT_TO_BCD(…) OR …)`).
    let bcd_operand = |program: &str| {
        super::types::INTEGERS
            .iter()
            .any(|ty| program.contains(&format!("BCD_TO_{0}({0}_TO_BCD(", ty.name())))
    };
    assert!(
        programs.iter().any(|p| bcd_operand(p)),
        "no BCD code in an operator"
    );
    let missing = constructs
        .iter()
        .filter(|construct| !programs.iter().any(|program| program.contains(**construct)))
        .collect::<Vec<_>>();
    assert!(
        missing.is_empty(),
        "no program of {SAMPLES} contains {missing:?}"
    );
}

#[test]
fn indices_fall_outside_their_array_only_sometimes() {
    // Indices outside their arrays must appear, but most element accesses must stay inside, or
    // nearly every program would stop at its first statement with a fault and the rest of it
    // would go untested.
    let all = samples().join("\n");
    let (mut inside, mut edges, mut unknown) = (0, 0, 0);
    for ty in ALL {
        let (low, high) = ty.array_bounds();
        let array = format!("r_{}[", ty.suffix());
        for index in indices(&all, &array) {
            let literal = index
                .split_once('#')
                .and_then(|(_, value)| value.parse::<i64>().ok());
            match literal {
                Some(value) => {
                    assert!(
                        (low..=high).contains(&value),
                        "the constant index {index} of {array}] is outside {low}..{high}, which the checker refuses"
                    );
                    inside += 1;
                }
                None if index.starts_with(&format!("LIMIT(DINT#{low}, ")) => inside += 1,
                None if index.starts_with(&format!("LIMIT(DINT#{}, ", low - 1)) => edges += 1,
                None if index.starts_with("MAX(") => unknown += 1,
                None => panic!("{array}{index}] is an index the generator does not write"),
            }
        }
    }
    assert!(edges > 0, "no index clamped to one past the bounds");
    assert!(unknown > 0, "no index by any expression");
    assert!(
        inside > 2 * (edges + unknown),
        "{inside} indices inside, {edges} at the edges and {unknown} by any expression"
    );
}

/// The index texts of every `array[…]` in `text` (`array` ends with the bracket).
fn indices<'t>(text: &'t str, array: &str) -> Vec<&'t str> {
    let mut found = Vec::new();
    for (at, _) in text.match_indices(array) {
        let start = at + array.len();
        let mut depth = 1;
        for (offset, character) in text[start..].char_indices() {
            match character {
                '[' => depth += 1,
                ']' => depth -= 1,
                _ => {}
            }
            if depth == 0 {
                found.push(&text[start..start + offset]);
                break;
            }
        }
    }
    found
}
