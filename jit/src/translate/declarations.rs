//! The module's function declarations as building a function's IR reads them, shared
//! read-only by the threads that build an image's functions at once (`docs/native-engine.md`
//! §9.3).

use cranelift_codegen::ir::{ExtFuncData, ExternalName, FuncRef, Function, UserExternalName};
use cranelift_codegen::isa::TargetFrontendConfig;
use cranelift_module::{FuncId, Module, ModuleDeclarations};

/// The functions declared in a module and its target's configuration: all that building a
/// function needs of the module. Unlike the module (whose `declare_func_in_func` takes it
/// mutably), it is `Sync`, so several threads build functions from it at once.
#[derive(Clone, Copy)]
pub(crate) struct FunctionDeclarations<'a> {
    /// Every function declared in the module, by id.
    declarations: &'a ModuleDeclarations,
    /// What the module's target tells a function builder (the pointer type, for one).
    config: TargetFrontendConfig,
}

impl<'a> FunctionDeclarations<'a> {
    /// The declarations of `module`, as they are now: the functions it declares later are
    /// not in them, so every function a call may name is declared first.
    pub(crate) fn of<M: Module + ?Sized>(module: &'a M) -> Self {
        Self {
            declarations: module.declarations(),
            config: module.target_config(),
        }
    }

    /// The target's configuration, which finalising a function builder takes.
    pub(crate) fn target_config(&self) -> TargetFrontendConfig {
        self.config
    }

    /// Declares the module's function `id` in `function` and gives its reference there: what
    /// Cranelift's `Module::declare_func_in_func` makes (the declared signature, the name
    /// `u0:id`, colocated exactly when the linkage is final, not patchable), so a function
    /// built here has the same bytes as one built with the module.
    pub(crate) fn declare_in(&self, id: FuncId, function: &mut Function) -> FuncRef {
        let declaration = self.declarations.get_function_decl(id);
        let signature = function.import_signature(declaration.signature.clone());
        let name = function.declare_imported_user_function(UserExternalName {
            namespace: 0,
            index: id.as_u32(),
        });
        function.import_function(ExtFuncData {
            name: ExternalName::user(name),
            signature,
            colocated: declaration.linkage.is_final(),
            patchable: false,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use cranelift_codegen::ir::{AbiParam, Signature, UserFuncName, types};
    use cranelift_jit::{JITBuilder, JITModule};
    use cranelift_module::Linkage;

    #[test]
    fn a_declaration_is_the_one_the_module_makes() {
        let Ok(isa) = crate::isa::host_isa() else {
            // No native code generator for this host: nothing is built at all.
            return;
        };
        let mut module = JITModule::new(JITBuilder::with_isa(
            isa,
            cranelift_module::default_libcall_names(),
        ));
        let mut signature = module.make_signature();
        signature.params.push(AbiParam::new(types::I64));
        signature.returns.push(AbiParam::new(types::I32));
        let local = module
            .declare_function("local", Linkage::Local, &signature)
            .unwrap();
        let imported = module
            .declare_function(
                "imported",
                Linkage::Import,
                &Signature::new(signature.call_conv),
            )
            .unwrap();
        // Declared in the other order too, so the references are numbered as they come.
        let ids = [local, imported, local, imported];
        let mut theirs = Function::with_name_signature(UserFuncName::user(0, 9), signature);
        let mut ours = theirs.clone();
        let their_refs: Vec<FuncRef> = ids
            .iter()
            .map(|id| module.declare_func_in_func(*id, &mut theirs))
            .collect();
        let declarations = FunctionDeclarations::of(&module);
        let our_refs: Vec<FuncRef> = ids
            .iter()
            .map(|id| declarations.declare_in(*id, &mut ours))
            .collect();
        assert_eq!(our_refs, their_refs);
        assert_eq!(ours, theirs);
        // Both kinds of linkage are there: one colocated, one not.
        let text = ours.display().to_string();
        assert!(text.contains("colocated u0:0"), "{text}");
        assert!(text.contains("= u0:1"), "{text}");
        assert_eq!(
            declarations.target_config().pointer_type(),
            module.target_config().pointer_type()
        );
        crate::machine::discard(module);
    }
}
