//! Textual SFC (IEC 61131-3 §6.7): steps, transitions and actions written in a POU's body.
//!
//! Each cycle the chart (1) activates its initial steps on the first cycle, (2) brings the
//! elapsed time `T` of every active step up to date, (3) runs the actions of the active steps
//! by their qualifiers (N while active, P once on activation, S and R setting and resetting a
//! stored action that then runs while set), then (4) evaluates every transition against the
//! steps active before any fires and fires those enabled: their source steps are deactivated
//! and their target steps activated (with `T` from zero), to act from the next cycle on.

use std::collections::HashMap;

use program_image::{BinaryOp, Elementary as IE, Instr, Operand};

use super::body::{BodyGen, Gen};
use super::error::fail;
use crate::sema::ty::Type;
use crate::syntax::ast::{
    Arg, AstNode, CallExpr, SourceFile, StatementList, StepDecl, StepList, Stmt,
};
use crate::syntax::{SyntaxNode, parse_statements};

/// One step's state in the instance.
#[derive(Clone, Debug)]
pub(crate) struct StepSlots {
    pub(crate) name: String,
    pub(crate) initial: bool,
    /// BOOL: active (`Step.X`).
    pub(crate) active: u32,
    /// BOOL: activated by the last transition, so its P actions run this cycle.
    pub(crate) fresh: u32,
    /// TIME: elapsed since activation (`Step.T`).
    pub(crate) elapsed: u32,
    /// LINT: the task clock at activation.
    pub(crate) started: u32,
}

/// The SFC state a chart keeps at the end of its instance.
#[derive(Clone, Debug, Default)]
pub(crate) struct SfcLayout {
    /// BOOL: the initial steps have been activated.
    pub(crate) initialised: u32,
    pub(crate) steps: Vec<StepSlots>,
    /// BOOL per stored action (S and R qualifiers), by lower-case action name.
    pub(crate) stored: Vec<(String, u32)>,
}

impl SfcLayout {
    /// The layout of the chart in `text` placed from `offset` on, with its end; `None` when
    /// the text has no steps.
    pub(crate) fn of_body(text: &str, offset: u32) -> Option<(Self, u32)> {
        if !text.to_ascii_uppercase().contains("STEP") {
            return None;
        }
        let root = top_level(&parse_statements(text).syntax())?;
        let mut layout = Self {
            initialised: offset,
            ..Self::default()
        };
        let mut at = (offset + 1).next_multiple_of(8);
        for step in root.steps() {
            let Some(name) = step.name() else {
                continue;
            };
            layout.steps.push(StepSlots {
                name: name.text(),
                initial: step.is_initial(),
                active: at,
                fresh: at + 1,
                elapsed: at + 4,
                started: at + 8,
            });
            at += 16;
            for (action, qualifier) in associations(&step) {
                if matches!(qualifier.as_str(), "S" | "R")
                    && !layout.stored.iter().any(|(a, _)| *a == action)
                {
                    layout.stored.push((action, 0));
                }
            }
        }
        if layout.steps.is_empty() {
            return None;
        }
        for (_, slot) in &mut layout.stored {
            *slot = at;
            at += 1;
        }
        Some((layout, at.next_multiple_of(8)))
    }

    /// The step called `name`.
    pub(crate) fn step(&self, name: &str) -> Option<&StepSlots> {
        self.steps
            .iter()
            .find(|s| s.name.eq_ignore_ascii_case(name))
    }
}

/// The statements at the top of a body: a chart's steps, transitions and actions are among
/// them.
pub(crate) fn top_level(root: &SyntaxNode) -> Option<StatementList> {
    SourceFile::cast(root.clone()).and_then(|file| file.statement_list())
}

/// The action associations of a step: (lower-case action name, upper-case qualifier).
fn associations(step: &StepDecl) -> Vec<(String, String)> {
    step.syntax()
        .descendants()
        .filter_map(CallExpr::cast)
        .filter_map(|call| {
            let name = call
                .callee()?
                .syntax()
                .text()
                .to_string()
                .trim()
                .to_lowercase();
            let qualifier = call
                .syntax()
                .descendants()
                .find_map(Arg::cast)
                .map(|arg| arg.syntax().text().to_string().trim().to_ascii_uppercase())
                .unwrap_or_else(|| "N".to_owned());
            Some((name, qualifier))
        })
        .collect()
}

fn step_names(list: &StepList) -> Vec<String> {
    list.steps().map(|step| step.text()).collect()
}

