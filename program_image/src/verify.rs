//! Load-time verification (`docs/program-image.md` §7.2): every reference inside an image is
//! checked before anything runs, so a runtime can trust the image's shape and report a bad one
//! by the name of what is wrong.

use crate::code::{Instr, Operand, StdFunction};
use crate::code_error::{CodeError, InstructionFault};
use crate::encoding::ImageError;
use crate::image::{InitRun, Pou, PouKind, Region};
use crate::types::TypeDef;
use crate::{ProgramImage, std_blocks};

/// The largest region accepted, so a hostile layout cannot make a runtime allocate without
/// bound.
pub const MAX_REGION_BYTES: u32 = 64 * 1024 * 1024;

impl ProgramImage {
    /// Axes name existing tasks, and axes and cams have their references inside the data
    /// region with finite parameters.
    fn verify_motion(&self) -> Result<(), ImageError> {
        let Some(motion) = &self.motion else {
            return Ok(());
        };
        for (index, axis) in motion.axes.iter().enumerate() {
            let name = &axis.name;
            if axis.task as usize >= self.tasks.len() {
                return invalid(format!(
                    "motion.axes[{index}] ('{name}') names task {}, but the image has {} tasks",
                    axis.task,
                    self.tasks.len()
                ));
            }
            if axis.offset >= self.layout.data_size {
                return invalid(format!(
                    "motion.axes[{index}] ('{name}') is at offset {}, outside the data region",
                    axis.offset
                ));
            }
            let limits = axis
                .software_limits
                .map_or([0.0; 2], |(low, high)| [low, high]);
            let numbers = [
                axis.modulo_period.unwrap_or(1.0),
                axis.max_velocity,
                axis.max_acceleration,
                axis.max_deceleration,
                axis.max_jerk,
            ];
            if numbers
                .iter()
                .chain(&limits)
                .any(|value| !value.is_finite())
            {
                return invalid(format!(
                    "motion.axes[{index}] ('{name}') has a parameter that is not a finite number"
                ));
            }
        }
        for (index, cam) in motion.cams.iter().enumerate() {
            if cam.offset >= self.layout.data_size {
                return invalid(format!(
                    "motion.cams[{index}] ('{}') is at offset {}, outside the data region",
                    cam.name, cam.offset
                ));
            }
        }
        Ok(())
    }

