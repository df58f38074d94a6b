//! Copies, backward jumps and the watchdog, instructions left to the host, entry checks, the
//! module's symbols and its lifetime.

#![allow(clippy::unwrap_used, clippy::expect_used)] // A panic is a failed test.

use super::real::real_code;
use super::*;

#[test]
fn copies_overlap_as_memmove_and_large_ones_go_to_the_host() {
    let code = vec![
        Instr::Copy {
            size: 12,
            dst: I(2),
            src: I(0),
        },
        Instr::Copy {
            size: 100,
            dst: I(150),
            src: I(32),
        },
    ];
    let fixture = Fixture::new(code);
    let mut host = fixture.host();
    for offset in 0..132u32 {
        host.put(offset, u64::from(offset as u8), 1);
    }
    let before = host.memory.clone();
    assert_eq!(fixture.run(&mut host), Status::Ok);
    let at = INSTANCE_AT as usize;
    assert_eq!(host.memory[at + 2..at + 14], before[at..at + 12]);
    assert_eq!(host.memory[at + 150..at + 250], before[at + 32..at + 132]);
}

#[test]
fn a_backward_jump_ticks_when_due_or_when_the_budget_is_spent() {
    // i := i + 1; IF i < 10 THEN GOTO 0 (the back-edge is instruction 2).
    let code = vec![
        Instr::Binary {
            op: BinaryOp::Add,
            ty: Dint,
            dst: I(0),
            a: I(0),
            b: I(4),
        },
        Instr::Compare {
            op: CompareOp::Lt,
            ty: Dint,
            dst: I(8),
            a: I(0),
            b: I(12),
        },
        Instr::JumpIf {
            cond: I(8),
            target: 0,
        },
        Instr::Return,
    ];
    let fixture = Fixture::new(code);
    let back_edge = Site {
        pou: 0,
        instruction: 2,
    };
    let prepare = |host: &mut TestHost| {
        host.put(4, 1, 4);
        host.put(12, 10, 4);
    };
    // Neither due nor spent: no tick, the budget counted down by the nine back-edges.
    let mut host = fixture.host();
    prepare(&mut host);
    let due = AtomicBool::new(false);
    let mut counters = Counters {
        depth: 3,
        budget: 100,
    };
    assert_eq!(fixture.run_with(&mut host, &due, &mut counters), Status::Ok);
    assert_eq!(host.get(0, 4), 10);
    assert!(host.ticks.is_empty());
    assert_eq!(
        counters,
        Counters {
            depth: 3,
            budget: 91
        }
    );
    // The budget reaches 0 at the fourth back-edge: one tick there, which resets it.
    let mut host = fixture.host();
    prepare(&mut host);
    let mut counters = Counters {
        depth: 0,
        budget: 4,
    };
    assert_eq!(fixture.run_with(&mut host, &due, &mut counters), Status::Ok);
    assert_eq!(
        host.ticks,
        vec![(
            back_edge,
            Counters {
                depth: 0,
                budget: 0
            }
        )]
    );
    assert_eq!(counters.budget, 4096 - 5);
    // With the flag set, every back-edge ticks until the host clears it.
    static DUE: AtomicBool = AtomicBool::new(true);
    let mut host = fixture.host();
    prepare(&mut host);
    host.clear_due = Some(&DUE);
    let mut counters = Counters {
        depth: 0,
        budget: 50,
    };
    assert_eq!(fixture.run_with(&mut host, &DUE, &mut counters), Status::Ok);
    assert_eq!(
        host.ticks,
        vec![(
            back_edge,
            Counters {
                depth: 0,
                budget: 49
            }
        )]
    );
}

