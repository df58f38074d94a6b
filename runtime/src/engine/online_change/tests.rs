use program_image::{Elementary, Member, StructKind, Symbol, SymbolFlags, TypeDef};

use super::*;
use crate::test_images::{self, TestTask};

/// Where the test variables start in the data region, after the test image's counters.
const BASE: u32 = 64;

fn dint() -> TypeDef {
    TypeDef::Elementary(Elementary::Dint)
}

fn member(name: &str, ty: u32, offset: u32) -> Member {
    Member {
        name: name.to_owned(),
        ty,
        offset,
        located: None,
        flags: 0,
    }
}

fn symbol(path: &str, ty: u32, offset: u32) -> Symbol {
    Symbol {
        path: path.to_owned(),
        ty,
        region: Region::Data,
        offset: BASE + offset,
        bit: None,
        flags: SymbolFlags(SymbolFlags::GLOBAL),
    }
}

/// The counting test image with `types` appended to its table (their ids start at 1) and
/// `symbols` in the data region from [`BASE`] on.
fn image_with(interval_ns: u64, types: Vec<TypeDef>, symbols: Vec<Symbol>) -> ProgramImage {
    let mut image = test_images::image(&[TestTask::cyclic(interval_ns, 1)], &[]);
    image.types.extend(types);
    image.symbols.extend(symbols);
    image.layout.data_size = BASE + 128;
    image
}

fn write_dint(engine: &mut Engine, offset: u32, value: i32) {
    let at = (BASE + offset) as usize;
    engine.region_mut(Region::Data)[at..at + 4].copy_from_slice(&value.to_le_bytes());
}

fn read_dint(engine: &Engine, offset: u32) -> i32 {
    test_images::dint(engine.region(Region::Data), BASE + offset)
}

fn write_u64(engine: &mut Engine, offset: u32, value: u64) {
    let at = (BASE + offset) as usize;
    engine.region_mut(Region::Data)[at..at + 8].copy_from_slice(&value.to_le_bytes());
}

fn read_u64_at(engine: &Engine, offset: u32) -> u64 {
    read_u64(engine.region(Region::Data), (BASE + offset) as usize)
}

fn names(plan: &OnlineChangePlan, kind: DetailKind) -> Vec<&str> {
    plan.details()
        .iter()
        .filter(|detail| detail.kind == kind)
        .map(|detail| detail.name.as_str())
        .collect()
}

fn fb(members: Vec<Member>, size: u32) -> TypeDef {
    TypeDef::Struct {
        name: "FB_Counter".to_owned(),
        kind: StructKind::FunctionBlock,
        size,
        members,
    }
}

#[test]
fn a_member_added_to_a_function_block_keeps_the_other_members_of_every_instance() {
    // Types: 1 DINT, 2 the block; two instances of it.
    let old_fb = fb(vec![member("count", 1, 0), member("step", 1, 4)], 8);
    let new_fb = fb(
        vec![
            member("count", 1, 0),
            member("limit", 1, 4),
            member("step", 1, 8),
        ],
        12,
    );
    let old = image_with(
        10_000_000,
        vec![dint(), old_fb],
        vec![symbol("GVL.a", 2, 0), symbol("GVL.b", 2, 8)],
    );
    let mut new = image_with(
        10_000_000,
        vec![dint(), new_fb],
        vec![symbol("GVL.a", 2, 0), symbol("GVL.b", 2, 12)],
    );
    // The new member starts from its initial value.
    new.initial.data.push(program_image::InitRun {
        offset: BASE + 4,
        bytes: 100_i32.to_le_bytes().to_vec(),
    });
    let mut running = Engine::new(old.clone()).unwrap();
    for (offset, value) in [(0, 41), (4, 2), (8, 7), (12, 3)] {
        write_dint(&mut running, offset, value);
    }
    let plan = OnlineChangePlan::new(&old, running.region(Region::Data), &new);
    assert_eq!(plan.refusal(), None);
    assert_eq!(
        names(&plan, DetailKind::VariableAdded),
        ["GVL.a.limit", "GVL.b.limit"]
    );
    assert!(names(&plan, DetailKind::VariableRemoved).is_empty());
    assert_eq!(plan.summary().added, 2);
    assert_eq!(plan.summary().carried, 4);

    let mut next = Engine::new(new).unwrap();
    let applied = plan.apply(&mut running, &mut next);
    assert_eq!(applied.carried, 4);
    assert_eq!(
        [0, 4, 8, 12, 16, 20].map(|offset| read_dint(&next, offset)),
        [41, 100, 2, 7, 0, 3]
    );
}

