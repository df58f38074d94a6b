//! Statements: the `Stmt` enum and the accessors of each statement node.

use super::expressions::ast_enum;
use super::support::{child, children, node_after, nth_node, tokens, trimmed_text};
use super::*;

ast_enum! {
    /// Any statement of a statement list (or of an SFC step or transition).
    Stmt {
        /// `target := value;`.
        AssignStmt,
        /// `target S= value;`.
        SetStmt,
        /// `target R= value;`.
        ResetStmt,
        /// `target REF= value;`.
        RefAssignStmt,
        /// `target ?= value;`.
        AttemptAssignStmt,
        /// `f(x);`.
        CallStmt,
        /// `IF … END_IF`.
        IfStmt,
        /// `CASE … END_CASE`.
        CaseStmt,
        /// `FOR … END_FOR`.
        ForStmt,
        /// `WHILE … END_WHILE`.
        WhileStmt,
        /// `REPEAT … END_REPEAT`.
        RepeatStmt,
        /// `EXIT;`.
        ExitStmt,
        /// `CONTINUE;`.
        ContinueStmt,
        /// `RETURN;`.
        ReturnStmt,
        /// `JMP label;`.
        JmpStmt,
        /// `label:`.
        LabelStmt,
        /// `;`.
        EmptyStmt,
        /// `STEP Name: … END_STEP`.
        StepDecl,
        /// `TRANSITION … END_TRANSITION`.
        TransitionDecl,
    }
}

/// Accessors of the statements written `target <operator> value;`.
macro_rules! target_and_value {
    ($($name:ident),*) => {
        $(
            impl $name {
                /// The place assigned (or, for a broken statement, the only expression).
                pub fn target(&self) -> Option<Expr> {
                    nth_node(&self.0, 0)
                }

                /// The value assigned.
                pub fn value(&self) -> Option<Expr> {
                    nth_node(&self.0, 1)
                }
            }
        )*
    };
}

target_and_value!(
    AssignStmt,
    SetStmt,
    ResetStmt,
    RefAssignStmt,
    AttemptAssignStmt
);

impl CallStmt {
    /// The call.
    pub fn call(&self) -> Option<CallExpr> {
        child(&self.0)
    }
}

impl StatementList {
    /// The statements, in order; input the parser could not read as a statement is left out.
    pub fn statements(&self) -> AstChildren<Stmt> {
        children(&self.0)
    }

    /// The SFC steps among the statements, in order.
    pub fn steps(&self) -> AstChildren<StepDecl> {
        children(&self.0)
    }

    /// The SFC transitions among the statements, in order.
    pub fn transitions(&self) -> AstChildren<TransitionDecl> {
        children(&self.0)
    }

    /// The SFC actions (`ACTION Name: … END_ACTION`) among the statements, in order.
    pub fn actions(&self) -> AstChildren<ActionDecl> {
        children(&self.0)
    }
}

impl SourceFile {
    /// The statement list of a body parsed on its own (`parse_statements`).
    pub fn statement_list(&self) -> Option<StatementList> {
        child(&self.0)
    }
}

impl IfStmt {
    /// The condition after `IF`.
    pub fn condition(&self) -> Option<Expr> {
        child(&self.0)
    }

    /// The statements after `THEN`.
    pub fn then_branch(&self) -> Option<StatementList> {
        child(&self.0)
    }

    /// The `ELSIF` branches, in order.
    pub fn elsif_branches(&self) -> AstChildren<ElsifBranch> {
        children(&self.0)
    }

    /// The `ELSE` branch.
    pub fn else_branch(&self) -> Option<ElseBranch> {
        child(&self.0)
    }
}

impl ElsifBranch {
    /// The condition after `ELSIF`.
    pub fn condition(&self) -> Option<Expr> {
        child(&self.0)
    }

    /// The statements after `THEN`.
    pub fn body(&self) -> Option<StatementList> {
        child(&self.0)
    }
}

impl ElseBranch {
    /// The statements after `ELSE`.
    pub fn body(&self) -> Option<StatementList> {
        child(&self.0)
    }
}

impl CaseStmt {
    /// The selector after `CASE`.
    pub fn selector(&self) -> Option<Expr> {
        child(&self.0)
    }

    /// The labelled branches, in order.
    pub fn branches(&self) -> AstChildren<CaseBranch> {
        children(&self.0)
    }

    /// The `ELSE` branch.
    pub fn else_branch(&self) -> Option<ElseBranch> {
        child(&self.0)
    }
}

impl CaseBranch {
    /// The labels before `:`.
    pub fn labels(&self) -> impl Iterator<Item = CaseLabel> + use<> {
        child::<CaseLabels>(&self.0)
            .into_iter()
            .flat_map(|labels| children::<CaseLabel>(&labels.0))
    }

    /// The statements after `:`.
    pub fn body(&self) -> Option<StatementList> {
        child(&self.0)
    }
}

