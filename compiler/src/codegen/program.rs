//! The build: the data region (globals and program instances), the constant pool, POU
//! indices, frames, symbols, tasks, the Modbus master's devices, and the code of every body,
//! assembled into an image.

use std::collections::HashMap;
use std::path::Path;

use program_image::{
    Elementary as IE, InitRun, Layout, Located, Operand, Pou as ImagePou, PouKind as ImageKind,
    ProgramCall, ProgramImage, Region, RetainLayout, Symbol, SymbolFlags, Task, TaskKind,
};
use project_model::{
    GlobalVarList, Object, Pou, PouKind, Project, StBody, TextTarget, VarSection, Variable,
};

use super::body::{BodyGen, Frame, FrameVar, Gen, Place, Typed};
use super::error::{CodegenError, Within, fail};
use super::layout::{Lay, LayShape, Layouts, flags_of, located_of};
use crate::sema::expression_types::CheckedBodies;
use crate::sema::scope::{Globals, Scope};
use crate::sema::ty::Type;
use crate::syntax::parse_statements;

/// The default sizes of the located areas, enough for the default Modbus map: `%IW0..1023`,
/// `%QW0..1023` and `%ML0..1023`.
const DEFAULT_INPUT_BYTES: u32 = 2048;
const DEFAULT_OUTPUT_BYTES: u32 = 2048;
const DEFAULT_MEMORY_BYTES: u32 = 8192;
/// The stack of each task.
const STACK_BYTES: u32 = 256 * 1024;
/// The interval of the task made for a project without a task configuration.
pub(crate) const IMPLICIT_TASK_INTERVAL_NS: u64 = 10_000_000;

/// The state of one build.
pub(crate) struct Build<'g, 'p> {
    pub(crate) layouts: Layouts<'g, 'p>,
    constants: Vec<u8>,
    constant_index: HashMap<Vec<u8>, u32>,
    pou_indices: HashMap<String, u32>,
    globals_by_var: HashMap<*const Variable, Typed>,
    gvls: HashMap<String, &'p GlobalVarList>,
    programs: HashMap<String, u32>,
    blocks: Vec<&'p Pou>,
    /// The `AXIS_REF` and `MC_CAM_REF` globals of the axes and cams, by lower-case name.
    devices: HashMap<String, Typed>,
    /// While a breakpoint condition is compiled: where its constants go, as it cannot add
    /// to the image's pool.
    pub(super) scratch_constants: Option<super::condition::ScratchConstants>,
}

impl<'g, 'p> Build<'g, 'p> {
    fn new(globals: &'g Globals<'p>) -> Self {
        Self {
            layouts: Layouts::new(globals),
            constants: Vec::new(),
            constant_index: HashMap::new(),
            pou_indices: HashMap::new(),
            globals_by_var: HashMap::new(),
            gvls: HashMap::new(),
            programs: HashMap::new(),
            blocks: Vec::new(),
            devices: HashMap::new(),
            scratch_constants: None,
        }
    }

    /// An operand holding `bytes` in the constant pool.
    pub(crate) fn constant(&mut self, bytes: &[u8]) -> Operand {
        if let Some(at) = self.constant_index.get(bytes) {
            return Operand::Const(*at);
        }
        if let Some(scratch) = &mut self.scratch_constants {
            return scratch.add(bytes);
        }
        let at = self.constants.len().next_multiple_of(8);
        self.constants.resize(at, 0);
        self.constants.extend_from_slice(bytes);
        self.constant_index.insert(bytes.to_vec(), at as u32);
        Operand::Const(at as u32)
    }

    /// An operand holding the raw value of a scalar.
    pub(crate) fn scalar_constant(&mut self, raw: u64, ty: IE) -> Operand {
        let bytes = raw.to_le_bytes();
        self.constant(&bytes[..ty.size_bytes() as usize])
    }

    /// The image index of a POU, or of its method or action `member`.
    pub(crate) fn pou_index(&self, pou: &str, member: Option<&str>) -> Gen<u32> {
        let key = key(pou, member);
        self.pou_indices.get(&key).copied().ok_or_else(|| {
            fail!(
                "'{}' is not compiled",
                member.map_or(pou.to_owned(), |m| format!("{pou}.{m}"))
            )
        })
    }

    /// The place of a global variable.
    pub(crate) fn global(&self, var: &Variable) -> Option<Typed> {
        self.globals_by_var.get(&std::ptr::from_ref(var)).cloned()
    }

