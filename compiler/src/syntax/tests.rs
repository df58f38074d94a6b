//! Parser tests: losslessness, error messages and positions, pathological input, golden trees.

use expect_test::expect;

use super::{parse, parse_statements};

/// Parses `text` and checks that the tree gives back exactly the input.
#[track_caller]
fn parse_lossless(text: &str) -> super::Parse {
    let parse = parse(text);
    assert_eq!(parse.syntax().to_string(), text, "the tree lost text");
    parse
}

/// The errors as `line:column: message`, for compact assertions.
fn errors_at(text: &str) -> Vec<String> {
    parse_lossless(text)
        .errors()
        .iter()
        .map(|error| {
            let before = &text[..error.range.start];
            let line = before.matches('\n').count() + 1;
            let column = before.len() - before.rfind('\n').map_or(0, |i| i + 1) + 1;
            format!("{line}:{column}: {}", error.message)
        })
        .collect()
}

const CONVEYOR: &str = "\
FUNCTION_BLOCK FB_Conveyor EXTENDS FB_Base IMPLEMENTS I_Drive
VAR_INPUT
    xStart AT %IX0.0 : BOOL; (* start (* nested *) *)
    tDelay : TIME := T#2S;
END_VAR
VAR_OUTPUT xMotor : BOOL; END_VAR
VAR RETAIN
    aValues : ARRAY[1..3, 0..1] OF INT := [2(0), 4(1)];
    pValue : POINTER TO INT;
    sName : STRING(20) := 'it$'s';
    stPoint : ST_Point := (x := 1, y := 2);
END_VAR
{attribute 'hide'}
IF xStart AND NOT xMotor THEN
    xMotor S= TRUE;
ELSIF aValues[1, 0] >= 16#FF THEN
    pValue^ := -2 ** 2 + INT#5 MOD 3;
ELSE
    ton(IN := xStart, PT := tDelay, Q => xMotor, ET => );
END_IF
CASE iState OF
    0, 1: iState := iState + 1;
    2..5, E_State.Idle: RETURN;
ELSE
    ;
END_CASE
FOR i := 1 TO 10 BY 2 DO
    IF i = 5 THEN EXIT; END_IF
END_FOR
WHILE x < 10 DO x := x + 1; END_WHILE
REPEAT x := x - 1; UNTIL x <= 0 END_REPEAT
METHOD PUBLIC Reset : BOOL
VAR_INPUT xHard : BOOL; END_VAR
Reset := THIS^.xMotor OR_ELSE SUPER^.Reset();
END_METHOD
END_FUNCTION_BLOCK
";

#[test]
fn a_function_block_with_every_kind_of_statement_parses_cleanly() {
    let parse = parse_lossless(CONVEYOR);
    assert!(parse.errors().is_empty(), "{:?}", parse.errors());
}