#[test]
fn a_faulted_tick_ends_the_function() {
    struct Stopping(TestHost);
    impl Host for Stopping {
        fn memory(&mut self) -> &mut [u8] {
            self.0.memory()
        }
        fn tick(&mut self, site: Site, counters: &mut Counters) -> Status {
            self.0.tick(site, counters);
            Status::Faulted
        }
        fn preempt(&mut self, site: Site, counters: &mut Counters) -> Status {
            self.0.preempt(site, counters)
        }
        fn op(&mut self, site: Site, instance: u64, frame: u64, c: &mut Counters) -> Status {
            self.0.op(site, instance, frame, c)
        }
        fn fault(&mut self, site: Site, fault: NativeFault) {
            self.0.fault(site, fault);
        }
        fn copy(&mut self, to: u64, from: u64, bytes: u64) -> Status {
            self.0.copy(to, from, bytes)
        }
        fn frame(&mut self, pou: u32, frame: u64) -> Status {
            self.0.frame(pou, frame)
        }
    }
    // An endless loop: only the host can end it.
    let fixture = Fixture::new(vec![
        Instr::Binary {
            op: BinaryOp::Add,
            ty: Dint,
            dst: I(0),
            a: I(0),
            b: I(4),
        },
        Instr::Jump { target: 0 },
    ]);
    let mut host = Stopping(fixture.host());
    host.0.put(4, 1, 4);
    let due = AtomicBool::new(false);
    let mut counters = Counters {
        depth: 0,
        budget: 4096,
    };
    let entry = Entry {
        instance: INSTANCE_AT,
        frame: fixture.frame_at(),
        stack_end: fixture.layout.stacks + fixture.layout.stack_size,
        native_stack_limit: 0,
        due: &due,
        now_ns: 0,
    };
    assert_eq!(
        fixture.code.run(0, &mut host, entry, &mut counters),
        Status::Faulted
    );
    assert_eq!(host.0.get(0, 4), 4096);
    assert_eq!(host.0.ticks.len(), 1);
}

#[test]
fn instructions_left_to_the_host_run_there_at_their_site() {
    let code = vec![
        Instr::Now { dst: I(0) },
        Instr::CallStdFunction {
            function: StdFunction::Len,
            wide: false,
            dst: (I(8), 0),
            args: vec![(I(16), 10)],
        },
        Instr::Clock {
            long: true,
            dst: I(32),
        },
    ];
    let fixture = Fixture::new(code);
    let mut host = fixture.host();
    assert_eq!(fixture.run(&mut host), Status::Ok);
    assert_eq!(host.get(0, 8), 1_234_567);
    let frame = fixture.frame_at();
    let sites: Vec<_> = host
        .ops
        .iter()
        .map(|(site, _, _)| site.instruction)
        .collect();
    assert_eq!(sites, vec![1, 2]);
    assert!(
        host.ops
            .iter()
            .all(|(_, instance, f)| *instance == INSTANCE_AT && *f == frame)
    );
}

#[test]
fn bases_outside_the_memory_fault_on_entry() {
    let fixture = Fixture::new(vec![Instr::Return]);
    let mut host = fixture.host();
    let due = AtomicBool::new(false);
    let mut counters = Counters {
        depth: 0,
        budget: 1,
    };
    let stack_end = fixture.layout.stacks + fixture.layout.stack_size;
    let entry = Entry {
        instance: INSTANCE_AT,
        frame: stack_end - 8,
        stack_end,
        native_stack_limit: 0,
        due: &due,
        now_ns: 0,
    };
    assert_eq!(
        fixture.code.run(0, &mut host, entry, &mut counters),
        Status::Faulted
    );
    let site = Site {
        pou: 0,
        instruction: 0,
    };
    assert_eq!(host.faults, vec![(site, NativeFault::StackOverflow)]);
    let entry = Entry {
        instance: fixture.layout.total,
        frame: fixture.frame_at(),
        ..entry
    };
    host.faults.clear();
    assert_eq!(
        fixture.code.run(0, &mut host, entry, &mut counters),
        Status::Faulted
    );
    assert_eq!(host.faults, vec![(site, NativeFault::Memory)]);
    // A POU the image does not have.
    host.faults.clear();
    assert_eq!(
        fixture.code.run(5, &mut host, entry, &mut counters),
        Status::Faulted
    );
}

#[test]
fn code_runs_on_the_memory_its_bases_were_checked_against() {
    // The host answers a buffer of 64 bytes on every second borrow: the entry must borrow the
    // memory once, check the bases against it and run on it; a callback that comes back with
    // the short buffer ends the code with `Memory` at its site.
    let fixture = Fixture::new(vec![
        Instr::Move {
            ty: Lint,
            dst: I(200),
            src: I(0),
        },
        Instr::Now { dst: I(8) },
        Instr::CallStdFunction {
            function: StdFunction::Len,
            wide: false,
            dst: (I(16), 0),
            args: vec![(I(24), 10)],
        },
        Instr::Move {
            ty: Lint,
            dst: I(208),
            src: I(0),
        },
    ]);
    let mut host = fixture.host();
    host.decoy = Some(vec![0; 64]);
    host.put(0, 0x1122_3344_5566_7788, 8);
    assert_eq!(fixture.run(&mut host), Status::Faulted);
    assert_eq!(host.get(200, 8), 0x1122_3344_5566_7788);
    assert_eq!(host.get(8, 8), 1_234_567);
    assert_eq!(host.get(208, 8), 0, "no instruction runs after the shrink");
    assert_eq!(host.decoy.as_deref(), Some(&[0u8; 64][..]));
    let site = Site {
        pou: 0,
        instruction: 2,
    };
    assert_eq!(host.faults, vec![(site, NativeFault::Memory)]);
}

