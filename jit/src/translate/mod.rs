//! One POU's instructions into one Cranelift function (`docs/native-engine.md` §3, §5).
//!
//! The function has the one signature of §4.1, `(context, instance, frame) -> status`. The
//! memory's address lives in a variable reloaded from the context after every call (§7 rule 3),
//! the watchdog budget, in a POU with a backward jump, in a variable stored to the context
//! around every call (§4.2).

mod blocks;
mod call;
mod counted;
pub(crate) mod declarations;
pub(crate) mod host_calls;
mod pointer;
pub(crate) mod promote;
mod real;
pub(crate) mod scalar;
pub(crate) mod stub;

use cranelift_codegen::ir::{
    AbiParam, Block, BlockArg, FuncRef, Function, InstBuilder, MemFlagsData, Signature, Type,
    UserFuncName, Value, types,
};
use cranelift_frontend::{FunctionBuilder, FunctionBuilderContext, Variable};
use cranelift_module::FuncId;
use program_image::{Elementary, Instr, Operand, Pou};

use crate::context;
use crate::layout::Layout;
use blocks::Blocks;
use call::CallInstance;
use declarations::FunctionDeclarations;
use host_calls::{Import, Imports};

/// A POU the translator leaves to the interpreter, with the reason (`docs/native-engine.md`
/// §8.2).
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("POU '{name}' (index {pou}) runs in the interpreter: {}{reason}", instruction_text(*.instruction))]
pub struct Untranslated {
    /// The POU's index in the image.
    pub pou: u32,
    /// The POU's name.
    pub name: String,
    /// The instruction that could not be translated, when one could be named.
    pub instruction: Option<u32>,
    /// Why.
    pub reason: String,
}

fn instruction_text(instruction: Option<u32>) -> String {
    instruction.map_or(String::new(), |index| format!("instruction {index}: "))
}

/// The name of a POU the translator refuses in the tests.
#[cfg(test)]
pub(crate) const REFUSED_IN_TESTS: &str = "RefusedInTests";

/// The name of a POU whose translation panics in the tests, after its function's builder was
/// made.
#[cfg(test)]
pub(crate) const TRANSLATE_PANICS_IN_TESTS: &str = "TranslatePanicsInTests";

#[cfg(test)]
thread_local! {
    /// The POUs translated on the current thread, in order, for the tests to see which are
    /// translated again after a refusal.
    pub(crate) static TRANSLATED_IN_TESTS: std::cell::RefCell<Vec<u32>> =
        const { std::cell::RefCell::new(Vec::new()) };
}

/// The one signature of every POU function: `(context, instance, frame) -> status`.
pub(crate) fn pou_signature(mut signature: Signature) -> Signature {
    signature.params.push(AbiParam::new(types::I64));
    signature.params.push(AbiParam::new(types::I64));
    signature.params.push(AbiParam::new(types::I64));
    signature.returns.push(AbiParam::new(types::I32));
    signature
}

/// The flags of every access to the engine's memory: never trapping (every access is checked
/// or verified), never assumed aligned (the layout does not promise it).
pub(crate) fn memory_flags() -> MemFlagsData {
    MemFlagsData::new().with_notrap()
}

/// The flags of accesses to the context, a `#[repr(C)]` structure on `Code::run`'s stack.
pub(crate) fn context_flags() -> MemFlagsData {
    MemFlagsData::trusted()
}

/// What the translation of every POU shares.
pub(crate) struct Environment<'a> {
    /// The image's POUs.
    pub(crate) pous: &'a [Pou],
    /// Where the regions lie.
    pub(crate) layout: &'a Layout,
    /// The imported callbacks and pure functions.
    pub(crate) imports: &'a Imports,
    /// The constant pool, when nothing can write it, so its values may be folded (§5.2).
    pub(crate) folded_constants: Option<&'a [u8]>,
    /// The signature of a POU function on this machine.
    pub(crate) signature: Signature,
    /// Per POU: its function in the module, when it has one (a call of a POU without one is
    /// handed to the interpreter, §4.4).
    pub(crate) functions: &'a [Option<FuncId>],
    /// Per POU: its entry stubs (§4.4), indexed by `stub::StubKind`, those some call needs.
    pub(crate) stubs: &'a [[Option<FuncId>; 2]],
}

