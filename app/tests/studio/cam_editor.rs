//! Editing a cam table in the studio: the example's knife cam opens in the cam editor, a key
//! point typed into the cam table is one undo step that Ctrl+Z takes back, and "Add cam" adds
//! the cam CODESYS starts with.

use app::studio::StudioApp;
use egui::{Key, Modifiers, Role};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
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
