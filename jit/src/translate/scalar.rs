//! Elementary values in IR: widths, copies, integer arithmetic and comparisons
//! (`docs/native-engine.md` §5.1).

use cranelift_codegen::ir::condcodes::{FloatCC, IntCC};
use cranelift_codegen::ir::immediates::{Ieee32, Ieee64};
use cranelift_codegen::ir::{InstBuilder, Type, Value, types};
use program_image::{BinaryOp, CompareOp, Elementary, Instr, Operand, ProgramImage, UnaryOp};

use super::host_calls::Import;
use super::{Translator, int_type, is_signed};
use crate::fault_kind;

/// The largest copy done with inline loads and stores; larger ones go to `rivet_jit_copy`.
const INLINE_COPY_BYTES: u32 = 64;

/// Whether nothing in `image` can write its constant pool, so that `Const` operands may be
/// folded into the code (§5.2). Two ways could write it: a `Const` destination (a call's
/// output transfer and the instance of a direct `CallBlock` or `CallStdBlock` count as
/// destinations), and a write through a pointer. ST allows pointer arithmetic, so a pointer
/// can be moved from any region into the pool's (tag 6); the pool is therefore writable as
/// soon as the image writes through any pointer at all: a `Store`, a block or method called on
/// an instance pointer (`CallBlock` or `CallStdBlock` with `indirect`, `CallFunction` with an
/// `instance`, `CallVirtual`), or a native block, which writes its `VAR_IN_OUT`s through theirs.
pub(crate) fn constant_pool_is_read_only(image: &ProgramImage) -> bool {
    let writable = |operand: &Operand| matches!(operand, Operand::Const(_));
    image
        .pous
        .iter()
        .flat_map(|pou| &pou.code)
        .all(|instr| match instr {
            Instr::Move { dst, .. }
            | Instr::Copy { dst, .. }
            | Instr::Unary { dst, .. }
            | Instr::Binary { dst, .. }
            | Instr::Compare { dst, .. }
            | Instr::Convert { dst, .. }
            | Instr::Trunc { dst, .. }
            | Instr::GetBit { dst, .. }
            | Instr::SetBit { dst, .. }
            | Instr::Element { dst, .. }
            | Instr::Offset { dst, .. }
            | Instr::Load { dst, .. }
            | Instr::OpenElement { dst, .. }
            | Instr::Now { dst }
            | Instr::Clock { dst, .. }
            | Instr::LoadElement { dst, .. }
            | Instr::ToText { dst, .. }
            | Instr::FromText { dst, .. }
            | Instr::Address { dst, .. } => !writable(dst),
            Instr::CallStdFunction { dst, .. } => !writable(&dst.0),
            Instr::CallFunction {
                outputs, instance, ..
            } => instance.is_none() && outputs.iter().all(|transfer| !writable(&transfer.caller)),
            // A block runs on its instance, which it writes.
            Instr::CallBlock {
                instance, indirect, ..
            }
            | Instr::CallStdBlock {
                instance, indirect, ..
            } => !indirect && !writable(instance),
            // A fused element store writes inside its array's extent, which verification keeps
            // in the array operand's region: a store into the pool only if the array is there.
            Instr::StoreElement { array, .. } => !writable(array),
            Instr::Store { .. } | Instr::CallVirtual { .. } | Instr::Native { .. } => false,
            Instr::Jump { .. } | Instr::JumpIf { .. } | Instr::JumpIfNot { .. } | Instr::Return => {
                true
            }
        })
}

impl Translator<'_, '_> {
    /// The value of type `ty` at `offset` of the constant pool as an immediate, when the pool
    /// may be folded; floats keep their stored bits.
    pub(crate) fn folded_constant(&mut self, ty: Type, offset: u32) -> Option<Value> {
        let bits = self.folded_bits(ty, offset)?;
        Some(match ty {
            types::F32 => self.builder.ins().f32const(Ieee32::with_bits(bits as u32)),
            types::F64 => self.builder.ins().f64const(Ieee64::with_bits(bits)),
            _ => self.builder.ins().iconst(ty, bits as i64),
        })
    }

    /// The bits of the `ty` value at `offset` of the constant pool, when the pool may be
    /// folded.
    pub(crate) fn folded_bits(&self, ty: Type, offset: u32) -> Option<u64> {
        let pool = self.folded_constants?;
        let size = ty.bytes() as usize;
        let bytes = pool.get(offset as usize..)?.get(..size)?;
        let mut raw = [0u8; 8];
        raw[..size].copy_from_slice(bytes);
        Some(u64::from_le_bytes(raw))
    }

    /// `value` of integer type `from` as integer type `to`: narrowed to its low bits, or
    /// widened by `signed`.
    pub(crate) fn resized(&mut self, value: Value, from: Type, to: Type, signed: bool) -> Value {
        if from == to {
            value
        } else if from.bits() > to.bits() {
            self.builder.ins().ireduce(to, value)
        } else if signed {
            self.builder.ins().sextend(to, value)
        } else {
            self.builder.ins().uextend(to, value)
        }
    }

