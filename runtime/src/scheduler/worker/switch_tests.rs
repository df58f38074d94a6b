//! The switch on the scheduler's thread, on the real clock; every wait is bounded.

use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use program_image::{Elementary, ProgramImage, Region, Symbol, SymbolFlags, TypeDef};

use crate::areas::LocatedAreas;
use crate::engine::{Engine, OnlineChangePlan};
use crate::scheduler::{Scheduler, SchedulerError, SchedulerOptions};
use crate::test_images::{TestTask, count, dint, image};

const MS: u64 = 1_000_000;

/// The counting image with its first task's cycle count as the variable `GVL.count`, counting
/// up by the first constant, `step`.
fn counting(step: i32) -> ProgramImage {
    let mut image = image(&[TestTask::cyclic(MS, 1)], &[]);
    image.types.push(TypeDef::Elementary(Elementary::Dint));
    image.symbols.push(Symbol {
        path: "GVL.count".to_owned(),
        ty: 1,
        region: Region::Data,
        offset: count(0),
        bit: None,
        flags: SymbolFlags(SymbolFlags::GLOBAL),
    });
    image.constants[..4].copy_from_slice(&step.to_le_bytes());
    image
}

/// The cycles run and the count, read together between two cycles.
fn cycles_and_count(scheduler: &Scheduler) -> (u64, i32) {
    scheduler
        .between(|between| {
            let count = between.memory.as_ref().map_or(0, |memory| {
                dint(memory.engine.region(Region::Data), count(0))
            });
            (between.cycles, count)
        })
        .unwrap()
}

#[test]
fn the_new_code_runs_from_the_next_cycle_with_the_count_carried_and_no_cycle_missed() {
    let areas = Arc::new(Mutex::new(LocatedAreas::default()));
    let scheduler = Scheduler::spawn(areas, SchedulerOptions::default()).unwrap();
    let (old, new) = (counting(1), counting(2));
    let (from, to) = (old.identity(), new.identity());
    scheduler.load(old.clone()).unwrap();
    scheduler.start().unwrap();
    let start = Instant::now();
    while cycles_and_count(&scheduler).0 < 5 {
        assert!(start.elapsed() < Duration::from_secs(10), "no cycles ran");
        std::thread::sleep(Duration::from_millis(1));
    }
    let snapshot = scheduler
        .between(|between| {
            between
                .memory
                .as_ref()
                .map(|memory| memory.engine.region(Region::Data).to_vec())
        })
        .unwrap()
        .unwrap();
    let plan = Arc::new(OnlineChangePlan::new(&old, &snapshot, &new));
    assert_eq!(plan.refusal(), None);
    let engine = Engine::new(new.clone()).unwrap();
    let report = scheduler
        .online_change(engine, Arc::clone(&plan), from, to)
        .unwrap();
    assert_eq!(report.applied.carried, 1);
    assert_eq!(scheduler.status().image, Some(to));
    while cycles_and_count(&scheduler).0 < report.cycles + 5 {
        assert!(start.elapsed() < Duration::from_secs(10), "no cycles ran");
        std::thread::sleep(Duration::from_millis(1));
    }
    // Up to the switch the count went up by one a cycle, from it by two: every cycle ran,
    // the old code until the switch and the new one after it.
    let (cycles, counted) = cycles_and_count(&scheduler);
    assert_eq!(i64::from(counted), 2 * cycles as i64 - report.cycles as i64);
    // The statistics count every cycle too; read after the count, they may have one more.
    assert!(scheduler.status().tasks[0].cycles >= cycles);

    // The same plan again: the running program is no longer the one it was made for.
    let engine = Engine::new(new).unwrap();
    assert!(matches!(
        scheduler.online_change(engine, plan, from, to),
        Err(SchedulerError::ProgramChanged)
    ));
}

/// The counting image with a variable `GVL.held` at `held` (which no code uses) and, when
/// `gone`, a variable `GVL.gone` at 20.
fn with_held(held: u32, gone: bool) -> ProgramImage {
    let mut image = counting(1);
    image.layout.data_size = 32;
    let symbol = |path: &str, offset: u32| Symbol {
        path: path.to_owned(),
        ty: 1,
        region: Region::Data,
        offset,
        bit: None,
        flags: SymbolFlags(SymbolFlags::GLOBAL),
    };
    image.symbols.push(symbol("GVL.held", held));
    if gone {
        image.symbols.push(symbol("GVL.gone", 20));
    }
    image
}

#[test]
fn a_force_follows_its_variable_and_one_on_a_removed_variable_is_released() {
    let areas = Arc::new(Mutex::new(LocatedAreas::default()));
    let scheduler = Scheduler::spawn(areas, SchedulerOptions::default()).unwrap();
    let (old, new) = (with_held(16, true), with_held(24, false));
    scheduler.load(old.clone()).unwrap();
    let place = |offset: u32| online_protocol::Place {
        region: 0,
        offset,
        bit: None,
        size: 4,
    };
    scheduler
        .between(move |between| {
            between.forces.set(place(16), 99_i32.to_le_bytes().to_vec());
            between.forces.set(place(20), 5_i32.to_le_bytes().to_vec());
        })
        .unwrap();
    let plan = Arc::new(OnlineChangePlan::new(&old, &[0; 32], &new));
    let engine = Engine::new(new.clone()).unwrap();
    let report = scheduler
        .online_change(engine, plan, old.identity(), new.identity())
        .unwrap();
    assert_eq!(report.forces_released, 1);
    let (forces, held) = scheduler
        .between(|between| {
            let held = between
                .memory
                .as_ref()
                .map_or(0, |memory| dint(memory.engine.region(Region::Data), 24));
            (between.forces.entries().to_vec(), held)
        })
        .unwrap();
    assert_eq!(forces, [(place(24), 99_i32.to_le_bytes().to_vec())]);
    assert_eq!(held, 99);
}
