//! Checking a textual SFC chart: steps, initial step, transitions, action associations with
//! their qualifiers and durations, step properties and the SFC flags (codes E0116–E0125).

use project_model::PouKind;

use super::{BodyChecker, Mode, range_of, text};
use crate::diagnostic::Code;
use crate::elementary::Elementary;
use crate::sema::scope::{Globals, LocalSymbol};
use crate::sema::ty::Type;
use crate::sfc_chart::{Chart, ChartStep};
use crate::syntax::ast::{AstNode, Expr};

const STEP_PROPERTIES: &[&str] = &["MIN_TIME", "MAX_TIME", "ENTRY", "MAIN", "EXIT"];

/// The type of `name` as a member of an instance of `type_name` whose body holds a chart: a
/// step (`Main.Fill`) or the flags of an associated action (`Main._Pump`).
pub(super) fn chart_member(globals: &Globals<'_>, type_name: &str, name: &str) -> Option<Type> {
    let pou = globals.pou(type_name)?;
    let text = pou
        .body
        .st_text()
        .filter(|text| crate::sfc_chart::may_hold_chart(text))?;
    let parse = crate::syntax::parse_statements(text);
    let list = crate::syntax::ast::SourceFile::cast(parse.syntax())?.statement_list()?;
    let chart = Chart::of(&list)?;
    if chart.step(name).is_some() {
        return Some(Type::Step);
    }
    let action = name.strip_prefix('_')?.to_ascii_lowercase();
    chart
        .associated_actions()
        .contains(&action)
        .then_some(Type::SfcAction)
}

