//! Building the code module of one image: every POU translated, compiled (on several threads,
//! `compile.rs`) and defined in order, the module finalised, and the code-size count
//! (`docs/native-engine.md` §8.2, §9.2, §9.3).

use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::{Arc, Mutex};

use cranelift_codegen::ir::Signature;
use cranelift_frontend::FunctionBuilderContext;
use cranelift_jit::{JITBuilder, JITModule};
use cranelift_module::{FuncId, Linkage, Module};
use program_image::ProgramImage;

use crate::compile::{Built, Compiled, NotCompiled, Piece, Task, Threads, compile_all};

use crate::isa::{NativeUnsupported, host_isa};
use crate::layout::Layout;
use crate::machine::{self, CountingMemory, MachineCode};
use crate::translate::declarations::FunctionDeclarations;
use crate::translate::host_calls::{Imports, PureFunctions, libcall_name, libcall_symbols};
use crate::translate::stub::{StubKind, StubTarget, stub_signature, stubs_needed, translate_stub};
use crate::translate::{Environment, pou_signature, translate_pou};
use crate::{Counters, Entry, Host, Status};

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
        Self::with_symbols(image, layout, our_symbols(pure), Threads::Host)
    }

    /// [`Translation::new`] with the symbols the module may import given as a table of names
    /// and addresses (the tests leave one out to see it refused as foreign), and the threads
    /// the functions are compiled on (the tests compare one with several).
    pub(crate) fn with_symbols(
        image: &ProgramImage,
        layout: &Layout,
        table: Vec<(&'static str, usize)>,
        threads: Threads,
    ) -> Result<Code, NativeUnsupported> {
        // The translator relies on verification (operands inside their regions, jump targets
        // inside the POU, bits below their widths, §2); checking again keeps `Code` sound
        // whatever image it is given.
        image.verify()?;
        layout.check(image)?;
        let isa = host_isa()?;
        let code_bytes = Arc::new(AtomicU64::new(0));
        let freed = Arc::new(AtomicBool::new(false));
        let symbols = Symbols::default();
        let mut builder = JITBuilder::with_isa(isa, Box::new(libcall_name));
        // Every name the module asks for comes here (the builder's own table is left empty,
        // and this lookup is tried before the system's symbol search, which is therefore never
        // reached), so the names it resolved are known and a foreign one refuses the module.
        let lookup = symbols.clone();
        builder.symbol_lookup_fn(Box::new(move |name| Some(lookup.resolve(name, &table))));
        builder.memory_provider(Box::new(CountingMemory::new(
            Arc::clone(&code_bytes),
            Arc::clone(&freed),
        )));
        let mut module = JITModule::new(builder);
        let imports = match Imports::declare(&mut module) {
            Ok(imports) => imports,
            Err(error) => {
                machine::discard(module);
                return Err(NativeUnsupported::Module(error));
            }
        };
        let signature = pou_signature(module.make_signature());
        let stub_signature = stub_signature(module.make_signature());
        // Every POU's function is declared before any is translated, so that a call can name
        // its callee's function (§4.4); a POU whose function cannot be declared runs in the
        // interpreter, and its callers hand their calls of it to the interpreter.
        let mut untranslated = Vec::new();
        let mut functions = Vec::with_capacity(image.pous.len());
        for (index, pou) in image.pous.iter().enumerate() {
            match module.declare_function(&format!("rivet_pou_{index}"), Linkage::Local, &signature)
            {
                Ok(id) => functions.push(Some(id)),
                Err(error) => {
                    untranslated.push(Untranslated {
                        pou: index as u32,
                        name: pou.name.clone(),
                        instruction: None,
                        reason: error.to_string(),
                    });
                    functions.push(None);
                }
            }
        }
        // The entry stubs some call needs (§4.4), declared beside their callees; a callee
        // without a function has none.
        let needed = stubs_needed(&image.pous);
        let mut stubs: Vec<[Option<FuncId>; 2]> = Vec::with_capacity(image.pous.len());
        for (index, kinds) in needed.iter().enumerate() {
            let mut ids = [None; 2];
            for kind in [StubKind::Enter, StubKind::Prepare] {
                if !kinds[kind as usize] || functions[index].is_none() {
                    continue;
                }
                match module.declare_function(&kind.name(index), Linkage::Local, &stub_signature) {
                    Ok(id) => ids[kind as usize] = Some(id),
                    Err(error) => {
                        // The callee's calls then cannot be made by generated code at all.
                        untranslated.push(Untranslated {
                            pou: index as u32,
                            name: image.pous[index].name.clone(),
                            instruction: None,
                            reason: error.to_string(),
                        });
                        functions[index] = None;
                        ids = [None; 2];
                        break;
                    }
                }
            }
            stubs.push(ids);
        }
        let folded_constants = crate::translate::scalar::constant_pool_is_read_only(image)
            .then_some(image.constants.as_slice());
        // Translated and compiled until no POU is refused anew: a refused callee has no
        // function, so its callers (only they) are translated again with their calls of it
        // handed to the interpreter; only then is anything defined, so no machine code calls
        // a function that is not defined (§8.2).
        let callees: Vec<Vec<u32>> = image
            .pous
            .iter()
            .map(|pou| called_pous(&pou.code))
            .collect();
        let mut compiled: Vec<Option<Compiled>> = image.pous.iter().map(|_| None).collect();
        let mut compiled_stubs: Vec<[Option<Compiled>; 2]> =
            image.pous.iter().map(|_| [None, None]).collect();
        let mut pending = vec![true; image.pous.len()];
        loop {
            // Every pending POU with a function is a task: its function and stubs are built
            // and compiled together on as many threads as `threads` gives (§9.3).
            let mut tasks = Vec::new();
            for (index, pou) in image.pous.iter().enumerate() {
                if !std::mem::take(&mut pending[index]) {
                    continue;
                }
                compiled[index] = None;
                if functions[index].is_some() {
                    let stub_count = stubs[index].iter().flatten().count();
                    tasks.push(Task {
                        pou: index,
                        instructions: pou.code.len(),
                        functions: 1 + stub_count,
                    });
                }
            }
            let built_pous: Vec<usize> = tasks.iter().map(|task| task.pou).collect();
            let results = {
                let environment = Environment {
                    pous: &image.pous,
                    layout,
                    imports: &imports,
                    folded_constants,
                    signature: signature.clone(),
                    functions: &functions,
                    stubs: &stubs,
                };
                // Read-only from here until every function is compiled: the threads name
                // callees and imports from the declarations alone.
                let declarations = FunctionDeclarations::of(&module);
                let build = |at: usize, function_context: &mut FunctionBuilderContext| {
                    build_pou(
                        &environment,
                        &declarations,
                        at,
                        &stub_signature,
                        function_context,
                    )
                };
                compile_all(tasks, &build, module.isa(), threads)
            };
            let mut refused_now = Vec::new();
            for (at, built) in built_pous.into_iter().zip(results) {
                let mut results = match built {
                    Built::Compiled(results) => results.into_iter(),
                    Built::Refused(refusal) => {
                        refused_now.push(refusal);
                        continue;
                    }
                    Built::Failed => {
                        refused_now.push(Untranslated {
                            pou: at as u32,
                            name: image.pous[at].name.clone(),
                            instruction: None,
                            reason: "the translator failed on it (an internal error)".into(),
                        });
                        continue;
                    }
                };
                let mut next_result = || {
                    results.next().unwrap_or_else(|| {
                        Err(NotCompiled(
                            "its machine code was lost (an internal error)".into(),
                        ))
                    })
                };
                let function = next_result();
                let made = [StubKind::Enter, StubKind::Prepare]
                    .map(|kind| stubs[at][kind as usize].map(|_| next_result()));
                // The callee's stubs are its own: one that cannot be made leaves the callee
                // to the interpreter, with its callers' calls. The function's reason comes
                // first, then its stubs' in order.
                let outcome = function.and_then(|function| {
                    let mut ready = [None, None];
                    for (slot, stub) in made.into_iter().enumerate() {
                        if let Some(stub) = stub {
                            ready[slot] = Some(stub?);
                        }
                    }
                    Ok((function, ready))
                });
                match outcome {
                    Ok((function, ready)) => {
                        compiled[at] = Some(function);
                        compiled_stubs[at] = ready;
                    }
                    Err(NotCompiled(reason)) => refused_now.push(Untranslated {
                        pou: at as u32,
                        name: image.pous[at].name.clone(),
                        instruction: None,
                        reason,
                    }),
                }
            }
            if refused_now.is_empty() {
                break;
            }
            let newly_refused: Vec<u32> = refused_now.iter().map(|refusal| refusal.pou).collect();
            for refusal in refused_now {
                functions[refusal.pou as usize] = None;
                stubs[refusal.pou as usize] = [None; 2];
                compiled_stubs[refusal.pou as usize] = [None, None];
                untranslated.push(refusal);
            }
            // The code of a POU that calls none of the newly refused ones names only
            // functions that are still there, and is kept.
            for (index, called) in callees.iter().enumerate() {
                pending[index] = functions[index].is_some()
                    && called.iter().any(|callee| newly_refused.contains(callee));
            }
        }
        let mut defined = Vec::with_capacity(image.pous.len());
        #[cfg(test)]
        let mut listings = Vec::new();
        #[cfg(test)]
        let mut defined_pieces = Vec::new();
        for (index, ((pou, function), made)) in image
            .pous
            .iter()
            .zip(compiled)
            .zip(compiled_stubs)
            .enumerate()
        {
            let (Some(function), Some(id)) = (function, functions[index]) else {
                #[cfg(test)]
                listings.push(String::new());
                defined.push(None);
                continue;
            };
            #[cfg(test)]
            listings.push(function.listing.clone());
            // The stubs first, then the function: a POU counts as defined with all of them.
            let pieces = [StubKind::Enter, StubKind::Prepare]
                .into_iter()
                .zip(made)
                .filter_map(|(kind, stub)| Some((stubs[index][kind as usize]?, stub?)))
                .chain([(id, function)]);
            let mut failure = None;
            for (piece_id, piece) in pieces {
                #[cfg(test)]
                defined_pieces.push(DefinedPiece::of(piece_id, &piece));
                if let Err(error) = module.define_function_bytes(
                    piece_id,
                    piece.alignment,
                    &piece.bytes,
                    &piece.relocations,
                ) {
                    failure = Some(error.to_string());
                    break;
                }
            }
            match failure {
                None => defined.push(Some(id)),
                Some(error) => {
                    // Only a module error (no memory for the code) can fail here; a caller of
                    // this POU then names a function that is not defined, finalising asks
                    // the symbol lookup for it, and the whole image is refused.
                    untranslated.push(Untranslated {
                        pou: index as u32,
                        name: pou.name.clone(),
                        instruction: None,
                        reason: error,
                    });
                    defined.push(None);
                }
            }
        }
        if let Err(error) = module.finalize_definitions() {
            machine::discard(module);
            return Err(NativeUnsupported::Module(Box::new(error)));
        }
        if let Some(name) = symbols.foreign() {
            machine::discard(module);
            return Err(NativeUnsupported::ForeignSymbol(name));
        }
        let sizes = image
            .pous
            .iter()
            .map(|pou| (u64::from(pou.instance_size), u64::from(pou.frame_size)))
            .collect();
        let machine = MachineCode::new(module, &defined, &signature, sizes, *layout);
        for (index, pou) in image.pous.iter().enumerate() {
            let index = index as u32;
            if defined[index as usize].is_some() && !machine.has(index) {
                untranslated.push(Untranslated {
                    pou: index,
                    name: pou.name.clone(),
                    instruction: None,
                    reason:
                        "its function was not declared with the POU signature (an internal error)"
                            .into(),
                });
            }
        }
        untranslated.sort_by_key(|refusal| refusal.pou);
        Ok(Code {
            untranslated,
            code_bytes: code_bytes.load(Ordering::Relaxed),
            imported: symbols.resolved(),
            freed,
            #[cfg(test)]
            listings,
            #[cfg(test)]
            defined_pieces,
            machine,
        })
    }
}

