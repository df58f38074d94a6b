//! REAL and LREAL operations and every conversion, bit for bit the interpreter's
//! (`docs/native-engine.md` §6).

use cranelift_codegen::ir::condcodes::{FloatCC, IntCC};
use cranelift_codegen::ir::{BlockArg, InstBuilder, Type, Value, types};
use program_image::{BinaryOp, Elementary, Instr, Operand, UnaryOp};

use super::host_calls::{Import, binary_op_code, unary_op_code};
use super::{Translator, int_type, is_signed};

/// 2⁶³ as a double: below it in magnitude an integral double converts to `i64` exactly.
const TWO_POW_63: f64 = 9_223_372_036_854_775_808.0;

/// The IR type of a real type.
fn float_type(ty: Elementary) -> Type {
    if ty == Elementary::Real {
        types::F32
    } else {
        types::F64
    }
}

/// Time and date types, which `convert` rescales between different units.
fn is_time(ty: Elementary) -> bool {
    use Elementary::*;
    matches!(
        ty,
        Time | Ltime | Date | Ldate | TimeOfDay | LtimeOfDay | DateAndTime | LdateAndTime
    )
}

impl Translator<'_, '_> {
    /// `Unary` on a real; false to leave it to the host.
    pub(crate) fn real_unary(
        &mut self,
        op: UnaryOp,
        ty: Elementary,
        dst: Operand,
        src: Operand,
    ) -> bool {
        let ir = float_type(ty);
        let result = match op {
            UnaryOp::Neg => {
                let value = self.load(ir, src);
                self.builder.ins().fneg(value)
            }
            UnaryOp::Abs => {
                let value = self.load(ir, src);
                self.builder.ins().fabs(value)
            }
            // Correctly rounded in the type, which equals the interpreter's square root in f64
            // rounded back (§5.1).
            UnaryOp::Sqrt => {
                let value = self.load(ir, src);
                self.builder.ins().sqrt(value)
            }
            UnaryOp::Ln
            | UnaryOp::Log
            | UnaryOp::Exp
            | UnaryOp::Sin
            | UnaryOp::Cos
            | UnaryOp::Tan
            | UnaryOp::Asin
            | UnaryOp::Acos
            | UnaryOp::Atan
            | UnaryOp::Round => {
                let value = self.load(ir, src);
                let code = self
                    .builder
                    .ins()
                    .iconst(types::I32, i64::from(unary_op_code(op)));
                let import = if ty == Elementary::Real {
                    Import::RealUnaryF32
                } else {
                    Import::RealUnaryF64
                };
                self.call_pure(import, &[code, value])
            }
            // NOT and BCD on reals are the interpreter's oddities (an identity through f64):
            // left to it.
            UnaryOp::Not | UnaryOp::ToBcd | UnaryOp::FromBcd => return false,
        };
        self.store(result, dst);
        true
    }

    /// A real operand loaded as the integer of its size and moved into a float register.
    ///
    /// For the left operand of `fadd` and `fmul`: Cranelift's x64 backend folds a load on
    /// the left of these commutative operations into the instruction by swapping the operands
    /// (`vmulsd [l], r`), and of two NaNs x86 keeps the first operand's, so the result would
    /// carry the right operand's NaN where the interpreter's `l * r` carries the left one's
    /// (§6.1). A bitcast is no load it can fold; a folded constant or a promoted place stays
    /// what it was.
    fn load_unfoldable(&mut self, ir: Type, operand: Operand) -> Value {
        let bits_type = if ir == types::F32 {
            types::I32
        } else {
            types::I64
        };
        let bits = self.load(bits_type, operand);
        self.builder
            .ins()
            .bitcast(ir, cranelift_codegen::ir::MemFlagsData::new(), bits)
    }