    /// The global of the axis or cam table `name`.
    pub(crate) fn device(&self, name: &str) -> Option<Typed> {
        self.devices.get(&name.to_lowercase()).cloned()
    }

    /// The variable `name` of the global variable list `gvl`.
    pub(crate) fn gvl_variable(&self, gvl: &str, name: &str) -> Option<&'p Variable> {
        self.gvls
            .get(&gvl.to_lowercase())?
            .variables
            .iter()
            .find(|v| v.name.eq_ignore_ascii_case(name))
    }

    /// Every function block of the project.
    pub(crate) fn function_blocks(&self) -> Vec<&'p Pou> {
        self.blocks.clone()
    }

    /// The data offset of a program's instance.
    pub(crate) fn program_offset(&self, name: &str) -> Option<u32> {
        self.programs.get(&name.to_lowercase()).copied()
    }

    /// The frame of a function, method or body: parameters and locals (a body: its VAR_TEMP),
    /// then the result.
    pub(crate) fn frame_of(
        &mut self,
        owner: &'p Pou,
        variables: &'p [Variable],
        return_type: Option<&str>,
    ) -> Gen<Frame<'p>> {
        let mut frame = Frame::default();
        let mut offset = 0u32;
        let function_like = return_type.is_some()
            || owner.kind == PouKind::Function
            || !std::ptr::eq(variables, owner.variables.as_slice());
        // Parameters come first, so every implementation of an interface method, whatever
        // its locals, takes its inputs and outputs at the same offsets.
        let parameter = |v: &&Variable| {
            matches!(
                v.section,
                VarSection::VarInput | VarSection::VarOutput | VarSection::VarInOut
            )
        };
        let parameters: Vec<&'p Variable> = variables.iter().filter(parameter).collect();
        let others: Vec<&'p Variable> = variables.iter().filter(|v| !parameter(v)).collect();
        self.frame_vars(owner, &mut frame, &mut offset, &parameters, function_like)?;
        // The result follows the parameters, also at the same offset in every implementation.
        if let Some(text) = return_type {
            let ty = self.layouts.globals.resolve_type(text);
            let lay = self.layouts.of(&ty)?;
            let at = offset.next_multiple_of(lay.align);
            offset = at + lay.size;
            frame.result = Some(FrameVar {
                offset: at,
                ty,
                lay,
                by_ref: false,
            });
        }
        self.frame_vars(owner, &mut frame, &mut offset, &others, function_like)?;
        frame.size = offset;
        Ok(frame)
    }

    fn frame_vars(
        &mut self,
        owner: &'p Pou,
        frame: &mut Frame<'p>,
        offset: &mut u32,
        variables: &[&'p Variable],
        function_like: bool,
    ) -> Gen<()> {
        // Array bounds may name constants of the frame's own declarations or of the POU.
        let locals: Vec<&Variable> = frame
            .vars
            .iter()
            .map(|(v, _)| *v)
            .chain(variables.iter().copied())
            .chain(frame_owner_variables(self.layouts.globals, owner))
            .collect();
        for var in variables {
            let in_frame = match var.section {
                VarSection::VarTemp => true,
                VarSection::VarInput
                | VarSection::VarOutput
                | VarSection::VarInOut
                | VarSection::Var
                | VarSection::VarInst => function_like,
                _ => false,
            };
            if !in_frame {
                continue;
            }
            let by_ref = var.section == VarSection::VarInOut;
            let declared = crate::sema::resolve_local_type(self.layouts.globals, &locals, &var.ty);
            let ty = if by_ref {
                Type::Reference(Box::new(declared))
            } else {
                declared
            };
            let lay = self
                .layouts
                .of(&ty)
                .map_err(|e| e.within(Within::Declaration(var.name.clone())))?;
            let at = offset.next_multiple_of(lay.align);
            *offset = at + lay.size;
            frame.vars.push((
                var,
                FrameVar {
                    offset: at,
                    ty,
                    lay,
                    by_ref,
                },
            ));
        }
        Ok(())
    }

    /// The initial bytes of a frame's variables.
    fn frame_init(&mut self, frame: &Frame<'p>) -> Gen<Vec<InitRun>> {
        let mut runs = Vec::new();
        for (var, slot) in &frame.vars {
            if slot.by_ref {
                continue;
            }
            let bytes = self
                .layouts
                .initial_bytes(&slot.lay, var.initial.as_deref())
                .map_err(|e| e.within(Within::Declaration(var.name.clone())))?;
            if bytes.iter().any(|b| *b != 0) {
                runs.push(InitRun {
                    offset: slot.offset,
                    bytes,
                });
            }
        }
        if let Some(result) = &frame.result {
            let bytes = self.layouts.default_bytes(&result.lay)?;
            if bytes.iter().any(|b| *b != 0) {
                runs.push(InitRun {
                    offset: result.offset,
                    bytes,
                });
            }
        }
        Ok(runs)
    }
}