/// Builds POU `at`'s function and then its entry stubs, in the order of `StubKind` (the order
/// their machine code is taken back in), with `function_context`, or says why the translator
/// refuses it.
fn build_pou(
    environment: &Environment<'_>,
    declarations: &FunctionDeclarations<'_>,
    at: usize,
    stub_signature: &Signature,
    function_context: &mut FunctionBuilderContext,
) -> Result<Vec<Piece>, Untranslated> {
    let index = at as u32;
    let (Some(pou), Some(Some(id))) = (environment.pous.get(at), environment.functions.get(at))
    else {
        // Only a POU with a function is given to the threads.
        return Err(Untranslated {
            pou: index,
            name: String::new(),
            instruction: None,
            reason: "it has no function to translate into (an internal error)".into(),
        });
    };
    #[cfg(test)]
    let panics = pou.name == crate::compile::COMPILE_PANICS_IN_TESTS;
    let function = translate_pou(environment, index, function_context, declarations)?;
    let mut pieces = vec![Piece {
        function,
        id: *id,
        #[cfg(test)]
        panics,
    }];
    let target = StubTarget {
        pou,
        index,
        function: *id,
        imports: environment.imports,
        signature: stub_signature.clone(),
    };
    let ids = environment.stubs.get(at).copied().unwrap_or_default();
    for kind in [StubKind::Enter, StubKind::Prepare] {
        if let Some(stub_id) = ids[kind as usize] {
            pieces.push(Piece {
                function: translate_stub(&target, kind, function_context, declarations),
                id: stub_id,
                #[cfg(test)]
                panics,
            });
        }
    }
    Ok(pieces)
}

