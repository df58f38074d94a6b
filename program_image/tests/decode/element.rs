//! The fused element instructions `LoadElement` (29) and `StoreElement` (30) of
//! `docs/program-image.md` §7.1: their encoding (the variant index is the instruction's number,
//! then the fields in the order of the table), their round trip, and each load-time refusal of
//! §7.2, which names the POU and the instruction.

use program_image::{Elementary, Instr, Operand, ProgramImage};

use super::{assert_contains, invalid_message, small_image};

/// `main`'s instance of 12 bytes read as an array of three DINTs from index -1, indexed by the
/// DINT at `Frame(0)`, into `Frame(4)`.
fn load() -> Instr {
    Instr::LoadElement {
        ty: Elementary::Dint,
        dst: Operand::Frame(4),
        array: Operand::Instance(0),
        index: Operand::Frame(0),
        index_ty: Elementary::Dint,
        low: -1,
        count: 3,
        stride: 4,
        offset: 0,
    }
}

/// The store into the array `load` reads, of the DINT at `Frame(4)`.
fn store() -> Instr {
    Instr::StoreElement {
        ty: Elementary::Dint,
        array: Operand::Instance(0),
        index: Operand::Frame(0),
        index_ty: Elementary::Dint,
        low: -1,
        count: 3,
        stride: 4,
        offset: 0,
        src: Operand::Frame(4),
    }
}

/// The small image with `main`'s instruction 1 replaced by `instr`.
fn with_instruction(instr: Instr) -> ProgramImage {
    let mut image = small_image();
    image.pous[0].code[1] = instr;
    image
}

/// `instr` with its shape changed by `change`.
fn changed(mut instr: Instr, change: impl FnOnce(&mut Instr)) -> Instr {
    change(&mut instr);
    instr
}

#[test]
fn the_fused_element_instructions_encode_as_numbers_29_and_30_with_their_fields_in_order() {
    let load = Instr::LoadElement {
        ty: Elementary::Real,
        dst: Operand::Frame(40),
        array: Operand::Instance(36),
        index: Operand::Instance(32),
        index_ty: Elementary::Dint,
        low: -2,
        count: 10,
        stride: 8,
        offset: 4,
    };
    // Postcard: the variant as a varint, each field in order; operands are (region, offset),
    // the signed low bound zigzag-encoded (-2 is 3).
    let bytes = postcard::to_allocvec(&load).unwrap();
    assert_eq!(bytes, [29, 13, 2, 40, 1, 36, 1, 32, 7, 3, 10, 8, 4]);
    let store = Instr::StoreElement {
        ty: Elementary::Ulint,
        array: Operand::Global(300),
        index: Operand::Frame(0),
        index_ty: Elementary::Ulint,
        low: 1,
        count: 2,
        stride: 8,
        offset: 0,
        src: Operand::Const(8),
    };
    let bytes = postcard::to_allocvec(&store).unwrap();
    assert_eq!(bytes, [30, 12, 0, 0xac, 0x02, 2, 0, 12, 2, 2, 8, 0, 3, 8]);
}

#[test]
fn images_with_fused_element_instructions_round_trip() {
    let mut image = small_image();
    image.pous[0].code[1] = load();
    image.pous[0].code.insert(2, store());
    // The inserted instruction moved the jump's target and the code after it by one.
    image.pous[0].code[4] = Instr::JumpIfNot {
        cond: Operand::Instance(8),
        target: 6,
    };
    assert_eq!(ProgramImage::decode(&image.encode()), Ok(image));
}

#[test]
fn a_fused_element_access_of_no_elements_is_refused() {
    for instr in [load(), store()] {
        let instr = changed(instr, |instr| match instr {
            Instr::LoadElement { count, .. } | Instr::StoreElement { count, .. } => *count = 0,
            _ => unreachable!(),
        });
        let message = invalid_message(&with_instruction(instr));
        assert_contains(&message, "POU 'main'");
        assert_contains(&message, "instruction 1: an array of no elements");
    }
}

#[test]
fn a_fused_element_access_with_an_index_that_is_not_an_integer_is_refused() {
    for (instr, index_type) in [
        (load(), Elementary::Real),
        (store(), Elementary::Bool),
        (load(), Elementary::Time),
    ] {
        let instr = changed(instr, |instr| match instr {
            Instr::LoadElement { index_ty, .. } | Instr::StoreElement { index_ty, .. } => {
                *index_ty = index_type;
            }
            _ => unreachable!(),
        });
        let message = invalid_message(&with_instruction(instr));
        assert_contains(
            &message,
            &format!(
                "instruction 1: an index of type {}, which is not an integer",
                index_type.name()
            ),
        );
    }
    // Every integer and bit string wider than BOOL is an index type.
    for index_type in [Elementary::Byte, Elementary::Usint, Elementary::Lword] {
        let image = with_instruction(changed(load(), |instr| {
            if let Instr::LoadElement { index_ty, .. } = instr {
                *index_ty = index_type;
            }
        }));
        assert_eq!(ProgramImage::decode(&image.encode()), Ok(image));
    }
}

