//! The native engine's part of loading an image: the translation into machine code, with
//! anything that goes wrong in it turned into a fallback to the interpreter
//! (`docs/native-engine.md` §8.2).

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::time::Instant;

use program_image::ProgramImage;

use super::choice::NativeReport;
use super::jit_pure;
use super::memory::Regions;

/// Translates `image`, laid out in the engine's memory as `regions` says, into machine code,
/// and reports what was made. No machine code (`None`) means the interpreter runs the whole
/// image, which the report says: no backend, no executable memory, or a panic anywhere in the
/// translation, the layout or the module's finalisation (a bug of the code generator must not
/// make an image that the interpreter runs fail to load).
pub(super) fn translate(
    image: &ProgramImage,
    regions: &Regions,
) -> (Option<jit::Code>, NativeReport) {
    let started = Instant::now();
    let outcome = catch_unwind(AssertUnwindSafe(|| {
        #[cfg(test)]
        tests::panic_if_asked();
        // The layout comes from the regions the interpreter uses, so that both engines address
        // the same bytes; the translator checks it against the image's sizes.
        let layout = regions.jit_layout();
        jit::Translation::new(image, &layout, &jit_pure::PURE_FUNCTIONS)
    }));
    match outcome {
        Ok(Ok(native)) => {
            let report = NativeReport::native(image, &native, started.elapsed());
            (Some(native), report)
        }
        Ok(Err(unsupported)) => (
            None,
            NativeReport::unavailable(image, &unsupported, started.elapsed()),
        ),
        Err(payload) => {
            let reason = format!(
                "internal error of the native code generator: {}",
                panic_message(payload.as_ref())
            );
            (
                None,
                NativeReport::unavailable(image, &reason, started.elapsed()),
            )
        }
    }
}

/// The text a panic was raised with, when it was raised with text.
fn panic_message(payload: &(dyn std::any::Any + Send)) -> &str {
    if let Some(text) = payload.downcast_ref::<&str>() {
        text
    } else if let Some(text) = payload.downcast_ref::<String>() {
        text
    } else {
        "a panic without a message"
    }
}

#[cfg(test)]
pub(super) mod tests {
    use std::cell::Cell;

    use super::*;
    use crate::engine::{Engine, EngineChoice};
    use crate::test_images::{self, TestTask};

    thread_local! {
        /// Whether the next translation on this thread panics, as a code generator bug would.
        static PANIC_IN_TRANSLATION: Cell<bool> = const { Cell::new(false) };
    }

    /// Panics when the running test asked for it, inside the part of the load a panic is
    /// caught in.
    pub(super) fn panic_if_asked() {
        if PANIC_IN_TRANSLATION.with(|asked| asked.replace(false)) {
            panic!("relocation out of range (injected by a test)");
        }
    }

    #[test]
    fn a_panic_in_the_translation_falls_back_to_the_interpreter_with_its_reason() {
        let image = test_images::image(&[TestTask::cyclic(1_000_000, 1)], &[]);
        PANIC_IN_TRANSLATION.with(|asked| asked.set(true));
        let (mut engine, report) =
            Engine::with_choice(image, EngineChoice::Native).expect("the image still loads");
        assert_eq!(report.chosen, EngineChoice::Native);
        assert_eq!(
            report.unavailable.as_deref(),
            Some(
                "internal error of the native code generator: relocation out of range (injected by a test)"
            )
        );
        assert!(!report.runs_natively());
        assert_eq!(engine.native_report(), &report);
        // The interpreter runs the image.
        engine.run_cycle(0, 0, 0).expect("the cycle runs");
        assert_eq!(engine.native_entries(), 0);
        assert_eq!(
            test_images::dint(
                engine.region(program_image::Region::Data),
                test_images::count(0)
            ),
            1
        );
    }

    #[test]
    fn a_panic_message_is_kept_whether_static_or_formatted() {
        let fixed: Box<dyn std::any::Any + Send> = Box::new("fixed");
        let formatted: Box<dyn std::any::Any + Send> = Box::new(String::from("formatted 7"));
        let other: Box<dyn std::any::Any + Send> = Box::new(7_u32);
        assert_eq!(panic_message(fixed.as_ref()), "fixed");
        assert_eq!(panic_message(formatted.as_ref()), "formatted 7");
        assert_eq!(panic_message(other.as_ref()), "a panic without a message");
    }
}
