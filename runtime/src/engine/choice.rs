//! Which engine runs an image, and what the native engine made of it at load
//! (`docs/native-engine.md` §8.2, §8.3).

use std::time::Duration;

use program_image::ProgramImage;

/// Which engine runs the POUs of an image (`docs/native-engine.md` §8.3). Chosen when an image
/// loads; every image a runtime loads is loaded with the same choice.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum EngineChoice {
    /// Every POU runs in the interpreter.
    Interpreter,
    /// Every POU the translator accepts runs as machine code, the others in the interpreter; a
    /// cycle the debugger watches runs entirely in the interpreter.
    Native,
}

impl Default for EngineChoice {
    /// The native engine on x86-64 and aarch64, where it is built and tested; the interpreter
    /// elsewhere. A machine without a backend falls back to the interpreter at load and says so
    /// in the [`NativeReport`].
    fn default() -> Self {
        if cfg!(any(target_arch = "x86_64", target_arch = "aarch64")) {
            Self::Native
        } else {
            Self::Interpreter
        }
    }
}

/// Why an `--engine` value is refused.
#[derive(Debug, thiserror::Error)]
pub enum EngineChoiceError {
    /// The value is neither `native` nor `interpreter`.
    #[error("--engine {0}: expected native or interpreter")]
    Unknown(String),
    /// `native` was asked for on a machine without a native code generator.
    #[error(
        "--engine native: this machine ({machine}) has no native code generator; use --engine interpreter"
    )]
    Unsupported {
        /// The machine's architecture, as Rust names it.
        machine: String,
        /// What refused the machine.
        #[source]
        reason: Box<jit::NativeUnsupported>,
    },
}

impl EngineChoice {
    /// The value of `--engine` that chooses this engine.
    pub fn name(self) -> &'static str {
        match self {
            Self::Interpreter => "interpreter",
            Self::Native => "native",
        }
    }

    /// Whether this machine has a native code generator (`jit::native_support`), so that
    /// [`EngineChoice::Native`] makes machine code here.
    pub fn native_available() -> bool {
        jit::native_support().is_ok()
    }

    /// The engine `--engine value` asks for on this machine ([`EngineChoice::from_command_line`]
    /// with `jit::native_support`).
    pub fn for_this_machine(value: &str) -> Result<Self, EngineChoiceError> {
        Self::from_command_line(value, jit::native_support)
    }

    /// The engine `--engine value` asks for, on a machine whose support of the native engine
    /// `support` tells (`jit::native_support` in the programs; a fake answer in tests). An
    /// explicit `native` on a machine without a backend is refused before anything loads.
    pub fn from_command_line(
        value: &str,
        support: impl FnOnce() -> Result<(), jit::NativeUnsupported>,
    ) -> Result<Self, EngineChoiceError> {
        match value {
            "interpreter" => Ok(Self::Interpreter),
            "native" => match support() {
                Ok(()) => Ok(Self::Native),
                Err(reason) => Err(EngineChoiceError::Unsupported {
                    machine: std::env::consts::ARCH.to_owned(),
                    reason: Box::new(reason),
                }),
            },
            other => Err(EngineChoiceError::Unknown(other.to_owned())),
        }
    }
}

/// A POU that runs in the interpreter although the native engine was chosen, with the reason.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PouFallback {
    /// The POU's name.
    pub pou: String,
    /// The instruction the translator could not translate, with its kind (`CallVirtual`),
    /// when one instruction is to blame.
    pub instruction: Option<(u32, String)>,
    /// Why.
    pub reason: String,
}

