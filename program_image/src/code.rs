//! The target-independent code of a POU: instructions over pre-resolved memory operands
//! (`docs/program-image.md` §7).

use serde::{Deserialize, Serialize};

use crate::Elementary;

/// A place in memory that an instruction reads or writes, with its byte offset resolved by the
/// compiler.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Operand {
    /// The data region: globals and program instances.
    Global(u32),
    /// The instance of the FB or program whose body runs (`THIS`).
    Instance(u32),
    /// The current stack frame: parameters and locals of functions, temporaries of every POU.
    Frame(u32),
    /// The constant pool of the image.
    Const(u32),
    /// The `%I` area.
    Input(u32),
    /// The `%Q` area.
    Output(u32),
    /// The `%M` area.
    Memory(u32),
}

/// Operations with one operand.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[allow(missing_docs)] // Each is the IEC function of the same name.
pub enum UnaryOp {
    Neg,
    Not,
    Abs,
    Sqrt,
    Ln,
    Log,
    Exp,
    Sin,
    Cos,
    Tan,
    Asin,
    Acos,
    Atan,
    /// Rounds a real to the nearest integer value, keeping the real type.
    Round,
    /// Binary-coded decimal of an unsigned value (`INT_TO_BCD`): one decimal digit a nibble.
    ToBcd,
    /// The value of a binary-coded decimal (`BCD_TO_INT`); a nibble above 9 counts as 9.
    FromBcd,
}

/// Operations with two operands of one type giving that type.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[allow(missing_docs)] // Each is the IEC operator or function of the same name.
pub enum BinaryOp {
    Add,
    Sub,
    Mul,
    /// Integer division by zero is a fault; real division gives an infinity or NaN.
    Div,
    /// The remainder with the sign of the dividend; by zero is a fault.
    Mod,
    Expt,
    And,
    Or,
    Xor,
    Min,
    Max,
    /// Shifts and rotations take the count in the second operand, of the same type.
    Shl,
    Shr,
    Rol,
    Ror,
    /// The angle of the point (`b`, `a`) in radians, `ATAN2(Y := a, X := b)`; reals only.
    Atan2,
}

/// Comparisons, giving BOOL.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[allow(missing_docs)]
pub enum CompareOp {
    Eq,
    Ne,
    Lt,
    Le,
    Gt,
    Ge,
}

/// A copy between the caller's frame and the callee's frame around a function call.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Transfer {
    /// The caller's place (read for inputs, written for outputs).
    pub caller: Operand,
    /// Byte offset in the callee's frame.
    pub callee_offset: u32,
    /// Bytes copied.
    pub size: u32,
}

/// The standard function blocks the runtime implements natively; their instance layouts are
/// in [`crate::std_blocks`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[allow(missing_docs)] // Each is the IEC function block of the same name.
pub enum StdBlock {
    Ton,
    Tof,
    Tp,
    Ctu,
    Ctd,
    Ctud,
    RTrig,
    FTrig,
    Sr,
    Rs,
    /// CODESYS's run-time clock: the date and time counted on from `PDT`.
    Rtc,
}

/// The standard functions on strings and times that are more than one instruction; the runtime
/// implements them. Arguments and result are operands of the types the function's signature
/// gives, strings with their capacity in characters.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[allow(missing_docs)] // Each is the IEC function of the same name.
pub enum StdFunction {
    Len,
    Left,
    Right,
    Mid,
    Concat,
    Insert,
    Delete,
    Replace,
    Find,
    /// Compares two strings character by character: -1, 0 or 1 (a DINT), for `=`, `<`, ….
    Compare,
    /// `STRING_TO_WSTRING` (`wide` false) or `WSTRING_TO_STRING` (`wide` true): the one argument
    /// has the width `wide` says and the result the other; a wide character above 255 has no
    /// STRING character and is skipped.
    Recode,
}