    /// Copies `size` bytes between absolute offsets: inline when small, every chunk loaded
    /// before any is stored (so overlapping places copy as `memmove` does); else through the
    /// host, whose refusal is the interpreter's `Memory` fault at this instruction.
    pub(crate) fn copy_bytes(&mut self, to: Value, from: Value, size: u32) {
        if size > INLINE_COPY_BYTES {
            let bytes = self.builder.ins().iconst(types::I64, i64::from(size));
            let status = self.call_host(Import::Copy, &[self.context, to, from, bytes]);
            self.fault_if(status, fault_kind::MEMORY, [None; 3]);
            self.reload_promoted();
            return;
        }
        let mut chunks = Vec::new();
        let mut done = 0u32;
        while done < size {
            let (ty, bytes) = match size - done {
                8.. => (types::I64, 8),
                4.. => (types::I32, 4),
                2.. => (types::I16, 2),
                _ => (types::I8, 1),
            };
            chunks.push((ty, done));
            done += bytes;
        }
        let source = self.machine_address(from);
        let values: Vec<Value> = chunks
            .iter()
            .map(|(ty, at)| {
                self.builder
                    .ins()
                    .load(*ty, super::memory_flags(), source, *at as i32)
            })
            .collect();
        let target = self.machine_address(to);
        for ((_, at), value) in chunks.iter().zip(values) {
            self.builder
                .ins()
                .store(super::memory_flags(), value, target, *at as i32);
        }
    }

    /// `Unary`; false to leave it to the host.
    pub(crate) fn unary(
        &mut self,
        op: UnaryOp,
        ty: Elementary,
        dst: Operand,
        src: Operand,
    ) -> bool {
        if ty.is_real() {
            return self.real_unary(op, ty, dst, src);
        }
        let ir = int_type(ty);
        let value = self.load(ir, src);
        let result = match op {
            UnaryOp::Not if ty == Elementary::Bool => {
                let zero = self.builder.ins().icmp_imm_u(IntCC::Equal, value, 0);
                self.resized(zero, types::I8, ir, false)
            }
            UnaryOp::Not => self.builder.ins().bnot(value),
            UnaryOp::Neg if ty != Elementary::Bool => self.builder.ins().ineg(value),
            UnaryOp::Abs if ty != Elementary::Bool => {
                if is_signed(ty) {
                    let negative = self
                        .builder
                        .ins()
                        .icmp_imm_s(IntCC::SignedLessThan, value, 0);
                    let negated = self.builder.ins().ineg(value);
                    self.builder.ins().select(negative, negated, value)
                } else {
                    value
                }
            }
            UnaryOp::ToBcd | UnaryOp::FromBcd => {
                let raw = self.resized(value, ir, types::I64, false);
                let tag = self.builder.ins().iconst(types::I32, i64::from(ty.tag()));
                let to_bcd = i64::from(op == UnaryOp::ToBcd);
                let to_bcd = self.builder.ins().iconst(types::I32, to_bcd);
                let result = self.call_pure(Import::Bcd, &[raw, tag, to_bcd]);
                self.resized(result, types::I64, ir, false)
            }
            // The rest is refused by the interpreter's lowering, so it cannot reach here in a
            // loaded image; the host gives the interpreter's answer regardless.
            _ => return false,
        };
        self.store(result, dst);
        true
    }

    /// `Binary`; false to leave it to the host.
    pub(crate) fn binary(
        &mut self,
        op: BinaryOp,
        ty: Elementary,
        dst: Operand,
        a: Operand,
        b: Operand,
    ) -> bool {
        if ty.is_real() {
            return self.real_binary(op, ty, dst, a, b);
        }
        let arithmetic = matches!(
            op,
            BinaryOp::Add
                | BinaryOp::Sub
                | BinaryOp::Mul
                | BinaryOp::Div
                | BinaryOp::Mod
                | BinaryOp::Expt
                | BinaryOp::Min
                | BinaryOp::Max
        );
        // The interpreter refuses arithmetic on BOOL and ATAN2 on integers at load.
        if (arithmetic && ty == Elementary::Bool) || op == BinaryOp::Atan2 {
            return false;
        }
        let ir = int_type(ty);
        let signed = is_signed(ty);
        let l = self.load(ir, a);
        let r = self.load(ir, b);
        let ins = self.builder.ins();
        let result = match op {
            BinaryOp::Add => ins.iadd(l, r),
            BinaryOp::Sub => ins.isub(l, r),
            BinaryOp::Mul => ins.imul(l, r),
            BinaryOp::And => ins.band(l, r),
            BinaryOp::Or => ins.bor(l, r),
            BinaryOp::Xor => ins.bxor(l, r),
            BinaryOp::Rol => ins.rotl(l, r),
            BinaryOp::Ror => ins.rotr(l, r),
            BinaryOp::Min | BinaryOp::Max => {
                let cc = match (op == BinaryOp::Min, signed) {
                    (true, true) => IntCC::SignedLessThan,
                    (true, false) => IntCC::UnsignedLessThan,
                    (false, true) => IntCC::SignedGreaterThan,
                    (false, false) => IntCC::UnsignedGreaterThan,
                };
                // `if r < l { r } else { l }` (MIN), `if r > l { r } else { l }` (MAX).
                let take_right = ins.icmp(cc, r, l);
                self.builder.ins().select(take_right, r, l)
            }
            BinaryOp::Shl | BinaryOp::Shr => {
                let count = self.resized(r, ir, types::I64, false);
                let width = i64::from(ir.bits());
                let too_far =
                    self.builder
                        .ins()
                        .icmp_imm_u(IntCC::UnsignedGreaterThanOrEqual, count, width);
                let shifted = if op == BinaryOp::Shl {
                    self.builder.ins().ishl(l, count)
                } else {
                    self.builder.ins().ushr(l, count)
                };
                let zero = self.builder.ins().iconst(ir, 0);
                self.builder.ins().select(too_far, zero, shifted)
            }
            BinaryOp::Div | BinaryOp::Mod => self.divide(op == BinaryOp::Div, signed, ir, l, r),
            BinaryOp::Expt => {
                let raw_l = self.resized(l, ir, types::I64, false);
                let raw_r = self.resized(r, ir, types::I64, false);
                let tag = self.builder.ins().iconst(types::I32, i64::from(ty.tag()));
                let result = self.call_pure(Import::IntExpt, &[raw_l, raw_r, tag]);
                self.resized(result, types::I64, ir, false)
            }
            BinaryOp::Atan2 => return false,
        };
        self.store(result, dst);
        true
    }

