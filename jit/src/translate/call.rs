//! Calls out of generated code (`docs/native-engine.md` §4.3, §4.4): a call of a POU with a
//! function is made inline, in the interpreter's order (`Exec::call_block`, `call_frame`,
//! `push_frame`); every other call instruction is handed to the interpreter through
//! `rivet_jit_op`, which runs the whole call (and may enter generated code again for a callee
//! further down).

use cranelift_codegen::ir::condcodes::IntCC;
use cranelift_codegen::ir::{FuncRef, InstBuilder, Value, types};
use program_image::{Operand, Transfer};

use super::host_calls::Import;
use super::{Translator, context, context_flags, memory_flags};
use crate::{MAX_CALL_DEPTH, fault_kind};

/// The largest frame prepared by inline stores; a larger one is prepared by `rivet_jit_frame`
/// (§4.4 step 5), so that a call does not grow the code by more than a few stores.
const INLINE_FRAME_BYTES: u32 = 64;

/// Where a called POU's instance comes from (§4.4 step 1).
#[derive(Clone, Copy, Debug)]
pub(crate) enum CallInstance {
    /// The caller's own instance: a function called without `instance`.
    Caller,
    /// A direct place that is the instance itself (`CallBlock` without `indirect`).
    Direct(Operand),
    /// A place holding a pointer to the instance, resolved for the callee's `instance_size`.
    Pointer(Operand),
}

impl Translator<'_, '_> {
    /// Hands the current instruction to the interpreter (`rivet_jit_op`).
    pub(crate) fn host_op(&mut self) {
        let pou = self.builder.ins().iconst(types::I32, i64::from(self.pou));
        let pc = self.builder.ins().iconst(types::I32, i64::from(self.pc));
        let status = self.call_host(
            Import::Op,
            &[self.context, pou, pc, self.instance, self.frame],
        );
        self.return_if_faulted(status);
        self.reload_promoted();
    }

    /// `CallFunction` and `CallBlock` (block calls have no transfers): inline when the callee
    /// has a function, else false, having emitted nothing, so that the instruction goes to the
    /// interpreter.
    pub(crate) fn call_function(
        &mut self,
        callee: u32,
        instance: CallInstance,
        inputs: &[Transfer],
        outputs: &[Transfer],
    ) -> bool {
        let Some(function) = self.pou_function(callee) else {
            return false;
        };
        let instance_size = self.pous[callee as usize].instance_size;
        let this = match instance {
            CallInstance::Caller => self.instance,
            CallInstance::Direct(place) => self.absolute(place),
            CallInstance::Pointer(pointer) => self.resolve(pointer, instance_size),
        };
        self.call_frame(callee, function, this, inputs, outputs);
        true
    }

    /// `CallVirtual`: the interface's pointer resolved for 0 bytes, its class compared with the
    /// table in order (the first match wins, as the interpreter's `find`), an unknown class
    /// `BadPointer(pointer)`, the pointer resolved again for the method's `instance_size`,
    /// then the call. False, having emitted nothing, when a method of the table has no
    /// function: the whole instruction then goes to the interpreter.
    pub(crate) fn call_virtual(
        &mut self,
        table: &[(u32, u32)],
        interface: Operand,
        inputs: &[Transfer],
        outputs: &[Transfer],
    ) -> bool {
        let mut functions = Vec::with_capacity(table.len());
        for (_, method) in table {
            match self.pou_function(*method) {
                Some(function) => functions.push(function),
                None => return false,
            }
        }
        let pointer = self.load(types::I64, interface);
        let class = self.load(types::I32, displaced(interface, 8));
        self.resolve(interface, 0);
        let merge = self.builder.create_block();
        for ((known, method), function) in table.iter().zip(functions) {
            let matches = self
                .builder
                .ins()
                .icmp_imm_u(IntCC::Equal, class, i64::from(*known));
            let call = self.builder.create_block();
            let next = self.builder.create_block();
            self.builder.ins().brif(matches, call, &[], next, &[]);
            self.builder.switch_to_block(call);
            let instance_size = self.pous[*method as usize].instance_size;
            let this = self.resolve(interface, instance_size);
            self.call_frame(*method, function, this, inputs, outputs);
            self.builder.ins().jump(merge, &[]);
            self.builder.switch_to_block(next);
        }
        self.record_fault(fault_kind::BAD_POINTER, [Some(pointer), None, None]);
        self.builder.switch_to_block(merge);
        true
    }

