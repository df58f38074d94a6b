//! What the accessors of expressions and statements return, on valid and on broken input.

use super::nodes::WRAPPED_KINDS;
use super::*;
use crate::syntax::{parse, parse_statements};

/// The first node of type `N` in the body `text` (parsed as statements).
#[track_caller]
pub(super) fn first<N: AstNode>(text: &str) -> N {
    parse_statements(text)
        .syntax()
        .descendants()
        .find_map(N::cast)
        .unwrap_or_else(|| panic!("no such node in {text:?}"))
}

/// The first node of type `N` in the source file `text`.
#[track_caller]
pub(super) fn first_in_file<N: AstNode>(text: &str) -> N {
    parse(text)
        .syntax()
        .descendants()
        .find_map(N::cast)
        .unwrap_or_else(|| panic!("no such node in {text:?}"))
}

/// The trimmed text of a node.
pub(super) fn text<N: AstNode>(node: Option<N>) -> Option<String> {
    node.map(|node| node.syntax().text().to_string().trim().to_owned())
}

pub(super) fn token_text(token: Option<crate::syntax::SyntaxToken>) -> Option<String> {
    token.map(|token| token.text().to_owned())
}

#[test]
fn every_node_kind_has_a_wrapper() {
    let first_node = SyntaxKind::SOURCE_FILE as usize;
    let nodes = &SyntaxKind::ALL[first_node..];
    assert_eq!(WRAPPED_KINDS, nodes);
}

#[test]
fn a_wrapper_casts_only_its_own_kind() {
    let binary = first::<BinaryExpr>("x := a + b;");
    assert!(UnaryExpr::cast(binary.syntax().clone()).is_none());
    assert!(matches!(
        Expr::cast(binary.syntax().clone()),
        Some(Expr::BinaryExpr(_))
    ));
    assert!(Stmt::cast(binary.syntax().clone()).is_none());
}

#[test]
fn a_binary_expression_has_its_operands_and_operator() {
    let binary = first::<BinaryExpr>("x := a * (b + 1);");
    assert_eq!(text(binary.lhs()).as_deref(), Some("a"));
    assert_eq!(token_text(binary.op()).as_deref(), Some("*"));
    assert_eq!(text(binary.rhs()).as_deref(), Some("(b + 1)"));
    let Some(Expr::ParenExpr(paren)) = binary.rhs() else {
        panic!("the right operand is not in parentheses");
    };
    assert_eq!(text(paren.inner()).as_deref(), Some("b + 1"));
}

#[test]
fn a_binary_expression_without_its_right_operand_has_none() {
    let binary = first::<BinaryExpr>("x := a + ;");
    assert_eq!(text(binary.lhs()).as_deref(), Some("a"));
    assert_eq!(token_text(binary.op()).as_deref(), Some("+"));
    assert_eq!(binary.rhs(), None);
}

#[test]
fn a_unary_expression_has_its_operator_and_operand() {
    let unary = first::<UnaryExpr>("x := NOT y;");
    assert_eq!(token_text(unary.op()).as_deref(), Some("NOT"));
    assert_eq!(text(unary.operand()).as_deref(), Some("y"));
    let broken = first::<UnaryExpr>("x := -;");
    assert_eq!(token_text(broken.op()).as_deref(), Some("-"));
    assert_eq!(broken.operand(), None);
}

#[test]
fn literals_give_their_tokens() {
    assert_eq!(
        token_text(first::<Literal>("x := 16#FF;").token()).as_deref(),
        Some("16#FF")
    );
    let typed = first::<TypedLiteral>("x := INT#-5;");
    assert_eq!(token_text(typed.type_name()).as_deref(), Some("INT"));
    assert_eq!(token_text(typed.value()).as_deref(), Some("5"));
    assert!(typed.is_negative());
    let broken = first::<TypedLiteral>("x := INT#;");
    assert_eq!(token_text(broken.type_name()).as_deref(), Some("INT"));
    assert_eq!(broken.value(), None);
}

#[test]
fn names_tell_identifiers_globals_and_keywords_apart() {
    let local = first::<NameExpr>("x := y;");
    assert_eq!(token_text(local.ident()).as_deref(), Some("x"));
    assert!(!local.is_global());
    let global = first::<NameExpr>(".g := 1;");
    assert_eq!(token_text(global.name()).as_deref(), Some("g"));
    assert!(global.is_global());
    let this = first::<NameExpr>("THIS^.x := 1;");
    assert_eq!(this.name(), None);
    assert_eq!(token_text(this.first_token()).as_deref(), Some("THIS"));
    let Some(Expr::NameExpr(operator)) = first::<CallExpr>("x := MOD(a, b);").callee() else {
        panic!("the callee is not a name");
    };
    assert_eq!(token_text(operator.name()).as_deref(), Some("MOD"));
    assert_eq!(operator.ident(), None);
}