#[test]
fn a_panicking_host_is_a_fault_at_the_callbacks_site() {
    // A panic must not unwind through generated code (it would abort the process).
    let code = vec![
        Instr::CallStdFunction {
            function: StdFunction::Len,
            wide: false,
            dst: (I(8), 0),
            args: vec![(I(16), 10)],
        },
        Instr::Copy {
            size: 100,
            dst: I(0),
            src: I(120),
        },
    ];
    let fixture = Fixture::new(code.clone());
    let mut host = fixture.host();
    host.panic = Some("a host bug in op");
    assert_eq!(fixture.run(&mut host), Status::Faulted);
    let site = |instruction| Site {
        pou: 0,
        instruction,
    };
    assert_eq!(host.faults, vec![(site(0), NativeFault::HostPanicked)]);
    // A copy has no site of its own: the fault generated code records at the `Copy` says the
    // host panicked, not that the range was outside the memory.
    let fixture = Fixture::new(code[1..].to_vec());
    let mut host = fixture.host();
    host.panic = Some("a host bug in copy");
    assert_eq!(fixture.run(&mut host), Status::Faulted);
    assert_eq!(host.faults, vec![(site(0), NativeFault::HostPanicked)]);
}

#[test]
fn only_our_symbols_are_imported_and_the_code_is_counted_and_freed() {
    fn send_and_sync<T: Send + Sync>() {}
    send_and_sync::<Code>();
    let fixture = Fixture::new(real_code(Real));
    let imported = fixture.code.imported_symbols();
    // The names the module resolved: the real code calls the pure functions and, for its
    // conversion faults, nothing else of ours is needed but what it uses.
    assert!(
        imported
            .iter()
            .any(|name| name == "rivet_pure_real_unary_f32"),
        "{imported:?}"
    );
    for name in imported {
        assert!(OUR_SYMBOLS.contains(&name.as_str()), "{name}");
    }
    // A module of moves alone imports nothing.
    let moves = Fixture::new(vec![Instr::Move {
        ty: Dint,
        dst: I(0),
        src: I(4),
    }]);
    assert_eq!(moves.code.imported_symbols(), &[] as &[String]);
    assert!(fixture.code.code_bytes() > 0);
    assert!(fixture.code.has(0));
    assert!(!fixture.code.has(1));
    let freed = fixture.code.freed_flag();
    assert!(!freed.load(Ordering::Relaxed));
    drop(fixture);
    assert!(freed.load(Ordering::Relaxed));
}

#[test]
fn an_image_needing_a_symbol_outside_the_table_is_refused() {
    // The division calls `rivet_jit_fault` for its zero check; without it in the table the
    // name is foreign, and the module is refused (and freed) before any of its code runs.
    let code = vec![Instr::Binary {
        op: BinaryOp::Div,
        ty: Dint,
        dst: I(0),
        a: I(4),
        b: I(8),
    }];
    let image = image(code, vec![0; 16]);
    let layout = Layout::of(&image, 1);
    let table: Vec<_> = crate::module::our_symbols(&PURE)
        .into_iter()
        .filter(|(name, _)| *name != "rivet_jit_fault")
        .collect();
    match Translation::with_symbols(&image, &layout, table, crate::compile::Threads::Host) {
        Err(crate::NativeUnsupported::ForeignSymbol(name)) => assert_eq!(name, "rivet_jit_fault"),
        other => panic!("not refused: {other:?}"),
    }
    let accepted = Translation::with_symbols(
        &image,
        &layout,
        crate::module::our_symbols(&PURE),
        crate::compile::Threads::Host,
    )
    .unwrap();
    assert_eq!(
        accepted.imported_symbols(),
        &["rivet_jit_fault".to_string()]
    );
}
