//! Every construct of the language, one small text each: the compiler accepts it, and the
//! tree-sitter tree is clean and holds the node the construct should give.
//!
//! The corpora cover what real code uses; this list covers the rest of what the compiler's
//! grammar accepts, so a construct no corpus happens to use is still checked.

#![allow(clippy::unwrap_used, clippy::expect_used)] // Test helpers may panic: a panic is a failed test.

use tree_sitter::{Node, Parser, Tree};

fn tree_sitter_parse(text: &str) -> Tree {
    let mut parser = Parser::new();
    parser
        .set_language(&tree_sitter_rivet_st::language())
        .unwrap();
    parser.parse(text, None).unwrap()
}

fn kinds(node: Node<'_>, out: &mut Vec<String>) {
    out.push(node.kind().to_owned());
    let mut cursor = node.walk();
    for child in node.children(&mut cursor) {
        kinds(child, out);
    }
}

/// Checks that the compiler accepts `text` through `compiler_parse` and that tree-sitter
/// parses it without errors into a tree that holds every kind in `expected`.
#[track_caller]
fn check(compiler_parse: fn(&str) -> compiler::syntax::Parse, text: &str, expected: &[&str]) {
    let compiled = compiler_parse(text);
    assert!(
        compiled.errors().is_empty(),
        "the compiler rejects {text:?}: {:?}",
        compiled.errors()
    );
    let tree = tree_sitter_parse(text);
    let root = tree.root_node();
    assert!(!root.has_error(), "{text:?} gives {}", root.to_sexp());
    let mut found = Vec::new();
    kinds(root, &mut found);
    for kind in expected {
        assert!(
            found.iter().any(|found| found == kind),
            "{text:?} has no {kind}: {}",
            root.to_sexp()
        );
    }
}

#[track_caller]
fn source(text: &str, expected: &[&str]) {
    check(compiler::syntax::parse, text, expected);
}

#[track_caller]
fn statements(text: &str, expected: &[&str]) {
    check(compiler::syntax::parse_statements, text, expected);
}

#[track_caller]
fn declaration_part(text: &str, expected: &[&str]) {
    check(compiler::syntax::parse_declaration_part, text, expected);
}

#[test]
fn keywords_are_case_insensitive() {
    source(
        "program P var x : int; end_var if x THEN x := 1; elsif X tHeN ; else ; End_If END_program",
        &[
            "program_declaration",
            "if_statement",
            "elsif_clause",
            "else_clause",
        ],
    );
    statements(
        "x := a and b Or not c mod 2;",
        &["binary_expression", "unary_expression"],
    );
}

#[test]
fn function_blocks_with_inheritance_methods_properties_and_modifiers_parse() {
    source(
        "FUNCTION_BLOCK ABSTRACT FB_A EXTENDS FB_Base IMPLEMENTS I_A, Lib.I_B;
VAR_INPUT x : BOOL; END_VAR
METHOD PUBLIC ABSTRACT Run : BOOL
VAR_INPUT n : INT; END_VAR
END_METHOD
METHOD FINAL PRIVATE Stop;
Stop := TRUE;
END_METHOD
PROPERTY PROTECTED Speed : REAL
END_PROPERTY
PROPERTY INTERNAL Count : INT
GET
VAR y : INT; END_VAR
Count := y;
END_GET
SET;
y := Count;
END_SET;
END_PROPERTY
END_FUNCTION_BLOCK",
        &[
            "function_block_declaration",
            "modifier",
            "extends_clause",
            "implements_clause",
            "qualified_name",
            "method_declaration",
            "property_declaration",
            "property_accessor",
            "GET",
            "END_GET",
            "SET",
            "END_SET",
        ],
    );
}

#[test]
fn get_set_step_and_transition_stay_names_where_the_compiler_takes_them_as_names() {
    statements(
        "GET := 1; SET(x); Step := 2; transition := Step + 1; Step.x := 3; get[1] := 0;",
        &["assignment_statement", "call_statement", "index_expression"],
    );
    let tree = tree_sitter_parse("GET := 1; SET(x); Step := 2; transition := 1;");
    let mut found = Vec::new();
    kinds(tree.root_node(), &mut found);
    assert!(
        !found
            .iter()
            .any(|kind| kind == "step" || kind == "transition")
    );
    source(
        "FUNCTION_BLOCK FB\nPROPERTY P : INT\nGet := 1;\nEND_PROPERTY\nEND_FUNCTION_BLOCK",
        &["property_declaration", "assignment_statement"],
    );
}