#[test]
fn an_array_extending_past_its_region_is_refused() {
    // Three elements of 4 bytes fill the instance of 12; a fourth does not fit.
    for instr in [load(), store()] {
        let instr = changed(instr, |instr| match instr {
            Instr::LoadElement { count, .. } | Instr::StoreElement { count, .. } => *count = 4,
            _ => unreachable!(),
        });
        let message = invalid_message(&with_instruction(instr));
        assert_contains(
            &message,
            "instruction 1: operand Instance(0) of 16 bytes is outside its region",
        );
    }
    // An array starting inside the region and reaching past it.
    let instr = changed(load(), |instr| {
        if let Instr::LoadElement { array, .. } = instr {
            *array = Operand::Instance(4);
        }
    });
    assert_contains(
        &invalid_message(&with_instruction(instr)),
        "operand Instance(4) of 12 bytes is outside its region",
    );
}

#[test]
fn an_array_extent_that_overflows_is_refused_without_wrapping() {
    // `count * stride` wraps a u64 to a small number; computed in u64 with a check it is
    // refused instead of passing as 0 bytes.
    let instr = changed(store(), |instr| {
        if let Instr::StoreElement { count, stride, .. } = instr {
            *count = 1 << 62;
            *stride = 8;
        }
    });
    assert_contains(
        &invalid_message(&with_instruction(instr)),
        "instruction 1: the array Instance(0) of 4611686018427387904 elements of 8 bytes is larger than any region",
    );
    let instr = changed(load(), |instr| {
        if let Instr::LoadElement { count, stride, .. } = instr {
            *count = u64::from(u32::MAX);
            *stride = 4;
        }
    });
    assert_contains(
        &invalid_message(&with_instruction(instr)),
        "is larger than any region",
    );
}

#[test]
fn a_value_not_inside_its_element_is_refused() {
    // A DINT at offset 1 of a 4-byte element, and an LINT in a 4-byte element.
    for instr in [
        changed(load(), |instr| {
            if let Instr::LoadElement { offset, .. } = instr {
                *offset = 1;
            }
        }),
        changed(store(), |instr| {
            if let Instr::StoreElement { offset, .. } = instr {
                *offset = 1;
            }
        }),
    ] {
        assert_contains(
            &invalid_message(&with_instruction(instr)),
            "instruction 1: a DINT at offset 1 does not fit an element of 4 bytes",
        );
    }
    let instr = changed(load(), |instr| {
        if let Instr::LoadElement { ty, .. } = instr {
            *ty = Elementary::Lint;
        }
    });
    assert_contains(
        &invalid_message(&with_instruction(instr)),
        "instruction 1: a LINT at offset 0 does not fit an element of 4 bytes",
    );
}

#[test]
fn a_fused_element_access_with_its_index_value_or_result_outside_its_region_is_refused() {
    // `main`'s frame has 8 bytes: an index or a value of 4 bytes at 6 does not fit.
    let cases = [
        (
            changed(load(), |instr| {
                if let Instr::LoadElement { index, .. } = instr {
                    *index = Operand::Frame(6);
                }
            }),
            "operand Frame(6) of 4 bytes is outside its region",
        ),
        (
            changed(load(), |instr| {
                if let Instr::LoadElement { dst, .. } = instr {
                    *dst = Operand::Frame(6);
                }
            }),
            "operand Frame(6) of 4 bytes is outside its region",
        ),
        (
            changed(store(), |instr| {
                if let Instr::StoreElement { src, .. } = instr {
                    *src = Operand::Const(1000);
                }
            }),
            "operand Const(1000) of 4 bytes is outside its region",
        ),
        (
            changed(store(), |instr| {
                if let Instr::StoreElement {
                    index, index_ty, ..
                } = instr
                {
                    *index = Operand::Frame(4);
                    *index_ty = Elementary::Lint;
                }
            }),
            "operand Frame(4) of 8 bytes is outside its region",
        ),
    ];
    for (instr, part) in cases {
        let message = invalid_message(&with_instruction(instr));
        assert_contains(&message, "instruction 1");
        assert_contains(&message, part);
    }
}
