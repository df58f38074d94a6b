//! Counted loops (`docs/native-engine.md` §5.3): a promoted `FOR` loop whose element accesses
//! by its counter are checked once, in the loop's preheader, for every value the counter can
//! take before the loop ends, instead of at every access.
//!
//! The compiler writes a `FOR` loop with a constant step as a test at the loop's start
//! (`Compare` of the counter with the end, `Gt` counting up, `Lt` counting down, then
//! `JumpIf` out of the loop), the body, and the increment (`Binary Add` of the step to the
//! counter) before the backward jump. When the counter is written by the increment alone and
//! the end and the step not at all, the counter in the body lies between its value on entry
//! and the end, as long as the increment cannot wrap; the preheader tests exactly that, and
//! that this range lies inside the bounds of every element access indexed by the counter.
//! When it does not (an index that would fault, a step of the wrong sign, an end so close to
//! the type's limit that the counter could wrap), the loop's unpromoted copy runs, whose
//! accesses are checked one by one and fault where the interpreter faults.
//!
//! The proof must hold whatever memory holds, since the accesses it spares reach memory at a
//! computed address: the promoted copy compares the counter with the end and adds the step the
//! preheader read and checked (not values read again from memory), the counter's variable is
//! only ever set by the preheader and the increment (a host operation in the loop does not
//! reload it: its destination is not the counter, which the analysis checks), and a tick on
//! the backward jump, after which memory may hold anything, goes back to the preheader, which
//! checks again.

use cranelift_codegen::ir::condcodes::IntCC;
use cranelift_codegen::ir::{Block, InstBuilder, Type, Value, types};
use program_image::{BinaryOp, CompareOp, Elementary, Instr, Operand};

use super::promote::{Access, accesses, jump_target, may_overlap};
use super::{Translator, int_type};
use crate::layout::Layout;

/// A promoted `FOR` loop whose element accesses by its counter are checked in its preheader.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct CountedLoop {
    /// The counter: a promoted place, written in the loop only by the increment.
    pub(crate) counter: Operand,
    /// The counter's type: a signed integer, or an unsigned one of at most 32 bits counting
    /// up.
    pub(crate) ty: Elementary,
    /// The end the loop's test compares the counter with; not written in the loop.
    pub(crate) end: Operand,
    /// The step the increment adds; not written in the loop.
    pub(crate) step: Operand,
    /// Whether the loop counts up (it ends once the counter is above the end) or down (below).
    pub(crate) upward: bool,
    /// The `LoadElement` and `StoreElement` instructions indexed by the counter, whose checks
    /// the preheader makes.
    pub(crate) accesses: Vec<u32>,
    /// The greatest low bound of those accesses.
    pub(crate) low: i64,
    /// The least high bound of those accesses, computed as the interpreter computes it.
    pub(crate) high: i64,
}

/// The counted loop `start ..= end` is, given its promoted `places`, if it is one whose
/// element checks may be made in its preheader.
pub(crate) fn counted_loop(
    code: &[Instr],
    layout: &Layout,
    (start, end): (u32, u32),
    places: &[(Operand, u32)],
) -> Option<CountedLoop> {
    let (first, last) = (start as usize, end as usize);
    if last < first + 3 {
        return None;
    }
    let Instr::Compare {
        op,
        ty,
        dst: done,
        a: counter,
        b: end_value,
    } = *code.get(first)?
    else {
        return None;
    };
    let upward = match op {
        CompareOp::Gt => true,
        CompareOp::Lt => false,
        _ => return None,
    };
    // An unsigned counter counting down adds a step that wraps; a 64-bit unsigned one does not
    // keep its order as an `i64`, the type the bounds are compared in.
    if !ty.is_integer() || (!ty.is_signed() && (!upward || ty.size_bytes() == 8)) {
        return None;
    }
    let Instr::JumpIf { cond, target: exit } = *code.get(first + 1)? else {
        return None;
    };
    let Instr::Binary {
        op: BinaryOp::Add,
        ty: step_ty,
        dst,
        a,
        b: step,
    } = *code.get(last - 1)?
    else {
        return None;
    };
    let closes = matches!(code.get(last)?, Instr::Jump { target } if *target == start);
    if cond != done || exit <= end || step_ty != ty || dst != counter || a != counter || !closes {
        return None;
    }
    let size = ty.size_bytes();
    if !places.contains(&(counter, size)) {
        return None;
    }
    for (pc, instr) in code.iter().enumerate().take(last + 1).skip(first) {
        // Every backward jump goes to the start, through the preheader after a tick.
        if jump_target(instr).is_some_and(|target| target as usize <= pc && target != start) {
            return None;
        }
        for (operand, bytes, access) in accesses(instr)? {
            if access == Access::Read {
                continue;
            }
            let place = (operand, bytes);
            if pc != last - 1 && may_overlap(layout, (counter, size), place) {
                return None;
            }
            if [end_value, step]
                .into_iter()
                .any(|kept| may_overlap(layout, (kept, size), place))
            {
                return None;
            }
        }
    }
    let mut checked = Vec::new();
    let (mut low, mut high) = (i64::MIN, i64::MAX);
    for (pc, instr) in code.iter().enumerate().take(last - 1).skip(first + 2) {
        if let Instr::LoadElement {
            index,
            index_ty,
            low: element_low,
            count,
            ..
        }
        | Instr::StoreElement {
            index,
            index_ty,
            low: element_low,
            count,
            ..
        } = *instr
            && index == counter
            && index_ty == ty
        {
            checked.push(pc as u32);
            low = low.max(element_low);
            high = high.min(interpreter_high(element_low, count));
        }
    }
    (!checked.is_empty() && low <= high).then_some(CountedLoop {
        counter,
        ty,
        end: end_value,
        step,
        upward,
        accesses: checked,
        low,
        high,
    })
}

