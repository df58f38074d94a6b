//! Decoding refuses every bad image with an error and never panics: truncated, corrupted,
//! wrong-version and hostile images (`docs/program-image.md` §1 "Safe to load"), and the
//! encoding of a small image is pinned so an accidental format change fails here.

use std::fmt::Write as _;

use expect_test::expect_file;
use program_image::{
    BinaryOp, DebugInfo, Elementary, FORMAT_VERSION, FrameVariable, FrameVariableKind, ImageError,
    Info, InitRun, InitialValues, Instr, Layout, LineEntry, MAGIC, MAX_REGION_BYTES, ModbusRange,
    ModbusTable, Operand, Pou, PouDebug, PouKind, ProgramCall, ProgramImage, Region, RetainLayout,
    StructKind, Symbol, SymbolFlags, Task, TaskKind, TypeDef,
};
use proptest::prelude::*;
use sha2::{Digest, Sha256};

#[path = "decode/element.rs"]
mod element;
#[path = "decode/modbus_master.rs"]
mod modbus_master;

/// A small image of every section: a program `main` that adds two DINTs in a loop and calls a
/// function, one task, a retained variable and a line table.
fn small_image() -> ProgramImage {
    let main = Pou {
        name: "main".to_owned(),
        kind: PouKind::Program,
        frame_size: 8,
        frame_init: Vec::new(),
        instance_size: 12,
        code: vec![
            Instr::Binary {
                op: BinaryOp::Add,
                ty: Elementary::Dint,
                dst: Operand::Frame(0),
                a: Operand::Instance(0),
                b: Operand::Const(0),
            },
            Instr::Move {
                ty: Elementary::Dint,
                dst: Operand::Instance(0),
                src: Operand::Frame(0),
            },
            Instr::Compare {
                op: program_image::CompareOp::Lt,
                ty: Elementary::Dint,
                dst: Operand::Instance(8),
                a: Operand::Instance(0),
                b: Operand::Const(4),
            },
            Instr::JumpIfNot {
                cond: Operand::Instance(8),
                target: 5,
            },
            Instr::CallFunction {
                pou: 1,
                instance: None,
                inputs: vec![program_image::Transfer {
                    caller: Operand::Instance(0),
                    callee_offset: 0,
                    size: 4,
                }],
                outputs: vec![program_image::Transfer {
                    caller: Operand::Instance(4),
                    callee_offset: 4,
                    size: 4,
                }],
            },
            Instr::Return,
        ],
        lines: vec![LineEntry {
            index: 0,
            file: 0,
            line: 7,
        }],
    };
    let double = Pou {
        name: "double".to_owned(),
        kind: PouKind::Function,
        frame_size: 8,
        frame_init: vec![InitRun {
            offset: 4,
            bytes: vec![0, 0, 0, 0],
        }],
        instance_size: 0,
        code: vec![
            Instr::Binary {
                op: BinaryOp::Add,
                ty: Elementary::Dint,
                dst: Operand::Frame(4),
                a: Operand::Frame(0),
                b: Operand::Frame(0),
            },
            Instr::Return,
        ],
        lines: Vec::new(),
    };
    ProgramImage {
        types: vec![
            TypeDef::Elementary(Elementary::Dint),
            TypeDef::Elementary(Elementary::Bool),
            TypeDef::Struct {
                name: "main".to_owned(),
                kind: StructKind::Program,
                size: 12,
                members: vec![
                    program_image::Member {
                        name: "count".to_owned(),
                        ty: 0,
                        offset: 0,
                        located: None,
                        flags: SymbolFlags::RETAIN,
                    },
                    program_image::Member {
                        name: "twice".to_owned(),
                        ty: 0,
                        offset: 4,
                        located: None,
                        flags: 0,
                    },
                    program_image::Member {
                        name: "running".to_owned(),
                        ty: 1,
                        offset: 8,
                        located: None,
                        flags: 0,
                    },
                ],
            },
        ],
        layout: Layout {
            data_size: 12,
            input_size: 2,
            output_size: 2,
            memory_size: 0,
            stack_size: 64,
        },
        initial: InitialValues {
            data: vec![InitRun {
                offset: 0,
                bytes: vec![1, 0, 0, 0],
            }],
            input: Vec::new(),
            output: Vec::new(),
            memory: Vec::new(),
        },
        symbols: vec![
            Symbol {
                path: "main.count".to_owned(),
                ty: 0,
                region: Region::Data,
                offset: 0,
                bit: None,
                flags: SymbolFlags(SymbolFlags::RETAIN),
            },
            Symbol {
                path: "main.twice".to_owned(),
                ty: 0,
                region: Region::Data,
                offset: 4,
                bit: None,
                flags: SymbolFlags(0),
            },
            Symbol {
                path: "start".to_owned(),
                ty: 1,
                region: Region::Input,
                offset: 1,
                bit: Some(3),
                flags: SymbolFlags(SymbolFlags::LOCATED | SymbolFlags::GLOBAL),
            },
        ],
        pous: vec![main, double],
        constants: vec![1, 0, 0, 0, 100, 0, 0, 0],
        tasks: vec![Task {
            name: "MainTask".to_owned(),
            kind: TaskKind::Cyclic,
            interval_ns: 10_000_000,
            trigger: None,
            priority: 1,
            watchdog_ns: 0,
            watchdog_sensitivity: 1,
            programs: vec![ProgramCall {
                pou: 0,
                instance_offset: 0,
            }],
        }],
        retain: RetainLayout {
            retain: vec![(0, 4)],
            persistent: Vec::new(),
        },
        sources: vec!["main.st".to_owned()],
        info: Info {
            project: "small".to_owned(),
            compiler: "test".to_owned(),
        },
        modbus_map: Some(vec![ModbusRange {
            table: ModbusTable::HoldingRegisters,
            start: 100,
            count: 1,
            region: Region::Output,
            byte_offset: 0,
            words_per_value: 1,
        }]),
        motion: None,
        debug: None,
        modbus_master: None,
    }
}

