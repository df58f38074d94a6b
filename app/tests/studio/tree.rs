//! Editing the device tree and the task configuration through the studio's accessibility tree.

use std::path::Path;

use app::studio::{Settings, StudioApp, TreeNode};
use egui::{Key, Modifiers};
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT as _, Queryable as _};
use project_model::{Object, PouKind, Project, TaskKind};

/// A copy of the example project in a temporary folder, so saving cannot touch the original.
pub(super) fn example_copy() -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    assets::copy_example_project(dir.path()).unwrap();
    dir
}

pub(super) fn studio(project: &Path) -> Harness<'static, StudioApp> {
    let app = StudioApp::new(Settings::default(), Some(project.to_owned()));
    let mut harness = Harness::builder()
        .with_size([1280.0, 800.0])
        .build_ui_state(|ui, app: &mut StudioApp| app.ui(ui), app);
    harness.run();
    harness
}

pub(super) fn project<'h>(harness: &'h Harness<'_, StudioApp>) -> &'h Project {
    &harness.state().session().unwrap().project
}

pub(super) fn undo_label(harness: &Harness<'_, StudioApp>) -> Option<String> {
    let session = harness.state().session().unwrap();
    session.history.undo_label().map(str::to_owned)
}

/// Right-clicks the tree row labelled `row` and chooses `item` from its context menu.
pub(super) fn menu(harness: &mut Harness<'_, StudioApp>, row: &str, item: &str) {
    // Rows below the fold are scrolled into view first, as a user would.
    harness.get_by_label(row).scroll_to_me();
    harness.run();
    harness.get_by_label(row).click_secondary();
    harness.run();
    harness.get_by_label(item).click();
    harness.run();
}

/// Replaces the text of the field labelled `label` with `text`.
pub(super) fn set_text(harness: &mut Harness<'_, StudioApp>, label: &str, text: &str) {
    harness.get_by_label(label).click();
    harness.run();
    harness.key_press_modifiers(Modifiers::COMMAND, Key::A);
    harness.get_by_label(label).type_text(text);
    harness.run();
}

/// Types `text` into the field labelled `label` and commits it with Enter.
pub(super) fn enter_text(harness: &mut Harness<'_, StudioApp>, label: &str, text: &str) {
    set_text(harness, label, text);
    harness.key_press(Key::Enter);
    harness.run();
}

pub(super) fn shortcut(harness: &mut Harness<'_, StudioApp>, key: Key) {
    harness.key_press_modifiers(Modifiers::COMMAND, key);
    harness.run();
}

#[test]
fn a_pou_added_from_the_context_menu_opens_and_undo_and_redo_take_it_away_and_back() {
    let dir = example_copy();
    let mut harness = studio(dir.path());
    menu(&mut harness, "Application", "Add POU…");
    harness.get_by_label("Function block").click();
    harness.run();
    enter_text(&mut harness, "Name", "FB_Drive");

    let added = TreeNode::Object("FB_Drive".into());
    match project(&harness).application.object("FB_Drive") {
        Some(Object::Pou(pou)) => assert_eq!(pou.kind, PouKind::FunctionBlock),
        other => panic!("FB_Drive was not added as a function block: {other:?}"),
    }
    assert!(harness.state().open_documents().contains(&added));
    assert_eq!(
        undo_label(&harness).as_deref(),
        Some("Add function block FB_Drive")
    );

    shortcut(&mut harness, Key::Z);
    assert!(project(&harness).application.object("FB_Drive").is_none());
    assert!(!harness.state().open_documents().contains(&added));

    shortcut(&mut harness, Key::Y);
    assert!(project(&harness).application.object("FB_Drive").is_some());
}

#[test]
fn a_function_gets_its_return_type_from_the_dialog() {
    let dir = example_copy();
    let mut harness = studio(dir.path());
    menu(&mut harness, "Motion", "Add POU…");
    harness.get_by_label("Function").click();
    harness.run();
    set_text(&mut harness, "Name", "Scale");
    set_text(&mut harness, "Return type", "REAL");
    harness.get_by_label("OK").click();
    harness.run();
    match project(&harness).application.object("Scale") {
        Some(Object::Pou(pou)) => {
            assert_eq!(pou.kind, PouKind::Function);
            assert_eq!(pou.return_type.as_deref(), Some("REAL"));
        }
        other => panic!("Scale was not added as a function: {other:?}"),
    }
    assert_eq!(
        project(&harness).application.locate("Scale"),
        Some((vec!["Motion".to_owned()], 1))
    );
}