/// Translates POU `index` into a function, naming its callees and imports as `declarations`
/// declare them, or says why it cannot.
pub(crate) fn translate_pou(
    environment: &Environment<'_>,
    index: u32,
    function_context: &mut FunctionBuilderContext,
    declarations: &FunctionDeclarations<'_>,
) -> Result<Function, Untranslated> {
    let pou = environment
        .pous
        .get(index as usize)
        .ok_or_else(|| Untranslated {
            pou: index,
            name: String::new(),
            instruction: None,
            reason: "no such POU".into(),
        })?;
    #[cfg(test)]
    TRANSLATED_IN_TESTS.with(|translated| translated.borrow_mut().push(index));
    // The tests see a refused callee's callers translated again with the call handed over.
    #[cfg(test)]
    if pou.name == REFUSED_IN_TESTS {
        return Err(Untranslated {
            pou: index,
            name: pou.name.clone(),
            instruction: None,
            reason: "refused by the tests".into(),
        });
    }
    let mut function =
        Function::with_name_signature(UserFuncName::user(0, index), environment.signature.clone());
    {
        let builder = FunctionBuilder::new(&mut function, function_context);
        let mut translator = Translator::new(environment, index, pou, builder, *declarations);
        // The tests see a translator that panics halfway through a function, with the
        // builder's context in use, and the POUs built after it on the same thread.
        #[cfg(test)]
        if pou.name == TRANSLATE_PANICS_IN_TESTS {
            panic!("a translator panic the tests ask for");
        }
        translator.body();
        let Translator { mut builder, .. } = translator;
        builder.seal_all_blocks();
        builder.finalize(declarations.target_config());
    }
    Ok(function)
}

/// The state of one POU's translation.
pub(crate) struct Translator<'a, 'b> {
    /// The builder of the POU's function.
    pub(crate) builder: FunctionBuilder<'b>,
    /// Where the regions lie in the engine's memory.
    pub(crate) layout: &'a Layout,
    /// The module's ids of the callbacks and pure functions.
    imports: &'a Imports,
    /// The constant pool, when its values may be folded.
    folded_constants: Option<&'a [u8]>,
    /// The functions of the module the function is made for, which it declares its imports
    /// and callees from.
    declarations: FunctionDeclarations<'a>,
    /// Per import: its reference in this function, once declared in it.
    refs: Vec<Option<FuncRef>>,
    /// The image's POUs.
    pub(crate) pous: &'a [Pou],
    /// Per POU: its function in the module, when it has one.
    functions: &'a [Option<FuncId>],
    /// Per POU: its function's reference in this function, once declared in it.
    pou_refs: Vec<Option<FuncRef>>,
    /// Per POU: its entry stubs in the module, indexed by `stub::StubKind`.
    stubs: &'a [[Option<FuncId>; 2]],
    /// Per POU: its stubs' references in this function, once declared in it.
    stub_refs: Vec<[Option<FuncRef>; 2]>,
    /// This POU's index.
    pub(crate) pou: u32,
    /// This POU's instructions.
    code: &'a [Instr],
    /// The block each instruction starts.
    blocks: Blocks,
    /// The context pointer (the function's first parameter).
    pub(crate) context: Value,
    /// The instance's offset in the memory (the second parameter).
    pub(crate) instance: Value,
    /// The frame's offset in the memory (the third parameter).
    pub(crate) frame: Value,
    /// The memory's address, reloaded after every call.
    memory: Variable,
    /// The machine addresses of the instance and of the frame (`memory` plus each),
    /// redefined with `memory`: an element access reaches its element in one addressing
    /// mode from them, and in a loop without calls the addition stays out of the loop.
    bases: [Variable; 2],
    /// Backward jumps left before the watchdog looks at the clock.
    budget: Variable,
    /// Whether the budget lives in `budget` at all: only a POU with a backward jump counts it
    /// down. In any other the variable would only ever hold what the context holds, so it
    /// is neither loaded nor stored, around calls or on return (§4.2).
    counts_budget: bool,
    /// The address of the preemption flag `due`, read from the context once on entry when
    /// the POU has a backward jump: the context does not change while the function runs, so
    /// a back-edge reads only the flag.
    due_pointer: Option<Value>,
    /// The blocks every return goes through, returning `Ok` and `Faulted`, so that the
    /// epilogue is emitted twice per function rather than at every check. They take no
    /// parameter (a status passed from thousands of call sites would cost the register
    /// allocator far more than the two blocks), and the budget is in the context when they
    /// are entered: stored by the return or the fault, kept there by the call whose failure
    /// it returns, or never anywhere else in a POU that does not count it.
    returns: [Option<Block>; 2],
    /// The blocks every fault goes through after its own write-back, so that a function
    /// makes one call of `rivet_jit_fault` per kind of tail rather than one per check: the
    /// first takes the instruction and the kind packed in one parameter
    /// ([`pack_site`]) and passes zeros as the details, the second takes the three details
    /// too. Most checks (stack, memory, null pointers, divisions) have no details, and one
    /// argument is one move at the check.
    fault_tails: [Option<Block>; 2],
    /// The instruction being translated.
    pub(crate) pc: u32,
    /// Back-edge blocks of the current instruction, where each goes and its target
    /// instruction, to emit once the current block is terminated.
    back_edges: Vec<(Block, Block, u32)>,
    /// The loops whose places are kept in variables (§5.3), in code order.
    promoted_loops: Vec<promote::PromotedLoop>,
    /// Per promoted loop: the block every entry from outside goes through.
    preheaders: Vec<Block>,
    /// The promoted loop being emitted.
    active_loop: Option<usize>,
    /// Its places: the operand, its size, and the variable that holds it.
    promoted: Vec<(Operand, u32, Variable)>,
    /// While the promoted copy of a counted loop is emitted: what its preheader checked.
    hoisted: Option<counted::Hoisted>,
    /// Exit blocks of the current instruction out of the active loop and where each goes,
    /// to emit once the current block is terminated.
    exits: Vec<(Block, Block)>,
}

