//! Calls out of generated code (`docs/native-engine.md` §4.3, §4.4): a call of a POU with a
//! function is made through the callee's entry stub (`stub.rs`), in the interpreter's order
//! (`Exec::call_block`, `call_frame`, `push_frame`); every other call instruction is handed
//! to the interpreter through
//! `rivet_jit_op`, which runs the whole call (and may enter generated code again for a callee
//! further down).

use cranelift_codegen::ir::condcodes::IntCC;
use cranelift_codegen::ir::{FuncRef, InstBuilder, Value, types};
use program_image::{Operand, Transfer};

use super::host_calls::Import;
use super::stub::{StubKind, count_down};
use super::{Translator, context, context_flags};
use crate::fault_kind;

/// What a call of a POU with a function names (§4.4).
#[derive(Clone, Copy, Debug)]
struct CalleeRefs {
    /// The callee's index.
    callee: u32,
    /// The callee's function, which the call site calls itself after `prepare_N`.
    body: FuncRef,
    /// The callee's stub of the call's form.
    stub: FuncRef,
    /// Which form.
    kind: StubKind,
}

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
        let Some(refs) = self.callee_refs(callee, !inputs.is_empty()) else {
            return false;
        };
        let instance_size = self.pous[callee as usize].instance_size;
        let this = match instance {
            CallInstance::Caller => {
                // §4.4 step 2: the caller's instance was checked for the caller's size only.
                if instance_size > self.pous[self.pou as usize].instance_size {
                    self.check_instance(self.instance, instance_size);
                }
                self.instance
            }
            CallInstance::Direct(place) => self.absolute(place),
            CallInstance::Pointer(pointer) => self.resolve(pointer, instance_size),
        };
        self.call_frame(refs, this, inputs, outputs);
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
        let mut callees = Vec::with_capacity(table.len());
        for (_, method) in table {
            match self.callee_refs(*method, !inputs.is_empty()) {
                Some(refs) => callees.push(refs),
                None => return false,
            }
        }
        let pointer = self.load(types::I64, interface);
        let class = self.load(types::I32, displaced(interface, 8));
        self.resolve(interface, 0);
        let merge = self.builder.create_block();
        for ((known, method), refs) in table.iter().zip(callees) {
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
            self.call_frame(refs, this, inputs, outputs);
            self.builder.ins().jump(merge, &[]);
            self.builder.switch_to_block(next);
        }
        self.record_fault(fault_kind::BAD_POINTER, [Some(pointer), None, None]);
        self.builder.switch_to_block(merge);
        true
    }

    /// The references a call of POU `callee` needs in this function (its function and the
    /// stub of the call's form), when the callee has a function.
    fn callee_refs(&mut self, callee: u32, has_inputs: bool) -> Option<CalleeRefs> {
        let kind = StubKind::for_call(has_inputs);
        let body = self.pou_function(callee)?;
        let at = callee as usize;
        let stub = match self.stub_refs.get(at).and_then(|refs| refs[kind as usize]) {
            Some(known) => known,
            None => {
                let id = self.stubs.get(at)?[kind as usize]?;
                let reference = self.declarations.declare_in(id, self.builder.func);
                self.stub_refs[at][kind as usize] = Some(reference);
                reference
            }
        };
        Some(CalleeRefs {
            callee,
            body,
            stub,
            kind,
        })
    }

    /// The reference to POU `callee`'s function in this function, when it has one.
    fn pou_function(&mut self, callee: u32) -> Option<FuncRef> {
        if let Some(Some(known)) = self.pou_refs.get(callee as usize) {
            return Some(*known);
        }
        let id = (*self.functions.get(callee as usize)?)?;
        let reference = self.declarations.declare_in(id, self.builder.func);
        self.pou_refs[callee as usize] = Some(reference);
        Some(reference)
    }

    /// `Memory` at the call site when `instance + size` lies past the memory (§4.4 step 2,
    /// §7 rule 2).
    fn check_instance(&mut self, instance: Value, size: u32) {
        let memory_len = self.builder.ins().load(
            types::I64,
            context_flags(),
            self.context,
            context::MEMORY_LEN,
        );
        let end = self.builder.ins().iadd_imm_u(instance, i64::from(size));
        let outside = self
            .builder
            .ins()
            .icmp(IntCC::UnsignedGreaterThan, end, memory_len);
        self.fault_if(outside, fault_kind::MEMORY, [None; 3]);
    }

    /// The call site's part of §4.4 (steps 2, 3, 9 and 10): the callee's frame, its stub
    /// called with this site, then for `prepare_N` the input transfers, the body and the
    /// depth counted down; the output transfers when it did not fault.
    fn call_frame(
        &mut self,
        refs: CalleeRefs,
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
        let caller_frame_size = self.pous[self.pou as usize].frame_size;
        // During a POU's body the interpreter's `sp` is its frame's end, where the callee's
        // frame starts.
        let callee_frame = self
            .builder
            .ins()
            .iadd_imm_u(self.frame, i64::from(caller_frame_size));
        let pou = self.builder.ins().iconst(types::I32, i64::from(self.pou));
        let pc = self.builder.ins().iconst(types::I32, i64::from(self.pc));
        let status = self.call_counted(refs.stub, &[self.context, this, callee_frame, pou, pc]);
        self.return_if_faulted(status);
        if refs.kind == StubKind::Prepare {
            for transfer in inputs {
                let to = self
                    .builder
                    .ins()
                    .iadd_imm_u(callee_frame, i64::from(transfer.callee_offset));
                let from = self.absolute(transfer.caller);
                self.copy_bytes(to, from, transfer.size);
            }
            let status = self.call_counted(refs.body, &[self.context, this, callee_frame]);
            count_down(&mut self.builder, self.context);
            self.return_if_faulted(status);
        }
        debug_assert!(
            refs.kind == StubKind::Prepare || inputs.is_empty(),
            "inputs of a call of POU {} through its enter stub",
            refs.callee
        );
        for transfer in outputs {
            let to = self.absolute(transfer.caller);
            let from = self
                .builder
                .ins()
                .iadd_imm_u(callee_frame, i64::from(transfer.callee_offset));
            self.copy_bytes(to, from, transfer.size);
        }
    }

    /// Calls generated code (a stub or a POU function): the budget stored before, the
    /// memory's address and the budget loaded after (§4.2, §7 rule 3). Returns its status.
    fn call_counted(&mut self, function: FuncRef, arguments: &[Value]) -> Value {
        self.store_budget();
        let call = self.builder.ins().call(function, arguments);
        let status = self.builder.inst_results(call)[0];
        self.reload_memory();
        self.load_budget();
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
        self.store_budget();
        let callee = self.func_ref(import);
        let call = self.builder.ins().call(callee, arguments);
        let result = self.builder.inst_results(call).first().copied();
        self.reload_memory();
        self.load_budget();
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
        let reference = self.declarations.declare_in(id, self.builder.func);
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