#[test]
fn functions_programs_actions_and_interfaces_parse() {
    source(
        "FUNCTION F_Add : INT VAR_INPUT a, b : INT; END_VAR F_Add := a + b; END_FUNCTION
PROGRAM Main
VAR fb : FB_A; END_VAR
fb();
ACTION Reset:
fb.x := FALSE;
END_ACTION
END_PROGRAM
ACTION Standalone: x := 1; END_ACTION
INTERFACE I_Drive EXTENDS I_Base, I_Other
METHOD Start : BOOL END_METHOD
PROPERTY Speed : REAL END_PROPERTY
END_INTERFACE
FUNCTION MOD : INT VAR_INPUT IN1, IN2 : INT; END_VAR RETURN; END_FUNCTION",
        &[
            "function_declaration",
            "return_type",
            "program_declaration",
            "action_declaration",
            "interface_declaration",
        ],
    );
}

#[test]
fn every_kind_of_type_declaration_parses() {
    source(
        "TYPE
E_Color : (Red := 1, Green, Blue) DINT := Green;
E_Plain : (A, B, C);
ST_Point EXTENDS ST_Base : STRUCT x : REAL; y : REAL := 1.5E3; END_STRUCT
U_Word : UNION w : WORD; b : ARRAY[0..1] OF BYTE; END_UNION
T_Percent : INT(0..100);
T_Ref : REFERENCE TO INT;
T_RefTo : REF_TO INT;
T_Ptr : POINTER TO ST_Point;
T_Matrix : ARRAY[1..3, 0..1, -1..1] OF LREAL := [6(0.0)];
T_Open : ARRAY[*] OF INT;
T_Name : STRING(80);
T_Wide : WSTRING[20];
T_Alias : DINT;
T_Qualified : Lib.T_Thing;
END_TYPE",
        &[
            "type_declaration",
            "type_definition",
            "enum_type",
            "enum_value",
            "struct_type",
            "union_type",
            "subrange",
            "reference_type",
            "pointer_type",
            "array_type",
            "array_range",
            "string_type",
            "named_type",
            "initializer",
            "repeated_initializer",
        ],
    );
}

#[test]
fn every_variable_section_qualifier_and_declaration_form_parses() {
    source(
        "PROGRAM P
VAR_INPUT a : BOOL; rising : BOOL R_EDGE; falling : BOOL F_EDGE; END_VAR
VAR_OUTPUT b : INT; END_VAR
VAR_IN_OUT c : ARRAY[1..2] OF INT; END_VAR
VAR_EXTERNAL CONSTANT d : INT; END_VAR
VAR_TEMP e : INT; END_VAR
VAR_STAT f : INT; END_VAR
VAR_INST g : INT; END_VAR
VAR RETAIN h : INT; END_VAR
VAR NON_RETAIN i : INT; END_VAR
VAR PERSISTENT RETAIN j : INT; END_VAR
VAR
    k, l AT %IX0.0 : BOOL;
    AT %QW3 : WORD;
    m AT %I* : BOOL;
    n : ARRAY[1..3, 0..1] OF INT := [2(0), 4(1)];
    o : ARRAY[1..5] OF INT := [1, 2, 3()];
    p : ST_Point := (x := 1, y := (z := 2));
    q : ARRAY[1..3] OF INT := 2, 7, 18;
    r : (Idle, Busy) := Idle;
    s : FB_Logger(Results);
    t : FB_Init(a := 1, b := 2);
    u : STRING := 'it$'s $$5 $N';
    v : WSTRING := \"wide $\"\";
END_VAR
END_PROGRAM
VAR_GLOBAL CONSTANT gc_Max : INT := 10; END_VAR
VAR_GLOBAL PERSISTENT RETAIN g_Count : UDINT; END_VAR
VAR_CONFIG Main.fb.xIn AT %IX1.0 : BOOL; END_VAR",
        &[
            "var_block",
            "var_declaration",
            "location",
            "direct_address",
            "array_initializer",
            "repeated_initializer",
            "struct_initializer",
            "field_initializer",
            "global_var_declaration",
            "argument_list",
            "string",
            "wide_string",
            "R_EDGE",
            "F_EDGE",
        ],
    );
}