    /// Checks that every index, offset and size refers to something that exists.
    pub fn verify(&self) -> Result<(), ImageError> {
        let layout = &self.layout;
        for (name, size) in [
            ("data_size", layout.data_size),
            ("input_size", layout.input_size),
            ("output_size", layout.output_size),
            ("memory_size", layout.memory_size),
            ("stack_size", layout.stack_size),
        ] {
            if size > MAX_REGION_BYTES {
                return invalid(format!(
                    "layout.{name} is {size} bytes, more than {MAX_REGION_BYTES}"
                ));
            }
        }
        // The runtime gives every task a stack of `stack_size` bytes, so a few bytes of task
        // table must not make it allocate without bound either.
        let stacks = u64::from(layout.stack_size) * self.tasks.len().max(1) as u64;
        if stacks > u64::from(MAX_REGION_BYTES) {
            return invalid(format!(
                "{} tasks with a stack of {} bytes each need {stacks} bytes, more than {MAX_REGION_BYTES}",
                self.tasks.len(),
                layout.stack_size
            ));
        }
        self.verify_types()?;
        self.verify_initial()?;
        self.verify_motion()?;
        self.verify_debug()?;
        if let Some(master) = &self.modbus_master {
            master.verify(self.tasks.len())?;
        }
        for (index, symbol) in self.symbols.iter().enumerate() {
            let Some(ty) = self.types.get(symbol.ty as usize) else {
                return invalid(format!("symbol {} ('{}') has no type", index, symbol.path));
            };
            let size = if symbol.bit.is_some() {
                1
            } else {
                ty.size_bytes(&self.types)
            };
            let region = self.region_size(symbol.region);
            if u64::from(symbol.offset) + size > u64::from(region) {
                return invalid(format!("symbol '{}' lies outside its region", symbol.path));
            }
        }
        for pou in &self.pous {
            self.verify_code(pou)
                .map_err(|error| ImageError::Invalid(format!("POU '{}': {error}", pou.name)))?;
        }
        for task in &self.tasks {
            if task.priority > 31 {
                return invalid(format!(
                    "task '{}' has priority {}",
                    task.name, task.priority
                ));
            }
            if let Some(trigger) = task.trigger
                && trigger as usize >= self.symbols.len()
            {
                return invalid(format!("task '{}' has no trigger symbol", task.name));
            }
            for call in &task.programs {
                let program = self
                    .pous
                    .get(call.pou as usize)
                    .filter(|pou| pou.kind == PouKind::Program);
                let Some(program) = program else {
                    return invalid(format!(
                        "task '{}' calls a POU that is not a program",
                        task.name
                    ));
                };
                if u64::from(call.instance_offset) + u64::from(program.instance_size)
                    > u64::from(layout.data_size)
                {
                    return invalid(format!(
                        "task '{}' calls '{}' on an instance outside the data region",
                        task.name, program.name
                    ));
                }
            }
        }
        for range in self.modbus_map.iter().flatten() {
            let bits = matches!(
                range.table,
                crate::ModbusTable::Coils | crate::ModbusTable::DiscreteInputs
            );
            let bytes = if bits {
                u64::from(range.count).div_ceil(8)
            } else {
                u64::from(range.count) * 2
            };
            let ok = range.count > 0
                && matches!(range.words_per_value, 1 | 2 | 4)
                && range.region != Region::Data
                && u64::from(range.start) + u64::from(range.count) <= 65_536
                && u64::from(range.byte_offset) + bytes
                    <= u64::from(self.region_size(range.region));
            if !ok {
                return invalid(format!(
                    "the Modbus range {:?} {} +{} does not fit its area",
                    range.table, range.start, range.count
                ));
            }
        }
        for (offset, length) in self.retain.retain.iter().chain(&self.retain.persistent) {
            if u64::from(*offset) + u64::from(*length) > u64::from(layout.data_size) {
                return invalid("a retain range lies outside the data region".to_owned());
            }
        }
        Ok(())
    }

    /// The size of a symbol region.
    pub fn region_size(&self, region: Region) -> u32 {
        match region {
            Region::Data => self.layout.data_size,
            Region::Input => self.layout.input_size,
            Region::Output => self.layout.output_size,
            Region::Memory => self.layout.memory_size,
        }
    }

    fn verify_types(&self) -> Result<(), ImageError> {
        // A type refers only to types before it, so the table has no cycles.
        for (index, ty) in self.types.iter().enumerate() {
            let before = |id: u32| (id as usize) < index;
            let ok = match ty {
                TypeDef::Elementary(_) | TypeDef::String { .. } | TypeDef::WString { .. } => true,
                TypeDef::Array { element, dims } => {
                    before(*element) && !dims.is_empty() && dims.iter().all(|(l, h)| l <= h)
                }
                TypeDef::Struct { members, .. } => members.iter().all(|m| before(m.ty)),
                TypeDef::Enum { .. } | TypeDef::Interface { .. } => true,
                TypeDef::OpenArray { element, rank } => before(*element) && (1..=8).contains(rank),
                TypeDef::Pointer { target, .. } => {
                    target.is_none_or(|t| (t as usize) < self.types.len())
                }
            };
            if !ok {
                return invalid(format!(
                    "type {index} refers to a type that does not come before it"
                ));
            }
        }
        Ok(())
    }

    fn verify_initial(&self) -> Result<(), ImageError> {
        let check = |runs: &[InitRun], size: u32, name: &str| {
            for run in runs {
                if u64::from(run.offset) + run.bytes.len() as u64 > u64::from(size) {
                    return invalid(format!("an initial value lies outside the {name} region"));
                }
            }
            Ok(())
        };
        check(&self.initial.data, self.layout.data_size, "data")?;
        check(&self.initial.input, self.layout.input_size, "%I")?;
        check(&self.initial.output, self.layout.output_size, "%Q")?;
        check(&self.initial.memory, self.layout.memory_size, "%M")
    }

