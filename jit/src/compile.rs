//! Translating an image's POUs into Cranelift functions and compiling those into machine code
//! on scoped threads (`docs/native-engine.md` §9.3). Building a function reads the module's
//! declarations only (`FunctionDeclarations`) and the code generator needs only the function
//! and the ISA, so each thread builds a POU's functions with its own `FunctionBuilderContext`
//! and compiles them with its own `cranelift_codegen::Context`, and the results come back in
//! the POUs' order, so the module defines the same bytes in the same order whatever the
//! number of threads.

use std::panic::AssertUnwindSafe;
use std::sync::{Mutex, PoisonError};

use cranelift_codegen::control::ControlPlane;
use cranelift_codegen::ir::Function;
use cranelift_codegen::isa::TargetIsa;
use cranelift_frontend::FunctionBuilderContext;
use cranelift_module::{FuncId, ModuleReloc};

use crate::translate::Untranslated;

/// The most threads one translation compiles on: past this the e-graph and register
/// allocation of a typical project's functions are done faster than the threads start, and a
/// large machine is left to the tasks it runs.
const MAX_THREADS: usize = 8;

/// Fewer functions than this are compiled on the loading thread alone: a small image (or a
/// round that compiles again only the callers of a refused POU) compiles in less time than
/// starting threads costs.
const FEWEST_FUNCTIONS_FOR_THREADS: usize = 16;

/// The stack of each compiling thread: a main thread's usual 8 MiB, so that a function the
/// loading thread could compile compiles on any thread (the memory is reserved, not used).
const THREAD_STACK_BYTES: usize = 8 << 20;

/// The name of a POU whose function makes the code generator panic in the tests.
#[cfg(test)]
pub(crate) const COMPILE_PANICS_IN_TESTS: &str = "CompilePanicsInTests";

#[cfg(test)]
thread_local! {
    /// The number of threads each call of [`compile_all`] on the current thread compiled on,
    /// in order, for the tests to see the parallel path taken.
    pub(crate) static THREADS_IN_TESTS: std::cell::RefCell<Vec<usize>> =
        const { std::cell::RefCell::new(Vec::new()) };
}

/// How many threads translate and compile an image's functions.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Threads {
    /// As many as the host offers to this process (`available_parallelism`, which on Linux
    /// counts only the processors the process may run on), at most [`MAX_THREADS`] and at most
    /// one per function; one (no thread started) for fewer than
    /// [`FEWEST_FUNCTIONS_FOR_THREADS`] functions.
    Host,
    /// This many (at least one, at most one per function), whatever the number of functions:
    /// the tests compare one thread with several.
    #[cfg(test)]
    Exactly(usize),
}

impl Threads {
    /// The threads that compile `functions` functions, the loading thread included.
    pub(crate) fn count(self, functions: usize) -> usize {
        match self {
            Threads::Host if functions < FEWEST_FUNCTIONS_FOR_THREADS => 1,
            Threads::Host => std::thread::available_parallelism()
                .map_or(1, std::num::NonZeroUsize::get)
                .min(MAX_THREADS)
                .min(functions),
            #[cfg(test)]
            Threads::Exactly(threads) => threads.min(functions).max(1),
        }
    }
}

/// A POU to translate and compile.
pub(crate) struct Task {
    /// The POU's index in the image.
    pub(crate) pou: usize,
    /// Its bytecode instructions: the threads take the largest POUs first.
    pub(crate) instructions: usize,
    /// The functions it will be built into (its own and its entry stubs'), which decide how
    /// many threads are worth starting.
    pub(crate) functions: usize,
}

/// A function built from a POU, to compile, and the id the module will define it as.
pub(crate) struct Piece {
    /// The function's Cranelift IR.
    pub(crate) function: Function,
    /// Its id in the module, which its relocations name it by.
    pub(crate) id: FuncId,
    /// Whether the code generator is made to panic on it (a POU named
    /// [`COMPILE_PANICS_IN_TESTS`]).
    #[cfg(test)]
    pub(crate) panics: bool,
}

