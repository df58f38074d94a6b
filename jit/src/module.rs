//! Building the code module of one image: every POU translated and defined, the module
//! finalised, and the code-size count (`docs/native-engine.md` §8.2, §9.2).

use std::panic::AssertUnwindSafe;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::{Arc, Mutex};

use cranelift_frontend::FunctionBuilderContext;
use cranelift_jit::{JITBuilder, JITModule};
use cranelift_module::{Linkage, Module};
use program_image::ProgramImage;

use crate::isa::{NativeUnsupported, host_isa};
use crate::layout::Layout;
use crate::machine::{self, Checked, CountingMemory, MachineCode, PouEntry};
use crate::translate::host_calls::{Imports, PureFunctions, libcall_name, libcall_symbols};
use crate::translate::{Environment, pou_signature, translate_pou};
use crate::{Counters, Entry, Host, NativeFault, Site, Status};

pub use crate::translate::Untranslated;

/// The translation of an image into machine code (`docs/native-engine.md` §8).
#[derive(Debug)]
pub struct Translation;

impl Translation {
    /// Translates every POU of `image`, laid out in memory as `layout` says, with the
    /// runtime's `pure` functions. POUs the translator refuses are listed in
    /// [`Code::untranslated`] and run in the interpreter; the whole image is refused only when
    /// no machine code can be made at all.
    #[allow(clippy::new_ret_no_self)] // The translation is a step, its result the code.
    pub fn new(
        image: &ProgramImage,
        layout: &Layout,
        pure: &PureFunctions,
    ) -> Result<Code, NativeUnsupported> {
        // The translator relies on verification (operands inside their regions, jump targets
        // inside the POU, bits below their widths, §2); checking again keeps `Code` sound
        // whatever image it is given.
        image.verify()?;
        layout.check(image)?;
        let isa = host_isa()?;
        let code_bytes = Arc::new(AtomicU64::new(0));
        let freed = Arc::new(AtomicBool::new(false));
        let foreign: Arc<Mutex<Vec<String>>> = Arc::default();
        let mut builder = JITBuilder::with_isa(isa, Box::new(libcall_name));
        for (name, address) in machine::callback_symbols()
            .into_iter()
            .chain(pure.symbols())
            .chain(libcall_symbols())
        {
            builder.symbol(name, address);
        }
        let seen = Arc::clone(&foreign);
        // Tried before the system's symbol search, which is therefore never reached.
        builder.symbol_lookup_fn(Box::new(move |name| {
            if let Ok(mut seen) = seen.lock() {
                seen.push(name.to_string());
            }
            Some(machine::foreign_symbol())
        }));
        builder.memory_provider(Box::new(CountingMemory::new(
            Arc::clone(&code_bytes),
            Arc::clone(&freed),
        )));
        let mut module = JITModule::new(builder);
        let imports = Imports::declare(&mut module).map_err(|error| module_error(*error))?;
        let environment = Environment {
            pous: &image.pous,
            layout,
            imports: &imports,
            folded_constants: crate::translate::scalar::constant_pool_is_read_only(image)
                .then_some(image.constants.as_slice()),
            signature: pou_signature(module.make_signature()),
        };
        let mut function_context = FunctionBuilderContext::new();
        let mut codegen = module.make_context();
        let mut defined = Vec::with_capacity(image.pous.len());
        let mut untranslated = Vec::new();
        #[cfg(test)]
        let mut listings = Vec::new();
        for (index, pou) in image.pous.iter().enumerate() {
            let index = index as u32;
            let refused = |reason: String| Untranslated {
                pou: index,
                name: pou.name.clone(),
                instruction: None,
                reason,
            };
            // A translator bug must not take the loading thread down: the POU falls back to
            // the interpreter with the reason (§8.2).
            let translated = std::panic::catch_unwind(AssertUnwindSafe(|| {
                translate_pou(&environment, index, &mut function_context, &mut module)
            }));
            let function = match translated {
                Ok(Ok(function)) => function,
                Ok(Err(refusal)) => {
                    untranslated.push(refusal);
                    defined.push(None);
                    continue;
                }
                Err(_) => {
                    untranslated.push(refused(
                        "the translator failed on it (an internal error)".into(),
                    ));
                    defined.push(None);
                    function_context = FunctionBuilderContext::new();
                    continue;
                }
            };
            let id = match module.declare_function(
                &format!("rivet_pou_{index}"),
                Linkage::Local,
                &environment.signature,
            ) {
                Ok(id) => id,
                Err(error) => {
                    untranslated.push(refused(error.to_string()));
                    defined.push(None);
                    continue;
                }
            };
            codegen.func = function;
            // The tests read the machine code's listing (§7 rule 5: no reachable trap).
            codegen.set_disasm(cfg!(test));
            let result = module.define_function(id, &mut codegen);
            #[cfg(test)]
            listings.push(
                codegen
                    .compiled_code()
                    .and_then(|compiled| compiled.vcode.clone())
                    .unwrap_or_default(),
            );
            module.clear_context(&mut codegen);
            match result {
                Ok(()) => defined.push(Some(id)),
                Err(error) => {
                    untranslated.push(refused(format!("{error:?}")));
                    defined.push(None);
                }
            }
        }
        module.finalize_definitions().map_err(module_error)?;
        let foreign_names = foreign
            .lock()
            .map(|names| names.clone())
            .unwrap_or_default();
        if let Some(name) = foreign_names.into_iter().next() {
            // Dropping the module leaks its code by design; free it before refusing.
            drop(MachineCode::new(module));
            return Err(NativeUnsupported::ForeignSymbol(name));
        }
        let functions = defined
            .iter()
            .map(|id| id.map(|id| PouEntry::from_finalized(module.get_finalized_function(id))))
            .collect();
        let sizes = image
            .pous
            .iter()
            .map(|pou| (u64::from(pou.instance_size), u64::from(pou.frame_size)))
            .collect();
        Ok(Code {
            functions,
            sizes,
            layout: *layout,
            untranslated,
            code_bytes: code_bytes.load(Ordering::Relaxed),
            freed,
            #[cfg(test)]
            listings,
            _machine: MachineCode::new(module),
        })
    }
}

