//! The symbols generated code imports: the host callbacks of `docs/native-engine.md` §4.3, the
//! pure functions of §4.6 and the float rounding library calls the backend may emit.

use cranelift_codegen::ir::{AbiParam, LibCall, Signature, types};
use cranelift_module::{FuncId, Linkage, Module, ModuleError};
use program_image::{BinaryOp, UnaryOp};

/// The pure functions the runtime gives the translator: the interpreter's own computations
/// behind `extern "C"` wrappers (`docs/native-engine.md` §4.6). Type and operation codes are
/// the encoded numbers of `docs/program-image.md` ([`unary_op_code`], [`binary_op_code`],
/// `Elementary::tag`).
#[derive(Clone, Copy, Debug)]
pub struct PureFunctions {
    /// `UnaryOp` `op` of a REAL (LN … ATAN, ROUND), computed as the interpreter's `real1`.
    pub real_unary_f32: extern "C" fn(op: u32, x: f32) -> f32,
    /// `UnaryOp` `op` of an LREAL.
    pub real_unary_f64: extern "C" fn(op: u32, x: f64) -> f64,
    /// `BinaryOp` `op` (MOD, EXPT, ATAN2) of two REALs.
    pub real_binary_f32: extern "C" fn(op: u32, a: f32, b: f32) -> f32,
    /// `BinaryOp` `op` (MOD, EXPT, ATAN2) of two LREALs.
    pub real_binary_f64: extern "C" fn(op: u32, a: f64, b: f64) -> f64,
    /// The integer power of raw values of type `ty` (wrapping, the negative-exponent rule).
    pub int_expt: extern "C" fn(raw_a: u64, raw_b: u64, ty: u32) -> u64,
    /// `TO_BCD` (`to_bcd` 1) or `FROM_BCD` (0) of a raw value of type `ty`.
    pub bcd: extern "C" fn(raw: u64, ty: u32, to_bcd: u32) -> u64,
    /// The runtime's `convert` of a raw value.
    pub convert: extern "C" fn(raw: u64, from: u32, to: u32) -> u64,
    /// The runtime's `trunc` of a raw value.
    pub trunc: extern "C" fn(raw: u64, from: u32, to: u32) -> u64,
}

/// Every symbol generated code may import; a test asserts that nothing else is imported.
pub const OUR_SYMBOLS: &[&str] = &[
    "rivet_jit_tick",
    "rivet_jit_preempt",
    "rivet_jit_op",
    "rivet_jit_fault",
    "rivet_jit_copy",
    "rivet_jit_frame",
    "rivet_pure_real_unary_f32",
    "rivet_pure_real_unary_f64",
    "rivet_pure_real_binary_f32",
    "rivet_pure_real_binary_f64",
    "rivet_pure_int_expt",
    "rivet_pure_bcd",
    "rivet_pure_convert",
    "rivet_pure_trunc",
    "rivet_libcall_floor_f32",
    "rivet_libcall_floor_f64",
    "rivet_libcall_ceil_f32",
    "rivet_libcall_ceil_f64",
    "rivet_libcall_trunc_f32",
    "rivet_libcall_trunc_f64",
    "rivet_libcall_nearest_f32",
    "rivet_libcall_nearest_f64",
];

/// An imported function, its index in [`Imports`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Import {
    Tick,
    Preempt,
    Op,
    Fault,
    Copy,
    Frame,
    RealUnaryF32,
    RealUnaryF64,
    RealBinaryF32,
    RealBinaryF64,
    IntExpt,
    Bcd,
    Convert,
    Trunc,
}

impl Import {
    /// How many there are.
    pub(crate) const COUNT: usize = 14;
    const ALL: [Self; Self::COUNT] = [
        Self::Tick,
        Self::Preempt,
        Self::Op,
        Self::Fault,
        Self::Copy,
        Self::Frame,
        Self::RealUnaryF32,
        Self::RealUnaryF64,
        Self::RealBinaryF32,
        Self::RealBinaryF64,
        Self::IntExpt,
        Self::Bcd,
        Self::Convert,
        Self::Trunc,
    ];