/// The declarations of `owner` and its bases, whose constants array bounds may name.
fn frame_owner_variables<'p>(
    globals: &Globals<'p>,
    owner: &'p Pou,
) -> impl Iterator<Item = &'p Variable> {
    crate::sema::scope::inheritance_chain(globals, owner)
        .into_iter()
        .flat_map(|p| &p.variables)
}

fn key(pou: &str, member: Option<&str>) -> String {
    match member {
        Some(member) => format!("{}.{}", pou.to_lowercase(), member.to_lowercase()),
        None => pou.to_lowercase(),
    }
}

/// Where each body's text is, for the line table: the file name shown in faults and the line
/// the body's first line has in it.
pub type BodyOrigin<'a> = &'a dyn Fn(&Path) -> (String, u32);

/// One compiled unit: a POU's body, a method or an action.
pub(super) struct Unit<'p> {
    /// The POU, or the owner of the method or action.
    pub(super) pou: &'p Pou,
    /// The method's, action's or accessor's name.
    pub(super) member: Option<String>,
    kind: ImageKind,
    /// The body it compiles.
    pub(super) target: TextTarget,
    /// A library function block the runtime runs natively (`docs/motion.md` §3).
    native: bool,
}

impl Unit<'_> {
    /// Its name in the image: `FB_Conveyor`, or `FB_Conveyor.Reset` for a member.
    pub(super) fn image_name(&self) -> String {
        match &self.member {
            Some(member) => format!("{}.{member}", self.pou.name),
            None => self.pou.name.clone(),
        }
    }
}

/// The data region being laid out.
#[derive(Default)]
struct Data {
    size: u32,
    runs: Vec<InitRun>,
    located_runs: [Vec<InitRun>; 3],
    symbols: Vec<Symbol>,
    retain: RetainLayout,
    area_ends: [u32; 3],
}

impl Data {
    fn allocate(&mut self, lay: &Lay) -> u32 {
        let at = self.size.next_multiple_of(lay.align.max(1));
        self.size = at + lay.size;
        at
    }
}

fn area_index(region: Region) -> usize {
    match region {
        Region::Input => 0,
        Region::Output => 1,
        _ => 2,
    }
}

