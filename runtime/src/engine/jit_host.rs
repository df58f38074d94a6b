//! The runtime's side of generated code (`docs/native-engine.md` §4.3): [`Exec`] entering a
//! POU's machine code, and answering its callbacks as the interpreter would at the same
//! instruction.
//!
//! The counters (`depth`, `budget`) travel with control: they are handed to generated code on
//! entry and taken back on return, taken from each callback before it runs and handed back
//! after, so an interpreted call inside a native one counts on the same numbers as a purely
//! interpreted cycle. A fault is recorded as [`Exec::run`] records it (`fault_at` keeps the
//! innermost site) and kept in `native_fault` until [`Exec::run_native`] returns it.

use std::sync::atomic::Ordering;

use super::exec::{Exec, FRAME, INSTANCE};
use super::fault::FaultKind;
use super::lower::Flow;

impl Exec<'_> {
    /// Runs POU `index`'s machine code with the current bases: the native half of the one
    /// dispatch in [`Exec::run`].
    pub(super) fn run_native(&mut self, code: &jit::Code, index: usize) -> Result<(), FaultKind> {
        let entries = &self.code.native_entries;
        entries.store(
            entries.load(Ordering::Relaxed).wrapping_add(1),
            Ordering::Relaxed,
        );
        let entry = jit::Entry {
            instance: self.bases[usize::from(INSTANCE)] as u64,
            frame: self.bases[usize::from(FRAME)] as u64,
            stack_end: self.stack_end as u64,
            native_stack_limit: self.native_stack_limit(),
            due: self.due,
            now_ns: self.now_ns,
        };
        let mut counters = jit::Counters {
            depth: self.depth,
            budget: self.budget,
        };
        // The callbacks move the bases and the stack pointer for the instructions they run;
        // the interpreted caller goes on with its own.
        let saved = (self.bases, self.sp);
        let status = code.run(index as u32, self, entry, &mut counters);
        (self.bases, self.sp) = saved;
        self.depth = counters.depth;
        self.budget = counters.budget;
        let fault = self.native_fault.take();
        match status {
            jit::Status::Ok => Ok(()),
            jit::Status::Faulted => Err(fault.unwrap_or_else(|| {
                // Code::run records its own entry faults through `fault`, so a fault without
                // a kind is a bug of the engine, kept as one rather than hidden.
                self.fault_at.get_or_insert((index, 0));
                FaultKind::Internal("generated code faulted without recording a fault".into())
            })),
        }
    }

    /// Records `kind` at `site`, as [`Exec::run`] records the fault of an instruction.
    fn record_native_fault(&mut self, site: jit::Site, kind: FaultKind) -> jit::Status {
        self.fault_at
            .get_or_insert((site.pou as usize, site.instruction as usize));
        self.native_fault = Some(kind);
        jit::Status::Faulted
    }

    /// Takes the counters from generated code before a callback runs.
    fn take_counters(&mut self, counters: &jit::Counters) {
        self.depth = counters.depth;
        self.budget = counters.budget;
    }

    /// Gives the counters back to generated code after a callback ran.
    fn give_counters(&self, counters: &mut jit::Counters) {
        counters.depth = self.depth;
        counters.budget = self.budget;
    }
}

/// The runtime's [`FaultKind`] of a fault generated code found (`docs/native-engine.md` §4.7).
fn fault_kind(fault: jit::NativeFault) -> FaultKind {
    match fault {
        jit::NativeFault::DivisionByZero => FaultKind::DivisionByZero,
        jit::NativeFault::IndexOutOfBounds { index, low, high } => {
            FaultKind::IndexOutOfBounds { index, low, high }
        }
        jit::NativeFault::NullPointer => FaultKind::NullPointer,
        jit::NativeFault::BadPointer(pointer) => FaultKind::BadPointer(pointer),
        jit::NativeFault::StackOverflow => FaultKind::StackOverflow,
        jit::NativeFault::Memory => FaultKind::Memory,
        jit::NativeFault::HostPanicked => FaultKind::Internal("a host callback panicked".into()),
    }
}

