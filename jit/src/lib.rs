//! The native engine: verified program images translated function by function into machine
//! code with Cranelift, run on the interpreter's memory (`docs/native-engine.md`).
//!
//! [`Translation::new`] turns a [`program_image::ProgramImage`] into a [`Code`]: one machine
//! function per POU it accepts, and an [`Untranslated`] entry for each POU it leaves to the
//! interpreter; the functions are compiled on several threads when the image has many
//! (`docs/native-engine.md` §9.3), into the same machine code as on one. [`Code::run`] enters
//! one POU function with an [`Entry`]; generated code calls back into the runtime through the
//! [`Host`] trait for safe points, the watchdog, the instructions it leaves to the
//! interpreter, copies larger than 64 bytes and faults.
//!
//! # The invariants this crate keeps (`docs/native-engine.md` §7)
//!
//! 1. Every memory access of generated code lies inside the engine's memory: direct operands
//!    are verified inside their regions, the instance and frame bases are checked when a POU
//!    function is entered ([`Code::run`]), pointers are resolved against the region spans, and
//!    element accesses check their index.
//! 2. Bases are checked once per entry, not per access.
//! 3. No address survives a call: generated code holds offsets, and reloads the memory's
//!    address from its context after every call, which the callbacks refresh from
//!    [`Host::memory`].
//! 4. The host is reached only through the callback shims of the `machine` module.
//! 5. No reachable trap: no `trap`, no trapping conversion, no memory access without `notrap`,
//!    and no division before the translator's own divisor checks.
//! 6. Code outlives every call: the machine code is freed only when [`Code`] is dropped.
//! 7. Every POU function has the one signature the `machine` module calls.
//! 8. [`Code`] is `Send` and `Sync`: the machine code is immutable once finalised.
//!
//! All `unsafe` code of the workspace is in the `machine` module; the translator is part of
//! the same audit boundary, because the soundness of calling generated code rests on what it
//! emits.

use std::sync::atomic::AtomicBool;

mod compile;
mod context;
mod isa;
mod layout;
mod machine;
mod module;
mod translate;

pub use isa::{NativeUnsupported, SettingsError, native_support};
pub use layout::Layout;
pub use module::{Code, Translation, Untranslated};
pub use translate::host_calls::{
    OUR_SYMBOLS, PureFunctions, binary_op_code, binary_op_from_code, unary_op_code,
    unary_op_from_code,
};

/// The limit of nested calls generated code enforces (`docs/native-engine.md` §4.4, the entry stub's depth check):
/// a call made at this depth or deeper is `StackOverflow`. It must equal the interpreter's
/// `MAX_CALL_DEPTH` (`runtime/src/engine/exec.rs`), and the runtime asserts that it does, so
/// that both engines fault at the same call.
pub const MAX_CALL_DEPTH: u32 = 2000;

/// What a POU function, a callback or [`Code::run`] returns (`docs/native-engine.md` §4.1).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u32)]
pub enum Status {
    /// The code ran to its end.
    Ok = 0,
    /// A fault stopped it; the host has recorded the fault and its site.
    Faulted = 1,
}

impl Status {
    /// The status of a number generated code returned: anything but 0 is a fault.
    pub(crate) fn from_code(code: u32) -> Self {
        if code == 0 { Self::Ok } else { Self::Faulted }
    }
}

/// Where something happens: a POU index and an instruction index in it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Site {
    /// The POU's index in the image.
    pub pou: u32,
    /// The instruction's index in the POU.
    pub instruction: u32,
}

/// The counters that travel with control between the engines (`docs/native-engine.md` §4.2).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Counters {
    /// Calls nested, as the interpreter counts them.
    pub depth: u32,
    /// Backward jumps left before the watchdog looks at the clock.
    pub budget: u32,
}

/// A fault a check in generated code found (`docs/native-engine.md` §4.7); the host turns it
/// into the runtime's fault kind.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NativeFault {
    /// Integer `DIV` or `MOD` by zero.
    DivisionByZero,
    /// An array index outside its bounds.
    IndexOutOfBounds {
        /// The index, sign-extended as the interpreter reads it.
        index: i64,
        /// The lowest index.
        low: i64,
        /// The highest index.
        high: i64,
    },
    /// A pointer of tag 0 resolved or moved.
    NullPointer,
    /// A pointer outside its region, or of an unknown tag.
    BadPointer(u64),
    /// A call beyond the stack, the call depth or the native stack.
    StackOverflow,
    /// A base outside the memory.
    Memory,
    /// A [`Host`] method panicked during a callback; the panic was caught in the callback's
    /// shim, never unwound into generated code (the runtime records it as an internal fault,
    /// `docs/native-engine.md` §4.3).
    HostPanicked,
}

