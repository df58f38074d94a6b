//! Turns verified image code into the engine's own form: one closure per instruction with its
//! operands resolved to a base and an offset, and the type's arithmetic chosen once.

use program_image::Elementary::{self as E};
use program_image::{
    BinaryOp, BreakCondition, CompareOp, ConditionError, Instr, Operand, ProgramImage, UnaryOp,
};

use super::blocks;
use super::debug::LoweredCondition;
use super::exec::{ABSOLUTE, Addr, Exec, FRAME, INSTANCE};
use super::fault::FaultKind;
use super::lower_refusal::LowerRefusal;
use super::memory::Regions;
use super::scalar::{Arith, Bits, Real, Scalar};
use super::strings;
use crate::stdlib::convert;

/// What the next instruction is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Flow {
    Next,
    /// Go on at the next instruction in the debug form: a call returned and, during it, the
    /// task came to be watched (a step, run to cursor or halt was given), so its caller must
    /// see its next statement start (`docs/debugging.md` §3, "Cost").
    NextWatched,
    Jump(u32),
    Return,
}

/// A fault as an instruction returns it: boxed, so the result of every instruction fits in
/// two registers and the common case (no fault) costs no memory traffic.
pub(crate) type Fault = Box<FaultKind>;

/// One executable instruction.
pub(crate) type Op = Box<dyn Fn(&mut Exec<'_>) -> Result<Flow, Fault> + Send + Sync>;

/// A POU ready to run.
pub(crate) struct CompiledPou {
    pub(crate) ops: Vec<Op>,
    pub(crate) frame_size: usize,
    pub(crate) frame_init: Vec<(usize, Vec<u8>)>,
    /// Per instruction, whether it starts a statement (an entry of the line table), where the
    /// debug form asks the debugger whether to halt.
    pub(crate) statement_starts: Vec<bool>,
}

/// Every POU of an image ready to run.
pub(crate) struct Compiled {
    pub(crate) pous: Vec<CompiledPou>,
    /// The machine code of the POUs the native engine translated, when it was chosen and could
    /// make code (`docs/native-engine.md` §1.3); the closures above stay for every POU.
    pub(crate) native: Option<jit::Code>,
    /// How many times generated code was entered from the interpreter, counted for the tests
    /// that a cycle runs natively (one thread runs an engine at a time, so a relaxed load and
    /// store count exactly, without a locked instruction).
    pub(crate) native_entries: std::sync::atomic::AtomicU64,
}

/// Why an instruction cannot run (a type the operation does not apply to).
#[derive(Debug, thiserror::Error)]
#[error("POU '{pou}', instruction {index}: {reason}")]
pub struct LowerError {
    pou: String,
    index: usize,
    reason: LowerRefusal,
}

impl Compiled {
    /// Lowers every POU of a verified image.
    pub(crate) fn new(image: &ProgramImage, regions: &Regions) -> Result<Self, LowerError> {
        let mut pous = Vec::with_capacity(image.pous.len());
        let sizes: Vec<usize> = image
            .pous
            .iter()
            .map(|p| p.instance_size as usize)
            .collect();
        for pou in &image.pous {
            let mut ops = Vec::with_capacity(pou.code.len());
            for (index, instr) in pou.code.iter().enumerate() {
                let op = match instr {
                    Instr::Native { block } => super::native::lower(block, &pou.name, image),
                    other => lower(other, regions, &sizes, index as u32),
                };
                ops.push(op.map_err(|reason| LowerError {
                    pou: pou.name.clone(),
                    index,
                    reason,
                })?);
            }
            let mut statement_starts = vec![false; ops.len()];
            for entry in &pou.lines {
                if let Some(start) = statement_starts.get_mut(entry.index as usize) {
                    *start = true;
                }
            }
            pous.push(CompiledPou {
                statement_starts,
                ops,
                frame_size: pou.frame_size as usize,
                frame_init: pou
                    .frame_init
                    .iter()
                    .map(|run| (run.offset as usize, run.bytes.clone()))
                    .collect(),
            });
        }
        Ok(Self {
            pous,
            native: None,
            native_entries: std::sync::atomic::AtomicU64::new(0),
        })
    }
}

/// Lowers a verified breakpoint condition (which calls nothing, so needs no callee sizes).
pub(crate) fn lower_condition(
    condition: &BreakCondition,
    regions: &Regions,
) -> Result<LoweredCondition, ConditionError> {
    let ops = condition
        .code
        .iter()
        .enumerate()
        .map(|(instruction, instr)| {
            lower(instr, regions, &[], instruction as u32).map_err(|reason| {
                ConditionError::Refused {
                    instruction,
                    reason: reason.to_string(),
                }
            })
        })
        .collect::<Result<Vec<Op>, ConditionError>>()?;
    Ok(LoweredCondition {
        ops,
        scratch_bytes: condition.scratch_bytes as usize,
        init: condition.init.clone(),
        result: condition.result as usize,
    })
}

fn addr(operand: Operand, regions: &Regions) -> Addr {
    let absolute = |start: usize, offset: u32| Addr {
        base: ABSOLUTE,
        offset: (start + offset as usize) as u32,
    };
    match operand {
        Operand::Global(o) => absolute(regions.data, o),
        Operand::Input(o) => absolute(regions.input, o),
        Operand::Output(o) => absolute(regions.output, o),
        Operand::Memory(o) => absolute(regions.memory, o),
        Operand::Const(o) => absolute(regions.constants, o),
        Operand::Instance(o) => Addr {
            base: INSTANCE,
            offset: o,
        },
        Operand::Frame(o) => Addr {
            base: FRAME,
            offset: o,
        },
    }
}

/// Calls `$f::<T>($args)` with the Rust type that holds values of the elementary type `$ty`,
/// for every type (`all`), for those with arithmetic (`num`), bit operations (`bits`) or real
/// functions (`real`).
macro_rules! dispatch {
    (all $ty:expr, $f:ident($($arg:expr),*)) => {
        match $ty {
            E::Real => $f::<f32>($($arg),*),
            E::Lreal => $f::<f64>($($arg),*),
            other => dispatch!(bits other, $f($($arg),*)),
        }
    };
    (num $ty:expr, $f:ident($($arg:expr),*)) => {
        match $ty {
            E::Real => Ok($f::<f32>($($arg),*)),
            E::Lreal => Ok($f::<f64>($($arg),*)),
            E::Bool => Err(LowerRefusal::Arithmetic { ty: $ty }),
            other => Ok(dispatch!(bits other, $f($($arg),*))),
        }
    };
    (bits $ty:expr, $f:ident($($arg:expr),*)) => {
        match $ty {
            E::Bool | E::Byte | E::Usint | E::Char => $f::<u8>($($arg),*),
            E::Word | E::Uint | E::Wchar => $f::<u16>($($arg),*),
            E::Dword | E::Udint | E::Date | E::TimeOfDay | E::DateAndTime => $f::<u32>($($arg),*),
            E::Lword | E::Ulint => $f::<u64>($($arg),*),
            E::Sint => $f::<i8>($($arg),*),
            E::Int => $f::<i16>($($arg),*),
            E::Dint | E::Time => $f::<i32>($($arg),*),
            E::Lint | E::Ltime | E::Ldate | E::LtimeOfDay | E::LdateAndTime => $f::<i64>($($arg),*),
            // Reals reach here only through the arms above; on their bits the operations
            // are still well defined.
            E::Real => $f::<u32>($($arg),*),
            E::Lreal => $f::<u64>($($arg),*),
        }
    };
}

/// `at` is the instruction's own index in its POU, which a call gives the debugger as the
/// caller's call site (the instruction a caller's frame shows on the call stack).
fn lower(instr: &Instr, regions: &Regions, sizes: &[usize], at: u32) -> Result<Op, LowerRefusal> {
    let a = |operand: &Operand| addr(*operand, regions);
    Ok(match instr {
        Instr::Move { ty, dst, src } => dispatch!(all ty, mov(a(dst), a(src))),
        Instr::Copy { size, dst, src } => {
            let (dst, src, size) = (a(dst), a(src), *size as usize);
            Box::new(move |x| {
                let (d, s) = (x.at(dst), x.at(src));
                x.copy(d, s, size)?;
                Ok(Flow::Next)
            })
        }
        Instr::Unary { op, ty, dst, src } => unary(*op, *ty, a(dst), a(src))?,
        Instr::Binary {
            op,
            ty,
            dst,
            a: l,
            b: r,
        } => binary(*op, *ty, a(dst), a(l), a(r))?,
        Instr::Compare {
            op,
            ty,
            dst,
            a: l,
            b: r,
        } => {
            dispatch!(all ty, compare(*op, a(dst), a(l), a(r)))
        }
        Instr::Convert { from, to, dst, src } => {
            let (from, to, dst, src) = (*from, *to, a(dst), a(src));
            Box::new(move |x| {
                let raw = read_raw(x, src, from)?;
                write_raw(x, dst, to, convert::convert(raw, from, to))?;
                Ok(Flow::Next)
            })
        }
        Instr::Trunc { from, to, dst, src } => {
            let (from, to, dst, src) = (*from, *to, a(dst), a(src));
            Box::new(move |x| {
                let raw = read_raw(x, src, from)?;
                write_raw(x, dst, to, convert::trunc(raw, from, to))?;
                Ok(Flow::Next)
            })
        }
        Instr::GetBit { ty, dst, src, bit } => {
            let (ty, dst, src, bit) = (*ty, a(dst), a(src), *bit);
            Box::new(move |x| {
                let raw = read_raw(x, src, ty)?;
                x.set::<u8>(dst, ((raw >> bit) & 1) as u8)?;
                Ok(Flow::Next)
            })
        }
        Instr::SetBit { ty, dst, bit, src } => {
            let (ty, dst, src, bit) = (*ty, a(dst), a(src), *bit);
            Box::new(move |x| {
                let raw = read_raw(x, dst, ty)?;
                let on = x.get::<u8>(src)? != 0;
                let raw = if on {
                    raw | (1 << bit)
                } else {
                    raw & !(1 << bit)
                };
                write_raw(x, dst, ty, raw)?;
                Ok(Flow::Next)
            })
        }
        Instr::Jump { target } => {
            let target = *target;
            Box::new(move |_| Ok(Flow::Jump(target)))
        }
        Instr::JumpIf { cond, target } => {
            let (cond, target) = (a(cond), *target);
            Box::new(move |x| {
                Ok(if x.get::<u8>(cond)? != 0 {
                    Flow::Jump(target)
                } else {
                    Flow::Next
                })
            })
        }
        Instr::JumpIfNot { cond, target } => {
            let (cond, target) = (a(cond), *target);
            Box::new(move |x| {
                Ok(if x.get::<u8>(cond)? == 0 {
                    Flow::Jump(target)
                } else {
                    Flow::Next
                })
            })
        }
        Instr::Address { dst, place } => {
            let (dst, place) = (a(dst), a(place));
            Box::new(move |x| {
                let pointer = x.pointer_to(x.at(place));
                x.set::<u64>(dst, pointer)?;
                Ok(Flow::Next)
            })
        }
        Instr::Element {
            dst,
            base,
            index,
            index_ty,
            low,
            count,
            stride,
        } => {
            let (dst, base, index, index_ty) = (a(dst), a(base), a(index), *index_ty);
            let (low, count, stride) = (*low, *count, u64::from(*stride));
            let high =
                low.saturating_add(i64::try_from(count.saturating_sub(1)).unwrap_or(i64::MAX));
            Box::new(move |x| {
                let i = checked_index(read_raw(x, index, index_ty)?, index_ty, low, high)?;
                let pointer = x.get::<u64>(base)?;
                let moved = pointer.wrapping_add((i.wrapping_sub(low) as u64).wrapping_mul(stride));
                x.set::<u64>(dst, moved)?;
                Ok(Flow::Next)
            })
        }
        Instr::LoadElement {
            ty,
            dst,
            array,
            index,
            index_ty,
            low,
            count,
            stride,
            offset,
        } => {
            let access = ElementAccess::new(
                a(array),
                a(index),
                *index_ty,
                *low,
                *count,
                *stride,
                *offset,
            );
            dispatch!(all ty, load_element(a(dst), access))
        }
        Instr::StoreElement {
            ty,
            array,
            index,
            index_ty,
            low,
            count,
            stride,
            offset,
            src,
        } => {
            let access = ElementAccess::new(
                a(array),
                a(index),
                *index_ty,
                *low,
                *count,
                *stride,
                *offset,
            );
            dispatch!(all ty, store_element(access, a(src)))
        }
        Instr::Offset { dst, base, offset } => {
            let (dst, base, offset) = (a(dst), a(base), u64::from(*offset));
            Box::new(move |x| {
                let pointer = x.get::<u64>(base)?;
                if pointer >> 56 == 0 {
                    return Err(Box::new(FaultKind::NullPointer));
                }
                x.set::<u64>(dst, pointer.wrapping_add(offset))?;
                Ok(Flow::Next)
            })
        }
        Instr::Load { size, dst, ptr } => {
            let (size, dst, ptr) = (*size as usize, a(dst), a(ptr));
            Box::new(move |x| {
                let from = x.deref(x.get::<u64>(ptr)?, size)?;
                let to = x.at(dst);
                x.copy(to, from, size)?;
                Ok(Flow::Next)
            })
        }
        Instr::Store { size, ptr, src } => {
            let (size, ptr, src) = (*size as usize, a(ptr), a(src));
            Box::new(move |x| {
                let to = x.deref(x.get::<u64>(ptr)?, size)?;
                let from = x.at(src);
                x.copy(to, from, size)?;
                Ok(Flow::Next)
            })
        }
        Instr::CallBlock {
            pou,
            instance,
            indirect,
        } => {
            let (pou, instance, indirect) = (*pou as usize, a(instance), *indirect);
            // A pointer to an instance must reach a whole instance of the callee.
            let size = sizes.get(pou).copied().unwrap_or(0);
            Box::new(move |x| {
                let instance_at = if indirect {
                    x.deref(x.get::<u64>(instance)?, size)?
                } else {
                    x.at(instance)
                };
                Ok(x.call_block(pou, instance_at, at)?)
            })
        }
        Instr::CallFunction {
            pou,
            instance,
            inputs,
            outputs,
        } => {
            let pou = *pou as usize;
            let instance = instance.map(|operand| a(&operand));
            let inputs = transfers(inputs, regions);
            let outputs = transfers(outputs, regions);
            let size = sizes.get(pou).copied().unwrap_or(0);
            Box::new(move |x| {
                let this = match instance {
                    Some(pointer) => x.deref(x.get::<u64>(pointer)?, size)?,
                    None => x.bases[usize::from(INSTANCE)],
                };
                Ok(call_frame(x, (pou, at), this, &inputs, &outputs)?)
            })
        }
        Instr::CallStdBlock {
            block,
            long,
            instance,
            indirect,
        } => blocks::lower(*block, *long, a(instance), *indirect),
        Instr::CallStdFunction {
            function,
            wide,
            dst,
            args,
        } => strings::lower(
            *function,
            *wide,
            (a(&dst.0), dst.1),
            args.iter()
                .map(|(operand, capacity)| (a(operand), *capacity))
                .collect(),
        )?,
        Instr::Return => Box::new(|_| Ok(Flow::Return)),
        Instr::CallVirtual {
            table,
            interface,
            inputs,
            outputs,
        } => {
            let table: Vec<(u32, usize, usize)> = table
                .iter()
                .map(|(class, method)| {
                    let method = *method as usize;
                    (*class, method, sizes.get(method).copied().unwrap_or(0))
                })
                .collect();
            let interface = a(interface);
            let inputs = transfers(inputs, regions);
            let outputs = transfers(outputs, regions);
            Box::new(move |x| {
                let pointer = x.get::<u64>(interface)?;
                let class = x.get::<u32>(Addr {
                    offset: interface.offset + 8,
                    ..interface
                })?;
                x.deref(pointer, 0)?;
                let (method, size) = table
                    .iter()
                    .find(|(known, _, _)| *known == class)
                    .map(|(_, method, size)| (*method, *size))
                    .ok_or(FaultKind::BadPointer(pointer))?;
                let this = x.deref(pointer, size)?;
                Ok(call_frame(x, (method, at), this, &inputs, &outputs)?)
            })
        }
        Instr::OpenElement {
            dst,
            descriptor,
            indices,
            stride,
        } => {
            let (dst, descriptor, stride) = (a(dst), a(descriptor), u64::from(*stride));
            let indices: Vec<(Addr, E)> = indices
                .iter()
                .map(|(operand, ty)| (a(operand), *ty))
                .collect();
            Box::new(move |x| {
                let pointer = x.get::<u64>(descriptor)?;
                let mut linear: u64 = 0;
                for (dim, (index, ty)) in indices.iter().enumerate() {
                    let bound = |k: u32| Addr {
                        offset: descriptor.offset + 8 + 16 * dim as u32 + k,
                        ..descriptor
                    };
                    let (low, high) = (x.get::<i64>(bound(0))?, x.get::<i64>(bound(8))?);
                    let i = checked_index(read_raw(x, *index, *ty)?, *ty, low, high)?;
                    let count = high.wrapping_sub(low).wrapping_add(1) as u64;
                    linear = linear
                        .wrapping_mul(count)
                        .wrapping_add(i.wrapping_sub(low) as u64);
                }
                x.set::<u64>(dst, pointer.wrapping_add(linear.wrapping_mul(stride)))?;
                Ok(Flow::Next)
            })
        }
        Instr::Native { block } => {
            return Err(LowerRefusal::NativeWithoutInstance {
                block: block.clone(),
            });
        }
        Instr::Now { dst } => {
            let dst = a(dst);
            Box::new(move |x| {
                let now = x.now_ns;
                x.set::<i64>(dst, now)?;
                Ok(Flow::Next)
            })
        }
        Instr::Clock { long: true, dst } => {
            let dst = a(dst);
            Box::new(move |x| {
                let now_ns = x.clock_ns();
                x.set::<i64>(dst, now_ns)?;
                Ok(Flow::Next)
            })
        }
        Instr::Clock { long: false, dst } => {
            let dst = a(dst);
            Box::new(move |x| {
                // TIME keeps the low 32 bits of the milliseconds, so it wraps as TIME does.
                let now_ms = x.clock_ns().div_euclid(1_000_000) as i32;
                x.set::<i32>(dst, now_ms)?;
                Ok(Flow::Next)
            })
        }
        Instr::ToText {
            from,
            wide,
            dst,
            capacity,
            src,
        } => strings::to_text(*from, *wide, a(dst), *capacity, a(src)),
        Instr::FromText {
            to,
            wide,
            dst,
            src,
            capacity,
        } => strings::from_text(*to, *wide, a(dst), a(src), *capacity),
    })
}

/// Transfers with their caller operands resolved.
fn transfers(list: &[program_image::Transfer], regions: &Regions) -> Vec<(Addr, usize, usize)> {
    list.iter()
        .map(|t| {
            (
                addr(t.caller, regions),
                t.callee_offset as usize,
                t.size as usize,
            )
        })
        .collect()
}

/// Calls a function or method: a new frame, the inputs copied in, the body run on `this`,
/// the outputs copied out. `call_site` is the call's instruction index in the caller.
fn call_frame(
    x: &mut Exec<'_>,
    (pou, call_site): (usize, u32),
    this: usize,
    inputs: &[(Addr, usize, usize)],
    outputs: &[(Addr, usize, usize)],
) -> Result<Flow, FaultKind> {
    let saved = (x.bases, x.sp);
    let frame = x.push_frame(pou, call_site)?;
    for (caller, offset, size) in inputs {
        let from = x.at(*caller);
        x.copy(frame + offset, from, *size)?;
    }
    x.bases = [0, this, frame];
    let result = x.run(pou, call_site);
    x.bases = saved.0;
    if result.is_ok() {
        for (caller, offset, size) in outputs {
            let to = x.at(*caller);
            x.copy(to, frame + offset, *size)?;
        }
    }
    x.sp = saved.1;
    x.pop_depth();
    result.map(|()| x.after_call())
}

/// Reads a value of type `ty` as raw bits.
pub(crate) fn read_raw(x: &Exec<'_>, at: Addr, ty: E) -> Result<u64, FaultKind> {
    Ok(match ty.size_bytes() {
        1 => u64::from(x.get::<u8>(at)?),
        2 => u64::from(x.get::<u16>(at)?),
        4 => u64::from(x.get::<u32>(at)?),
        _ => x.get::<u64>(at)?,
    })
}

/// Writes raw bits as a value of type `ty`.
pub(crate) fn write_raw(x: &mut Exec<'_>, at: Addr, ty: E, raw: u64) -> Result<(), FaultKind> {
    match ty.size_bytes() {
        1 => x.set::<u8>(at, raw as u8),
        2 => x.set::<u16>(at, raw as u16),
        4 => x.set::<u32>(at, raw as u32),
        _ => x.set::<u64>(at, raw),
    }
}

/// Raw bits of an integer type as a signed number.
pub(crate) fn sign_extend(raw: u64, ty: E) -> i64 {
    let shift = 64 - ty.size_bytes() * 8;
    if ty.is_signed() {
        ((raw << shift) as i64) >> shift
    } else {
        raw as i64
    }
}

/// An index's raw bits as the number checked against `low ..= high`, or the fault of an index
/// outside them. An unsigned 64-bit index (`ULINT`, `LWORD`) above `i64::MAX` is outside every
/// array: read as `i64` it would be negative and could pass a negative low bound, so it is
/// refused before the comparison and reported saturated, as index `i64::MAX`.
fn checked_index(raw: u64, ty: E, low: i64, high: i64) -> Result<i64, Fault> {
    let beyond_i64 = !ty.is_signed() && raw > i64::MAX as u64;
    let i = if beyond_i64 {
        i64::MAX
    } else {
        sign_extend(raw, ty)
    };
    if beyond_i64 || i < low || i > high {
        return Err(Box::new(FaultKind::IndexOutOfBounds {
            index: i,
            low,
            high,
        }));
    }
    Ok(i)
}

/// The element (or member of an element) a `LoadElement` or `StoreElement` reaches: the
/// array is a direct place, so the element's address is the array's plus a checked offset, with
/// no pointer to resolve.
#[derive(Clone, Copy)]
struct ElementAccess {
    array: Addr,
    index: Addr,
    index_ty: E,
    low: i64,
    /// The highest index, computed as `Instr::Element` computes it so a fault reports the same
    /// bounds.
    high: i64,
    stride: u64,
    offset: u32,
}

impl ElementAccess {
    fn new(
        array: Addr,
        index: Addr,
        index_ty: E,
        low: i64,
        count: u64,
        stride: u32,
        offset: u32,
    ) -> Self {
        let high = low.saturating_add(i64::try_from(count.saturating_sub(1)).unwrap_or(i64::MAX));
        Self {
            array,
            index,
            index_ty,
            low,
            high,
            stride: u64::from(stride),
            offset,
        }
    }

    /// The address of the value, or the fault of an index outside the bounds.
    #[inline(always)]
    fn addr(&self, x: &Exec<'_>) -> Result<Addr, Fault> {
        let raw = read_raw(x, self.index, self.index_ty)?;
        let i = checked_index(raw, self.index_ty, self.low, self.high)?;
        // The verifier checked that the whole array lies inside its region, so the element's
        // offset fits; wrapping keeps a corrupted value a memory fault of `get`/`set` rather
        // than a panic.
        let element = (i.wrapping_sub(self.low) as u64).wrapping_mul(self.stride) as u32;
        Ok(Addr {
            base: self.array.base,
            offset: self
                .array
                .offset
                .wrapping_add(element)
                .wrapping_add(self.offset),
        })
    }
}

fn load_element<T: Scalar>(dst: Addr, access: ElementAccess) -> Op {
    Box::new(move |x| {
        let value = x.get::<T>(access.addr(x)?)?;
        x.set(dst, value)?;
        Ok(Flow::Next)
    })
}

fn store_element<T: Scalar>(access: ElementAccess, src: Addr) -> Op {
    Box::new(move |x| {
        let value = x.get::<T>(src)?;
        x.set(access.addr(x)?, value)?;
        Ok(Flow::Next)
    })
}

fn mov<T: Scalar>(dst: Addr, src: Addr) -> Op {
    Box::new(move |x| {
        let value = x.get::<T>(src)?;
        x.set(dst, value)?;
        Ok(Flow::Next)
    })
}

fn compare<T: Scalar>(op: CompareOp, dst: Addr, a: Addr, b: Addr) -> Op {
    macro_rules! cmp {
        ($e:tt) => {
            Box::new(move |x| {
                let (l, r) = (x.get::<T>(a)?, x.get::<T>(b)?);
                x.set::<u8>(dst, u8::from(l $e r))?;
                Ok(Flow::Next)
            })
        };
    }
    match op {
        CompareOp::Eq => cmp!(==),
        CompareOp::Ne => cmp!(!=),
        CompareOp::Lt => cmp!(<),
        CompareOp::Le => cmp!(<=),
        CompareOp::Gt => cmp!(>),
        CompareOp::Ge => cmp!(>=),
    }
}

fn unary(op: UnaryOp, ty: E, dst: Addr, src: Addr) -> Result<Op, LowerRefusal> {
    match op {
        UnaryOp::Not if ty == E::Bool => Ok(Box::new(move |x| {
            let value = x.get::<u8>(src)?;
            x.set::<u8>(dst, u8::from(value == 0))?;
            Ok(Flow::Next)
        })),
        UnaryOp::Not if !ty.is_real() => Ok(dispatch!(bits ty, not_op(dst, src))),
        UnaryOp::ToBcd | UnaryOp::FromBcd if !ty.is_real() => {
            let to_bcd = op == UnaryOp::ToBcd;
            Ok(Box::new(move |x| {
                let raw = read_raw(x, src, ty)?;
                let value = if to_bcd {
                    crate::stdlib::numeric::to_bcd(raw)
                } else {
                    crate::stdlib::numeric::from_bcd(raw)
                };
                write_raw(x, dst, ty, value)?;
                Ok(Flow::Next)
            }))
        }
        UnaryOp::Neg => dispatch!(num ty, arith1(dst, src, Arith::neg)),
        UnaryOp::Abs => dispatch!(num ty, arith1(dst, src, Arith::abs)),
        _ if ty == E::Real => Ok(real1::<f32>(op, dst, src)),
        _ if ty == E::Lreal => Ok(real1::<f64>(op, dst, src)),
        _ => Err(LowerRefusal::Unary { op, ty }),
    }
}

fn not_op<T: Bits>(dst: Addr, src: Addr) -> Op {
    Box::new(move |x| {
        let value = x.get::<T>(src)?.not();
        x.set(dst, value)?;
        Ok(Flow::Next)
    })
}

fn arith1<T: Arith>(dst: Addr, src: Addr, f: fn(T) -> T) -> Op {
    Box::new(move |x| {
        let value = f(x.get::<T>(src)?);
        x.set(dst, value)?;
        Ok(Flow::Next)
    })
}

fn real1<T: Real>(op: UnaryOp, dst: Addr, src: Addr) -> Op {
    let f = real_function(op);
    Box::new(move |x| {
        let value = x.get::<T>(src)?.apply(f);
        x.set(dst, value)?;
        Ok(Flow::Next)
    })
}

/// The `f64` function a unary operation applies to a real (computed in `f64` and rounded back
/// for REAL); the native engine's pure functions call the same (`engine/jit_pure.rs`).
pub(crate) fn real_function(op: UnaryOp) -> fn(f64) -> f64 {
    match op {
        UnaryOp::Sqrt => f64::sqrt,
        UnaryOp::Ln => f64::ln,
        UnaryOp::Log => f64::log10,
        UnaryOp::Exp => f64::exp,
        UnaryOp::Sin => f64::sin,
        UnaryOp::Cos => f64::cos,
        UnaryOp::Tan => f64::tan,
        UnaryOp::Asin => f64::asin,
        UnaryOp::Acos => f64::acos,
        UnaryOp::Atan => f64::atan,
        UnaryOp::Round => f64::round,
        UnaryOp::Neg => |v| -v,
        UnaryOp::Abs => f64::abs,
        UnaryOp::Not | UnaryOp::ToBcd | UnaryOp::FromBcd => |v| v,
    }
}

fn binary(op: BinaryOp, ty: E, dst: Addr, a: Addr, b: Addr) -> Result<Op, LowerRefusal> {
    let bit_op = matches!(
        op,
        BinaryOp::And
            | BinaryOp::Or
            | BinaryOp::Xor
            | BinaryOp::Shl
            | BinaryOp::Shr
            | BinaryOp::Rol
            | BinaryOp::Ror
    );
    if op == BinaryOp::Atan2 {
        return match ty {
            E::Real => Ok(real2::<f32>(dst, a, b, f64::atan2)),
            E::Lreal => Ok(real2::<f64>(dst, a, b, f64::atan2)),
            _ => Err(LowerRefusal::Binary { op, ty }),
        };
    }
    if bit_op {
        if ty.is_real() {
            return Err(LowerRefusal::Binary { op, ty });
        }
        return Ok(dispatch!(bits ty, bits2(op, dst, a, b)));
    }
    dispatch!(num ty, arith2(op, dst, a, b))
}

fn real2<T: Real>(dst: Addr, a: Addr, b: Addr, f: fn(f64, f64) -> f64) -> Op {
    Box::new(move |x| {
        let value = x.get::<T>(a)?.apply2(x.get::<T>(b)?, f);
        x.set(dst, value)?;
        Ok(Flow::Next)
    })
}

fn bits2<T: Bits>(op: BinaryOp, dst: Addr, a: Addr, b: Addr) -> Op {
    let f: fn(T, T) -> T = match op {
        BinaryOp::And => Bits::and,
        BinaryOp::Or => Bits::or,
        BinaryOp::Xor => Bits::xor,
        BinaryOp::Shl => Bits::shl,
        BinaryOp::Shr => Bits::shr,
        BinaryOp::Rol => Bits::rol,
        _ => Bits::ror,
    };
    Box::new(move |x| {
        let value = f(x.get::<T>(a)?, x.get::<T>(b)?);
        x.set(dst, value)?;
        Ok(Flow::Next)
    })
}

fn arith2<T: Arith>(op: BinaryOp, dst: Addr, a: Addr, b: Addr) -> Op {
    macro_rules! total {
        ($f:expr) => {
            Box::new(move |x| {
                let value = $f(x.get::<T>(a)?, x.get::<T>(b)?);
                x.set(dst, value)?;
                Ok(Flow::Next)
            })
        };
    }
    macro_rules! partial {
        ($f:expr) => {
            Box::new(move |x| {
                let value = $f(x.get::<T>(a)?, x.get::<T>(b)?).ok_or(FaultKind::DivisionByZero)?;
                x.set(dst, value)?;
                Ok(Flow::Next)
            })
        };
    }
    match op {
        BinaryOp::Add => total!(T::add),
        BinaryOp::Sub => total!(T::sub),
        BinaryOp::Mul => total!(T::mul),
        BinaryOp::Div => partial!(T::div),
        BinaryOp::Mod => partial!(T::rem),
        BinaryOp::Expt => total!(T::expt),
        BinaryOp::Min => total!(|l: T, r: T| if r < l { r } else { l }),
        _ => total!(|l: T, r: T| if r > l { r } else { l }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn outside(index: i64, low: i64, high: i64) -> Result<i64, Fault> {
        Err(Box::new(FaultKind::IndexOutOfBounds { index, low, high }))
    }

    #[test]
    fn an_unsigned_64_bit_index_above_i64_max_is_outside_even_a_negative_low_bound() {
        // Read as i64 these would be -1, -2 and i64::MIN; the first two lie in -2..=2.
        for ty in [E::Ulint, E::Lword] {
            for raw in [u64::MAX, u64::MAX - 1, 1 << 63] {
                assert_eq!(
                    checked_index(raw, ty, -2, 2),
                    outside(i64::MAX, -2, 2),
                    "{ty:?} {raw}"
                );
            }
            assert_eq!(
                checked_index(i64::MAX as u64, ty, -2, 2),
                outside(i64::MAX, -2, 2)
            );
            assert_eq!(checked_index(2, ty, -2, 2), Ok(2));
        }
        // Signed and narrower types keep their values: LINT -1 and UDINT 2^32 - 1.
        assert_eq!(checked_index(u64::MAX, E::Lint, -2, 2), Ok(-1));
        assert_eq!(checked_index(u64::MAX, E::Sint, -2, 2), Ok(-1));
        assert_eq!(
            checked_index(u64::from(u32::MAX), E::Udint, -2, 2),
            outside(i64::from(u32::MAX), -2, 2)
        );
        assert_eq!(checked_index(0xFF, E::Sint, -2, 2), Ok(-1));
    }
}