/// A section of the container: id, flags and payload.
#[derive(Clone, Debug, PartialEq)]
struct Section {
    id: u16,
    flags: u16,
    payload: Vec<u8>,
}

/// The sections of well-formed image bytes.
#[track_caller]
fn sections(bytes: &[u8]) -> Vec<Section> {
    let count = u32::from_le_bytes([bytes[12], bytes[13], bytes[14], bytes[15]]);
    let mut rest = &bytes[16..bytes.len() - 32];
    let mut sections = Vec::new();
    for _ in 0..count {
        let id = u16::from_le_bytes([rest[0], rest[1]]);
        let flags = u16::from_le_bytes([rest[2], rest[3]]);
        let length = u32::from_le_bytes([rest[4], rest[5], rest[6], rest[7]]) as usize;
        sections.push(Section {
            id,
            flags,
            payload: rest[8..8 + length].to_vec(),
        });
        rest = &rest[8 + length..];
    }
    assert!(rest.is_empty());
    sections
}

/// Image bytes of these sections with a correct header and hash.
fn container(sections: &[Section]) -> Vec<u8> {
    let mut bytes = MAGIC.to_vec();
    bytes.extend_from_slice(&FORMAT_VERSION.to_le_bytes());
    bytes.extend_from_slice(&0u16.to_le_bytes());
    bytes.extend_from_slice(&(sections.len() as u32).to_le_bytes());
    for section in sections {
        bytes.extend_from_slice(&section.id.to_le_bytes());
        bytes.extend_from_slice(&section.flags.to_le_bytes());
        bytes.extend_from_slice(&(section.payload.len() as u32).to_le_bytes());
        bytes.extend_from_slice(&section.payload);
    }
    rehash(bytes)
}

/// `content` (an image without its trailer) with the trailer its hash gives.
fn rehash(mut content: Vec<u8>) -> Vec<u8> {
    let hash = Sha256::digest(&content);
    content.extend_from_slice(&hash);
    content
}

