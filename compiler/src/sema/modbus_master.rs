//! The build's checks of the runtime Modbus master (`docs/modbus-master.md` §3): the devices
//! that name an I/O task, their channels and the serial ports they use, reported in `rivet.toml`
//! at the device's (or port's) name with E0140–E0145, W0015 and W0016.
//!
//! The settings' own rules are `project_model::device_check`'s, which the device editors refuse
//! with; the build reports them for files edited by hand and adds what needs the program: the
//! task, the bound variables and their types, and what else writes them.

use std::collections::HashSet;
use std::path::PathBuf;

use project_model::{
    ChannelDirection, DeviceProblem, ModbusBinding, ModbusDevice, ModbusSchedule, Project,
    TaskKind, TypeDefinition, Variable, modbus_device_problems, same_identifier,
    serial_port_problems,
};

use super::ProjectDiagnostic;
use super::scope::Globals;
use super::ty::Type;
use crate::diagnostic::{Code, Diagnostic};
use crate::elementary::Elementary;
use crate::ide::ChannelBindingError;
use crate::ide::variable_type::{BoundPath, Unbound, bind_path, bound_path, channel_misfit};
use crate::library::MODBUS_DEVICE_STATUS;
use program_image::modbus_master::{MAX_CHANNELS_PER_DEVICE, MAX_DEVICES, MAX_SERIAL_PORTS};

/// What a bound path is to its device, for the words of a finding.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Field {
    /// A channel's `variable`.
    Variable,
    /// The device's `status`.
    Status,
    /// A channel's `error_flag`.
    ErrorFlag,
    /// A channel's `trigger_variable`.
    Trigger,
}

impl Field {
    /// The field in a sentence: `the error flag`.
    fn words(self) -> &'static str {
        match self {
            Self::Variable => "the variable",
            Self::Status => "the status variable",
            Self::ErrorFlag => "the error flag",
            Self::Trigger => "the trigger variable",
        }
    }

    /// Whether the runtime writes the variable; a channel's `variable` only when the channel
    /// reads.
    fn is_written_by_runtime(self, direction: ChannelDirection) -> bool {
        match self {
            Self::Variable => direction == ChannelDirection::Read,
            Self::Status | Self::ErrorFlag => true,
            Self::Trigger => false,
        }
    }
}

/// A variable the runtime fills (a read channel's, a status, an error flag), kept to find two
/// fillers of one variable (E0142) and the program's writes of it (W0015).
struct Filled<'p> {
    /// The device's name, where the finding goes.
    device: String,
    /// `Modbus device 'X', channel N (path)` or `Modbus device 'X', status (path)`.
    prefix: String,
    /// What fills it.
    field: Field,
    /// The path as the runtime finds it, in lower case, split at the dots.
    segments: Vec<String>,
    /// The path as written.
    path: String,
    /// The declaration the path starts from.
    root: &'p Variable,
    /// Whether the path names the whole declaration.
    whole: bool,
}