    /// The reference to POU `callee`'s function in this function, when it has one.
    fn pou_function(&mut self, callee: u32) -> Option<FuncRef> {
        if let Some(Some(known)) = self.pou_refs.get(callee as usize) {
            return Some(*known);
        }
        let id = (*self.functions.get(callee as usize)?)?;
        let reference = self.module.declare_func_in_func(id, self.builder.func);
        self.pou_refs[callee as usize] = Some(reference);
        Some(reference)
    }

    /// Steps 2 to 8 of §4.4: the safe point, the frame's checks and preparation, the input
    /// transfers, the call counted in `depth`, and the output transfers when it did not fault.
    fn call_frame(
        &mut self,
        callee: u32,
        function: FuncRef,
        this: Value,
        inputs: &[Transfer],
        outputs: &[Transfer],
    ) {
        // The analysis promotes no place in a loop that calls (§5.3), so the instance, the
        // inputs and the callee all read memory as the interpreter leaves it.
        debug_assert!(
            self.promoted.is_empty(),
            "a call inside a promoted loop (pou {}, instruction {})",
            self.pou,
            self.pc
        );
        let pous = self.pous;
        let called = &pous[callee as usize];
        let caller_frame_size = pous[self.pou as usize].frame_size;
        self.preempt_if_due();
        // During a POU's body the interpreter's `sp` is its frame's end, where the callee's
        // frame starts.
        let callee_frame = self
            .builder
            .ins()
            .iadd_imm_u(self.frame, i64::from(caller_frame_size));
        let frame_end = self
            .builder
            .ins()
            .iadd_imm_u(callee_frame, i64::from(called.frame_size));
        let stack_end = self.builder.ins().load(
            types::I64,
            context_flags(),
            self.context,
            context::STACK_END,
        );
        let past_stack = self
            .builder
            .ins()
            .icmp(IntCC::UnsignedGreaterThan, frame_end, stack_end);
        let depth =
            self.builder
                .ins()
                .load(types::I32, context_flags(), self.context, context::DEPTH);
        let too_deep = self.builder.ins().icmp_imm_u(
            IntCC::UnsignedGreaterThanOrEqual,
            depth,
            i64::from(MAX_CALL_DEPTH),
        );
        // The machine's own stack: the bound the interpreter measures against (§4.4).
        let stack_pointer = self.builder.ins().get_stack_pointer(types::I64);
        let native_limit = self.builder.ins().load(
            types::I64,
            context_flags(),
            self.context,
            context::NATIVE_STACK_LIMIT,
        );
        let native_low =
            self.builder
                .ins()
                .icmp(IntCC::UnsignedLessThan, stack_pointer, native_limit);
        let overflow = self.builder.ins().bor(past_stack, too_deep);
        let overflow = self.builder.ins().bor(overflow, native_low);
        self.fault_if(overflow, fault_kind::STACK_OVERFLOW, [None; 3]);
        // §7 rule 2: one check of the callee's bases covers every direct access of its body.
        let memory_len = self.builder.ins().load(
            types::I64,
            context_flags(),
            self.context,
            context::MEMORY_LEN,
        );
        let instance_end = self
            .builder
            .ins()
            .iadd_imm_u(this, i64::from(called.instance_size));
        let instance_outside =
            self.builder
                .ins()
                .icmp(IntCC::UnsignedGreaterThan, instance_end, memory_len);
        let frame_outside =
            self.builder
                .ins()
                .icmp(IntCC::UnsignedGreaterThan, frame_end, memory_len);
        let outside = self.builder.ins().bor(instance_outside, frame_outside);
        self.fault_if(outside, fault_kind::MEMORY, [None; 3]);
        self.prepare_frame(callee, callee_frame);
        for transfer in inputs {
            let to = self
                .builder
                .ins()
                .iadd_imm_u(callee_frame, i64::from(transfer.callee_offset));
            let from = self.absolute(transfer.caller);
            self.copy_bytes(to, from, transfer.size);
        }
        let status = self.call_counted(function, this, callee_frame);
        self.return_if_faulted(status);
        for transfer in outputs {
            let to = self.absolute(transfer.caller);
            let from = self
                .builder
                .ins()
                .iadd_imm_u(callee_frame, i64::from(transfer.callee_offset));
            self.copy_bytes(to, from, transfer.size);
        }
    }