/// The bytes of `image` with their last 32 bytes replaced by the hash of the others.
fn with_correct_hash(bytes: &[u8]) -> Vec<u8> {
    rehash(bytes[..bytes.len().saturating_sub(32)].to_vec())
}

/// The error decoding `bytes` gives, which must exist.
#[track_caller]
fn refused(bytes: &[u8]) -> ImageError {
    match ProgramImage::decode(bytes) {
        Ok(_) => panic!("a bad image was accepted"),
        Err(error) => error,
    }
}

/// The message of the `Invalid` error that decoding the encoded `image` gives.
#[track_caller]
fn invalid_message(image: &ProgramImage) -> String {
    match refused(&image.encode()) {
        ImageError::Invalid(message) => message,
        other => panic!("expected an inconsistent image, got: {other}"),
    }
}

#[track_caller]
fn assert_contains(text: &str, part: &str) {
    assert!(text.contains(part), "{text:?} does not contain {part:?}");
}

/// The section of `bytes` with id `id` replaced by `payload`, re-hashed.
fn with_payload(bytes: &[u8], id: u16, payload: Vec<u8>) -> Vec<u8> {
    let mut all = sections(bytes);
    let Some(section) = all.iter_mut().find(|s| s.id == id) else {
        panic!("no section {id}");
    };
    section.payload = payload;
    container(&all)
}

#[test]
fn the_small_image_round_trips() {
    let image = small_image();
    assert_eq!(ProgramImage::decode(&image.encode()), Ok(image));
}

#[test]
fn the_encoding_of_a_small_image_is_pinned() {
    // A change of these bytes is a change of the format: it needs a new format version or,
    // for an addition, an optional section (docs/program-image.md §13).
    let bytes = small_image().encode();
    let mut dump = String::new();
    let hex = |bytes: &[u8]| bytes.iter().map(|b| format!("{b:02x}")).collect::<String>();
    writeln!(dump, "header {}", hex(&bytes[..16])).unwrap();
    for section in sections(&bytes) {
        writeln!(
            dump,
            "section {} flags {} length {}: {}",
            section.id,
            section.flags,
            section.payload.len(),
            hex(&section.payload)
        )
        .unwrap();
    }
    writeln!(dump, "trailer {}", hex(&bytes[bytes.len() - 32..])).unwrap();
    expect_file!["encoding/small_image.txt"].assert_eq(&dump);
}

#[test]
fn an_image_cut_short_at_any_length_is_refused() {
    let bytes = small_image().encode();
    for length in 0..bytes.len() {
        refused(&bytes[..length]);
    }
}

#[test]
fn an_image_cut_short_and_rehashed_at_any_length_is_refused() {
    // Re-hashing gets past the hash check, so the section reader itself sees every cut.
    let bytes = small_image().encode();
    let content = &bytes[..bytes.len() - 32];
    for length in 0..content.len() {
        refused(&rehash(content[..length].to_vec()));
    }
}

#[test]
fn every_single_byte_corruption_is_refused() {
    let bytes = small_image().encode();
    for at in 0..bytes.len() {
        for flip in [0x01, 0x80, 0xff] {
            let mut corrupted = bytes.clone();
            corrupted[at] ^= flip;
            let error = refused(&corrupted);
            if at >= 16 {
                assert_eq!(error, ImageError::HashMismatch, "byte {at} ^ {flip:#x}");
            }
        }
    }
}

#[test]
fn bytes_that_do_not_start_with_the_magic_are_refused() {
    let mut bytes = small_image().encode();
    bytes[..8].copy_from_slice(b"RIVETIMH");
    assert_eq!(refused(&bytes), ImageError::BadMagic);
    assert_eq!(refused(b"not an image"), ImageError::TooShort(12));
}

#[test]
fn a_newer_format_version_is_refused_with_both_versions() {
    let mut bytes = small_image().encode();
    bytes[8..10].copy_from_slice(&(FORMAT_VERSION + 1).to_le_bytes());
    let bytes = with_correct_hash(&bytes);
    let error = refused(&bytes);
    assert_eq!(
        error,
        ImageError::WrongVersion {
            found: FORMAT_VERSION + 1
        }
    );
    let message = error.to_string();
    assert_contains(&message, &format!("format version {}", FORMAT_VERSION + 1));
    assert_contains(&message, &format!("reads version {FORMAT_VERSION}"));
}

