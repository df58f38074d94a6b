//! REAL and LREAL operations bit for bit, no fused product and sum, conversions at every
//! boundary.

#![allow(clippy::unwrap_used, clippy::expect_used)] // A panic is a failed test.

use super::*;

pub(super) fn real_code(ty: Elementary) -> Vec<Instr> {
    let mut code = Vec::new();
    for (index, op) in [
        BinaryOp::Add,
        BinaryOp::Sub,
        BinaryOp::Mul,
        BinaryOp::Div,
        BinaryOp::Min,
        BinaryOp::Max,
        BinaryOp::Mod,
    ]
    .into_iter()
    .enumerate()
    {
        code.push(Instr::Binary {
            op,
            ty,
            dst: I(16 + 8 * index as u32),
            a: I(0),
            b: I(8),
        });
    }
    for (index, op) in [
        CompareOp::Eq,
        CompareOp::Ne,
        CompareOp::Lt,
        CompareOp::Le,
        CompareOp::Gt,
        CompareOp::Ge,
    ]
    .into_iter()
    .enumerate()
    {
        code.push(Instr::Compare {
            op,
            ty,
            dst: I(80 + index as u32),
            a: I(0),
            b: I(8),
        });
    }
    for (index, op) in [UnaryOp::Neg, UnaryOp::Abs, UnaryOp::Sqrt, UnaryOp::Round]
        .into_iter()
        .enumerate()
    {
        code.push(Instr::Unary {
            op,
            ty,
            dst: I(96 + 8 * index as u32),
            src: I(0),
        });
    }
    code
}

#[test]
fn reals_are_bit_for_bit_the_interpreters() {
    let values = [
        0.0,
        -0.0,
        1.5,
        -2.5,
        3.0e38,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NAN,
        -f64::NAN,
        1.0e-310,
    ];
    // The interpreter's operations in Rust, on the type's own values.
    macro_rules! check {
        ($t:ty, $ty:expr, $bits:ident) => {{
            let fixture = Fixture::new(real_code($ty));
            let size = $ty.size_bytes();
            for a in values {
                for b in values {
                    let (l, r) = (a as $t, b as $t);
                    let mut host = fixture.host();
                    host.put(0, u64::from(l.to_bits()), size);
                    host.put(8, u64::from(r.to_bits()), size);
                    assert_eq!(fixture.run(&mut host), Status::Ok);
                    let got = |offset: u32| host.get(offset, size);
                    let expected: [$t; 7] = [
                        l + r,
                        l - r,
                        l * r,
                        l / r,
                        if r < l { r } else { l },
                        if r > l { r } else { l },
                        l % r,
                    ];
                    for (index, value) in expected.iter().enumerate() {
                        assert_eq!(
                            got(16 + 8 * index as u32),
                            u64::from(value.to_bits()),
                            "operation {index} of {l:?} and {r:?}"
                        );
                    }
                    let compared = [l == r, l != r, l < r, l <= r, l > r, l >= r];
                    for (index, value) in compared.iter().enumerate() {
                        assert_eq!(host.get(80 + index as u32, 1), u64::from(*value));
                    }
                    let unary: [$t; 4] = [
                        -l,
                        l.abs(),
                        f64::from(l).sqrt() as $t,
                        f64::from(l).round() as $t,
                    ];
                    for (index, value) in unary.iter().enumerate() {
                        assert_eq!(
                            got(96 + 8 * index as u32),
                            u64::from(value.to_bits()),
                            "unary {index} of {l:?}"
                        );
                    }
                }
            }
        }};
    }
    check!(f32, Real, u32);
    check!(f64, Lreal, u64);
}

#[test]
fn a_product_and_a_sum_are_never_fused() {
    // a·b rounds to 1.0, so a·b + c is 0; a fused multiply-add would give −2⁻⁵⁴.
    let (a, b, c) = (1.0 + 2f64.powi(-27), 1.0 - 2f64.powi(-27), -1.0f64);
    assert_ne!(a.mul_add(b, c), a * b + c);
    let code = vec![
        Instr::Binary {
            op: BinaryOp::Mul,
            ty: Lreal,
            dst: Operand::Frame(0),
            a: I(0),
            b: I(8),
        },
        Instr::Binary {
            op: BinaryOp::Add,
            ty: Lreal,
            dst: I(24),
            a: Operand::Frame(0),
            b: I(16),
        },
    ];
    let fixture = Fixture::new(code);
    let mut host = fixture.host();
    host.put(0, a.to_bits(), 8);
    host.put(8, b.to_bits(), 8);
    host.put(16, c.to_bits(), 8);
    assert_eq!(fixture.run(&mut host), Status::Ok);
    assert_eq!(f64::from_bits(host.get(24, 8)), a * b + c);
}