    /// Checks the code of `pou` (the image's own, or a breakpoint condition in its POU's
    /// scope); the error names the instruction.
    pub(crate) fn verify_code(&self, pou: &Pou) -> Result<(), CodeError> {
        if pou.frame_size > self.layout.stack_size {
            return Err(CodeError::FrameExceedsStack {
                frame_bytes: pou.frame_size,
            });
        }
        for run in &pou.frame_init {
            if u64::from(run.offset) + run.bytes.len() as u64 > u64::from(pou.frame_size) {
                return Err(CodeError::InitialOutsideFrame);
            }
        }
        // Without the optional `sources` section, faults name the POU and instruction only.
        for entry in &pou.lines {
            if !self.sources.is_empty() && entry.file as usize >= self.sources.len() {
                return Err(CodeError::UnknownLineFile);
            }
        }
        // Every refusal below names the instruction it is about.
        let at = |instruction: usize, fault: InstructionFault| CodeError::Instruction {
            instruction,
            fault,
        };
        let operand = |op: Operand, size: u64, word: usize| -> Result<(), CodeError> {
            let (offset, limit) = match op {
                Operand::Global(o) => (o, self.layout.data_size),
                Operand::Instance(o) => (o, pou.instance_size),
                Operand::Frame(o) => (o, pou.frame_size),
                Operand::Const(o) => (o, self.constants.len() as u32),
                Operand::Input(o) => (o, self.layout.input_size),
                Operand::Output(o) => (o, self.layout.output_size),
                Operand::Memory(o) => (o, self.layout.memory_size),
            };
            if u64::from(offset) + size > u64::from(limit) {
                return Err(at(
                    word,
                    InstructionFault::OperandOutside {
                        operand: op,
                        size_bytes: size,
                    },
                ));
            }
            Ok(())
        };
        let target = |t: u32, word: usize| {
            if (t as usize) < pou.code.len() {
                Ok(())
            } else {
                Err(at(word, InstructionFault::JumpOutside { target: t }))
            }
        };
        let callee = |p: u32, word: usize| {
            self.pous
                .get(p as usize)
                .ok_or_else(|| at(word, InstructionFault::UnknownPou { pou: p }))
        };
        for (word, instr) in pou.code.iter().enumerate() {
            match instr {
                Instr::Move { ty, dst, src } => {
                    let size = u64::from(ty.size_bytes());
                    operand(*dst, size, word)?;
                    operand(*src, size, word)?;
                }
                Instr::Copy { size, dst, src } => {
                    operand(*dst, u64::from(*size), word)?;
                    operand(*src, u64::from(*size), word)?;
                }
                Instr::Unary { ty, dst, src, .. } => {
                    let size = u64::from(ty.size_bytes());
                    operand(*dst, size, word)?;
                    operand(*src, size, word)?;
                }
                Instr::Binary { ty, dst, a, b, .. } => {
                    let size = u64::from(ty.size_bytes());
                    operand(*dst, size, word)?;
                    operand(*a, size, word)?;
                    operand(*b, size, word)?;
                }
                Instr::Compare { ty, dst, a, b, .. } => {
                    let size = u64::from(ty.size_bytes());
                    operand(*dst, 1, word)?;
                    operand(*a, size, word)?;
                    operand(*b, size, word)?;
                }
                Instr::Convert { from, to, dst, src } | Instr::Trunc { from, to, dst, src } => {
                    operand(*dst, u64::from(to.size_bytes()), word)?;
                    operand(*src, u64::from(from.size_bytes()), word)?;
                }
                Instr::GetBit { ty, dst, src, bit } => {
                    if u32::from(*bit) >= ty.size_bytes() * 8 {
                        return Err(at(
                            word,
                            InstructionFault::BitOutside { bit: *bit, ty: *ty },
                        ));
                    }
                    operand(*dst, 1, word)?;
                    operand(*src, u64::from(ty.size_bytes()), word)?;
                }
                Instr::SetBit { ty, dst, bit, src } => {
                    if u32::from(*bit) >= ty.size_bytes() * 8 {
                        return Err(at(
                            word,
                            InstructionFault::BitOutside { bit: *bit, ty: *ty },
                        ));
                    }
                    operand(*dst, u64::from(ty.size_bytes()), word)?;
                    operand(*src, 1, word)?;
                }
                Instr::Jump { target: t } => target(*t, word)?,
                Instr::JumpIf { cond, target: t } | Instr::JumpIfNot { cond, target: t } => {
                    operand(*cond, 1, word)?;
                    target(*t, word)?;
                }
                Instr::Address { dst, place } => {
                    operand(*dst, 8, word)?;
                    operand(*place, 0, word)?;
                }
                Instr::Element {
                    dst,
                    base,
                    index,
                    index_ty,
                    count,
                    ..
                } => {
                    if *count == 0 {
                        return Err(at(word, InstructionFault::EmptyArray));
                    }
                    operand(*dst, 8, word)?;
                    operand(*base, 8, word)?;
                    operand(*index, u64::from(index_ty.size_bytes()), word)?;
                }
                Instr::LoadElement {
                    ty,
                    dst,
                    array,
                    index,
                    index_ty,
                    count,
                    stride,
                    offset,
                    ..
                } => {
                    element_access(*ty, *array, *index_ty, *count, *stride, *offset, word)
                        .and_then(|extent| operand(*array, extent, word))?;
                    operand(*index, u64::from(index_ty.size_bytes()), word)?;
                    operand(*dst, u64::from(ty.size_bytes()), word)?;
                }
                Instr::StoreElement {
                    ty,
                    array,
                    index,
                    index_ty,
                    count,
                    stride,
                    offset,
                    src,
                    ..
                } => {
                    element_access(*ty, *array, *index_ty, *count, *stride, *offset, word)
                        .and_then(|extent| operand(*array, extent, word))?;
                    operand(*index, u64::from(index_ty.size_bytes()), word)?;
                    operand(*src, u64::from(ty.size_bytes()), word)?;
                }
                Instr::Offset { dst, base, .. } => {
                    operand(*dst, 8, word)?;
                    operand(*base, 8, word)?;
                }
                Instr::Load { size, dst, ptr } => {
                    operand(*dst, u64::from(*size), word)?;
                    operand(*ptr, 8, word)?;
                }
                Instr::Store { size, ptr, src } => {
                    operand(*ptr, 8, word)?;
                    operand(*src, u64::from(*size), word)?;
                }
                Instr::CallFunction {
                    pou: p,
                    instance,
                    inputs,
                    outputs,
                } => {
                    let callee = callee(*p, word)?;
                    if !matches!(callee.kind, PouKind::Function | PouKind::Method) {
                        return Err(at(
                            word,
                            InstructionFault::NotAFunction {
                                callee: callee.name.clone(),
                            },
                        ));
                    }
                    if let Some(instance) = instance {
                        operand(*instance, 8, word)?;
                    }
                    for transfer in inputs.iter().chain(outputs) {
                        operand(transfer.caller, u64::from(transfer.size), word)?;
                        if u64::from(transfer.callee_offset) + u64::from(transfer.size)
                            > u64::from(callee.frame_size)
                        {
                            return Err(at(
                                word,
                                InstructionFault::ParameterOutsideFrame {
                                    callee: callee.name.clone(),
                                },
                            ));
                        }
                    }
                }
                Instr::CallBlock {
                    pou: p,
                    instance,
                    indirect,
                } => {
                    let callee = callee(*p, word)?;
                    if !matches!(
                        callee.kind,
                        PouKind::Program | PouKind::FunctionBlock | PouKind::Action
                    ) {
                        return Err(at(
                            word,
                            InstructionFault::NotABlock {
                                callee: callee.name.clone(),
                            },
                        ));
                    }
                    let size = if *indirect {
                        8
                    } else {
                        u64::from(callee.instance_size)
                    };
                    operand(*instance, size, word)?;
                }
                Instr::CallStdBlock {
                    block,
                    long,
                    instance,
                    indirect,
                } => {
                    let size = if *indirect {
                        8
                    } else {
                        u64::from(std_blocks::layout(*block, *long).size)
                    };
                    operand(*instance, size, word)?;
                }
                Instr::CallStdFunction {
                    function,
                    wide,
                    dst,
                    args,
                } => {
                    let unit = if *wide { 2 } else { 1 };
                    let size = |capacity: u32| {
                        if capacity == 0 {
                            4
                        } else {
                            (u64::from(capacity) + 1) * unit
                        }
                    };
                    let integer_result = matches!(
                        function,
                        StdFunction::Len | StdFunction::Find | StdFunction::Compare
                    );
                    if integer_result != (dst.1 == 0) {
                        return Err(at(
                            word,
                            InstructionFault::WrongResultKind {
                                function: *function,
                            },
                        ));
                    }
                    // A recoded string's result has the other width.
                    let dst_size = if *function == StdFunction::Recode && dst.1 != 0 {
                        (u64::from(dst.1) + 1) * (3 - unit)
                    } else {
                        size(dst.1)
                    };
                    operand(dst.0, dst_size, word)?;
                    for (arg, capacity) in args {
                        operand(*arg, size(*capacity), word)?;
                    }
                }
                Instr::Return => {}
                Instr::CallVirtual {
                    table,
                    interface,
                    inputs,
                    outputs,
                } => {
                    operand(*interface, 16, word)?;
                    for (class, method) in table {
                        callee(*class, word)?;
                        let target = callee(*method, word)?;
                        if target.kind != PouKind::Method {
                            return Err(at(
                                word,
                                InstructionFault::NotAMethod {
                                    callee: target.name.clone(),
                                },
                            ));
                        }
                        for transfer in inputs.iter().chain(outputs) {
                            operand(transfer.caller, u64::from(transfer.size), word)?;
                            if u64::from(transfer.callee_offset) + u64::from(transfer.size)
                                > u64::from(target.frame_size)
                            {
                                return Err(at(
                                    word,
                                    InstructionFault::ParameterOutsideFrame {
                                        callee: target.name.clone(),
                                    },
                                ));
                            }
                        }
                    }
                }
                Instr::OpenElement {
                    dst,
                    descriptor,
                    indices,
                    ..
                } => {
                    if indices.is_empty() || indices.len() > 8 {
                        return Err(at(
                            word,
                            InstructionFault::OpenArrayDimensions {
                                dimensions: indices.len(),
                            },
                        ));
                    }
                    operand(*dst, 8, word)?;
                    operand(*descriptor, 8 + 16 * indices.len() as u64, word)?;
                    for (index, ty) in indices {
                        operand(*index, u64::from(ty.size_bytes()), word)?;
                    }
                }
                Instr::Now { dst } => operand(*dst, 8, word)?,
                Instr::Clock { long, dst } => operand(*dst, if *long { 8 } else { 4 }, word)?,
                // The runtime resolves the block's name and its members at load.
                Instr::Native { .. } => {}
                Instr::ToText {
                    from,
                    wide,
                    dst,
                    capacity,
                    src,
                } => {
                    let unit = if *wide { 2 } else { 1 };
                    operand(*dst, (u64::from(*capacity) + 1) * unit, word)?;
                    operand(*src, u64::from(from.size_bytes()), word)?;
                }
                Instr::FromText {
                    to,
                    wide,
                    dst,
                    src,
                    capacity,
                } => {
                    let unit = if *wide { 2 } else { 1 };
                    operand(*dst, u64::from(to.size_bytes()), word)?;
                    operand(*src, (u64::from(*capacity) + 1) * unit, word)?;
                }
            }
        }
        Ok(())
    }
}

