//! The only module with `unsafe` code (`docs/native-engine.md` §1.1, §7): the POU functions'
//! pointer type and its transmute, [`Code::run`](crate::Code::run)'s call into generated code,
//! the `extern "C"` callback shims, the memory provider that counts code bytes, and the
//! freeing of the code when it is dropped.
//!
//! Every `unsafe` block names the rules of §7 (listed in the crate's documentation) it relies on.

#![allow(unsafe_code)]

use std::ffi::c_void;
use std::io;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::{Arc, Mutex};

use cranelift_jit::{
    BranchProtection, JITMemoryKind, JITMemoryProvider, JITModule, SystemMemoryProvider,
};
use cranelift_module::ModuleResult;

use crate::context::Context;
use crate::{Counters, Entry, Host, NativeFault, Site, Status};

/// The one signature of every POU function (§4.1, rule 7).
type PouFunction = unsafe extern "C" fn(*mut Context, u64, u64) -> u32;

/// A finalised POU function. Function pointers are `Send` and `Sync`; the code they point to
/// is immutable after `finalize_definitions` and lives as long as the [`MachineCode`] that
/// made it (rule 6, rule 8).
#[derive(Clone, Copy)]
pub(crate) struct PouEntry(PouFunction);

impl PouEntry {
    /// The function at `address`, which `JITModule::get_finalized_function` returned for a
    /// function declared with the POU signature.
    pub(crate) fn from_finalized(address: *const u8) -> Self {
        // SAFETY: rule 7: every POU function is declared and defined with the one signature
        // of `translate::pou_signature`, which is the platform's C convention of this type.
        Self(unsafe { std::mem::transmute::<*const u8, PouFunction>(address) })
    }
}

/// The code module, owned until the [`crate::Code`] holding it is dropped.
pub(crate) struct MachineCode {
    module: Mutex<Option<JITModule>>,
}

impl MachineCode {
    /// Takes ownership of a finalised module.
    pub(crate) fn new(module: JITModule) -> Self {
        Self {
            module: Mutex::new(Some(module)),
        }
    }
}

impl Drop for MachineCode {
    fn drop(&mut self) {
        let module = match self.module.get_mut() {
            Ok(module) => module.take(),
            Err(poisoned) => poisoned.into_inner().take(),
        };
        if let Some(module) = module {
            // SAFETY: rule 6: the function pointers never leave `Code`, and `Code::run`
            // borrows the `Code` for the whole call, so none of this module's code can be
            // running or be called after this.
            unsafe { module.free_memory() };
        }
    }
}

/// The system's memory provider, counting every byte allocated for the module (§9.2) and
/// telling when its memory is freed.
pub(crate) struct CountingMemory {
    inner: SystemMemoryProvider,
    bytes: Arc<AtomicU64>,
    freed: Arc<AtomicBool>,
}

impl CountingMemory {
    /// A provider adding to `bytes` and setting `freed` when it unmaps its memory.
    pub(crate) fn new(bytes: Arc<AtomicU64>, freed: Arc<AtomicBool>) -> Self {
        Self {
            inner: SystemMemoryProvider::new(),
            bytes,
            freed,
        }
    }
}

impl JITMemoryProvider for CountingMemory {
    fn allocate(&mut self, size: usize, align: u64, kind: JITMemoryKind) -> io::Result<*mut u8> {
        // The size with its alignment: what the module's text and data take at most.
        self.bytes
            .fetch_add(size as u64 + align.saturating_sub(1), Ordering::Relaxed);
        self.inner.allocate(size, align, kind)
    }

    unsafe fn free_memory(&mut self) {
        // SAFETY: the caller (`JITModule::free_memory`, called only by `MachineCode::drop`)
        // promises that no code of the module runs or is called again (rule 6).
        unsafe { self.inner.free_memory() };
        self.freed.store(true, Ordering::Relaxed);
    }

    fn finalize(&mut self, branch_protection: BranchProtection) -> ModuleResult<()> {
        self.inner.finalize(branch_protection)
    }
}

/// What `Code::run` checked and computed before it enters generated code.
pub(crate) struct Checked {
    /// The function.
    pub(crate) function: PouEntry,
    /// The spans by pointer tag.
    pub(crate) spans: [[u64; 2]; 8],
}