/// One label of a CASE branch.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum CaseLabel {
    /// A range `3..5`.
    Range(CaseRange),
    /// One value.
    Value(Expr),
}

impl AstNode for CaseLabel {
    fn can_cast(kind: SyntaxKind) -> bool {
        CaseRange::can_cast(kind) || Expr::can_cast(kind)
    }

    fn cast(node: SyntaxNode) -> Option<Self> {
        match CaseRange::cast(node.clone()) {
            Some(range) => Some(Self::Range(range)),
            None => Expr::cast(node).map(Self::Value),
        }
    }

    fn syntax(&self) -> &SyntaxNode {
        match self {
            Self::Range(range) => range.syntax(),
            Self::Value(value) => value.syntax(),
        }
    }
}

impl CaseRange {
    /// The lower bound.
    pub fn low(&self) -> Option<Expr> {
        nth_node(&self.0, 0)
    }

    /// The upper bound.
    pub fn high(&self) -> Option<Expr> {
        nth_node(&self.0, 1)
    }
}

impl ForStmt {
    /// The control variable, between `FOR` and `:=`.
    pub fn variable(&self) -> Option<Expr> {
        node_after(&self.0, Some(SyntaxKind::FOR))
    }

    /// The start value, after `:=`.
    pub fn from(&self) -> Option<Expr> {
        node_after(&self.0, Some(SyntaxKind::ASSIGN))
    }

    /// The end value, after `TO`.
    pub fn to(&self) -> Option<Expr> {
        node_after(&self.0, Some(SyntaxKind::TO))
    }

    /// The step, after `BY`.
    pub fn by(&self) -> Option<Expr> {
        node_after(&self.0, Some(SyntaxKind::BY))
    }

    /// The statements after `DO`.
    pub fn body(&self) -> Option<StatementList> {
        child(&self.0)
    }
}

impl WhileStmt {
    /// The condition after `WHILE`.
    pub fn condition(&self) -> Option<Expr> {
        child(&self.0)
    }

    /// The statements after `DO`.
    pub fn body(&self) -> Option<StatementList> {
        child(&self.0)
    }
}

impl RepeatStmt {
    /// The statements after `REPEAT`.
    pub fn body(&self) -> Option<StatementList> {
        child(&self.0)
    }

    /// The condition after `UNTIL`.
    pub fn condition(&self) -> Option<Expr> {
        child(&self.0)
    }
}

impl JmpStmt {
    /// The label jumped to.
    pub fn label(&self) -> Option<NameRef> {
        child(&self.0)
    }
}

impl LabelStmt {
    /// The label's name.
    pub fn name(&self) -> Option<Name> {
        child(&self.0)
    }
}

impl StepDecl {
    /// The step's name.
    pub fn name(&self) -> Option<Name> {
        child(&self.0)
    }

    /// Whether it is the `INITIAL_STEP`.
    pub fn is_initial(&self) -> bool {
        tokens(&self.0)
            .next()
            .is_some_and(|t| t.text().eq_ignore_ascii_case("INITIAL_STEP"))
    }

    /// The step's properties, `(MIN_TIME := T#1s, ENTRY := Fill_in)`, when written.
    pub fn arg_list(&self) -> Option<ArgList> {
        child(&self.0)
    }

    /// The action associations, `Action(N);`, as written.
    pub fn statements(&self) -> AstChildren<Stmt> {
        children(&self.0)
    }
}

impl TransitionDecl {
    /// The transition's name, if it has one.
    pub fn name(&self) -> Option<Name> {
        child(&self.0)
    }

    /// The arguments after `TRANSITION`, `(PRIORITY := 1)`.
    pub fn arg_list(&self) -> Option<ArgList> {
        child(&self.0)
    }

    /// The steps after `FROM`.
    pub fn from_steps(&self) -> Option<StepList> {
        children::<StepList>(&self.0).next()
    }

    /// The steps after `TO`.
    pub fn to_steps(&self) -> Option<StepList> {
        children::<StepList>(&self.0).nth(1)
    }

    /// The condition after `:=`.
    pub fn condition(&self) -> Option<Expr> {
        child(&self.0)
    }

    /// The statements of the `:` form, which assign the transition's name.
    pub fn statements(&self) -> AstChildren<Stmt> {
        children(&self.0)
    }
}

impl StepList {
    /// The steps named, in order.
    pub fn steps(&self) -> AstChildren<NameRef> {
        children(&self.0)
    }
}

impl ActionDecl {
    /// The action's name.
    pub fn name(&self) -> Option<Name> {
        child(&self.0)
    }

    /// The action's statements.
    pub fn body(&self) -> Option<StatementList> {
        child(&self.0)
    }
}

impl Name {
    /// The name as written, without surrounding trivia.
    pub fn text(&self) -> String {
        trimmed_text(&self.0)
    }
}

impl NameRef {
    /// The name as written (dotted names keep their dots), without surrounding trivia.
    pub fn text(&self) -> String {
        trimmed_text(&self.0)
    }
}