impl BodyChecker<'_, '_, '_> {
    /// Checks the chart of a body (its steps, transitions and associations); the statements
    /// of transitions are checked with the other statements.
    pub(super) fn chart(&mut self, chart: &Chart) {
        let pou = self.scope.pou;
        if pou.is_some() && !self.scope.chart_allowed {
            self.error(
                Code::SfcOutsideInstance,
                chart.steps[0].name_range.clone(),
                "only the body of a program or function block itself holds a chart, not one of its methods, properties or actions",
            );
        } else if let Some(pou) = pou
            && !matches!(pou.kind, PouKind::Program | PouKind::FunctionBlock)
        {
            let first = &chart.steps[0];
            self.error(
                Code::SfcOutsideInstance,
                first.name_range.clone(),
                format!(
                    "'{}' is a {}: SFC steps keep their state in an instance, so only programs and function blocks may hold a chart",
                    pou.name,
                    pou.kind.keyword()
                ),
            );
        }
        self.steps_and_initial(chart);
        for step in &chart.steps {
            self.step_properties(step);
            self.associations(step);
        }
        for transition in &chart.transitions {
            for (name, range) in transition.from.iter().chain(&transition.to) {
                if chart.step(name).is_none() {
                    let known: Vec<&str> = chart.steps.iter().map(|s| s.name.as_str()).collect();
                    let hint = crate::sema::closest(name, known.iter().copied())
                        .map(|c| format!("; did you mean '{c}'?"))
                        .unwrap_or_default();
                    self.error(
                        Code::UnknownStep,
                        range.clone(),
                        format!(
                            "the transition names '{name}', which is no step of the chart{hint}"
                        ),
                    );
                }
            }
            if transition.node.condition().is_none() && transition.node.name().is_none() {
                self.error(
                    Code::InvalidTransitionPriority,
                    range_of(transition.node.syntax()),
                    "a transition is 'TRANSITION FROM a TO b := condition;', or 'TRANSITION Name FROM a TO b : statements assigning Name END_TRANSITION'",
                );
            }
            if let Some(priority) = &transition.priority {
                let written = text(priority.syntax());
                if written.parse::<u32>().is_err() {
                    self.error(
                        Code::InvalidTransitionPriority,
                        range_of(priority.syntax()),
                        format!(
                            "a transition's PRIORITY is a whole number from 0 up, not '{written}'"
                        ),
                    );
                }
            }
        }
        for range in chart.bad_transition_arguments.clone() {
            self.error(
                Code::InvalidTransitionPriority,
                range,
                "a transition takes only '(PRIORITY := n)' before FROM",
            );
        }
    }

    fn steps_and_initial(&mut self, chart: &Chart) {
        let mut seen = std::collections::HashSet::new();
        for step in &chart.steps {
            let clashes = self.scope.pou.is_some_and(|pou| {
                pou.variables
                    .iter()
                    .any(|v| v.name.eq_ignore_ascii_case(&step.name))
            });
            if clashes {
                self.error(
                    Code::DuplicateName,
                    step.name_range.clone(),
                    format!(
                        "the step '{}' has the name of a variable of the POU; `{}.x` would be ambiguous",
                        step.name, step.name
                    ),
                );
            }
            if !seen.insert(step.name.to_ascii_lowercase()) {
                self.error(
                    Code::DuplicateStep,
                    step.name_range.clone(),
                    format!("the chart has a step called '{}' already", step.name),
                );
            }
        }
        let initial: Vec<&ChartStep> = chart.steps.iter().filter(|s| s.initial).collect();
        match initial.as_slice() {
            [] => self.error(
                Code::InitialStep,
                chart.steps[0].name_range.clone(),
                "the chart has no INITIAL_STEP; write 'INITIAL_STEP' for the step it starts in",
            ),
            [_] => {}
            [first, others @ ..] => {
                for other in others {
                    self.error(
                        Code::InitialStep,
                        other.name_range.clone(),
                        format!(
                            "the chart has its initial step '{}' already; a chart has exactly one",
                            first.name
                        ),
                    );
                }
            }
        }
    }

    fn step_properties(&mut self, step: &ChartStep) {
        for property in &step.properties {
            if !STEP_PROPERTIES.contains(&property.name.as_str()) {
                self.error(
                    Code::UnknownStepAction,
                    property.name_range.clone(),
                    format!(
                        "a step's properties are MIN_TIME, MAX_TIME, ENTRY, MAIN and EXIT, written 'NAME := value'; '{}' is none of them",
                        if property.name.is_empty() { "this" } else { &property.name }
                    ),
                );
                continue;
            }
            if step
                .properties
                .iter()
                .take_while(|p| !std::ptr::eq(*p, property))
                .any(|p| p.name == property.name)
            {
                self.error(
                    Code::UnknownStepAction,
                    property.name_range.clone(),
                    format!("the step gives {} twice", property.name),
                );
            }
            let Some(value) = &property.value else {
                continue;
            };
            if property.name.ends_with("_TIME") {
                self.time_value(value);
            } else {
                let name = text(value.syntax());
                if !self.is_action(&name) {
                    self.error(
                        Code::UnknownStepAction,
                        range_of(value.syntax()),
                        format!(
                            "the step's {} names '{name}', which is no action of the POU or of the chart",
                            property.name
                        ),
                    );
                }
            }
        }
        for range in &step.strays {
            self.error(
                Code::UnknownAction,
                range.clone(),
                "a step holds only action associations such as 'Act(N);' or 'Act(L, T#5s);'",
            );
        }
    }

    fn associations(&mut self, step: &ChartStep) {
        for association in &step.associations {
            let action = &association.action;
            if !self.is_action(action) {
                // A boolean action: a BOOL variable set to the action's Q.
                let ty = match self.scope.local(action) {
                    Some(LocalSymbol::Var(_)) => {
                        Some(self.expression(&association.action_node, Mode::Write))
                    }
                    None if self.scope.globals.lookup(action).is_some() => {
                        Some(self.expression(&association.action_node, Mode::Write))
                    }
                    _ => None,
                };
                if ty != Some(Type::BOOL) {
                    self.error(
                        Code::UnknownAction,
                        association.action_range.clone(),
                        format!(
                            "'{action}' is neither an action of the POU or of the chart nor a BOOL variable"
                        ),
                    );
                }
            }
            if let Some((written, range)) = &association.qualifier_written
                && crate::sfc_chart::ActionQualifier::parse(written).is_none()
            {
                self.error(
                    Code::QualifierTime,
                    range.clone(),
                    format!(
                        "'{written}' is no action qualifier; they are N, R, S, L, D, P, P0, P1, SD, DS and SL"
                    ),
                );
                continue;
            }
            let qualifier = association.qualifier;
            match (&association.time, qualifier.is_timed()) {
                (None, true) => self.error(
                    Code::QualifierTime,
                    association.range.clone(),
                    format!(
                        "the qualifier {} needs a duration, as in '{action}({}, T#5s);'",
                        qualifier.as_str(),
                        qualifier.as_str()
                    ),
                ),
                (Some(time), false) => self.error(
                    Code::QualifierTime,
                    range_of(time.syntax()),
                    format!("the qualifier {} takes no duration", qualifier.as_str()),
                ),
                (Some(time), true) => self.time_value(time),
                (None, false) => {}
            }
            for range in &association.extra {
                self.error(
                    Code::QualifierTime,
                    range.clone(),
                    "an association is 'Action(qualifier[, duration][, indicator]);'",
                );
            }
            if let Some(indicator) = &association.indicator {
                let ty = self.expression(indicator, Mode::Write);
                if qualifier.is_timed() || ty != Type::Elementary(Elementary::Time) {
                    if self.assignable_target(indicator, &ty) {
                        self.expect_type(
                            &ty,
                            &Type::BOOL,
                            indicator.syntax(),
                            "an indicator variable",
                        );
                    }
                } else {
                    self.error(
                        Code::QualifierTime,
                        range_of(indicator.syntax()),
                        format!("the qualifier {} takes no duration", qualifier.as_str()),
                    );
                }
            }
        }
    }

    /// Checks a duration: a TIME constant or variable.
    fn time_value(&mut self, value: &Expr) {
        let ty = self.expression(value, Mode::Read);
        if !matches!(ty, Type::Elementary(Elementary::Time) | Type::Error) {
            self.error(
                Code::NotATime,
                range_of(value.syntax()),
                format!("a step's or action's duration is a TIME, such as T#5s, not {ty}"),
            );
        }
    }

    /// Whether `name` is an action of the POU or one declared in the chart.
    fn is_action(&self, name: &str) -> bool {
        matches!(self.scope.local(name), Some(LocalSymbol::Action))
    }
}