impl<'a, 'b> Translator<'a, 'b> {
    fn new(
        environment: &Environment<'a>,
        index: u32,
        pou: &'a Pou,
        mut builder: FunctionBuilder<'b>,
        declarations: FunctionDeclarations<'a>,
    ) -> Self {
        let blocks = Blocks::new(&pou.code, &mut builder);
        let promoted_loops =
            promote::promotable_loops(&pou.code, environment.layout, environment.folded_constants);
        let preheaders = promoted_loops
            .iter()
            .map(|_| builder.create_block())
            .collect();
        let entry = builder.create_block();
        builder.append_block_params_for_function_params(entry);
        builder.switch_to_block(entry);
        let params = builder.block_params(entry).to_vec();
        let (context, instance, frame) = (params[0], params[1], params[2]);
        let memory = builder.declare_var(types::I64);
        let bases = [
            builder.declare_var(types::I64),
            builder.declare_var(types::I64),
        ];
        let budget = builder.declare_var(types::I32);
        // A POU with a backward jump counts the budget and reads the flag `due` at its
        // back-edges; any other does neither. The flag's address is loaded only where a
        // back-edge reads it: a load the code generator keeps even unused, and one it may
        // move (read-only) it copies to every back-edge of a large function.
        let backward = pou.code.iter().enumerate().any(|(at, instr)| {
            promote::jump_target(instr).is_some_and(|target| target as usize <= at)
        });
        let due_pointer = backward.then(|| {
            builder
                .ins()
                .load(types::I64, context_flags(), context, context::DUE)
        });
        let mut translator = Self {
            builder,
            layout: environment.layout,
            imports: environment.imports,
            folded_constants: environment.folded_constants,
            declarations,
            refs: vec![None; Import::COUNT],
            pous: environment.pous,
            functions: environment.functions,
            pou_refs: vec![None; environment.pous.len()],
            stubs: environment.stubs,
            stub_refs: vec![[None; 2]; environment.pous.len()],
            pou: index,
            code: &pou.code,
            blocks,
            context,
            instance,
            frame,
            memory,
            bases,
            budget,
            counts_budget: backward,
            due_pointer,
            returns: [None; 2],
            fault_tails: [None; 2],
            pc: 0,
            back_edges: Vec::new(),
            promoted_loops,
            preheaders,
            active_loop: None,
            promoted: Vec::new(),
            hoisted: None,
            exits: Vec::new(),
        };
        translator.reload_memory();
        translator.load_budget();
        translator
    }

