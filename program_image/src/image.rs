//! The program image as data: every section of `docs/program-image.md` as a Rust structure.

use serde::{Deserialize, Serialize};

use crate::code::Instr;
use crate::types::{TypeDef, TypeId};

/// A compiled program: what `rivet build` writes and `rivet-runtime` runs.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct ProgramImage {
    /// The type table.
    pub types: Vec<TypeDef>,
    /// Sizes of the memory regions.
    pub layout: Layout,
    /// The data region's content after a cold start.
    pub initial: InitialValues,
    /// Every variable a user can name.
    pub symbols: Vec<Symbol>,
    /// The POUs and their code.
    pub pous: Vec<Pou>,
    /// The constant pool that [`crate::Operand::Const`] addresses.
    pub constants: Vec<u8>,
    /// The tasks.
    pub tasks: Vec<Task>,
    /// The retain and persistent ranges of the data region.
    pub retain: RetainLayout,
    /// Source files, for fault reports.
    pub sources: Vec<String>,
    /// Project name, compiler version: shown, never interpreted.
    pub info: Info,
    /// The project's own Modbus server map; `None` for the runtime's default map
    /// (`docs/modbus-map.md`).
    pub modbus_map: Option<Vec<ModbusRange>>,
    /// The project's axes and cam tables (`docs/motion.md`); `None` when it has neither.
    pub motion: Option<crate::motion::MotionSection>,
    /// What the debugger needs beyond the code (frame variables, source hashes); `None`
    /// when the compiler wrote none. The runtime never needs it.
    pub debug: Option<crate::debug::DebugInfo>,
    /// The devices the runtime masters over Modbus TCP and RTU, with their serial ports
    /// (`docs/modbus-master.md` §5); `None` when the project has no device with an I/O task.
    pub modbus_master: Option<crate::modbus_master::MasterSection>,
}

/// A Modbus table.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum ModbusTable {
    /// Coils (function codes 1, 5, 15).
    Coils,
    /// Discrete inputs (function code 2).
    DiscreteInputs,
    /// Input registers (function code 4).
    InputRegisters,
    /// Holding registers (function codes 3, 6, 16, 23).
    HoldingRegisters,
}

/// A range of Modbus addresses mapped onto consecutive bytes of a located area.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct ModbusRange {
    /// The table.
    pub table: ModbusTable,
    /// The first Modbus address (0-based).
    pub start: u16,
    /// How many coils or registers.
    pub count: u16,
    /// The area: `%I`, `%Q` or `%M`.
    pub region: Region,
    /// The byte the first address reaches (bit 0 of it, in a bit table).
    pub byte_offset: u32,
    /// Registers per value: 1 (`W`), 2 (`D`) or 4 (`L`), most significant word first.
    pub words_per_value: u8,
}

/// Sizes of the memory regions in bytes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct Layout {
    /// Globals and program instances.
    pub data_size: u32,
    /// The `%I` area.
    pub input_size: u32,
    /// The `%Q` area.
    pub output_size: u32,
    /// The `%M` area.
    pub memory_size: u32,
    /// The stack of each task.
    pub stack_size: u32,
}

/// A run of initial bytes over a zero-filled region.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct InitRun {
    /// Byte offset in the region.
    pub offset: u32,
    /// The bytes.
    pub bytes: Vec<u8>,
}

/// Initial values per region.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct InitialValues {
    /// The data region.
    pub data: Vec<InitRun>,
    /// The `%I` area.
    pub input: Vec<InitRun>,
    /// The `%Q` area.
    pub output: Vec<InitRun>,
    /// The `%M` area.
    pub memory: Vec<InitRun>,
}

/// The memory region a symbol lives in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Region {
    /// The data region.
    Data,
    /// `%I`.
    Input,
    /// `%Q`.
    Output,
    /// `%M`.
    Memory,
}

/// Where a located variable lives: its area and bit offset.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub struct Located {
    /// `%I`, `%Q` or `%M`.
    pub region: Region,
    /// Offset in bits from the start of the area (`%QX2.3` is 19).
    pub bit_offset: u64,
    /// Size in bits (1 for `X`, 8 for `B`, 16 for `W`, 32 for `D`, 64 for `L`).
    pub size_bits: u32,
}

/// Bit flags of a symbol.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct SymbolFlags(pub u16);

