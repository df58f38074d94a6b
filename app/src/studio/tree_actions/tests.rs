//! Plans checked against the example project, by applying their edits.

use project_model::{Body, Edit, Network, Object, PouKind, Project, TextTarget, load_project};

use super::members::NewMember;
use super::{BodyLanguage, DropPlace, ListKind, MemberKind, NewObject, Refusal, TreeAction, plan};
use crate::studio::i18n::Language;
use crate::studio::tree_node::TreeNode;

fn example() -> Project {
    load_project(&assets::example_project_dir())
        .unwrap()
        .project
}

/// Plans `action` on `project` and applies the plan's edits; returns the plan's label.
fn apply(project: &mut Project, action: TreeAction) -> String {
    let plan = plan(project, &action, Language::English).unwrap().unwrap();
    Edit::Group(plan.edits).apply(project).unwrap();
    plan.label
}

fn names(project: &Project, folder: &[String]) -> Vec<String> {
    project
        .application
        .folder(folder)
        .unwrap()
        .children
        .iter()
        .map(|node| node.name().to_owned())
        .collect()
}

#[test]
fn a_drop_before_or_after_a_node_of_the_same_folder_lands_there() {
    let mut project = example();
    let label = apply(
        &mut project,
        TreeAction::Move {
            node: TreeNode::Object("Main".into()),
            target: TreeNode::Object("Sequence".into()),
            place: DropPlace::After,
        },
    );
    assert_eq!(label, "Move Main after Sequence");
    assert_eq!(
        names(&project, &[])[..4],
        ["FB_Conveyor", "Sequence", "Main", "MotionControl"]
    );
    apply(
        &mut project,
        TreeAction::Move {
            node: TreeNode::Object("Main".into()),
            target: TreeNode::Object("FB_Conveyor".into()),
            place: DropPlace::Before,
        },
    );
    assert_eq!(names(&project, &[])[..2], ["Main", "FB_Conveyor"]);
    // Dropping a node where it already is changes nothing.
    let unchanged = TreeAction::Move {
        node: TreeNode::Object("Main".into()),
        target: TreeNode::Object("FB_Conveyor".into()),
        place: DropPlace::Before,
    };
    assert_eq!(plan(&project, &unchanged, Language::English), Ok(None));
}

#[test]
fn a_folder_cannot_be_dropped_into_its_own_contents() {
    let project = example();
    let into_itself = TreeAction::Move {
        node: TreeNode::Folder(vec!["Motion".into()]),
        target: TreeNode::Object("CAM_Knife".into()),
        place: DropPlace::Before,
    };
    assert!(plan(&project, &into_itself, Language::English).is_err());
}

#[test]
fn list_entries_reorder_and_duplicate_within_their_list() {
    let mut project = example();
    apply(
        &mut project,
        TreeAction::Move {
            node: TreeNode::Task("MainTask".into()),
            target: TreeNode::Task("MotionTask".into()),
            place: DropPlace::After,
        },
    );
    assert_eq!(ListKind::Tasks.names(&project), ["MotionTask", "MainTask"]);
    let label = apply(
        &mut project,
        TreeAction::Duplicate(TreeNode::ModbusDevice("BeltDrive".into())),
    );
    assert_eq!(label, "Duplicate BeltDrive as BeltDrive_1");
    assert_eq!(
        ListKind::ModbusDevices.names(&project),
        ["BeltDrive", "BeltDrive_1"]
    );
}

#[test]
fn a_serial_port_is_deleted_only_when_no_device_names_it() {
    let mut project = example();
    project
        .serial_ports
        .push(project_model::SerialPort::new("RS485", "/dev/ttyUSB0"));
    let mut drive = project.modbus_devices[0].clone();
    drive.link = project_model::ModbusLink::Rtu {
        serial_port: "rs485".into(),
    };
    let mut meter = drive.clone();
    meter.name = "Meter".into();
    project.modbus_devices = vec![drive.clone(), meter];
    let delete = TreeAction::Delete(TreeNode::SerialPort("RS485".into()));
    let Err(refusal) = plan(&project, &delete, Language::English) else {
        panic!("a port two devices name was deleted");
    };
    assert_eq!(
        refusal,
        Refusal::SerialPortInUse("RS485".into(), vec!["BeltDrive".into(), "Meter".into()])
    );
    assert!(
        refusal
            .text(Language::SimplifiedChinese)
            .contains("BeltDrive、Meter")
    );
    // Once the devices are gone, the port goes.
    project.modbus_devices.clear();
    apply(&mut project, delete);
    assert!(project.serial_ports.is_empty());
}

#[test]
fn a_duplicated_folder_gives_every_object_in_it_a_new_name() {
    let mut project = example();
    apply(
        &mut project,
        TreeAction::Duplicate(TreeNode::Folder(vec!["Diagnostics".into()])),
    );
    assert_eq!(
        names(&project, &["Diagnostics_1".into()]),
        ["TRC_Conveyor_1", "TRC_Knife_1", "WATCH_Machine_1"]
    );
    assert!(matches!(
        project.application.object("TRC_Conveyor"),
        Some(Object::Trace(_))
    ));
}