    /// Emits every instruction, then the end (running past the last instruction returns).
    fn body(&mut self) {
        // The entry block falls into instruction 0.
        let mut reachable = true;
        let mut index = 0;
        while index < self.code.len() {
            if let Some(position) = self.loop_starting_at(index) {
                reachable = self.promoted_loop(position, reachable);
                index = self.promoted_loops[position].end as usize + 1;
                continue;
            }
            reachable = self.emit_at(index, reachable);
            index += 1;
        }
        if let Some(end) = self.blocks.at(self.code.len()) {
            if reachable {
                self.builder.ins().jump(end, &[]);
            }
            self.builder.switch_to_block(end);
            self.return_status(0);
        }
        self.emit_fault_tails();
        self.emit_returns();
    }

    /// Emits instruction `index`, starting its block if it starts one; `reachable` says
    /// whether control falls into it from the one before. Returns whether control falls
    /// through to the next.
    pub(crate) fn emit_at(&mut self, index: usize, reachable: bool) -> bool {
        self.pc = index as u32;
        let mut reachable = reachable;
        if let Some(block) = self.blocks.at(index) {
            if reachable {
                self.builder.ins().jump(block, &[]);
            }
            self.builder.switch_to_block(block);
            reachable = true;
        }
        if !reachable {
            return false;
        }
        let instr = &self.code[index];
        let falls_through = self.instruction(instr);
        self.emit_back_edges();
        self.emit_exits();
        falls_through
    }

    /// Emits one instruction; false when control does not fall through to the next.
    fn instruction(&mut self, instr: &Instr) -> bool {
        match instr {
            Instr::Jump { target } => {
                let block = self.branch_target(*target);
                self.builder.ins().jump(block, &[]);
                false
            }
            Instr::JumpIf { cond, target } | Instr::JumpIfNot { cond, target } => {
                let value = self.load(types::I8, *cond);
                let taken = self.branch_target(*target);
                let next = self.next_block();
                if matches!(instr, Instr::JumpIf { .. }) {
                    self.builder.ins().brif(value, taken, &[], next, &[]);
                } else {
                    self.builder.ins().brif(value, next, &[], taken, &[]);
                }
                false
            }
            Instr::Return => {
                self.write_back();
                self.return_status(0);
                false
            }
            other => {
                if !self.inline(other) {
                    self.host_op();
                }
                true
            }
        }
    }

