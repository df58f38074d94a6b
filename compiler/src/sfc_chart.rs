//! A textual SFC chart read out of a body's syntax tree: its steps with their properties and
//! action associations, and its transitions. The checker and the code generator both read the
//! chart through this one model, so they never disagree on what a step or an association is.
//! The semantics are documented in `docs/sfc-semantics.md`.

use std::ops::Range;

use crate::syntax::ast::{ArgKind, AstNode, CallExpr, Expr, StatementList, Stmt, TransitionDecl};
use crate::syntax::{SyntaxKind, SyntaxNode};

/// The action qualifiers of IEC 61131-3 that CODESYS accepts: the project model's, which the
/// textual chart writes as the graphical one stores them.
pub use project_model::ActionQualifier;

/// One action association of a step: `Act(L, T#5s, lamp);`.
#[derive(Clone, Debug)]
pub struct Association {
    /// The action (or BOOL variable) as written.
    pub action: String,
    /// Where the action's name is written.
    pub action_range: Range<usize>,
    /// The action's name as an expression (a boolean action is a variable written).
    pub action_node: Expr,
    /// The qualifier; `N` when none is written.
    pub qualifier: ActionQualifier,
    /// The qualifier as written, with its range, when written (an unknown one is kept for the
    /// checker to report).
    pub qualifier_written: Option<(String, Range<usize>)>,
    /// The duration of a timed qualifier, or a wrongly given one of an untimed qualifier.
    pub time: Option<Expr>,
    /// The BOOL indicator variable that shows the action's `Q`.
    pub indicator: Option<Expr>,
    /// Arguments after the indicator, for the checker to refuse.
    pub extra: Vec<Range<usize>>,
    /// The whole association.
    pub range: Range<usize>,
}

/// A step property of CODESYS: `MIN_TIME`, `MAX_TIME`, `ENTRY`, `MAIN` or `EXIT`.
#[derive(Clone, Debug)]
pub struct StepProperty {
    /// The property's name in upper case.
    pub name: String,
    /// Where the property's name is written.
    pub name_range: Range<usize>,
    /// Its value.
    pub value: Option<Expr>,
}

/// One step of the chart.
#[derive(Clone, Debug)]
pub struct ChartStep {
    /// The step's name as written.
    pub name: String,
    /// Where the name is written.
    pub name_range: Range<usize>,
    /// `INITIAL_STEP`.
    pub initial: bool,
    /// The properties written before the colon.
    pub properties: Vec<StepProperty>,
    /// The action associations, in the order written.
    pub associations: Vec<Association>,
    /// Statements of the step that are no association, for the checker to refuse.
    pub strays: Vec<Range<usize>>,
}

impl ChartStep {
    /// The value of the property `name` (upper case).
    pub fn property(&self, name: &str) -> Option<&Expr> {
        self.properties
            .iter()
            .find(|p| p.name == name)
            .and_then(|p| p.value.as_ref())
    }

    /// The name of the action given as the property `name` (`ENTRY`, `MAIN`, `EXIT`).
    pub fn action_property(&self, name: &str) -> Option<String> {
        self.property(name)
            .map(|value| value.syntax().text().to_string().trim().to_owned())
    }
}

/// One transition of the chart.
#[derive(Clone, Debug)]
pub struct ChartTransition {
    /// The source steps with where each is written.
    pub from: Vec<(String, Range<usize>)>,
    /// The target steps with where each is written.
    pub to: Vec<(String, Range<usize>)>,
    /// `PRIORITY := n`; `None` when not written.
    pub priority: Option<Expr>,
    /// The transition as written.
    pub node: TransitionDecl,
}

impl ChartTransition {
    /// The priority as a number; transitions without one come after those with one.
    pub fn priority_value(&self) -> u32 {
        self.priority
            .as_ref()
            .and_then(|p| p.syntax().text().to_string().trim().parse().ok())
            .unwrap_or(u32::MAX)
    }
}

/// The SFC flags of CODESYS a POU may declare, with whether each is a STRING (else BOOL).
pub const SFC_FLAGS: &[(&str, bool)] = &[
    ("SFCInit", false),
    ("SFCReset", false),
    ("SFCPause", false),
    ("SFCError", false),
    ("SFCEnableLimit", false),
    ("SFCErrorStep", true),
    ("SFCErrorPOU", true),
    ("SFCQuitError", false),
    ("SFCTrans", false),
    ("SFCCurrentStep", true),
    ("SFCTip", false),
    ("SFCTipMode", false),
];

/// Whether the text of a body may hold a chart (it mentions a step), a cheap test made before
/// parsing it for one.
pub fn may_hold_chart(text: &str) -> bool {
    text.to_ascii_uppercase().contains("STEP")
}