#[test]
fn a_rename_to_an_invalid_or_taken_name_is_refused_with_the_reason_and_a_valid_one_renames() {
    let dir = example_copy();
    let mut harness = studio(dir.path());
    menu(&mut harness, "FB_Conveyor", "Rename");

    enter_text(&mut harness, "Name", "1Belt");
    assert!(
        harness
            .query_by_label_contains("'1Belt' is not a valid name")
            .is_some()
    );
    // Enter did not close the dialog or change anything.
    assert!(harness.query_by_label("OK").is_some());
    assert!(
        project(&harness)
            .application
            .object("FB_Conveyor")
            .is_some()
    );

    set_text(&mut harness, "Name", "main");
    assert!(
        harness
            .query_by_label_contains("the name 'main' is already used")
            .is_some()
    );

    set_text(&mut harness, "Name", "FB_Belt");
    assert!(harness.query_by_label_contains("already used").is_none());
    harness.get_by_label("OK").click();
    harness.run();
    assert!(
        project(&harness)
            .application
            .object("FB_Conveyor")
            .is_none()
    );
    assert!(project(&harness).application.object("FB_Belt").is_some());
    assert_eq!(
        undo_label(&harness).as_deref(),
        Some("Rename FB_Conveyor to FB_Belt")
    );
    assert!(
        harness.query_by_label("OK").is_none(),
        "the dialog stayed open"
    );
}

#[test]
fn renaming_a_program_renames_its_task_calls_in_the_same_undo_step() {
    let dir = example_copy();
    let mut harness = studio(dir.path());
    menu(&mut harness, "Sequence", "Rename");
    enter_text(&mut harness, "Name", "MachineSequence");
    let main_task = project(&harness).task("MainTask").unwrap();
    assert_eq!(
        main_task.programs,
        [
            "Main",
            "MachineSequence",
            "Interlock",
            "Scaling",
            "PackCycle",
            "TempControl"
        ]
    );
    shortcut(&mut harness, Key::Z);
    let main_task = project(&harness).task("MainTask").unwrap();
    assert_eq!(
        main_task.programs,
        [
            "Main",
            "Sequence",
            "Interlock",
            "Scaling",
            "PackCycle",
            "TempControl"
        ]
    );
    assert!(project(&harness).application.object("Sequence").is_some());
}

#[test]
fn renaming_a_task_carries_into_its_axes_and_traces_in_the_same_undo_step() {
    let dir = example_copy();
    let mut harness = studio(dir.path());
    menu(&mut harness, "MotionTask", "Rename");
    enter_text(&mut harness, "Name", "Motion");
    let project_now = project(&harness);
    assert!(project_now.task("Motion").is_some());
    // The example has two axes in the task, so the checks below cannot pass on no axes.
    assert_eq!(project_now.axes.len(), 2);
    assert!(project_now.axes.iter().all(|axis| axis.task == "Motion"));
    let trace_task = |project: &Project| match project.application.object("TRC_Knife") {
        Some(Object::Trace(trace)) => trace.task.clone(),
        _ => String::new(),
    };
    assert_eq!(trace_task(project_now), "Motion");
    shortcut(&mut harness, Key::Z);
    let project_now = project(&harness);
    assert_eq!(project_now.axes.len(), 2);
    assert!(
        project_now
            .axes
            .iter()
            .all(|axis| axis.task == "MotionTask")
    );
    assert_eq!(trace_task(project_now), "MotionTask");
}

#[test]
fn duplicate_puts_a_copy_next_to_the_original_and_delete_removes_nodes() {
    let dir = example_copy();
    let mut harness = studio(dir.path());
    let (folder, index) = project(&harness).application.locate("GVL_IO").unwrap();
    menu(&mut harness, "GVL_IO", "Duplicate");
    assert_eq!(
        project(&harness).application.locate("GVL_IO_1"),
        Some((folder, index + 1))
    );
    let copy = project(&harness).application.object("GVL_IO_1").cloned();
    let original = project(&harness).application.object("GVL_IO").cloned();
    match (copy, original) {
        (Some(Object::Gvl(copy)), Some(Object::Gvl(original))) => {
            assert_eq!(copy.variables, original.variables);
        }
        other => panic!("the copy is not a global variable list: {other:?}"),
    }

    // The Delete key deletes the selected node, without asking: it can be undone.
    harness.get_by_label("GVL_IO_1 *").click();
    harness.run();
    harness.key_press(Key::Delete);
    harness.run();
    assert!(project(&harness).application.object("GVL_IO_1").is_none());

    menu(&mut harness, "MotionTask", "Duplicate");
    assert_eq!(
        project(&harness)
            .tasks
            .iter()
            .map(|task| task.name.as_str())
            .collect::<Vec<_>>(),
        ["MainTask", "MotionTask", "MotionTask_1"]
    );
    menu(&mut harness, "Master", "Delete");
    assert!(
        project(&harness)
            .axes
            .iter()
            .all(|axis| axis.name != "Master")
    );
    assert_eq!(undo_label(&harness).as_deref(), Some("Delete Master"));
    shortcut(&mut harness, Key::Z);
    assert!(
        project(&harness)
            .axes
            .iter()
            .any(|axis| axis.name == "Master")
    );
}