impl BodyGen<'_, '_, '_> {
    fn sfc(&self) -> Gen<SfcLayout> {
        self.instance
            .as_ref()
            .and_then(|i| i.sfc.clone())
            .ok_or_else(|| "SFC steps are only allowed in a program or function block".into())
    }

    fn set_bool(&mut self, offset: u32, value: bool) {
        let constant = self.build.constant(&[u8::from(value)]);
        self.emit(Instr::Move {
            ty: IE::Bool,
            dst: Operand::Instance(offset),
            src: constant,
        });
    }

    fn activate(&mut self, step: &StepSlots, now: Operand) {
        self.set_bool(step.active, true);
        self.set_bool(step.fresh, true);
        self.emit(Instr::Move {
            ty: IE::Lint,
            dst: Operand::Instance(step.started),
            src: now,
        });
        let zero = self.build.constant(&[0; 4]);
        self.emit(Instr::Move {
            ty: IE::Time,
            dst: Operand::Instance(step.elapsed),
            src: zero,
        });
    }

    /// Runs the action `name`: one declared in the chart (its statements, inline) or an action
    /// of the POU.
    fn run_action(&mut self, name: &str, inline: &HashMap<String, StatementList>) -> Gen<()> {
        if let Some(statements) = inline.get(name) {
            let statements = statements.clone();
            return self.statement_list(&statements);
        }
        let pou = self.pou;
        let action = pou
            .actions
            .iter()
            .find(|a| a.name.eq_ignore_ascii_case(name))
            .ok_or_else(|| {
                format!(
                    "the step names '{name}', which is no action of '{}'",
                    pou.name
                )
            })?;
        let index = self.build.pou_index(&pou.name, Some(&action.name))?;
        self.emit(Instr::CallBlock {
            pou: index,
            instance: Operand::Instance(0),
            indirect: false,
        });
        Ok(())
    }

    /// The condition under which an N or P association runs its action this cycle.
    fn control(&mut self, qualifier: &str, step: &StepSlots) -> Gen<Operand> {
        match qualifier {
            "N" => Ok(Operand::Instance(step.active)),
            "P" | "P1" => {
                let both = self.temp(1);
                self.emit(Instr::Binary {
                    op: BinaryOp::And,
                    ty: IE::Bool,
                    dst: both,
                    a: Operand::Instance(step.active),
                    b: Operand::Instance(step.fresh),
                });
                Ok(both)
            }
            other => Err(fail!(
                "the action qualifier {other} is not supported yet (N, P, S and R are)"
            )),
        }
    }

    /// ORs `control` into the sum kept for the boolean action `name`.
    fn or_into(&mut self, sums: &mut Vec<(String, Operand)>, name: String, control: Operand) {
        match sums.iter().find(|(known, _)| *known == name) {
            Some((_, sum)) => {
                let sum = *sum;
                self.emit(Instr::Binary {
                    op: BinaryOp::Or,
                    ty: IE::Bool,
                    dst: sum,
                    a: sum,
                    b: control,
                });
            }
            None => {
                let sum = self.temp(1);
                self.emit(Instr::Move {
                    ty: IE::Bool,
                    dst: sum,
                    src: control,
                });
                sums.push((name, sum));
            }
        }
    }

    /// Generates a body holding a chart: its plain statements, then one step of the chart.
    pub(crate) fn chart(&mut self, root: &SyntaxNode) -> Gen<()> {
        let Some(root) = &top_level(root) else {
            return Ok(());
        };
        let sfc = self.sfc()?;
        let mut inline = HashMap::new();
        for action in root.actions() {
            if let (Some(name), Some(body)) = (action.name(), action.body()) {
                inline.insert(name.text().to_lowercase(), body);
            }
        }
        for statement in root.statements() {
            if !matches!(statement, Stmt::StepDecl(_) | Stmt::TransitionDecl(_)) {
                self.statement_with_line(&statement)?;
            }
        }
        let now = self.temp(8);
        self.emit(Instr::Now { dst: now });
        // (1) The first cycle activates the initial steps.
        let initialised = Operand::Instance(sfc.initialised);
        let skip = self.emit(Instr::JumpIf {
            cond: initialised,
            target: 0,
        });
        for step in sfc.steps.iter().filter(|s| s.initial) {
            self.activate(step, now);
        }
        self.set_bool(sfc.initialised, true);
        let after = self.here();
        self.patch(skip, after);
        // (2) Elapsed times of the active steps.
        for step in &sfc.steps {
            let skip = self.emit(Instr::JumpIfNot {
                cond: Operand::Instance(step.active),
                target: 0,
            });
            let nanos = self.temp(8);
            self.emit(Instr::Binary {
                op: BinaryOp::Sub,
                ty: IE::Lint,
                dst: nanos,
                a: now,
                b: Operand::Instance(step.started),
            });
            self.emit(Instr::Convert {
                from: IE::Ltime,
                to: IE::Time,
                dst: Operand::Instance(step.elapsed),
                src: nanos,
            });
            let after = self.here();
            self.patch(skip, after);
        }
        // (3) Actions by qualifier.
        let steps: Vec<StepDecl> = root.steps().collect();
        // An action may also be a BOOL variable (IEC's boolean action): it is TRUE exactly
        // while some association controls it.
        let is_action = |name: &str| {
            inline.contains_key(name)
                || self
                    .pou
                    .actions
                    .iter()
                    .any(|a| a.name.eq_ignore_ascii_case(name))
        };
        let mut boolean: Vec<(String, Operand)> = Vec::new();
        for node in &steps {
            let Some(name) = node.name() else {
                continue;
            };
            let step = sfc
                .step(&name.text())
                .cloned()
                .ok_or("a step without state")?;
            for (action, qualifier) in associations(node) {
                if matches!(qualifier.as_str(), "S" | "R") {
                    let (_, stored) = sfc
                        .stored
                        .iter()
                        .find(|(a, _)| *a == action)
                        .ok_or("a stored action")?;
                    let skip = self.emit(Instr::JumpIfNot {
                        cond: Operand::Instance(step.active),
                        target: 0,
                    });
                    self.set_bool(*stored, qualifier == "S");
                    let after = self.here();
                    self.patch(skip, after);
                    continue;
                }
                let control = self.control(&qualifier, &step)?;
                if is_action(&action) {
                    let skip = self.emit(Instr::JumpIfNot {
                        cond: control,
                        target: 0,
                    });
                    self.run_action(&action, &inline)?;
                    let after = self.here();
                    self.patch(skip, after);
                } else {
                    self.or_into(&mut boolean, action, control);
                }
            }
        }
        for (action, stored) in &sfc.stored {
            if is_action(action) {
                let skip = self.emit(Instr::JumpIfNot {
                    cond: Operand::Instance(*stored),
                    target: 0,
                });
                self.run_action(action, &inline)?;
                let after = self.here();
                self.patch(skip, after);
            } else {
                self.or_into(&mut boolean, action.clone(), Operand::Instance(*stored));
            }
        }
        for (name, control) in boolean {
            let variable = self.variable_named(&name)?;
            self.store(&variable, control)?;
        }
        for step in &sfc.steps {
            self.set_bool(step.fresh, false);
        }
        // (4) Transitions: all evaluated first, then fired.
        let mut fired = Vec::new();
        for transition in root.transitions() {
            let (Some(from), Some(to)) = (transition.from_steps(), transition.to_steps()) else {
                return Err("a transition needs FROM and TO steps".into());
            };
            let condition = transition
                .condition()
                .ok_or("a transition needs a condition (':= condition;')")?;
            let enabled = self.temp(1);
            let value = self.expr_as(&condition, &Type::BOOL)?;
            self.emit(Instr::Move {
                ty: IE::Bool,
                dst: enabled,
                src: value,
            });
            for name in step_names(&from) {
                let step = sfc.step(&name).ok_or_else(|| fail!("no step '{name}'"))?;
                self.emit(Instr::Binary {
                    op: BinaryOp::And,
                    ty: IE::Bool,
                    dst: enabled,
                    a: enabled,
                    b: Operand::Instance(step.active),
                });
            }
            fired.push((enabled, step_names(&from), step_names(&to)));
        }
        for (enabled, from, to) in fired {
            let skip = self.emit(Instr::JumpIfNot {
                cond: enabled,
                target: 0,
            });
            for name in &from {
                let step = sfc
                    .step(name)
                    .ok_or_else(|| fail!("no step '{name}'"))?
                    .clone();
                self.set_bool(step.active, false);
            }
            for name in &to {
                let step = sfc
                    .step(name)
                    .ok_or_else(|| fail!("no step '{name}'"))?
                    .clone();
                self.activate(&step, now);
            }
            let after = self.here();
            self.patch(skip, after);
        }
        Ok(())
    }
}