/// Every finding about the project's runtime Modbus devices; `written` holds the declarations
/// some body writes (as W0002 finds writes), for W0015.
pub(super) fn check_modbus_master(
    project: &Project,
    globals: &Globals<'_>,
    written: &HashSet<*const Variable>,
) -> Vec<ProjectDiagnostic> {
    let mut found = Vec::new();
    let devices: Vec<(usize, &ModbusDevice)> = runtime_devices(project).collect();
    if devices.is_empty() {
        return found;
    }
    check_serial_ports(project, &devices, &mut found);
    if let Some((_, first_too_many)) = devices.get(MAX_DEVICES) {
        let message = format!(
            "Modbus device '{}': the project has {} devices with an I/O task, but the runtime masters at most {MAX_DEVICES}: this and the later ones are too many; master some in the Studio (no task)",
            first_too_many.name,
            devices.len()
        );
        found.push(finding(
            &first_too_many.name,
            Code::ModbusDeviceSetting,
            message,
        ));
    }
    let mut filled = Vec::new();
    for &(index, device) in &devices {
        check_device(project, globals, index, device, &mut filled, &mut found);
    }
    for (position, later) in filled.iter().enumerate() {
        let earlier = filled[..position].iter().find(|earlier| {
            let shared = earlier.segments.len().min(later.segments.len());
            earlier.segments[..shared] == later.segments[..shared]
        });
        if let Some(earlier) = earlier {
            let message = format!(
                "{}: {} '{}' is also filled by {}{}: bind each channel, status and error flag to a variable of its own",
                later.prefix,
                later.field.words(),
                later.path,
                earlier.prefix,
                match earlier.field {
                    Field::Status => ", as its status",
                    Field::ErrorFlag => ", as its error flag",
                    _ => "",
                },
            );
            found.push(finding(&later.device, Code::ModbusDoubleWrite, message));
        }
    }
    for filled in &filled {
        if filled.whole && written.contains(&std::ptr::from_ref(filled.root)) {
            let fix = match filled.field {
                Field::Variable => "write another variable, or make the channel a write channel",
                _ => "leave it to the runtime, or bind another variable",
            };
            let message = format!(
                "{}: the program also writes {} '{}', but the next cycle's copy from the device overwrites what it wrote: {fix}",
                filled.prefix,
                filled.field.words(),
                filled.path,
            );
            found.push(finding(
                &filled.device,
                Code::ModbusReadVariableWritten,
                message,
            ));
        }
    }
    found
}

/// The declarations that read channels, status variables and error flags of runtime devices
/// fill: W0002 does not report them, since the runtime writes them every cycle.
pub(super) fn runtime_filled(project: &Project, globals: &Globals<'_>) -> HashSet<*const Variable> {
    let mut filled = HashSet::new();
    for (_, device) in runtime_devices(project) {
        let read_channels = device
            .bindings
            .iter()
            .filter(|binding| binding.direction == ChannelDirection::Read)
            .map(|binding| binding.variable.as_str());
        let paths = read_channels.chain(device.status.as_deref()).chain(
            device
                .bindings
                .iter()
                .filter_map(|b| b.error_flag.as_deref()),
        );
        for path in paths {
            if let Ok(BoundPath {
                last: Some(variable),
                ..
            }) = bound_path(project, globals, path)
            {
                filled.insert(std::ptr::from_ref(variable));
            }
        }
    }
    filled
}

/// The devices the runtime masters (those with an I/O task), with their index in the project.
fn runtime_devices(project: &Project) -> impl Iterator<Item = (usize, &ModbusDevice)> {
    project
        .modbus_devices
        .iter()
        .enumerate()
        .filter(|(_, device)| device.is_runtime_device())
}

/// A finding in `rivet.toml` at the device's or port's `name`.
fn finding(declaration: &str, code: Code, message: String) -> ProjectDiagnostic {
    ProjectDiagnostic {
        file: PathBuf::from(project_model::MANIFEST_FILE_NAME),
        declaration: Some(declaration.to_owned()),
        element: None,
        diagnostic: Diagnostic::new(code, 0..0, message),
    }
}

/// The serial ports runtime devices name: their problems as the editor finds them, 7 data bits
/// (which the editor accepts and Modbus RTU cannot send), and two ports on one device file.
fn check_serial_ports(
    project: &Project,
    devices: &[(usize, &ModbusDevice)],
    found: &mut Vec<ProjectDiagnostic>,
) {
    let mut used: Vec<usize> = Vec::new();
    for (index, port) in project.serial_ports.iter().enumerate() {
        let named = devices.iter().any(|(_, device)| {
            device
                .serial_port()
                .is_some_and(|name| same_identifier(name, &port.name))
        });
        if !named {
            continue;
        }
        let mut problems = serial_port_problems(&project.serial_ports, Some(index), port);
        if port.data_bits == 7 {
            problems.push(DeviceProblem::UnsupportedDataBits(7));
        }
        for problem in problems {
            let message = format!("serial port '{}': {problem}", port.name);
            found.push(finding(&port.name, Code::ModbusDeviceSetting, message));
        }
        let device_file = port.device.trim();
        let sharing = used
            .iter()
            .map(|&other| &project.serial_ports[other])
            .find(|other| !device_file.is_empty() && other.device.trim() == device_file);
        if let Some(other) = sharing {
            let message = format!(
                "serial port '{}': its device file '{device_file}' is also the device file of serial port '{}': two ports cannot share one device file",
                port.name, other.name
            );
            found.push(finding(&port.name, Code::ModbusDeviceSetting, message));
        }
        used.push(index);
        if used.len() == MAX_SERIAL_PORTS + 1 {
            let message = format!(
                "serial port '{}': the project's runtime devices name more than {MAX_SERIAL_PORTS} serial ports, the most the runtime masters: let devices share ports, or move some to the Studio",
                port.name
            );
            found.push(finding(&port.name, Code::ModbusDeviceSetting, message));
        }
    }
}