    /// Whether the left operand `a` of a REAL or LREAL (`ty`) `fadd` or `fmul` must be loaded
    /// by [`Self::load_unfoldable`], because the code generator could fold its load into the
    /// instruction by swapping the operands (§6.1).
    ///
    /// The backend folds a load that is the last load or store before the operation, and the
    /// code generator's alias analysis removes loads it can prove redundant (a place loaded or
    /// stored before, with no store since, even across blocks and instructions), so whether the
    /// right operand's load stays between them cannot be told here. The float load is kept
    /// only where no swap can show or no load of the left operand is left: the same place on
    /// both sides, a right operand that is a folded constant and no NaN (of a NaN and a
    /// number, either order gives the NaN), a left operand that is a folded constant or a
    /// place a loop keeps in a variable, and a left operand the instruction just before
    /// computed with an inline real operation and stored, whose store is then the last one and
    /// is forwarded to the load (the temporaries of an expression, where keeping the value in
    /// a register matters most).
    fn left_could_be_folded(&self, ty: Elementary, a: Operand, b: Operand) -> bool {
        if a == b {
            // The same value on both sides: the order cannot show.
            return false;
        }
        let ir = float_type(ty);
        if let Operand::Const(offset) = b
            && self.constant_is_a_number(ir, offset)
        {
            return false;
        }
        if matches!(a, Operand::Const(_)) && self.folded_constants.is_some() {
            return false;
        }
        let size = ir.bytes();
        if self
            .promoted
            .iter()
            .any(|(place, place_size, _)| *place == a && *place_size == size)
        {
            return false;
        }
        let pc = self.pc as usize;
        let computed_just_before = self.blocks.at(pc).is_none()
            && !self.aliases_promoted(a, size)
            && pc
                .checked_sub(1)
                .and_then(|before| self.code.get(before))
                .is_some_and(|instr| {
                    matches!(
                        instr,
                        Instr::Binary {
                            op: BinaryOp::Add | BinaryOp::Sub | BinaryOp::Mul | BinaryOp::Div,
                            ty: computed,
                            dst,
                            ..
                        } if *dst == a && *computed == ty
                    )
                });
        !computed_just_before
    }

    /// Whether the constant pool is folded and holds a number (no NaN) of type `ir` at
    /// `offset`.
    fn constant_is_a_number(&self, ir: Type, offset: u32) -> bool {
        self.folded_bits(ir, offset).is_some_and(|bits| {
            if ir == types::F32 {
                !f32::from_bits(bits as u32).is_nan()
            } else {
                !f64::from_bits(bits).is_nan()
            }
        })
    }

    /// `Binary` on a real; false to leave it to the host.
    pub(crate) fn real_binary(
        &mut self,
        op: BinaryOp,
        ty: Elementary,
        dst: Operand,
        a: Operand,
        b: Operand,
    ) -> bool {
        let ir = float_type(ty);
        let pure = matches!(op, BinaryOp::Mod | BinaryOp::Expt | BinaryOp::Atan2);
        let inline = matches!(
            op,
            BinaryOp::Add
                | BinaryOp::Sub
                | BinaryOp::Mul
                | BinaryOp::Div
                | BinaryOp::Min
                | BinaryOp::Max
        );
        if !pure && !inline {
            // Bit operations on reals are refused by the interpreter at load.
            return false;
        }
        let l =
            if matches!(op, BinaryOp::Add | BinaryOp::Mul) && self.left_could_be_folded(ty, a, b) {
                self.load_unfoldable(ir, a)
            } else {
                self.load(ir, a)
            };
        let r = self.load(ir, b);
        let result = match op {
            BinaryOp::Add => self.builder.ins().fadd(l, r),
            BinaryOp::Sub => self.builder.ins().fsub(l, r),
            BinaryOp::Mul => self.builder.ins().fmul(l, r),
            BinaryOp::Div => self.builder.ins().fdiv(l, r),
            // The interpreter's comparisons and selections, not fmin/fmax (§6.1).
            BinaryOp::Min => {
                let take_right = self.builder.ins().fcmp(FloatCC::LessThan, r, l);
                self.builder.ins().select(take_right, r, l)
            }
            BinaryOp::Max => {
                let take_right = self.builder.ins().fcmp(FloatCC::GreaterThan, r, l);
                self.builder.ins().select(take_right, r, l)
            }
            _ => {
                let code = self
                    .builder
                    .ins()
                    .iconst(types::I32, i64::from(binary_op_code(op)));
                let import = if ty == Elementary::Real {
                    Import::RealBinaryF32
                } else {
                    Import::RealBinaryF64
                };
                self.call_pure(import, &[code, l, r])
            }
        };
        self.store(result, dst);
        true
    }