impl SymbolFlags {
    /// `VAR_INPUT`.
    pub const INPUT: u16 = 1;
    /// `VAR_OUTPUT`.
    pub const OUTPUT: u16 = 1 << 1;
    /// `VAR_IN_OUT`.
    pub const IN_OUT: u16 = 1 << 2;
    /// `CONSTANT`.
    pub const CONSTANT: u16 = 1 << 3;
    /// `RETAIN`.
    pub const RETAIN: u16 = 1 << 4;
    /// `PERSISTENT`.
    pub const PERSISTENT: u16 = 1 << 5;
    /// Located (`AT %…`).
    pub const LOCATED: u16 = 1 << 6;
    /// A global variable.
    pub const GLOBAL: u16 = 1 << 7;

    /// Whether `flag` is set.
    pub fn has(self, flag: u16) -> bool {
        self.0 & flag != 0
    }
}

/// A variable a user can name: a global, a program's variable, or a member of an FB instance
/// inside one, by its full path.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Symbol {
    /// The full path as declared: `Main.fbConveyor.tonStart.ET`.
    pub path: String,
    /// Its type.
    pub ty: TypeId,
    /// Its region.
    pub region: Region,
    /// Byte offset in the region; for a located BOOL, the byte holding its bit.
    pub offset: u32,
    /// For a located BOOL, its bit in that byte.
    pub bit: Option<u8>,
    /// [`SymbolFlags`].
    pub flags: SymbolFlags,
}

/// What kind of POU a [`Pou`] is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum PouKind {
    /// A program body.
    Program,
    /// A function block body.
    FunctionBlock,
    /// A function.
    Function,
    /// A method of a function block.
    Method,
    /// An action of a program or function block.
    Action,
}

/// One line-table entry: from instruction `index` on, the code comes from this place.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct LineEntry {
    /// The first instruction of the statement.
    pub index: u32,
    /// Index into [`ProgramImage::sources`].
    pub file: u32,
    /// 1-based line.
    pub line: u32,
}

/// A compiled POU.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Pou {
    /// The declared name (`FB_Conveyor`, or `FB_Conveyor.Reset` for a method).
    pub name: String,
    /// What it is.
    pub kind: PouKind,
    /// Bytes of stack frame: temporaries, and for functions and methods their variables.
    pub frame_size: u32,
    /// Initial bytes of a new frame (initial values of a function's variables).
    pub frame_init: Vec<InitRun>,
    /// Bytes of instance, for programs and function blocks (0 otherwise).
    pub instance_size: u32,
    /// The instructions.
    pub code: Vec<Instr>,
    /// Source positions, in ascending `index` order.
    pub lines: Vec<LineEntry>,
}

/// How a task is started.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum TaskKind {
    /// Every `interval_ns`.
    Cyclic,
    /// Again as soon as it ends.
    Freewheeling,
    /// On a rising edge of the BOOL symbol `trigger`.
    Event,
}

/// A program call of a task: a PROGRAM's body on its instance.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct ProgramCall {
    /// The program's POU index.
    pub pou: u32,
    /// The instance's offset in the data region.
    pub instance_offset: u32,
}

/// A task of the task configuration.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Task {
    /// The name.
    pub name: String,
    /// How it is started.
    pub kind: TaskKind,
    /// The interval of a cyclic task in nanoseconds.
    pub interval_ns: u64,
    /// For an event task, the index of the BOOL symbol whose rising edge starts it.
    pub trigger: Option<u32>,
    /// 0 (highest) to 31.
    pub priority: u8,
    /// The watchdog time in nanoseconds; 0 for none.
    pub watchdog_ns: u64,
    /// How many consecutive overruns of the watchdog time are tolerated before the fault.
    pub watchdog_sensitivity: u32,
    /// The programs in calling order.
    pub programs: Vec<ProgramCall>,
}

/// The retain and persistent ranges of the data region.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct RetainLayout {
    /// `RETAIN` variables: (offset, length).
    pub retain: Vec<(u32, u32)>,
    /// `PERSISTENT` variables: (offset, length).
    pub persistent: Vec<(u32, u32)>,
}

/// Facts shown to people, never interpreted.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct Info {
    /// The project's name.
    pub project: String,
    /// The compiler's version.
    pub compiler: String,
}