#[test]
fn a_moved_signalling_nan_keeps_its_bits() {
    let code = vec![
        Instr::Move {
            ty: Real,
            dst: I(8),
            src: I(0),
        },
        Instr::Move {
            ty: Lreal,
            dst: I(24),
            src: I(16),
        },
    ];
    let fixture = Fixture::new(code);
    let mut host = fixture.host();
    host.put(0, 0x7F80_0001, 4);
    host.put(16, 0x7FF0_0000_0000_0001, 8);
    assert_eq!(fixture.run(&mut host), Status::Ok);
    assert_eq!(host.get(8, 4), 0x7F80_0001);
    assert_eq!(host.get(24, 8), 0x7FF0_0000_0000_0001);
}

#[test]
fn reals_convert_to_integers_at_every_boundary() {
    let two_63 = 2f64.powi(63);
    let values = [
        0.5,
        -0.5,
        1.5,
        -1.5,
        2.5,
        -2.5,
        -2.4,
        0.499_999_999_999_999_94,
        two_63,
        -two_63,
        two_63 - 1024.0,
        -(two_63 - 1024.0),
        1.0e19,
        2f64.powi(64),
        2f64.powi(127),
        -0.0,
        70_000.0,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NAN,
    ];
    let targets = [
        Sint, Int, Dint, Lint, Usint, Uint, Udint, Ulint, Time, Ltime,
    ];
    for from in [Real, Lreal] {
        let mut code = Vec::new();
        for (index, to) in targets.iter().enumerate() {
            code.push(Instr::Convert {
                from,
                to: *to,
                dst: I(16 + 8 * index as u32),
                src: I(0),
            });
            code.push(Instr::Trunc {
                from,
                to: *to,
                dst: I(112 + 8 * index as u32),
                src: I(0),
            });
        }
        code.push(Instr::Convert {
            from,
            to: Bool,
            dst: I(208),
            src: I(0),
        });
        code.push(Instr::Trunc {
            from,
            to: Bool,
            dst: I(209),
            src: I(0),
        });
        let fixture = Fixture::new(code);
        for value in values {
            let raw = reference::raw_of_real(value, from);
            let x = reference::real_of(raw, from);
            let mut host = fixture.host();
            host.put(0, raw, from.size_bytes());
            assert_eq!(fixture.run(&mut host), Status::Ok);
            for (index, to) in targets.iter().enumerate() {
                let size = to.size_bytes();
                assert_eq!(
                    host.get(16 + 8 * index as u32, size),
                    reference::real_to_integer(x, *to, false),
                    "{}_TO_{} of {x:?}",
                    from.name(),
                    to.name()
                );
                assert_eq!(
                    host.get(112 + 8 * index as u32, size),
                    reference::real_to_integer(x, *to, true),
                    "TRUNC {} to {} of {x:?}",
                    from.name(),
                    to.name()
                );
            }
            assert_eq!(host.get(208, 1), u64::from(x != 0.0));
            assert_eq!(host.get(209, 1), u64::from(x.trunc() != 0.0 || x.is_nan()));
        }
    }
}

#[test]
fn integers_convert_to_integers_reals_and_bool() {
    let targets = [Sint, Uint, Dint, Ulint, Real, Lreal, Bool];
    for from in INTEGERS {
        let code = targets
            .iter()
            .enumerate()
            .map(|(index, to)| Instr::Convert {
                from,
                to: *to,
                dst: I(16 + 8 * index as u32),
                src: I(0),
            })
            .collect();
        let fixture = Fixture::new(code);
        for raw in samples(from) {
            let mut host = fixture.host();
            host.put(0, raw, from.size_bytes());
            assert_eq!(fixture.run(&mut host), Status::Ok);
            let value = reference::value(raw, from);
            for (index, to) in targets.iter().enumerate() {
                let expected = match to {
                    Real => u64::from((value as f32).to_bits()),
                    Lreal => (value as f64).to_bits(),
                    Bool => u64::from(value != 0),
                    _ => (value as u64) & reference::mask(*to),
                };
                assert_eq!(
                    host.get(16 + 8 * index as u32, to.size_bytes()),
                    expected,
                    "{}_TO_{} of {raw:#x}",
                    from.name(),
                    to.name()
                );
            }
        }
    }
}