/// One instruction. A statement such as `x := a + b` is one instruction with three operands.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum Instr {
    /// `dst := src` for one elementary value.
    Move {
        /// The type moved.
        ty: Elementary,
        /// Where to.
        dst: Operand,
        /// From where.
        src: Operand,
    },
    /// Copies `size` bytes (structures, arrays, strings, instances).
    Copy {
        /// Bytes copied.
        size: u32,
        /// Where to.
        dst: Operand,
        /// From where.
        src: Operand,
    },
    /// `dst := op(src)`.
    Unary {
        /// The operation.
        op: UnaryOp,
        /// The type of operand and result.
        ty: Elementary,
        /// The result.
        dst: Operand,
        /// The operand.
        src: Operand,
    },
    /// `dst := a op b`.
    Binary {
        /// The operation.
        op: BinaryOp,
        /// The type of operands and result.
        ty: Elementary,
        /// The result.
        dst: Operand,
        /// The left operand.
        a: Operand,
        /// The right operand.
        b: Operand,
    },
    /// `dst := a op b` giving BOOL.
    Compare {
        /// The comparison.
        op: CompareOp,
        /// The type of both operands.
        ty: Elementary,
        /// The BOOL result.
        dst: Operand,
        /// The left operand.
        a: Operand,
        /// The right operand.
        b: Operand,
    },
    /// `dst := FROM_TO_TO(src)` with the IEC and CODESYS conversion rules.
    Convert {
        /// The source type.
        from: Elementary,
        /// The result type.
        to: Elementary,
        /// The result.
        dst: Operand,
        /// The value converted.
        src: Operand,
    },
    /// `dst := TRUNC(src)`: a real to an integer, towards zero.
    Trunc {
        /// The real type.
        from: Elementary,
        /// The integer type.
        to: Elementary,
        /// The result.
        dst: Operand,
        /// The value.
        src: Operand,
    },
    /// `dst := src.bit` (BOOL) for a bit of a value of type `ty`.
    GetBit {
        /// The type of `src`.
        ty: Elementary,
        /// The BOOL result.
        dst: Operand,
        /// The value read.
        src: Operand,
        /// The bit number, below the width of `ty`.
        bit: u8,
    },
    /// `dst.bit := src` (BOOL), leaving the other bits of `dst` as they are.
    SetBit {
        /// The type of `dst`.
        ty: Elementary,
        /// The value changed.
        dst: Operand,
        /// The bit number, below the width of `ty`.
        bit: u8,
        /// The BOOL written.
        src: Operand,
    },
    /// Continues at instruction `target` of the same POU.
    Jump {
        /// The instruction index.
        target: u32,
    },
    /// Continues at `target` when the BOOL `cond` is TRUE.
    JumpIf {
        /// The BOOL tested.
        cond: Operand,
        /// The instruction index.
        target: u32,
    },
    /// Continues at `target` when the BOOL `cond` is FALSE.
    JumpIfNot {
        /// The BOOL tested.
        cond: Operand,
        /// The instruction index.
        target: u32,
    },
    /// `dst := ADR(place)`: a pointer value (§5.2).
    Address {
        /// The pointer written.
        dst: Operand,
        /// The place pointed to.
        place: Operand,
    },
    /// `dst := base + (index - low) * stride`, a fault when `index` is outside
    /// `low ..= low + count - 1`.
    Element {
        /// The pointer written.
        dst: Operand,
        /// A pointer to the array's first element.
        base: Operand,
        /// The index, of type `index_ty`.
        index: Operand,
        /// The integer type of the index.
        index_ty: Elementary,
        /// The lowest index.
        low: i64,
        /// The number of elements.
        count: u64,
        /// Bytes per element.
        stride: u32,
    },
    /// `dst := base + offset` on pointers (a member reached through a pointer).
    Offset {
        /// The pointer written.
        dst: Operand,
        /// The pointer.
        base: Operand,
        /// Bytes added.
        offset: u32,
    },
    /// Copies `size` bytes from where the pointer `ptr` points to `dst`.
    Load {
        /// Bytes copied.
        size: u32,
        /// Where to.
        dst: Operand,
        /// The pointer.
        ptr: Operand,
    },
    /// Copies `size` bytes from `src` to where the pointer `ptr` points.
    Store {
        /// Bytes copied.
        size: u32,
        /// The pointer.
        ptr: Operand,
        /// From where.
        src: Operand,
    },
    /// Calls a function or method: a new frame, the inputs copied in, the body run, the
    /// outputs copied out.
    CallFunction {
        /// The callee's index in the image's POU list.
        pou: u32,
        /// The instance a method runs on, as a pointer operand; `None` for a function.
        instance: Option<Operand>,
        /// Copies into the new frame before the body runs.
        inputs: Vec<Transfer>,
        /// Copies out of the frame after the body returns.
        outputs: Vec<Transfer>,
    },
    /// Runs the body of a function block or program on an instance.
    CallBlock {
        /// The callee's index in the image's POU list.
        pou: u32,
        /// The instance: the place itself, or a pointer to it when `indirect`.
        instance: Operand,
        /// Whether `instance` holds a pointer to the instance.
        indirect: bool,
    },
    /// Runs a standard function block of the runtime on an instance laid out as
    /// [`crate::std_blocks::layout`] says.
    CallStdBlock {
        /// The block.
        block: StdBlock,
        /// Whether the times are the long forms (`LTON`, `LTOF`, `LTP`).
        long: bool,
        /// The instance: the place itself, or a pointer to it when `indirect`.
        instance: Operand,
        /// Whether `instance` holds a pointer to the instance.
        indirect: bool,
    },
    /// A string function of the runtime.
    CallStdFunction {
        /// The function.
        function: StdFunction,
        /// Whether the strings are WSTRING.
        wide: bool,
        /// The result and its capacity in characters (for string results).
        dst: (Operand, u32),
        /// The arguments, strings with their capacity in characters, integers as DINT.
        args: Vec<(Operand, u32)>,
    },
    /// Returns from the POU.
    Return,
    /// `dst := *_TO_STRING(src)` (or `*_TO_WSTRING`): the value as text, cut to `capacity`.
    ToText {
        /// The type of `src`.
        from: Elementary,
        /// Whether `dst` is a WSTRING.
        wide: bool,
        /// The string written.
        dst: Operand,
        /// Its capacity in characters.
        capacity: u32,
        /// The value.
        src: Operand,
    },
    /// `dst := STRING_TO_*(src)`: the value a text spells (0 when it spells none).
    FromText {
        /// The type of `dst`.
        to: Elementary,
        /// Whether `src` is a WSTRING.
        wide: bool,
        /// The value written.
        dst: Operand,
        /// The string read.
        src: Operand,
        /// Its capacity in characters.
        capacity: u32,
    },
    /// Calls a method through an interface: the class in the interface value selects the
    /// method from `table`, which then runs as [`Instr::CallFunction`] does on the instance
    /// the interface value points to. A null interface is a fault.
    CallVirtual {
        /// (class: the POU index of a function block, method: the POU index of its method).
        table: Vec<(u32, u32)>,
        /// The 16-byte interface value.
        interface: Operand,
        /// Copies into the new frame before the body runs (the same for every method).
        inputs: Vec<Transfer>,
        /// Copies out of the frame after the body returns.
        outputs: Vec<Transfer>,
    },
    /// `dst := ` the address of an element of an array with open bounds: the descriptor
    /// (pointer, then low and high of each dimension as `i64`) gives the bounds, each index is
    /// checked against them (a fault outside), and the element is `stride` bytes.
    OpenElement {
        /// The pointer written.
        dst: Operand,
        /// The open array's descriptor.
        descriptor: Operand,
        /// One index per dimension, with its integer type.
        indices: Vec<(Operand, Elementary)>,
        /// Bytes per element.
        stride: u32,
    },
    /// `dst := ` the task clock (the start of the current cycle) in nanoseconds, as a LINT:
    /// what SFC step times and timers measure against.
    Now {
        /// The LINT written.
        dst: Operand,
    },
    /// Runs the runtime's native function block `block` (`MC_MoveAbsolute`) on the current
    /// instance: the whole body of a library function block (`docs/motion.md` §3).
    Native {
        /// The block's name.
        block: String,
    },
    /// `dst := TIME()` (`long` false) or `dst := LTIME()` (`long` true), CODESYS's clock
    /// operators: the time since the runtime started at the instant of the call, as a TIME in
    /// milliseconds (wrapping as TIME does) or an LTIME in nanoseconds. On the real scheduler
    /// that is the task clock at the cycle's start plus the time elapsed since, so the
    /// difference of two calls in one cycle measures the code between them; on a simulated
    /// clock it is the task clock, which stands still during a cycle.
    Clock {
        /// LTIME (nanoseconds, 8 bytes) rather than TIME (milliseconds, 4 bytes).
        long: bool,
        /// The TIME or LTIME written.
        dst: Operand,
    },
    /// `dst := ` the `ty` value at `array + (index - low) * stride + offset`, a fault when
    /// `index` is outside `low ..= low + count - 1`: [`Instr::Element`] and [`Instr::Load`] of
    /// an elementary element (or of a member of a structure element) of an array that is a
    /// direct place, in one instruction with no pointer (`docs/program-image.md` §7.1).
    LoadElement {
        /// The elementary type read.
        ty: Elementary,
        /// The value written.
        dst: Operand,
        /// The array's first element.
        array: Operand,
        /// The index, of type `index_ty`.
        index: Operand,
        /// The integer type of the index.
        index_ty: Elementary,
        /// The lowest index.
        low: i64,
        /// The number of elements.
        count: u64,
        /// Bytes per element.
        stride: u32,
        /// Bytes from the element's start to the value read (a member of a structure
        /// element; 0 for the element itself).
        offset: u32,
    },
    /// Stores the `ty` value `src` at `array + (index - low) * stride + offset`, a fault when
    /// `index` is outside `low ..= low + count - 1`: the store counterpart of
    /// [`Instr::LoadElement`].
    StoreElement {
        /// The elementary type written.
        ty: Elementary,
        /// The array's first element.
        array: Operand,
        /// The index, of type `index_ty`.
        index: Operand,
        /// The integer type of the index.
        index_ty: Elementary,
        /// The lowest index.
        low: i64,
        /// The number of elements.
        count: u64,
        /// Bytes per element.
        stride: u32,
        /// Bytes from the element's start to the value written (a member of a structure
        /// element; 0 for the element itself).
        offset: u32,
        /// The value stored.
        src: Operand,
    },
}