    /// Emits an instruction inline, or returns false to hand it to the host.
    fn inline(&mut self, instr: &Instr) -> bool {
        match instr {
            Instr::Move { ty, dst, src } => {
                let ty = int_type(*ty);
                let value = self.load(ty, *src);
                self.store(value, *dst);
                true
            }
            Instr::Copy { size, dst, src } => {
                let reload = self.promoted_copy(*dst, *src, *size);
                let (to, from) = (self.absolute(*dst), self.absolute(*src));
                self.copy_bytes(to, from, *size);
                if reload {
                    self.reload_promoted();
                }
                true
            }
            Instr::Unary { op, ty, dst, src } => self.unary(*op, *ty, *dst, *src),
            Instr::Binary { op, ty, dst, a, b } => self.binary(*op, *ty, *dst, *a, *b),
            Instr::Compare { op, ty, dst, a, b } => self.compare(*op, *ty, *dst, *a, *b),
            Instr::Convert { from, to, dst, src } => self.convert(*from, *to, *dst, *src, false),
            Instr::Trunc { from, to, dst, src } => self.convert(*from, *to, *dst, *src, true),
            Instr::GetBit { ty, dst, src, bit } => {
                let value = self.load(int_type(*ty), *src);
                let shifted = self.builder.ins().ushr_imm_u(value, i64::from(*bit));
                let one = self.builder.ins().band_imm_u(shifted, 1);
                let byte = self.resized(one, int_type(*ty), types::I8, false);
                self.store(byte, *dst);
                true
            }
            Instr::SetBit { ty, dst, bit, src } => {
                let ty = int_type(*ty);
                let value = self.load(ty, *dst);
                let on = self.load(types::I8, *src);
                let mask = 1u64 << bit;
                let set = self.builder.ins().bor_imm_u(value, mask as i64);
                let cleared = self.builder.ins().band_imm_u(value, !mask as i64);
                let result = self.builder.ins().select(on, set, cleared);
                self.store(result, *dst);
                true
            }
            Instr::Address { dst, place } => {
                let pointer = self.address_of(*place);
                self.store(pointer, *dst);
                true
            }
            Instr::Element {
                dst,
                base,
                index,
                index_ty,
                low,
                count,
                stride,
            } => {
                self.element(*dst, *base, (*index, *index_ty), *low, *count, *stride);
                true
            }
            Instr::Offset { dst, base, offset } => {
                self.offset(*dst, *base, *offset);
                true
            }
            Instr::Load { size, dst, ptr } => {
                let from = self.resolve(*ptr, *size);
                let to = self.absolute(*dst);
                self.copy_bytes(to, from, *size);
                true
            }
            Instr::Store { size, ptr, src } => {
                let to = self.resolve(*ptr, *size);
                let from = self.absolute(*src);
                self.copy_bytes(to, from, *size);
                true
            }
            Instr::Now { dst } => {
                let now = self.builder.ins().load(
                    types::I64,
                    context_flags(),
                    self.context,
                    context::NOW_NS,
                );
                self.store(now, *dst);
                true
            }
            Instr::CallFunction {
                pou,
                instance,
                inputs,
                outputs,
            } => {
                let this = match instance {
                    Some(pointer) => CallInstance::Pointer(*pointer),
                    None => CallInstance::Caller,
                };
                self.call_function(*pou, this, inputs, outputs)
            }
            Instr::CallBlock {
                pou,
                instance,
                indirect,
            } => {
                let this = if *indirect {
                    CallInstance::Pointer(*instance)
                } else {
                    CallInstance::Direct(*instance)
                };
                self.call_function(*pou, this, &[], &[])
            }
            Instr::CallVirtual {
                table,
                interface,
                inputs,
                outputs,
            } => self.call_virtual(table, *interface, inputs, outputs),
            Instr::OpenElement {
                dst,
                descriptor,
                indices,
                stride,
            } => {
                self.open_element(*dst, *descriptor, indices, *stride);
                true
            }
            Instr::LoadElement {
                ty,
                dst,
                array,
                index,
                index_ty,
                low,
                count,
                stride,
                offset,
            } => {
                self.load_element(
                    (int_type(*ty), *dst),
                    *array,
                    (*index, *index_ty),
                    (*low, *count, *stride),
                    *offset,
                );
                true
            }
            Instr::StoreElement {
                ty,
                array,
                index,
                index_ty,
                low,
                count,
                stride,
                offset,
                src,
            } => {
                self.store_element(
                    (int_type(*ty), *src),
                    *array,
                    (*index, *index_ty),
                    (*low, *count, *stride),
                    *offset,
                );
                true
            }
            // The runtime's blocks and functions, strings, the real clock and the motion
            // blocks run in the interpreter (§5.1 "host").
            _ => false,
        }
    }

    /// The block after the current instruction (every branch ends a block, `blocks.rs`).
    fn next_block(&mut self) -> Block {
        let next = self
            .blocks
            .at(self.pc as usize + 1)
            .unwrap_or(self.blocks.end());
        self.promoted_destination(self.pc + 1, next)
    }

    /// The block a jump to `target` goes to: the target's own block for a forward jump, a
    /// block with the back-edge check of §4.5 for a backward one (emitted once the current
    /// block is terminated, by [`Self::emit_back_edges`]).
    fn branch_target(&mut self, target: u32) -> Block {
        let destination = self.blocks.at(target as usize).unwrap_or(self.blocks.end());
        let destination = self.promoted_destination(target, destination);
        if target > self.pc {
            return destination;
        }
        let back_edge = self.builder.create_block();
        self.back_edges.push((back_edge, destination, target));
        back_edge
    }

