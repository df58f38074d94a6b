//! The declared type of a variable named by its path, for editors that bind variables to
//! channels (the Modbus device editor) and must say whether a variable exists and fits; the
//! checker's Modbus checks (`sema::modbus_master`) and the code generator use the same path
//! resolution ([`bound_path`]) and fits, so the editor, the build and the image agree.

use project_model::{
    ChannelDirection, ModbusBinding, ModbusDataType, Object, PouKind, Project, VarSection,
    Variable, is_valid_identifier,
};
use thiserror::Error;

use super::Unplaceable;
use crate::sema::address::parse_address;
use crate::sema::scope::{GlobalSymbol, Globals, inheritance_chain};
use crate::sema::ty::Type;
use crate::sema::types::Shape;

/// Why a variable cannot be bound to a Modbus channel of some data type.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
pub enum ChannelVariableError {
    /// The path names no variable of the project.
    #[error(
        "there is no variable '{0}': write the path of a global or program variable, such as GVL_IO.rSpeed"
    )]
    NoSuchVariable(String),
    /// The variable's declared type is not the channel's.
    #[error(
        "'{path}' is declared as {declared}, but the channel reads {data_type}: declare it as {}",
        expected.join(" or ")
    )]
    TypeMismatch {
        /// The variable's path.
        path: String,
        /// Its declared type, as the compiler spells it.
        declared: String,
        /// The channel's data type, as the project file spells it.
        data_type: String,
        /// The types that fit the channel, such as `UINT` and `WORD`.
        expected: Vec<String>,
    },
}

/// Why a variable cannot be bound to a channel of some data type and count
/// ([`check_channel_binding`]): the build's reasons (E0140, E0141) for a channel's variable.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
pub enum ChannelBindingError {
    /// The path names no variable of the project.
    #[error(
        "there is no variable '{0}': write the path of a global or program variable, such as GVL_IO.rSpeed"
    )]
    NoSuchVariable(String),
    /// The path names something without a fixed place between cycles (E0140).
    #[error(
        "the variable '{path}' is {what}: bind a global variable or a program's VAR, VAR_INPUT or VAR_OUTPUT"
    )]
    NoFixedPlace {
        /// The variable's path.
        path: String,
        /// What it names.
        what: Unplaceable,
    },
    /// The path names a `VAR_STAT` through an instance, or through a function block derived
    /// from the one declaring it (E0140).
    #[error(
        "the variable '{path}' names a VAR_STAT, which all instances share under the name of the function block declaring it: bind '{symbol}' instead"
    )]
    StaticElsewhere {
        /// The variable's path.
        path: String,
        /// The path of the one shared variable: `<declaring function block>.<name>`.
        symbol: String,
    },
    /// A read channel's variable is `CONSTANT`, which the runtime would write (E0140).
    #[error(
        "the variable '{path}' is a CONSTANT, which the runtime cannot write: remove CONSTANT or bind another variable"
    )]
    Constant {
        /// The variable's path.
        path: String,
    },
    /// The variable's type does not fit the channel's data type and count (E0141).
    #[error("'{path}': {misfit}")]
    Misfit {
        /// The variable's path.
        path: String,
        /// How it does not fit.
        misfit: ChannelMisfit,
    },
    /// A channel of several values is bound to a variable at a bit address, where the runtime
    /// copies one bit (E0141).
    #[error(
        "the variable '{path}' is located at the bit address {address}, where the runtime copies one bit, but the channel holds {count} values: remove the AT address, or bind a variable of its own to each bit"
    )]
    AtBitAddress {
        /// The variable's path.
        path: String,
        /// The declaration's address, as written (`%IX0.0`).
        address: String,
        /// How many values the channel holds.
        count: u16,
    },
}

