//! Libraries every project sees without declaring them: the motion library (`motion.st`), the
//! PLCopen and CODESYS SoftMotion function blocks and their types, and the Modbus library
//! (`modbus.st`), the types of the runtime Modbus master's status (`docs/modbus-master.md` §3.1).
//!
//! A library is Structured Text read once into a project of its own. The checker resolves
//! names in it after the project's own, so a project may declare a name of a library itself.
//! Its function blocks have no ST body: the runtime runs them natively (`docs/motion.md`).

use std::sync::OnceLock;

use project_model::{Object, Project};

use crate::SourceProject;

/// The type of an axis of the device tree, which the motion function blocks take.
pub const AXIS_REF: &str = "AXIS_REF";

/// The type of a cam table of the application, which `MC_CamTableSelect` takes.
pub const CAM_REF: &str = "MC_CAM_REF";

/// The type of a runtime Modbus device's status variable (`docs/modbus-master.md` §3.1), which
/// the runtime finds by this name in the image's type table.
pub const MODBUS_DEVICE_STATUS: &str = "MODBUS_DEVICE_STATUS";

/// The text of the motion library.
const MOTION_SOURCE: &str = include_str!("motion.st");

/// The text of the Modbus library.
const MODBUS_SOURCE: &str = include_str!("modbus.st");

/// The motion library as a project of its own, read on first use.
pub fn motion() -> &'static Project {
    static MOTION: OnceLock<Project> = OnceLock::new();
    MOTION.get_or_init(|| SourceProject::new(MOTION_SOURCE).project)
}

/// The Modbus library as a project of its own, read on first use.
pub fn modbus() -> &'static Project {
    static MODBUS: OnceLock<Project> = OnceLock::new();
    MODBUS.get_or_init(|| SourceProject::new(MODBUS_SOURCE).project)
}

/// Every object of every library.
pub(crate) fn objects() -> Vec<&'static Object> {
    let mut objects = motion().application.objects();
    objects.extend(modbus().application.objects());
    objects
}

/// Whether `name` (any case) is a function block of a library that the runtime runs natively.
pub fn is_native_block(name: &str) -> bool {
    objects().iter().any(|object| {
        matches!(object, Object::Pou(pou)
            if pou.kind == project_model::PouKind::FunctionBlock
                && pou.name.eq_ignore_ascii_case(name))
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sema::check_project;

    #[test]
    fn the_motion_library_reads_without_a_finding() {
        reads_without_a_finding(MOTION_SOURCE);
    }

    #[test]
    fn the_modbus_library_reads_without_a_finding() {
        reads_without_a_finding(MODBUS_SOURCE);
    }

    /// Checks that a library's text parses and checks without a finding.
    #[track_caller]
    fn reads_without_a_finding(text: &str) {
        let source = SourceProject::new(text);
        assert!(
            source.parse.errors().is_empty(),
            "{:?}",
            source.parse.errors()
        );
        assert!(source.diagnostics.is_empty(), "{:?}", source.diagnostics);
        let findings: Vec<_> = check_project(&source.project)
            .into_iter()
            .map(|finding| {
                format!(
                    "{:?}: {}",
                    finding.diagnostic.code, finding.diagnostic.message
                )
            })
            .collect();
        assert!(findings.is_empty(), "{findings:#?}");
    }

    #[test]
    fn the_modbus_status_has_the_layout_the_runtime_writes_by() {
        let source = SourceProject::new(
            "PROGRAM Main\nVAR\n    stDrive : MODBUS_DEVICE_STATUS;\nEND_VAR\n\
             stDrive.eLastError := MB_ErrorCodes.NOT_YET_POLLED;\nEND_PROGRAM\n",
        );
        let image = crate::compile_source(&source, "Main.st").unwrap();
        let status = image
            .types
            .iter()
            .find_map(|ty| match ty {
                program_image::TypeDef::Struct {
                    name,
                    size,
                    members,
                    ..
                } if name == MODBUS_DEVICE_STATUS => Some((*size, members)),
                _ => None,
            })
            .unwrap();
        let offsets: Vec<(&str, u32)> = status
            .1
            .iter()
            .map(|member| (member.name.as_str(), member.offset))
            .collect();
        assert_eq!(status.0, 32);
        assert_eq!(
            offsets,
            [
                ("xConnected", 0),
                ("xError", 1),
                ("eLastError", 2),
                ("byLastException", 3),
                ("udiConsecutiveErrors", 4),
                ("udiRequests", 8),
                ("udiErrors", 12),
                ("udiRounds", 16),
                ("udiOverruns", 20),
                ("ltLastResponseTime", 24),
            ]
        );
        let error_codes = status.1[2].ty as usize;
        assert!(matches!(
            &image.types[error_codes],
            program_image::TypeDef::Enum { name, base: program_image::Elementary::Usint, values }
                if name == "MB_ErrorCodes"
                    && values.contains(&("NOT_YET_POLLED".to_owned(), 0xC1))
        ));
    }

    #[test]
    fn a_project_s_own_modbus_status_type_takes_precedence() {
        let source = SourceProject::new(
            "TYPE MODBUS_DEVICE_STATUS :\nSTRUCT\n    iOwn : INT;\nEND_STRUCT\nEND_TYPE\n\
             PROGRAM Main\nVAR\n    stDrive : MODBUS_DEVICE_STATUS;\nEND_VAR\n\
             stDrive.iOwn := 1;\nEND_PROGRAM\n",
        );
        let image = crate::compile_source(&source, "Main.st").unwrap();
        assert!(image.types.iter().any(|ty| matches!(ty,
            program_image::TypeDef::Struct { name, size: 2, .. } if name == MODBUS_DEVICE_STATUS)));
    }

    #[test]
    fn the_motion_library_holds_the_function_blocks_the_issue_names() {
        for name in [
            "MC_Power",
            "MC_Home",
            "MC_Stop",
            "MC_Halt",
            "MC_Reset",
            "MC_MoveAbsolute",
            "MC_MoveRelative",
            "MC_MoveAdditive",
            "MC_MoveVelocity",
            "MC_Jog",
            "MC_SetPosition",
            "MC_ReadActualPosition",
            "MC_ReadActualVelocity",
            "MC_ReadStatus",
            "MC_ReadAxisError",
            "MC_CamTableSelect",
            "MC_CamIn",
            "MC_CamOut",
            "MC_GearIn",
            "MC_GearOut",
            "MC_GearInPos",
            "MC_Phasing",
            "SMC_CamRegister",
            "SMC_GetTappetValue",
            "SMC_GetCamSlaveSetPosition",
            "MC_DigitalCamSwitch",
        ] {
            assert!(is_native_block(name), "{name}");
        }
        assert!(!is_native_block("TON"));
    }
}