#[test]
fn new_objects_get_the_next_free_default_name() {
    let mut project = example();
    for _ in 0..2 {
        apply(
            &mut project,
            TreeAction::AddObject {
                folder: Vec::new(),
                kind: NewObject::WatchList,
            },
        );
    }
    assert!(project.application.object("Watch").is_some());
    assert!(project.application.object("Watch_1").is_some());
}

fn pou<'p>(project: &'p Project, name: &str) -> &'p project_model::Pou {
    match project.application.object(name) {
        Some(Object::Pou(pou)) => pou,
        other => panic!("{name} is not a POU: {other:?}"),
    }
}

fn member(kind: MemberKind, name: &str, language: BodyLanguage, type_name: &str) -> NewMember {
    NewMember {
        kind,
        name: name.to_owned(),
        language,
        type_name: type_name.to_owned(),
    }
}

#[test]
fn a_pou_added_in_ld_or_fbd_starts_with_one_empty_network_and_in_st_with_no_text() {
    let mut project = example();
    for (name, language) in [
        ("PRG_Ladder", BodyLanguage::Ld),
        ("FB_Blocks", BodyLanguage::Fbd),
        ("PRG_Text", BodyLanguage::St),
    ] {
        apply(
            &mut project,
            TreeAction::AddPou {
                folder: Vec::new(),
                kind: PouKind::Program,
                name: name.to_owned(),
                return_type: None,
                language,
            },
        );
    }
    let one_empty_network = [Network::default()];
    assert!(matches!(
        &pou(&project, "PRG_Ladder").body,
        Body::Ld { networks } if networks == &one_empty_network
    ));
    assert!(matches!(
        &pou(&project, "FB_Blocks").body,
        Body::Fbd { networks } if networks == &one_empty_network
    ));
    assert_eq!(pou(&project, "PRG_Text").body, Body::st(""));
}

#[test]
fn a_program_added_in_sfc_starts_as_codesys_starts_one_and_a_function_cannot_be_sfc() {
    let mut project = example();
    apply(
        &mut project,
        TreeAction::AddPou {
            folder: Vec::new(),
            kind: PouKind::Program,
            name: "PRG_Steps".to_owned(),
            return_type: None,
            language: BodyLanguage::Sfc,
        },
    );
    assert!(matches!(
        &pou(&project, "PRG_Steps").body,
        Body::Sfc { chart } if chart == &project_model::SfcChart::new_body()
    ));
    let function = TreeAction::AddPou {
        folder: Vec::new(),
        kind: PouKind::Function,
        name: "F_Steps".to_owned(),
        return_type: Some("BOOL".to_owned()),
        language: BodyLanguage::Sfc,
    };
    let refusal = plan(&project, &function, Language::English).unwrap_err();
    assert_eq!(
        refusal.text(Language::English),
        "only a program or function block itself can be a Sequential Function Chart"
    );
    let action = TreeAction::AddMember {
        pou: "FB_Conveyor".into(),
        member: member(MemberKind::Action, "Steps", BodyLanguage::Sfc, ""),
    };
    assert!(matches!(
        plan(&project, &action, Language::English),
        Err(Refusal::SfcNotHere)
    ));
}

#[test]
fn a_method_is_added_to_a_function_block_as_one_edit_that_undo_takes_back() {
    let mut project = example();
    let before = project.clone();
    let action = TreeAction::AddMember {
        pou: "FB_Conveyor".into(),
        member: member(MemberKind::Method, "Jog", BodyLanguage::Ld, " REAL "),
    };
    let plan = plan(&project, &action, Language::English).unwrap().unwrap();
    assert_eq!(plan.label, "Add method Jog to FB_Conveyor");
    assert_eq!(plan.edits.len(), 1);
    assert_eq!(plan.open, Some(TreeNode::Object("FB_Conveyor".into())));
    assert_eq!(
        plan.part,
        Some(TextTarget::Method {
            pou: "FB_Conveyor".into(),
            method: "Jog".into()
        })
    );
    let inverse = Edit::Group(plan.edits).apply(&mut project).unwrap();
    let method = pou(&project, "FB_Conveyor").methods.last().unwrap();
    assert_eq!(method.name, "Jog");
    assert_eq!(method.return_type.as_deref(), Some("REAL"));
    assert_eq!(
        method.body,
        Body::Ld {
            networks: vec![Network::default()]
        }
    );
    inverse.apply(&mut project).unwrap();
    assert_eq!(project, before);
}

