//! The only module with `unsafe` code (`docs/native-engine.md` §1.1, §7): the POU functions'
//! pointer type and its transmute, [`Code::run`](crate::Code::run)'s call into generated code,
//! the `extern "C"` callback shims, the memory provider that counts code bytes, and the
//! freeing of the code when it is dropped.
//!
//! Every `unsafe` block names the rules of §7 (listed in the crate's documentation) it relies on.

#![allow(unsafe_code)]

use std::ffi::c_void;
use std::io;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::{Arc, Mutex};

use cranelift_codegen::ir::Signature;
use cranelift_jit::{
    BranchProtection, JITMemoryKind, JITMemoryProvider, JITModule, SystemMemoryProvider,
};
use cranelift_module::{FuncId, Module, ModuleResult};

use crate::context::Context;
use crate::layout::Layout;
use crate::{Counters, Entry, Host, NativeFault, Site, Status};

/// The one signature of every POU function (§4.1, rule 7).
type PouFunction = unsafe extern "C" fn(*mut Context, u64, u64) -> u32;

/// A finalised POU function. Function pointers are `Send` and `Sync`; the code they point to
/// is immutable after `finalize_definitions` and lives as long as the [`MachineCode`] that
/// made it (rule 6, rule 8).
#[derive(Clone, Copy)]
struct PouEntry(PouFunction);

impl PouEntry {
    /// The function at `address`.
    ///
    /// # Safety
    ///
    /// `address` must be what `JITModule::get_finalized_function` returned for a function
    /// declared and defined with the signature of `translate::pou_signature` (rule 7), and the
    /// result must not be called after that module's memory is freed (rule 6).
    unsafe fn from_finalized(address: *const u8) -> Self {
        // SAFETY: the caller promises rule 7: the address is a function of the platform's C
        // convention with this type's parameters and result.
        Self(unsafe { std::mem::transmute::<*const u8, PouFunction>(address) })
    }
}

/// The code module of one image with its POU functions, owned until the [`crate::Code`]
/// holding it is dropped, and the only way into its code: [`MachineCode::run`] checks the
/// bases of §7 rule 2 before it enters a function.
pub(crate) struct MachineCode {
    /// The module, behind a lock only so that `MachineCode` is `Sync` (it is never locked
    /// while code runs: the code is immutable once finalised).
    module: Mutex<Option<JITModule>>,
    /// Per POU of the image: its function, when it has one.
    functions: Vec<Option<PouEntry>>,
    /// Per POU: instance and frame sizes in bytes.
    sizes: Vec<(u64, u64)>,
    /// Where the regions lie in the engine's memory.
    layout: Layout,
}

impl MachineCode {
    /// Takes ownership of a finalised module whose POU `i` is the function `defined[i]`. A
    /// function not declared with `signature` (which would be a translator bug) gets no
    /// entry, so it can never be called with the wrong signature.
    pub(crate) fn new(
        module: JITModule,
        defined: &[Option<FuncId>],
        signature: &Signature,
        sizes: Vec<(u64, u64)>,
        layout: Layout,
    ) -> Self {
        let functions = defined
            .iter()
            .map(|id| {
                let id = (*id)?;
                let declared = &module.declarations().get_function_decl(id).signature;
                (declared == signature).then(|| {
                    let address = module.get_finalized_function(id);
                    // SAFETY: rule 7: the function was declared with the POU signature, just
                    // checked, and defined in this module, which `finalize_definitions`
                    // finalised; rule 6: the entry lives in this `MachineCode`, which frees the
                    // module only when it is dropped.
                    unsafe { PouEntry::from_finalized(address) }
                })
            })
            .collect();
        Self {
            module: Mutex::new(Some(module)),
            functions,
            sizes,
            layout,
        }
    }

    /// Whether POU `pou` has a function.
    pub(crate) fn has(&self, pou: u32) -> bool {
        matches!(self.functions.get(pou as usize), Some(Some(_)))
    }

