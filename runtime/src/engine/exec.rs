//! The execution state of one task while its programs run: memory, the current instance and
//! frame, the stack pointer, the task clock and the watchdog.

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Instant;

use program_image::ProgramImage;

use super::debug::DebugState;
use super::fault::FaultKind;
use super::lower::{Compiled, Flow};
use super::memory::Regions;
use super::scalar::Scalar;
use super::view::{EngineView, Preempt};

/// The flag of a cycle that nothing may interrupt: never set.
pub(super) static NEVER_DUE: AtomicBool = AtomicBool::new(false);

/// Which base an [`Addr`] is relative to.
pub(crate) const ABSOLUTE: u8 = 0;
/// The current instance (`THIS`).
pub(crate) const INSTANCE: u8 = 1;
/// The current frame.
pub(crate) const FRAME: u8 = 2;

/// An operand resolved at load time: a base and a byte offset from it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Addr {
    pub(crate) base: u8,
    pub(crate) offset: u32,
}

/// How many backward jumps run between two looks at the clock.
const WATCHDOG_STRIDE: u32 = 4096;

/// The deepest nesting of calls, whatever the stack size, so recursion ends as a fault long
/// before the thread's own stack would.
pub(crate) const MAX_CALL_DEPTH: u32 = 2000;

// The native engine checks the same depth in its own code (`docs/native-engine.md` §4.4); the
// two must never drift apart, or a recursion would fault at different depths in the engines.
const _: () = assert!(MAX_CALL_DEPTH == jit::MAX_CALL_DEPTH);

/// The native stack a cycle may use. Every PLC call nests a few Rust calls, so deep recursion
/// in a user program would exhaust the thread's stack (and abort the process) before the
/// PLC stack fills; measured against the address of a local at the start of the cycle, this
/// bound turns it into a fault. 512 KiB fits the smallest thread stack Rust gives (2 MiB).
pub(crate) const NATIVE_STACK_BUDGET: usize = 512 * 1024;

/// The address of a local of the caller: how deep the native stack is (it grows down on
/// every platform the runtime supports). Only compared, never dereferenced.
#[inline(never)]
fn stack_position() -> usize {
    let marker = 0u8;
    std::hint::black_box(std::ptr::from_ref(&marker)).addr()
}

/// One task's run through its programs.
pub(crate) struct Exec<'a> {
    pub(crate) mem: &'a mut [u8],
    /// Absolute, instance and frame bases, indexed by [`Addr::base`].
    pub(crate) bases: [usize; 3],
    pub(crate) sp: usize,
    pub(crate) stack_end: usize,
    pub(crate) regions: &'a Regions,
    pub(crate) code: &'a Compiled,
    /// The image, lent with the memory to a task that interrupts this cycle.
    pub(super) image: &'a Arc<ProgramImage>,
    /// Set when a task of higher priority may be due; read at every safe point.
    pub(super) due: &'a AtomicBool,
    /// Runs the tasks that interrupt this cycle, and serves a halt; `None` when nothing may.
    pub(super) hook: Option<&'a mut dyn Preempt>,
    /// The task whose cycle this is.
    pub(super) task: usize,
    /// The debug session's state, lent on with the memory.
    pub(super) debug: &'a mut DebugState,
    /// Nanoseconds this cycle spent halted, taken out of its axes' clock at its end.
    pub(super) halted_ns: i64,
    /// Whether a session was active when the cycle started: then the debugger keeps count of
    /// the cycle (its start, end and flow recording).
    pub(super) session: bool,
    /// Whether the cycle runs with the debugger ([`DebugState::cycle_needs_debugger`], set
    /// when the cycle starts): then every call keeps the task's shadow call stack, and each
    /// POU runs the debug form or the light form as [`Exec::run_watched`] decides.
    pub(super) debugging: bool,
    /// The task clock in nanoseconds, read by the timers.
    pub(crate) now_ns: i64,
    /// When the cycle started, on the real clock; `None` on a simulated clock, where time
    /// stands still during a cycle. `TIME()` and `LTIME()` add the time elapsed since.
    pub(crate) clock_started: Option<Instant>,
    pub(crate) deadline: Option<(Instant, u64)>,
    /// Backward jumps left before the watchdog looks at the clock; carried into and out of
    /// generated code (`docs/native-engine.md` §4.2).
    pub(super) budget: u32,
    /// Calls nested; carried into and out of generated code like the budget.
    pub(super) depth: u32,
    /// Where the first fault happened: POU index and instruction index.
    pub(crate) fault_at: Option<(usize, usize)>,
    /// The fault a callback of generated code recorded, kept until the `Code::run` that
    /// entered the code returns `Faulted` ([`Exec::run_native`]).
    pub(super) native_fault: Option<FaultKind>,
    /// [`stack_position`] when the cycle started.
    native_base: usize,
    /// The motion kernel and the state of the native motion blocks.
    pub(crate) motion: &'a mut super::native::MotionState,
}