/// Compiles a checked project into an image.
///
/// `checked` holds the checker's trees and types of the bodies, reused rather than parsed
/// and typed again (a body missing there is parsed and typed here).
pub(crate) fn build_image(
    project: &Project,
    origin: BodyOrigin<'_>,
    mut checked: CheckedBodies,
    condition: Option<&mut super::condition::ConditionJob>,
) -> Gen<ProgramImage> {
    let globals = Globals::new(project);
    let mut build = Build::new(&globals);
    let mut data = Data::default();

    // Global variable lists.
    for object in project.application.objects() {
        let Object::Gvl(gvl) = object else { continue };
        build.gvls.insert(gvl.name.to_lowercase(), gvl);
        for var in &gvl.variables {
            let ty = globals.resolve_type(&var.ty);
            let lay = build
                .layouts
                .of(&ty)
                .map_err(|e| e.within(Within::Declaration(format!("{}.{}", gvl.name, var.name))))?;
            let bytes = build
                .layouts
                .initial_bytes(&lay, var.initial.as_deref())
                .map_err(|e| e.within(Within::Declaration(format!("{}.{}", gvl.name, var.name))))?;
            let path = format!("{}.{}", gvl.name, var.name);
            let flags = flags_of(var) | SymbolFlags::GLOBAL;
            let place = place_variable(&mut data, var, &lay, &bytes, &path, flags);
            build
                .globals_by_var
                .insert(std::ptr::from_ref(var), Typed { place, ty, lay });
        }
    }

    // The axes' and cams' globals, and the motion section.
    let devices = {
        let Data {
            size,
            runs,
            symbols,
            ..
        } = &mut data;
        let mut allocate = |length: u32, align: u32| {
            let at = size.next_multiple_of(align.max(1));
            *size = at + length;
            at
        };
        super::motion::device_globals(project, &mut build.layouts, &mut allocate, runs, symbols)?
    };
    build.devices = devices.places.into_iter().collect();

    // Static variables (VAR_STAT) of every POU and method, one copy shared by all calls.
    let objects = project.application.objects();
    build.blocks = objects
        .iter()
        .filter_map(|o| match o {
            Object::Pou(pou) if pou.kind == PouKind::FunctionBlock => Some(pou),
            _ => None,
        })
        .collect();
    for object in &objects {
        let Object::Pou(pou) = object else { continue };
        let variables = pou
            .variables
            .iter()
            .chain(pou.methods.iter().flat_map(|m| &m.variables));
        let locals: Vec<&Variable> = frame_owner_variables(&globals, pou).collect();
        for var in variables.filter(|v| v.section == VarSection::VarStat) {
            let ty = crate::sema::resolve_local_type(&globals, &locals, &var.ty);
            let lay = build
                .layouts
                .of(&ty)
                .map_err(|e| e.within(Within::Declaration(format!("{}.{}", pou.name, var.name))))?;
            let bytes = build
                .layouts
                .initial_bytes(&lay, var.initial.as_deref())
                .map_err(|e| e.within(Within::Declaration(format!("{}.{}", pou.name, var.name))))?;
            let path = format!("{}.{}", pou.name, var.name);
            let place = place_variable(&mut data, var, &lay, &bytes, &path, flags_of(var));
            build
                .globals_by_var
                .insert(std::ptr::from_ref(var), Typed { place, ty, lay });
        }
    }

    // Program instances, each with the symbols of everything inside it.
    let programs: Vec<&Pou> = objects
        .iter()
        .filter_map(|o| match o {
            Object::Pou(pou) if pou.kind == PouKind::Program => Some(pou),
            _ => None,
        })
        .collect();
    for pou in &programs {
        let lay = build
            .layouts
            .of(&Type::Named(pou.name.clone()))
            .map_err(|e| e.within(Within::Pou(pou.name.clone())))?;
        let offset = data.allocate(&lay);
        build.programs.insert(pou.name.to_lowercase(), offset);
        let bytes = build
            .layouts
            .default_bytes(&lay)
            .map_err(|e| e.within(Within::Pou(pou.name.clone())))?;
        data.runs.push(InitRun { offset, bytes });
        data.symbols.push(Symbol {
            path: pou.name.clone(),
            ty: lay.id,
            region: Region::Data,
            offset,
            bit: None,
            flags: SymbolFlags(0),
        });
        instance_symbols(&mut build.layouts, &mut data, pou, offset, &pou.name, 0)?;
    }

    // Every unit gets its index before any code refers to it.
    let mut units = Vec::new();
    for object in &objects {
        let Object::Pou(pou) = object else { continue };
        let kind = match pou.kind {
            PouKind::Program => ImageKind::Program,
            PouKind::FunctionBlock => ImageKind::FunctionBlock,
            PouKind::Function => ImageKind::Function,
            _ => continue,
        };
        units.push(Unit {
            pou,
            member: None,
            kind,
            target: TextTarget::Pou(pou.name.clone()),
            native: false,
        });
        for method in &pou.methods {
            units.push(Unit {
                pou,
                member: Some(method.name.clone()),
                kind: ImageKind::Method,
                target: TextTarget::Method {
                    pou: pou.name.clone(),
                    method: method.name.clone(),
                },
                native: false,
            });
        }
        for property in &pou.properties {
            for (get, present) in [
                (true, property.get.is_some()),
                (false, property.set.is_some()),
            ] {
                if present {
                    units.push(Unit {
                        pou,
                        member: Some(super::property::accessor_name(&property.name, get)),
                        kind: ImageKind::Method,
                        target: TextTarget::Property {
                            pou: pou.name.clone(),
                            property: property.name.clone(),
                            get,
                        },
                        native: false,
                    });
                }
            }
        }
        for action in &pou.actions {
            units.push(Unit {
                pou,
                member: Some(action.name.clone()),
                kind: ImageKind::Action,
                target: TextTarget::Action {
                    pou: pou.name.clone(),
                    action: action.name.clone(),
                },
                native: false,
            });
        }
    }
    // The library's function blocks the project uses and does not declare itself: their
    // bodies are one native instruction.
    let used = super::motion::used_library_blocks(project);
    for object in crate::library::objects() {
        let Object::Pou(pou) = object else { continue };
        let declared = units
            .iter()
            .any(|unit| unit.member.is_none() && unit.pou.name.eq_ignore_ascii_case(&pou.name));
        if pou.kind == PouKind::FunctionBlock
            && !declared
            && used.contains(&pou.name.to_lowercase())
        {
            units.push(Unit {
                pou,
                member: None,
                kind: ImageKind::FunctionBlock,
                target: TextTarget::Pou(pou.name.clone()),
                native: true,
            });
        }
    }
    for (index, unit) in units.iter().enumerate() {
        build
            .pou_indices
            .insert(key(&unit.pou.name, unit.member.as_deref()), index as u32);
    }

    let bodies = project_model::st_body_files(project);
    let mut sources: Vec<String> = Vec::new();
    let mut pous = Vec::with_capacity(units.len());
    let mut debug_pous = Vec::with_capacity(units.len());
    for unit in &units {
        let body = bodies
            .iter()
            .find(|b| std::ptr::eq(b.pou, unit.pou) && b.target == unit.target);
        let (pou, debug) = compile_unit(
            &mut build,
            &globals,
            unit,
            body,
            origin,
            &mut sources,
            &mut checked,
        )?;
        pous.push(pou);
        debug_pous.push(debug);
    }
    // A breakpoint condition is compiled in its POU's scope once every POU is, against the
    // same layouts and constant pool as the image.
    if let Some(job) = condition {
        job.run(&mut build, &globals, &units, &pous);
    }

    // Tasks, or one implicit task for a project of one program without a configuration.
    let mut tasks = Vec::new();
    for task in &project.tasks {
        let mut calls = Vec::new();
        for program in &task.programs {
            let pou = build.pou_index(program, None)?;
            let instance_offset = build.program_offset(program).ok_or_else(|| {
                format!(
                    "task '{}' calls '{program}', which is not a program",
                    task.name
                )
            })?;
            calls.push(ProgramCall {
                pou,
                instance_offset,
            });
        }
        let (kind, interval_ns, trigger) = match &task.kind {
            project_model::TaskKind::Cyclic { interval_us } => {
                (TaskKind::Cyclic, u64::from(*interval_us) * 1000, None)
            }
            project_model::TaskKind::Freewheeling => (TaskKind::Freewheeling, 0, None),
            project_model::TaskKind::Event { trigger } => {
                let index = data
                    .symbols
                    .iter()
                    .position(|s| s.path.eq_ignore_ascii_case(trigger))
                    .ok_or_else(|| {
                        format!(
                            "task '{}': the trigger '{trigger}' is not a variable",
                            task.name
                        )
                    })?;
                (TaskKind::Event, 0, Some(index as u32))
            }
        };
        tasks.push(Task {
            name: task.name.clone(),
            kind,
            interval_ns,
            trigger,
            priority: task.priority.min(31),
            watchdog_ns: task.watchdog.map_or(0, |w| u64::from(w.time_us) * 1000),
            watchdog_sensitivity: task.watchdog.map_or(1, |w| w.sensitivity.max(1)),
            programs: calls,
        });
    }
    if tasks.is_empty() {
        match programs.as_slice() {
            [only] => tasks.push(Task {
                name: "MainTask".to_owned(),
                kind: TaskKind::Cyclic,
                interval_ns: IMPLICIT_TASK_INTERVAL_NS,
                trigger: None,
                priority: 1,
                watchdog_ns: 0,
                watchdog_sensitivity: 1,
                programs: vec![ProgramCall {
                    pou: build.pou_index(&only.name, None)?,
                    instance_offset: build.program_offset(&only.name).unwrap_or(0),
                }],
            }),
            [] => return Err("the project has no PROGRAM to run".into()),
            _ => {
                return Err(
                    "the project has several programs but no task configuration that calls them"
                        .into(),
                );
            }
        }
    }

    let modbus_master = super::modbus_master::master_section(project, &globals, &tasks)?;
    let modbus_map = match &project.controller.modbus_map {
        Some(map) => Some(modbus_ranges(map)?),
        None => None,
    };
    let [input_runs, output_runs, memory_runs] = std::mem::take(&mut data.located_runs);
    let [input_end, output_end, memory_end] = data.area_ends;
    let image = ProgramImage {
        types: build.layouts.types,
        layout: Layout {
            data_size: data.size.next_multiple_of(8),
            input_size: DEFAULT_INPUT_BYTES.max(input_end),
            output_size: DEFAULT_OUTPUT_BYTES.max(output_end),
            memory_size: DEFAULT_MEMORY_BYTES.max(memory_end),
            stack_size: STACK_BYTES,
        },
        initial: program_image::InitialValues {
            data: data
                .runs
                .into_iter()
                .filter(|r| r.bytes.iter().any(|b| *b != 0))
                .collect(),
            input: input_runs,
            output: output_runs,
            memory: memory_runs,
        },
        symbols: data.symbols,
        pous,
        constants: build.constants,
        tasks,
        retain: data.retain,
        sources,
        info: program_image::Info {
            project: project.name.clone(),
            compiler: format!("rivet {}", env!("CARGO_PKG_VERSION")),
        },
        modbus_map,
        motion: devices.section,
        debug: Some(program_image::DebugInfo { pous: debug_pous }),
        modbus_master,
    };
    image.verify().map_err(CodegenError::InvalidImage)?;
    Ok(image)
}

