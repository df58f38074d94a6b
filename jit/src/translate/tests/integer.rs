//! Integer arithmetic per width, division checks, unary operations and bits, BOOL reads.

#![allow(clippy::unwrap_used, clippy::expect_used)] // A panic is a failed test.

use super::*;

fn integer_reference(op: BinaryOp, ty: Elementary, a: u64, b: u64) -> u64 {
    let mask = reference::mask(ty);
    let bits = u64::from(ty.size_bytes() * 8);
    let (l, r) = (reference::value(a, ty), reference::value(b, ty));
    let wrap = |v: i128| (v as u64) & mask;
    match op {
        BinaryOp::Add => wrap(l + r),
        BinaryOp::Sub => wrap(l - r),
        BinaryOp::Mul => wrap(l.wrapping_mul(r)),
        BinaryOp::Div => wrap(l / r),
        BinaryOp::Mod => wrap(l % r),
        BinaryOp::And => a & b,
        BinaryOp::Or => a | b,
        BinaryOp::Xor => a ^ b,
        BinaryOp::Min => {
            if r < l {
                b
            } else {
                a
            }
        }
        BinaryOp::Max => {
            if r > l {
                b
            } else {
                a
            }
        }
        BinaryOp::Shl if b >= bits => 0,
        BinaryOp::Shl => (a << b) & mask,
        BinaryOp::Shr if b >= bits => 0,
        BinaryOp::Shr => a >> b,
        BinaryOp::Rol | BinaryOp::Ror => {
            let n = b % bits;
            let n = if op == BinaryOp::Ror {
                (bits - n) % bits
            } else {
                n
            };
            if n == 0 {
                a
            } else {
                ((a << n) | (a >> (bits - n))) & mask
            }
        }
        _ => unreachable!(),
    }
}

#[test]
fn integer_operations_wrap_per_width() {
    let ops = [
        BinaryOp::Add,
        BinaryOp::Sub,
        BinaryOp::Mul,
        BinaryOp::And,
        BinaryOp::Or,
        BinaryOp::Xor,
        BinaryOp::Min,
        BinaryOp::Max,
        BinaryOp::Shl,
        BinaryOp::Shr,
        BinaryOp::Rol,
        BinaryOp::Ror,
    ];
    for ty in INTEGERS {
        let size = ty.size_bytes();
        let code = ops
            .iter()
            .enumerate()
            .map(|(index, op)| Instr::Binary {
                op: *op,
                ty,
                dst: I(16 + 8 * index as u32),
                a: I(0),
                b: I(8),
            })
            .collect();
        let fixture = Fixture::new(code);
        for a in samples(ty) {
            for b in samples(ty) {
                let mut host = fixture.host();
                host.put(0, a, size);
                host.put(8, b, size);
                assert_eq!(fixture.run(&mut host), Status::Ok);
                for (index, op) in ops.iter().enumerate() {
                    assert_eq!(
                        host.get(16 + 8 * index as u32, size),
                        integer_reference(*op, ty, a, b),
                        "{op:?} on {} of {a:#x} and {b:#x}",
                        ty.name()
                    );
                }
            }
        }
    }
}

#[test]
fn division_by_zero_faults_and_by_minus_one_wraps() {
    for ty in INTEGERS {
        let size = ty.size_bytes();
        let code = vec![
            Instr::Move {
                ty: Dint,
                dst: I(100),
                src: I(104),
            },
            Instr::Binary {
                op: BinaryOp::Div,
                ty,
                dst: I(16),
                a: I(0),
                b: I(8),
            },
            Instr::Binary {
                op: BinaryOp::Mod,
                ty,
                dst: I(24),
                a: I(0),
                b: I(8),
            },
        ];
        let fixture = Fixture::new(code);
        for a in samples(ty) {
            for b in samples(ty) {
                let mut host = fixture.host();
                host.put(0, a, size);
                host.put(8, b, size);
                let status = fixture.run(&mut host);
                if b == 0 {
                    assert_eq!(status, Status::Faulted);
                    let site = Site {
                        pou: 0,
                        instruction: 1,
                    };
                    assert_eq!(host.faults, vec![(site, NativeFault::DivisionByZero)]);
                    continue;
                }
                assert_eq!(status, Status::Ok);
                assert!(host.faults.is_empty());
                assert_eq!(
                    host.get(16, size),
                    integer_reference(BinaryOp::Div, ty, a, b)
                );
                assert_eq!(
                    host.get(24, size),
                    integer_reference(BinaryOp::Mod, ty, a, b)
                );
            }
        }
    }
}

#[test]
fn unary_integer_operations_and_bits() {
    for ty in INTEGERS {
        let size = ty.size_bytes();
        let code = vec![
            Instr::Unary {
                op: UnaryOp::Neg,
                ty,
                dst: I(16),
                src: I(0),
            },
            Instr::Unary {
                op: UnaryOp::Abs,
                ty,
                dst: I(24),
                src: I(0),
            },
            Instr::Unary {
                op: UnaryOp::Not,
                ty,
                dst: I(32),
                src: I(0),
            },
            Instr::GetBit {
                ty,
                dst: I(40),
                src: I(0),
                bit: (size * 8 - 1) as u8,
            },
            Instr::SetBit {
                ty,
                dst: I(48),
                bit: 1,
                src: I(41),
            },
            Instr::Compare {
                op: CompareOp::Lt,
                ty,
                dst: I(56),
                a: I(0),
                b: I(8),
            },
        ];
        let fixture = Fixture::new(code);
        for a in samples(ty) {
            let mut host = fixture.host();
            host.put(0, a, size);
            host.put(8, 3, size);
            host.put(41, 1, 1);
            host.put(48, 0, size);
            assert_eq!(fixture.run(&mut host), Status::Ok);
            let value = reference::value(a, ty);
            let mask = reference::mask(ty);
            assert_eq!(host.get(16, size), (value.wrapping_neg() as u64) & mask);
            let abs = if value < 0 {
                value.wrapping_neg()
            } else {
                value
            };
            assert_eq!(host.get(24, size), (abs as u64) & mask, "ABS of {a:#x}");
            assert_eq!(host.get(32, size), !a & mask);
            assert_eq!(host.get(40, 1), (a >> (size * 8 - 1)) & 1);
            assert_eq!(host.get(48, size), 2);
            assert_eq!(host.get(56, 1), u64::from(value < 3));
        }
    }
}

#[test]
fn bool_not_and_compare_read_the_whole_byte() {
    let code = vec![
        Instr::Unary {
            op: UnaryOp::Not,
            ty: Bool,
            dst: I(1),
            src: I(0),
        },
        Instr::Compare {
            op: CompareOp::Eq,
            ty: Bool,
            dst: I(3),
            a: I(0),
            b: I(2),
        },
        Instr::Convert {
            from: Bool,
            to: Dint,
            dst: I(4),
            src: I(0),
        },
    ];
    let fixture = Fixture::new(code);
    let mut host = fixture.host();
    host.put(0, 2, 1);
    host.put(2, 1, 1);
    assert_eq!(fixture.run(&mut host), Status::Ok);
    assert_eq!(host.get(1, 1), 0);
    // A byte of 2 is TRUE, but not equal to a byte of 1, as in the interpreter.
    assert_eq!(host.get(3, 1), 0);
    assert_eq!(host.get(4, 4), 1);
}
