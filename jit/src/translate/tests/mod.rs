//! The translator's table tests: per instruction, a one-POU image built by hand, translated
//! and run against a small host over a byte vector, compared with the interpreter's rules
//! written out here (`docs/native-engine.md` §11.2, "Unit tests").

#![allow(clippy::unwrap_used, clippy::expect_used)] // A panic is a failed test.

mod call;
mod control;
mod counted;
mod elements;
mod integer;
mod module;
mod pointer;
mod promote;
mod real;

use std::sync::atomic::{AtomicBool, Ordering};

use program_image::Elementary::{self, *};
use program_image::{
    BinaryOp, CompareOp, InitRun, Instr, Layout as Sizes, Operand, Pou, PouKind, ProgramImage,
    StdFunction, UnaryOp,
};

use crate::{
    Code, Counters, Entry, Host, Layout, NativeFault, OUR_SYMBOLS, PureFunctions, Site, Status,
    Translation, Untranslated,
};

const DATA: u32 = 512;
const INPUT: u32 = 16;
const OUTPUT: u32 = 16;
const MARKER: u32 = 16;
const STACK: u32 = 256;
/// The POU's instance lies in the upper half of the data region.
const INSTANCE_AT: u64 = 256;
const INSTANCE_SIZE: u32 = 256;
const FRAME_SIZE: u32 = 128;

/// A host over a byte vector that records what generated code asks of it.
struct TestHost {
    memory: Vec<u8>,
    ops: Vec<(Site, u64, u64)>,
    ticks: Vec<(Site, Counters)>,
    faults: Vec<(Site, NativeFault)>,
    /// Set during a tick, to see a flag cleared by the host.
    clear_due: Option<&'static AtomicBool>,
    /// When set, every second call of `memory` (the 2nd, the 4th, …) returns this shorter
    /// buffer instead: a safe host that code must never run on past its length.
    decoy: Option<Vec<u8>>,
    /// Calls of `memory` so far.
    memory_calls: usize,
    /// When set, `op` and `copy` panic with this message.
    panic: Option<&'static str>,
    /// The frames prepared by `frame`: the POU and the frame's offset.
    frames: Vec<(u32, u64)>,
    /// Every POU's frame size and initial runs, from the image: what `frame` prepares for
    /// the POU it is given, as the interpreter's `push_frame` does.
    frame_shapes: Vec<(u32, Vec<InitRun>)>,
    /// The instance's first 16 bytes at each tick, to see what generated code left in memory.
    tick_snapshots: Vec<Vec<u8>>,
    /// A byte of the instance each tick writes, as a preempting task may.
    tick_poke: Option<(u32, u8)>,
    /// When set, the first tick takes the memory away (`memory` then gives an empty buffer)
    /// and, if this is true, panics.
    tick_releases_memory: Option<bool>,
    /// The instance's first 16 bytes at each `op`, as at a tick.
    op_snapshots: Vec<Vec<u8>>,
    /// A byte of the instance each `op` writes, as the interpreter's instruction may.
    op_poke: Option<(u32, u8)>,
    /// When set, a tick after this many fails, as the watchdog ends an endless loop.
    watchdog_after_ticks: Option<usize>,
    /// A call site whose safe point ends the cycle, as the runtime's host ends it there for
    /// `Watchdog` or `Abandoned`: `preempt` at that site returns `Faulted`, the fault being the
    /// host's to record (this host records only the tick).
    stop_at: Option<Site>,
    /// The copies made by `copy`: the target, the source and the bytes.
    copies: Vec<(u64, u64, u64)>,
    /// When true, `copy` fails as for a place outside the memory.
    refuse_copies: bool,
}

