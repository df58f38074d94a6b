//! Unsaved changes survive the studio closing without a save: they are offered back when the
//! project opens again, and a save or a discard removes the copy.

use std::path::Path;

use crate::support::{example_copy, show_tab, wait_until, watch};
use app::studio::{Recovery, Settings, StudioApp, StudioOptions};
use egui::{Key, Modifiers};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use project_model::Object;

fn studio_with_recovery(project: &Path, recovery: &Path) -> Harness<'static, StudioApp> {
    let app = StudioApp::with_options(StudioOptions {
        settings: Settings::default(),
        layout: None,
        project: Some(project.to_owned()),
        recovery: Some(Recovery::new(recovery.to_owned())),
    });
    let mut harness = Harness::builder()
        .with_size([1400.0, 900.0])
        .build_ui_state(|ui, app: &mut StudioApp| app.ui(ui), app);
    harness.step();
    harness
}

fn entries_of(project: &project_model::Project) -> Vec<String> {
    match project.application.object("WATCH_Machine") {
        Some(Object::WatchList(list)) => list.entries.iter().map(|e| e.path.clone()).collect(),
        _ => Vec::new(),
    }
}

fn watch_entries(app: &StudioApp) -> Vec<String> {
    entries_of(&app.session().unwrap().project)
}

fn entries_on_disk(dir: &Path) -> Vec<String> {
    entries_of(&project_model::load_project(dir).unwrap().project)
}

#[test]
fn unsaved_changes_are_offered_back_after_the_studio_closed_without_saving() {
    let project = example_copy(|_| {});
    let recovery_dir = tempfile::tempdir().unwrap();
    let recovery = Recovery::new(recovery_dir.path().to_owned());

    // An edit, then the studio goes away without saving (as in a crash).
    {
        let mut harness = studio_with_recovery(project.path(), recovery_dir.path());
        show_tab(&mut harness, "Watch");
        watch(&mut harness, "Main.rtrigPackage.Q");
        assert!(watch_entries(harness.state()).contains(&"Main.rtrigPackage.Q".to_owned()));
        wait_until(&mut harness, "the recovery copy", |_| {
            recovery.find(project.path()).is_some()
        });
    }
    // The files on disk were not touched.
    assert!(!entries_on_disk(project.path()).contains(&"Main.rtrigPackage.Q".to_owned()));

    // Opening the project again offers the changes; recovering them makes the project dirty.
    let mut harness = studio_with_recovery(project.path(), recovery_dir.path());
    harness.step();
    assert!(harness.query_by_label("Recover").is_some());
    harness.get_by_label("Recover").click();
    harness.step();
    harness.step();
    assert!(watch_entries(harness.state()).contains(&"Main.rtrigPackage.Q".to_owned()));
    assert!(harness.state().session().unwrap().history.is_dirty());
    // The recovery is one undo step.
    harness.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    harness.step();
    assert!(!watch_entries(harness.state()).contains(&"Main.rtrigPackage.Q".to_owned()));
    harness.key_press_modifiers(Modifiers::COMMAND, Key::Y);
    harness.step();
    assert!(watch_entries(harness.state()).contains(&"Main.rtrigPackage.Q".to_owned()));

    // Saving writes the project and removes the copy.
    harness.key_press_modifiers(Modifiers::COMMAND, Key::S);
    harness.step();
    harness.step();
    assert!(!harness.state().session().unwrap().history.is_dirty());
    assert!(recovery.find(project.path()).is_none());
    assert!(entries_on_disk(project.path()).contains(&"Main.rtrigPackage.Q".to_owned()));
}

#[test]
fn discarded_changes_are_not_offered_again() {
    let project = example_copy(|_| {});
    let recovery_dir = tempfile::tempdir().unwrap();
    let recovery = Recovery::new(recovery_dir.path().to_owned());
    let mut changed = project_model::load_project(project.path()).unwrap().project;
    changed.description = "changed in a session that crashed".to_owned();
    recovery.write(project.path(), &changed).unwrap();

    let mut harness = studio_with_recovery(project.path(), recovery_dir.path());
    harness.step();
    harness.get_by_label("Discard").click();
    harness.step();
    harness.step();
    assert!(harness.query_by_label("Recover").is_none());
    assert!(!harness.state().session().unwrap().history.is_dirty());
    assert!(recovery.find(project.path()).is_none());
}