/// The checks of a `LoadElement` or `StoreElement` that need no region (§7.2): at least one
/// element, an integer index, the value inside its element; gives the array's extent in bytes
/// (`count * stride`, computed in `u64` so no count wraps it), which the caller checks against
/// the array's region.
fn element_access(
    ty: crate::Elementary,
    array: Operand,
    index_ty: crate::Elementary,
    count: u64,
    stride: u32,
    offset: u32,
    word: usize,
) -> Result<u64, CodeError> {
    let at = |fault: InstructionFault| CodeError::Instruction {
        instruction: word,
        fault,
    };
    if count == 0 {
        return Err(at(InstructionFault::EmptyArray));
    }
    if !index_ty.is_integer() {
        return Err(at(InstructionFault::IndexNotInteger { index_ty }));
    }
    if u64::from(offset) + u64::from(ty.size_bytes()) > u64::from(stride) {
        return Err(at(InstructionFault::ElementTooSmall { ty, offset, stride }));
    }
    // No region is larger than `u32::MAX` bytes, so a larger extent is refused here before
    // the region check adds the array's offset to it.
    count
        .checked_mul(u64::from(stride))
        .filter(|extent| *extent <= u64::from(u32::MAX))
        .ok_or_else(|| {
            at(InstructionFault::ArrayTooLarge {
                array,
                count,
                stride,
            })
        })
}

fn invalid<T>(message: String) -> Result<T, ImageError> {
    Err(ImageError::Invalid(message))
}
