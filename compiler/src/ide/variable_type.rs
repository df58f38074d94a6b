//! The declared type of a variable named by its path, for editors that bind variables to
//! channels (the Modbus device editor) and must say whether a variable exists and fits.

use project_model::{ModbusDataType, PouKind, Project};
use thiserror::Error;

use crate::sema::scope::{GlobalSymbol, Globals};
use crate::sema::ty::Type;

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
        "'{path}' is declared as {declared}, but the channel reads {data_type}: declare it as {expected}"
    )]
    TypeMismatch {
        /// The variable's path.
        path: String,
        /// Its declared type, as the compiler spells it.
        declared: String,
        /// The channel's data type, as the project file spells it.
        data_type: String,
        /// The types that fit the channel, such as `UINT or WORD`.
        expected: String,
    },
}

/// The declared type of the variable at `path` (`GVL_IO.rSpeed`, `Main.fbConveyor.xRun`, or an
/// unqualified global), spelled as the compiler shows types (`REAL`, `ST_Recipe`,
/// `ARRAY[0..3] OF INT`); `None` when the path names no variable.
pub fn variable_type(project: &Project, path: &str) -> Option<String> {
    let globals = Globals::new(project);
    resolve(&globals, path).map(|ty| ty.to_string())
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
        expected: fitting.join(" or "),
    })
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
}
