//! Tests of the IL parser: every instruction form, and the errors with their lines.

use expect_test::{Expect, expect};

use super::parse::{IlItem, parse};
use crate::diagnostic::line_column;

/// Each item of `text` on a line: `line: label` or `line: operator flags 'operand'`, then the
/// errors as `line:column code message`.
#[track_caller]
fn check(text: &str, expect: Expect) {
    let program = parse(text);
    let mut out = String::new();
    for item in &program.items {
        match item {
            IlItem::Label { name, range } => {
                let (line, _) = line_column(text, range.start);
                out.push_str(&format!("{line}: label {name}\n"));
            }
            IlItem::Instruction(instruction) => {
                let (line, _) = line_column(text, instruction.range.start);
                let mut flags = String::new();
                for (set, flag) in [
                    (instruction.negated, " N"),
                    (instruction.conditional, " C"),
                    (instruction.deferred, " ("),
                ] {
                    if set {
                        flags.push_str(flag);
                    }
                }
                let operand = instruction
                    .operand
                    .as_ref()
                    .map(|(text, _)| format!(" '{text}'"))
                    .unwrap_or_default();
                out.push_str(&format!(
                    "{line}: {:?}{flags}{operand}\n",
                    instruction.operator
                ));
            }
        }
    }
    for error in &program.errors {
        let (line, column) = line_column(text, error.range.start);
        out.push_str(&format!(
            "error {line}:{column} {}: {}\n",
            error.code.id(),
            error.message
        ));
    }
    expect.assert_eq(&out);
}

#[test]
fn every_operator_and_modifier_is_read_case_insensitively() {
    check(
        "LD a\nldn b\nST c\nSTN d\nS e\nR f\nAND g\nANDN h\n& i\n&N j\nOR k\nORN l\nXOR m\nXORN n\nNOT\nADD 1\nSUB 2\nMUL 3\nDIV 4\nMOD 5\nGT 6\nGE 7\nEQ 8\nNE 9\nLE 10\nLT 11\n",
        expect![[r#"
            1: Load 'a'
            2: Load N 'b'
            3: Store 'c'
            4: Store N 'd'
            5: Set 'e'
            6: Reset 'f'
            7: Binary(And) 'g'
            8: Binary(And) N 'h'
            9: Binary(And) 'i'
            10: Binary(And) N 'j'
            11: Binary(Or) 'k'
            12: Binary(Or) N 'l'
            13: Binary(Xor) 'm'
            14: Binary(Xor) N 'n'
            15: Not
            16: Binary(Add) '1'
            17: Binary(Sub) '2'
            18: Binary(Mul) '3'
            19: Binary(Div) '4'
            20: Binary(Mod) '5'
            21: Binary(Gt) '6'
            22: Binary(Ge) '7'
            23: Binary(Eq) '8'
            24: Binary(Ne) '9'
            25: Binary(Le) '10'
            26: Binary(Lt) '11'
        "#]],
    );
}

#[test]
fn jumps_calls_returns_labels_parentheses_and_functions() {
    check(
        "Start: LD a\nJMP Start\nJMPC Start\nJMPCN Start\nCAL t(IN := a, PT := T#1s)\nCALC t\nCALCN t(\n  IN := b)\nRET\nRETC\nRETCN\nAND( b\nOR(\nLD c\n)\n)\nLIMIT 0, 10\nLEN\nMAX(IN1 := 1, IN2 := 2)\nCU ctr\nIN tmr\nEnd:\n",
        expect![[r#"
            1: label Start
            1: Load 'a'
            2: Jump 'Start'
            3: Jump C 'Start'
            4: Jump N C 'Start'
            5: Call 't(IN := a, PT := T#1s)'
            6: Call C 't'
            7: Call N C 't(
              IN := b)'
            9: Return
            10: Return C
            11: Return N C
            12: Binary(And) ( 'b'
            13: Binary(Or) (
            14: Load 'c'
            15: Close
            16: Close
            17: Function("LIMIT") '0, 10'
            18: Function("LEN")
            19: Function("MAX") '(IN1 := 1, IN2 := 2)'
            20: BlockInput("CU") 'ctr'
            21: BlockInput("IN") 'tmr'
            22: label End
        "#]],
    );
}

#[test]
fn comments_are_skipped_even_across_lines_and_strings_keep_their_comment_marks() {
    check(
        "(* a comment\n   over lines *) LD a // the start\nST s (* inline *)\nLD '(* not a comment *)'\n",
        expect![[r#"
            2: Load 'a'
            3: Store 's'
            4: Load ''(* not a comment *)''
        "#]],
    );
}

#[test]
fn malformed_lines_are_errors_at_their_line_and_the_others_are_still_read() {
    check(
        "LD\nNOT a\nRET x\n)  y\n1st\nLD b\n2nd: LD c\n",
        expect![[r#"
            6: Load 'b'
            7: Load 'c'
            error 1:1 E0136: 'LD' needs an operand
            error 2:5 E0136: 'NOT' takes no operand, but 'a' follows it
            error 3:5 E0136: 'RET' takes no operand, but 'x' follows it
            error 4:4 E0136: ')' takes no operand, but 'y' follows it
            error 5:1 E0136: '1st' is not an instruction; expected an operator or a function
            error 7:1 E0136: '2nd' is not a valid label; a label is an identifier
        "#]],
    );
}