/// One function's compiled machine code, not yet defined in the module.
pub(crate) struct Compiled {
    /// The machine code.
    pub(crate) bytes: Vec<u8>,
    /// Its alignment in bytes.
    pub(crate) alignment: u64,
    /// Its relocations: the calls of the imports and of other POUs.
    pub(crate) relocations: Vec<ModuleReloc>,
    /// The machine code as text, for the tests.
    #[cfg(test)]
    pub(crate) listing: String,
}

/// Why the code generator refused a function.
#[derive(Debug)]
pub(crate) struct NotCompiled(pub(crate) String);

/// What became of one POU's task.
pub(crate) enum Built {
    /// The translator refused the POU.
    Refused(Untranslated),
    /// The translator panicked on it (an internal error).
    Failed,
    /// Each function built from it, in the order built: its machine code, or why the code
    /// generator made none.
    Compiled(Vec<Result<Compiled, NotCompiled>>),
}

/// The work still to be taken: the tasks' positions with the tasks, largest first.
type Queue = Mutex<std::vec::IntoIter<(usize, Task)>>;

/// One thread's finished tasks, each with its position in the tasks given (and, in the
/// tests, the POUs its translation recorded).
type Done = Vec<(usize, Built, Recorded)>;

/// The POUs a task's translation recorded as translated, for the tests.
#[cfg(test)]
type Recorded = Vec<u32>;
/// Nothing is recorded outside the tests.
#[cfg(not(test))]
type Recorded = ();

/// Translates and compiles every task's POU for `isa` on the [`Threads::count`] of their
/// functions, at most one thread per POU (the calling thread one of them), and gives what
/// became of each in the tasks' order.
///
/// `build` makes a POU's functions (its own, then its stubs') with the thread's builder
/// context; each thread then compiles them with its own `cranelift_codegen::Context`. The
/// threads take the POUs largest first (the most bytecode instructions; a project's POUs range
/// from a few instructions to thousands), so that no thread is left with a large one at the
/// end; which thread builds and compiles a POU does not change its bytes. A panic of the
/// translator or of the code generator refuses that POU only; a thread that cannot be started
/// leaves its share to the others.
pub(crate) fn compile_all<B>(
    tasks: Vec<Task>,
    build: &B,
    isa: &dyn TargetIsa,
    threads: Threads,
) -> Vec<Built>
where
    B: Fn(usize, &mut FunctionBuilderContext) -> Result<Vec<Piece>, Untranslated> + Sync,
{
    let count = tasks.len();
    let functions = tasks.iter().map(|task| task.functions).sum();
    let threads = threads.count(functions).min(count).max(1);
    let mut largest_first: Vec<(usize, Task)> = tasks.into_iter().enumerate().collect();
    largest_first.sort_by_key(|(_, task)| std::cmp::Reverse(task.instructions));
    let queue: Queue = Mutex::new(largest_first.into_iter());
    let settings = TestSettings::of_this_thread();
    let mut parts: Vec<Done> = Vec::with_capacity(threads);
    if threads <= 1 {
        parts.push(compile_queued(&queue, build, isa));
        #[cfg(test)]
        THREADS_IN_TESTS.with(|counts| counts.borrow_mut().push(1));
    } else {
        std::thread::scope(|scope| {
            let helpers: Vec<_> = (1..threads)
                .filter_map(|number| {
                    std::thread::Builder::new()
                        .name(format!("rivet-jit-{number}"))
                        .stack_size(THREAD_STACK_BYTES)
                        .spawn_scoped(scope, || {
                            settings.apply();
                            compile_queued(&queue, build, isa)
                        })
                        .ok()
                })
                .collect();
            #[cfg(test)]
            THREADS_IN_TESTS.with(|counts| counts.borrow_mut().push(1 + helpers.len()));
            parts.push(compile_queued(&queue, build, isa));
            // Joined here, so that a thread that panicked outside its tasks' catch (which
            // nothing in `compile_queued` does) loses only its results instead of panicking
            // the scope: its POUs are then refused below.
            parts.extend(helpers.into_iter().filter_map(|helper| helper.join().ok()));
        });
    }
    let mut results: Vec<Option<(Built, Recorded)>> = (0..count).map(|_| None).collect();
    for (position, built, recorded) in parts.into_iter().flatten() {
        results[position] = Some((built, recorded));
    }
    results
        .into_iter()
        .map(|result| {
            let (built, _recorded) = result.unwrap_or_else(|| {
                let lost = NotCompiled("its compiling thread failed (an internal error)".into());
                (Built::Compiled(vec![Err(lost)]), Recorded::default())
            });
            // The POUs translated on the other threads are recorded on this one, in the
            // tasks' order, as one thread would have.
            #[cfg(test)]
            crate::translate::TRANSLATED_IN_TESTS
                .with(|translated| translated.borrow_mut().extend(_recorded));
            built
        })
        .collect()
}

