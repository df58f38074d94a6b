//! Textual SFC (IEC 61131-3 §6.7 with CODESYS's extensions): the code of a chart, following
//! CODESYS's processing order per cycle (see `docs/sfc-semantics.md`).
//!
//! Each step keeps `x` (active this cycle), `_x` (active next cycle), `t` and its activation
//! time in the instance; each associated action keeps the state of its `ACTION_CONTROL`. The
//! `x` and `_x` flags of all steps, and the `busy` and `Q` flags of all actions, lie in arrays
//! of bytes, so one LWORD covers the flags of eight steps or actions: every pass over the steps
//! or actions first tests eight at a time and skips a group none of which has work, and the
//! work of a step or action inside a busy group is guarded by its own flags. A chart of 1,000
//! steps with one active runs about one instruction per step and cycle.

use std::collections::HashMap;

use program_image::{BinaryOp, CompareOp, Elementary as IE, Instr, Operand};

use super::body::{BodyGen, Gen, Typed};
use super::error::fail;
pub(crate) use super::sfc_layout::SfcLayout;
use super::sfc_layout::{GROUP, StepSlots, action_at, step_at};
use crate::sema::ty::Type;
use crate::sfc_chart::{Association, Chart, ChartStep};
use crate::syntax::SyntaxNode;
use crate::syntax::ast::{AstNode, Expr, SourceFile, StatementList, Stmt};

/// The statements at the top of a body: a chart's steps, transitions and actions are among
/// them.
pub(crate) fn top_level(root: &SyntaxNode) -> Option<StatementList> {
    SourceFile::cast(root.clone()).and_then(|file| file.statement_list())
}

pub(super) fn inst(offset: u32) -> Operand {
    Operand::Instance(offset)
}

/// The SFC flags the POU declares, as places.
#[derive(Default)]
pub(super) struct Flags {
    init: Option<Typed>,
    reset: Option<Typed>,
    pause: Option<Typed>,
    error: Option<Typed>,
    enable_limit: Option<Typed>,
    error_step: Option<Typed>,
    error_pou: Option<Typed>,
    quit_error: Option<Typed>,
    trans: Option<Typed>,
    current_step: Option<Typed>,
    tip: Option<Typed>,
    tip_mode: Option<Typed>,
}