    /// Emits the back-edge blocks the current instruction branches to: `budget -= 1`, and
    /// when the budget is spent or the flag `due` is set, `rivet_jit_tick` at this site. The
    /// two tests are two branches (a decrement and a jump on zero, a byte compared in memory
    /// and a jump), so that the common case is one load of the flag and no other memory.
    fn emit_back_edges(&mut self) {
        for (back_edge, destination, target) in std::mem::take(&mut self.back_edges) {
            self.builder.switch_to_block(back_edge);
            let budget = self.builder.use_var(self.budget);
            let budget = self.builder.ins().iadd_imm_s(budget, -1);
            self.builder.def_var(self.budget, budget);
            let slow = self.builder.create_block();
            self.builder.set_cold_block(slow);
            let flag = self.builder.create_block();
            self.builder.ins().brif(budget, flag, &[], slow, &[]);
            self.builder.switch_to_block(flag);
            let due_pointer = match self.due_pointer {
                Some(loaded) => loaded,
                None => {
                    self.builder
                        .ins()
                        .load(types::I64, context_flags(), self.context, context::DUE)
                }
            };
            // An atomic load, so that the flag is read anew at every back-edge (§4.5).
            let due = self
                .builder
                .ins()
                .atomic_load(types::I8, context_flags(), due_pointer);
            self.builder.ins().brif(due, slow, &[], destination, &[]);
            self.builder.switch_to_block(slow);
            let pou = self.builder.ins().iconst(types::I32, i64::from(self.pou));
            let pc = self.builder.ins().iconst(types::I32, i64::from(self.pc));
            let status = self.call_host(Import::Tick, &[self.context, pou, pc]);
            self.return_if_faulted(status);
            // A tick may change memory: a loop whose checks were made once in its preheader
            // goes back there, to make them again on what memory holds now (§5.3).
            if let Some(preheader) = self.recheck_after_tick(target) {
                self.builder.ins().jump(preheader, &[]);
                continue;
            }
            // Only once the tick succeeded: the memory is then as long as it was checked.
            self.reload_promoted();
            self.builder.ins().jump(destination, &[]);
        }
    }

    /// Returns `Faulted` when `status` is not 0, else goes on in a new block. Called right
    /// after a call (a callback, an entry stub or a POU function), after which the context
    /// holds the budget (the call stored it where this POU counts it, and the callee leaves
    /// it there on every return), so the way out stores nothing: the budget does not flow into the shared exit
    /// block, which keeps the register allocator's work small in functions with thousands of
    /// calls.
    pub(crate) fn return_if_faulted(&mut self, status: Value) {
        let exit = self.exit_block(1);
        let next = self.builder.create_block();
        self.builder.ins().brif(status, exit, &[], next, &[]);
        self.builder.switch_to_block(next);
    }

    /// Branches to a cold block that records `kind` with `a`, `b`, `c` at the current
    /// instruction and returns `Faulted` when `failed` is true; goes on otherwise.
    pub(crate) fn fault_if(&mut self, failed: Value, kind: u32, details: [Option<Value>; 3]) {
        let faulted = self.builder.create_block();
        let next = self.builder.create_block();
        self.builder.set_cold_block(faulted);
        self.builder.ins().brif(failed, faulted, &[], next, &[]);
        self.builder.switch_to_block(faulted);
        self.record_fault(kind, details);
        self.builder.switch_to_block(next);
    }

    /// Records a fault at the current instruction and returns `Faulted`: the promoted places
    /// written back here, then the shared tail with this site, the kind and the details.
    pub(crate) fn record_fault(&mut self, kind: u32, details: [Option<Value>; 3]) {
        self.write_back();
        let site = self
            .builder
            .ins()
            .iconst(types::I64, pack_site(self.pc, kind));
        let mut arguments = vec![BlockArg::Value(site)];
        let detailed = details.iter().any(Option::is_some);
        if detailed {
            for detail in details {
                let value = detail.unwrap_or_else(|| self.builder.ins().iconst(types::I64, 0));
                arguments.push(BlockArg::Value(value));
            }
        }
        let tail = self.fault_tail_block(usize::from(detailed));
        self.builder.ins().jump(tail, &arguments);
    }

