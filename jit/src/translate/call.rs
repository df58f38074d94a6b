//! Calls out of generated code (`docs/native-engine.md` §4.3, §4.4). In this wave every call
//! instruction is handed to the interpreter through `rivet_jit_op`, which runs the whole call
//! (and may enter generated code again for a callee with machine code); the inline calls of
//! §4.4 come with wave 2.

use cranelift_codegen::ir::{FuncRef, InstBuilder, Value, types};

use super::host_calls::Import;
use super::{Translator, context, context_flags};

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
    }

    /// Calls a host callback: the budget stored before, the memory and the budget loaded
    /// after (§4.2, §7 rule 3). Returns the callback's result, if it has one.
    pub(crate) fn call_host(&mut self, import: Import, arguments: &[Value]) -> Value {
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