    /// At a call, the safe point: `rivet_jit_preempt` when `due` is set (§4.5).
    fn preempt_if_due(&mut self) {
        let due_pointer =
            self.builder
                .ins()
                .load(types::I64, context_flags(), self.context, context::DUE);
        // An atomic load, read anew at every call (§4.5).
        let due = self
            .builder
            .ins()
            .atomic_load(types::I8, context_flags(), due_pointer);
        let slow = self.builder.create_block();
        let next = self.builder.create_block();
        self.builder.set_cold_block(slow);
        self.builder.ins().brif(due, slow, &[], next, &[]);
        self.builder.switch_to_block(slow);
        let pou = self.builder.ins().iconst(types::I32, i64::from(self.pou));
        let pc = self.builder.ins().iconst(types::I32, i64::from(self.pc));
        let status = self.call_host(Import::Preempt, &[self.context, pou, pc]);
        self.return_if_faulted(status);
        self.reload_promoted();
        self.builder.ins().jump(next, &[]);
        self.builder.switch_to_block(next);
    }

    /// The new frame zeroed and its `frame_init` runs written, as `push_frame` does (a run
    /// that does not fit the frame is skipped there too): by inline stores of the bytes the
    /// translation computes for a small frame, by `rivet_jit_frame` for a larger one.
    fn prepare_frame(&mut self, callee: u32, callee_frame: Value) {
        let called = &self.pous[callee as usize];
        let size = called.frame_size;
        if size == 0 {
            return;
        }
        if size > INLINE_FRAME_BYTES {
            let pou = self.builder.ins().iconst(types::I32, i64::from(callee));
            let status = self.call_host(Import::Frame, &[self.context, pou, callee_frame]);
            // Like a copy, the callback has no site: a failure is recorded here (§4.3).
            self.fault_if(status, fault_kind::MEMORY, [None; 3]);
            self.reload_promoted();
            return;
        }
        let mut bytes = vec![0u8; size as usize];
        for run in &called.frame_init {
            let start = run.offset as usize;
            let end = start.saturating_add(run.bytes.len());
            if let Some(place) = bytes.get_mut(start..end) {
                place.copy_from_slice(&run.bytes);
            }
        }
        let base = self.machine_address(callee_frame);
        let mut done = 0usize;
        while done < bytes.len() {
            let (ty, width) = match bytes.len() - done {
                8.. => (types::I64, 8),
                4.. => (types::I32, 4),
                2.. => (types::I16, 2),
                _ => (types::I8, 1),
            };
            let mut raw = [0u8; 8];
            raw[..width].copy_from_slice(&bytes[done..done + width]);
            let value = self
                .builder
                .ins()
                .iconst(ty, u64::from_le_bytes(raw) as i64);
            self.builder
                .ins()
                .store(memory_flags(), value, base, done as i32);
            done += width;
        }
    }