/// The project's Modbus map as image ranges: each range's located address says the area, the
/// first byte and (by its size letter) how many registers make one value.
fn modbus_ranges(map: &project_model::ModbusServerMap) -> Gen<Vec<program_image::ModbusRange>> {
    use program_image::ModbusTable as T;
    let mut ranges = Vec::new();
    for (index, range) in map.ranges.iter().enumerate() {
        let field = format!(
            "controller.modbus_map.range[{}] ({:?} {})",
            index + 1,
            range.table,
            range.start
        );
        let variable = Variable {
            address: Some(range.area_address.clone()),
            ..Default::default()
        };
        let located = located_of(&variable).ok_or_else(|| {
            format!(
                "{field}: '{}' is not a direct address such as %MW0 or %QX0.0",
                range.area_address
            )
        })?;
        let table = match range.table {
            project_model::ModbusTable::Coil => T::Coils,
            project_model::ModbusTable::DiscreteInput => T::DiscreteInputs,
            project_model::ModbusTable::InputRegister => T::InputRegisters,
            project_model::ModbusTable::HoldingRegister => T::HoldingRegisters,
        };
        let bits = matches!(table, T::Coils | T::DiscreteInputs);
        let words_per_value = match (bits, located.size_bits) {
            (true, 1) if located.bit_offset % 8 == 0 => 1,
            (true, _) => {
                return Err(fail!(
                    "{field}: a bit table starts at bit 0 of a byte, such as %QX4.0, not {}",
                    range.area_address
                ));
            }
            (false, 16) => 1,
            (false, 32) => 2,
            (false, 64) => 4,
            (false, _) => {
                return Err(fail!(
                    "{field}: a register table starts at a W, D or L address, such as %MW0, not {}",
                    range.area_address
                ));
            }
        };
        if range.count == 0 {
            return Err(fail!("{field}: the count must be at least 1"));
        }
        ranges.push(program_image::ModbusRange {
            table,
            start: range.start,
            count: range.count,
            region: located.region,
            byte_offset: (located.bit_offset / 8) as u32,
            words_per_value,
        });
    }
    Ok(ranges)
}