/// One runtime device: its task, the editor's problems, its status, its channels and how often
/// it is polled.
fn check_device<'p>(
    project: &'p Project,
    globals: &Globals<'p>,
    index: usize,
    device: &ModbusDevice,
    filled: &mut Vec<Filled<'p>>,
    found: &mut Vec<ProjectDiagnostic>,
) {
    let name = device.name.as_str();
    let device_prefix = format!("Modbus device '{name}'");
    let task_name = device.task.as_deref().unwrap_or_default();
    let task = project
        .tasks
        .iter()
        .find(|task| same_identifier(&task.name, task_name));
    if task.is_none() {
        let message = format!(
            "{device_prefix}: there is no task named '{task_name}' to copy the device's values: choose one of the project's tasks"
        );
        found.push(finding(name, Code::ModbusDeviceSetting, message));
    }
    if device.bindings.len() > MAX_CHANNELS_PER_DEVICE {
        let message = format!(
            "{device_prefix}: it has {} channels, but the runtime masters at most {MAX_CHANNELS_PER_DEVICE} per device: merge neighbouring channels into longer ones, or split the device",
            device.bindings.len()
        );
        found.push(finding(name, Code::ModbusChannelSetting, message));
    }
    for problem in modbus_device_problems(project, Some(index), device) {
        match channel_row(&problem) {
            // A path that is not one names no variable: the variable check says so (E0140).
            Some(_)
                if matches!(
                    problem,
                    DeviceProblem::EmptyVariable { .. } | DeviceProblem::InvalidVariable { .. }
                ) => {}
            Some(row) => {
                let prefix = channel_prefix(device, row);
                let message = format!("{prefix}: {}", without_row(&problem.to_string(), row));
                found.push(finding(name, Code::ModbusChannelSetting, message));
            }
            None => {
                let message = format!("{device_prefix}: {problem}");
                found.push(finding(name, Code::ModbusDeviceSetting, message));
            }
        }
    }
    if let Some(path) = device.status.as_deref() {
        let prefix = format!("{device_prefix}, status ({})", path.trim());
        let place = Place {
            prefix: &prefix,
            device: name,
            direction: ChannelDirection::Read,
        };
        if let Some(bound) = bind(project, globals, &place, Field::Status, path, found) {
            let misfit = match status_fit(globals, &bound.ty) {
                StatusFit::Fits => None,
                StatusFit::OtherType => Some(format!(
                    "the status variable is declared as {}: declare it as {MODBUS_DEVICE_STATUS}",
                    bound.ty
                )),
                StatusFit::OwnDeclarationDiffers => Some(format!(
                    "the project declares its own {MODBUS_DEVICE_STATUS}, whose members differ from the Modbus library's, which the runtime writes: remove the project's declaration or give it the library's members"
                )),
                StatusFit::MemberMisfit(misfit) => Some(misfit),
            };
            if let Some(misfit) = misfit {
                let message = format!("{prefix}: {misfit}");
                found.push(finding(name, Code::ModbusFlagType, message));
            }
            filled.push(filled_by(name, prefix, Field::Status, path, &bound));
        }
    }
    for (position, binding) in device.bindings.iter().enumerate() {
        check_channel(
            project,
            globals,
            device,
            position + 1,
            binding,
            filled,
            found,
        );
    }
    if let (Some(task), ModbusSchedule::Interval, Some(poll_interval_ms)) =
        (task, device.schedule, device.poll_interval_ms)
        && let TaskKind::Cyclic { interval_us } = task.kind
        && u64::from(poll_interval_ms) * 1000 < u64::from(interval_us)
    {
        let task_interval = if interval_us % 1000 == 0 {
            format!("{} ms", interval_us / 1000)
        } else {
            format!("{interval_us} µs")
        };
        let message = format!(
            "{device_prefix}: polled every {poll_interval_ms} ms, but its task '{}' copies its values every {task_interval}: set poll_interval_ms to {} or more, or schedule = \"every_cycle\"",
            task.name,
            interval_us.div_ceil(1000)
        );
        found.push(finding(name, Code::ModbusPollFasterThanTask, message));
    }
}