/// What the tests set on the loading thread that building a POU reads (thread-locals, so
/// that tests running at once do not meet), carried to the compiling threads; nothing outside
/// the tests.
#[derive(Clone, Copy)]
struct TestSettings {
    /// Whether loops are left unpromoted (`PROMOTION_OFF_IN_TESTS`).
    #[cfg(test)]
    promotion_off: bool,
    /// Where guards count their outcomes: the loading thread's counters, which the test reads
    /// and which outlive the compiling threads.
    #[cfg(test)]
    guard_outcomes_at: usize,
}

impl TestSettings {
    /// The settings of the current thread.
    fn of_this_thread() -> Self {
        Self {
            #[cfg(test)]
            promotion_off: crate::translate::promote::PROMOTION_OFF_IN_TESTS
                .with(std::cell::Cell::get),
            #[cfg(test)]
            guard_outcomes_at: crate::translate::promote::guard_outcomes_address_in_tests(),
        }
    }

    /// Makes them the current thread's.
    #[cfg_attr(not(test), allow(clippy::unused_self))]
    fn apply(self) {
        #[cfg(test)]
        {
            crate::translate::promote::PROMOTION_OFF_IN_TESTS
                .with(|off| off.set(self.promotion_off));
            crate::translate::promote::GUARD_OUTCOMES_AT_IN_TESTS
                .with(|at| at.set(Some(self.guard_outcomes_at)));
        }
    }
}

/// Translates and compiles the POUs of tasks taken from `queue` until it is empty, with one
/// builder context and one code generator context, and gives them with their positions.
fn compile_queued<B>(queue: &Queue, build: &B, isa: &dyn TargetIsa) -> Done
where
    B: Fn(usize, &mut FunctionBuilderContext) -> Result<Vec<Piece>, Untranslated> + Sync,
{
    let mut function_context = FunctionBuilderContext::new();
    let mut codegen = cranelift_codegen::Context::new();
    let mut done = Vec::new();
    loop {
        // The lock is held only to take the next task (a lock poisoned by another thread's
        // panic still holds a sound iterator: `next` does not panic halfway).
        let next = queue.lock().unwrap_or_else(PoisonError::into_inner).next();
        let Some((position, task)) = next else {
            return done;
        };
        // This thread's record (the loading thread's own, when it is this one) is set aside
        // while the task's translation records into it.
        #[cfg(test)]
        let earlier = crate::translate::TRANSLATED_IN_TESTS.with(|translated| translated.take());
        // A translator bug must not take the loading thread down: the POU falls back to the
        // interpreter with the reason (§8.2).
        let pieces =
            std::panic::catch_unwind(AssertUnwindSafe(|| build(task.pou, &mut function_context)));
        #[cfg(test)]
        let recorded =
            crate::translate::TRANSLATED_IN_TESTS.with(|translated| translated.replace(earlier));
        #[cfg(not(test))]
        let recorded = ();
        let built = match pieces {
            Ok(Ok(pieces)) => Built::Compiled(
                pieces
                    .into_iter()
                    .map(|piece| compile_caught(&mut codegen, piece, isa))
                    .collect(),
            ),
            Ok(Err(refusal)) => Built::Refused(refusal),
            Err(_) => {
                // The builder context may be left halfway through a function.
                function_context = FunctionBuilderContext::new();
                Built::Failed
            }
        };
        done.push((position, built, recorded));
    }
}