/// Places a global variable: in its area when located, else in the data region.
fn place_variable(
    data: &mut Data,
    var: &Variable,
    lay: &Lay,
    bytes: &[u8],
    path: &str,
    flags: u16,
) -> Place {
    if let Some(located) = located_of(var) {
        return place_located(data, located, lay, bytes, path, flags);
    }
    let offset = data.allocate(lay);
    data.runs.push(InitRun {
        offset,
        bytes: bytes.to_vec(),
    });
    if var.retain || var.persistent {
        let list = if var.persistent {
            &mut data.retain.persistent
        } else {
            &mut data.retain.retain
        };
        list.push((offset, lay.size));
    }
    data.symbols.push(Symbol {
        path: path.to_owned(),
        ty: lay.id,
        region: Region::Data,
        offset,
        bit: None,
        flags: SymbolFlags(flags),
    });
    Place::Direct(Operand::Global(offset))
}

fn place_located(
    data: &mut Data,
    located: Located,
    lay: &Lay,
    bytes: &[u8],
    path: &str,
    flags: u16,
) -> Place {
    let bit = (located.size_bits == 1).then_some((located.bit_offset % 8) as u8);
    let byte = (located.bit_offset / 8) as u32;
    let index = area_index(located.region);
    let end = byte + if bit.is_some() { 1 } else { lay.size };
    data.area_ends[index] = data.area_ends[index].max(end);
    if bit.is_none() && bytes.iter().any(|b| *b != 0) {
        data.located_runs[index].push(InitRun {
            offset: byte,
            bytes: bytes.to_vec(),
        });
    }
    data.symbols.push(Symbol {
        path: path.to_owned(),
        ty: lay.id,
        region: located.region,
        offset: byte,
        bit,
        flags: SymbolFlags(flags | SymbolFlags::LOCATED),
    });
    super::expr::located_place(located)
}

