//! IEC 61131-3's `ACTION_CONTROL` generated for one action of a textual SFC chart, with only
//! the qualifiers the chart uses with it (see `docs/sfc-semantics.md`).

use std::collections::HashMap;

use program_image::{BinaryOp, CompareOp, Elementary as IE, Instr, Operand};

use super::body::{BodyGen, Gen};
use super::sfc::inst;
use super::sfc_layout::{ActionSlots, action_at};
use crate::sfc_chart::{ActionQualifier, Association};
use crate::syntax::ast::StatementList;

impl BodyGen<'_, '_, '_> {
    /// A timer of the action control: running while `input`, done once the qualifier's
    /// duration has elapsed since it started. Returns `done`.
    pub(super) fn control_timer(
        &mut self,
        action: &ActionSlots,
        qualifier: ActionQualifier,
        input: Operand,
        now: Operand,
    ) -> Operand {
        let done = self.temp(1);
        self.set_place_bool(done, false);
        let stop = self.skip_unless(input);
        let running = self.skip_if(inst(action.running(qualifier)));
        self.set_bool(action.running(qualifier), true);
        self.emit(Instr::Move {
            ty: IE::Lint,
            dst: inst(action.timer_started(qualifier)),
            src: now,
        });
        self.land(running);
        let elapsed = self.temp(4);
        self.elapsed_into(elapsed, now, inst(action.timer_started(qualifier)));
        let reached = self.compare_time(CompareOp::Ge, elapsed, inst(action.time(qualifier)));
        self.move_bool(done, reached);
        let finished = self.emit(Instr::Jump { target: 0 });
        self.land(stop);
        self.set_bool(action.running(qualifier), false);
        self.land(finished);
        done
    }

    /// IEC 61131-3's `ACTION_CONTROL` for one action, generated for the qualifiers the chart
    /// uses with it; then its indicators and boolean variable, and its final call.
    pub(super) fn action_control(
        &mut self,
        associations: &[&Association],
        name: &str,
        action: &ActionSlots,
        now: Operand,
        inline: &HashMap<String, StatementList>,
    ) -> Gen<()> {
        let used = |q: ActionQualifier| associations.iter().any(|a| a.qualifier == q);
        let idle = self.skip_unless(inst(action.busy()));
        let req = |q: ActionQualifier| inst(action.request(q));
        let mem = |q: ActionQualifier| inst(action.memory(q));
        let not_reset = self.not(req(ActionQualifier::R));
        let q = self.temp(1);
        self.move_bool(q, req(ActionQualifier::N));
        // A flip-flop with dominant reset: `memory := (memory OR set) AND NOT R`.
        let latch = |this: &mut Self, qualifier: ActionQualifier, set: Operand| {
            let kept = this.bool_op(BinaryOp::Or, mem(qualifier), set);
            this.bool_op_into(BinaryOp::And, mem(qualifier), kept, not_reset);
        };
        if used(ActionQualifier::S) {
            latch(self, ActionQualifier::S, req(ActionQualifier::S));
            self.bool_op_into(BinaryOp::Or, q, q, mem(ActionQualifier::S));
        }
        if used(ActionQualifier::L) {
            let done = self.control_timer(action, ActionQualifier::L, req(ActionQualifier::L), now);
            let left = self.not(done);
            let on = self.bool_op(BinaryOp::And, req(ActionQualifier::L), left);
            self.bool_op_into(BinaryOp::Or, q, q, on);
        }
        if used(ActionQualifier::D) {
            let done = self.control_timer(action, ActionQualifier::D, req(ActionQualifier::D), now);
            self.bool_op_into(BinaryOp::Or, q, q, done);
        }
        if used(ActionQualifier::P) {
            let before = self.not(mem(ActionQualifier::P));
            let edge = self.bool_op(BinaryOp::And, req(ActionQualifier::P), before);
            self.move_bool(mem(ActionQualifier::P), req(ActionQualifier::P));
            self.bool_op_into(BinaryOp::Or, q, q, edge);
        }
        if used(ActionQualifier::SD) {
            latch(self, ActionQualifier::SD, req(ActionQualifier::SD));
            let done =
                self.control_timer(action, ActionQualifier::SD, mem(ActionQualifier::SD), now);
            self.bool_op_into(BinaryOp::Or, q, q, done);
        }
        if used(ActionQualifier::DS) {
            let done =
                self.control_timer(action, ActionQualifier::DS, req(ActionQualifier::DS), now);
            latch(self, ActionQualifier::DS, done);
            self.bool_op_into(BinaryOp::Or, q, q, mem(ActionQualifier::DS));
        }
        if used(ActionQualifier::SL) {
            latch(self, ActionQualifier::SL, req(ActionQualifier::SL));
            let done =
                self.control_timer(action, ActionQualifier::SL, mem(ActionQualifier::SL), now);
            let left = self.not(done);
            let on = self.bool_op(BinaryOp::And, mem(ActionQualifier::SL), left);
            self.bool_op_into(BinaryOp::Or, q, q, on);
        }
        self.bool_op_into(BinaryOp::And, inst(action.active()), q, not_reset);
        // A: Q, or the falling edge of Q (the final call), or a P1 or P0 edge.
        let q_now = inst(action.active());
        let not_q = self.not(q_now);
        let fell = self.bool_op(BinaryOp::And, inst(action.at + action_at::Q_PREV), not_q);
        let mut runs = self.bool_op(BinaryOp::Or, q_now, fell);
        if used(ActionQualifier::P1) {
            let before = self.not(mem(ActionQualifier::P1));
            let edge = self.bool_op(BinaryOp::And, req(ActionQualifier::P1), before);
            self.move_bool(mem(ActionQualifier::P1), req(ActionQualifier::P1));
            runs = self.bool_op(BinaryOp::Or, runs, edge);
        }
        if used(ActionQualifier::P0) {
            let gone = self.not(req(ActionQualifier::P0));
            let edge = self.bool_op(BinaryOp::And, mem(ActionQualifier::P0), gone);
            self.move_bool(mem(ActionQualifier::P0), req(ActionQualifier::P0));
            runs = self.bool_op(BinaryOp::Or, runs, edge);
        }
        self.move_bool(inst(action.x()), runs);
        self.bool_op_into(
            BinaryOp::And,
            inst(action.at + action_at::FINAL),
            runs,
            not_q,
        );
        self.move_bool(inst(action.at + action_at::Q_PREV), q_now);
        // Indicators and a boolean action's variable follow Q.
        for association in associations {
            if let Some(indicator) = &association.indicator {
                let place = self.place_of(indicator)?;
                self.store(&place, q_now)?;
            }
        }
        if !self.is_action(name, inline) {
            let variable = self.variable_named(&action.name)?;
            self.store(&variable, q_now)?;
        }
        // The inputs are the associations of this cycle only.
        let zero = self.build.constant(&[0; 11]);
        self.emit(Instr::Copy {
            size: 11,
            dst: inst(action.at + action_at::REQUEST),
            src: zero,
        });
        // Busy while anything could still change Q or A without a step asking.
        let mut busy = self.bool_op(BinaryOp::Or, q_now, runs);
        for qualifier in ActionQualifier::ALL {
            if used(qualifier) {
                busy = self.bool_op(BinaryOp::Or, busy, mem(qualifier));
                if qualifier.is_timed() {
                    busy = self.bool_op(BinaryOp::Or, busy, inst(action.running(qualifier)));
                }
            }
        }
        self.move_bool(inst(action.busy()), busy);
        if self.is_action(name, inline) {
            let skip = self.skip_unless(inst(action.at + action_at::FINAL));
            self.run_action(name, inline)?;
            self.land(skip);
        }
        self.land(idle);
        Ok(())
    }
}