    /// The symbol's name (the first entries of [`OUR_SYMBOLS`], in this order).
    pub(crate) fn name(self) -> &'static str {
        OUR_SYMBOLS[self as usize]
    }

    /// The function's signature in the machine's C convention.
    fn signature(self, mut signature: Signature) -> Signature {
        use types::{F32, F64, I32, I64};
        let (params, returns): (&[_], &[_]) = match self {
            Self::Tick | Self::Preempt => (&[I64, I32, I32], &[I32]),
            Self::Op => (&[I64, I32, I32, I64, I64], &[I32]),
            Self::Fault => (&[I64, I32, I32, I32, I64, I64, I64], &[]),
            Self::Copy => (&[I64, I64, I64, I64], &[I32]),
            Self::Frame => (&[I64, I32, I64], &[I32]),
            Self::RealUnaryF32 => (&[I32, F32], &[F32]),
            Self::RealUnaryF64 => (&[I32, F64], &[F64]),
            Self::RealBinaryF32 => (&[I32, F32, F32], &[F32]),
            Self::RealBinaryF64 => (&[I32, F64, F64], &[F64]),
            Self::IntExpt | Self::Bcd | Self::Convert | Self::Trunc => (&[I64, I32, I32], &[I64]),
        };
        // INT_EXPT takes two raw values and a type.
        let params: &[_] = if self == Self::IntExpt {
            &[I64, I64, I32]
        } else {
            params
        };
        signature
            .params
            .extend(params.iter().map(|ty| AbiParam::new(*ty)));
        signature
            .returns
            .extend(returns.iter().map(|ty| AbiParam::new(*ty)));
        signature
    }
}

/// The imported functions declared in one module.
pub(crate) struct Imports {
    /// The module's id of each import, indexed by [`Import`].
    ids: Vec<FuncId>,
}

impl Imports {
    /// Declares every import in `module`.
    pub(crate) fn declare(module: &mut dyn Module) -> Result<Self, Box<ModuleError>> {
        let mut ids = Vec::with_capacity(Import::COUNT);
        for import in Import::ALL {
            let signature = import.signature(module.make_signature());
            ids.push(
                module
                    .declare_function(import.name(), Linkage::Import, &signature)
                    .map_err(Box::new)?,
            );
        }
        Ok(Self { ids })
    }

    /// The module's id of an import.
    pub(crate) fn id(&self, import: Import) -> FuncId {
        self.ids[import as usize]
    }
}