impl<'a> Exec<'a> {
    /// An execution over `mem` whose stack starts at `stack_start`; with a `hook`, tasks of
    /// higher priority may interrupt it at its safe points when `due` is set.
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn new(
        mem: &'a mut [u8],
        image: &'a Arc<ProgramImage>,
        regions: &'a Regions,
        code: &'a Compiled,
        (stack_start, stack_end): (usize, usize),
        now_ns: i64,
        deadline: Option<(Instant, u64)>,
        motion: &'a mut super::native::MotionState,
        (due, hook): (&'a AtomicBool, Option<&'a mut dyn Preempt>),
        (task, debug): (usize, &'a mut DebugState),
    ) -> Self {
        let session = debug.active();
        Self {
            halted_ns: 0,
            task,
            debug,
            session,
            debugging: false,
            image,
            due,
            hook,
            mem,
            bases: [0, 0, stack_start],
            sp: stack_start,
            stack_end,
            regions,
            code,
            now_ns,
            clock_started: None,
            deadline,
            budget: WATCHDOG_STRIDE,
            depth: 0,
            fault_at: None,
            native_fault: None,
            native_base: stack_position(),
            motion,
        }
    }

    /// The clock `TIME()` and `LTIME()` read, in nanoseconds since the runtime started: the
    /// task clock plus, on the real clock, the time elapsed since the cycle started.
    pub(crate) fn clock_ns(&self) -> i64 {
        let elapsed_ns = self.clock_started.map_or(0, |started| {
            i64::try_from(started.elapsed().as_nanos()).unwrap_or(i64::MAX)
        });
        self.now_ns.saturating_add(elapsed_ns)
    }

    /// The absolute offset of an operand.
    #[inline(always)]
    pub(crate) fn at(&self, addr: Addr) -> usize {
        self.bases[usize::from(addr.base)] + addr.offset as usize
    }

    /// Reads a value.
    #[inline(always)]
    pub(crate) fn get<T: Scalar>(&self, addr: Addr) -> Result<T, FaultKind> {
        let at = self.at(addr);
        match self.mem.get(at..at + T::SIZE) {
            Some(bytes) => Ok(T::read(bytes)),
            None => Err(FaultKind::Memory),
        }
    }

    /// Writes a value.
    #[inline(always)]
    pub(crate) fn set<T: Scalar>(&mut self, addr: Addr, value: T) -> Result<(), FaultKind> {
        let at = self.at(addr);
        match self.mem.get_mut(at..at + T::SIZE) {
            Some(bytes) => {
                value.write(bytes);
                Ok(())
            }
            None => Err(FaultKind::Memory),
        }
    }

    /// Copies `size` bytes between absolute offsets.
    pub(crate) fn copy(&mut self, dst: usize, src: usize, size: usize) -> Result<(), FaultKind> {
        if src.checked_add(size).is_none_or(|end| end > self.mem.len())
            || dst.checked_add(size).is_none_or(|end| end > self.mem.len())
        {
            return Err(FaultKind::Memory);
        }
        self.mem.copy_within(src..src + size, dst);
        Ok(())
    }

    /// The pointer value of an absolute offset.
    pub(crate) fn pointer_to(&self, at: usize) -> u64 {
        self.regions.pointer_to(at, self.stack_end)
    }

    /// The absolute offset a pointer refers to, checked for `size` bytes.
    pub(crate) fn deref(&self, pointer: u64, size: usize) -> Result<usize, FaultKind> {
        self.regions.resolve(pointer, size, self.stack_end)
    }

    /// Counts the backward jump at instruction `pc`, and looks at the clock every so often. A
    /// safe point: a task of higher priority that is due runs here. Says whether the task
    /// may halt now, after what was served while it was interrupted.
    #[inline(always)]
    pub(super) fn tick(&mut self, pc: usize) -> Result<bool, FaultKind> {
        let watched = self.safe_point(pc)?;
        self.budget -= 1;
        self.look_at_the_clock()?;
        Ok(watched)
    }

    /// When the budget of backward jumps is spent: its reset, and the watchdog's look at the
    /// clock. Generated code counts the budget itself and calls this through its tick.
    #[inline(always)]
    pub(super) fn look_at_the_clock(&mut self) -> Result<(), FaultKind> {
        if self.budget == 0 {
            self.budget = WATCHDOG_STRIDE;
            if let Some((deadline, limit_us)) = self.deadline
                && Instant::now() > deadline
            {
                return Err(FaultKind::Watchdog { limit_us });
            }
        }
        Ok(())
    }

    /// Lets the tasks of higher priority that are due run, when the alarm says one may be;
    /// `at` is the instruction of the current POU the task stands at. Says whether the task
    /// may halt now, after what was served meanwhile; fails with [`FaultKind::Abandoned`] when
    /// the scheduler abandoned the cycles in progress meanwhile (a stop while a task is
    /// halted).
    #[inline(always)]
    pub(super) fn safe_point(&mut self, at: usize) -> Result<bool, FaultKind> {
        if self.due.load(Ordering::Relaxed) {
            return self.preempt(at);
        }
        Ok(false)
    }

    /// Lends the memory to the scheduler, which runs the due tasks of higher priority on it
    /// (and, while a task is halted, serves its commands), and moves the watchdog's deadline by
    /// the time they took: the watchdog counts this cycle's own time. With the debugger, the
    /// innermost frame first notes instruction `at`, so a client sees where the waiting task
    /// stands; returns whether the task may halt now (a step, run to cursor, halt or a
    /// breakpoint it can reach was given meanwhile), so the POU goes on in the debug form.
    #[cold]
    #[inline(never)]
    fn preempt(&mut self, at: usize) -> Result<bool, FaultKind> {
        let Some(hook) = self.hook.as_deref_mut() else {
            return Ok(false);
        };
        if self.debugging {
            self.debug.note_position(self.task, at as u32);
        }
        let paused = Instant::now();
        hook.preempt(EngineView {
            image: self.image,
            regions: self.regions,
            code: self.code,
            memory: &mut *self.mem,
            motion: &mut *self.motion,
            debug: &mut *self.debug,
        });
        if let Some((deadline, _)) = &mut self.deadline {
            *deadline += paused.elapsed();
        }
        // A cycle beneath or above a halted one ends with it: a stop is not kept waiting by a
        // cycle that loops.
        if self.debug.abandoning() {
            return Err(FaultKind::Abandoned);
        }
        // Requests served meanwhile (above a halt) may have given the task a step, a halt
        // or a breakpoint it can reach: the POU goes on in the debug form.
        Ok(self.debugging && self.debug.may_halt(self.task))
    }

    /// Runs POU `index` with the current bases, called from instruction `call_site` of the
    /// POU that calls it (0 for a task's program).
    pub(crate) fn run(&mut self, index: usize, call_site: u32) -> Result<(), FaultKind> {
        // The one cost of the debugger in a cycle that runs without it: this test per call.
        if self.debugging {
            return self.run_watched(index, call_site);
        }
        let code = self.code;
        // The one dispatch between the engines (`docs/native-engine.md` §1.3): a cycle
        // without the debugger runs each POU that has machine code natively.
        if let Some(native) = &code.native
            && native.has(index as u32)
        {
            return self.run_native(native, index);
        }
        let Some(pou) = code.pous.get(index) else {
            return Err(FaultKind::Memory);
        };
        let ops = &pou.ops;
        let mut pc = 0usize;
        while let Some(op) = ops.get(pc) {
            match op(self) {
                Ok(Flow::Next | Flow::NextWatched) => pc += 1,
                Ok(Flow::Jump(target)) => {
                    let target = target as usize;
                    if target <= pc
                        && let Err(fault) = self.tick(pc)
                    {
                        self.fault_at.get_or_insert((index, pc));
                        return Err(fault);
                    }
                    pc = target;
                }
                Ok(Flow::Return) => break,
                Err(fault) => {
                    self.fault_at.get_or_insert((index, pc));
                    return Err(*fault);
                }
            }
        }
        Ok(())
    }

    /// Pushes a frame for POU `index`, called from instruction `call_site` of its caller,
    /// initialised from its template, and returns its start. Every call does, so this is a
    /// safe point.
    pub(crate) fn push_frame(&mut self, index: usize, call_site: u32) -> Result<usize, FaultKind> {
        self.safe_point(call_site as usize)?;
        let code = self.code;
        let pou = code.pous.get(index).ok_or(FaultKind::Memory)?;
        let frame = self.sp;
        let end = frame + pou.frame_size;
        let native_depth = self.native_base.abs_diff(stack_position());
        if end > self.stack_end
            || self.depth >= MAX_CALL_DEPTH
            || native_depth > NATIVE_STACK_BUDGET
        {
            return Err(FaultKind::StackOverflow);
        }
        self.prepare_frame(index, frame)?;
        self.sp = end;
        self.depth += 1;
        Ok(frame)
    }

    /// Zeroes the frame of POU `index` at `frame` and writes its initial values.
    pub(super) fn prepare_frame(&mut self, index: usize, frame: usize) -> Result<(), FaultKind> {
        let code = self.code;
        let pou = code.pous.get(index).ok_or(FaultKind::Memory)?;
        let end = frame.checked_add(pou.frame_size).ok_or(FaultKind::Memory)?;
        let bytes = self.mem.get_mut(frame..end).ok_or(FaultKind::Memory)?;
        bytes.fill(0);
        for (offset, init) in &pou.frame_init {
            if let Some(place) = bytes.get_mut(*offset..*offset + init.len()) {
                place.copy_from_slice(init);
            }
        }
        Ok(())
    }

    /// The lowest native stack pointer generated code may call from: the same bound
    /// [`Exec::push_frame`] measures against, so a cycle that mixes engines is bounded once.
    pub(super) fn native_stack_limit(&self) -> u64 {
        self.native_base.saturating_sub(NATIVE_STACK_BUDGET) as u64
    }

    /// Undoes the depth count of [`Exec::push_frame`].
    pub(crate) fn pop_depth(&mut self) {
        self.depth = self.depth.saturating_sub(1);
    }

    /// Runs POU `index` on the instance at `instance` with a new frame, called from
    /// instruction `call_site` of its caller (0 for a task's program).
    pub(crate) fn call_block(
        &mut self,
        index: usize,
        instance: usize,
        call_site: u32,
    ) -> Result<Flow, FaultKind> {
        let saved = (self.bases, self.sp);
        let frame = self.push_frame(index, call_site)?;
        self.bases = [0, instance, frame];
        let result = self.run(index, call_site);
        self.bases = saved.0;
        self.sp = saved.1;
        self.pop_depth();
        result.map(|()| self.after_call())
    }

    /// How the caller goes on after a call returned: in the debug form from its next
    /// instruction when the task came to be watched during the call (a step out of the
    /// callee, for one), else as it was.
    #[inline(always)]
    pub(crate) fn after_call(&self) -> Flow {
        if self.debugging && self.debug.watched(self.task) {
            Flow::NextWatched
        } else {
            Flow::Next
        }
    }
}