impl Host for TestHost {
    fn memory(&mut self) -> &mut [u8] {
        self.memory_calls += 1;
        match &mut self.decoy {
            Some(decoy) if self.memory_calls.is_multiple_of(2) => decoy,
            _ => &mut self.memory,
        }
    }
    fn tick(&mut self, site: Site, counters: &mut Counters) -> Status {
        self.ticks.push((site, *counters));
        if self
            .watchdog_after_ticks
            .is_some_and(|limit| self.ticks.len() > limit)
        {
            return Status::Faulted;
        }
        if let Some(panics) = self.tick_releases_memory.take() {
            // A large buffer is unmapped when freed: code reading it after this faults.
            self.memory = Vec::new();
            if panics {
                panic!("the test host panics in a tick");
            }
            return Status::Ok;
        }
        let instance = INSTANCE_AT as usize;
        self.tick_snapshots
            .push(self.memory[instance..instance + 16].to_vec());
        if let Some((offset, byte)) = self.tick_poke {
            self.memory[instance + offset as usize] = byte;
        }
        if counters.budget == 0 {
            counters.budget = 4096;
        }
        if let Some(due) = self.clear_due {
            due.store(false, Ordering::Relaxed);
        }
        Status::Ok
    }
    fn preempt(&mut self, site: Site, counters: &mut Counters) -> Status {
        self.ticks.push((site, *counters));
        if self.stop_at == Some(site) {
            return Status::Faulted;
        }
        Status::Ok
    }
    fn op(&mut self, site: Site, instance: u64, frame: u64, _: &mut Counters) -> Status {
        if let Some(message) = self.panic {
            panic!("{message}");
        }
        self.ops.push((site, instance, frame));
        let at = INSTANCE_AT as usize;
        self.op_snapshots.push(self.memory[at..at + 16].to_vec());
        if let Some((offset, byte)) = self.op_poke {
            self.memory[at + offset as usize] = byte;
        }
        Status::Ok
    }
    fn fault(&mut self, site: Site, fault: NativeFault) {
        self.faults.push((site, fault));
    }
    fn copy(&mut self, to: u64, from: u64, bytes: u64) -> Status {
        if let Some(message) = self.panic {
            panic!("{message}");
        }
        self.copies.push((to, from, bytes));
        if self.refuse_copies {
            return Status::Faulted;
        }
        let (to, from, bytes) = (to as usize, from as usize, bytes as usize);
        let inside = |at: usize| {
            at.checked_add(bytes)
                .is_some_and(|end| end <= self.memory.len())
        };
        if !inside(to) || !inside(from) {
            return Status::Faulted;
        }
        self.memory.copy_within(from..from + bytes, to);
        Status::Ok
    }
    fn frame(&mut self, pou: u32, frame: u64) -> Status {
        self.frames.push((pou, frame));
        let Some((size, runs)) = self.frame_shapes.get(pou as usize) else {
            return Status::Faulted;
        };
        let Some(bytes) = self
            .memory
            .get_mut(frame as usize..frame as usize + *size as usize)
        else {
            return Status::Faulted;
        };
        bytes.fill(0);
        for run in runs {
            let start = run.offset as usize;
            if let Some(place) = bytes.get_mut(start..start + run.bytes.len()) {
                place.copy_from_slice(&run.bytes);
            }
        }
        Status::Ok
    }
}

/// The interpreter's rules, written again for the tests.
mod reference {
    use super::*;

    pub fn mask(ty: Elementary) -> u64 {
        match ty.size_bytes() {
            8 => u64::MAX,
            size => (1u64 << (size * 8)) - 1,
        }
    }

    pub fn value(raw: u64, ty: Elementary) -> i128 {
        let bits = ty.size_bytes() * 8;
        let raw = raw & mask(ty);
        if ty.is_signed() {
            i128::from(((raw << (64 - bits)) as i64) >> (64 - bits))
        } else {
            i128::from(raw)
        }
    }

    /// A real rounded half away from zero (or truncated), then the exact integer's low bits;
    /// 0 where there is none.
    pub fn real_to_integer(x: f64, to: Elementary, truncate: bool) -> u64 {
        let whole = if truncate { x.trunc() } else { x.round() };
        let limit = 2f64.powi(127);
        if whole.is_finite() && whole.abs() < limit {
            (whole as i128 as u64) & mask(to)
        } else {
            0
        }
    }

    pub fn real_of(raw: u64, ty: Elementary) -> f64 {
        if ty == Real {
            f64::from(f32::from_bits(raw as u32))
        } else {
            f64::from_bits(raw)
        }
    }

    pub fn raw_of_real(x: f64, ty: Elementary) -> u64 {
        if ty == Real {
            u64::from((x as f32).to_bits())
        } else {
            x.to_bits()
        }
    }
}

// The pure functions below are the interpreter's, written again for these tests from
// `runtime/src/engine/lower.rs` (`real1`, `real2`), `engine/scalar.rs` (`Arith::expt`, `%`,
// `powf`) and `stdlib/numeric.rs` (`to_bcd`, `from_bcd`): they only show that generated code
// calls them with the right codes and values. The real check is N4's differential tests, where
// the runtime hands the translator the interpreter's own functions.