    /// `Convert` (`truncate` false) or `Trunc` (`truncate` true) from `from` to `to`.
    pub(crate) fn convert(
        &mut self,
        from: Elementary,
        to: Elementary,
        dst: Operand,
        src: Operand,
        truncate: bool,
    ) -> bool {
        use Elementary::Bool;
        // TRUNC of a type that is not a real is CONVERT (the interpreter's `trunc`).
        let truncate = truncate && from.is_real();
        let result = match (from.is_real(), to.is_real()) {
            (false, _) if from == Bool && to != Bool => self.pure_convert(from, to, src, false),
            (false, false) if to == Bool => {
                let value = self.load(int_type(from), src);
                self.builder.ins().icmp_imm_u(IntCC::NotEqual, value, 0)
            }
            (false, false) if is_time(from) && is_time(to) && from != to => {
                self.pure_convert(from, to, src, false)
            }
            (false, false) => {
                let value = self.load(int_type(from), src);
                self.resized(value, int_type(from), int_type(to), is_signed(from))
            }
            (false, true) => {
                let value = self.load(int_type(from), src);
                let wide = self.resized(value, int_type(from), types::I64, is_signed(from));
                if is_signed(from) {
                    self.builder.ins().fcvt_from_sint(float_type(to), wide)
                } else {
                    self.builder.ins().fcvt_from_uint(float_type(to), wide)
                }
            }
            (true, true) => {
                let value = self.load(float_type(from), src);
                if truncate {
                    let wide = self.widened_to_double(value, from);
                    let whole = self.builder.ins().trunc(wide);
                    self.narrowed_from_double(whole, to)
                } else if from == to {
                    // The interpreter goes through f64 and back (which quiets a signalling
                    // NaN of a REAL); the pure function does exactly that.
                    return self.convert_by_pure(from, to, dst, src);
                } else if to == Elementary::Lreal {
                    self.builder.ins().fpromote(types::F64, value)
                } else {
                    self.builder.ins().fdemote(types::F32, value)
                }
            }
            (true, false) if to == Bool => {
                let value = self.load(float_type(from), src);
                let wide = self.widened_to_double(value, from);
                let tested = if truncate {
                    self.builder.ins().trunc(wide)
                } else {
                    wide
                };
                let zero = self.builder.ins().f64const(0.0);
                // True for NaN, as `x != 0.0`.
                self.builder.ins().fcmp(FloatCC::NotEqual, tested, zero)
            }
            (true, false) => self.real_to_integer(from, to, src, truncate),
        };
        self.store(result, dst);
        true
    }

    fn convert_by_pure(
        &mut self,
        from: Elementary,
        to: Elementary,
        dst: Operand,
        src: Operand,
    ) -> bool {
        let result = self.pure_convert(from, to, src, false);
        self.store(result, dst);
        true
    }

