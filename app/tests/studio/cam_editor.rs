//! Editing a cam table in the studio: the example's knife cam opens in the cam editor, a key
//! point typed into the cam table is one undo step that Ctrl+Z takes back, and "Add cam" adds
//! the cam CODESYS starts with.

use app::studio::StudioApp;
use egui::{Key, Modifiers, Role};
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT as _, Queryable as _};
use project_model::{CamProfile, CamTable, Object};

use crate::support::{example_copy, studio};

fn cam(app: &StudioApp, name: &str) -> Option<CamTable> {
    match app.session().unwrap().project.application.object(name) {
        Some(Object::CamTable(cam)) => Some(cam.clone()),
        _ => None,
    }
}

fn second_key_point_slave(cam: &CamTable) -> f64 {
    match &cam.profile {
        CamProfile::Segments { segments, .. } => segments[0].end.slave,
        CamProfile::Points { .. } => panic!("CAM_Knife is a cam of segments"),
    }
}

/// Opens the tree node labelled `name` as a double-click would, with Enter.
fn open(harness: &mut Harness<'_, StudioApp>, name: &str) {
    harness.get_by_label(name).scroll_to_me();
    harness.step();
    harness.get_by_label(name).focus();
    harness.step();
    harness.key_press(Key::Enter);
    harness.step();
    harness.step();
}

#[test]
fn a_key_point_edited_in_the_cam_table_is_one_undo_step() {
    let project = example_copy(|_| {});
    let mut harness = studio(project.path());
    let original = cam(harness.state(), "CAM_Knife").unwrap();
    open(&mut harness, "CAM_Knife");
    harness.get_by_label("Cam table").click();
    harness.step();
    harness.step();
    let field = "Key point 2 Y";
    harness
        .get_by_role_and_label(Role::TextInput, field)
        .focus();
    harness.step();
    harness.key_press_modifiers(Modifiers::COMMAND, Key::A);
    harness
        .get_by_role_and_label(Role::TextInput, field)
        .type_text("75");
    harness.step();
    harness.key_press(Key::Enter);
    harness.step();
    harness.step();
    let edited = cam(harness.state(), "CAM_Knife").unwrap();
    assert_eq!(second_key_point_slave(&edited), 75.0);
    assert_eq!(
        harness.state().session().unwrap().history.undo_label(),
        Some("CAM_Knife: Key point 2 Y")
    );

    harness.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    harness.step();
    harness.step();
    assert_eq!(cam(harness.state(), "CAM_Knife").unwrap(), original);
    // The table shows the model's value again.
    let shown = harness
        .get_by_role_and_label(Role::TextInput, field)
        .value()
        .unwrap_or_default();
    assert_eq!(shown, "60");
}

#[test]
fn add_cam_adds_the_codesys_default_cam() {
    let project = example_copy(|_| {});
    let mut harness = studio(project.path());
    harness.get_by_label("Application").click_secondary();
    harness.step();
    harness.step();
    harness.get_by_label("Add cam").click();
    harness.step();
    harness.step();
    let added = cam(harness.state(), "CAM").expect("a cam named CAM");
    assert_eq!(added, CamTable::codesys_default("CAM"));
}

#[test]
fn logged_in_the_cam_shows_where_the_running_coupling_is() {
    // The master turns from the start, without the machine's start button.
    let project = example_copy(|dir| {
        crate::support::replace_in(
            dir,
            "application/MotionControl.st",
            "xRunning := GVL_Machine.eMachineState = E_MachineState.Running;",
            "xRunning := TRUE;",
        );
    });
    let mut harness = studio(project.path());
    crate::support::login_with_download(&mut harness);
    harness.key_press(Key::F5);
    open(&mut harness, "CAM_Knife");
    // The runtime writes the coupling into CAM_Knife's MC_CAM_REF every cycle; the editor
    // shows it once the studio has read it, and the master moves on.
    let start = std::time::Instant::now();
    let moving = loop {
        harness.step();
        let shown = harness
            .query_all_by_label_contains("Online: master ")
            .next()
            // A label's text is its accessible value.
            .and_then(|node| node.accesskit_node().value());
        if let Some(label) = shown
            && !label.starts_with("Online: master 0.000")
        {
            break label;
        }
        assert!(
            start.elapsed() < std::time::Duration::from_secs(20),
            "no live position on the cam: {:?}, {:?}",
            harness.state().online().value("CAM_Knife.fMasterPosition"),
            harness
                .state()
                .online()
                .problem("CAM_Knife.fMasterPosition"),
        );
        std::thread::sleep(std::time::Duration::from_millis(20));
    };
    assert!(moving.contains(", slave "), "{moving}");
}