#[test]
fn types_global_lists_interfaces_and_configurations_parse_cleanly() {
    let text = "\
{attribute 'qualified_only'}
TYPE E_Color : (Red := 1, Green, Blue) DINT := Green; END_TYPE
TYPE ST_Point EXTENDS ST_Base : STRUCT x : REAL; y : REAL := 1.5E3; END_STRUCT END_TYPE
TYPE U_Word : UNION w : WORD; b : ARRAY[0..1] OF BYTE; END_UNION END_TYPE
TYPE T_Percent : INT(0..100); T_Ref : REFERENCE TO INT; END_TYPE
VAR_GLOBAL CONSTANT gc_Max : INT := 10; END_VAR
VAR_GLOBAL PERSISTENT RETAIN g_Count : UDINT; END_VAR
VAR_CONFIG Main.fb.xIn AT %IX1.0 : BOOL; END_VAR
INTERFACE I_Drive EXTENDS I_Base
METHOD Start : BOOL END_METHOD
PROPERTY Speed : REAL END_PROPERTY
END_INTERFACE
FUNCTION F_Add : INT VAR_INPUT a, b : INT; END_VAR F_Add := a + b; END_FUNCTION
CONFIGURATION Cell
    RESOURCE Cpu ON PLC
        TASK Fast (INTERVAL := T#2ms, PRIORITY := 0);
        PROGRAM Inst WITH Fast : Main;
    END_RESOURCE
END_CONFIGURATION
";
    let parse = parse_lossless(text);
    assert!(parse.errors().is_empty(), "{:#?}", parse.errors());
}

#[test]
fn a_missing_semicolon_is_reported_where_it_belongs_and_parsing_goes_on() {
    let text = "PROGRAM P\nx := 1\ny := 2;\nIF x THEN\nEND_PROGRAM\n";
    assert_eq!(
        errors_at(text),
        vec![
            "2:7: expected ';' after the statement, found 'y'",
            "4:10: expected END_IF to close the IF, found END_PROGRAM",
        ]
    );
}

#[test]
fn errors_say_what_was_found_and_what_was_expected() {
    assert_eq!(
        errors_at("PROGRAM P\nVAR x INT; END_VAR\nx := (1 + ;\nEND_PROGRAM"),
        vec![
            "2:6: expected ':' before the type, found 'INT'",
            // Reported once: the missing ')' trips over the same ';'.
            "3:11: expected an expression, found ';'",
        ]
    );
    assert_eq!(
        errors_at("PROGRAM P\nTHEN x := 1;\nEND_PROGRAM"),
        vec!["2:1: expected a statement, found THEN"]
    );
}

#[test]
fn a_missing_end_keeps_the_next_pou_intact() {
    let text = "PROGRAM A\nx := 1;\nPROGRAM B\ny := 2;\nEND_PROGRAM\n";
    let parse = parse_lossless(text);
    let pous = parse
        .syntax()
        .children()
        .filter(|node| node.kind() == super::SyntaxKind::POU)
        .count();
    assert_eq!(pous, 2);
    assert_eq!(
        errors_at(text),
        vec!["2:8: expected END_PROGRAM to close the declaration, found PROGRAM"]
    );
}

#[test]
fn ten_thousand_nested_parentheses_give_one_error_not_a_crash() {
    let text = format!("x := {}1{};", "(".repeat(10_000), ")".repeat(10_000));
    let parse = parse_statements(&text);
    assert_eq!(parse.syntax().to_string(), text);
    assert_eq!(parse.errors().len(), 1, "{:?}", parse.errors());
    assert_eq!(parse.errors()[0].code, crate::Code::NestingTooDeep);
}

#[test]
fn deeply_nested_statements_give_one_error_not_a_crash() {
    let text = format!(
        "{}x := 1;{}",
        "IF a THEN ".repeat(5_000),
        " END_IF".repeat(5_000)
    );
    let parse = parse_statements(&text);
    assert_eq!(parse.syntax().to_string(), text);
    assert_eq!(parse.errors().len(), 1, "{:?}", parse.errors());
}

#[test]
fn a_five_megabyte_line_parses() {
    // A long flat list is fine.
    let text = format!("x := [{}0];", "1, ".repeat(1_700_000));
    assert!(text.len() > 5_000_000);
    let parse = parse_statements(&text);
    assert!(parse.errors().is_empty());
    assert_eq!(
        parse.syntax().text_range().len(),
        u32::try_from(text.len()).unwrap().into()
    );
    // A megabyte-long chain of operators gives one error instead of a tree too deep to walk.
    let text = format!("x := {};", "a + ".repeat(1_250_000) + "b");
    let parse = parse_statements(&text);
    assert_eq!(parse.errors().len(), 1);
    assert_eq!(parse.errors()[0].code, crate::Code::NestingTooDeep);
    assert_eq!(
        parse.syntax().text_range().len(),
        u32::try_from(text.len()).unwrap().into()
    );
}

#[test]
fn garbage_never_breaks_losslessness() {
    for text in [
        "",
        ")))",
        "END_IF END_IF",
        "PROGRAM",
        "FUNCTION_BLOCK F VAR x : ; END_VAR",
        "TYPE : END_TYPE",
        "x := 'open\n",
        "(* open",
        "IF THEN ELSE END_IF",
        "CASE OF 1: END_CASE",
        "§§ 中文 := ;",
        "VAR_GLOBAL END_VAR END_VAR",
    ] {
        parse_lossless(text);
        let statements = parse_statements(text);
        assert_eq!(statements.syntax().to_string(), text);
    }
}

#[test]
fn operators_bind_with_iec_precedence() {
    let parse = parse_statements("x := NOT a AND b OR c = d + e * -f ** 2;");
    let tree = parse.debug_tree();
    let shape: Vec<&str> = tree
        .lines()
        .filter(|line| line.contains("EXPR"))
        .map(|line| line.trim_start().split('@').next().unwrap_or(""))
        .collect();
    // x := OR(AND(NOT a, b), =(c, +(d, *(e, -(f ** 2))))); literals are not listed.
    assert_eq!(
        shape,
        vec![
            "NAME_EXPR",
            "BINARY_EXPR",
            "BINARY_EXPR",
            "UNARY_EXPR",
            "NAME_EXPR",
            "NAME_EXPR",
            "BINARY_EXPR",
            "NAME_EXPR",
            "BINARY_EXPR",
            "NAME_EXPR",
            "BINARY_EXPR",
            "NAME_EXPR",
            "UNARY_EXPR",
            "BINARY_EXPR",
            "NAME_EXPR",
        ]
    );
}

#[test]
fn the_golden_tree_of_a_small_statement() {
    let parse = parse_statements("x S= a; (* c *)\nfb(IN := TRUE, Q => y);");
    expect![[r#"
        SOURCE_FILE@0..39
          STATEMENT_LIST@0..39
            SET_STMT@0..7
              NAME_EXPR@0..1
                IDENT@0..1 "x"
              WHITESPACE@1..2 " "
              IDENT@2..3 "S"
              EQ@3..4 "="
              WHITESPACE@4..5 " "
              NAME_EXPR@5..6
                IDENT@5..6 "a"
              SEMICOLON@6..7 ";"
            WHITESPACE@7..8 " "
            BLOCK_COMMENT@8..15 "(* c *)"
            WHITESPACE@15..16 "\n"
            CALL_STMT@16..39
              CALL_EXPR@16..38
                NAME_EXPR@16..18
                  IDENT@16..18 "fb"
                ARG_LIST@18..38
                  L_PAREN@18..19 "("
                  ARG@19..29
                    IDENT@19..21 "IN"
                    WHITESPACE@21..22 " "
                    ASSIGN@22..24 ":="
                    WHITESPACE@24..25 " "
                    LITERAL@25..29
                      TRUE@25..29 "TRUE"
                  COMMA@29..30 ","
                  WHITESPACE@30..31 " "
                  ARG@31..37
                    IDENT@31..32 "Q"
                    WHITESPACE@32..33 " "
                    OUTPUT_ASSIGN@33..35 "=>"
                    WHITESPACE@35..36 " "
                    NAME_EXPR@36..37
                      IDENT@36..37 "y"
                  R_PAREN@37..38 ")"
              SEMICOLON@38..39 ";"
    "#]]
    .assert_eq(&parse.debug_tree());
}

#[test]
fn the_lc1200_operator_and_conversion_examples_parse() {
    // The expressions of the LC1200 digest §2.4 and §2.5; their values are runtime tests.
    let expressions = [
        "9 MOD 2",
        "SIZEOF(aInts)",
        "2#1001_0011 AND 2#1000_1010",
        "NOT 2#1001_0011",
        "SHL(BYTE#16#45, 2)",
        "ROR(WORD#16#45, 2)",
        "SEL(TRUE, 3, 4)",
        "MAX(40, MAX(90, 30))",
        "LIMIT(30, 90, 80)",
        "MUX(0, 30, 40, 50)",
        "EXPT(7, 2)",
        "SQRT(16)",
        "BOOL_TO_TIME(TRUE)",
        "TIME_TO_BOOL(T#5ms)",
        "STRING_TO_BOOL('TRUE')",
        "TO_INT(4.22)",
        "INT_TO_SINT(4223)",
        "REAL_TO_INT(-1.5)",
        "TIME_TO_DWORD(T#5m)",
        "TOD_TO_SINT(TOD#00:00:00.012)",
        "DATE_TO_INT(D#1970-01-15)",
        "DT_TO_BYTE(DT#1970-01-15-05:05:05)",
        "DT_TO_STRING(DT#1998-02-13-14:20)",
        "STRING_TO_TIME('T#127ms')",
        "TRUNC(-1.4)",
        "LTIME#1000d15h23m12s34ms2us44ns",
        "TOD#23:59:59.999 - TOD#00:00:00.001",
        "DT#2106-2-7-6:28:15",
        "pValue^ + ADR(x)",
        "a AND_THEN b OR_ELSE c",
        "E_Color#Red",
        "INT#-5",
        "'$N$$$L$''",
    ];
    for expression in expressions {
        let parse = parse_statements(&format!("x := {expression};"));
        assert!(
            parse.errors().is_empty(),
            "{expression}: {:?}",
            parse.errors()
        );
    }
}

#[test]
fn inputs_found_by_fuzzing_end_quickly() {
    // A lone '.' once made the statement loop spin without consuming anything.
    for text in [
        ".",
        "x := 1; . ; .x := 2;",
        "TYPE . END_TYPE",
        "VAR_GLOBAL . END_VAR",
        "CONFIGURATION C . END_CONFIGURATION",
    ] {
        let parse = parse_statements(text);
        assert_eq!(parse.syntax().to_string(), text);
        assert!(!parse.errors().is_empty());
        let parse = super::parse(text);
        assert_eq!(parse.syntax().to_string(), text);
    }
}

#[test]
fn property_accessors_written_inline_parse_as_accessors() {
    let text = "FUNCTION_BLOCK FB\nPROPERTY P : INT\nGET\nVAR x : INT; END_VAR\nP := x;\nEND_GET\nSET\nx := P;\nEND_SET\nEND_PROPERTY\nEND_FUNCTION_BLOCK\n";
    let parse = parse(text);
    assert!(parse.errors().is_empty(), "{:?}", parse.errors());
    let accessors = parse
        .syntax()
        .descendants()
        .filter(|node| node.kind() == super::SyntaxKind::ACCESSOR_DECL)
        .count();
    assert_eq!(accessors, 2);
    // The words are not reserved: a statement may still assign a variable called GET.
    let parse = parse_statements("GET := 1; SET(x);");
    assert!(parse.errors().is_empty(), "{:?}", parse.errors());
}