/// A textual SFC chart.
#[derive(Clone, Debug, Default)]
pub struct Chart {
    /// The steps, in text order.
    pub steps: Vec<ChartStep>,
    /// The transitions, in text order.
    pub transitions: Vec<ChartTransition>,
    /// Arguments of `TRANSITION (…)` other than `PRIORITY := n`, for the checker to refuse.
    pub bad_transition_arguments: Vec<Range<usize>>,
}

fn range_of(node: &SyntaxNode) -> Range<usize> {
    let range = node.text_range();
    usize::from(range.start())..usize::from(range.end())
}

fn trimmed(node: &SyntaxNode) -> String {
    node.text().to_string().trim().to_owned()
}

impl Chart {
    /// The chart among the statements `list`; `None` when it has no step.
    pub fn of(list: &StatementList) -> Option<Self> {
        let mut chart = Self::default();
        for statement in list.statements() {
            match statement {
                Stmt::StepDecl(step) => {
                    let Some(name) = step.name() else {
                        continue;
                    };
                    let mut properties = Vec::new();
                    for arg in step.arg_list().iter().flat_map(|l| l.args()) {
                        let (name, name_range) = match arg.name() {
                            Some(token) => {
                                let range = token.text_range();
                                (
                                    token.text().to_ascii_uppercase(),
                                    usize::from(range.start())..usize::from(range.end()),
                                )
                            }
                            None => (String::new(), range_of(arg.syntax())),
                        };
                        properties.push(StepProperty {
                            name,
                            name_range,
                            value: arg.value(),
                        });
                    }
                    let mut associations = Vec::new();
                    let mut strays = Vec::new();
                    for inner in step.statements() {
                        match association(&inner) {
                            Some(found) => associations.push(found),
                            None => {
                                if !matches!(inner, Stmt::EmptyStmt(_)) {
                                    strays.push(range_of(inner.syntax()));
                                }
                            }
                        }
                    }
                    chart.steps.push(ChartStep {
                        name: name.text(),
                        name_range: range_of(name.syntax()),
                        initial: step.is_initial(),
                        properties,
                        associations,
                        strays,
                    });
                }
                Stmt::TransitionDecl(transition) => {
                    let names = |list: Option<crate::syntax::ast::StepList>| {
                        list.iter()
                            .flat_map(|l| l.steps())
                            .map(|s| (s.text(), range_of(s.syntax())))
                            .collect::<Vec<_>>()
                    };
                    let mut priority = None;
                    for arg in transition.arg_list().iter().flat_map(|l| l.args()) {
                        let is_priority = arg
                            .name()
                            .is_some_and(|n| n.text().eq_ignore_ascii_case("PRIORITY"));
                        if is_priority && priority.is_none() {
                            priority = arg.value();
                        } else {
                            chart.bad_transition_arguments.push(range_of(arg.syntax()));
                        }
                    }
                    chart.transitions.push(ChartTransition {
                        from: names(transition.from_steps()),
                        to: names(transition.to_steps()),
                        priority,
                        node: transition,
                    });
                }
                _ => {}
            }
        }
        (!chart.steps.is_empty()).then_some(chart)
    }

    /// The step called `name` (any case) with its index.
    pub fn step(&self, name: &str) -> Option<(usize, &ChartStep)> {
        self.steps
            .iter()
            .enumerate()
            .find(|(_, s)| s.name.eq_ignore_ascii_case(name))
    }

    /// The transitions in the order they are tested: by `PRIORITY` (lowest first, those without
    /// one last), then in text order.
    pub fn transitions_in_test_order(&self) -> Vec<&ChartTransition> {
        let mut ordered: Vec<(usize, &ChartTransition)> =
            self.transitions.iter().enumerate().collect();
        ordered.sort_by_key(|(index, t)| (t.priority_value(), *index));
        ordered.into_iter().map(|(_, t)| t).collect()
    }

    /// The names (lower case) of everything the steps associate as actions, in alphabetical
    /// order, each once: the order CODESYS runs IEC actions in.
    pub fn associated_actions(&self) -> Vec<String> {
        let mut names: Vec<String> = self
            .steps
            .iter()
            .flat_map(|s| &s.associations)
            .map(|a| a.action.to_ascii_lowercase())
            .collect();
        names.sort();
        names.dedup();
        names
    }
}

