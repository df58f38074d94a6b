//! The entry stubs of the callees (`docs/native-engine.md` §4.4 steps 4–8, §9.2): one small
//! function per called POU and form, shared by every call of it, so that a call site keeps
//! only what differs between sites (the instance, the transfers, the call).
//!
//! A stub receives the call site's POU and instruction, so that it reports the safe point and
//! its faults where the interpreter's `push_frame` reports them.

use cranelift_codegen::ir::condcodes::IntCC;
use cranelift_codegen::ir::{
    AbiParam, BlockArg, Function, InstBuilder, Signature, StackSlotData, StackSlotKind,
    UserFuncName, Value, types,
};
use cranelift_frontend::{FunctionBuilder, FunctionBuilderContext};
use cranelift_module::FuncId;
use program_image::{Instr, Pou};

use super::declarations::FunctionDeclarations;
use super::host_calls::{Import, Imports};
use super::{context_flags, memory_flags};
use crate::{MAX_CALL_DEPTH, context, fault_kind};

/// The largest frame prepared by inline stores; a larger one is prepared by `rivet_jit_frame`
/// (§4.4 step 6), so that a stub does not grow by more than a few stores.
const INLINE_FRAME_BYTES: u32 = 64;

/// The two forms of a callee's stub.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum StubKind {
    /// `enter_N`: the checks, the frame, the depth, then the callee's body; for calls without
    /// input transfers.
    Enter = 0,
    /// `prepare_N`: the checks, the frame and the depth only; the call site then copies the
    /// inputs and calls the body itself.
    Prepare = 1,
}

impl StubKind {
    /// The form a call with or without input transfers uses.
    pub(crate) fn for_call(has_inputs: bool) -> Self {
        if has_inputs {
            Self::Prepare
        } else {
            Self::Enter
        }
    }

    /// The stub's symbol name for POU `callee`.
    pub(crate) fn name(self, callee: usize) -> String {
        match self {
            Self::Enter => format!("rivet_enter_{callee}"),
            Self::Prepare => format!("rivet_prepare_{callee}"),
        }
    }
}

/// Per POU: which of its stubs some call of the image needs, indexed by [`StubKind`].
pub(crate) fn stubs_needed(pous: &[Pou]) -> Vec<[bool; 2]> {
    let mut needed = vec![[false; 2]; pous.len()];
    let mut need = |callee: u32, has_inputs: bool| {
        if let Some(kinds) = needed.get_mut(callee as usize) {
            kinds[StubKind::for_call(has_inputs) as usize] = true;
        }
    };
    for pou in pous {
        for instr in &pou.code {
            match instr {
                Instr::CallFunction { pou, inputs, .. } => need(*pou, !inputs.is_empty()),
                Instr::CallBlock { pou, .. } => need(*pou, false),
                Instr::CallVirtual { table, inputs, .. } => {
                    for (_, method) in table {
                        need(*method, !inputs.is_empty());
                    }
                }
                _ => {}
            }
        }
    }
    needed
}

/// The signature of every stub: `(context, instance, callee_frame, pou, pc) -> status`.
pub(crate) fn stub_signature(mut signature: Signature) -> Signature {
    signature.params.push(AbiParam::new(types::I64));
    signature.params.push(AbiParam::new(types::I64));
    signature.params.push(AbiParam::new(types::I64));
    signature.params.push(AbiParam::new(types::I32));
    signature.params.push(AbiParam::new(types::I32));
    signature.returns.push(AbiParam::new(types::I32));
    signature
}

/// What a stub's translation needs of the module.
pub(crate) struct StubTarget<'a> {
    /// The callee.
    pub(crate) pou: &'a Pou,
    /// The callee's index.
    pub(crate) index: u32,
    /// The callee's function, which `enter_N` calls.
    pub(crate) function: FuncId,
    /// The imported callbacks.
    pub(crate) imports: &'a Imports,
    /// The signature of a stub on this machine.
    pub(crate) signature: Signature,
}