#[test]
fn dragging_an_object_onto_a_folder_moves_it_in() {
    let dir = example_copy();
    let mut harness = studio(dir.path());
    let from = harness.get_by_label("FB_Conveyor").rect().center();
    let to = harness.get_by_label("Motion").rect().center();
    harness.hover_at(from);
    harness.run();
    harness.drag_at(from);
    harness.step();
    harness.hover_at(from + egui::vec2(0.0, 12.0));
    harness.step();
    harness.hover_at(to);
    harness.step();
    harness.step();
    harness.drop_at(to);
    harness.run();
    assert_eq!(
        project(&harness).application.locate("FB_Conveyor"),
        Some((vec!["Motion".to_owned()], 1))
    );
    assert_eq!(
        undo_label(&harness).as_deref(),
        Some("Move FB_Conveyor into Motion")
    );
}

#[test]
fn dirty_markers_follow_edits_and_disappear_when_saved() {
    let dir = example_copy();
    let mut harness = studio(dir.path());
    let marked = |harness: &Harness<'_, StudioApp>| {
        harness
            .query_all_by_label_contains(" *")
            .filter_map(|node| node.accesskit_node().label())
            .collect::<Vec<_>>()
    };
    assert!(marked(&harness).is_empty());
    menu(&mut harness, "Diagnostics", "Add global variable list");
    // The new list and the folder that holds it differ from the saved project; nothing else.
    let mut dirty = marked(&harness);
    dirty.sort();
    assert_eq!(dirty, ["Diagnostics *", "GVL *"]);

    shortcut(&mut harness, Key::S);
    assert!(marked(&harness).is_empty());
    assert!(harness.query_all_by_label("GVL").next().is_some());
    assert!(
        dir.path()
            .join("application/Diagnostics/GVL.gvl.toml")
            .exists()
    );
}

#[test]
fn the_task_editor_changes_interval_priority_and_calls_and_refuses_bad_values() {
    let dir = example_copy();
    let mut harness = studio(dir.path());
    harness.get_by_label("Task configuration").focus();
    harness.run();
    harness.key_press(Key::Enter);
    harness.run();
    assert!(
        harness
            .state()
            .open_documents()
            .contains(&TreeNode::TaskConfiguration)
    );

    enter_text(&mut harness, "Interval of MainTask", "T#5ms");
    let task = project(&harness).task("MainTask").unwrap();
    assert_eq!(task.kind, TaskKind::Cyclic { interval_us: 5000 });
    assert_eq!(
        undo_label(&harness).as_deref(),
        Some("Set interval of MainTask to T#5ms")
    );

    enter_text(&mut harness, "Priority of MainTask", "40");
    assert!(
        harness
            .query_by_label_contains("'40' is not a priority")
            .is_some()
    );
    assert_eq!(project(&harness).task("MainTask").unwrap().priority, 1);

    enter_text(&mut harness, "Priority of MainTask", "3");
    assert_eq!(project(&harness).task("MainTask").unwrap().priority, 3);
    assert!(
        harness
            .query_by_label_contains("is not a priority")
            .is_none()
    );

    enter_text(&mut harness, "Interval of MainTask", "0");
    assert!(harness.query_by_label_contains("longer than 0").is_some());
    assert_eq!(
        project(&harness).task("MainTask").unwrap().kind,
        TaskKind::Cyclic { interval_us: 5000 }
    );

    set_text(&mut harness, "Program to call", "Missing");
    harness.get_by_label("Add call").click();
    harness.run();
    assert!(
        harness
            .query_by_label_contains("no PROGRAM named 'Missing'")
            .is_some()
    );
    set_text(&mut harness, "Program to call", "MotionControl");
    harness.get_by_label("Add call").click();
    harness.run();
    assert_eq!(
        project(&harness).task("MainTask").unwrap().programs,
        [
            "Main",
            "Sequence",
            "Interlock",
            "Scaling",
            "PackCycle",
            "TempControl",
            "MotionControl"
        ]
    );
    harness.get_by_label("Move up MotionControl").click();
    harness.run();
    assert_eq!(
        project(&harness).task("MainTask").unwrap().programs,
        [
            "Main",
            "Sequence",
            "Interlock",
            "Scaling",
            "PackCycle",
            "MotionControl",
            "TempControl"
        ]
    );

    enter_text(&mut harness, "Name of MainTask", "MotionTask");
    assert!(
        harness
            .query_by_label_contains("the name 'MotionTask' is already used")
            .is_some()
    );
    assert!(project(&harness).task("MainTask").is_some());
}