#[test]
fn a_changed_type_is_reinitialised_a_removed_variable_listed_and_a_constant_takes_its_new_value() {
    let int = TypeDef::Elementary(Elementary::Int);
    let old = image_with(
        10_000_000,
        vec![dint(), int.clone()],
        vec![
            symbol("GVL.speed", 2, 0),
            symbol("GVL.gone", 1, 4),
            Symbol {
                flags: SymbolFlags(SymbolFlags::GLOBAL | SymbolFlags::CONSTANT),
                ..symbol("GVL.limit", 1, 8)
            },
        ],
    );
    let mut new = image_with(
        10_000_000,
        vec![dint(), int],
        vec![
            symbol("GVL.speed", 1, 0),
            Symbol {
                flags: SymbolFlags(SymbolFlags::GLOBAL | SymbolFlags::CONSTANT),
                ..symbol("GVL.limit", 1, 8)
            },
        ],
    );
    new.initial.data.push(program_image::InitRun {
        offset: BASE + 8,
        bytes: 50_i32.to_le_bytes().to_vec(),
    });
    let mut running = Engine::new(old.clone()).unwrap();
    write_dint(&mut running, 0, 1234);
    write_dint(&mut running, 8, 20);
    let plan = OnlineChangePlan::new(&old, running.region(Region::Data), &new);
    assert_eq!(
        names(&plan, DetailKind::VariableReinitialised),
        ["GVL.speed"]
    );
    assert_eq!(names(&plan, DetailKind::VariableRemoved), ["GVL.gone"]);
    assert_eq!(plan.summary().carried, 0);
    let mut next = Engine::new(new).unwrap();
    plan.apply(&mut running, &mut next);
    assert_eq!(read_dint(&next, 0), 0);
    assert_eq!(read_dint(&next, 8), 50);
}

#[test]
fn a_pointer_follows_its_target_to_its_new_place_and_one_whose_target_is_gone_is_cleared() {
    let pointer = TypeDef::Pointer {
        target: None,
        reference: false,
    };
    let old = image_with(
        10_000_000,
        vec![dint(), pointer.clone()],
        vec![
            symbol("GVL.target", 1, 0),
            symbol("GVL.gone", 1, 4),
            symbol("GVL.toTarget", 2, 8),
            symbol("GVL.toGone", 2, 16),
            symbol("GVL.toOutput", 2, 24),
        ],
    );
    let new = image_with(
        10_000_000,
        vec![dint(), pointer],
        vec![
            symbol("GVL.added", 1, 0),
            symbol("GVL.target", 1, 4),
            symbol("GVL.toTarget", 2, 8),
            symbol("GVL.toGone", 2, 16),
            symbol("GVL.toOutput", 2, 24),
        ],
    );
    let data_pointer = |offset: u32| 1u64 << 56 | u64::from(BASE + offset);
    let output_pointer = 4u64 << 56 | 2;
    let mut running = Engine::new(old.clone()).unwrap();
    write_dint(&mut running, 0, 77);
    write_u64(&mut running, 8, data_pointer(0));
    write_u64(&mut running, 16, data_pointer(4));
    write_u64(&mut running, 24, output_pointer);
    let plan = OnlineChangePlan::new(&old, running.region(Region::Data), &new);
    assert_eq!(plan.summary().pointers_moved, 1);
    assert_eq!(plan.summary().pointers_cleared, 1);
    assert_eq!(names(&plan, DetailKind::PointerCleared), ["GVL.toGone"]);
    let mut next = Engine::new(new).unwrap();
    let applied = plan.apply(&mut running, &mut next);
    assert_eq!((applied.pointers_moved, applied.pointers_cleared), (1, 1));
    assert_eq!(read_dint(&next, 4), 77);
    assert_eq!(read_u64_at(&next, 8), data_pointer(4));
    assert_eq!(read_u64_at(&next, 16), 0);
    assert_eq!(read_u64_at(&next, 24), output_pointer);
    assert_eq!(
        plan.moved_range((BASE) as usize, 4),
        Some((BASE + 4) as usize)
    );
    assert_eq!(plan.moved_range((BASE + 4) as usize, 4), None);
}