/// The symbols of an instance's variables at `base` in the data region, recursively into
/// function block instances.
fn instance_symbols<'p>(
    layouts: &mut Layouts<'_, 'p>,
    data: &mut Data,
    pou: &'p Pou,
    base: u32,
    path: &str,
    depth: u32,
) -> Gen<()> {
    if depth > 16 {
        return Ok(());
    }
    let instance = layouts.instance(pou)?;
    // The steps and actions of a chart can be watched and written like variables:
    // `Main.Fill.x`, `Main.Fill._x`, `Main.Fill.t`, `Main._Fill_do.x`, `Main._Fill_do._x`.
    let time = Type::Elementary(crate::elementary::Elementary::Time);
    let mut chart_members = Vec::new();
    for sfc in instance.sfc.iter() {
        for step in &sfc.steps {
            chart_members.push((step.name.clone(), "x", Type::BOOL, step.x(), false));
            chart_members.push((step.name.clone(), "_x", Type::BOOL, step.next(), true));
            chart_members.push((step.name.clone(), "t", time.clone(), step.t(), false));
        }
        for (_, action) in &sfc.actions {
            let flags = format!("_{}", action.name);
            chart_members.push((flags.clone(), "x", Type::BOOL, action.x(), false));
            chart_members.push((flags, "_x", Type::BOOL, action.active(), false));
        }
    }
    for (owner, member, ty, offset, driven_by_hand) in chart_members {
        let id = layouts.of(&ty)?.id;
        // `_x` of a step is written to drive the chart by hand; the others show its state.
        let flags = if driven_by_hand {
            SymbolFlags(0)
        } else {
            SymbolFlags(SymbolFlags::OUTPUT)
        };
        data.symbols.push(Symbol {
            path: format!("{path}.{owner}.{member}"),
            ty: id,
            region: Region::Data,
            offset: base + offset,
            bit: None,
            flags,
        });
    }
    for slot in &instance.slots {
        let child = format!("{path}.{}", slot.var.name);
        let flags = flags_of(slot.var);
        if let Some(located) = slot.located {
            let bytes = layouts.initial_bytes(&slot.lay, slot.var.initial.as_deref())?;
            place_located(data, located, &slot.lay, &bytes, &child, flags);
            continue;
        }
        let offset = base + slot.offset;
        if slot.var.retain || slot.var.persistent {
            let list = if slot.var.persistent {
                &mut data.retain.persistent
            } else {
                &mut data.retain.retain
            };
            list.push((offset, slot.lay.size));
        }
        data.symbols.push(Symbol {
            path: child.clone(),
            ty: slot.lay.id,
            region: Region::Data,
            offset,
            bit: None,
            flags: SymbolFlags(flags),
        });
        match &slot.lay.shape {
            LayShape::Pou(name) => {
                if let Some(inner) = layouts.globals.pou(name) {
                    instance_symbols(layouts, data, inner, offset, &child, depth + 1)?;
                }
            }
            LayShape::Std(block, long) => {
                for member in program_image::std_blocks::layout(*block, *long).members {
                    if member.name.starts_with('_') {
                        continue;
                    }
                    let ty =
                        layouts.of(&Type::Elementary(super::init::elementary_of(member.ty)))?;
                    data.symbols.push(Symbol {
                        path: format!("{child}.{}", member.name),
                        ty: ty.id,
                        region: Region::Data,
                        offset: offset + member.offset,
                        bit: None,
                        flags: SymbolFlags(if member.input {
                            SymbolFlags::INPUT
                        } else {
                            SymbolFlags::OUTPUT
                        }),
                    });
                }
            }
            _ => {}
        }
    }
    Ok(())
}

/// The frame of `unit`: a method's or property accessor's, a function's, or a body's
/// (VAR_TEMP only).
pub(super) fn unit_frame<'p>(build: &mut Build<'_, 'p>, unit: &Unit<'p>) -> Gen<Frame<'p>> {
    let pou = unit.pou;
    match &unit.target {
        TextTarget::Method { method, .. } => {
            let method = pou
                .methods
                .iter()
                .find(|m| &m.name == method)
                .ok_or("a method without a declaration")?;
            build.frame_of(pou, &method.variables, method.return_type.as_deref())
        }
        TextTarget::Property { property, get, .. } => {
            let property = pou
                .properties
                .iter()
                .find(|p| &p.name == property)
                .ok_or("a property without a declaration")?;
            let accessor = if *get { &property.get } else { &property.set };
            let accessor = accessor
                .as_ref()
                .ok_or("a property accessor without a declaration")?;
            build.frame_of(pou, &accessor.variables, Some(&property.ty))
        }
        _ if pou.kind == PouKind::Function => {
            build.frame_of(pou, &pou.variables, pou.return_type.as_deref())
        }
        _ => build.frame_of(pou, &pou.variables, None),
    }
}