/// How a variable's declared type misses a channel: the channel's values, the declared type and
/// the declarations that would fit (`docs/modbus-master.md` §2.2).
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[error(
    "the channel {} {}, but the variable is declared as {declared}: declare it as {}",
    if *direction == ChannelDirection::Write { "writes" } else { "reads" },
    values(*data_type, *count),
    expected.join(" or ")
)]
pub struct ChannelMisfit {
    /// Whether the channel reads or writes.
    pub direction: ChannelDirection,
    /// The channel's data type.
    pub data_type: ModbusDataType,
    /// How many values the channel holds.
    pub count: u16,
    /// The variable's declared type, as the compiler spells it.
    pub declared: String,
    /// The declarations that fit, such as `ARRAY[0..7] OF UINT` and `ARRAY[0..7] OF WORD`.
    pub expected: Vec<String>,
}

/// A variable path of a Modbus binding resolved against the project's declarations.
pub(crate) struct BoundPath<'p> {
    /// The path as the runtime finds it among the image's symbols: an unqualified global gets
    /// its list's name in front.
    pub(crate) canonical: String,
    /// The declared type of what the path names.
    pub(crate) ty: Type,
    /// The declaration the path starts from: a global variable or a program's variable.
    pub(crate) root: &'p Variable,
    /// The declaration of the variable the path names, when it is a declared variable (of a
    /// list, a program or a function block) rather than a member of a structure or of a
    /// standard function block.
    pub(crate) last: Option<&'p Variable>,
    /// Whether the path names `root` itself, not a part of it.
    pub(crate) whole: bool,
    /// Whether a declaration along the path is `CONSTANT`.
    pub(crate) constant: bool,
}

/// Why a path names nothing the runtime can copy to or from between cycles.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) enum Unbound {
    /// It names no variable of the project.
    NoVariable,
    /// It names something without a fixed place between cycles.
    NoFixedPlace(Unplaceable),
    /// It names a `CONSTANT` the runtime would write.
    Constant,
    /// It names a `VAR_STAT` through an instance or through a function block derived from the
    /// one declaring it: the runtime's symbol of the one shared variable is
    /// `<declaring POU>.<name>`, the path the finding asks for.
    StaticElsewhere(String),
}

/// The declared type of the variable at `path` (`GVL_IO.rSpeed`, `Main.fbConveyor.xRun`, or an
/// unqualified global), spelled as the compiler shows types (`REAL`, `ST_Recipe`,
/// `ARRAY[0..3] OF INT`); `None` when the path names no variable.
pub fn variable_type(project: &Project, path: &str) -> Option<String> {
    let globals = Globals::new(project);
    resolve(&globals, path).map(|ty| ty.to_string())
}

/// The elementary type of the values the variable at `path` holds and, for a one-dimensional
/// array, its length: `("REAL", None)` for a `REAL` (or a subrange of its base),
/// `("INT", Some(8))` for an `ARRAY[0..7] OF INT`; `None` when the path names no variable, or
/// one of another type (a structure, an array of several dimensions or of structures). A
/// channel editor takes a new channel's data type and count from it.
pub fn variable_values(project: &Project, path: &str) -> Option<(&'static str, Option<u64>)> {
    let globals = Globals::new(project);
    match resolve(&globals, path)? {
        Type::Array { element, dims } => match dims.as_slice() {
            [Some((low, high))] => {
                let length = u64::try_from(high - low + 1).ok()?;
                Some((elementary_name(&element)?, Some(length)))
            }
            _ => None,
        },
        other => Some((elementary_name(&other)?, None)),
    }
}

/// Checks that `path` names a variable whose declared type fits a channel of `data_type`: the
/// channel's IEC type (`REAL` for `real`), or the bit string of the same size for an unsigned
/// channel (`WORD` for `uint16`), since both hold the register's bits unchanged.
pub fn check_channel_variable(
    project: &Project,
    path: &str,
    data_type: ModbusDataType,
) -> Result<(), ChannelVariableError> {
    let globals = Globals::new(project);
    let path = path.trim();
    let ty = resolve(&globals, path)
        .ok_or_else(|| ChannelVariableError::NoSuchVariable(path.to_owned()))?;
    let fitting = fitting_types(data_type);
    let declared = match &ty {
        Type::Subrange { base, .. } => base.name().to_owned(),
        other => other.to_string(),
    };
    if fitting.contains(&declared.as_str()) {
        return Ok(());
    }
    Err(ChannelVariableError::TypeMismatch {
        path: path.to_owned(),
        declared: ty.to_string(),
        data_type: data_type.iec_name().to_owned(),
        expected: fitting.iter().map(|name| (*name).to_owned()).collect(),
    })
}