#[test]
fn a_change_of_the_tasks_or_the_areas_or_to_the_same_image_is_refused_with_the_difference() {
    let old = image_with(10_000_000, vec![dint()], vec![symbol("GVL.a", 1, 0)]);
    let data = vec![0; 256];

    let same = OnlineChangePlan::new(&old, &data, &old);
    assert_eq!(same.refusal().map(|r| r.0), Some(ChangeRefusal::SameImage));

    let faster = image_with(2_000_000, vec![dint()], vec![symbol("GVL.b", 1, 0)]);
    let plan = OnlineChangePlan::new(&old, &data, &faster);
    assert_eq!(
        plan.refusal(),
        Some((
            ChangeRefusal::Tasks,
            "task 'Task0': interval changed from 10 ms to 2 ms"
        ))
    );
    // The details are worked out all the same, for the user who asks.
    assert_eq!(names(&plan, DetailKind::VariableAdded), ["GVL.b"]);

    let mut bigger = image_with(10_000_000, vec![dint()], vec![symbol("GVL.b", 1, 0)]);
    bigger.layout.output_size += 2;
    let plan = OnlineChangePlan::new(&old, &data, &bigger);
    let (reason, why) = plan.refusal().unwrap();
    assert_eq!(reason, ChangeRefusal::Areas);
    assert!(why.contains("%Q"), "{why}");

    let mut renamed = image_with(10_000_000, vec![dint()], vec![symbol("GVL.b", 1, 0)]);
    renamed.tasks[0].name = "Fast".to_owned();
    let plan = OnlineChangePlan::new(&old, &data, &renamed);
    let (reason, why) = plan.refusal().unwrap();
    assert_eq!(reason, ChangeRefusal::Tasks);
    assert!(why.contains("'Task0'"), "{why}");
}

#[test]
fn a_changed_pou_is_listed_with_those_added_and_removed() {
    let old = image_with(10_000_000, vec![dint()], vec![symbol("GVL.a", 1, 0)]);
    let mut new = old.clone();
    new.pous[0].code.insert(0, program_image::Instr::Return);
    let mut helper = new.pous[0].clone();
    helper.name = "Helper".to_owned();
    helper.kind = program_image::PouKind::Function;
    new.pous.push(helper);
    let plan = OnlineChangePlan::new(&old, &[0; 256], &new);
    assert_eq!(plan.refusal(), None);
    assert_eq!(names(&plan, DetailKind::PouChanged), ["Program0"]);
    assert_eq!(names(&plan, DetailKind::PouAdded), ["Helper"]);
    let back = OnlineChangePlan::new(&new, &[0; 256], &old);
    assert_eq!(names(&back, DetailKind::PouRemoved), ["Helper"]);
}

/// `image` with a function `Helper` after its program, and a `debug` section giving the
/// program and the function the source hashes `program` and `helper`.
fn with_helper_and_hashes(mut image: ProgramImage, program: u8, helper: u8) -> ProgramImage {
    let mut function = image.pous[0].clone();
    function.name = "Helper".to_owned();
    function.kind = program_image::PouKind::Function;
    image.pous.push(function);
    let pou = |hash: u8| program_image::PouDebug {
        source_hash: [hash; 32],
        frame: Vec::new(),
    };
    image.debug = Some(DebugInfo {
        pous: vec![pou(program), pou(helper)],
    });
    image
}

#[test]
fn with_source_hashes_only_the_edited_pou_is_changed_when_a_global_moved_every_address() {
    let old = with_helper_and_hashes(
        image_with(10_000_000, vec![dint()], vec![symbol("GVL.a", 1, 0)]),
        1,
        2,
    );
    // A global added before `GVL.a` moves it, so both POUs' code is generated again with
    // other addresses; only the function's source was edited.
    let mut new = with_helper_and_hashes(
        image_with(
            10_000_000,
            vec![dint()],
            vec![symbol("GVL.b", 1, 0), symbol("GVL.a", 1, 4)],
        ),
        1,
        3,
    );
    for pou in &mut new.pous {
        pou.code.insert(0, program_image::Instr::Return);
    }
    let plan = OnlineChangePlan::new(&old, &[0; 256], &new);
    assert_eq!(plan.refusal(), None);
    assert_eq!(names(&plan, DetailKind::PouChanged), ["Helper"]);
    assert_eq!(names(&plan, DetailKind::VariableAdded), ["GVL.b"]);
    assert_eq!(plan.summary().pous_changed, 1);

    // Without the debug section of one image, the code decides: both are listed.
    let mut bare = new.clone();
    bare.debug = None;
    let plan = OnlineChangePlan::new(&old, &[0; 256], &bare);
    assert_eq!(names(&plan, DetailKind::PouChanged), ["Program0", "Helper"]);
}
