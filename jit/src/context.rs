//! The context generated code receives: the engine's memory, the pointer spans, the stack
//! bounds, the preemption flag, the host and the counters (`docs/native-engine.md` §4.2).

use std::ffi::c_void;
use std::mem::offset_of;
use std::sync::atomic::AtomicBool;

/// What one entry into generated code sees, made by [`crate::Code::run`] on its stack and
/// read by generated code at the fixed offsets below (192 bytes, C layout).
#[repr(C)]
#[derive(Debug)]
pub struct Context {
    /// The engine's memory; reloaded by generated code after every call.
    pub(crate) memory: *mut u8,
    /// The memory's length in bytes.
    pub(crate) memory_len: u64,
    /// Per pointer tag 0–7: start and end offsets of the region a pointer of that tag reaches.
    pub(crate) spans: [[u64; 2]; 8],
    /// End offset of the running task's stack.
    pub(crate) stack_end: u64,
    /// The lowest native stack pointer a call may start from.
    pub(crate) native_stack_limit: u64,
    /// The preemption flag, read at every safe point.
    pub(crate) due: *const AtomicBool,
    /// A `*mut &mut dyn Host` on `Code::run`'s stack.
    pub(crate) host: *mut c_void,
    /// The task clock in nanoseconds, read by `Now`.
    pub(crate) now_ns: i64,
    /// Calls nested, counted as the interpreter counts them.
    pub(crate) depth: u32,
    /// Backward jumps left before the watchdog looks at the clock.
    pub(crate) budget: u32,
}

/// Offset of [`Context::memory`].
pub(crate) const MEMORY: i32 = offset_of!(Context, memory) as i32;
/// Offset of [`Context::memory_len`].
pub(crate) const MEMORY_LEN: i32 = offset_of!(Context, memory_len) as i32;
/// Offset of [`Context::spans`].
pub(crate) const SPANS: i32 = offset_of!(Context, spans) as i32;
/// Offset of [`Context::stack_end`].
pub(crate) const STACK_END: i32 = offset_of!(Context, stack_end) as i32;
/// Offset of [`Context::native_stack_limit`].
pub(crate) const NATIVE_STACK_LIMIT: i32 = offset_of!(Context, native_stack_limit) as i32;
/// Offset of [`Context::due`].
pub(crate) const DUE: i32 = offset_of!(Context, due) as i32;
/// Offset of [`Context::now_ns`].
pub(crate) const NOW_NS: i32 = offset_of!(Context, now_ns) as i32;
/// Offset of [`Context::depth`].
pub(crate) const DEPTH: i32 = offset_of!(Context, depth) as i32;
/// Offset of [`Context::budget`].
pub(crate) const BUDGET: i32 = offset_of!(Context, budget) as i32;

// The table of docs/native-engine.md §4.2, checked when the crate compiles.
const _: () = {
    assert!(MEMORY == 0);
    assert!(MEMORY_LEN == 8);
    assert!(SPANS == 16);
    assert!(STACK_END == 144);
    assert!(NATIVE_STACK_LIMIT == 152);
    assert!(DUE == 160);
    assert!(offset_of!(Context, host) == 168);
    assert!(NOW_NS == 176);
    assert!(DEPTH == 184);
    assert!(BUDGET == 188);
    assert!(size_of::<Context>() == 192);
};