/// Enters POU `pou`'s function: the context made on this stack, the host lent to the shims
/// for the call, the counters in and out (§4.2).
pub(crate) fn enter(
    checked: Checked,
    host: &mut dyn Host,
    entry: &Entry<'_>,
    counters: &mut Counters,
) -> Status {
    let memory = host.memory();
    let (memory_address, memory_len) = (memory.as_mut_ptr(), memory.len() as u64);
    let mut host_ref: &mut dyn Host = host;
    let mut context = Context {
        memory: memory_address,
        memory_len,
        spans: checked.spans,
        stack_end: entry.stack_end,
        native_stack_limit: entry.native_stack_limit,
        due: std::ptr::from_ref(entry.due),
        host: std::ptr::from_mut(&mut host_ref).cast::<c_void>(),
        now_ns: entry.now_ns,
        depth: counters.depth,
        budget: counters.budget,
    };
    // SAFETY: rules 1 and 2: the caller (`Code::run`) checked that the memory holds the
    // layout's regions, that the spans lie inside it and that the instance and frame lie
    // inside it for the POU's sizes; rule 3: `memory_address` was derived from the host's
    // last borrow of the memory, and the shims refresh it after every callback; rule 4: the
    // host reference lives on this stack for the whole call; rule 6: `checked.function`
    // belongs to a `Code` borrowed for this call; rule 7: the signature matches.
    let status = unsafe { (checked.function.0)(&mut context, entry.instance, entry.frame) };
    counters.depth = context.depth;
    counters.budget = context.budget;
    Status::from_code(status)
}

/// Runs one callback with the host and the counters of the context, then refreshes the
/// memory's address from the host (rule 3). Returns `Faulted` (after recording `Memory` at
/// `site`, when there is one) if the host's memory became shorter than the code may address.
fn with_host(
    context: *mut Context,
    site: Option<Site>,
    callback: impl FnOnce(&mut dyn Host, &mut Counters) -> Status,
) -> u32 {
    // SAFETY: rule 4: generated code passes the context `enter` made, which lives on
    // `enter`'s stack for the whole call, and generated code is suspended while this runs (one
    // thread), so this is the only reference to it; its `host` field points at `enter`'s
    // `host_ref`, alive for the same time.
    let context = unsafe { &mut *context };
    // SAFETY: as above: `host` is the `*mut &mut dyn Host` `enter` stored.
    let host = unsafe { &mut **context.host.cast::<&mut dyn Host>() };
    let mut counters = Counters {
        depth: context.depth,
        budget: context.budget,
    };
    let mut status = callback(&mut *host, &mut counters);
    context.depth = counters.depth;
    context.budget = counters.budget;
    let memory = host.memory();
    context.memory = memory.as_mut_ptr();
    if (memory.len() as u64) < context.memory_len {
        // Generated code was checked against the old length; it must not run on.
        if let Some(site) = site {
            host.fault(site, NativeFault::Memory);
        }
        status = Status::Faulted;
    }
    status as u32
}

extern "C" fn rivet_jit_tick(context: *mut Context, pou: u32, pc: u32) -> u32 {
    let site = Site {
        pou,
        instruction: pc,
    };
    with_host(context, Some(site), |host, counters| {
        host.tick(site, counters)
    })
}

extern "C" fn rivet_jit_preempt(context: *mut Context, pou: u32, pc: u32) -> u32 {
    let site = Site {
        pou,
        instruction: pc,
    };
    with_host(context, Some(site), |host, counters| {
        host.preempt(site, counters)
    })
}

extern "C" fn rivet_jit_op(
    context: *mut Context,
    pou: u32,
    pc: u32,
    instance: u64,
    frame: u64,
) -> u32 {
    let site = Site {
        pou,
        instruction: pc,
    };
    with_host(context, Some(site), |host, counters| {
        host.op(site, instance, frame, counters)
    })
}

extern "C" fn rivet_jit_fault(
    context: *mut Context,
    pou: u32,
    pc: u32,
    kind: u32,
    a: u64,
    b: u64,
    c: u64,
) {
    let site = Site {
        pou,
        instruction: pc,
    };
    with_host(context, None, |host, _| {
        host.fault(site, NativeFault::from_code(kind, a, b, c));
        Status::Faulted
    });
}

extern "C" fn rivet_jit_copy(context: *mut Context, to: u64, from: u64, bytes: u64) -> u32 {
    with_host(context, None, |host, _| host.copy(to, from, bytes))
}

extern "C" fn rivet_jit_frame(context: *mut Context, pou: u32, frame: u64) -> u32 {
    with_host(context, None, |host, _| host.frame(pou, frame))
}

/// The host callbacks with their addresses, in the order of `OUR_SYMBOLS`.
pub(crate) fn callback_symbols() -> [(&'static str, *const u8); 6] {
    [
        ("rivet_jit_tick", rivet_jit_tick as *const u8),
        ("rivet_jit_preempt", rivet_jit_preempt as *const u8),
        ("rivet_jit_op", rivet_jit_op as *const u8),
        ("rivet_jit_fault", rivet_jit_fault as *const u8),
        ("rivet_jit_copy", rivet_jit_copy as *const u8),
        ("rivet_jit_frame", rivet_jit_frame as *const u8),
    ]
}

/// What a foreign symbol resolves to while the module is finalised: never called, because a
/// module that needed one is refused before any of its code runs (`module.rs`).
extern "C" fn rivet_jit_foreign() -> u32 {
    Status::Faulted as u32
}

/// The address given for a foreign symbol.
pub(crate) fn foreign_symbol() -> *const u8 {
    rivet_jit_foreign as *const u8
}
