use super::*;
use crate::code::{BinaryOp, CompareOp, Transfer};
use crate::image::{Layout, PouKind};
use crate::{Elementary, TypeDef};

/// An image of one program with a frame of 8 bytes and an instance of 12, on stacks of 64.
fn image() -> ProgramImage {
    ProgramImage {
        types: vec![TypeDef::Elementary(Elementary::Dint)],
        layout: Layout {
            data_size: 12,
            stack_size: 64,
            ..Layout::default()
        },
        pous: vec![Pou {
            name: "Main".to_owned(),
            kind: PouKind::Program,
            frame_size: 8,
            frame_init: Vec::new(),
            instance_size: 12,
            code: vec![Instr::Return],
            lines: Vec::new(),
        }],
        constants: vec![100, 0, 0, 0],
        ..ProgramImage::default()
    }
}

/// `Main.count > 100` with its result at frame offset 8, the scratch area's first byte.
fn count_above_100() -> BreakCondition {
    BreakCondition {
        scratch_bytes: 4,
        init: vec![0],
        code: vec![Instr::Compare {
            op: CompareOp::Gt,
            ty: Elementary::Dint,
            dst: Operand::Frame(8),
            a: Operand::Instance(0),
            b: Operand::Const(0),
        }],
        result: 8,
    }
}

#[track_caller]
fn refused(condition: &BreakCondition) -> ConditionError {
    match image().verify_condition(0, condition) {
        Ok(()) => panic!("a hostile condition was accepted: {condition:?}"),
        Err(error) => error,
    }
}

#[track_caller]
fn refused_at(condition: &BreakCondition, instruction: usize, part: &str) {
    match refused(condition) {
        ConditionError::Refused {
            instruction: found,
            reason,
        } => {
            assert_eq!(found, instruction, "{reason}");
            assert!(
                reason.contains(part),
                "{reason:?} does not contain {part:?}"
            );
        }
        other => panic!("expected a refused instruction, got: {other}"),
    }
}

#[test]
fn a_comparison_of_an_instance_variable_into_its_scratch_area_is_accepted() {
    let condition = count_above_100();
    assert_eq!(image().verify_condition(0, &condition), Ok(()));
    let bytes = condition.encode();
    assert_eq!(BreakCondition::decode(&bytes), Ok(condition));
}

#[test]
fn bytes_that_are_no_condition_or_have_bytes_left_over_are_refused() {
    let mut bytes = count_above_100().encode();
    bytes.push(0);
    assert_eq!(
        BreakCondition::decode(&bytes),
        Err(ConditionError::Malformed("1 bytes left over".to_owned()))
    );
    for end in 0..bytes.len() - 1 {
        assert!(
            BreakCondition::decode(&bytes[..end]).is_err(),
            "cut to {end} bytes"
        );
    }
}

#[test]
fn a_condition_for_a_missing_pou_is_refused() {
    assert_eq!(
        image().verify_condition(3, &count_above_100()),
        Err(ConditionError::UnknownPou(3))
    );
}

#[test]
fn calls_stores_returns_and_native_blocks_are_refused() {
    let hostile = [
        Instr::Store {
            size: 4,
            ptr: Operand::Frame(8),
            src: Operand::Const(0),
        },
        Instr::CallFunction {
            pou: 0,
            instance: None,
            inputs: vec![Transfer {
                caller: Operand::Frame(8),
                callee_offset: 0,
                size: 1,
            }],
            outputs: Vec::new(),
        },
        Instr::CallBlock {
            pou: 0,
            instance: Operand::Global(0),
            indirect: false,
        },
        Instr::Return,
        Instr::Native {
            block: "MC_Power".to_owned(),
        },
        // Writing an element of the program's array is a store like any other.
        Instr::StoreElement {
            ty: Elementary::Dint,
            array: Operand::Instance(0),
            index: Operand::Const(0),
            index_ty: Elementary::Dint,
            low: 100,
            count: 3,
            stride: 4,
            offset: 0,
            src: Operand::Const(0),
        },
    ];
    for instr in hostile {
        let mut condition = count_above_100();
        condition.code.push(instr);
        refused_at(&condition, 1, "not allowed in a condition");
    }
}

#[test]
fn an_element_read_into_the_scratch_area_is_accepted_and_one_outside_it_refused() {
    // `Main.values[Main.values[100]] > 100` over the instance's three DINTs from index 100.
    let read = |dst| Instr::LoadElement {
        ty: Elementary::Dint,
        dst,
        array: Operand::Instance(0),
        index: Operand::Instance(0),
        index_ty: Elementary::Dint,
        low: 100,
        count: 3,
        stride: 4,
        offset: 0,
    };
    let mut condition = count_above_100();
    condition.scratch_bytes = 8;
    condition.code = vec![
        read(Operand::Frame(12)),
        Instr::Compare {
            op: CompareOp::Gt,
            ty: Elementary::Dint,
            dst: Operand::Frame(8),
            a: Operand::Frame(12),
            b: Operand::Const(0),
        },
    ];
    assert_eq!(image().verify_condition(0, &condition), Ok(()));
    condition.code[0] = read(Operand::Instance(4));
    refused_at(
        &condition,
        0,
        "writes Instance(4) (4 bytes) outside its scratch area",
    );
}

#[test]
fn a_write_outside_the_scratch_area_is_refused() {
    for dst in [
        Operand::Instance(0),
        Operand::Global(0),
        Operand::Frame(4),
        Operand::Output(0),
        Operand::Frame(10),
    ] {
        let mut condition = count_above_100();
        condition.code.insert(
            0,
            Instr::Move {
                ty: Elementary::Dint,
                dst,
                src: Operand::Const(0),
            },
        );
        refused_at(&condition, 0, "outside its scratch area");
    }
}

#[test]
fn a_backward_jump_or_a_jump_to_itself_is_refused() {
    let mut condition = count_above_100();
    condition.code.push(Instr::JumpIf {
        cond: Operand::Frame(8),
        target: 0,
    });
    refused_at(&condition, 1, "jumps back to 0");
    let mut condition = count_above_100();
    condition.code.push(Instr::Jump { target: 1 });
    refused_at(&condition, 1, "jumps only forward");
}

#[test]
fn operands_are_checked_as_the_image_checks_its_own_code() {
    let mut condition = count_above_100();
    condition.code.push(Instr::Binary {
        op: BinaryOp::Add,
        ty: Elementary::Dint,
        dst: Operand::Frame(8),
        a: Operand::Instance(10),
        b: Operand::Const(0),
    });
    refused_at(&condition, 1, "outside its region");
    let mut condition = count_above_100();
    condition.code.push(Instr::Jump { target: 9 });
    refused_at(&condition, 1, "outside the code");
}

#[test]
fn a_result_initial_bytes_or_scratch_area_that_do_not_fit_are_refused() {
    let mut condition = count_above_100();
    condition.result = 4;
    assert!(matches!(refused(&condition), ConditionError::Scratch(_)));
    let mut condition = count_above_100();
    condition.result = 12;
    assert!(matches!(refused(&condition), ConditionError::Scratch(_)));
    let mut condition = count_above_100();
    condition.init = vec![0; 5];
    assert!(matches!(refused(&condition), ConditionError::Scratch(_)));
    let mut condition = count_above_100();
    condition.scratch_bytes = 57;
    assert!(matches!(refused(&condition), ConditionError::Scratch(_)));
}