#[test]
fn unknown_header_flags_are_refused() {
    let mut bytes = small_image().encode();
    bytes[10..12].copy_from_slice(&4u16.to_le_bytes());
    let bytes = with_correct_hash(&bytes);
    assert_eq!(refused(&bytes), ImageError::UnknownFlags(4));
}

#[test]
fn an_unknown_critical_section_is_refused() {
    let mut all = sections(&small_image().encode());
    all.push(Section {
        id: 200,
        flags: 1,
        payload: vec![1, 2, 3],
    });
    let error = refused(&container(&all));
    assert_eq!(error, ImageError::UnknownCriticalSection { id: 200 });
    assert_contains(&error.to_string(), "section 200");
}

#[test]
fn an_unknown_optional_section_is_skipped() {
    let image = small_image();
    let mut all = sections(&image.encode());
    all.push(Section {
        id: 200,
        flags: 0,
        payload: vec![0xff; 40],
    });
    assert_eq!(ProgramImage::decode(&container(&all)), Ok(image));
}

#[test]
fn repeated_missing_and_unordered_sections_are_refused() {
    let all = sections(&small_image().encode());
    let mut twice = all.clone();
    twice.insert(1, all[0].clone());
    assert_eq!(
        refused(&container(&twice)),
        ImageError::SectionOrder { id: 1 }
    );
    let mut swapped = all.clone();
    swapped.swap(2, 3);
    assert_eq!(
        refused(&container(&swapped)),
        ImageError::SectionOrder { id: 3 }
    );
    let without_code: Vec<Section> = all.iter().filter(|s| s.id != 5).cloned().collect();
    assert_eq!(
        refused(&container(&without_code)),
        ImageError::MissingSection("code")
    );
    // The optional sections may be left out (the line tables name files of `sources`, so
    // an image without that section has none).
    let mut image = small_image();
    image.pous[0].lines.clear();
    let all = sections(&image.encode());
    let without_optional: Vec<Section> = all.iter().filter(|s| s.id <= 8).cloned().collect();
    let decoded = ProgramImage::decode(&container(&without_optional)).unwrap();
    assert!(decoded.sources.is_empty() && decoded.info == Info::default());
}

#[test]
fn a_section_longer_than_the_image_or_bytes_after_the_last_are_refused() {
    let bytes = small_image().encode();
    let mut long = bytes[..bytes.len() - 32].to_vec();
    // The first section's length, made one longer than everything that follows.
    let remaining = (long.len() - 24) as u32;
    long[20..24].copy_from_slice(&(remaining + 1).to_le_bytes());
    assert!(matches!(
        refused(&rehash(long)),
        ImageError::SectionTruncated { id: 1, .. }
    ));
    let mut trailing = bytes[..bytes.len() - 32].to_vec();
    trailing.extend_from_slice(&[0, 0, 0]);
    assert_eq!(refused(&rehash(trailing)), ImageError::TrailingBytes(3));
}

#[test]
fn a_section_with_bytes_left_over_is_refused_by_name() {
    let bytes = small_image().encode();
    let mut layout = sections(&bytes)[1].payload.clone();
    layout.push(0);
    let error = refused(&with_payload(&bytes, 2, layout));
    assert_eq!(
        error,
        ImageError::Malformed {
            section: "layout",
            message: "1 bytes left over".to_owned()
        }
    );
}