impl NativeFault {
    /// The fault of the numbers generated code passes to `rivet_jit_fault` (the `kind`
    /// column of §4.7); an unknown kind is [`NativeFault::Memory`], which it cannot be.
    pub(crate) fn from_code(kind: u32, a: u64, b: u64, c: u64) -> Self {
        match kind {
            1 => Self::DivisionByZero,
            2 => Self::IndexOutOfBounds {
                index: a as i64,
                low: b as i64,
                high: c as i64,
            },
            3 => Self::NullPointer,
            4 => Self::BadPointer(a),
            5 => Self::StackOverflow,
            _ => Self::Memory,
        }
    }
}

/// The numbers of §4.7's `kind` column, as the translator emits them.
pub(crate) mod fault_kind {
    /// [`super::NativeFault::DivisionByZero`].
    pub const DIVISION_BY_ZERO: u32 = 1;
    /// [`super::NativeFault::IndexOutOfBounds`].
    pub const INDEX_OUT_OF_BOUNDS: u32 = 2;
    /// [`super::NativeFault::NullPointer`].
    pub const NULL_POINTER: u32 = 3;
    /// [`super::NativeFault::BadPointer`].
    pub const BAD_POINTER: u32 = 4;
    /// [`super::NativeFault::StackOverflow`].
    pub const STACK_OVERFLOW: u32 = 5;
    /// [`super::NativeFault::Memory`].
    pub const MEMORY: u32 = 6;
}

/// Where a POU function starts: its bases and the task's bounds (`docs/native-engine.md` §4.1).
#[derive(Clone, Copy, Debug)]
pub struct Entry<'a> {
    /// The instance's offset in the engine's memory.
    pub instance: u64,
    /// The frame's offset in the engine's memory.
    pub frame: u64,
    /// The end offset of the running task's stack.
    pub stack_end: u64,
    /// The lowest native stack pointer a call may start from.
    pub native_stack_limit: u64,
    /// The preemption flag.
    pub due: &'a AtomicBool,
    /// The task clock in nanoseconds.
    pub now_ns: i64,
}

/// The runtime's side of generated code: what it calls back (`docs/native-engine.md` §4.3).
///
/// Every method but [`Host::memory`] receives control while generated code is suspended; the
/// memory borrowed from [`Host::memory`] before is not used again until the method returns
/// and generated code has asked for the memory's address anew.
pub trait Host {
    /// The engine's memory, reborrowed.
    fn memory(&mut self) -> &mut [u8];
    /// A backward jump found the preemption flag set or the budget at 0: the safe point, and
    /// when the budget is 0 its reset and the deadline test.
    fn tick(&mut self, site: Site, counters: &mut Counters) -> Status;
    /// A call found the preemption flag set: the safe point at the call site.
    fn preempt(&mut self, site: Site, counters: &mut Counters) -> Status;
    /// Runs the instruction at `site` in the interpreter, with `instance` and `frame` as the
    /// bases, and records its fault if it has one.
    fn op(&mut self, site: Site, instance: u64, frame: u64, counters: &mut Counters) -> Status;
    /// Records a fault generated code found at `site`.
    fn fault(&mut self, site: Site, fault: NativeFault);
    /// Records that a callback at `site` panicked with `message` (the panic's text, or a
    /// note that it had none), caught in its shim (`docs/native-engine.md` §4.3). The default
    /// records [`NativeFault::HostPanicked`] through [`Host::fault`], without the message; a
    /// host that shows faults to a user keeps the message, which says what went wrong.
    fn host_panicked(&mut self, site: Site, message: &str) {
        let _ = message;
        self.fault(site, NativeFault::HostPanicked);
    }
    /// Copies `bytes` bytes from offset `from` to offset `to` as `memmove` does; `Faulted`
    /// (without recording anything) when either range is outside the memory.
    fn copy(&mut self, to: u64, from: u64, bytes: u64) -> Status;
    /// Prepares a new frame of POU `pou` at offset `frame`: zeroed, then its initial runs.
    fn frame(&mut self, pou: u32, frame: u64) -> Status;
}