/// Checks that `binding.variable` names a variable that fits the channel: its data type as
/// [`check_channel_variable`] says, and for a `count` above 1 a one-dimensional `ARRAY` of
/// exactly `count` such elements.
pub fn check_channel_binding(
    project: &Project,
    binding: &ModbusBinding,
) -> Result<(), ChannelBindingError> {
    let globals = Globals::new(project);
    let path = binding.variable.trim();
    let written_by_runtime = binding.direction == ChannelDirection::Read;
    let owned = || path.to_owned();
    let bound =
        bind_path(project, &globals, path, written_by_runtime).map_err(
            |unbound| match unbound {
                Unbound::NoVariable => ChannelBindingError::NoSuchVariable(owned()),
                Unbound::NoFixedPlace(what) => ChannelBindingError::NoFixedPlace {
                    path: owned(),
                    what,
                },
                Unbound::StaticElsewhere(symbol) => ChannelBindingError::StaticElsewhere {
                    path: owned(),
                    symbol,
                },
                Unbound::Constant => ChannelBindingError::Constant { path: owned() },
            },
        )?;
    match channel_misfit(&bound, binding) {
        None => Ok(()),
        Some(error) => Err(error),
    }
}

/// How the variable `bound` misses the channel `binding`, or `None` when it fits: its type
/// ([`ChannelBindingError::Misfit`]), or for several values a declaration at a bit address
/// ([`ChannelBindingError::AtBitAddress`]). The build's E0141 and the device editor both ask
/// this, so they agree.
pub(crate) fn channel_misfit(
    bound: &BoundPath<'_>,
    binding: &ModbusBinding,
) -> Option<ChannelBindingError> {
    let path = binding.variable.trim();
    if let Some(misfit) = type_misfit(&bound.ty, binding) {
        return Some(ChannelBindingError::Misfit {
            path: path.to_owned(),
            misfit,
        });
    }
    // The runtime copies a symbol at a bit address as that one bit, so the other values of an
    // array there would be lost.
    let address = bound.root.address.as_deref()?;
    let located = parse_address(address).ok().flatten()?;
    (binding.count > 1 && located.size_bits == 1).then(|| ChannelBindingError::AtBitAddress {
        path: path.to_owned(),
        address: address.trim().to_owned(),
        count: binding.count,
    })
}

/// How `ty` misses the channel `binding`'s data type and count, or `None` when it fits.
fn type_misfit(ty: &Type, binding: &ModbusBinding) -> Option<ChannelMisfit> {
    let fitting = fitting_types(binding.data_type);
    let fits = |ty: &Type| elementary_name(ty).is_some_and(|name| fitting.contains(&name));
    let count = binding.count;
    let (fit, low) = match ty {
        Type::Array { element, dims } => match dims.as_slice() {
            [Some((low, high))] => (
                count > 1 && high - low + 1 == i128::from(count) && fits(element),
                *low,
            ),
            _ => (false, 0),
        },
        _ => (count == 1 && fits(ty), 0),
    };
    if fit || *ty == Type::Error {
        return None;
    }
    let expected: Vec<String> = fitting
        .iter()
        .map(|name| {
            if count == 1 {
                (*name).to_owned()
            } else {
                format!("ARRAY[{low}..{}] OF {name}", low + i128::from(count) - 1)
            }
        })
        .collect();
    Some(ChannelMisfit {
        direction: binding.direction,
        data_type: binding.data_type,
        count,
        declared: ty.to_string(),
        expected,
    })
}

/// The IEC name of an elementary type or of a subrange's base, the names [`fitting_types`]
/// lists.
fn elementary_name(ty: &Type) -> Option<&'static str> {
    match ty {
        Type::Elementary(elementary)
        | Type::Subrange {
            base: elementary, ..
        } => Some(elementary.name()),
        _ => None,
    }
}