#[test]
fn members_indices_and_dereferences_have_their_bases() {
    let field = first::<FieldExpr>("x := fb.tonStart.Q;");
    assert_eq!(text(field.base()).as_deref(), Some("fb.tonStart"));
    assert_eq!(token_text(field.member()).as_deref(), Some("Q"));
    assert_eq!(
        token_text(first::<FieldExpr>("x := w.3;").member()).as_deref(),
        Some("3")
    );
    let index = first::<IndexExpr>("x := a[i, j + 1];");
    assert_eq!(text(index.base()).as_deref(), Some("a"));
    let indices: Vec<String> = index
        .indices()
        .map(|i| i.syntax().text().to_string())
        .collect();
    assert_eq!(indices, ["i", "j + 1"]);
    assert_eq!(first::<IndexExpr>("x := a[];").indices().count(), 0);
    let deref = first::<DerefExpr>("x := p^;");
    assert_eq!(text(deref.base()).as_deref(), Some("p"));
}

#[test]
fn a_call_has_its_callee_and_arguments() {
    let call = first::<CallExpr>("fb(IN := x, PT => t, NOT Q => q, 5, ET =>);");
    assert_eq!(text(call.callee()).as_deref(), Some("fb"));
    let args: Vec<(Option<String>, ArgKind, bool, Option<String>)> = call
        .args()
        .map(|arg| {
            (
                token_text(arg.name()),
                arg.kind(),
                arg.is_negated(),
                text(arg.value()),
            )
        })
        .collect();
    assert_eq!(
        args,
        [
            (Some("IN".into()), ArgKind::Input, false, Some("x".into())),
            (Some("PT".into()), ArgKind::Output, false, Some("t".into())),
            (Some("Q".into()), ArgKind::Output, true, Some("q".into())),
            (None, ArgKind::Positional, false, Some("5".into())),
            (Some("ET".into()), ArgKind::Output, false, None),
        ]
    );
    let unclosed = first::<CallExpr>("f(a;");
    assert_eq!(unclosed.args().count(), 1);
}

#[test]
fn an_address_expression_gives_its_address() {
    let address = first::<AddressExpr>("x := %IX0.1;");
    assert_eq!(token_text(address.address()).as_deref(), Some("%IX0.1"));
}

#[test]
fn assignments_have_a_target_and_a_value() {
    let assign = first::<AssignStmt>("a.b := c + 1;");
    assert_eq!(text(assign.target()).as_deref(), Some("a.b"));
    assert_eq!(text(assign.value()).as_deref(), Some("c + 1"));
    let set = first::<SetStmt>("x S= y;");
    assert_eq!(text(set.target()).as_deref(), Some("x"));
    assert_eq!(text(set.value()).as_deref(), Some("y"));
    assert_eq!(
        text(first::<ResetStmt>("x R= y;").value()).as_deref(),
        Some("y")
    );
    assert_eq!(
        text(first::<RefAssignStmt>("r REF= y;").value()).as_deref(),
        Some("y")
    );
    assert_eq!(
        text(first::<AttemptAssignStmt>("i ?= y;").value()).as_deref(),
        Some("y")
    );
    let broken = first::<AssignStmt>("a b;");
    assert_eq!(text(broken.target()).as_deref(), Some("a"));
    assert_eq!(broken.value(), None);
    let call = first::<CallStmt>("fb(x);");
    assert_eq!(
        text(call.call().and_then(|c| c.callee())).as_deref(),
        Some("fb")
    );
}

#[test]
fn an_if_has_its_condition_and_branches() {
    let stmt = first::<IfStmt>(
        "IF a THEN x := 1; ELSIF b THEN x := 2; ELSIF c THEN ; ELSE x := 3; END_IF",
    );
    assert_eq!(text(stmt.condition()).as_deref(), Some("a"));
    assert_eq!(text(stmt.then_branch()).as_deref(), Some("x := 1;"));
    let elsifs: Vec<(Option<String>, Option<String>)> = stmt
        .elsif_branches()
        .map(|b| (text(b.condition()), text(b.body())))
        .collect();
    assert_eq!(
        elsifs,
        [
            (Some("b".into()), Some("x := 2;".into())),
            (Some("c".into()), Some(";".into())),
        ]
    );
    assert_eq!(
        text(stmt.else_branch().and_then(|e| e.body())).as_deref(),
        Some("x := 3;")
    );
    let broken = first::<IfStmt>("IF THEN x := 1;");
    assert_eq!(broken.condition(), None);
    assert_eq!(text(broken.then_branch()).as_deref(), Some("x := 1;"));
    assert_eq!(broken.else_branch(), None);
}