#[test]
fn an_operand_outside_its_region_is_refused() {
    let mut image = small_image();
    image.pous[0].code[1] = Instr::Move {
        ty: Elementary::Dint,
        dst: Operand::Instance(10),
        src: Operand::Frame(0),
    };
    let message = invalid_message(&image);
    assert_contains(&message, "POU 'main'");
    assert_contains(&message, "instruction 1");
    assert_contains(&message, "Instance(10) of 4 bytes is outside its region");

    let mut image = small_image();
    image.pous[1].code[0] = Instr::Binary {
        op: BinaryOp::Add,
        ty: Elementary::Dint,
        dst: Operand::Frame(4),
        a: Operand::Frame(0),
        b: Operand::Const(u32::MAX),
    };
    let message = invalid_message(&image);
    assert_contains(&message, "POU 'double'");
    assert_contains(
        &message,
        "Const(4294967295) of 4 bytes is outside its region",
    );

    let mut image = small_image();
    image.pous[0].code[0] = Instr::Move {
        ty: Elementary::Lint,
        dst: Operand::Output(0),
        src: Operand::Input(0),
    };
    assert_contains(
        &invalid_message(&image),
        "Output(0) of 8 bytes is outside its region",
    );
}

#[test]
fn a_clock_read_is_checked_for_the_width_of_its_time() {
    // `main`'s instance has 12 bytes: a TIME fits at offset 8, an LTIME does not.
    let mut image = small_image();
    image.pous[0].code[1] = Instr::Clock {
        long: false,
        dst: Operand::Instance(8),
    };
    assert_eq!(ProgramImage::decode(&image.encode()), Ok(image.clone()));
    image.pous[0].code[1] = Instr::Clock {
        long: true,
        dst: Operand::Instance(8),
    };
    let message = invalid_message(&image);
    assert_contains(&message, "instruction 1");
    assert_contains(&message, "Instance(8) of 8 bytes is outside its region");
}

#[test]
fn a_jump_outside_the_code_is_refused() {
    let mut image = small_image();
    image.pous[0].code[3] = Instr::JumpIfNot {
        cond: Operand::Instance(8),
        target: 6,
    };
    let message = invalid_message(&image);
    assert_contains(&message, "POU 'main'");
    assert_contains(&message, "instruction 3: jump target 6 is outside the code");
}

#[test]
fn a_call_of_a_missing_pou_is_refused() {
    let mut image = small_image();
    if let Instr::CallFunction { pou, .. } = &mut image.pous[0].code[4] {
        *pou = 7;
    }
    assert_contains(
        &invalid_message(&image),
        "instruction 4: calls POU 7, which does not exist",
    );
}

#[test]
fn a_call_of_a_program_as_a_function_is_refused() {
    let mut image = small_image();
    if let Instr::CallFunction { pou, .. } = &mut image.pous[0].code[4] {
        *pou = 0;
    }
    assert_contains(
        &invalid_message(&image),
        "instruction 4: calls 'main' as a function",
    );
}

#[test]
fn a_parameter_outside_the_callee_frame_is_refused() {
    let mut image = small_image();
    if let Instr::CallFunction { outputs, .. } = &mut image.pous[0].code[4] {
        outputs[0].callee_offset = 6;
    }
    assert_contains(
        &invalid_message(&image),
        "a parameter lies outside the frame of 'double'",
    );
}

#[test]
fn a_type_referring_to_a_later_type_is_refused() {
    let mut image = small_image();
    image.types.push(TypeDef::Array {
        element: 3,
        dims: vec![(1, 2)],
    });
    assert_contains(
        &invalid_message(&image),
        "type 3 refers to a type that does not come before it",
    );
    let mut image = small_image();
    if let TypeDef::Struct { members, .. } = &mut image.types[2] {
        members[0].ty = 2;
    }
    assert_contains(
        &invalid_message(&image),
        "type 2 refers to a type that does not come before it",
    );
}

#[test]
fn a_symbol_outside_its_region_or_without_a_type_is_refused() {
    let mut image = small_image();
    image.symbols[1].offset = 9;
    assert_contains(
        &invalid_message(&image),
        "symbol 'main.twice' lies outside its region",
    );
    let mut image = small_image();
    image.symbols[2].offset = 2;
    assert_contains(
        &invalid_message(&image),
        "symbol 'start' lies outside its region",
    );
    let mut image = small_image();
    image.symbols[0].ty = 3;
    assert_contains(
        &invalid_message(&image),
        "symbol 0 ('main.count') has no type",
    );
}