/// Translates the `kind` stub of `target` into a function (§4.4 steps 4–8), naming the
/// callee and the callbacks as `declarations` declare them.
pub(crate) fn translate_stub(
    target: &StubTarget<'_>,
    kind: StubKind,
    function_context: &mut FunctionBuilderContext,
    declarations: &FunctionDeclarations<'_>,
) -> Function {
    let mut function = Function::with_name_signature(
        UserFuncName::user(1 + kind as u32, target.index),
        target.signature.clone(),
    );
    let config = declarations.target_config();
    let mut builder = FunctionBuilder::new(&mut function, function_context);
    let entry = builder.create_block();
    builder.append_block_params_for_function_params(entry);
    builder.switch_to_block(entry);
    let params = builder.block_params(entry).to_vec();
    let import = |import: Import, builder: &mut FunctionBuilder<'_>| {
        declarations.declare_in(target.imports.id(import), builder.func)
    };
    // Step 4: the safe point, at the call site.
    let due_pointer = builder
        .ins()
        .load(types::I64, context_flags(), params[0], context::DUE);
    // An atomic load, read anew at every call (§4.5).
    let due = builder
        .ins()
        .atomic_load(types::I8, context_flags(), due_pointer);
    let preempt = builder.create_block();
    // The checks take the parameters as block parameters, so that on the cold path they come
    // back from a stack slot after the callback rather than living across it: a value live
    // across a call takes a callee-saved register, which every call would save and restore.
    let checks = builder.create_block();
    let types_of_params = [types::I64, types::I64, types::I64, types::I32, types::I32];
    for ty in types_of_params {
        builder.append_block_param(checks, ty);
    }
    let arguments: Vec<BlockArg> = params.iter().copied().map(BlockArg::Value).collect();
    builder.set_cold_block(preempt);
    builder.ins().brif(due, preempt, &[], checks, &arguments);
    builder.switch_to_block(preempt);
    let slot = builder.create_sized_stack_slot(StackSlotData::new(
        StackSlotKind::ExplicitSlot,
        8 * params.len() as u32,
        3,
    ));
    for (at, param) in params.iter().enumerate() {
        builder
            .ins()
            .stack_store(types::I64, *param, slot, 8 * at as i32);
    }
    let preempt_ref = import(Import::Preempt, &mut builder);
    let call = builder
        .ins()
        .call(preempt_ref, &[params[0], params[3], params[4]]);
    let status = builder.inst_results(call)[0];
    let faulted = builder.create_block();
    let resume = builder.create_block();
    builder.set_cold_block(faulted);
    builder.set_cold_block(resume);
    builder.ins().brif(status, faulted, &[], resume, &[]);
    builder.switch_to_block(faulted);
    // The host recorded the safe point's fault (`Watchdog`, `Abandoned`).
    let one = builder.ins().iconst(types::I32, 1);
    builder.ins().return_(&[one]);
    builder.switch_to_block(resume);
    let reloaded: Vec<BlockArg> = types_of_params
        .iter()
        .enumerate()
        .map(|(at, ty)| {
            BlockArg::Value(
                builder
                    .ins()
                    .stack_load(types::I64, *ty, slot, 8 * at as i32),
            )
        })
        .collect();
    builder.ins().jump(checks, &reloaded);
    builder.switch_to_block(checks);
    let params = builder.block_params(checks).to_vec();
    let stub = Stub {
        context: params[0],
        instance: params[1],
        frame: params[2],
        site_pou: params[3],
        site_pc: params[4],
    };
    // Step 5: the stack, the depth and the machine's stack.
    let frame_end = builder
        .ins()
        .iadd_imm_u(stub.frame, i64::from(target.pou.frame_size));
    let stack_end = builder.ins().load(
        types::I64,
        context_flags(),
        stub.context,
        context::STACK_END,
    );
    let past_stack = builder
        .ins()
        .icmp(IntCC::UnsignedGreaterThan, frame_end, stack_end);
    let depth = builder
        .ins()
        .load(types::I32, context_flags(), stub.context, context::DEPTH);
    let too_deep = builder.ins().icmp_imm_u(
        IntCC::UnsignedGreaterThanOrEqual,
        depth,
        i64::from(MAX_CALL_DEPTH),
    );
    // The machine's own stack: the bound the interpreter measures against (§4.4).
    let stack_pointer = builder.ins().get_stack_pointer(types::I64);
    let native_limit = builder.ins().load(
        types::I64,
        context_flags(),
        stub.context,
        context::NATIVE_STACK_LIMIT,
    );
    let native_low = builder
        .ins()
        .icmp(IntCC::UnsignedLessThan, stack_pointer, native_limit);
    let overflow = builder.ins().bor(past_stack, too_deep);
    let overflow = builder.ins().bor(overflow, native_low);
    let fault_ref = import(Import::Fault, &mut builder);
    stub.fault_if(
        &mut builder,
        overflow,
        fault_kind::STACK_OVERFLOW,
        fault_ref,
    );
    // Step 6: the frame.
    let size = target.pou.frame_size;
    if size > INLINE_FRAME_BYTES {
        let frame_ref = import(Import::Frame, &mut builder);
        let pou = builder.ins().iconst(types::I32, i64::from(target.index));
        let call = builder
            .ins()
            .call(frame_ref, &[stub.context, pou, stub.frame]);
        let status = builder.inst_results(call)[0];
        // Like a copy, the callback has no site: a failure is recorded at the call site
        // (§4.3).
        stub.fault_if(&mut builder, status, fault_kind::MEMORY, fault_ref);
    } else if size > 0 {
        stub.store_frame(&mut builder, target.pou);
    }
    // Step 7: the depth, counted where `push_frame` counts it. Read again after the frame's
    // callback, which hands the counters to the host and takes them back; step 4's callback
    // came before the checks read it.
    let depth = if size > INLINE_FRAME_BYTES {
        builder
            .ins()
            .load(types::I32, context_flags(), stub.context, context::DEPTH)
    } else {
        depth
    };
    let deeper = builder.ins().iadd_imm_u(depth, 1);
    builder
        .ins()
        .store(context_flags(), deeper, stub.context, context::DEPTH);
    match kind {
        StubKind::Prepare => {
            let ok = builder.ins().iconst(types::I32, 0);
            builder.ins().return_(&[ok]);
        }
        StubKind::Enter => {
            // Step 8: the body, then the depth counted down whatever its result.
            let body = declarations.declare_in(target.function, builder.func);
            let call = builder
                .ins()
                .call(body, &[stub.context, stub.instance, stub.frame]);
            let status = builder.inst_results(call)[0];
            count_down(&mut builder, stub.context);
            builder.ins().return_(&[status]);
        }
    }
    builder.seal_all_blocks();
    builder.finalize(config);
    function
}