/// `one int16 value` or `8 real values`, with the data type as the project file spells it.
fn values(data_type: ModbusDataType, count: u16) -> String {
    let name = data_type.file_name();
    if count == 1 {
        format!("one {name} value")
    } else {
        format!("{count} {name} values")
    }
}

/// Resolves a binding's `path` as [`bound_path`] does and refuses a `CONSTANT` when the
/// runtime writes it (`written_by_runtime`: a read channel's variable, a status, an error
/// flag): the decision the build's E0140 and the device editor share.
pub(crate) fn bind_path<'p>(
    project: &'p Project,
    globals: &Globals<'p>,
    path: &str,
    written_by_runtime: bool,
) -> Result<BoundPath<'p>, Unbound> {
    let bound = bound_path(project, globals, path)?;
    if bound.constant && written_by_runtime {
        return Err(Unbound::Constant);
    }
    Ok(bound)
}

/// Resolves a binding's `path` (`GVL_Io.aiTemps`, `Main.fbDrive.xReady`, an unqualified global)
/// to the declaration it names and its type, or says why the runtime could not copy it.
pub(crate) fn bound_path<'p>(
    project: &'p Project,
    globals: &Globals<'p>,
    path: &str,
) -> Result<BoundPath<'p>, Unbound> {
    let path = path.trim();
    let segments: Vec<&str> = path.split('.').collect();
    if !segments.iter().all(|segment| is_valid_identifier(segment)) {
        return Err(Unbound::NoVariable);
    }
    let (root, canonical, rest) = match globals.lookup(segments[0]) {
        Some(GlobalSymbol::Var(variable)) => {
            let list = project
                .application
                .objects()
                .into_iter()
                .find_map(|object| match object {
                    Object::Gvl(gvl) if gvl.variables.iter().any(|v| std::ptr::eq(v, variable)) => {
                        Some(gvl.name.as_str())
                    }
                    _ => None,
                });
            let canonical = match list {
                Some(list) => format!("{list}.{path}"),
                None => path.to_owned(),
            };
            (variable, canonical, &segments[1..])
        }
        Some(GlobalSymbol::Gvl(gvl)) => {
            let name = segments.get(1).ok_or(Unbound::NoVariable)?;
            let variable = gvl
                .variables
                .iter()
                .find(|v| v.name.eq_ignore_ascii_case(name))
                .ok_or(Unbound::NoVariable)?;
            (variable, path.to_owned(), &segments[2..])
        }
        Some(GlobalSymbol::Pou(pou)) => {
            let name = segments.get(1).ok_or(Unbound::NoVariable)?;
            let variable = match pou.kind {
                PouKind::Program => pou_variable(globals, pou, name)?.1,
                PouKind::FunctionBlock => {
                    // Only a function block's static variables have a place of their own, under
                    // the name of the block that declares them.
                    let (declaring, variable) = pou_variable(globals, pou, name)?;
                    if variable.section != VarSection::VarStat {
                        return Err(Unbound::NoVariable);
                    }
                    if !std::ptr::eq(declaring, pou) {
                        return Err(Unbound::StaticElsewhere(format!(
                            "{}.{}",
                            declaring.name, variable.name
                        )));
                    }
                    variable
                }
                PouKind::Function => {
                    return Err(Unbound::NoFixedPlace(Unplaceable::FunctionVariable));
                }
                _ => return Err(Unbound::NoVariable),
            };
            (variable, path.to_owned(), &segments[2..])
        }
        Some(GlobalSymbol::Axis | GlobalSymbol::Cam) => {
            return Err(Unbound::NoFixedPlace(Unplaceable::AxisOrCam));
        }
        _ => return Err(Unbound::NoVariable),
    };
    let mut bound = BoundPath {
        canonical,
        ty: globals.resolve_type(&root.ty),
        root,
        last: Some(root),
        whole: rest.is_empty(),
        constant: root.constant,
    };
    for segment in rest {
        let Type::Named(name) = &bound.ty else {
            return Err(Unbound::NoVariable);
        };
        match globals.shape(name).ok_or(Unbound::NoVariable)? {
            Shape::Struct(_) | Shape::StandardFb(_) => {
                let member = globals.member(name, segment).ok_or(Unbound::NoVariable)?;
                bound.ty = member.ty;
                bound.last = None;
            }
            Shape::Pou(pou) if pou.kind == PouKind::FunctionBlock => {
                let (declaring, variable) = pou_variable(globals, pou, segment)?;
                // An instance holds no VAR_STAT: all instances share the declaring block's one.
                if variable.section == VarSection::VarStat {
                    return Err(Unbound::StaticElsewhere(format!(
                        "{}.{}",
                        declaring.name, variable.name
                    )));
                }
                bound.ty = globals.resolve_type(&variable.ty);
                bound.constant |= variable.constant;
                bound.last = Some(variable);
            }
            Shape::Pou(_) | Shape::Enum(_) => return Err(Unbound::NoVariable),
        }
    }
    Ok(bound)
}