impl BodyGen<'_, '_, '_> {
    pub(super) fn sfc(&self) -> Gen<SfcLayout> {
        self.instance
            .as_ref()
            .and_then(|i| i.sfc.clone())
            .ok_or_else(|| "SFC steps are only allowed in a program or function block".into())
    }

    pub(super) fn set_bool(&mut self, offset: u32, value: bool) {
        self.set_place_bool(inst(offset), value);
    }

    pub(super) fn set_place_bool(&mut self, dst: Operand, value: bool) {
        let src = self.build.constant(&[u8::from(value)]);
        self.emit(Instr::Move {
            ty: IE::Bool,
            dst,
            src,
        });
    }

    pub(super) fn bool_op(&mut self, op: BinaryOp, a: Operand, b: Operand) -> Operand {
        let dst = self.temp(1);
        self.bool_op_into(op, dst, a, b);
        dst
    }

    /// `dst := a op b` on BOOLs, into a place of the chart's state (`dst` may be `a`).
    pub(super) fn bool_op_into(&mut self, op: BinaryOp, dst: Operand, a: Operand, b: Operand) {
        self.emit(Instr::Binary {
            op,
            ty: IE::Bool,
            dst,
            a,
            b,
        });
    }

    pub(super) fn not(&mut self, src: Operand) -> Operand {
        let dst = self.temp(1);
        self.emit(Instr::Unary {
            op: program_image::UnaryOp::Not,
            ty: IE::Bool,
            dst,
            src,
        });
        dst
    }

    pub(super) fn move_bool(&mut self, dst: Operand, src: Operand) {
        self.emit(Instr::Move {
            ty: IE::Bool,
            dst,
            src,
        });
    }

    /// Emits a jump taken when `cond` is FALSE, to be patched with `land`.
    pub(super) fn skip_unless(&mut self, cond: Operand) -> usize {
        self.emit(Instr::JumpIfNot { cond, target: 0 })
    }

    pub(super) fn skip_if(&mut self, cond: Operand) -> usize {
        self.emit(Instr::JumpIf { cond, target: 0 })
    }

    pub(super) fn land(&mut self, jump: usize) {
        let here = self.here();
        self.patch(jump, here);
    }

    /// A flag the POU declares (any case), as a place.
    pub(super) fn flag(&mut self, name: &str) -> Gen<Option<Typed>> {
        let Some(variable) = self
            .pou
            .variables
            .iter()
            .find(|v| v.name.eq_ignore_ascii_case(name))
        else {
            return Ok(None);
        };
        let name = variable.name.clone();
        self.variable_place_named(&name).map(Some)
    }

    pub(super) fn flags(&mut self) -> Gen<Flags> {
        Ok(Flags {
            init: self.flag("SFCInit")?,
            reset: self.flag("SFCReset")?,
            pause: self.flag("SFCPause")?,
            error: self.flag("SFCError")?,
            enable_limit: self.flag("SFCEnableLimit")?,
            error_step: self.flag("SFCErrorStep")?,
            error_pou: self.flag("SFCErrorPOU")?,
            quit_error: self.flag("SFCQuitError")?,
            trans: self.flag("SFCTrans")?,
            current_step: self.flag("SFCCurrentStep")?,
            tip: self.flag("SFCTip")?,
            tip_mode: self.flag("SFCTipMode")?,
        })
    }

    pub(super) fn read_flag(&mut self, flag: &Typed) -> Gen<Operand> {
        self.load(flag)
    }

    pub(super) fn write_flag(&mut self, flag: &Typed, value: bool) -> Gen<()> {
        let src = self.build.constant(&[u8::from(value)]);
        self.store(flag, src)
    }

    /// Writes the text `value` into a STRING flag.
    pub(super) fn write_text(&mut self, flag: &Typed, value: &str) -> Gen<()> {
        let Type::String { wide, length } = flag.ty else {
            return Err(fail!(
                "an SFC flag that should be a STRING is a {}",
                flag.ty
            ));
        };
        let chars: Vec<u16> = value.encode_utf16().collect();
        let bytes = super::constant::text_bytes(&chars, wide, length);
        let src = self.build.constant(&bytes);
        self.store(flag, src)
    }

    /// Runs the action `name`: one declared in the chart (its statements, inline) or an action
    /// of the POU.
    pub(super) fn run_action(
        &mut self,
        name: &str,
        inline: &HashMap<String, StatementList>,
    ) -> Gen<()> {
        if let Some(statements) = inline.get(&name.to_ascii_lowercase()) {
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
                    "the chart names '{name}', which is no action of '{}'",
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

    /// `elapsed := now - started` as a TIME into `dst`.
    pub(super) fn elapsed_into(&mut self, dst: Operand, now: Operand, started: Operand) {
        let nanos = self.temp(8);
        self.emit(Instr::Binary {
            op: BinaryOp::Sub,
            ty: IE::Lint,
            dst: nanos,
            a: now,
            b: started,
        });
        self.emit(Instr::Convert {
            from: IE::Ltime,
            to: IE::Time,
            dst,
            src: nanos,
        });
    }

    /// A TIME comparison `a op b`.
    pub(super) fn compare_time(&mut self, op: CompareOp, a: Operand, b: Operand) -> Operand {
        let dst = self.temp(1);
        self.emit(Instr::Compare {
            op,
            ty: IE::Time,
            dst,
            a,
            b,
        });
        dst
    }

    /// Generates a body holding a chart: its plain statements, then one cycle of the chart.
    pub(crate) fn chart(&mut self, root: &SyntaxNode) -> Gen<()> {
        let Some(root) = &top_level(root) else {
            return Ok(());
        };
        let Some(chart) = Chart::of(root) else {
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
        let flags = self.flags()?;
        let now = self.temp(8);
        self.emit(Instr::Now { dst: now });
        let mut to_end = Vec::new();
        self.initialisation(&sfc, &flags, now, &mut to_end)?;
        self.pause_and_quit(&sfc, &flags, now, &mut to_end)?;
        if let Some(trans) = &flags.trans {
            self.write_flag(trans, false)?;
        }
        let has_entry_or_exit = chart
            .steps
            .iter()
            .any(|s| s.property("ENTRY").is_some() || s.property("EXIT").is_some());
        // (2, 3, 4) Steps: activation and deactivation, times, timeouts, associations.
        let steps: Vec<(&ChartStep, &StepSlots)> = chart.steps.iter().zip(&sfc.steps).collect();
        for (group, members) in steps.chunks(GROUP).enumerate() {
            let idle = self.group_guard(&[sfc.step_x.0, sfc.step_next.0], group);
            for (step, slots) in members {
                self.step_pass(step, slots, &sfc, &flags, now, !has_entry_or_exit, &inline)?;
            }
            self.land(idle);
        }
        if has_entry_or_exit {
            // Exit actions of the steps left, entry actions of the steps entered, then the
            // step actions of the active steps; the one-shot flags of the first two are
            // cleared as their actions run.
            type StepFlag = fn(&StepSlots) -> u32;
            let passes: [(&str, StepFlag, bool); 3] = [
                ("EXIT", StepSlots::leaving, true),
                ("ENTRY", StepSlots::entering, true),
                ("MAIN", StepSlots::x, false),
            ];
            for (property, flag, one_shot) in passes {
                for (step, slots) in chart.steps.iter().zip(&sfc.steps) {
                    if let Some(action) = step.action_property(property) {
                        let skip = self.skip_unless(inst(flag(slots)));
                        if one_shot {
                            self.set_bool(flag(slots), false);
                        }
                        self.run_action(&action, &inline)?;
                        self.land(skip);
                    }
                }
            }
        }
        // (5) IEC actions in alphabetical order: their control, then the final calls, then
        // the active ones.
        let mut by_action: HashMap<String, Vec<&Association>> = HashMap::new();
        for association in chart.steps.iter().flat_map(|s| &s.associations) {
            by_action
                .entry(association.action.to_ascii_lowercase())
                .or_default()
                .push(association);
        }
        for (group, members) in sfc.actions.chunks(GROUP).enumerate() {
            let idle = self.group_guard(&[sfc.action_busy.0], group);
            for (name, slots) in members {
                let associations = by_action.get(name).map_or(&[][..], Vec::as_slice);
                self.action_control(associations, name, slots, now, &inline)?;
            }
            self.land(idle);
        }
        for (group, members) in sfc.actions.chunks(GROUP).enumerate() {
            if !members
                .iter()
                .any(|(name, _)| self.is_action(name, &inline))
            {
                continue;
            }
            let idle = self.group_guard(&[sfc.action_q.0], group);
            for (name, slots) in members {
                if self.is_action(name, &inline) {
                    let skip = self.skip_unless(inst(slots.active()));
                    self.run_action(name, &inline)?;
                    self.land(skip);
                }
            }
            self.land(idle);
        }
        // (6) Transitions.
        self.transitions(&chart, &sfc, &flags)?;
        let end = self.here();
        for jump in to_end {
            self.patch(jump, end);
        }
        self.emit(Instr::Move {
            ty: IE::Lint,
            dst: inst(sfc.previous_now),
            src: now,
        });
        Ok(())
    }

    /// A jump over a group's code taken when none of the `GROUP` flags of group `group` in
    /// any of the byte arrays starting at `arrays` is TRUE: one LWORD per array.
    pub(super) fn group_guard(&mut self, arrays: &[u32], group: usize) -> usize {
        let offset = (group * GROUP) as u32;
        let mut any = inst(arrays[0] + offset);
        for array in &arrays[1..] {
            let both = self.temp(8);
            self.emit(Instr::Binary {
                op: BinaryOp::Or,
                ty: IE::Lword,
                dst: both,
                a: any,
                b: inst(array + offset),
            });
            any = both;
        }
        let zero = self.build.constant(&[0; 8]);
        let busy = self.temp(1);
        self.emit(Instr::Compare {
            op: CompareOp::Ne,
            ty: IE::Lword,
            dst: busy,
            a: any,
            b: zero,
        });
        self.skip_unless(busy)
    }

    pub(super) fn is_action(&self, name: &str, inline: &HashMap<String, StatementList>) -> bool {
        inline.contains_key(&name.to_ascii_lowercase())
            || self
                .pou
                .actions
                .iter()
                .any(|a| a.name.eq_ignore_ascii_case(name))
    }

    /// The first cycle, `SFCInit` and `SFCReset`: every step off but the initial one, every
    /// action idle.
    pub(super) fn initialisation(
        &mut self,
        sfc: &SfcLayout,
        flags: &Flags,
        now: Operand,
        to_end: &mut Vec<usize>,
    ) -> Gen<()> {
        let mut cond = self.not(inst(sfc.initialised));
        for flag in [&flags.init, &flags.reset].into_iter().flatten() {
            let value = self.read_flag(flag)?;
            cond = self.bool_op(BinaryOp::Or, cond, value);
        }
        let skip = self.skip_unless(cond);
        // The flag arrays lie together, from the steps' `x` to the actions' `Q`.
        let flags_size = 2 * sfc.step_x.1 + 2 * sfc.action_busy.1;
        let zero_flags = self.build.constant(&vec![0; flags_size as usize]);
        self.emit(Instr::Copy {
            size: flags_size,
            dst: inst(sfc.step_x.0),
            src: zero_flags,
        });
        let zero_step = self.build.constant(&[0; step_at::SIZE as usize]);
        for step in &sfc.steps {
            self.emit(Instr::Copy {
                size: step_at::SIZE,
                dst: inst(step.at),
                src: zero_step,
            });
            self.emit(Instr::Move {
                ty: IE::Lint,
                dst: inst(step.started()),
                src: now,
            });
            if step.initial {
                self.set_bool(step.next(), true);
            }
        }
        let zero_action = self.build.constant(&[0; action_at::SIZE as usize]);
        for (_, action) in &sfc.actions {
            self.emit(Instr::Copy {
                size: action_at::SIZE,
                dst: inst(action.at),
                src: zero_action,
            });
        }
        for flag in [&flags.error, &flags.trans].into_iter().flatten() {
            self.write_flag(flag, false)?;
        }
        for flag in [&flags.error_step, &flags.error_pou, &flags.current_step]
            .into_iter()
            .flatten()
        {
            self.write_text(flag, "")?;
        }
        self.set_bool(sfc.initialised, true);
        self.emit(Instr::Move {
            ty: IE::Lint,
            dst: inst(sfc.previous_now),
            src: now,
        });
        if let Some(init) = &flags.init {
            // While SFCInit is TRUE the initial step is set but nothing runs.
            let value = self.read_flag(init)?;
            let first = sfc.steps.iter().find(|s| s.initial);
            let keep = self.skip_unless(value);
            if let Some(first) = first {
                // Shown active; its entry action runs when processing resumes.
                self.set_bool(first.x(), true);
                self.set_bool(first.entering(), true);
            }
            to_end.push(self.emit(Instr::Jump { target: 0 }));
            self.land(keep);
        }
        self.land(skip);
        Ok(())
    }

    /// `SFCPause` and `SFCQuitError` hold the chart; the falling edge of `SFCQuitError`
    /// restarts the times of the active steps.
    pub(super) fn pause_and_quit(
        &mut self,
        sfc: &SfcLayout,
        flags: &Flags,
        now: Operand,
        to_end: &mut Vec<usize>,
    ) -> Gen<()> {
        if let Some(pause) = &flags.pause {
            let value = self.read_flag(pause)?;
            to_end.push(self.skip_if(value));
        }
        let Some(quit) = &flags.quit_error else {
            return Ok(());
        };
        let value = self.read_flag(quit)?;
        let released = self.skip_unless(value);
        if let Some(error) = &flags.error {
            self.write_flag(error, false)?;
        }
        for flag in [&flags.error_step, &flags.error_pou].into_iter().flatten() {
            self.write_text(flag, "")?;
        }
        self.set_bool(sfc.quit_before, true);
        to_end.push(self.emit(Instr::Jump { target: 0 }));
        self.land(released);
        let steady = self.skip_unless(inst(sfc.quit_before));
        self.set_bool(sfc.quit_before, false);
        for step in &sfc.steps {
            let skip = self.skip_unless(inst(step.x()));
            self.emit(Instr::Move {
                ty: IE::Lint,
                dst: inst(step.started()),
                src: now,
            });
            self.land(skip);
        }
        self.land(steady);
        Ok(())
    }

    /// One step's share of the cycle: it takes `_x` into `x` (activation and deactivation),
    /// brings `t` up to date, checks its maximum time, names itself the current step, hands
    /// its associations to their actions, and runs its MAIN action when `with_main`.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn step_pass(
        &mut self,
        step: &ChartStep,
        slots: &StepSlots,
        sfc: &SfcLayout,
        flags: &Flags,
        now: Operand,
        with_main: bool,
        inline: &HashMap<String, StatementList>,
    ) -> Gen<()> {
        let off = self.skip_unless(inst(slots.next()));
        // The step's line starts a statement where its active pass begins, so a breakpoint on
        // the step halts while it is active (as CODESYS does) and flow control marks it then.
        self.mark_statement_start_at(step.name_range.start);
        let steady = self.skip_if(inst(slots.x()));
        self.set_bool(slots.x(), true);
        self.emit(Instr::Move {
            ty: IE::Lint,
            dst: inst(slots.started()),
            src: inst(sfc.previous_now),
        });
        if step.property("ENTRY").is_some() {
            self.set_bool(slots.entering(), true);
        }
        self.land(steady);
        self.elapsed_into(inst(slots.t()), now, inst(slots.started()));
        if let (Some(max), Some(error)) = (step.property("MAX_TIME"), &flags.error) {
            let max = self.expr_as(max, &Type::Elementary(crate::elementary::Elementary::Time))?;
            let over = self.compare_time(CompareOp::Gt, inst(slots.t()), max);
            let reported = self.read_flag(error)?;
            let fresh = self.not(reported);
            let mut report = self.bool_op(BinaryOp::And, over, fresh);
            if let Some(limit) = &flags.enable_limit {
                let enabled = self.read_flag(limit)?;
                report = self.bool_op(BinaryOp::And, report, enabled);
            }
            let skip = self.skip_unless(report);
            self.write_flag(error, true)?;
            if let Some(error_step) = &flags.error_step {
                self.write_text(error_step, &step.name)?;
            }
            if let Some(error_pou) = &flags.error_pou {
                let pou = self.pou.name.clone();
                self.write_text(error_pou, &pou)?;
            }
            self.land(skip);
        }
        if let Some(current) = &flags.current_step {
            self.write_text(current, &step.name)?;
        }
        for association in &step.associations {
            let action = sfc
                .action(&association.action)
                .ok_or_else(|| fail!("no state for the action '{}'", association.action))?
                .clone();
            let qualifier = association.qualifier;
            self.set_bool(action.request(qualifier), true);
            self.set_bool(action.busy(), true);
            if let Some(time) = &association.time {
                let value =
                    self.expr_as(time, &Type::Elementary(crate::elementary::Elementary::Time))?;
                self.emit(Instr::Move {
                    ty: IE::Time,
                    dst: inst(action.time(qualifier)),
                    src: value,
                });
            }
        }
        if with_main && let Some(main) = step.action_property("MAIN") {
            self.run_action(&main, inline)?;
        }
        let done = self.emit(Instr::Jump { target: 0 });
        self.land(off);
        let idle = self.skip_unless(inst(slots.x()));
        self.set_bool(slots.x(), false);
        if step.property("EXIT").is_some() {
            self.set_bool(slots.leaving(), true);
        }
        self.land(idle);
        self.land(done);
        Ok(())
    }

    /// The transitions in test order: each fires when its source steps are active and not yet
    /// left this cycle, their minimum times have elapsed and its condition is TRUE (or, in tip
    /// mode, on the rising edge of `SFCTip`).
    pub(super) fn transitions(&mut self, chart: &Chart, sfc: &SfcLayout, flags: &Flags) -> Gen<()> {
        let tip_edge = match (&flags.tip_mode, &flags.tip) {
            (Some(mode), Some(tip)) => {
                let mode = self.read_flag(mode)?;
                let tip = self.read_flag(tip)?;
                let before = self.not(inst(sfc.tip_before));
                let edge = self.bool_op(BinaryOp::And, tip, before);
                self.move_bool(inst(sfc.tip_before), tip);
                let edge_keep = self.temp(1);
                self.move_bool(edge_keep, edge);
                Some((mode, edge_keep))
            }
            _ => None,
        };
        // Consecutive transitions (in test order) whose first source steps share a group are
        // skipped together when none of that group's steps is active.
        let mut open: Option<(usize, usize)> = None;
        for transition in chart.transitions_in_test_order() {
            // Each transition's test is a statement start of its line, where breakpoints,
            // steps and flow control work.
            self.mark_statement_start(transition.node.syntax());
            let anchor = transition
                .from
                .first()
                .and_then(|(name, _)| chart.step(name))
                .map(|(index, _)| index / GROUP);
            if open.map(|(group, _)| Some(group)) != Some(anchor) {
                if let Some((_, jump)) = open.take() {
                    self.land(jump);
                }
                if let Some(group) = anchor {
                    open = Some((group, self.group_guard(&[sfc.step_x.0], group)));
                }
            }
            let mut skips = Vec::new();
            for (name, _) in &transition.from {
                let step = sfc.step(name).ok_or_else(|| fail!("no step '{name}'"))?;
                skips.push(self.skip_unless(inst(step.x())));
                skips.push(self.skip_unless(inst(step.next())));
            }
            for (name, _) in &transition.from {
                let (_, step) = chart.step(name).ok_or_else(|| fail!("no step '{name}'"))?;
                if let Some(min) = step.property("MIN_TIME") {
                    let slots = sfc.step(name).ok_or_else(|| fail!("no step '{name}'"))?;
                    let t = inst(slots.t());
                    let min =
                        self.expr_as(min, &Type::Elementary(crate::elementary::Elementary::Time))?;
                    let reached = self.compare_time(CompareOp::Ge, t, min);
                    skips.push(self.skip_unless(reached));
                }
            }
            let by_hand = match tip_edge {
                Some((mode, edge)) => {
                    let automatic = self.skip_unless(mode);
                    skips.push(self.skip_unless(edge));
                    Some((self.emit(Instr::Jump { target: 0 }), automatic))
                }
                None => None,
            };
            if let Some((_, automatic)) = by_hand {
                self.land(automatic);
            }
            let condition = self.condition(&transition.node, sfc)?;
            skips.push(self.skip_unless(condition));
            if let Some((fire, _)) = by_hand {
                self.land(fire);
            }
            for (name, _) in &transition.from {
                let step = sfc.step(name).ok_or_else(|| fail!("no step '{name}'"))?;
                self.set_bool(step.next(), false);
            }
            for (name, _) in &transition.to {
                let step = sfc.step(name).ok_or_else(|| fail!("no step '{name}'"))?;
                self.set_bool(step.next(), true);
            }
            if let Some(trans) = &flags.trans {
                self.write_flag(trans, true)?;
            }
            for skip in skips {
                self.land(skip);
            }
        }
        if let Some((_, jump)) = open {
            self.land(jump);
        }
        Ok(())
    }

    /// The value of a transition's condition: its expression, or the value its statements
    /// assign to the transition's name (FALSE when they assign nothing).
    pub(super) fn condition(
        &mut self,
        transition: &crate::syntax::ast::TransitionDecl,
        sfc: &SfcLayout,
    ) -> Gen<Operand> {
        if let Some(condition) = transition.condition() {
            let value = self.expr_as(&condition, &Type::BOOL)?;
            let kept = self.temp(1);
            self.move_bool(kept, value);
            return Ok(kept);
        }
        let name = transition
            .name()
            .ok_or("a transition needs ':= condition;' or a name its statements assign")?
            .text();
        let value = sfc
            .transition_value(&name)
            .ok_or_else(|| fail!("no value for the transition '{name}'"))?;
        self.set_bool(value, false);
        for statement in transition.statements() {
            self.statement_with_line(&statement)?;
        }
        Ok(inst(value))
    }

    /// The place an expression names (an indicator variable).
    pub(super) fn place_of(&mut self, node: &Expr) -> Gen<Typed> {
        self.place(node)
    }
}