/// `depth -= 1` in the context, saturating at 0 (the interpreter's `pop_depth`).
pub(crate) fn count_down(builder: &mut FunctionBuilder<'_>, context: Value) {
    let depth = builder
        .ins()
        .load(types::I32, context_flags(), context, context::DEPTH);
    let at_zero = builder.ins().icmp_imm_u(IntCC::Equal, depth, 0);
    let shallower = builder.ins().iadd_imm_s(depth, -1);
    let depth = builder.ins().select(at_zero, depth, shallower);
    builder
        .ins()
        .store(context_flags(), depth, context, context::DEPTH);
}

/// A stub's parameters.
struct Stub {
    /// The context.
    context: Value,
    /// The callee's instance offset (passed on to the body; the stub does not read it).
    instance: Value,
    /// The callee's frame offset.
    frame: Value,
    /// The call site's POU.
    site_pou: Value,
    /// The call site's instruction.
    site_pc: Value,
}

impl Stub {
    /// Records `kind` at the call site and returns `Faulted` when `failed` is true; goes on
    /// otherwise.
    fn fault_if(
        &self,
        builder: &mut FunctionBuilder<'_>,
        failed: Value,
        kind: u32,
        fault: cranelift_codegen::ir::FuncRef,
    ) {
        let faulted = builder.create_block();
        let next = builder.create_block();
        builder.set_cold_block(faulted);
        builder.ins().brif(failed, faulted, &[], next, &[]);
        builder.switch_to_block(faulted);
        let kind = builder.ins().iconst(types::I32, i64::from(kind));
        let zero = builder.ins().iconst(types::I64, 0);
        builder.ins().call(
            fault,
            &[
                self.context,
                self.site_pou,
                self.site_pc,
                kind,
                zero,
                zero,
                zero,
            ],
        );
        let one = builder.ins().iconst(types::I32, 1);
        builder.ins().return_(&[one]);
        builder.switch_to_block(next);
    }

    /// The new frame zeroed and its `frame_init` runs written by inline stores of the bytes
    /// the translation computes, as `push_frame` does (a run that does not fit the frame is
    /// skipped there too). The memory's address is read here, after every callback of the
    /// stub (§7 rule 3).
    fn store_frame(&self, builder: &mut FunctionBuilder<'_>, callee: &Pou) {
        let mut bytes = vec![0u8; callee.frame_size as usize];
        for run in &callee.frame_init {
            let start = run.offset as usize;
            let end = start.saturating_add(run.bytes.len());
            if let Some(place) = bytes.get_mut(start..end) {
                place.copy_from_slice(&run.bytes);
            }
        }
        let memory = builder
            .ins()
            .load(types::I64, context_flags(), self.context, context::MEMORY);
        let base = builder.ins().iadd(memory, self.frame);
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
            let value = builder.ins().iconst(ty, u64::from_le_bytes(raw) as i64);
            builder
                .ins()
                .store(memory_flags(), value, base, done as i32);
            done += width;
        }
    }
}
