//! File ▸ Import PLCopen XML…: the preview of a corpus file, the import into the open project
//! (new objects added, a clash skipped by default, one undo step), a file that cannot be read,
//! and the import as a new project.

use std::path::{Path, PathBuf};

use app::studio::StudioApp;
use egui::{Key, Modifiers};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use project_model::{GlobalVarList, Node, Object, load_project, save_project};

use crate::support::{example_copy, studio};

fn first_steps() -> PathBuf {
    Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../shared/corpora/plcopen/beremiz/exemples/first_steps/plc.xml"
    ))
    .to_path_buf()
}

/// The example with a global variable list named `CounterST`, so that the POU of that name in
/// `first_steps` clashes with it.
fn example_with_a_clash() -> tempfile::TempDir {
    example_copy(|dir| {
        let mut loaded = load_project(dir).unwrap();
        loaded
            .project
            .application
            .children
            .push(Node::Object(Object::Gvl(GlobalVarList {
                name: "CounterST".into(),
                comment: "mine".into(),
                ..GlobalVarList::default()
            })));
        save_project(&loaded.project, dir, &loaded.files).unwrap();
    })
}

fn preview(harness: &mut Harness<'static, StudioApp>, file: &Path) {
    harness.state_mut().import_plcopen(file);
    harness.run();
    assert!(harness.state().is_import_open());
}

#[test]
fn importing_into_the_project_adds_the_pous_and_skips_a_clash_by_default() {
    let dir = example_with_a_clash();
    let mut harness = studio(dir.path());
    preview(&mut harness, &first_steps());
    assert!(harness.query_by_label("Import report").is_some());
    assert!(
        harness
            .query_by_label_contains("PLCopen TC6 v2.01, written by Beremiz")
            .is_some()
    );
    assert!(harness.query_by_label("POU AverageVal").is_none());
    assert!(harness.query_by_label("+ POU AverageVal").is_some());
    assert!(
        harness
            .query_by_label("clashes with global variable list CounterST")
            .is_some()
    );
    harness.get_by_label("Import into this project").click();
    harness.run();
    assert!(!harness.state().is_import_open());
    let session = harness.state().session().unwrap();
    assert!(session.history.is_dirty());
    assert_eq!(session.history.undo_label(), Some("Import plc.xml"));
    match session.project.application.object("CounterST") {
        Some(Object::Gvl(list)) => assert_eq!(list.comment, "mine"),
        other => panic!("CounterST is {other:?}"),
    }
    assert!(session.project.task("plc_task").is_some());
    // The tree marks the new objects as not saved yet.
    assert!(harness.query_by_label("AverageVal *").is_some());
    assert!(harness.query_by_label("config *").is_some());
    // Nothing was written: the folder still holds the project as it was.
    let on_disk = load_project(dir.path()).unwrap().project;
    assert!(on_disk.application.object("AverageVal").is_none());
}

#[test]
fn a_clash_set_to_replace_replaces_and_undo_takes_the_whole_import_back() {
    let dir = example_with_a_clash();
    let mut harness = studio(dir.path());
    let before = harness.state().session().unwrap().project.clone();
    preview(&mut harness, &first_steps());
    harness.get_by_label("Replace").click();
    harness.run();
    harness.get_by_label("Import into this project").click();
    harness.run();
    let project = &harness.state().session().unwrap().project;
    assert!(matches!(
        project.application.object("CounterST"),
        Some(Object::Pou(_))
    ));
    harness.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    harness.run();
    assert_eq!(harness.state().session().unwrap().project, before);
}

#[test]
fn a_truncated_file_shows_its_line_and_column_and_changes_nothing() {
    let dir = example_copy(|_| {});
    let temp = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(first_steps()).unwrap();
    let file = temp.path().join("cut.xml");
    std::fs::write(&file, &text[..3000]).unwrap();
    let mut harness = studio(dir.path());
    preview(&mut harness, &file);
    let location = format!("{}:105:15:", file.display());
    assert!(
        harness.query_by_label_contains(&location).is_some(),
        "{location}"
    );
    assert!(
        harness
            .query_by_label_contains("nothing was changed")
            .is_some()
    );
    harness.get_by_label("Cancel").click();
    harness.run();
    assert!(!harness.state().is_import_open());
    assert!(!harness.state().session().unwrap().history.is_dirty());
}

#[test]
fn importing_as_a_new_project_refuses_a_busy_folder_and_opens_the_new_one() {
    let dir = example_copy(|_| {});
    let temp = tempfile::tempdir().unwrap();
    let busy = temp.path().join("busy");
    std::fs::create_dir(&busy).unwrap();
    std::fs::write(busy.join("notes.txt"), "mine").unwrap();
    let mut harness = studio(dir.path());
    preview(&mut harness, &first_steps());
    harness.state_mut().import_as_new_project(&busy);
    harness.run();
    assert!(harness.state().is_import_open());
    assert!(
        harness
            .query_by_label_contains("the folder is not empty; nothing was written")
            .is_some()
    );
    assert_eq!(std::fs::read_dir(&busy).unwrap().count(), 1);
    let fresh = temp.path().join("fresh");
    harness.state_mut().import_as_new_project(&fresh);
    harness.run();
    assert!(!harness.state().is_import_open());
    let session = harness.state().session().unwrap();
    assert_eq!(session.dir, fresh);
    assert_eq!(session.project.name, "First Steps");
    assert!(harness.query_by_label("CounterST").is_some());
}

#[test]
fn without_an_open_project_the_preview_offers_only_a_new_project() {
    let app = StudioApp::new(app::studio::Settings::default(), None);
    let mut harness = Harness::builder()
        .with_size([1280.0, 800.0])
        .build_ui_state(|ui, app: &mut StudioApp| app.ui(ui), app);
    harness.run();
    preview(&mut harness, &first_steps());
    assert!(
        harness
            .query_by_label("No project is open: import as a new project")
            .is_some()
    );
    // The disabled button does nothing.
    harness.get_by_label("Import into this project").click();
    harness.run();
    assert!(harness.state().is_import_open());
    assert!(harness.state().session().is_none());
}