    /// Stores the budget into the context and returns `status` (0 `Ok`, 1 `Faulted`) through
    /// its shared exit block.
    pub(crate) fn return_status(&mut self, status: usize) {
        self.store_budget();
        let exit = self.exit_block(status);
        self.builder.ins().jump(exit, &[]);
    }

    /// The shared exit block returning `status`, made on first use; the one of `Faulted` is
    /// cold.
    fn exit_block(&mut self, status: usize) -> Block {
        if let Some(exit) = self.returns[status] {
            return exit;
        }
        let exit = self.builder.create_block();
        if status != 0 {
            self.builder.set_cold_block(exit);
        }
        self.returns[status] = Some(exit);
        exit
    }

    /// The shared fault block without details (`detailed` 0) or with them (1), made on first
    /// use; cold.
    fn fault_tail_block(&mut self, detailed: usize) -> Block {
        if let Some(tail) = self.fault_tails[detailed] {
            return tail;
        }
        let tail = self.builder.create_block();
        self.builder.set_cold_block(tail);
        let parameters = if detailed == 0 { 1 } else { 4 };
        for _ in 0..parameters {
            self.builder.append_block_param(tail, types::I64);
        }
        self.fault_tails[detailed] = Some(tail);
        tail
    }

    /// Emits the shared fault blocks that faults use: `rivet_jit_fault` at the site their
    /// parameters name, then `Faulted`. They run after every promoted loop's write-back, so
    /// they write nothing back themselves.
    fn emit_fault_tails(&mut self) {
        debug_assert!(self.promoted.is_empty(), "a fault tail inside a loop");
        for tail in self.fault_tails.into_iter().flatten() {
            self.builder.switch_to_block(tail);
            let parameters = self.builder.block_params(tail).to_vec();
            let pou = self.builder.ins().iconst(types::I32, i64::from(self.pou));
            let pc = self.builder.ins().ushr_imm_u(parameters[0], 8);
            let pc = self.builder.ins().ireduce(types::I32, pc);
            let kind = self.builder.ins().band_imm_u(parameters[0], 0xFF);
            let kind = self.builder.ins().ireduce(types::I32, kind);
            let mut arguments = vec![self.context, pou, pc, kind];
            match parameters[1..] {
                [a, b, c] => arguments.extend([a, b, c]),
                _ => {
                    let zero = self.builder.ins().iconst(types::I64, 0);
                    arguments.extend([zero, zero, zero]);
                }
            }
            // The callback is the function's last act: nothing is read after it (the host
            // keeps the budget it was given), so nothing but its arguments lives across it
            // and a POU whose only calls are its faults saves no register for them. The
            // budget is stored first, so it is in the context when `Faulted` is returned.
            self.store_budget();
            let fault = self.func_ref(Import::Fault);
            self.builder.ins().call(fault, &arguments);
            let exit = self.exit_block(1);
            self.builder.ins().jump(exit, &[]);
        }
    }

    /// Emits the shared exit blocks that something returns through.
    fn emit_returns(&mut self) {
        for (status, exit) in self.returns.into_iter().enumerate() {
            if let Some(exit) = exit {
                self.builder.switch_to_block(exit);
                let status = self.builder.ins().iconst(types::I32, status as i64);
                self.builder.ins().return_(&[status]);
            }
        }
    }

    /// Stores the budget into the context, before a call, a fault or a return, where this POU
    /// counts it.
    pub(crate) fn store_budget(&mut self) {
        if self.counts_budget {
            let budget = self.builder.use_var(self.budget);
            self.builder
                .ins()
                .store(context_flags(), budget, self.context, context::BUDGET);
        }
    }

    /// Loads the budget from the context, on entry and after a call, where this POU counts
    /// it.
    pub(crate) fn load_budget(&mut self) {
        if self.counts_budget {
            let budget =
                self.builder
                    .ins()
                    .load(types::I32, context_flags(), self.context, context::BUDGET);
            self.builder.def_var(self.budget, budget);
        }
    }

    fn reload_memory(&mut self) {
        let memory =
            self.builder
                .ins()
                .load(types::I64, context_flags(), self.context, context::MEMORY);
        self.builder.def_var(self.memory, memory);
        for (variable, base) in self.bases.into_iter().zip([self.instance, self.frame]) {
            let address = self.builder.ins().iadd(memory, base);
            self.builder.def_var(variable, address);
        }
    }