/// The variable `name` of a program or function block (its bases' included) that has a place in
/// its instance, with the POU declaring it, or why not.
fn pou_variable<'p>(
    globals: &Globals<'p>,
    pou: &'p project_model::Pou,
    name: &str,
) -> Result<(&'p project_model::Pou, &'p Variable), Unbound> {
    for current in inheritance_chain(globals, pou) {
        if let Some(variable) = current
            .variables
            .iter()
            .find(|v| v.name.eq_ignore_ascii_case(name))
        {
            return match variable.section {
                VarSection::VarTemp => Err(Unbound::NoFixedPlace(Unplaceable::VarTemp)),
                VarSection::VarInOut => Err(Unbound::NoFixedPlace(Unplaceable::VarInOut)),
                VarSection::VarExternal => Err(Unbound::NoFixedPlace(Unplaceable::VarExternal)),
                _ => Ok((current, variable)),
            };
        }
        if current
            .methods
            .iter()
            .any(|m| m.name.eq_ignore_ascii_case(name))
        {
            return Err(Unbound::NoFixedPlace(Unplaceable::Method));
        }
        if current
            .properties
            .iter()
            .any(|p| p.name.eq_ignore_ascii_case(name))
        {
            return Err(Unbound::NoFixedPlace(Unplaceable::Property));
        }
    }
    Err(Unbound::NoVariable)
}

/// The IEC types a channel of `data_type` may be bound to.
fn fitting_types(data_type: ModbusDataType) -> &'static [&'static str] {
    match data_type {
        ModbusDataType::Bool => &["BOOL"],
        ModbusDataType::Int16 => &["INT"],
        ModbusDataType::Uint16 => &["UINT", "WORD"],
        ModbusDataType::Int32 => &["DINT"],
        ModbusDataType::Uint32 => &["UDINT", "DWORD"],
        ModbusDataType::Int64 => &["LINT"],
        ModbusDataType::Uint64 => &["ULINT", "LWORD"],
        ModbusDataType::Real => &["REAL"],
        ModbusDataType::Lreal => &["LREAL"],
    }
}