#[test]
fn renaming_a_task_in_the_task_editor_carries_into_its_axes_and_traces_in_one_undo_step() {
    let dir = example_copy();
    let mut harness = studio(dir.path());
    harness.state_mut().open(TreeNode::TaskConfiguration);
    harness.run();
    enter_text(&mut harness, "Name of MotionTask", "Motion");
    let project_now = project(&harness);
    assert!(project_now.task("MotionTask").is_none());
    assert!(project_now.task("Motion").is_some());
    assert_eq!(project_now.axes.len(), 2);
    assert!(project_now.axes.iter().all(|axis| axis.task == "Motion"));
    let trace_task = |project: &Project| match project.application.object("TRC_Knife") {
        Some(Object::Trace(trace)) => trace.task.clone(),
        _ => String::new(),
    };
    assert_eq!(trace_task(project_now), "Motion");

    shortcut(&mut harness, Key::Z);
    let project_now = project(&harness);
    assert!(project_now.task("MotionTask").is_some());
    assert_eq!(project_now.axes.len(), 2);
    assert!(
        project_now
            .axes
            .iter()
            .all(|axis| axis.task == "MotionTask")
    );
    assert_eq!(trace_task(project_now), "MotionTask");
}

#[test]
fn a_task_made_an_event_task_asks_for_its_trigger_and_takes_it() {
    let dir = example_copy();
    let mut harness = studio(dir.path());
    harness.get_by_label("MotionTask").focus();
    harness.run();
    harness.key_press(Key::Enter);
    harness.run();
    harness.get_by_label("Kind of MotionTask").click();
    harness.run();
    harness.get_by_label("Event").click();
    harness.run();
    assert_eq!(
        project(&harness).task("MotionTask").unwrap().kind,
        TaskKind::Event {
            trigger: String::new()
        }
    );
    assert!(
        harness
            .query_by_label_contains("BOOL variable whose rising edge")
            .is_some()
    );
    // An interval means nothing to an event task, so it has no interval field.
    assert!(harness.query_by_label("Interval of MotionTask").is_none());

    enter_text(
        &mut harness,
        "Trigger variable of MotionTask",
        "GVL_IO.x Start",
    );
    assert!(
        harness
            .query_by_label_contains("is not a variable")
            .is_some()
    );
    enter_text(
        &mut harness,
        "Trigger variable of MotionTask",
        "GVL_IO.xStart",
    );
    assert_eq!(
        project(&harness).task("MotionTask").unwrap().kind,
        TaskKind::Event {
            trigger: "GVL_IO.xStart".into()
        }
    );
    assert_eq!(
        undo_label(&harness).as_deref(),
        Some("Set trigger of MotionTask to GVL_IO.xStart")
    );
}

#[test]
fn the_tree_menus_dialogs_and_task_editor_speak_chinese_when_chosen() {
    let dir = example_copy();
    let settings = Settings {
        language: app::studio::Language::SimplifiedChinese,
        ..Settings::default()
    };
    let app = StudioApp::new(settings, Some(dir.path().to_owned()));
    let mut harness = Harness::builder()
        .with_size([1280.0, 800.0])
        .build_ui_state(|ui, app: &mut StudioApp| app.ui(ui), app);
    harness.run();
    menu(&mut harness, "应用", "添加 POU…");
    assert!(harness.query_by_label("功能块").is_some());
    harness.get_by_label("取消").click();
    harness.run();
    assert!(project(&harness).application.object("POU").is_none());

    harness.get_by_label("任务配置").focus();
    harness.run();
    harness.key_press(Key::Enter);
    harness.run();
    assert!(harness.query_by_label("MainTask 的优先级").is_some());
    assert!(harness.query_by_label("添加任务").is_some());
}
