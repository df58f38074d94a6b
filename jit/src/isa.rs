//! The host's instruction set and the code generator's flags (`docs/native-engine.md` §8.1).

use cranelift_codegen::isa::OwnedTargetIsa;
use cranelift_codegen::settings::{self, Configurable};

/// Why no machine code can be made for an image at all: the whole image then runs in the
/// interpreter (`docs/native-engine.md` §8.2).
#[derive(Debug, thiserror::Error)]
pub enum NativeUnsupported {
    /// Cranelift has no backend for this machine, or the machine is not one the native engine
    /// is tested on.
    #[error("this machine ({machine}) has no native code generator: {reason}")]
    NoBackend {
        /// The machine's architecture, as Rust names it.
        machine: &'static str,
        /// What refused it.
        reason: &'static str,
    },
    /// A code generator flag was refused (a Cranelift version this crate was not written for).
    #[error("the native code generator refused its settings")]
    Settings(#[source] SettingsError),
    /// The image does not pass verification, which the translator relies on.
    #[error("the image does not pass verification: {0}")]
    Unverified(#[from] program_image::ImageError),
    /// The layout given is not the image's.
    #[error("the memory layout {layout} is not the image's ({image})")]
    LayoutMismatch {
        /// The layout given.
        layout: String,
        /// The image's layout.
        image: String,
    },
    /// The code module could not be built or finalised (no executable memory, for one).
    #[error("the machine code could not be made executable")]
    Module(#[source] Box<cranelift_module::ModuleError>),
    /// Generated code would import a symbol that is not one of this crate's callbacks.
    #[error("generated code would import the foreign symbol '{0}'")]
    ForeignSymbol(String),
}

/// Which of the code generator's settings was refused.
#[derive(Debug, thiserror::Error)]
pub enum SettingsError {
    /// A flag of §8.1.
    #[error("the flag {name} = {value}")]
    Flag {
        /// The flag's name.
        name: &'static str,
        /// The value given.
        value: &'static str,
        /// What Cranelift said.
        #[source]
        source: settings::SetError,
    },
    /// The instruction set with the flags.
    #[error("the instruction set with these flags")]
    Isa(#[source] cranelift_codegen::CodegenError),
}

/// Whether this machine can run generated code: `Ok` when the instruction set of §8.1 can be
/// made here, else why not. The runtime asks before it loads anything, so that an explicit
/// `--engine native` on a machine without a backend is refused at once (§8.3).
pub fn native_support() -> Result<(), NativeUnsupported> {
    host_isa().map(drop)
}

/// The instruction set of this machine with the flags of §8.1.
pub(crate) fn host_isa() -> Result<OwnedTargetIsa, NativeUnsupported> {
    let machine = std::env::consts::ARCH;
    // Generated code reads memory in the interpreter's little-endian layout with native loads,
    // and only the two architectures the runtime is tested on are offered.
    if !matches!(machine, "x86_64" | "aarch64") || cfg!(target_endian = "big") {
        return Err(NativeUnsupported::NoBackend {
            machine,
            reason: "the native engine runs on x86-64 and aarch64 only",
        });
    }
    let mut flags = settings::builder();
    let verifier = if cfg!(debug_assertions) {
        "true"
    } else {
        "false"
    };
    for (name, value) in [
        ("opt_level", "speed"),
        ("is_pic", "false"),
        ("use_colocated_libcalls", "false"),
        ("enable_probestack", "true"),
        ("probestack_strategy", "inline"),
        ("preserve_frame_pointers", "true"),
        ("enable_verifier", verifier),
    ] {
        flags.set(name, value).map_err(|source| {
            NativeUnsupported::Settings(SettingsError::Flag {
                name,
                value,
                source,
            })
        })?;
    }
    let builder = cranelift_native::builder()
        .map_err(|reason| NativeUnsupported::NoBackend { machine, reason })?;
    builder
        .finish(settings::Flags::new(flags))
        .map_err(|source| NativeUnsupported::Settings(SettingsError::Isa(source)))
}