    /// Step 7 of §4.4: `depth += 1`, the call, `depth -= 1` whatever its result (the
    /// interpreter's `pop_depth`, saturating); the budget travels through the context as
    /// around a callback. Returns the callee's status.
    fn call_counted(&mut self, function: FuncRef, this: Value, callee_frame: Value) -> Value {
        let depth =
            self.builder
                .ins()
                .load(types::I32, context_flags(), self.context, context::DEPTH);
        let deeper = self.builder.ins().iadd_imm_u(depth, 1);
        self.builder
            .ins()
            .store(context_flags(), deeper, self.context, context::DEPTH);
        let budget = self.builder.use_var(self.budget);
        self.builder
            .ins()
            .store(context_flags(), budget, self.context, context::BUDGET);
        let call = self
            .builder
            .ins()
            .call(function, &[self.context, this, callee_frame]);
        let status = self.builder.inst_results(call)[0];
        self.reload_memory();
        let budget =
            self.builder
                .ins()
                .load(types::I32, context_flags(), self.context, context::BUDGET);
        self.builder.def_var(self.budget, budget);
        let depth =
            self.builder
                .ins()
                .load(types::I32, context_flags(), self.context, context::DEPTH);
        let at_zero = self.builder.ins().icmp_imm_u(IntCC::Equal, depth, 0);
        let shallower = self.builder.ins().iadd_imm_s(depth, -1);
        let depth = self.builder.ins().select(at_zero, depth, shallower);
        self.builder
            .ins()
            .store(context_flags(), depth, self.context, context::DEPTH);
        status
    }

    /// Calls a host callback: the promoted places written back and the budget stored before,
    /// the memory's address and the budget loaded after (§4.2, §7 rule 3). Returns the
    /// callback's result, if it has one.
    ///
    /// The promoted places are not loaded again here: after a failed callback the memory may
    /// be shorter than the code was checked against, or its address stale (a host that
    /// panicked), and the code only returns. The caller calls `reload_promoted` on the
    /// success path, after testing the status (§7 rules 1 and 3).
    pub(crate) fn call_host(&mut self, import: Import, arguments: &[Value]) -> Value {
        // A callback sees memory as the interpreter leaves it, and may change it (§5.3).
        self.write_back();
        let budget = self.builder.use_var(self.budget);
        self.builder
            .ins()
            .store(context_flags(), budget, self.context, context::BUDGET);
        let callee = self.func_ref(import);
        let call = self.builder.ins().call(callee, arguments);
        let result = self.builder.inst_results(call).first().copied();
        self.reload_memory();
        let budget =
            self.builder
                .ins()
                .load(types::I32, context_flags(), self.context, context::BUDGET);
        self.builder.def_var(self.budget, budget);
        result.unwrap_or_else(|| self.builder.ins().iconst(types::I32, 0))
    }

    /// Calls a pure function (§4.6), which touches no memory; the memory's address is still
    /// reloaded after it, as after every call (§7 rule 3).
    pub(crate) fn call_pure(&mut self, import: Import, arguments: &[Value]) -> Value {
        let callee = self.func_ref(import);
        let call = self.builder.ins().call(callee, arguments);
        let result = self.builder.inst_results(call)[0];
        self.reload_memory();
        result
    }

    pub(crate) fn func_ref(&mut self, import: Import) -> FuncRef {
        if let Some(known) = self.refs[import as usize] {
            return known;
        }
        let id = self.imports.id(import);
        let reference = self.module.declare_func_in_func(id, self.builder.func);
        self.refs[import as usize] = Some(reference);
        reference
    }
}

/// The place `bytes` bytes after a direct operand, in the same region.
pub(crate) fn displaced(operand: Operand, bytes: u32) -> Operand {
    let moved = |offset: u32| offset.wrapping_add(bytes);
    match operand {
        Operand::Global(offset) => Operand::Global(moved(offset)),
        Operand::Instance(offset) => Operand::Instance(moved(offset)),
        Operand::Frame(offset) => Operand::Frame(moved(offset)),
        Operand::Const(offset) => Operand::Const(moved(offset)),
        Operand::Input(offset) => Operand::Input(moved(offset)),
        Operand::Output(offset) => Operand::Output(moved(offset)),
        Operand::Memory(offset) => Operand::Memory(moved(offset)),
    }
}