/// One channel: its variable, error flag and trigger variable.
fn check_channel<'p>(
    project: &'p Project,
    globals: &Globals<'p>,
    device: &ModbusDevice,
    row: usize,
    binding: &ModbusBinding,
    filled: &mut Vec<Filled<'p>>,
    found: &mut Vec<ProjectDiagnostic>,
) {
    let name = device.name.as_str();
    let prefix = channel_prefix(device, row);
    let reads = binding.direction == ChannelDirection::Read;
    let place = Place {
        prefix: &prefix,
        device: name,
        direction: binding.direction,
    };
    if let Some(bound) = bind(
        project,
        globals,
        &place,
        Field::Variable,
        &binding.variable,
        found,
    ) {
        // The device editor refuses with the same check, so the two say the same.
        if let Some(misfit) = channel_misfit(&bound, binding) {
            let message = match misfit {
                ChannelBindingError::Misfit { misfit, .. } => format!("{prefix}: {misfit}"),
                other => format!("{prefix}: {other}"),
            };
            found.push(finding(name, Code::ModbusChannelType, message));
        }
        if reads {
            filled.push(filled_by(
                name,
                prefix.clone(),
                Field::Variable,
                &binding.variable,
                &bound,
            ));
        }
    }
    for (field, path) in [
        (Field::ErrorFlag, binding.error_flag.as_deref()),
        (Field::Trigger, binding.trigger_variable.as_deref()),
    ] {
        let Some(path) = path else { continue };
        let Some(bound) = bind(project, globals, &place, field, path, found) else {
            continue;
        };
        if !matches!(bound.ty, Type::Elementary(Elementary::Bool) | Type::Error) {
            let message = format!(
                "{prefix}: {} '{}' is declared as {}: declare it as BOOL",
                field.words(),
                path.trim(),
                bound.ty
            );
            found.push(finding(name, Code::ModbusFlagType, message));
        }
        if field == Field::ErrorFlag {
            filled.push(filled_by(name, prefix.clone(), field, path, &bound));
        }
    }
}

/// Resolves a bound path, reporting E0140 when it names nothing the runtime can copy, or a
/// `CONSTANT` the runtime would write.
fn bind<'p>(
    project: &'p Project,
    globals: &Globals<'p>,
    place: &Place<'_>,
    field: Field,
    path: &str,
    found: &mut Vec<ProjectDiagnostic>,
) -> Option<BoundPath<'p>> {
    let path = path.trim();
    let words = field.words();
    let written_by_runtime = field.is_written_by_runtime(place.direction);
    // The device editor decides with the same function (`ide::check_channel_binding`).
    let problem = match bind_path(project, globals, path, written_by_runtime) {
        Ok(bound) => return Some(bound),
        Err(Unbound::Constant) => format!(
            "{words} '{path}' is a CONSTANT, which the runtime cannot write: remove CONSTANT or bind another variable"
        ),
        Err(Unbound::NoVariable) => format!(
            "{words} '{path}' names no variable of the project: write the path of a global or program variable, such as GVL_IO.rSpeed"
        ),
        Err(Unbound::StaticElsewhere(symbol)) => format!(
            "{words} '{path}' names a VAR_STAT, which all instances share under the name of the function block declaring it: bind '{symbol}' instead"
        ),
        Err(Unbound::NoFixedPlace(what)) => format!(
            "{words} '{path}' is {what}: bind a global variable or a program's VAR, VAR_INPUT or VAR_OUTPUT"
        ),
    };
    found.push(finding(
        place.device,
        Code::ModbusUncopyableVariable,
        format!("{}: {problem}", place.prefix),
    ));
    None
}

