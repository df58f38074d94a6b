//! The studio driven through its accessibility tree, without a window or GPU.

use std::path::Path;

use app::studio::{Language, Settings, StudioApp, Text, TreeNode};
use egui_kittest::Harness;
use egui_kittest::kittest::{Queryable as _, by};

fn example_dir() -> std::path::PathBuf {
    assets::example_project_dir()
}

fn studio(project: Option<&Path>, settings: Settings) -> Harness<'static, StudioApp> {
    let app = StudioApp::new(settings, project.map(Path::to_owned));
    let mut harness = Harness::builder()
        .with_size([1280.0, 800.0])
        .build_ui_state(|ui, app: &mut StudioApp| app.ui(ui), app);
    harness.run();
    harness
}

#[test]
fn the_example_opens_and_a_tree_node_can_be_selected() {
    let mut harness = studio(Some(&example_dir()), Settings::default());
    assert!(harness.state().session().is_some());
    assert!(harness.state().problems().is_empty());

    harness.get_by_label("FB_Conveyor").click();
    harness.run();
    assert_eq!(
        harness.state().selection(),
        Some(&TreeNode::Object("FB_Conveyor".into()))
    );

    harness.get_by_label("MotionTask").click();
    harness.run();
    assert_eq!(
        harness.state().selection(),
        Some(&TreeNode::Task("MotionTask".into()))
    );
}

#[test]
fn enter_on_a_pou_opens_its_text_in_a_tab() {
    // Double-click and Enter both open a node; Enter is what a harness can send reliably.
    let mut harness = studio(Some(&example_dir()), Settings::default());
    harness.get_by_label("Sequence").focus();
    harness.run();
    harness.key_press(egui::Key::Enter);
    harness.run();
    assert_eq!(
        harness.state().open_documents(),
        vec![TreeNode::Object("Sequence".into())]
    );
    // The body text is on screen (read-only) in the tab.
    let shows_body = by().predicate(|node| {
        node.value()
            .is_some_and(|text| text.contains("CASE eState OF"))
    });
    assert!(harness.query_all(shows_body).next().is_some());
}

#[test]
fn a_broken_project_shows_its_errors_and_the_studio_keeps_running() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("rivet.toml"),
        "format_version = 1\nname = \n",
    )
    .unwrap();
    let mut harness = studio(Some(dir.path()), Settings::default());
    assert!(harness.state().session().is_none());
    let problems = harness.state().problems();
    assert_eq!(problems.len(), 1);
    assert_eq!(problems[0].line, Some(2));
    // The messages panel lists the error as file:line.
    let shown = format!("{}:2:", dir.path().join("rivet.toml").display());
    assert!(harness.query_by_label_contains(&shown).is_some());
    harness.run();
    assert!(
        harness
            .query_by_label(Text::CouldNotOpen.get(Language::English))
            .is_some()
    );
}

#[test]
fn the_interface_speaks_chinese_when_chosen() {
    let settings = Settings {
        language: Language::SimplifiedChinese,
        ..Settings::default()
    };
    let harness = studio(Some(&example_dir()), settings);
    assert!(harness.query_by_label("任务配置").is_some());
    assert!(harness.query_by_label("文件").is_some());
}

#[test]
fn the_declaration_table_and_the_io_mapping_speak_chinese_too() {
    let settings = Settings {
        language: Language::SimplifiedChinese,
        ..Settings::default()
    };
    let mut harness = studio(Some(&example_dir()), settings);
    harness.get_by_label("GVL_IO").focus();
    harness.step();
    harness.key_press(egui::Key::Enter);
    harness.run();
    harness
        .get_by_label(Text::AsTable.get(Language::SimplifiedChinese))
        .click();
    harness.run();
    assert!(harness.query_by_label("xStartButton 的地址").is_some());
    assert!(harness.query_by_label("在上方插入").is_some());
    assert!(harness.query_by_label("拖动 GVL_IO.xStartButton").is_some());
    assert!(harness.query_by_label("Address of xStartButton").is_none());

    harness.state_mut().open(TreeNode::Controller);
    harness.run();
    // One channel table per I/O area, each with its header.
    assert!(harness.query_all_by_label("通道").next().is_some());
    assert!(harness.query_all_by_label("Channel").next().is_none());
}

#[test]
fn switching_the_language_in_settings_translates_the_interface() {
    let mut harness = studio(Some(&example_dir()), Settings::default());
    harness.get_by_label("Settings").click();
    harness.run();
    harness.get_by_label("Language").click();
    harness.run();
    harness.get_by_label("简体中文").click();
    harness.run();
    assert_eq!(
        harness.state().settings().language,
        Language::SimplifiedChinese
    );
    assert!(harness.query_by_label("任务配置").is_some());
    assert!(harness.query_by_label("Task configuration").is_none());
}