extern "C" fn real_unary_f32(op: u32, x: f32) -> f32 {
    // REAL is computed in f64 and rounded back, as `Real::apply` does.
    real_unary_f64(op, f64::from(x)) as f32
}
extern "C" fn real_unary_f64(op: u32, x: f64) -> f64 {
    let f: fn(f64) -> f64 = match crate::unary_op_from_code(op) {
        Some(UnaryOp::Sqrt) => f64::sqrt,
        Some(UnaryOp::Ln) => f64::ln,
        Some(UnaryOp::Log) => f64::log10,
        Some(UnaryOp::Exp) => f64::exp,
        Some(UnaryOp::Sin) => f64::sin,
        Some(UnaryOp::Cos) => f64::cos,
        Some(UnaryOp::Tan) => f64::tan,
        Some(UnaryOp::Asin) => f64::asin,
        Some(UnaryOp::Acos) => f64::acos,
        Some(UnaryOp::Atan) => f64::atan,
        Some(UnaryOp::Round) => f64::round,
        Some(UnaryOp::Neg) => |v| -v,
        Some(UnaryOp::Abs) => f64::abs,
        Some(UnaryOp::Not | UnaryOp::ToBcd | UnaryOp::FromBcd) | None => |v| v,
    };
    f(x)
}
extern "C" fn real_binary_f32(op: u32, a: f32, b: f32) -> f32 {
    match crate::binary_op_from_code(op) {
        Some(BinaryOp::Mod) => a % b,
        Some(BinaryOp::Expt) => a.powf(b),
        _ => f64::from(a).atan2(f64::from(b)) as f32,
    }
}
extern "C" fn real_binary_f64(op: u32, a: f64, b: f64) -> f64 {
    match crate::binary_op_from_code(op) {
        Some(BinaryOp::Mod) => a % b,
        Some(BinaryOp::Expt) => a.powf(b),
        _ => a.atan2(b),
    }
}
extern "C" fn int_expt(a: u64, b: u64, ty: u32) -> u64 {
    // `Arith::expt` of the type: a negative exponent gives 0 unless the base is 1 or −1 (the
    // real result truncated toward zero); otherwise the wrapping power, the exponent's raw
    // value saturated at `u32::MAX`.
    let ty = Elementary::from_tag(ty as u8).unwrap();
    let (base, exponent) = (reference::value(a, ty), reference::value(b, ty));
    let mask = reference::mask(ty);
    if exponent < 0 {
        return match base {
            1 => 1,
            -1 if exponent % 2 == 0 => 1,
            -1 => mask,
            _ => 0,
        };
    }
    let exponent = u32::try_from(b & mask).unwrap_or(u32::MAX);
    (base as u64).wrapping_pow(exponent) & mask
}
extern "C" fn bcd(raw: u64, _: u32, to_bcd: u32) -> u64 {
    if to_bcd == 1 {
        let (mut value, mut bcd) = (raw, 0u64);
        for nibble in 0..16 {
            bcd |= (value % 10) << (4 * nibble);
            value /= 10;
            if value == 0 {
                break;
            }
        }
        bcd
    } else {
        (0..16).rev().fold(0, |value, nibble| {
            value * 10 + ((raw >> (4 * nibble)) & 0xF).min(9)
        })
    }
}
extern "C" fn convert(raw: u64, from: u32, to: u32) -> u64 {
    let (from, to) = (
        Elementary::from_tag(from as u8).unwrap(),
        Elementary::from_tag(to as u8).unwrap(),
    );
    match (from.is_real(), to.is_real()) {
        (true, false) => reference::real_to_integer(reference::real_of(raw, from), to, false),
        (true, true) => reference::raw_of_real(reference::real_of(raw, from), to),
        (false, true) => reference::raw_of_real(reference::value(raw, from) as f64, to),
        (false, false) if from == Bool => u64::from(raw & 0xFF != 0),
        (false, false) => (reference::value(raw, from) as u64) & reference::mask(to),
    }
}
extern "C" fn trunc(raw: u64, from: u32, to: u32) -> u64 {
    let (from_ty, to_ty) = (
        Elementary::from_tag(from as u8).unwrap(),
        Elementary::from_tag(to as u8).unwrap(),
    );
    if from_ty.is_real() && !to_ty.is_real() {
        reference::real_to_integer(reference::real_of(raw, from_ty), to_ty, true)
    } else {
        convert(raw, from, to)
    }
}

const PURE: PureFunctions = PureFunctions {
    real_unary_f32,
    real_unary_f64,
    real_binary_f32,
    real_binary_f64,
    int_expt,
    bcd,
    convert,
    trunc,
};

/// A POU of `kind` with `code`, its frame and instance sizes, and nothing else.
fn pou(name: &str, kind: PouKind, frame_size: u32, instance_size: u32, code: Vec<Instr>) -> Pou {
    Pou {
        name: name.into(),
        kind,
        frame_size,
        frame_init: Vec::new(),
        instance_size,
        code,
        lines: Vec::new(),
    }
}