/// Where a bound path belongs, for [`bind`]'s finding.
struct Place<'a> {
    /// `Modbus device 'X', channel N (path)`.
    prefix: &'a str,
    /// The device's name.
    device: &'a str,
    /// The channel's direction (a status is read).
    direction: ChannelDirection,
}

/// What [`Filled`] keeps of a resolved path.
fn filled_by<'p>(
    device: &str,
    prefix: String,
    field: Field,
    path: &str,
    bound: &BoundPath<'p>,
) -> Filled<'p> {
    Filled {
        device: device.to_owned(),
        prefix,
        field,
        segments: bound.canonical.split('.').map(str::to_lowercase).collect(),
        path: path.trim().to_owned(),
        root: bound.root,
        whole: bound.whole,
    }
}

/// `Modbus device 'X', channel N (path)`, channels numbered from 1.
fn channel_prefix(device: &ModbusDevice, row: usize) -> String {
    let variable = device
        .bindings
        .get(row.wrapping_sub(1))
        .map_or("", |binding| binding.variable.trim());
    format!(
        "Modbus device '{}', channel {row} ({variable})",
        device.name
    )
}

/// The size in bytes of each member of `MODBUS_DEVICE_STATUS` as the runtime writes it
/// (`docs/modbus-master.md` §3.1), in the library's member order: with these sizes the
/// structure's members fall at the spec's offsets and the structure is 32 bytes.
const STATUS_MEMBER_BYTES: [u32; 10] = [1, 1, 1, 1, 4, 4, 4, 4, 4, 8];

/// Whether a status variable's type is the one the runtime writes.
enum StatusFit {
    /// The Modbus library's status structure, or a project's own declaration of its name with
    /// the same members whose types resolve to the same sizes (the runtime finds the members by
    /// name and offset).
    Fits,
    /// Another type.
    OtherType,
    /// A project's own declaration of the name with other members.
    OwnDeclarationDiffers,
    /// A project's own declaration (of the structure or of a member's type) that makes a member
    /// another size than the runtime writes: the words say which and how to fix it.
    MemberMisfit(String),
}

/// How `ty` fits a status variable.
fn status_fit(globals: &Globals<'_>, ty: &Type) -> StatusFit {
    let Type::Named(name) = ty else {
        return if *ty == Type::Error {
            StatusFit::Fits
        } else {
            StatusFit::OtherType
        };
    };
    if !name.eq_ignore_ascii_case(MODBUS_DEVICE_STATUS) {
        return StatusFit::OtherType;
    }
    let library = crate::library::modbus().application.objects();
    let members = |definition: &TypeDefinition| -> Option<Vec<(String, String)>> {
        match definition {
            TypeDefinition::Struct {
                members,
                extends: None,
            } => Some(
                members
                    .iter()
                    .map(|member| (member.name.clone(), member.ty.clone()))
                    .collect(),
            ),
            _ => None,
        }
    };
    let expected = library.iter().find_map(|object| match object {
        project_model::Object::DataType(data_type)
            if data_type.name.eq_ignore_ascii_case(MODBUS_DEVICE_STATUS) =>
        {
            members(&data_type.definition)
        }
        _ => None,
    });
    let declared = globals
        .data_type(name)
        .and_then(|data_type| members(&data_type.definition));
    let (Some(expected), Some(declared)) = (expected, declared) else {
        return StatusFit::OwnDeclarationDiffers;
    };
    let same_names = expected.len() == declared.len()
        && expected
            .iter()
            .zip(&declared)
            .all(|((expected, _), (declared, _))| expected.eq_ignore_ascii_case(declared));
    if !same_names {
        return StatusFit::OwnDeclarationDiffers;
    }
    // The names match; the runtime also needs each member's size, which a project's own
    // declaration of a member's type (MB_ErrorCodes without a base) can change.
    for (((member, library_ty), (_, declared_ty)), bytes) in
        expected.iter().zip(&declared).zip(STATUS_MEMBER_BYTES)
    {
        if let Some(misfit) = member_misfit(globals, member, library_ty, declared_ty, bytes) {
            return StatusFit::MemberMisfit(misfit);
        }
    }
    StatusFit::Fits
}