    /// Runs POU `pou`'s function on the host's memory, from `entry`; see
    /// [`crate::Code::run`]. The memory is borrowed from the host once: the bases are checked
    /// against that borrow's length and the code runs on that borrow's address (rule 2).
    pub(crate) fn run(
        &self,
        pou: u32,
        host: &mut dyn Host,
        entry: &Entry<'_>,
        counters: &mut Counters,
    ) -> Status {
        let mut cell = HostCell {
            host,
            panicked: None,
        };
        // The one borrow of the memory the entry's checks and the generated code share; it
        // is taken through the cell, whose address the context keeps, so the shims' later
        // borrows derive from the same reference (rule 3).
        let memory = cell.host.memory();
        let (memory_address, memory_len) = (memory.as_mut_ptr(), memory.len() as u64);
        let checked = match self.check(pou, memory_len, entry) {
            Ok(checked) => checked,
            Err(fault) => {
                let site = Site {
                    pou,
                    instruction: 0,
                };
                cell.host.fault(site, fault);
                return Status::Faulted;
            }
        };
        let mut context = Context {
            memory: memory_address,
            memory_len: checked.memory_len,
            spans: checked.spans,
            stack_end: entry.stack_end,
            native_stack_limit: entry.native_stack_limit,
            due: std::ptr::from_ref(entry.due),
            host: std::ptr::from_mut(&mut cell).cast::<c_void>(),
            now_ns: entry.now_ns,
            depth: counters.depth,
            budget: counters.budget,
        };
        // SAFETY: rules 1 and 2: `check` found the layout's regions, the spans, the instance
        // and the frame inside the memory of `memory_len` bytes at `memory_address`, the
        // borrow just taken and not used since; rule 3: the shims refresh the address after
        // every callback and end the code if the memory shrank; rule 4: the cell lives on this
        // stack for the whole call; rule 6: the function belongs to this `MachineCode`,
        // borrowed for the call; rule 7: its signature was checked in `new`.
        let status = unsafe { (checked.function.0)(&mut context, entry.instance, entry.frame) };
        counters.depth = context.depth;
        counters.budget = context.budget;
        Status::from_code(status)
    }

    /// The checks of §7 rule 2 on entry, against a memory of `memory_len` bytes: the only
    /// place a [`Checked`] is made. A POU without a function, or bases outside the memory
    /// (the checks of the interpreter's `push_frame`), are `Memory`, a frame past the stack's
    /// end `StackOverflow`.
    fn check(&self, pou: u32, memory_len: u64, entry: &Entry<'_>) -> Result<Checked, NativeFault> {
        let index = pou as usize;
        let (Some(Some(function)), Some((instance_size, frame_size))) =
            (self.functions.get(index), self.sizes.get(index))
        else {
            return Err(NativeFault::Memory);
        };
        let regions_inside = self.layout.total <= memory_len;
        let stack_inside = entry.stack_end <= memory_len;
        let instance_inside = entry
            .instance
            .checked_add(*instance_size)
            .is_some_and(|end| end <= memory_len);
        if !(regions_inside && stack_inside && instance_inside) {
            return Err(NativeFault::Memory);
        }
        let frame_inside = entry
            .frame
            .checked_add(*frame_size)
            .is_some_and(|end| end <= entry.stack_end);
        if !frame_inside {
            return Err(NativeFault::StackOverflow);
        }
        Ok(Checked {
            function: *function,
            spans: self.layout.spans(entry.stack_end),
            memory_len,
        })
    }
}

/// Frees the memory of a module none of whose code was ever called: one refused after
/// `finalize_definitions`, or one whose finalising failed (dropping a `JITModule` leaks its
/// mappings by design).
pub(crate) fn discard(module: JITModule) {
    // SAFETY: rule 6: a POU function is made only by `MachineCode::new`, which takes the
    // module, so no function of this one was ever made, let alone called.
    unsafe { module.free_memory() };
}

impl Drop for MachineCode {
    fn drop(&mut self) {
        let module = match self.module.get_mut() {
            Ok(module) => module.take(),
            Err(poisoned) => poisoned.into_inner().take(),
        };
        if let Some(module) = module {
            // SAFETY: rule 6: the function pointers never leave this `MachineCode`, and `run`
            // borrows it for the whole call, so none of this module's code can be running or
            // be called after this.
            unsafe { module.free_memory() };
        }
    }
}