#[test]
fn configurations_resources_tasks_and_program_instances_parse() {
    source(
        "CONFIGURATION Cell
VAR_GLOBAL g : INT; END_VAR
RESOURCE Cpu ON PLC
    TASK Fast (INTERVAL := T#2ms, PRIORITY := 0);
    TASK Slow(SINGLE := trigger, PRIORITY := 5);
    PROGRAM Inst WITH Fast : Main;
    PROGRAM RETAIN Other WITH Slow : Lib.Main (a := g, b => %QW1);
END_RESOURCE
VAR_ACCESS ext : Cpu.Inst.x : INT READ_ONLY; END_VAR
END_CONFIGURATION",
        &[
            "configuration_declaration",
            "resource_declaration",
            "task_configuration",
            "program_configuration",
            "output_argument",
            "READ_ONLY",
        ],
    );
}

#[test]
fn literals_of_every_form_parse() {
    statements(
        "x := INT#5 + INT#-5 + 16#FF + 2#1010_1010 + 8#777 + 1_000 + 1.5E-3 + 1E6 + WORD#16#FF;
t := T#1h2m3s4ms + TIME#5s + LTIME#1000d15h23m12s34ms2us44ns + lt#1s;
d := D#2024-01-31; dt := DT#2024-01-31-12:00; tod := TOD#12:30:00.5;
d2 := DATE#2024-01-31; ldt := LDT#2024-01-31-12:00:00; ltod := LTOD#1:2:3;
c := Color#Red; b := BOOL#TRUE; f := FALSE; s := '$N$$$L$''; w := \"$\"ok$\"\";
r := REAL#1.5; ss := STRING#'abc';",
        &[
            "typed_literal",
            "integer",
            "real",
            "time_literal",
            "date_literal",
            "boolean",
            "string",
            "wide_string",
        ],
    );
}

#[test]
fn every_statement_parses() {
    statements(
        "x := 1; x S= TRUE; x R= FALSE; p REF= x; i ?= itf; fb(IN := TRUE, PT := T#1s, Q => q, ET => );
fb(x, y); fb.Run(a, NOT done => d); f := SUPER^.Calc(); THIS^.x := 1; .global := 2;
IF a THEN ; ELSIF b THEN x := 1; ELSIF c THEN ; ELSE x := 2; END_IF;
CASE n OF 1, 2: x := 1; 3..5, E.Idle, -1: ; INT#7: RETURN; ELSE x := 0; END_CASE;
FOR i := 1 TO 10 BY 2 DO IF i = 5 THEN EXIT; END_IF CONTINUE; END_FOR;
WHILE x < 10 DO x := x + 1; END_WHILE;
REPEAT x := x - 1; UNTIL x <= 0 END_REPEAT;
JMP label1; label1: x := 0; RETURN; ;
pValue^ := arr[1, 2]^.field; a[i].b[j] := x.1; w.%X3 := TRUE;",
        &[
            "assignment_statement",
            "set_statement",
            "reset_statement",
            "reference_assignment_statement",
            "attempt_assignment_statement",
            "call_statement",
            "named_argument",
            "output_argument",
            "if_statement",
            "case_statement",
            "case_branch",
            "case_range",
            "for_statement",
            "while_statement",
            "repeat_statement",
            "exit_statement",
            "continue_statement",
            "return_statement",
            "jump_statement",
            "label_statement",
            "empty_statement",
            "dereference_expression",
            "index_expression",
            "field_expression",
            "global_reference",
            "this",
            "super",
        ],
    );
}

#[test]
fn operators_bind_with_iec_precedence() {
    // x := OR(AND(NOT a, b), =(c, +(d, *(e, -(f ** 2))))), as the compiler's test has it.
    let text = "x := NOT a AND b OR c = d + e * -f ** 2;";
    statements(text, &["binary_expression"]);
    let tree = tree_sitter_parse(text);
    let sexp = tree.root_node().to_sexp();
    let expected = "(source_file (assignment_statement left: (identifier) right: \
        (binary_expression left: (binary_expression left: (unary_expression operand: \
        (identifier)) right: (identifier)) right: (binary_expression left: (identifier) \
        right: (binary_expression left: (identifier) right: (binary_expression left: \
        (identifier) right: (unary_expression operand: (binary_expression left: (identifier) \
        right: (integer)))))))))";
    assert_eq!(sexp, expected);
    statements(
        "y := a XOR b AND_THEN c OR_ELSE d & e <> f <= g - h / i MOD j ** k ** l;",
        &["binary_expression"],
    );
    statements(
        "y := MOD(a, b) + AND(a, b, c) + OR(a, b) + XOR(a, b);",
        &["call_expression"],
    );
}

#[test]
fn textual_sfc_parses() {
    source(
        "FUNCTION_BLOCK sfc
VAR x : BOOL; END_VAR
INITIAL_STEP Start:
END_STEP
TRANSITION FROM Start TO Mid := x;
END_TRANSITION
STEP Mid:
  Reset(N);
END_STEP
TRANSITION t2 FROM Mid TO (A, B) :
  Mid := TRUE;
END_TRANSITION
TRANSITION (PRIORITY := 1) FROM (A, B) TO Start := NOT x; END_TRANSITION
STEP Fill (MIN_TIME := T#1s, ENTRY := Reset, EXIT := Reset): Reset(L, T#2s, x); END_STEP
ACTION Reset:
  x := FALSE;
END_ACTION
END_FUNCTION_BLOCK",
        &[
            "step",
            "INITIAL_STEP",
            "STEP",
            "transition",
            "step_list",
            "step_properties",
            "action_declaration",
        ],
    );
}

#[test]
fn comments_nest_and_pragmas_go_anywhere() {
    statements(
        "(* a (* b *) c *) x := 1; // line
/* block (* not nested here */ {attribute 'hide'} y := {pragma} 2;
(*@KEY@:DESCRIPTION*) free text (* with an unclosed ( *) @ # (*@KEY@:END_DESCRIPTION*)",
        &["comment", "pragma"],
    );
    let tree = tree_sitter_parse("(* a (* b *) c *)x := 1;");
    let comment = tree.root_node().child(0).unwrap();
    assert_eq!((comment.kind(), comment.end_byte()), ("comment", 17));
}

#[test]
fn declaration_parts_alone_parse() {
    declaration_part(
        "{attribute 'x'}\nFUNCTION_BLOCK FB_X EXTENDS FB_Base IMPLEMENTS I_X\nVAR_INPUT a : INT; END_VAR\nVAR END_VAR\n",
        &["function_block_declaration", "var_block"],
    );
    declaration_part(
        "METHOD PUBLIC Close : SysFile.SysTypes.RTS_IEC_RESULT;\nVAR_INPUT b : BOOL; END_VAR",
        &["method_declaration", "qualified_name"],
    );
    declaration_part("PROPERTY PUBLIC Speed : REAL", &["property_declaration"]);
    declaration_part("PROGRAM Main", &["program_declaration"]);
    declaration_part(
        "FUNCTION F : BOOL\nVAR_INPUT a : INT; END_VAR",
        &["function_declaration"],
    );
    declaration_part("VAR\nEND_VAR\n", &["var_block"]);
    declaration_part(
        "VAR_INPUT a : INT; END_VAR VAR_OUTPUT b : INT; END_VAR",
        &["var_block"],
    );
    declaration_part("INTERFACE I_X EXTENDS I_Y", &["interface_declaration"]);
    declaration_part("", &["source_file"]);
    // Like the compiler, a declaration part may run on into its body up to the end.
    declaration_part(
        "FUNCTION_BLOCK FB VAR x : INT; END_VAR x := 1; METHOD M END_METHOD",
        &["function_block_declaration", "body", "method_declaration"],
    );
    declaration_part(
        "METHOD M : BOOL\nM := TRUE;",
        &["method_declaration", "body"],
    );
    declaration_part(
        "PROPERTY P : INT\nGET P := 1; END_GET",
        &["property_declaration", "property_accessor"],
    );
    declaration_part("ACTION A:\nx := 1;", &["action_declaration", "body"]);
    declaration_part(
        "FUNCTION F : INT\nMETHOD PRIVATE M : BOOL\nVAR END_VAR",
        &["function_declaration", "method_declaration"],
    );
    declaration_part(
        "INTERFACE I\nMETHOD A END_METHOD\nPROPERTY P : INT",
        &["interface_declaration", "property_declaration"],
    );
}

#[test]
fn postfix_operators_apply_to_any_operand_as_in_the_compiler() {
    // Nonsense the type checker rejects, but the syntax is the compiler's.
    statements(
        "x := 3.0 (y) + [1, 2][0] + 1 (NOT a AND b) + INT#5.x + 'abc'[1];",
        &["call_expression", "index_expression", "field_expression"],
    );
    // In an array initialiser, `3(` repeats instead.
    source(
        "PROGRAM P VAR a : ARRAY[1..5] OF INT := [2(0), 3(), 4]; END_VAR END_PROGRAM",
        &["repeated_initializer"],
    );
}

#[test]
fn names_that_look_like_set_and_reset_stay_names_in_expressions() {
    statements(
        "IF R=1 THEN x := S=2; END_IF x := REF=1 AND S =2; WHILE R=S DO R:=S; END_WHILE",
        &["if_statement", "while_statement", "binary_expression"],
    );
    statements("S := R; R := 1; REF := 2;", &["assignment_statement"]);
}

#[test]
fn names_may_be_written_in_any_script() {
    statements(
        "变量 := 名字 + 1; über := 2; _x1 := Ωmega;",
        &["assignment_statement"],
    );
    source(
        "PROGRAM 主程序 VAR 计数 : INT; END_VAR 计数 := 计数 + 1; END_PROGRAM",
        &["program_declaration"],
    );
}