/// Why the status structure's member `member`, declared as `declared_ty`, is not an integer,
/// bit string, duration or enumeration of `bytes` bytes as the library's `library_ty`.
fn member_misfit(
    globals: &Globals<'_>,
    member: &str,
    library_ty: &str,
    declared_ty: &str,
    bytes: u32,
) -> Option<String> {
    let declared_ty = declared_ty.trim();
    let resolved = globals.resolve_type(declared_ty);
    let size = |ty: &Type| match ty {
        Type::Elementary(elementary)
        | Type::Subrange {
            base: elementary, ..
        } => Some(elementary.size_bits() / 8),
        _ => None,
    };
    if let Type::Named(enum_name) = &resolved
        && let Some(data_type) = globals.data_type(enum_name)
        && let TypeDefinition::Enum { base, .. } = &data_type.definition
    {
        let base_text = base.as_deref().map_or("INT", str::trim);
        if size(&globals.resolve_type(base_text)) == Some(bytes) {
            return None;
        }
        let default = if base.is_none() { " (the default)" } else { "" };
        return Some(format!(
            "the project's {} has the base type {base_text}{default}, which makes the member {member} another size than the runtime writes: the project's {} must have the base type USINT",
            data_type.name, data_type.name
        ));
    }
    if resolved == Type::Error || size(&resolved) == Some(bytes) {
        return None;
    }
    Some(format!(
        "the project's {MODBUS_DEVICE_STATUS} declares the member {member} as {declared_ty}, which the runtime cannot write: declare it as {library_ty}"
    ))
}

/// The channel a problem of the device editor's checks is about, numbered from 1; `None` for a
/// problem of the device itself.
fn channel_row(problem: &DeviceProblem) -> Option<usize> {
    match problem {
        DeviceProblem::EmptyVariable { row }
        | DeviceProblem::InvalidVariable { row, .. }
        | DeviceProblem::ChannelPastEnd { row, .. }
        | DeviceProblem::ChannelsOverlap { row, .. }
        | DeviceProblem::TableTypeMismatch { row, .. }
        | DeviceProblem::ZeroCount { row }
        | DeviceProblem::ChannelTooLong { row, .. }
        | DeviceProblem::WriteToReadOnlyTable { row, .. }
        | DeviceProblem::FunctionCodeOnRead { row, .. }
        | DeviceProblem::FunctionCodeMisfit { row, .. }
        | DeviceProblem::SingleWriteTooWide { row, .. }
        | DeviceProblem::TriggerVariableWithoutEdge { row }
        | DeviceProblem::EdgeWithoutTriggerVariable { row }
        | DeviceProblem::OnErrorOnWrite { row } => Some(*row),
        _ => None,
    }
}

/// A channel problem's text without its leading `channel N`, which the finding's prefix already
/// says: `channel 2: a coil cannot…` becomes `a coil cannot…`, `channel 2 writes…` becomes
/// `the channel writes…`.
fn without_row(text: &str, row: usize) -> String {
    let lead = format!("channel {row}");
    match text.strip_prefix(&lead) {
        Some(rest) => match rest.strip_prefix(": ") {
            Some(rest) => rest.to_owned(),
            None => format!("the channel{rest}"),
        },
        None => text.to_owned(),
    }
}

#[cfg(test)]
#[path = "modbus_master_tests.rs"]
mod tests;