fn image(code: Vec<Instr>, constants: Vec<u8>) -> ProgramImage {
    ProgramImage {
        layout: Sizes {
            data_size: DATA,
            input_size: INPUT,
            output_size: OUTPUT,
            memory_size: MARKER,
            stack_size: STACK,
        },
        constants,
        pous: vec![Pou {
            name: "Main".into(),
            kind: PouKind::Program,
            frame_size: FRAME_SIZE,
            frame_init: Vec::new(),
            instance_size: INSTANCE_SIZE,
            code,
            lines: Vec::new(),
        }],
        ..ProgramImage::default()
    }
}

/// A translated one-POU image and where its regions lie.
struct Fixture {
    code: Code,
    layout: Layout,
    constants: Vec<u8>,
    /// Every POU's frame size and initial runs.
    frame_shapes: Vec<(u32, Vec<InitRun>)>,
}

impl Fixture {
    fn new(code: Vec<Instr>) -> Self {
        Self::with_constants(code, vec![0; 16])
    }

    fn with_constants(code: Vec<Instr>, constants: Vec<u8>) -> Self {
        Self::of_image(image(code, constants))
    }

    /// The translation of a whole image, every POU of which must be translated.
    fn of_image(image: ProgramImage) -> Self {
        let constants = image.constants.clone();
        let frame_shapes = image
            .pous
            .iter()
            .map(|pou| (pou.frame_size, pou.frame_init.clone()))
            .collect();
        let layout = Layout::of(&image, 1);
        let code = Translation::new(&image, &layout, &PURE).unwrap();
        let refused: Vec<&Untranslated> = code
            .untranslated()
            .iter()
            .filter(|refusal| refusal.name != crate::translate::REFUSED_IN_TESTS)
            .collect();
        assert!(refused.is_empty(), "{refused:?}");
        Self {
            code,
            layout,
            constants,
            frame_shapes,
        }
    }

    fn host(&self) -> TestHost {
        let mut memory = vec![0; self.layout.total as usize];
        memory[self.layout.constants as usize..][..self.constants.len()]
            .copy_from_slice(&self.constants);
        TestHost {
            memory,
            ops: Vec::new(),
            ticks: Vec::new(),
            faults: Vec::new(),
            clear_due: None,
            decoy: None,
            memory_calls: 0,
            panic: None,
            frames: Vec::new(),
            frame_shapes: self.frame_shapes.clone(),
            tick_snapshots: Vec::new(),
            tick_poke: None,
            tick_releases_memory: None,
            op_snapshots: Vec::new(),
            op_poke: None,
            watchdog_after_ticks: None,
            stop_at: None,
            copies: Vec::new(),
            refuse_copies: false,
        }
    }

    fn frame_at(&self) -> u64 {
        self.layout.stacks
    }

    fn run_with(&self, host: &mut TestHost, due: &AtomicBool, counters: &mut Counters) -> Status {
        let entry = Entry {
            instance: INSTANCE_AT,
            frame: self.frame_at(),
            stack_end: self.layout.stacks + self.layout.stack_size,
            native_stack_limit: 0,
            due,
            now_ns: 1_234_567,
        };
        self.code.run(0, host, entry, counters)
    }

    fn run(&self, host: &mut TestHost) -> Status {
        let due = AtomicBool::new(false);
        let mut counters = Counters {
            depth: 0,
            budget: 4096,
        };
        self.run_with(host, &due, &mut counters)
    }
}

/// Reads and writes the instance's bytes.
trait InstanceBytes {
    fn put(&mut self, offset: u32, raw: u64, size: u32);
    fn get(&self, offset: u32, size: u32) -> u64;
}

impl InstanceBytes for TestHost {
    fn put(&mut self, offset: u32, raw: u64, size: u32) {
        let at = INSTANCE_AT as usize + offset as usize;
        self.memory[at..at + size as usize].copy_from_slice(&raw.to_le_bytes()[..size as usize]);
    }
    fn get(&self, offset: u32, size: u32) -> u64 {
        let at = INSTANCE_AT as usize + offset as usize;
        let mut bytes = [0u8; 8];
        bytes[..size as usize].copy_from_slice(&self.memory[at..at + size as usize]);
        u64::from_le_bytes(bytes)
    }
}

const I: fn(u32) -> Operand = Operand::Instance;

const INTEGERS: [Elementary; 8] = [Sint, Int, Dint, Lint, Usint, Uint, Udint, Ulint];

fn samples(ty: Elementary) -> Vec<u64> {
    let bits = ty.size_bytes() * 8;
    let mask = reference::mask(ty);
    let min_signed = 1u64 << (bits - 1);
    vec![
        0,
        1,
        2,
        3,
        7,
        mask,            // −1, or the unsigned maximum
        min_signed,      // MIN of a signed type
        min_signed - 1,  // MAX of a signed type
        u64::from(bits), // a shift by the width
        u64::from(bits) + 1,
        0x5A5A_5A5A_5A5A_5A5A & mask,
    ]
}
