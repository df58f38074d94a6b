//! File ▸ Export PLCopen XML…: the menu item, the project in the editor written with its unsaved
//! changes (and importing back to it), a file that cannot be written, a project with objects
//! that did not load, and the status in Chinese.

use std::path::{Path, PathBuf};

use app::studio::{Language, Settings, StudioApp};
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT as _, Queryable as _};

use crate::support::{example_copy, studio};

fn first_steps() -> PathBuf {
    Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../shared/corpora/plcopen/beremiz/exemples/first_steps/plc.xml"
    ))
    .to_path_buf()
}

/// The status bar's text and whether it reports a failure.
fn status(harness: &Harness<'static, StudioApp>) -> (String, bool) {
    let status = harness.state().status().expect("a status");
    (status.text.clone(), status.is_error)
}

#[test]
fn the_file_menu_offers_the_export_beside_the_import() {
    let dir = example_copy(|_| {});
    let mut harness = studio(dir.path());
    harness.get_by_label("File").click();
    harness.run();
    assert!(harness.query_by_label("Import PLCopen XML…").is_some());
    let export = harness.get_by_label("Export PLCopen XML…");
    assert!(!export.accesskit_node().is_disabled());
}

#[test]
fn without_a_project_the_export_is_disabled() {
    let app = StudioApp::new(Settings::default(), None);
    let mut harness = Harness::builder()
        .with_size([1280.0, 800.0])
        .build_ui_state(|ui, app: &mut StudioApp| app.ui(ui), app);
    harness.run();
    harness.get_by_label("File").click();
    harness.run();
    assert!(
        harness
            .get_by_label("Export PLCopen XML…")
            .accesskit_node()
            .is_disabled()
    );
}

#[test]
fn the_export_writes_the_project_in_the_editor_with_its_unsaved_changes() {
    let dir = example_copy(|_| {});
    let mut harness = studio(dir.path());
    // An unsaved change: first_steps imported into the open project.
    harness.state_mut().import_plcopen(&first_steps());
    harness.run();
    harness.get_by_label("Import into this project").click();
    harness.run();
    assert!(harness.state().session().unwrap().history.is_dirty());

    let temp = tempfile::tempdir().unwrap();
    let file = temp.path().join("machine.xml");
    harness.state_mut().export_plcopen(&file);
    harness.run();
    let (text, is_error) = status(&harness);
    assert!(!is_error, "{text}");
    assert!(
        text.starts_with("Exported machine.xml: ") && text.ends_with("unsaved changes included"),
        "{text}"
    );
    // The file holds the project as it is in the editor: it imports back to it, the imported
    // POUs included, and nothing else was written.
    let document = plcopen::read_file(&file).unwrap();
    let imported = plcopen::import(&document).unwrap().project;
    let session = harness.state().session().unwrap();
    assert!(imported.application.object("AverageVal").is_some());
    assert_eq!(imported.application, session.project.application);
    assert_eq!(imported.tasks, session.project.tasks);
    assert_eq!(std::fs::read_dir(temp.path()).unwrap().count(), 1);
    // The export neither saved the project nor marked it saved.
    assert!(session.history.is_dirty());
    let on_disk = project_model::load_project(dir.path()).unwrap().project;
    assert!(on_disk.application.object("AverageVal").is_none());
}

#[test]
fn a_saved_project_is_exported_without_the_unsaved_note() {
    let dir = example_copy(|_| {});
    let mut harness = studio(dir.path());
    let temp = tempfile::tempdir().unwrap();
    let file = temp.path().join("machine.xml");
    harness.state_mut().export_plcopen(&file);
    harness.run();
    let (text, is_error) = status(&harness);
    assert!(!is_error, "{text}");
    let objects = harness
        .state()
        .session()
        .unwrap()
        .project
        .application
        .objects()
        .len();
    assert_eq!(text, format!("Exported machine.xml: {objects} objects"));
}

#[test]
fn a_file_that_cannot_be_written_is_named_and_nothing_is_left_behind() {
    let dir = example_copy(|_| {});
    let mut harness = studio(dir.path());
    let temp = tempfile::tempdir().unwrap();
    let file = temp.path().join("missing").join("machine.xml");
    harness.state_mut().export_plcopen(&file);
    harness.run();
    let (text, is_error) = status(&harness);
    assert!(is_error);
    let expected = format!(
        "PLCopen export failed: {}: cannot be written: ",
        file.display()
    );
    assert!(text.starts_with(&expected), "{text}");
    assert!(harness.query_by_label(&text).is_some());
    assert_eq!(std::fs::read_dir(temp.path()).unwrap().count(), 0);
}

#[test]
fn a_project_with_objects_that_did_not_load_is_not_exported() {
    let dir = example_copy(|dir| {
        let pou = dir.join("application/Main.pou.toml");
        let broken = std::fs::read_to_string(&pou)
            .unwrap()
            .replace("kind = \"program\"", "kind = \"prgram\"");
        std::fs::write(&pou, broken).unwrap();
    });
    let mut harness = studio(dir.path());
    assert_eq!(harness.state().session().unwrap().held_back.len(), 1);
    let temp = tempfile::tempdir().unwrap();
    let file = temp.path().join("machine.xml");
    harness.state_mut().export_plcopen(&file);
    harness.run();
    let (text, is_error) = status(&harness);
    assert!(is_error);
    assert_eq!(
        text,
        "PLCopen export failed: 1 objects could not be loaded and would be missing from the \
         export; fix their files first"
    );
    assert!(!file.exists());
}

#[test]
fn the_export_reports_in_chinese_when_chosen() {
    let dir = example_copy(|_| {});
    let app = StudioApp::new(
        Settings {
            language: Language::SimplifiedChinese,
            ..Settings::default()
        },
        Some(dir.path().to_owned()),
    );
    let mut harness = Harness::builder()
        .with_size([1400.0, 900.0])
        .build_ui_state(|ui, app: &mut StudioApp| app.ui(ui), app);
    harness.run();
    let temp = tempfile::tempdir().unwrap();
    harness
        .state_mut()
        .export_plcopen(&temp.path().join("missing").join("machine.xml"));
    harness.run();
    let (text, is_error) = status(&harness);
    assert!(is_error);
    assert!(text.starts_with("PLCopen 导出失败: "), "{text}");
    harness
        .state_mut()
        .export_plcopen(&temp.path().join("machine.xml"));
    harness.run();
    let (text, is_error) = status(&harness);
    assert!(!is_error, "{text}");
    assert!(text.starts_with("已导出 machine.xml："), "{text}");
    harness.get_by_label("文件").click();
    harness.run();
    assert!(harness.query_by_label("导出 PLCopen XML…").is_some());
}
