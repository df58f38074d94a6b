//! Libraries every project sees without declaring them: today the motion library
//! (`motion.st`), the PLCopen and CODESYS SoftMotion function blocks and their types.
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

/// The text of the motion library.
const MOTION_SOURCE: &str = include_str!("motion.st");

/// The motion library as a project of its own, read on first use.
pub fn motion() -> &'static Project {
    static MOTION: OnceLock<Project> = OnceLock::new();
    MOTION.get_or_init(|| SourceProject::new(MOTION_SOURCE).project)
}

/// Every object of every library.
pub(crate) fn objects() -> Vec<&'static Object> {
    motion().application.objects()
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
        let source = SourceProject::new(MOTION_SOURCE);
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
