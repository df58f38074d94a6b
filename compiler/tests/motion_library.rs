//! The motion library's function blocks and types are known to the checker in every project:
//! axes of the device tree are `AXIS_REF` globals, cam tables `MC_CAM_REF` globals, and calls of
//! `MC_*` blocks are checked like calls of any function block.

#![allow(clippy::unwrap_used, clippy::expect_used)] // A panic is a failed test.

use std::path::Path;

use compiler::sema::check_project;
use project_model::{Body, Node, Object, Pou, PouKind, Project, VarSection, Variable};

/// The example project (two axes `Master` and `Knife`, the cam `CAM_Knife`) with one more
/// program whose variables and body are given.
fn example_with(variables: &[(&str, &str)], body: &str) -> Project {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../assets/examples/packaging_machine");
    let mut project = project_model::load_project(&dir).unwrap().project;
    let variables = variables
        .iter()
        .map(|(name, ty)| Variable {
            section: VarSection::Var,
            ..Variable::new(*name, *ty)
        })
        .collect();
    project
        .application
        .children
        .push(Node::Object(Object::Pou(Pou {
            variables,
            body: Body::st(body),
            ..pou("MotionTest", PouKind::Program)
        })));
    project
}

/// An empty POU.
fn pou(name: &str, kind: PouKind) -> Pou {
    Pou {
        name: name.into(),
        kind,
        return_type: None,
        extends: None,
        implements: Vec::new(),
        comment: String::new(),
        variables: Vec::new(),
        body: Body::st(""),
        methods: Vec::new(),
        properties: Vec::new(),
        actions: Vec::new(),
        transitions: Vec::new(),
    }
}

/// The errors of `project`, as `CODE: message`.
fn errors(project: &Project) -> Vec<String> {
    check_project(project)
        .into_iter()
        .filter(|found| found.diagnostic.severity == compiler::Severity::Error)
        .map(|found| {
            format!(
                "{}: {}",
                found.diagnostic.code.id(),
                found.diagnostic.message
            )
        })
        .collect()
}

#[test]
fn a_cam_coupling_written_as_in_codesys_type_checks() {
    let project = example_with(
        &[
            ("fbPower", "MC_Power"),
            ("fbMove", "MC_MoveAbsolute"),
            ("fbSelect", "MC_CamTableSelect"),
            ("fbCamIn", "MC_CamIn"),
            ("fbTappet", "SMC_GetTappetValue"),
            ("fbStatus", "MC_ReadStatus"),
            ("xGlue", "BOOL"),
            ("lrPosition", "LREAL"),
        ],
        "fbPower(Axis := Master, Enable := TRUE, bRegulatorOn := TRUE, bDriveStart := TRUE);
fbMove(Axis := Master, Execute := fbPower.Status, Position := 90.0, Velocity := 360.0,
    Acceleration := 3600.0, Deceleration := 3600.0, Direction := MC_DIRECTION.positive,
    BufferMode := MC_BUFFER_MODE.Aborting);
fbSelect(Master := Master, Slave := Knife, CamTable := CAM_Knife, Execute := TRUE,
    Periodic := TRUE, MasterAbsolute := TRUE, SlaveAbsolute := TRUE);
fbCamIn(Master := Master, Slave := Knife, Execute := fbSelect.Done,
    CamTableID := fbSelect.CamTableID, StartMode := MC_StartMode.absolute);
fbTappet(Tappets := fbCamIn.Tappets, iID := 1, bInitValue := FALSE);
xGlue := fbTappet.bTappet;
fbStatus(Axis := Knife, Enable := TRUE);
lrPosition := Knife.fActPosition;
IF Knife.nAxisState = SMC_AXIS_STATE.synchronized_motion AND CAM_Knife.xEnd > 0.0 THEN
    lrPosition := 0.0;
END_IF",
    );
    assert_eq!(errors(&project), Vec::<String>::new());
}

#[test]
fn mistakes_in_motion_calls_are_reported_like_any_call() {
    let project = example_with(
        &[("fbMove", "MC_MoveAbsolute"), ("iValue", "INT")],
        "fbMove(Axis := iValue, Execute := 1.5, Posiiton := 90.0);
fbMove(Axis := 5);
iValue := Master;",
    );
    let found = errors(&project);
    let expected = [
        "VAR_IN_OUT 'Axis' of 'fbMove' expects AXIS_REF, found INT",
        "input 'Execute' of 'fbMove' expects BOOL",
        "'fbMove' has no parameter 'Posiiton'; did you mean 'Position'?",
        "'Axis' of 'fbMove' is VAR_IN_OUT and needs a variable, not a value",
        "the assignment expects INT, found AXIS_REF",
    ];
    for part in expected {
        assert!(
            found.iter().any(|message| message.contains(part)),
            "no error mentions {part:?}: {found:#?}"
        );
    }
}

#[test]
fn a_project_may_declare_a_name_of_the_motion_library_itself() {
    let mut project = example_with(&[("fbOwn", "MC_Power")], "fbOwn(bOn := TRUE);");
    // The example's own motion program calls the library's MC_Power.
    project.application.children.retain(
        |node| !matches!(node, Node::Object(Object::Pou(pou)) if pou.name == "MotionControl"),
    );
    project.tasks.iter_mut().for_each(|task| {
        task.programs.retain(|program| program != "MotionControl");
    });
    project
        .application
        .children
        .push(Node::Object(Object::Pou(Pou {
            variables: vec![Variable {
                section: VarSection::VarInput,
                ..Variable::new("bOn", "BOOL")
            }],
            ..pou("MC_Power", PouKind::FunctionBlock)
        })));
    assert_eq!(errors(&project), Vec::<String>::new());
}