/// What the engine choice made of an image at load (`docs/native-engine.md` §8.2): kept by the
/// engine for its life, printed by `rivet-runtime` and `rivet simulate`, carried by the
/// scheduler's load report.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct NativeReport {
    /// The engine asked for.
    pub chosen: EngineChoice,
    /// Why no machine code was made at all when the native engine was chosen (no backend on
    /// this machine, no executable memory); `None` when it was made or not asked for.
    pub unavailable: Option<String>,
    /// The POUs of the image.
    pub pous: usize,
    /// The POUs that run in the interpreter although machine code was made for the others.
    pub fallbacks: Vec<PouFallback>,
    /// The wall time of the translation and the module's finalisation.
    pub translation_time: Duration,
    /// Every byte of machine code (text, read-only data, alignment).
    pub code_bytes: u64,
    /// The interpreter's closures, one per instruction, kept beside the machine code.
    pub closures: usize,
}

impl NativeReport {
    /// The report of an image loaded in the interpreter, as asked.
    pub(crate) fn interpreter(image: &ProgramImage) -> Self {
        Self {
            chosen: EngineChoice::Interpreter,
            unavailable: None,
            pous: image.pous.len(),
            fallbacks: Vec::new(),
            translation_time: Duration::ZERO,
            code_bytes: 0,
            closures: closures(image),
        }
    }

    /// The report of an image for which the native engine was chosen but no machine code could
    /// be made, for `reason`.
    pub(crate) fn unavailable(
        image: &ProgramImage,
        reason: &dyn std::fmt::Display,
        translation_time: Duration,
    ) -> Self {
        Self {
            chosen: EngineChoice::Native,
            unavailable: Some(reason.to_string()),
            translation_time,
            ..Self::interpreter(image)
        }
    }

    /// The report of an image translated into `code` in `translation_time`.
    pub(crate) fn native(
        image: &ProgramImage,
        code: &jit::Code,
        translation_time: Duration,
    ) -> Self {
        let fallbacks = code
            .untranslated()
            .iter()
            .map(|untranslated| PouFallback {
                pou: untranslated.name.clone(),
                instruction: untranslated.instruction.map(|index| {
                    let kind = image
                        .pous
                        .get(untranslated.pou as usize)
                        .and_then(|pou| pou.code.get(index as usize))
                        .map_or_else(String::new, instruction_kind);
                    (index, kind)
                }),
                reason: untranslated.reason.clone(),
            })
            .collect();
        Self {
            chosen: EngineChoice::Native,
            unavailable: None,
            pous: image.pous.len(),
            fallbacks,
            translation_time,
            code_bytes: code.code_bytes(),
            closures: closures(image),
        }
    }

    /// Whether machine code runs at all: the native engine was chosen and made code.
    pub fn runs_natively(&self) -> bool {
        self.chosen == EngineChoice::Native && self.unavailable.is_none()
    }

    /// One line saying which engine runs the image, for `rivet-runtime`'s load message.
    pub fn summary(&self) -> String {
        if self.chosen == EngineChoice::Interpreter {
            return format!(
                "engine: the interpreter runs all {} POUs (--engine interpreter)",
                self.pous
            );
        }
        if let Some(reason) = &self.unavailable {
            return format!(
                "native engine: not available, the interpreter runs all {} POUs: {reason}",
                self.pous
            );
        }
        let native = self.pous - self.fallbacks.len().min(self.pous);
        format!(
            "native engine: {native} of {} POUs run as machine code ({} bytes, translated in {:.1} ms)",
            self.pous,
            self.code_bytes,
            self.translation_time.as_secs_f64() * 1000.0
        )
    }

    /// What a user may act on, as lines for standard error without a prefix (`rivet simulate`
    /// puts `note: ` before each): one line per POU that fell back to the interpreter, or one
    /// line when the native engine was chosen and could make no code at all; none when
    /// everything runs as chosen.
    pub fn lines(&self) -> Vec<String> {
        if self.chosen == EngineChoice::Interpreter {
            return Vec::new();
        }
        if self.unavailable.is_some() {
            return vec![self.summary()];
        }
        let mut lines = Vec::new();
        lines.extend(self.fallbacks.iter().map(|fallback| {
            let instruction = fallback
                .instruction
                .as_ref()
                .map_or_else(String::new, |(index, kind)| {
                    format!("instruction {index} ({kind}): ")
                });
            format!(
                "native engine: POU '{}' runs in the interpreter: {instruction}{}",
                fallback.pou, fallback.reason
            )
        }));
        lines
    }
}