    /// The pure `convert` or `trunc` of the operand, narrowed to `to`'s width (as its IR type:
    /// an integer type, or a float type for reals).
    fn pure_convert(
        &mut self,
        from: Elementary,
        to: Elementary,
        src: Operand,
        truncate: bool,
    ) -> Value {
        let raw = self.load(int_type(from), src);
        let raw = self.resized(raw, int_type(from), types::I64, false);
        let result = self.pure_raw(raw, from, to, truncate);
        let narrowed = self.resized(result, types::I64, int_type(to), false);
        if to.is_real() {
            self.builder.ins().bitcast(
                float_type(to),
                cranelift_codegen::ir::MemFlagsData::new(),
                narrowed,
            )
        } else {
            narrowed
        }
    }

    /// Calls the pure `convert` or `trunc` on raw bits.
    fn pure_raw(&mut self, raw: Value, from: Elementary, to: Elementary, truncate: bool) -> Value {
        let from_tag = self.builder.ins().iconst(types::I32, i64::from(from.tag()));
        let to_tag = self.builder.ins().iconst(types::I32, i64::from(to.tag()));
        let import = if truncate {
            Import::Trunc
        } else {
            Import::Convert
        };
        self.call_pure(import, &[raw, from_tag, to_tag])
    }

    fn widened_to_double(&mut self, value: Value, ty: Elementary) -> Value {
        if ty == Elementary::Real {
            self.builder.ins().fpromote(types::F64, value)
        } else {
            value
        }
    }

    fn narrowed_from_double(&mut self, value: Value, ty: Elementary) -> Value {
        if ty == Elementary::Real {
            self.builder.ins().fdemote(types::F32, value)
        } else {
            value
        }
    }

    /// A real to an integer (§6.2): in f64, rounded half away from zero (or truncated), then
    /// the low bits of the exact integer; magnitudes of 2⁶³ or more, NaN and the infinities
    /// through the pure function.
    fn real_to_integer(
        &mut self,
        from: Elementary,
        to: Elementary,
        src: Operand,
        truncate: bool,
    ) -> Value {
        let value = self.load(float_type(from), src);
        let x = self.widened_to_double(value, from);
        let whole = self.builder.ins().trunc(x);
        let rounded = if truncate {
            whole
        } else {
            // `x - t` is exact, so this is `f64::round`.
            let fraction = self.builder.ins().fsub(x, whole);
            let magnitude = self.builder.ins().fabs(fraction);
            let half = self.builder.ins().f64const(0.5);
            let away = self
                .builder
                .ins()
                .fcmp(FloatCC::GreaterThanOrEqual, magnitude, half);
            let one = self.builder.ins().f64const(1.0);
            let step = self.builder.ins().fcopysign(one, x);
            let stepped = self.builder.ins().fadd(whole, step);
            self.builder.ins().select(away, stepped, whole)
        };
        let size = self.builder.ins().fabs(rounded);
        let limit = self.builder.ins().f64const(TWO_POW_63);
        // False for NaN, which takes the slow path.
        let fast = self.builder.ins().fcmp(FloatCC::LessThan, size, limit);
        let fast_block = self.builder.create_block();
        let slow_block = self.builder.create_block();
        let join = self.builder.create_block();
        self.builder.append_block_param(join, types::I64);
        self.builder.set_cold_block(slow_block);
        self.builder
            .ins()
            .brif(fast, fast_block, &[], slow_block, &[]);
        self.builder.switch_to_block(fast_block);
        // In range, so the saturating conversion is exact and cannot trap.
        let exact = self.builder.ins().fcvt_to_sint_sat(types::I64, rounded);
        self.builder.ins().jump(join, &[BlockArg::Value(exact)]);
        self.builder.switch_to_block(slow_block);
        let bits =
            self.builder
                .ins()
                .bitcast(types::I64, cranelift_codegen::ir::MemFlagsData::new(), x);
        let slow = self.pure_raw(bits, Elementary::Lreal, to, truncate);
        self.builder.ins().jump(join, &[BlockArg::Value(slow)]);
        self.builder.switch_to_block(join);
        let result = self.builder.block_params(join)[0];
        self.resized(result, types::I64, int_type(to), false)
    }
}