/// The names and addresses of every symbol generated code may import: the callbacks, the
/// runtime's pure functions and the float rounding library calls ([`crate::OUR_SYMBOLS`]).
pub(crate) fn our_symbols(pure: &PureFunctions) -> Vec<(&'static str, usize)> {
    machine::callback_symbols()
        .into_iter()
        .chain(pure.symbols())
        .chain(libcall_symbols())
        .map(|(name, address)| (name, address as usize))
        .collect()
}

/// The names a module asked for while it was finalised, shared with its symbol lookup.
#[derive(Clone, Default)]
struct Symbols {
    /// Every name asked for, in order, and whether it was in the table.
    names: Arc<Mutex<Vec<(String, bool)>>>,
    /// Whether any name was not in the table; an atomic, so that a poisoned lock cannot hide
    /// it.
    foreign: Arc<AtomicBool>,
}

impl Symbols {
    /// The address of `name` in `table`; a foreign name is recorded and answered with an
    /// address that is never called, because the module is then refused.
    fn resolve(&self, name: &str, table: &[(&'static str, usize)]) -> *const u8 {
        let found = table.iter().find(|(known, _)| *known == name);
        if found.is_none() {
            self.foreign.store(true, Ordering::Relaxed);
        }
        self.names
            .lock()
            .unwrap_or_else(|poisoned| poisoned.into_inner())
            .push((name.to_string(), found.is_some()));
        found.map_or_else(machine::foreign_symbol, |(_, address)| {
            *address as *const u8
        })
    }

    /// The first foreign name asked for, if any.
    fn foreign(&self) -> Option<String> {
        if !self.foreign.load(Ordering::Relaxed) {
            return None;
        }
        let names = self
            .names
            .lock()
            .unwrap_or_else(|poisoned| poisoned.into_inner());
        // Refused even if the name itself was lost: the flag is what decides.
        Some(
            names
                .iter()
                .find(|(_, ours)| !ours)
                .map(|(name, _)| name.clone())
                .unwrap_or_default(),
        )
    }

    /// Every name asked for.
    fn resolved(&self) -> Vec<String> {
        self.names
            .lock()
            .unwrap_or_else(|poisoned| poisoned.into_inner())
            .iter()
            .map(|(name, _)| name.clone())
            .collect()
    }
}

/// The machine code of one image: a function per translated POU (`docs/native-engine.md`
/// §1.3). Freed when dropped.
pub struct Code {
    /// The POUs that run in the interpreter, with the reasons.
    untranslated: Vec<Untranslated>,
    /// Every byte allocated for the machine code.
    code_bytes: u64,
    /// The symbols the module resolved when it was finalised.
    imported: Vec<String>,
    /// Set when the machine code is unmapped.
    freed: Arc<AtomicBool>,
    /// The machine code of each POU as text, for the tests.
    #[cfg(test)]
    pub(crate) listings: Vec<String>,
    /// Every function and stub given to the module, in the order they were defined, for the
    /// tests to compare translations.
    #[cfg(test)]
    pub(crate) defined_pieces: Vec<DefinedPiece>,
    /// The functions and the module; its `Drop` frees the machine code.
    machine: MachineCode,
}

impl std::fmt::Debug for Code {
    fn fmt(&self, formatter: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        formatter
            .debug_struct("Code")
            .field("untranslated", &self.untranslated)
            .field("code_bytes", &self.code_bytes)
            .field("imported", &self.imported)
            .finish()
    }
}

impl Code {
    /// Whether POU `pou` has machine code.
    pub fn has(&self, pou: u32) -> bool {
        self.machine.has(pou)
    }

    /// The POUs that run in the interpreter, with the reasons.
    pub fn untranslated(&self) -> &[Untranslated] {
        &self.untranslated
    }

    /// Every byte allocated for the machine code (text, read-only data, alignment; §9.2).
    pub fn code_bytes(&self) -> u64 {
        self.code_bytes
    }

    /// The symbols the module resolved when it was finalised: the callbacks, pure functions
    /// and library calls its code calls (each one of [`crate::OUR_SYMBOLS`], or the image
    /// would have been refused).
    pub fn imported_symbols(&self) -> &[String] {
        &self.imported
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
        self.machine.run(pou, host, &entry, counters)
    }
}

/// The POUs `code` may call directly: those its `CallFunction`, `CallBlock` and
/// `CallVirtual` instructions name.
fn called_pous(code: &[program_image::Instr]) -> Vec<u32> {
    use program_image::Instr;
    let mut called = Vec::new();
    for instr in code {
        match instr {
            Instr::CallFunction { pou, .. } | Instr::CallBlock { pou, .. } => called.push(*pou),
            Instr::CallVirtual { table, .. } => {
                called.extend(table.iter().map(|(_, method)| *method));
            }
            _ => {}
        }
    }
    called.sort_unstable();
    called.dedup();
    called
}

/// A function or stub as it was given to the module: its id, machine code and relocations,
/// for the tests to compare translations made on different numbers of threads.
#[cfg(test)]
#[derive(Debug, PartialEq, Eq)]
pub(crate) struct DefinedPiece {
    /// Its id in the module.
    pub(crate) id: u32,
    /// Its machine code, before relocation.
    pub(crate) bytes: Vec<u8>,
    /// Its alignment in bytes.
    pub(crate) alignment: u64,
    /// Its relocations: offset, kind, target and addend of each.
    pub(crate) relocations: Vec<String>,
}

#[cfg(test)]
impl DefinedPiece {
    /// The record of `piece`, defined as `id`.
    fn of(id: FuncId, piece: &Compiled) -> Self {
        Self {
            id: id.as_u32(),
            bytes: piece.bytes.clone(),
            alignment: piece.alignment,
            relocations: piece
                .relocations
                .iter()
                .map(|relocation| {
                    format!(
                        "{} {:?} {:?} {}",
                        relocation.offset, relocation.kind, relocation.name, relocation.addend
                    )
                })
                .collect(),
        }
    }
}