    /// The machine address and displacement of a direct operand, from the instance's or the
    /// frame's machine address for their places: one register and a displacement.
    pub(crate) fn based_operand_address(&mut self, operand: Operand) -> (Value, i32) {
        let (variable, offset) = match operand {
            Operand::Instance(offset) => (self.bases[0], offset),
            Operand::Frame(offset) => (self.bases[1], offset),
            fixed => return self.operand_address(fixed),
        };
        let address = self.builder.use_var(variable);
        match i32::try_from(offset) {
            Ok(displacement) => (address, displacement),
            Err(_) => (self.builder.ins().iadd_imm_u(address, i64::from(offset)), 0),
        }
    }

    /// The absolute offset of a direct operand in the engine's memory, as a value.
    pub(crate) fn absolute(&mut self, operand: Operand) -> Value {
        match operand {
            Operand::Instance(offset) => self
                .builder
                .ins()
                .iadd_imm_u(self.instance, i64::from(offset)),
            Operand::Frame(offset) => self.builder.ins().iadd_imm_u(self.frame, i64::from(offset)),
            fixed => {
                let at = self.layout.absolute(fixed).unwrap_or(0);
                self.builder.ins().iconst(types::I64, at as i64)
            }
        }
    }

    /// The machine address of an absolute offset (a value), valid until the next call.
    pub(crate) fn machine_address(&mut self, absolute: Value) -> Value {
        let memory = self.builder.use_var(self.memory);
        self.builder.ins().iadd(memory, absolute)
    }

    /// The machine address and displacement of a direct operand.
    fn operand_address(&mut self, operand: Operand) -> (Value, i32) {
        let memory = self.builder.use_var(self.memory);
        let (base, offset) = match operand {
            Operand::Instance(offset) => (Some(self.instance), u64::from(offset)),
            Operand::Frame(offset) => (Some(self.frame), u64::from(offset)),
            fixed => (None, self.layout.absolute(fixed).unwrap_or(0)),
        };
        let address = match base {
            Some(base) => self.builder.ins().iadd(memory, base),
            None => memory,
        };
        match i32::try_from(offset) {
            Ok(displacement) => (address, displacement),
            Err(_) => (self.builder.ins().iadd_imm_u(address, offset as i64), 0),
        }
    }

    /// Loads a value of IR type `ty` from a direct operand.
    pub(crate) fn load(&mut self, ty: Type, operand: Operand) -> Value {
        if let Operand::Const(offset) = operand
            && let Some(folded) = self.folded_constant(ty, offset)
        {
            return folded;
        }
        if let Some(checked) = self.invariant(ty, operand) {
            return checked;
        }
        if let Some(promoted) = self.promoted_load(ty, operand) {
            return promoted;
        }
        let (address, displacement) = self.operand_address(operand);
        self.builder
            .ins()
            .load(ty, memory_flags(), address, displacement)
    }

    /// Stores a value into a direct operand.
    pub(crate) fn store(&mut self, value: Value, operand: Operand) {
        if self.promoted_store(value, operand) {
            return;
        }
        let (address, displacement) = self.operand_address(operand);
        self.builder
            .ins()
            .store(memory_flags(), value, address, displacement);
    }
}

/// An instruction index and a fault kind (below 256, `fault_kind`) as the one parameter of
/// a shared fault block: the index in the upper bits, the kind in the lowest byte.
fn pack_site(pc: u32, kind: u32) -> i64 {
    (i64::from(pc) << 8) | i64::from(kind & 0xFF)
}

/// The integer IR type of an elementary type's size (reals too: moves are bit copies).
pub(crate) fn int_type(ty: Elementary) -> Type {
    match ty.size_bytes() {
        1 => types::I8,
        2 => types::I16,
        4 => types::I32,
        _ => types::I64,
    }
}

/// Whether an elementary type is an integer the interpreter computes with signed arithmetic.
pub(crate) fn is_signed(ty: Elementary) -> bool {
    ty.is_signed()
}

#[cfg(test)]
mod tests;
