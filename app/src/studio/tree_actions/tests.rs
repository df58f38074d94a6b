//! Plans checked against the example project, by applying their edits.

use project_model::{Edit, Object, Project, load_project};

use super::{DropPlace, ListKind, NewObject, TreeAction, plan};
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