#[test]
fn a_case_has_its_selector_labels_and_branches() {
    let stmt = first::<CaseStmt>("CASE n OF 1, 3..5: x := 1; E.Idle: ; ELSE x := 0; END_CASE");
    assert_eq!(text(stmt.selector()).as_deref(), Some("n"));
    let branches: Vec<CaseBranch> = stmt.branches().collect();
    assert_eq!(branches.len(), 2);
    let labels: Vec<String> = branches[0]
        .labels()
        .map(|label| match label {
            CaseLabel::Value(value) => format!("value {}", value.syntax()),
            CaseLabel::Range(range) => {
                format!("range {:?}..{:?}", text(range.low()), text(range.high()))
            }
        })
        .collect();
    assert_eq!(labels, ["value 1", "range Some(\"3\")..Some(\"5\")"]);
    assert_eq!(text(branches[0].body()).as_deref(), Some("x := 1;"));
    assert_eq!(
        text(stmt.else_branch().and_then(|e| e.body())).as_deref(),
        Some("x := 0;")
    );
    let broken = first::<CaseStmt>("CASE OF 1: x := 1; END_CASE");
    assert_eq!(broken.selector(), None);
    assert_eq!(broken.branches().count(), 1);
}

#[test]
fn a_for_has_its_variable_bounds_and_body() {
    let stmt = first::<ForStmt>("FOR i := 1 TO n BY 2 DO x := i; END_FOR");
    assert_eq!(text(stmt.variable()).as_deref(), Some("i"));
    assert_eq!(text(stmt.from()).as_deref(), Some("1"));
    assert_eq!(text(stmt.to()).as_deref(), Some("n"));
    assert_eq!(text(stmt.by()).as_deref(), Some("2"));
    assert_eq!(text(stmt.body()).as_deref(), Some("x := i;"));
    let without_step = first::<ForStmt>("FOR i := 1 TO n DO END_FOR");
    assert_eq!(without_step.by(), None);
    let broken = first::<ForStmt>("FOR := 1 TO DO END_FOR");
    assert_eq!(broken.variable(), None);
    assert_eq!(text(broken.from()).as_deref(), Some("1"));
    assert_eq!(broken.to(), None);
}

#[test]
fn loops_have_their_condition_and_body() {
    let stmt = first::<WhileStmt>("WHILE a < 3 DO a := a + 1; END_WHILE");
    assert_eq!(text(stmt.condition()).as_deref(), Some("a < 3"));
    assert_eq!(text(stmt.body()).as_deref(), Some("a := a + 1;"));
    let stmt = first::<RepeatStmt>("REPEAT a := a + 1; UNTIL a > 3 END_REPEAT");
    assert_eq!(text(stmt.body()).as_deref(), Some("a := a + 1;"));
    assert_eq!(text(stmt.condition()).as_deref(), Some("a > 3"));
    let broken = first::<WhileStmt>("WHILE DO END_WHILE");
    assert_eq!(broken.condition(), None);
}

#[test]
fn a_body_lists_its_statements_and_skips_what_is_not_one() {
    let file = SourceFile::cast(parse_statements("x := 1; ) y := 2; EXIT;").syntax())
        .expect("a body is a source file");
    let kinds: Vec<SyntaxKind> = file
        .statement_list()
        .into_iter()
        .flat_map(|list| list.statements())
        .map(|s| s.syntax().kind())
        .collect();
    assert_eq!(
        kinds,
        [
            SyntaxKind::ASSIGN_STMT,
            SyntaxKind::ASSIGN_STMT,
            SyntaxKind::EXIT_STMT
        ]
    );
}

#[test]
fn jumps_and_labels_have_their_names() {
    assert_eq!(
        first::<JmpStmt>("JMP done;")
            .label()
            .map(|l| l.text())
            .as_deref(),
        Some("done")
    );
    assert_eq!(
        first::<LabelStmt>("done: ;")
            .name()
            .map(|n| n.text())
            .as_deref(),
        Some("done")
    );
}

#[test]
fn steps_and_transitions_have_their_parts() {
    let body = "INITIAL_STEP Init: Fill(N); END_STEP
STEP Run: END_STEP
TRANSITION (PRIORITY := 1) FROM Init TO (Run, Init) := xGo; END_TRANSITION";
    let step = first::<StepDecl>(body);
    assert_eq!(step.name().map(|n| n.text()).as_deref(), Some("Init"));
    assert!(step.is_initial());
    assert_eq!(step.statements().count(), 1);
    let transition = first::<TransitionDecl>(body);
    assert_eq!(transition.name(), None);
    assert_eq!(transition.arg_list().map(|l| l.args().count()), Some(1));
    let steps = |list: Option<StepList>| -> Vec<String> {
        list.into_iter()
            .flat_map(|l| l.steps())
            .map(|s| s.text())
            .collect()
    };
    assert_eq!(steps(transition.from_steps()), ["Init"]);
    assert_eq!(steps(transition.to_steps()), ["Run", "Init"]);
    assert_eq!(text(transition.condition()).as_deref(), Some("xGo"));
}

#[test]
fn an_action_has_its_name_and_body() {
    let action = first_in_file::<ActionDecl>("ACTION Reset: x := 0; END_ACTION");
    assert_eq!(action.name().map(|n| n.text()).as_deref(), Some("Reset"));
    assert_eq!(text(action.body()).as_deref(), Some("x := 0;"));
}