/// The system's memory provider, counting every byte allocated for the module (§9.2) and
/// telling when its memory is freed.
pub(crate) struct CountingMemory {
    /// The provider that maps the memory.
    inner: SystemMemoryProvider,
    /// Bytes allocated so far, shared with the `Code` that reports them.
    bytes: Arc<AtomicU64>,
    /// Set once the memory is unmapped, shared with the `Code`'s `freed_flag`.
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

/// What [`MachineCode::check`] found true of an entry, made nowhere else: the function to
/// enter, the spans of the running task and the memory length the bases were checked
/// against.
struct Checked {
    /// The function.
    function: PouEntry,
    /// The spans by pointer tag.
    spans: [[u64; 2]; 8],
    /// The length of the memory borrow the checks used.
    memory_len: u64,
}

/// What the context's `host` field points at: the host lent for one entry, and whether a
/// callback without a site of its own panicked (§4.3), so that the fault generated code then
/// records at its instruction says so.
struct HostCell<'h> {
    /// The host.
    host: &'h mut dyn Host,
    /// The panic's message when `rivet_jit_copy`'s callback panicked, until the fault
    /// generated code then records takes it.
    panicked: Option<String>,
}

/// Runs one callback with the host and the counters of the context, then refreshes the
/// memory's address from the host (rule 3). Returns `Faulted` (after recording `Memory` at
/// `site`, when there is one) if the host's memory became shorter than the code may address.
/// A panic in the host is caught here, never unwound into generated code: it is recorded with
/// its message through [`Host::host_panicked`] at `site` (or its message kept in the cell for
/// the fault generated code records next) and the callback is `Faulted`.
///
/// # Safety
///
/// `context` must be the pointer [`MachineCode::run`] passed to the generated code that is
/// calling this shim, during that call (rule 4).
unsafe fn with_host(
    context: *mut Context,
    site: Option<Site>,
    callback: impl FnOnce(&mut dyn Host, &mut Counters) -> Status,
) -> u32 {
    // SAFETY: rule 4: the caller passes the context `run` made, which lives on `run`'s stack
    // for the whole call, and generated code is suspended while this runs (one thread), so
    // this is the only reference to it.
    let context = unsafe { &mut *context };
    // SAFETY: as above: `host` is the `*mut HostCell` `run` stored, alive for the same time.
    let cell = unsafe { &mut *context.host.cast::<HostCell<'_>>() };
    let mut counters = Counters {
        depth: context.depth,
        budget: context.budget,
    };
    let host = &mut *cell.host;
    let outcome = catch_unwind(AssertUnwindSafe(|| {
        let status = callback(&mut *host, &mut counters);
        let memory = host.memory();
        (status, memory.as_mut_ptr(), memory.len() as u64)
    }));
    context.depth = counters.depth;
    context.budget = counters.budget;
    let (mut status, memory_address, memory_len) = match outcome {
        Ok(outcome) => outcome,
        Err(payload) => {
            // The memory's address is not refreshed: generated code returns at once and
            // reads no memory on its way out.
            let message = panic_message(payload);
            match site {
                Some(site) => record_panic(host, site, &message),
                None => cell.panicked = Some(message),
            }
            return Status::Faulted as u32;
        }
    };
    context.memory = memory_address;
    if memory_len < context.memory_len {
        // Generated code was checked against the old length; it must not run on.
        if let Some(site) = site {
            record(host, site, NativeFault::Memory);
        }
        status = Status::Faulted;
    }
    status as u32
}

/// Records `fault` at `site`; a panic in the host's `fault` is swallowed (the callback is
/// `Faulted` anyway, and no panic may cross into generated code).
fn record(host: &mut dyn Host, site: Site, fault: NativeFault) {
    let _ = catch_unwind(AssertUnwindSafe(|| host.fault(site, fault)));
}

/// Records at `site` that a callback panicked with `message`, swallowing a panic of the host's
/// own as [`record`] does.
fn record_panic(host: &mut dyn Host, site: Site, message: &str) {
    let _ = catch_unwind(AssertUnwindSafe(|| host.host_panicked(site, message)));
}

/// The text of a caught panic (`panic!` with a literal or a formatted message), or a note that
/// it had none. The payload is dropped under `catch_unwind` too: a payload whose `Drop` panics
/// must not unwind into generated code either, and is leaked instead.
fn panic_message(payload: Box<dyn std::any::Any + Send>) -> String {
    let message = if let Some(text) = payload.downcast_ref::<&str>() {
        (*text).to_owned()
    } else if let Some(text) = payload.downcast_ref::<String>() {
        text.clone()
    } else {
        "a panic without a message".to_owned()
    };
    if let Err(again) = catch_unwind(AssertUnwindSafe(|| drop(payload))) {
        std::mem::forget(again);
    }
    message
}

/// `rivet_jit_tick` (§4.3).
///
/// # Safety
///
/// Called only by generated code, with the context it was entered with.
unsafe extern "C" fn rivet_jit_tick(context: *mut Context, pou: u32, pc: u32) -> u32 {
    let site = Site {
        pou,
        instruction: pc,
    };
    // SAFETY: this function's own precondition is `with_host`'s.
    unsafe {
        with_host(context, Some(site), |host, counters| {
            host.tick(site, counters)
        })
    }
}

/// `rivet_jit_preempt` (§4.3).
///
/// # Safety
///
/// Called only by generated code, with the context it was entered with.
unsafe extern "C" fn rivet_jit_preempt(context: *mut Context, pou: u32, pc: u32) -> u32 {
    let site = Site {
        pou,
        instruction: pc,
    };
    // SAFETY: this function's own precondition is `with_host`'s.
    unsafe {
        with_host(context, Some(site), |host, counters| {
            host.preempt(site, counters)
        })
    }
}

/// `rivet_jit_op` (§4.3).
///
/// # Safety
///
/// Called only by generated code, with the context it was entered with.
unsafe extern "C" fn rivet_jit_op(
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
    // SAFETY: this function's own precondition is `with_host`'s.
    unsafe {
        with_host(context, Some(site), |host, counters| {
            host.op(site, instance, frame, counters)
        })
    }
}

/// `rivet_jit_fault` (§4.3, §4.7): a fault found by generated code, or, when the callback it
/// follows panicked, that panic with its message ([`Host::host_panicked`]).
///
/// # Safety
///
/// Called only by generated code, with the context it was entered with.
unsafe extern "C" fn rivet_jit_fault(
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
    // SAFETY: as in `with_host`: `context` is `run`'s, and its `host` field `run`'s cell;
    // the reference ends with this statement, before `with_host` takes the cell again.
    let panicked = unsafe { (*(*context).host.cast::<HostCell<'_>>()).panicked.take() };
    // SAFETY: this function's own precondition is `with_host`'s.
    unsafe {
        with_host(context, None, |host, _| {
            match &panicked {
                Some(message) => host.host_panicked(site, message),
                None => host.fault(site, NativeFault::from_code(kind, a, b, c)),
            }
            Status::Faulted
        })
    };
}

/// `rivet_jit_copy` (§4.3).
///
/// # Safety
///
/// Called only by generated code, with the context it was entered with.
unsafe extern "C" fn rivet_jit_copy(context: *mut Context, to: u64, from: u64, bytes: u64) -> u32 {
    // SAFETY: this function's own precondition is `with_host`'s.
    unsafe { with_host(context, None, |host, _| host.copy(to, from, bytes)) }
}

/// `rivet_jit_frame` (§4.3).
///
/// # Safety
///
/// Called only by generated code, with the context it was entered with.
unsafe extern "C" fn rivet_jit_frame(context: *mut Context, pou: u32, frame: u64) -> u32 {
    // SAFETY: this function's own precondition is `with_host`'s.
    unsafe { with_host(context, None, |host, _| host.frame(pou, frame)) }
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