/// The association a step's statement writes, `Act(D, T#2s, lamp);` or `Act;`.
fn association(statement: &Stmt) -> Option<Association> {
    let (callee, call): (Expr, Option<CallExpr>) = match statement {
        Stmt::CallStmt(stmt) => {
            let call = stmt.call()?;
            (call.callee()?, Some(call))
        }
        _ => return None,
    };
    if callee.syntax().kind() != SyntaxKind::NAME_EXPR {
        return None;
    }
    let mut args = call.iter().flat_map(CallExpr::args);
    let mut qualifier = ActionQualifier::N;
    let mut qualifier_written = None;
    let mut time = None;
    let mut indicator = None;
    let mut extra = Vec::new();
    if let Some(first) = args.next() {
        if first.kind() != ArgKind::Positional {
            return None;
        }
        let written = first.value().map(|v| trimmed(v.syntax()))?;
        if let Some(known) = ActionQualifier::parse(&written) {
            qualifier = known;
        }
        qualifier_written = Some((written, range_of(first.syntax())));
    }
    let rest: Vec<Expr> = args.filter_map(|a| a.value()).collect();
    match rest.as_slice() {
        [] => {}
        [one] if qualifier.is_timed() => time = Some(one.clone()),
        [one] => {
            // An untimed qualifier's one further argument is its indicator, unless it is
            // written as a duration, which the checker refuses.
            if trimmed(one.syntax()).to_ascii_uppercase().starts_with("T#")
                || trimmed(one.syntax())
                    .to_ascii_uppercase()
                    .starts_with("TIME#")
            {
                time = Some(one.clone());
            } else {
                indicator = Some(one.clone());
            }
        }
        [first, second, more @ ..] => {
            time = Some(first.clone());
            indicator = Some(second.clone());
            extra = more.iter().map(|e| range_of(e.syntax())).collect();
        }
    }
    Some(Association {
        action: trimmed(callee.syntax()),
        action_range: range_of(callee.syntax()),
        action_node: callee.clone(),
        qualifier,
        qualifier_written,
        time,
        indicator,
        extra,
        range: range_of(statement.syntax()),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::syntax::ast::SourceFile;
    use crate::syntax::parse_statements;

    fn chart(text: &str) -> Chart {
        let root = parse_statements(text).syntax();
        let list = SourceFile::cast(root)
            .and_then(|file| file.statement_list())
            .expect("a statement list");
        Chart::of(&list).expect("a chart")
    }

    #[test]
    fn steps_properties_and_associations_are_read_as_written() {
        let chart = chart(
            "INITIAL_STEP Idle: END_STEP
             STEP Fill (MIN_TIME := T#1s, EXIT := Out): Pump(L, T#5s, lamp); Horn; valve(N, lit); Stir(); END_STEP",
        );
        assert_eq!(chart.steps.len(), 2);
        assert!(chart.steps[0].initial);
        let fill = &chart.steps[1];
        assert_eq!(fill.action_property("EXIT").as_deref(), Some("Out"));
        assert!(fill.property("MIN_TIME").is_some());
        let pump = &fill.associations[0];
        assert_eq!(
            (pump.action.as_str(), pump.qualifier),
            ("Pump", ActionQualifier::L)
        );
        assert!(pump.time.is_some() && pump.indicator.is_some());
        // `Horn;` is no association, `valve(N, lit)` has an indicator and no time, and
        // `Stir()` is N.
        assert_eq!(fill.strays.len(), 1);
        assert!(fill.associations[1].time.is_none() && fill.associations[1].indicator.is_some());
        assert_eq!(fill.associations[2].qualifier, ActionQualifier::N);
    }

    #[test]
    fn transitions_are_tested_by_priority_then_text_order() {
        let chart = chart(
            "INITIAL_STEP S0: END_STEP STEP A: END_STEP STEP B: END_STEP STEP C: END_STEP
             TRANSITION FROM S0 TO A := TRUE; END_TRANSITION
             TRANSITION (PRIORITY := 2) FROM S0 TO B := TRUE; END_TRANSITION
             TRANSITION (PRIORITY := 1) FROM S0 TO C := TRUE; END_TRANSITION",
        );
        let order: Vec<&str> = chart
            .transitions_in_test_order()
            .iter()
            .map(|t| t.to[0].0.as_str())
            .collect();
        assert_eq!(order, ["C", "B", "A"]);
    }

    #[test]
    fn qualifiers_parse_in_any_case_and_know_their_durations() {
        for qualifier in ActionQualifier::ALL {
            assert_eq!(
                ActionQualifier::parse(&qualifier.as_str().to_lowercase()),
                Some(qualifier)
            );
        }
        assert_eq!(ActionQualifier::parse("Q"), None);
        let timed: Vec<&str> = ["N", "L", "D", "P", "SD", "DS", "SL", "S"]
            .into_iter()
            .filter(|q| ActionQualifier::parse(q).is_some_and(ActionQualifier::is_timed))
            .collect();
        assert_eq!(timed, ["L", "D", "SD", "DS", "SL"]);
    }

    #[test]
    fn actions_are_listed_once_in_alphabetical_order() {
        let chart = chart(
            "INITIAL_STEP S0: Zeta(N); alpha(S); END_STEP STEP S1: ALPHA(R); Mid(P); END_STEP",
        );
        assert_eq!(chart.associated_actions(), ["alpha", "mid", "zeta"]);
    }
}