fn module_error(error: cranelift_module::ModuleError) -> NativeUnsupported {
    NativeUnsupported::Module(error.to_string())
}

/// The machine code of one image: a function per translated POU (`docs/native-engine.md`
/// §1.3). Freed when dropped.
pub struct Code {
    functions: Vec<Option<PouEntry>>,
    /// Per POU: instance and frame sizes in bytes.
    sizes: Vec<(u64, u64)>,
    layout: Layout,
    untranslated: Vec<Untranslated>,
    code_bytes: u64,
    freed: Arc<AtomicBool>,
    /// The machine code of each POU as text, for the tests.
    #[cfg(test)]
    pub(crate) listings: Vec<String>,
    /// Owned for its `Drop`, which frees the machine code.
    _machine: MachineCode,
}

impl std::fmt::Debug for Code {
    fn fmt(&self, formatter: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        formatter
            .debug_struct("Code")
            .field(
                "translated",
                &self.functions.iter().filter(|f| f.is_some()).count(),
            )
            .field("untranslated", &self.untranslated)
            .field("code_bytes", &self.code_bytes)
            .finish()
    }
}

impl Code {
    /// Whether POU `pou` has machine code.
    pub fn has(&self, pou: u32) -> bool {
        matches!(self.functions.get(pou as usize), Some(Some(_)))
    }

    /// The POUs that run in the interpreter, with the reasons.
    pub fn untranslated(&self) -> &[Untranslated] {
        &self.untranslated
    }

    /// Every byte allocated for the machine code (text, read-only data, alignment; §9.2).
    pub fn code_bytes(&self) -> u64 {
        self.code_bytes
    }

    /// The symbols generated code imports (each one of [`crate::OUR_SYMBOLS`]).
    pub fn imported_symbols(&self) -> Vec<String> {
        Imports::names()
    }

    /// A flag set once the machine code is unmapped (when this `Code` is dropped).
    pub fn freed_flag(&self) -> Arc<AtomicBool> {
        Arc::clone(&self.freed)
    }

    /// Runs POU `pou`'s machine code on the host's memory, from `entry`, with the counters
    /// carried in and out. A POU without machine code, or bases outside the memory (the checks
    /// of the interpreter's `push_frame`), fault at instruction 0: `StackOverflow` for a frame
    /// past the stack's end, `Memory` otherwise.
    pub fn run(
        &self,
        pou: u32,
        host: &mut dyn Host,
        entry: Entry<'_>,
        counters: &mut Counters,
    ) -> Status {
        let site = Site {
            pou,
            instruction: 0,
        };
        match self.check(pou, host, &entry) {
            Ok(checked) => machine::enter(checked, host, &entry, counters),
            Err(fault) => {
                host.fault(site, fault);
                Status::Faulted
            }
        }
    }

    /// The checks of §7 rule 2 on entry.
    fn check(
        &self,
        pou: u32,
        host: &mut dyn Host,
        entry: &Entry<'_>,
    ) -> Result<Checked, NativeFault> {
        let index = pou as usize;
        let (Some(Some(function)), Some((instance_size, frame_size))) =
            (self.functions.get(index), self.sizes.get(index))
        else {
            return Err(NativeFault::Memory);
        };
        let memory_len = host.memory().len() as u64;
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
        })
    }
}