/// The interpreter's closures of an image: one per instruction.
fn closures(image: &ProgramImage) -> usize {
    image.pous.iter().map(|pou| pou.code.len()).sum()
}

/// The kind of an instruction as the image format names it (`CallVirtual`), from its debug
/// form, which starts with the variant's name.
fn instruction_kind(instruction: &program_image::Instr) -> String {
    let text = format!("{instruction:?}");
    text.split([' ', '{', '('])
        .next()
        .unwrap_or_default()
        .to_owned()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unsupported() -> Result<(), jit::NativeUnsupported> {
        Err(jit::NativeUnsupported::NoBackend {
            machine: "riscv64",
            reason: "the native engine runs on x86-64 and aarch64 only",
        })
    }

    #[test]
    fn an_explicit_native_engine_is_refused_on_a_machine_without_a_backend() {
        let refusal = EngineChoice::from_command_line("native", unsupported)
            .expect_err("refused")
            .to_string();
        assert_eq!(
            refusal,
            format!(
                "--engine native: this machine ({}) has no native code generator; use --engine interpreter",
                std::env::consts::ARCH
            )
        );
        // The interpreter needs no backend.
        assert_eq!(
            EngineChoice::from_command_line("interpreter", unsupported).expect("accepted"),
            EngineChoice::Interpreter
        );
    }

    #[test]
    fn engine_values_are_parsed_and_an_unknown_one_is_named() {
        assert_eq!(
            EngineChoice::from_command_line("native", || Ok(())).expect("accepted"),
            EngineChoice::Native
        );
        let refusal = EngineChoice::from_command_line("fast", || Ok(()))
            .expect_err("refused")
            .to_string();
        assert_eq!(refusal, "--engine fast: expected native or interpreter");
        assert_eq!(EngineChoice::Native.name(), "native");
        assert_eq!(EngineChoice::Interpreter.name(), "interpreter");
    }

    #[test]
    fn the_report_names_each_fallen_back_pou_with_its_instruction() {
        let report = NativeReport {
            chosen: EngineChoice::Native,
            unavailable: None,
            pous: 3,
            fallbacks: vec![PouFallback {
                pou: "FB_Filter".into(),
                instruction: Some((41, "CallVirtual".into())),
                reason: "a Cranelift error".into(),
            }],
            translation_time: Duration::from_micros(2500),
            code_bytes: 4096,
            closures: 120,
        };
        assert_eq!(
            report.summary(),
            "native engine: 2 of 3 POUs run as machine code (4096 bytes, translated in 2.5 ms)"
        );
        assert_eq!(
            report.lines(),
            [
                "native engine: POU 'FB_Filter' runs in the interpreter: instruction 41 (CallVirtual): a Cranelift error",
            ]
        );
        let all_native = NativeReport {
            fallbacks: Vec::new(),
            ..report.clone()
        };
        assert!(all_native.lines().is_empty());
        assert!(report.runs_natively());
        let unavailable = NativeReport {
            unavailable: Some("this machine (riscv64) has no native code generator".into()),
            fallbacks: Vec::new(),
            ..report.clone()
        };
        assert_eq!(
            unavailable.lines(),
            [
                "native engine: not available, the interpreter runs all 3 POUs: this machine (riscv64) has no native code generator"
            ]
        );
        assert!(!unavailable.runs_natively());
        let interpreter = NativeReport {
            chosen: EngineChoice::Interpreter,
            ..unavailable
        };
        assert_eq!(
            interpreter.summary(),
            "engine: the interpreter runs all 3 POUs (--engine interpreter)"
        );
        assert!(interpreter.lines().is_empty());
    }

    #[test]
    fn an_instruction_is_named_by_its_kind() {
        assert_eq!(instruction_kind(&program_image::Instr::Return), "Return");
        assert_eq!(
            instruction_kind(&program_image::Instr::Jump { target: 3 }),
            "Jump"
        );
    }
}