/// The type of the variable at `path`: a global variable list's or a program's variable, or an
/// unqualified global, then members of structures and function blocks.
fn resolve(globals: &Globals<'_>, path: &str) -> Option<Type> {
    let mut segments = path.trim().split('.');
    let first = segments.next()?;
    let mut ty = match globals.lookup(first)? {
        GlobalSymbol::Var(variable) => globals.resolve_type(&variable.ty),
        GlobalSymbol::Gvl(gvl) => {
            let name = segments.next()?;
            let variable = gvl
                .variables
                .iter()
                .find(|v| v.name.eq_ignore_ascii_case(name))?;
            globals.resolve_type(&variable.ty)
        }
        GlobalSymbol::Pou(pou) if pou.kind == PouKind::Program => {
            let name = segments.next()?;
            globals.member(&pou.name, name)?.ty
        }
        _ => return None,
    };
    for segment in segments {
        let Type::Named(name) = &ty else {
            return None;
        };
        let member = globals.member(name, segment)?;
        if member.is_method {
            return None;
        }
        ty = member.ty;
    }
    Some(ty)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn example() -> Project {
        project_model::load_project(&assets::example_project_dir())
            .unwrap()
            .project
    }

    #[test]
    fn global_and_program_variables_have_their_declared_types() {
        let project = example();
        assert_eq!(
            variable_type(&project, "GVL_Machine.rBeltSpeedActual").as_deref(),
            Some("REAL")
        );
        assert_eq!(
            variable_type(&project, "gvl_machine.xdriveready").as_deref(),
            Some("BOOL")
        );
        assert_eq!(
            variable_type(&project, "Main.fbConveyor").as_deref(),
            Some("FB_Conveyor")
        );
        assert_eq!(
            variable_type(&project, "Main.ctuPackages.Q").as_deref(),
            Some("BOOL")
        );
        assert_eq!(variable_type(&project, "GVL_Machine.Missing"), None);
        assert_eq!(variable_type(&project, "GVL_Machine"), None);
        assert_eq!(variable_type(&project, ""), None);
    }

    #[test]
    fn a_variable_fits_a_channel_of_its_type_and_is_refused_by_another() {
        let project = example();
        let speed = "GVL_Machine.rBeltSpeedActual";
        assert_eq!(
            check_channel_variable(&project, speed, ModbusDataType::Real),
            Ok(())
        );
        let error = check_channel_variable(&project, speed, ModbusDataType::Int16).unwrap_err();
        assert_eq!(
            error.to_string(),
            "'GVL_Machine.rBeltSpeedActual' is declared as REAL, but the channel reads INT: declare it as INT"
        );
        assert_eq!(
            check_channel_variable(&project, "GVL_Machine.rNothing", ModbusDataType::Real),
            Err(ChannelVariableError::NoSuchVariable(
                "GVL_Machine.rNothing".into()
            ))
        );
    }

    #[test]
    fn a_channel_of_several_values_needs_an_array_of_exactly_that_many() {
        let project = crate::SourceProject::new(
            "VAR_GLOBAL\n    awRaw : ARRAY[1..4] OF WORD;\n    iOne : INT;\nEND_VAR\n",
        )
        .project;
        let mut binding = ModbusBinding::new(
            "GVL.awRaw",
            project_model::ModbusTable::HoldingRegister,
            0,
            ModbusDataType::Uint16,
        );
        binding.count = 4;
        assert_eq!(check_channel_binding(&project, &binding), Ok(()));
        binding.count = 5;
        binding.direction = ChannelDirection::Write;
        assert_eq!(
            check_channel_binding(&project, &binding)
                .unwrap_err()
                .to_string(),
            "'GVL.awRaw': the channel writes 5 uint16 values, but the variable is declared as ARRAY[1..4] OF WORD: declare it as ARRAY[1..5] OF UINT or ARRAY[1..5] OF WORD"
        );
        binding.variable = "GVL.iOne".into();
        binding.data_type = ModbusDataType::Int16;
        binding.count = 1;
        assert_eq!(check_channel_binding(&project, &binding), Ok(()));
        binding.variable = "GVL.iNone".into();
        assert_eq!(
            check_channel_binding(&project, &binding),
            Err(ChannelBindingError::NoSuchVariable("GVL.iNone".into()))
        );
    }

    #[test]
    fn a_variable_s_values_are_its_element_type_and_an_array_s_length() {
        let project = crate::SourceProject::new(
            "VAR_GLOBAL\n    awRaw : ARRAY[1..4] OF WORD;\n    iOne : INT;\n    \
             aaGrid : ARRAY[0..1, 0..1] OF INT;\nEND_VAR\n",
        )
        .project;
        assert_eq!(
            variable_values(&project, "GVL.awRaw"),
            Some(("WORD", Some(4)))
        );
        assert_eq!(variable_values(&project, "GVL.iOne"), Some(("INT", None)));
        assert_eq!(variable_values(&project, "GVL.aaGrid"), None);
        assert_eq!(variable_values(&project, "GVL.iNone"), None);
    }
}
