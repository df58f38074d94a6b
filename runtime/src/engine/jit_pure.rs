//! The pure functions generated code calls (`docs/native-engine.md` §4.6): `extern "C"`
//! wrappers around the interpreter's own computations, so that a native result is the
//! interpreter's bit for bit.
//!
//! Generated code calls these directly, not through a shim that catches panics, so each is
//! total: the ones that reach code that could panic catch it themselves and answer 0. Type and
//! operation codes are the image format's numbers; an unknown number (which the translator
//! cannot write) gives the operand back unchanged.

use std::panic::catch_unwind;

use program_image::{BinaryOp, Elementary as E};

use super::lower::real_function;
use super::scalar::{Arith, Real};
use crate::stdlib::{convert, numeric};

/// The table the translator registers (`jit::PureFunctions`).
pub(crate) const PURE_FUNCTIONS: jit::PureFunctions = jit::PureFunctions {
    real_unary_f32,
    real_unary_f64,
    real_binary_f32,
    real_binary_f64,
    int_expt,
    bcd,
    convert: convert_raw,
    trunc: trunc_raw,
};

/// A unary real function of a REAL, computed in `f64` and rounded back as `Real::apply` does.
extern "C" fn real_unary_f32(op: u32, x: f32) -> f32 {
    match jit::unary_op_from_code(op) {
        Some(op) => x.apply(real_function(op)),
        None => x,
    }
}

/// A unary real function of an LREAL.
extern "C" fn real_unary_f64(op: u32, x: f64) -> f64 {
    match jit::unary_op_from_code(op) {
        Some(op) => x.apply(real_function(op)),
        None => x,
    }
}

/// `MOD`, `EXPT` or `ATAN2` of two REALs, as the interpreter's `arith2` and `real2` compute.
extern "C" fn real_binary_f32(op: u32, a: f32, b: f32) -> f32 {
    real_binary(op, a, b)
}

/// `MOD`, `EXPT` or `ATAN2` of two LREALs.
extern "C" fn real_binary_f64(op: u32, a: f64, b: f64) -> f64 {
    real_binary(op, a, b)
}

/// `MOD`, `EXPT` or `ATAN2` (the operation's code, `jit::binary_op_code`) of two reals of
/// either width, by the interpreter's own `Arith` and `Real` methods so both engines round
/// alike; an operation code of anything else gives `a` back, which the translator never emits.
fn real_binary<T: Real>(op: u32, a: T, b: T) -> T {
    match jit::binary_op_from_code(op) {
        // A real remainder never fails (`Arith::rem` of a real is always `Some`).
        Some(BinaryOp::Mod) => a.rem(b).unwrap_or(a),
        Some(BinaryOp::Expt) => a.expt(b),
        Some(BinaryOp::Atan2) => a.apply2(b, f64::atan2),
        _ => a,
    }
}

/// The integer power of two raw values of type `ty` (`Arith::expt` of the type).
extern "C" fn int_expt(raw_a: u64, raw_b: u64, ty: u32) -> u64 {
    fn expt<T: Arith>(a: u64, b: u64) -> u64 {
        T::from_raw(a).expt(T::from_raw(b)).to_raw()
    }
    let Some(ty) = E::from_tag(ty as u8) else {
        return raw_a;
    };
    let power = match ty {
        E::Bool | E::Byte | E::Usint | E::Char => expt::<u8>,
        E::Word | E::Uint | E::Wchar => expt::<u16>,
        E::Dword | E::Udint | E::Date | E::TimeOfDay | E::DateAndTime => expt::<u32>,
        E::Lword | E::Ulint => expt::<u64>,
        E::Sint => expt::<i8>,
        E::Int => expt::<i16>,
        E::Dint | E::Time => expt::<i32>,
        E::Lint | E::Ltime | E::Ldate | E::LtimeOfDay | E::LdateAndTime => expt::<i64>,
        E::Real | E::Lreal => return raw_a,
    };
    catch_unwind(|| power(raw_a, raw_b)).unwrap_or(0)
}

/// `TO_BCD` (`to_bcd` 1) or `FROM_BCD` (0) of a raw value, as the interpreter's `unary`.
extern "C" fn bcd(raw: u64, _ty: u32, to_bcd: u32) -> u64 {
    let result = catch_unwind(|| {
        if to_bcd == 1 {
            numeric::to_bcd(raw)
        } else {
            numeric::from_bcd(raw)
        }
    });
    result.unwrap_or(0)
}

/// The interpreter's `convert` of a raw value.
extern "C" fn convert_raw(raw: u64, from: u32, to: u32) -> u64 {
    match (E::from_tag(from as u8), E::from_tag(to as u8)) {
        (Some(from), Some(to)) => catch_unwind(|| convert::convert(raw, from, to)).unwrap_or(0),
        _ => raw,
    }
}

/// The interpreter's `trunc` of a raw value.
extern "C" fn trunc_raw(raw: u64, from: u32, to: u32) -> u64 {
    match (E::from_tag(from as u8), E::from_tag(to as u8)) {
        (Some(from), Some(to)) => catch_unwind(|| convert::trunc(raw, from, to)).unwrap_or(0),
        _ => raw,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_pure_functions_are_the_interpreters() {
        let sin = jit::unary_op_code(program_image::UnaryOp::Sin);
        assert_eq!(
            real_unary_f32(sin, 1.0).to_bits(),
            ((1.0f64).sin() as f32).to_bits()
        );
        let round = jit::unary_op_code(program_image::UnaryOp::Round);
        assert_eq!(real_unary_f64(round, -2.5), -3.0);
        let modulo = jit::binary_op_code(BinaryOp::Mod);
        assert_eq!(real_binary_f32(modulo, 7.5, 2.0), 1.5);
        let atan2 = jit::binary_op_code(BinaryOp::Atan2);
        assert_eq!(real_binary_f64(atan2, 1.0, 1.0), 1.0f64.atan2(1.0));
        // SINT: 3 ** 5 = 243 wraps to -13; a negative exponent of 2 gives 0.
        let sint = u32::from(E::Sint.tag());
        assert_eq!(int_expt(3, 5, sint) as u8 as i8, -13);
        assert_eq!(int_expt(2, (-1i8) as u8 as u64, sint), 0);
        assert_eq!(bcd(42, u32::from(E::Byte.tag()), 1), 0x42);
        assert_eq!(bcd(0x42, u32::from(E::Byte.tag()), 0), 42);
        let (real, dint) = (u32::from(E::Real.tag()), u32::from(E::Dint.tag()));
        assert_eq!(convert_raw(u64::from(2.5f32.to_bits()), real, dint), 3);
        assert_eq!(trunc_raw(u64::from(2.5f32.to_bits()), real, dint), 2);
        // Unknown codes give the operand back.
        assert_eq!(convert_raw(7, 200, dint), 7);
        assert_eq!(int_expt(7, 2, 200), 7);
    }
}