impl PureFunctions {
    /// The symbols to register, with their addresses.
    pub(crate) fn symbols(&self) -> [(&'static str, *const u8); 8] {
        [
            (
                Import::RealUnaryF32.name(),
                self.real_unary_f32 as *const u8,
            ),
            (
                Import::RealUnaryF64.name(),
                self.real_unary_f64 as *const u8,
            ),
            (
                Import::RealBinaryF32.name(),
                self.real_binary_f32 as *const u8,
            ),
            (
                Import::RealBinaryF64.name(),
                self.real_binary_f64 as *const u8,
            ),
            (Import::IntExpt.name(), self.int_expt as *const u8),
            (Import::Bcd.name(), self.bcd as *const u8),
            (Import::Convert.name(), self.convert as *const u8),
            (Import::Trunc.name(), self.trunc as *const u8),
        ]
    }
}

/// The name generated code uses for a library call: ours for the float roundings, a name no
/// table holds for anything else (then the module refuses it, `module.rs`).
pub(crate) fn libcall_name(call: LibCall) -> String {
    let name = match call {
        LibCall::FloorF32 => "rivet_libcall_floor_f32",
        LibCall::FloorF64 => "rivet_libcall_floor_f64",
        LibCall::CeilF32 => "rivet_libcall_ceil_f32",
        LibCall::CeilF64 => "rivet_libcall_ceil_f64",
        LibCall::TruncF32 => "rivet_libcall_trunc_f32",
        LibCall::TruncF64 => "rivet_libcall_trunc_f64",
        LibCall::NearestF32 => "rivet_libcall_nearest_f32",
        LibCall::NearestF64 => "rivet_libcall_nearest_f64",
        other => return format!("foreign_libcall_{other}"),
    };
    name.to_string()
}

extern "C" fn floor_f32(x: f32) -> f32 {
    x.floor()
}
extern "C" fn floor_f64(x: f64) -> f64 {
    x.floor()
}
extern "C" fn ceil_f32(x: f32) -> f32 {
    x.ceil()
}
extern "C" fn ceil_f64(x: f64) -> f64 {
    x.ceil()
}
extern "C" fn trunc_f32(x: f32) -> f32 {
    x.trunc()
}
extern "C" fn trunc_f64(x: f64) -> f64 {
    x.trunc()
}
extern "C" fn nearest_f32(x: f32) -> f32 {
    x.round_ties_even()
}
extern "C" fn nearest_f64(x: f64) -> f64 {
    x.round_ties_even()
}

/// The library-call shims with their addresses.
pub(crate) fn libcall_symbols() -> [(&'static str, *const u8); 8] {
    [
        ("rivet_libcall_floor_f32", floor_f32 as *const u8),
        ("rivet_libcall_floor_f64", floor_f64 as *const u8),
        ("rivet_libcall_ceil_f32", ceil_f32 as *const u8),
        ("rivet_libcall_ceil_f64", ceil_f64 as *const u8),
        ("rivet_libcall_trunc_f32", trunc_f32 as *const u8),
        ("rivet_libcall_trunc_f64", trunc_f64 as *const u8),
        ("rivet_libcall_nearest_f32", nearest_f32 as *const u8),
        ("rivet_libcall_nearest_f64", nearest_f64 as *const u8),
    ]
}

/// The number of a unary operation, its variant index in the image's encoding.
pub fn unary_op_code(op: UnaryOp) -> u32 {
    UNARY_OPS.iter().position(|known| *known == op).unwrap_or(0) as u32
}

/// The unary operation of a number from [`unary_op_code`].
pub fn unary_op_from_code(code: u32) -> Option<UnaryOp> {
    UNARY_OPS.get(code as usize).copied()
}

/// The number of a binary operation, its variant index in the image's encoding.
pub fn binary_op_code(op: BinaryOp) -> u32 {
    BINARY_OPS
        .iter()
        .position(|known| *known == op)
        .unwrap_or(0) as u32
}

/// The binary operation of a number from [`binary_op_code`].
pub fn binary_op_from_code(code: u32) -> Option<BinaryOp> {
    BINARY_OPS.get(code as usize).copied()
}

/// The unary operations in their declaration (and encoding) order.
const UNARY_OPS: [UnaryOp; 16] = [
    UnaryOp::Neg,
    UnaryOp::Not,
    UnaryOp::Abs,
    UnaryOp::Sqrt,
    UnaryOp::Ln,
    UnaryOp::Log,
    UnaryOp::Exp,
    UnaryOp::Sin,
    UnaryOp::Cos,
    UnaryOp::Tan,
    UnaryOp::Asin,
    UnaryOp::Acos,
    UnaryOp::Atan,
    UnaryOp::Round,
    UnaryOp::ToBcd,
    UnaryOp::FromBcd,
];

/// The binary operations in their declaration (and encoding) order.
const BINARY_OPS: [BinaryOp; 16] = [
    BinaryOp::Add,
    BinaryOp::Sub,
    BinaryOp::Mul,
    BinaryOp::Div,
    BinaryOp::Mod,
    BinaryOp::Expt,
    BinaryOp::And,
    BinaryOp::Or,
    BinaryOp::Xor,
    BinaryOp::Min,
    BinaryOp::Max,
    BinaryOp::Shl,
    BinaryOp::Shr,
    BinaryOp::Rol,
    BinaryOp::Ror,
    BinaryOp::Atan2,
];