#[test]
fn actions_and_properties_get_their_bodies_in_the_chosen_language() {
    let mut project = example();
    let label = apply(
        &mut project,
        TreeAction::AddMember {
            pou: "Main".into(),
            member: member(MemberKind::Action, "Clean", BodyLanguage::Fbd, "ignored"),
        },
    );
    assert_eq!(label, "Add action Clean to Main");
    apply(
        &mut project,
        TreeAction::AddMember {
            pou: "FB_Conveyor".into(),
            member: member(MemberKind::Property, "Speed", BodyLanguage::St, "LREAL"),
        },
    );
    apply(
        &mut project,
        TreeAction::AddMember {
            pou: "FB_Conveyor".into(),
            member: member(MemberKind::Method, "Stop", BodyLanguage::St, ""),
        },
    );
    let action = pou(&project, "Main").actions.last().unwrap();
    assert_eq!(action.name, "Clean");
    assert_eq!(action.body.language(), project_model::Language::Fbd);
    let fb = pou(&project, "FB_Conveyor");
    let property = fb.properties.last().unwrap();
    assert_eq!(
        (property.name.as_str(), property.ty.as_str()),
        ("Speed", "LREAL")
    );
    for accessor in [&property.get, &property.set] {
        assert_eq!(accessor.as_ref().map(|a| &a.body), Some(&Body::st("")));
    }
    // An empty return type makes a method that returns nothing.
    assert_eq!(fb.methods.last().unwrap().return_type, None);
}

#[test]
fn member_names_are_refused_when_they_clash_without_case_or_are_no_identifiers() {
    let project = example();
    let refusal = |name: &str| {
        let action = TreeAction::AddMember {
            pou: "FB_Conveyor".into(),
            member: member(MemberKind::Action, name, BodyLanguage::St, ""),
        };
        plan(&project, &action, Language::English)
            .err()
            .map(|refusal| refusal.text(Language::English))
    };
    // `Reset` is a method and `xStart` a variable of FB_Conveyor.
    assert_eq!(
        refusal("RESET").as_deref(),
        Some("the name 'RESET' is already used")
    );
    assert_eq!(
        refusal("xstart").as_deref(),
        Some("the name 'xstart' is already used")
    );
    assert!(refusal("2nd").is_some_and(|text| text.contains("not a valid name")));
    assert!(refusal("while").is_some_and(|text| text.contains("keyword")));
    assert_eq!(refusal("").as_deref(), Some("enter a name"));
    assert_eq!(refusal("Jog"), None);
}

#[test]
fn functions_take_no_members_and_a_property_needs_a_type() {
    let mut project = example();
    apply(
        &mut project,
        TreeAction::AddPou {
            folder: Vec::new(),
            kind: PouKind::Function,
            name: "Scale".into(),
            return_type: Some("REAL".into()),
            language: BodyLanguage::St,
        },
    );
    let in_function = TreeAction::AddMember {
        pou: "Scale".into(),
        member: member(MemberKind::Method, "Inner", BodyLanguage::St, ""),
    };
    assert_eq!(
        plan(&project, &in_function, Language::English),
        Err(Refusal::NoMembers("Scale".into()))
    );
    let untyped = TreeAction::AddMember {
        pou: "FB_Conveyor".into(),
        member: member(MemberKind::Property, "Speed", BodyLanguage::St, " "),
    };
    assert_eq!(
        plan(&project, &untyped, Language::English),
        Err(Refusal::NoPropertyType)
    );
}

#[test]
fn a_transition_is_added_to_a_program_opened_on_its_body_and_its_name_clashes_with_members() {
    let mut project = example();
    let before = project.clone();
    let action = TreeAction::AddMember {
        pou: "Main".into(),
        member: member(MemberKind::Transition, "Ready", BodyLanguage::Ld, "ignored"),
    };
    let added = plan(&project, &action, Language::English).unwrap().unwrap();
    assert_eq!(added.label, "Add transition Ready to Main");
    assert_eq!(added.open, Some(TreeNode::Object("Main".into())));
    assert_eq!(
        added.part,
        Some(TextTarget::Transition {
            pou: "Main".into(),
            transition: "Ready".into()
        })
    );
    let inverse = Edit::Group(added.edits).apply(&mut project).unwrap();
    let transition = pou(&project, "Main").transitions.last().unwrap();
    assert_eq!(transition.name, "Ready");
    assert_eq!(
        transition.body,
        Body::Ld {
            networks: vec![Network::default()]
        }
    );
    // Transitions share the namespace of the other members, both ways.
    for (kind, name) in [
        (MemberKind::Action, "READY"),
        (MemberKind::Transition, "ready"),
    ] {
        let clash = TreeAction::AddMember {
            pou: "Main".into(),
            member: member(kind, name, BodyLanguage::St, ""),
        };
        assert_eq!(
            plan(&project, &clash, Language::English)
                .err()
                .map(|refusal| refusal.text(Language::English)),
            Some(format!("the name '{name}' is already used"))
        );
    }
    // A transition cannot be a chart of its own, nor belong to a function.
    let in_sfc = TreeAction::AddMember {
        pou: "Main".into(),
        member: member(MemberKind::Transition, "Done", BodyLanguage::Sfc, ""),
    };
    assert_eq!(
        plan(&project, &in_sfc, Language::English),
        Err(Refusal::SfcNotHere)
    );
    assert!(!MemberKind::Transition.allowed_in(PouKind::Function));
    inverse.apply(&mut project).unwrap();
    assert_eq!(project, before);
}