#[test]
fn a_task_calling_a_non_program_is_refused() {
    let mut image = small_image();
    image.tasks[0].programs[0].pou = 1;
    assert_contains(
        &invalid_message(&image),
        "task 'MainTask' calls a POU that is not a program",
    );
    let mut image = small_image();
    image.tasks[0].programs[0].pou = 2;
    assert_contains(
        &invalid_message(&image),
        "task 'MainTask' calls a POU that is not a program",
    );
    let mut image = small_image();
    image.tasks[0].programs[0].instance_offset = 4;
    assert_contains(
        &invalid_message(&image),
        "task 'MainTask' calls 'main' on an instance outside the data region",
    );
}

#[test]
fn a_region_larger_than_the_limit_is_refused() {
    let mut image = small_image();
    image.layout.data_size = MAX_REGION_BYTES + 1;
    assert_contains(
        &invalid_message(&image),
        &format!(
            "layout.data_size is {} bytes, more than {MAX_REGION_BYTES}",
            MAX_REGION_BYTES + 1
        ),
    );
    let mut image = small_image();
    image.layout.stack_size = u32::MAX;
    assert_contains(&invalid_message(&image), "layout.stack_size is 4294967295");
}

#[test]
fn task_stacks_larger_than_the_limit_together_are_refused() {
    // Each task is a few bytes of the image but gets a stack of `stack_size` bytes.
    let mut image = small_image();
    image.layout.stack_size = MAX_REGION_BYTES;
    image.tasks.push(image.tasks[0].clone());
    assert_contains(
        &invalid_message(&image),
        &format!(
            "2 tasks with a stack of {MAX_REGION_BYTES} bytes each need {} bytes",
            2 * u64::from(MAX_REGION_BYTES)
        ),
    );
    image.tasks.pop();
    assert_eq!(ProgramImage::decode(&image.encode()), Ok(image));
}

#[test]
fn initial_values_retain_ranges_and_frames_outside_their_region_are_refused() {
    let mut image = small_image();
    image.initial.data[0].offset = 10;
    assert_contains(
        &invalid_message(&image),
        "an initial value lies outside the data region",
    );
    let mut image = small_image();
    image.retain.retain[0] = (8, 8);
    assert_contains(
        &invalid_message(&image),
        "a retain range lies outside the data region",
    );
    let mut image = small_image();
    image.pous[1].frame_size = 65;
    assert_contains(
        &invalid_message(&image),
        "POU 'double': its frame of 65 bytes exceeds the stack",
    );
    let mut image = small_image();
    image.pous[0].lines[0].file = 1;
    assert_contains(
        &invalid_message(&image),
        "POU 'main': its line table names an unknown file",
    );
}

/// A postcard varint of `value`.
fn varint(mut value: u64) -> Vec<u8> {
    let mut bytes = Vec::new();
    loop {
        let low = (value & 0x7f) as u8;
        value >>= 7;
        if value == 0 {
            bytes.push(low);
            return bytes;
        }
        bytes.push(low | 0x80);
    }
}