/// Compiles `piece` with `codegen`, a panic of the code generator caught as its refusal.
fn compile_caught(
    codegen: &mut cranelift_codegen::Context,
    piece: Piece,
    isa: &dyn TargetIsa,
) -> Result<Compiled, NotCompiled> {
    // A code generator bug must not take the loading thread down: the POU falls back to the
    // interpreter with the reason (§8.2).
    let result = std::panic::catch_unwind(AssertUnwindSafe(|| {
        #[cfg(test)]
        if piece.panics {
            panic!("the code generator fails (injected by a test)");
        }
        compile(codegen, piece.function, piece.id, isa)
    }));
    match result {
        Ok(result) => {
            codegen.clear();
            result
        }
        Err(_) => {
            // The context may be left halfway through a compilation.
            *codegen = cranelift_codegen::Context::new();
            Err(NotCompiled(
                "the code generator failed on it (an internal error)".into(),
            ))
        }
    }
}

/// Compiles function `function` (to be defined as `id`) for `isa`, or says why it cannot.
fn compile(
    codegen: &mut cranelift_codegen::Context,
    function: Function,
    id: FuncId,
    isa: &dyn TargetIsa,
) -> Result<Compiled, NotCompiled> {
    codegen.func = function;
    // The tests read the machine code's listing (§7 rule 5: no reachable trap).
    codegen.set_disasm(cfg!(test));
    codegen
        .compile(isa, &mut ControlPlane::default())
        .map_err(|error| NotCompiled(format!("{:?}", error.inner)))?;
    // Read again through a shared borrow, beside the function the relocations name.
    let compiled = codegen
        .compiled_code()
        .ok_or_else(|| NotCompiled("the code generator gave no code (an internal error)".into()))?;
    let relocations = compiled
        .buffer
        .relocs()
        .iter()
        .map(|relocation| ModuleReloc::from_mach_reloc(relocation, &codegen.func, id))
        .collect();
    Ok(Compiled {
        bytes: compiled.code_buffer().to_vec(),
        alignment: u64::from(compiled.buffer.alignment),
        relocations,
        #[cfg(test)]
        listing: compiled.vcode.clone().unwrap_or_default(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn few_functions_are_compiled_on_the_loading_thread_many_on_at_most_eight() {
        let offered = std::thread::available_parallelism().map_or(1, std::num::NonZeroUsize::get);
        assert_eq!(Threads::Host.count(0), 1);
        assert_eq!(Threads::Host.count(15), 1);
        assert_eq!(Threads::Host.count(16), offered.min(8));
        assert_eq!(Threads::Host.count(5_000), offered.min(8));
        assert_eq!(Threads::Exactly(4).count(2), 2);
        assert_eq!(Threads::Exactly(4).count(0), 1);
        assert_eq!(Threads::Exactly(0).count(40), 1);
    }

    /// A compiling thread builds with the test's settings: loops unpromoted when the test says
    /// so, and guards counting in the test thread's counters, which outlive the compiling
    /// thread (its own would be freed with it, and the test would read nothing).
    #[test]
    fn compiling_threads_build_with_the_tests_settings() {
        use crate::translate::promote::{PROMOTION_OFF_IN_TESTS, guard_outcomes_address_in_tests};
        let seen_on_a_thread = |settings: Option<TestSettings>| {
            std::thread::spawn(move || {
                if let Some(settings) = settings {
                    settings.apply();
                }
                (
                    PROMOTION_OFF_IN_TESTS.with(std::cell::Cell::get),
                    guard_outcomes_address_in_tests(),
                )
            })
            .join()
            .unwrap()
        };
        PROMOTION_OFF_IN_TESTS.with(|off| off.set(true));
        let settings = TestSettings::of_this_thread();
        PROMOTION_OFF_IN_TESTS.with(|off| off.set(false));
        let here = guard_outcomes_address_in_tests();
        assert_eq!(seen_on_a_thread(Some(settings)), (true, here));
        // Without them a thread has its own.
        let (off, counters) = seen_on_a_thread(None);
        assert!(!off);
        assert_ne!(counters, here);
    }
}