impl jit::Host for Exec<'_> {
    fn memory(&mut self) -> &mut [u8] {
        self.mem
    }

    fn tick(&mut self, site: jit::Site, counters: &mut jit::Counters) -> jit::Status {
        #[cfg(test)]
        tests::panic_if_asked("tick");
        // Generated code has counted this backward jump already; what is left of
        // `Exec::tick` is the safe point and, with the budget spent, the watchdog.
        self.take_counters(counters);
        let result = self
            .safe_point(site.instruction as usize)
            .and_then(|_| self.look_at_the_clock());
        self.give_counters(counters);
        match result {
            Ok(()) => jit::Status::Ok,
            Err(kind) => self.record_native_fault(site, kind),
        }
    }

    fn preempt(&mut self, site: jit::Site, counters: &mut jit::Counters) -> jit::Status {
        self.take_counters(counters);
        let result = self.safe_point(site.instruction as usize);
        self.give_counters(counters);
        match result {
            Ok(_) => jit::Status::Ok,
            Err(kind) => self.record_native_fault(site, kind),
        }
    }

    fn op(
        &mut self,
        site: jit::Site,
        instance: u64,
        frame: u64,
        counters: &mut jit::Counters,
    ) -> jit::Status {
        let code = self.code;
        let (pou, pc) = (site.pou as usize, site.instruction as usize);
        let Some(compiled) = code.pous.get(pou) else {
            return self.record_native_fault(site, FaultKind::Memory);
        };
        let Some(op) = compiled.ops.get(pc) else {
            return self.record_native_fault(site, FaultKind::Memory);
        };
        // During a POU's body the interpreter's stack pointer is its frame's end.
        let (instance, frame) = (instance as usize, frame as usize);
        self.bases = [0, instance, frame];
        self.sp = frame.saturating_add(compiled.frame_size);
        self.take_counters(counters);
        let result = op(self);
        self.give_counters(counters);
        match result {
            Ok(Flow::Next) => jit::Status::Ok,
            Ok(flow) => self.record_native_fault(
                site,
                FaultKind::Internal(format!(
                    "an instruction handed over by generated code went on as {flow:?}"
                )),
            ),
            Err(fault) => self.record_native_fault(site, *fault),
        }
    }

    fn fault(&mut self, site: jit::Site, fault: jit::NativeFault) {
        self.record_native_fault(site, fault_kind(fault));
    }

    fn host_panicked(&mut self, site: jit::Site, message: &str) {
        self.record_native_fault(
            site,
            FaultKind::Internal(format!("a host callback panicked: {message}")),
        );
    }

    fn copy(&mut self, to: u64, from: u64, bytes: u64) -> jit::Status {
        #[cfg(test)]
        tests::panic_if_asked("copy");
        let (Ok(to), Ok(from), Ok(bytes)) = (
            usize::try_from(to),
            usize::try_from(from),
            usize::try_from(bytes),
        ) else {
            return jit::Status::Faulted;
        };
        match Exec::copy(self, to, from, bytes) {
            Ok(()) => jit::Status::Ok,
            Err(_) => jit::Status::Faulted,
        }
    }

    fn frame(&mut self, pou: u32, frame: u64) -> jit::Status {
        let Ok(frame) = usize::try_from(frame) else {
            return jit::Status::Faulted;
        };
        match self.prepare_frame(pou as usize, frame) {
            Ok(()) => jit::Status::Ok,
            Err(_) => jit::Status::Faulted,
        }
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, clippy::expect_used)] // A panic is a failed test.

    use std::cell::Cell;

    use super::*;
    use crate::engine::exec::NEVER_DUE;
    use crate::engine::{Engine, EngineChoice};
    use crate::test_images::{Body, TestTask, image};

    thread_local! {
        /// Whether the next `tick` or `copy` callback on this thread panics, as a bug of the
        /// runtime's side would.
        static PANIC_IN_CALLBACK: Cell<bool> = const { Cell::new(false) };
    }

    /// Panics when the running test asked for it, inside callback `callback`: a literal
    /// message from `tick`, a formatted one from `copy` (the two kinds of panic payload).
    pub(super) fn panic_if_asked(callback: &str) {
        if PANIC_IN_CALLBACK.with(|asked| asked.replace(false)) {
            if callback == "tick" {
                panic!("tick panicked (injected by a test)");
            }
            panic!("{callback} panicked (injected by a test)");
        }
    }

    /// The fault of the one cycle of task 0 of `image` under the native engine, with a
    /// callback made to panic; `None` where this machine makes no machine code.
    fn fault_of_a_panicking_callback(
        image: program_image::ProgramImage,
    ) -> Option<crate::engine::FaultRecord> {
        let (mut engine, report) = Engine::with_choice(image, EngineChoice::Native).unwrap();
        if !report.runs_natively() {
            assert!(!EngineChoice::native_available());
            return None;
        }
        PANIC_IN_CALLBACK.with(|asked| asked.set(true));
        let fault = engine
            .run_cycle(0, 0, 0)
            .expect_err("the callback panicked");
        assert!(!PANIC_IN_CALLBACK.with(Cell::get), "no callback was made");
        // The runtime lives: the next cycle runs, and the panic is not asked for again.
        engine.run_cycle(0, 0, 1).unwrap();
        Some(fault)
    }

    #[test]
    fn a_panic_in_a_callback_with_a_site_is_an_internal_fault_with_its_message() {
        // A loop of more than one budget of backward jumps: its tick with the budget spent
        // panics at the back-edge.
        let watching = TestTask {
            body: Body::Watch {
                iterations: 10_000,
                sets_trigger: false,
            },
            ..TestTask::cyclic(1_000_000, 1)
        };
        let image = image(&[watching], &[]);
        let back_edge = image.pous[0]
            .code
            .iter()
            .position(|instr| matches!(instr, program_image::Instr::Jump { .. }))
            .unwrap() as u32;
        let Some(fault) = fault_of_a_panicking_callback(image) else {
            return;
        };
        assert_eq!(
            fault.kind,
            FaultKind::Internal(
                "a host callback panicked: tick panicked (injected by a test)".into()
            )
        );
        assert_eq!(
            (fault.pou.as_str(), fault.instruction),
            ("Program0", back_edge)
        );
    }

    #[test]
    fn a_panic_in_a_large_copy_is_an_internal_fault_with_its_message_at_the_copy() {
        use program_image::{Instr, Operand};
        // A copy of more than 64 bytes goes to the host, which has no site of its own: the
        // fault generated code records at the Copy carries the panic's message.
        let mut image = image(&[TestTask::cyclic(1_000_000, 1)], &[]);
        image.pous[0].code = vec![
            Instr::Move {
                ty: program_image::Elementary::Dint,
                dst: Operand::Global(0),
                src: Operand::Const(0),
            },
            Instr::Copy {
                size: 100,
                dst: Operand::Global(900),
                src: Operand::Global(0),
            },
            Instr::Return,
        ];
        let Some(fault) = fault_of_a_panicking_callback(image) else {
            return;
        };
        assert_eq!(
            fault.kind,
            FaultKind::Internal(
                "a host callback panicked: copy panicked (injected by a test)".into()
            )
        );
        assert_eq!((fault.pou.as_str(), fault.instruction), ("Program0", 1));
    }

    #[test]
    fn an_instance_outside_the_memory_is_a_memory_fault_at_the_pous_first_instruction() {
        let (mut engine, report) = Engine::with_choice(
            image(&[TestTask::cyclic(1_000_000, 0)], &[]),
            EngineChoice::Native,
        )
        .unwrap();
        if !report.runs_natively() {
            // No machine code on this machine: nothing of the native engine to test.
            assert!(!EngineChoice::native_available());
            return;
        }
        let pou = engine.image.tasks[0].programs[0].pou as usize;
        let Engine {
            image,
            regions,
            code,
            memory,
            motion,
            debug,
            ..
        } = &mut engine;
        // Past the end even for a program whose instance is empty.
        let beyond = memory.len() + 1;
        let mut exec = Exec::new(
            memory,
            image,
            regions,
            code,
            regions.stack(0),
            0,
            None,
            motion,
            (&NEVER_DUE, None),
            (0, debug),
        );
        // The generated code checks its bases once when it is entered (native-engine.md §7
        // rule 2); an instance past the memory's end is refused there, at instruction 0.
        exec.bases[usize::from(INSTANCE)] = beyond;
        let entries = code.native_entries.load(Ordering::Relaxed);
        assert_eq!(exec.run(pou, 0), Err(FaultKind::Memory));
        assert_eq!(exec.fault_at, Some((pou, 0)));
        assert_eq!(code.native_entries.load(Ordering::Relaxed), entries + 1);
        // The counters came back as they went in.
        assert_eq!(exec.depth, 0);
    }

    #[test]
    fn every_native_fault_is_the_interpreters_kind() {
        assert_eq!(
            fault_kind(jit::NativeFault::IndexOutOfBounds {
                index: 11,
                low: 1,
                high: 10
            }),
            FaultKind::IndexOutOfBounds {
                index: 11,
                low: 1,
                high: 10
            }
        );
        assert_eq!(
            fault_kind(jit::NativeFault::BadPointer(7 << 56)),
            FaultKind::BadPointer(7 << 56)
        );
        assert_eq!(
            fault_kind(jit::NativeFault::HostPanicked),
            FaultKind::Internal("a host callback panicked".into())
        );
        for (native, kind) in [
            (jit::NativeFault::DivisionByZero, FaultKind::DivisionByZero),
            (jit::NativeFault::NullPointer, FaultKind::NullPointer),
            (jit::NativeFault::StackOverflow, FaultKind::StackOverflow),
            (jit::NativeFault::Memory, FaultKind::Memory),
        ] {
            assert_eq!(fault_kind(native), kind);
        }
    }

    /// A hand-made image whose program (task 0) calls a method without an instance, so the
    /// method runs on the program's instance, which is far smaller than the method's: the
    /// method's last instance byte lies past the end of the memory. Task 1 counts.
    fn method_beyond_the_memory() -> program_image::ProgramImage {
        use program_image::{Elementary, Instr, Operand, Pou, PouKind};
        const METHOD_INSTANCE_BYTES: u32 = 1 << 20;
        let mut image = image(
            &[
                TestTask::cyclic(1_000_000, 1),
                TestTask::cyclic(1_000_000, 2),
            ],
            &[],
        );
        image.pous[0].code = vec![
            Instr::CallFunction {
                pou: 2,
                instance: None,
                inputs: Vec::new(),
                outputs: Vec::new(),
            },
            Instr::Return,
        ];
        image.pous.push(Pou {
            name: "Beyond".to_owned(),
            kind: PouKind::Method,
            frame_size: 0,
            frame_init: Vec::new(),
            instance_size: METHOD_INSTANCE_BYTES,
            code: vec![
                Instr::Move {
                    ty: Elementary::Dint,
                    dst: Operand::Instance(METHOD_INSTANCE_BYTES - 4),
                    src: Operand::Const(0),
                },
                Instr::Return,
            ],
            lines: Vec::new(),
        });
        image
    }

    #[test]
    fn a_method_whose_instance_passes_the_memorys_end_is_a_memory_fault_at_the_call() {
        let image = method_beyond_the_memory();
        let (mut native, report) =
            crate::simulation::Simulation::with_choice(image.clone(), EngineChoice::Native)
                .unwrap();
        if !report.runs_natively() {
            assert!(!EngineChoice::native_available());
            return;
        }
        assert!(report.fallbacks.is_empty(), "{report:#?}");
        assert!(
            image.layout.data_size < 1 << 20,
            "the memory must be smaller than the method's instance"
        );
        native.run(3);
        // The native engine checks the callee's instance once, at the call
        // (native-engine.md 4.4 step 4): the fault is the caller's, at its call instruction.
        let [fault] = native.faults() else {
            panic!("one fault: {:?}", native.faults())
        };
        assert_eq!(
            (fault.task.as_str(), &fault.kind, fault.pou.as_str()),
            ("Task0", &FaultKind::Memory, "Program0")
        );
        assert_eq!((fault.instruction, fault.cycle), (0, 0));
        assert!(native.engine().native_entries() > 0);
        // The runtime lives: the other task goes on.
        assert_eq!(native.cycles(), [1, 3]);
        // The interpreter checks each access instead and faults Memory at the method's store
        // past the memory's end (native-engine.md 7 rule 2: both safe, the sites differ).
        let (mut interpreted, _) =
            crate::simulation::Simulation::with_choice(image, EngineChoice::Interpreter).unwrap();
        interpreted.run(3);
        let [fault] = interpreted.faults() else {
            panic!("one fault: {:?}", interpreted.faults())
        };
        assert_eq!(
            (&fault.kind, fault.pou.as_str(), fault.instruction),
            (&FaultKind::Memory, "Beyond", 0)
        );
        assert_eq!(interpreted.cycles(), [1, 3]);
    }
}