#[test]
fn a_huge_length_prefix_inside_a_section_fails_without_allocating_it() {
    // Each prefix announces about four billion elements in a payload of a few bytes. Were the
    // decoder to reserve what the prefix says (tens of gigabytes for instructions), the test
    // process would abort; it must instead run out of bytes and say so.
    let bytes = small_image().encode();
    let huge = varint(u64::from(u32::MAX));
    let cases: [(u16, &str, Vec<u8>); 4] = [
        (1, "types", huge.clone()),
        (6, "constants", [huge.clone(), vec![1, 2, 3]].concat()),
        (
            5,
            "code",
            // One POU whose name claims four billion bytes.
            [varint(1), huge.clone(), b"main".to_vec()].concat(),
        ),
        (
            5,
            "code",
            // One POU `m`, a program, no frame, no frame initialisation, no instance, and an
            // instruction list of four billion entries.
            [vec![1, 1, b'm', 0, 0, 0, 0], huge.clone(), vec![0]].concat(),
        ),
    ];
    for (id, name, payload) in cases {
        match refused(&with_payload(&bytes, id, payload)) {
            ImageError::Malformed { section, .. } => assert_eq!(section, name),
            other => panic!("section {name}: expected a malformed section, got {other}"),
        }
    }
    // A length prefix beyond u32 in a u32 field is refused too.
    let mut layout = varint(u64::MAX);
    layout.extend_from_slice(&[0; 4]);
    assert!(matches!(
        refused(&with_payload(&bytes, 2, layout)),
        ImageError::Malformed {
            section: "layout",
            ..
        }
    ));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn random_bytes_never_panic(bytes in proptest::collection::vec(any::<u8>(), 0..512)) {
        let _ = ProgramImage::decode(&bytes);
        let _ = ProgramImage::decode(&with_correct_hash(&bytes));
        let mut with_header = MAGIC.to_vec();
        with_header.extend_from_slice(&[1, 0, 0, 0]);
        with_header.extend_from_slice(&bytes);
        let _ = ProgramImage::decode(&with_correct_hash(&with_header));
    }

    #[test]
    fn mutations_of_a_valid_image_never_panic(
        edits in proptest::collection::vec((any::<proptest::sample::Index>(), any::<u8>()), 1..8),
        cut in any::<proptest::sample::Index>(),
    ) {
        let mut bytes = small_image().encode();
        for (at, byte) in &edits {
            let at = at.index(bytes.len());
            bytes[at] = *byte;
        }
        prop_assert!(ProgramImage::decode(&bytes).is_err() || bytes == small_image().encode());
        // Re-hashed, the mutation reaches the section decoders and the verifier.
        let rehashed = with_correct_hash(&bytes);
        let _ = ProgramImage::decode(&rehashed);
        let _ = ProgramImage::decode(&rehashed[..cut.index(rehashed.len() + 1)]);
    }
}

/// The small image with a debug section: `double`'s parameter and result in its frame.
fn with_debug() -> ProgramImage {
    let mut image = small_image();
    let double = PouDebug {
        source_hash: [7; 32],
        frame: vec![
            FrameVariable {
                name: "x".to_owned(),
                ty: 0,
                offset: 0,
                kind: FrameVariableKind::Input,
            },
            FrameVariable {
                name: "double".to_owned(),
                ty: 0,
                offset: 4,
                kind: FrameVariableKind::Result,
            },
        ],
    };
    image.debug = Some(DebugInfo {
        pous: vec![PouDebug::default(), double],
    });
    image
}

#[test]
fn a_debug_section_round_trips_as_the_optional_section_13() {
    let image = with_debug();
    let bytes = image.encode();
    assert_eq!(ProgramImage::decode(&bytes), Ok(image));
    let debug = sections(&bytes)
        .into_iter()
        .find(|section| section.id == 13)
        .unwrap_or_else(|| panic!("no section 13"));
    assert_eq!(debug.flags, 0, "the debug section is not critical");
    // A reader that does not know the section skips it: without it the image is the same.
    let without: Vec<Section> = sections(&bytes)
        .into_iter()
        .filter(|section| section.id != 13)
        .collect();
    assert_eq!(
        ProgramImage::decode(&container(&without)),
        Ok(small_image())
    );
}

#[test]
fn a_debug_section_that_does_not_match_the_code_is_refused() {
    let mut image = with_debug();
    if let Some(debug) = &mut image.debug {
        debug.pous.pop();
    }
    assert_contains(&invalid_message(&image), "debug has 1 POUs, the code 2");
    let mut image = with_debug();
    if let Some(debug) = &mut image.debug {
        debug.pous[1].frame[1].offset = 6;
    }
    assert_contains(
        &invalid_message(&image),
        "variable 'double' of POU 'double' lies outside its frame",
    );
    let mut image = with_debug();
    if let Some(debug) = &mut image.debug {
        debug.pous[1].frame[0].ty = 99;
    }
    assert_contains(
        &invalid_message(&image),
        "variable 'x' of POU 'double' has no type",
    );
}