    /// Integer `DIV` or `MOD`: a zero divisor faults; a signed −1 divisor gives `ineg a` or 0
    /// without dividing (the interpreter's `wrapping_div`, `wrapping_rem`), so the division
    /// instruction never sees a divisor it could trap on (§7 rule 5).
    fn divide(&mut self, quotient: bool, signed: bool, ir: Type, l: Value, r: Value) -> Value {
        let zero = self.builder.ins().icmp_imm_u(IntCC::Equal, r, 0);
        self.fault_if(zero, fault_kind::DIVISION_BY_ZERO, [None; 3]);
        if !signed {
            return if quotient {
                self.builder.ins().udiv(l, r)
            } else {
                self.builder.ins().urem(l, r)
            };
        }
        let minus_one = self.builder.ins().icmp_imm_s(IntCC::Equal, r, -1);
        let one = self.builder.ins().iconst(ir, 1);
        let safe = self.builder.ins().select(minus_one, one, r);
        let (divided, by_minus_one) = if quotient {
            (self.builder.ins().sdiv(l, safe), self.builder.ins().ineg(l))
        } else {
            (
                self.builder.ins().srem(l, safe),
                self.builder.ins().iconst(ir, 0),
            )
        };
        self.builder.ins().select(minus_one, by_minus_one, divided)
    }

    /// `Compare`: the result 0 or 1 as a byte.
    pub(crate) fn compare(
        &mut self,
        op: CompareOp,
        ty: Elementary,
        dst: Operand,
        a: Operand,
        b: Operand,
    ) -> bool {
        let result = if ty.is_real() {
            let ir = if ty == Elementary::Real {
                types::F32
            } else {
                types::F64
            };
            let l = self.load(ir, a);
            let r = self.load(ir, b);
            let cc = match op {
                CompareOp::Eq => FloatCC::Equal,
                // True when unordered, as Rust's `!=`.
                CompareOp::Ne => FloatCC::NotEqual,
                CompareOp::Lt => FloatCC::LessThan,
                CompareOp::Le => FloatCC::LessThanOrEqual,
                CompareOp::Gt => FloatCC::GreaterThan,
                CompareOp::Ge => FloatCC::GreaterThanOrEqual,
            };
            self.builder.ins().fcmp(cc, l, r)
        } else {
            let ir = int_type(ty);
            let signed = is_signed(ty);
            let l = self.load(ir, a);
            let r = self.load(ir, b);
            let cc = match (op, signed) {
                (CompareOp::Eq, _) => IntCC::Equal,
                (CompareOp::Ne, _) => IntCC::NotEqual,
                (CompareOp::Lt, true) => IntCC::SignedLessThan,
                (CompareOp::Lt, false) => IntCC::UnsignedLessThan,
                (CompareOp::Le, true) => IntCC::SignedLessThanOrEqual,
                (CompareOp::Le, false) => IntCC::UnsignedLessThanOrEqual,
                (CompareOp::Gt, true) => IntCC::SignedGreaterThan,
                (CompareOp::Gt, false) => IntCC::UnsignedGreaterThan,
                (CompareOp::Ge, true) => IntCC::SignedGreaterThanOrEqual,
                (CompareOp::Ge, false) => IntCC::UnsignedGreaterThanOrEqual,
            };
            self.builder.ins().icmp(cc, l, r)
        };
        self.store(result, dst);
        true
    }
}