/// The highest index of `count` elements from `low`, saturated as the interpreter computes it.
pub(crate) fn interpreter_high(low: i64, count: u64) -> i64 {
    low.saturating_add(i64::try_from(count.saturating_sub(1)).unwrap_or(i64::MAX))
}

/// The smallest and largest value of an integer type the analysis accepts, as `i64`.
fn type_range(ty: Elementary) -> (i64, i64) {
    let bits = ty.size_bytes() * 8;
    if ty.is_signed() {
        if bits == 64 {
            (i64::MIN, i64::MAX)
        } else {
            (-(1i64 << (bits - 1)), (1i64 << (bits - 1)) - 1)
        }
    } else {
        (0, (1i64 << bits) - 1)
    }
}

/// What the promoted copy of a counted loop uses while it is emitted.
#[derive(Clone, Debug)]
pub(crate) struct Hoisted {
    /// The loop's start, where a tick goes back through `preheader`.
    pub(crate) start: u32,
    /// The loop's preheader.
    pub(crate) preheader: Block,
    /// The counter, which only the preheader and the increment set.
    pub(crate) counter: Operand,
    /// The element accesses whose checks the preheader made.
    pub(crate) accesses: Vec<u32>,
    /// The end and the step as the preheader read and checked them: the loop's test and its
    /// increment use these values, not memory.
    pub(crate) invariants: Vec<(Operand, Type, Value)>,
}

impl Translator<'_, '_> {
    /// In a counted loop's preheader: whether its checks fail for what memory holds now, and
    /// the counter, the end and the step read for them, each of the counter's IR type.
    pub(crate) fn counted_checks_fail(&mut self, counted: &CountedLoop) -> (Value, [Value; 3]) {
        let ir = int_type(counted.ty);
        let signed = counted.ty.is_signed();
        let counter = self.load(ir, counted.counter);
        let end = self.load(ir, counted.end);
        let step = self.load(ir, counted.step);
        let [c, l, k] =
            [counter, end, step].map(|value| self.resized(value, ir, types::I64, signed));
        let (min, max) = type_range(counted.ty);
        let (step_right_way, room, first_inside, last_inside) = if counted.upward {
            // In the body the counter is between its first value and the end, and each step
            // adds k >= 0 to a value at most the end, which cannot pass the type's maximum.
            let step_right_way =
                self.builder
                    .ins()
                    .icmp_imm_s(IntCC::SignedGreaterThanOrEqual, k, 0);
            let max = self.builder.ins().iconst(types::I64, max);
            let limit = self.builder.ins().isub(max, k);
            let room = self
                .builder
                .ins()
                .icmp(IntCC::SignedLessThanOrEqual, l, limit);
            let first_inside =
                self.builder
                    .ins()
                    .icmp_imm_s(IntCC::SignedGreaterThanOrEqual, c, counted.low);
            let last_inside =
                self.builder
                    .ins()
                    .icmp_imm_s(IntCC::SignedLessThanOrEqual, l, counted.high);
            (step_right_way, room, first_inside, last_inside)
        } else {
            let step_right_way = self
                .builder
                .ins()
                .icmp_imm_s(IntCC::SignedLessThanOrEqual, k, 0);
            let min = self.builder.ins().iconst(types::I64, min);
            let limit = self.builder.ins().isub(min, k);
            let room = self
                .builder
                .ins()
                .icmp(IntCC::SignedGreaterThanOrEqual, l, limit);
            let first_inside =
                self.builder
                    .ins()
                    .icmp_imm_s(IntCC::SignedLessThanOrEqual, c, counted.high);
            let last_inside =
                self.builder
                    .ins()
                    .icmp_imm_s(IntCC::SignedGreaterThanOrEqual, l, counted.low);
            (step_right_way, room, first_inside, last_inside)
        };
        let both_ends = self.builder.ins().band(first_inside, last_inside);
        let steps = self.builder.ins().band(step_right_way, room);
        let hold = self.builder.ins().band(both_ends, steps);
        let fail = self.builder.ins().icmp_imm_u(IntCC::Equal, hold, 0);
        (fail, [counter, end, step])
    }

    /// Whether the current instruction's element check was made in the preheader of the
    /// counted loop being emitted.
    pub(crate) fn check_made_in_preheader(&self) -> bool {
        self.hoisted
            .as_ref()
            .is_some_and(|hoisted| hoisted.accesses.contains(&self.pc))
    }

    /// The value the preheader of the counted loop being emitted read for `operand` as `ty`,
    /// if it read one.
    pub(crate) fn invariant(&self, ty: Type, operand: Operand) -> Option<Value> {
        let hoisted = self.hoisted.as_ref()?;
        hoisted
            .invariants
            .iter()
            .find(|(place, place_ty, _)| *place == operand && *place_ty == ty)
            .map(|(_, _, value)| *value)
    }

    /// The counter of the counted loop being emitted, which a reload after a callback leaves
    /// alone.
    pub(crate) fn hoisted_counter(&self) -> Option<Operand> {
        self.hoisted.as_ref().map(|hoisted| hoisted.counter)
    }

    /// Where a backward jump to `target` goes after its tick: the preheader of the counted
    /// loop being emitted when the jump closes it, to check again; else `None`.
    pub(crate) fn recheck_after_tick(&self, target: u32) -> Option<Block> {
        let hoisted = self.hoisted.as_ref()?;
        (hoisted.start == target).then_some(hoisted.preheader)
    }
}