fn compile_unit<'g, 'p>(
    build: &mut Build<'g, 'p>,
    globals: &'g Globals<'p>,
    unit: &Unit<'p>,
    body: Option<&StBody<'p>>,
    origin: BodyOrigin<'_>,
    sources: &mut Vec<String>,
    checked: &mut CheckedBodies,
) -> Gen<(ImagePou, program_image::PouDebug)> {
    let pou = unit.pou;
    let name = unit.image_name();
    let instance = match pou.kind {
        PouKind::Program | PouKind::FunctionBlock => Some(
            build
                .layouts
                .instance(pou)
                .map_err(|e| e.within(Within::Pou(name.clone())))?,
        ),
        _ => None,
    };
    let frame = unit_frame(build, unit).map_err(|e| e.within(Within::Pou(name.clone())))?;
    let frame_init = build
        .frame_init(&frame)
        .map_err(|e| e.within(Within::Pou(name.clone())))?;
    let instance_size = instance.as_ref().map_or(0, |i| i.size);
    let debug = build
        .pou_debug(
            pou,
            &unit.target,
            &name,
            &frame,
            body.map_or("", |b| b.text),
        )
        .map_err(|e| e.within(Within::Pou(name.clone())))?;
    if unit.native {
        let native = ImagePou {
            name: name.clone(),
            kind: unit.kind,
            frame_size: frame.size,
            frame_init,
            instance_size,
            code: vec![
                program_image::Instr::Native { block: name },
                program_image::Instr::Return,
            ],
            lines: Vec::new(),
        };
        return Ok((native, debug));
    }
    let mut image_pou = ImagePou {
        name: name.clone(),
        kind: unit.kind,
        frame_size: frame.size,
        frame_init,
        instance_size,
        code: Vec::new(),
        lines: Vec::new(),
    };
    let Some(body) = body else {
        let language = match &unit.target {
            TextTarget::Pou(_) => pou.body.language(),
            TextTarget::Method { method, .. } => pou
                .methods
                .iter()
                .find(|m| &m.name == method)
                .map_or(pou.body.language(), |m| m.body.language()),
            TextTarget::Action { action, .. } => pou
                .actions
                .iter()
                .find(|a| &a.name == action)
                .map_or(pou.body.language(), |a| a.body.language()),
            TextTarget::Transition { transition, .. } => pou
                .transitions
                .iter()
                .find(|t| &t.name == transition)
                .map_or(pou.body.language(), |t| t.body.language()),
            TextTarget::Property { property, get, .. } => pou
                .properties
                .iter()
                .find(|p| &p.name == property)
                .and_then(|p| if *get { p.get.as_ref() } else { p.set.as_ref() })
                .map_or(pou.body.language(), |a| a.body.language()),
        };
        if language != project_model::Language::None {
            return Err(fail!(
                "internal error: {name}: its {language:?} body reached the code generator without being lowered into Structured Text"
            ));
        }
        image_pou.code.push(program_image::Instr::Return);
        return Ok((image_pou, debug));
    };
    let (file_name, first_line) = origin(&body.file);
    let file = match sources.iter().position(|s| *s == file_name) {
        Some(at) => at as u32,
        None => {
            sources.push(file_name.clone());
            (sources.len() - 1) as u32
        }
    };
    let checked = checked.take(&body.file, body.text);
    let (root, scope, types) = match checked {
        Some((root, types)) => {
            let scope = Scope::for_body(globals, pou, &body.target, &root);
            (root, scope, types)
        }
        None => {
            let root = parse_statements(body.text).syntax();
            let scope = Scope::for_body(globals, pou, &body.target, &root);
            let types = crate::sema::expression_types(&scope, &root);
            (root, scope, types)
        }
    };
    let mut generator = BodyGen::new(
        build,
        scope,
        pou,
        types,
        instance,
        frame,
        file,
        body.text,
        first_line.saturating_sub(1),
    );
    generator.body(&root).map_err(|error| {
        error
            .within(Within::Pou(name.clone()))
            .within(Within::File(file_name.clone()))
    })?;
    generator.emit(program_image::Instr::Return);
    image_pou.frame_size = generator.frame_max;
    image_pou.code = std::mem::take(&mut generator.code);
    image_pou.lines = std::mem::take(&mut generator.lines);
    Ok((image_pou, debug))
}
