//! The I/O mapping view of the example machine, driven through its accessibility tree.

#![allow(clippy::unwrap_used, clippy::expect_used)] // Test helpers may panic: a panic is a failed test.

use editor::{IoMappingOutput, TableTexts, io_mapping_ui};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use project_model::Project;

/// egui's fonts with the CJK fallback behind them, as the studio installs them: the example's
/// comments are partly Chinese.
fn install_fonts(ctx: &egui::Context) {
    let mut fonts = egui::FontDefinitions::default();
    fonts.font_data.insert(
        "cjk".to_owned(),
        std::sync::Arc::new(egui::FontData::from_static(assets::CJK_FONT_TTF)),
    );
    for family in [egui::FontFamily::Proportional, egui::FontFamily::Monospace] {
        fonts
            .families
            .entry(family)
            .or_default()
            .push("cjk".to_owned());
    }
    ctx.set_fonts(fonts);
}

struct App {
    project: Project,
    opened: Vec<(String, String)>,
}

fn harness() -> Harness<'static, App> {
    let loaded = project_model::load_project(&assets::example_project_dir()).unwrap();
    let app = App {
        project: loaded.project,
        opened: Vec::new(),
    };
    let mut harness = Harness::builder()
        .with_size([1000.0, 2000.0])
        .with_context_setup(install_fonts)
        .build_ui_state(
            |ui, app: &mut App| {
                let IoMappingOutput { open } =
                    io_mapping_ui(ui, &app.project, &TableTexts::default());
                app.opened.extend(open);
            },
            app,
        );
    harness.run();
    harness
}

#[test]
fn the_example_lists_its_buttons_under_the_input_area_and_opens_them() {
    let mut harness = harness();
    assert!(
        harness
            .query_by_label_contains("DI_16 (inputs, %IB0 to %IB1)")
            .is_some()
    );
    // Channels are listed whether bound or not.
    assert!(harness.query_by_label("%IX0.0").is_some());
    assert!(harness.query_by_label("%IX1.7").is_some());
    assert!(harness.query_by_label("%QW1").is_some());
    harness.get_by_label("GVL_IO.xStartButton").click();
    harness.run();
    assert_eq!(
        harness.state().opened,
        [("GVL_IO".to_owned(), "xStartButton".to_owned())]
    );
    harness.get_by_label("GVL_IO.iBeltSpeedSetpoint").click();
    harness.run();
    assert_eq!(harness.state().opened[1].1, "iBeltSpeedSetpoint");
}

#[test]
fn modbus_bindings_list_their_channels_and_open_their_variables() {
    let mut harness = harness();
    assert!(
        harness
            .query_by_label_contains("BeltDrive (Modbus TCP 192.168.1.50:502, unit 1)")
            .is_some()
    );
    assert!(harness.query_by_label("Input register").is_some());
    assert!(harness.query_by_label("0..1").is_some());
    harness.get_by_label("GVL_Machine.xDriveReady").click();
    harness.run();
    assert_eq!(
        harness.state().opened,
        [("GVL_Machine".to_owned(), "xDriveReady".to_owned())]
    );
}

#[test]
fn a_binding_to_an_undeclared_variable_is_marked() {
    let loaded = project_model::load_project(&assets::example_project_dir()).unwrap();
    let mut project = loaded.project;
    project.modbus_devices[0].bindings[0].variable = "GVL_Machine.rGone".to_owned();
    let mut harness = Harness::builder()
        .with_context_setup(install_fonts)
        .build_ui_state(
            |ui, project: &mut Project| {
                io_mapping_ui(ui, project, &TableTexts::default());
            },
            project,
        );
    harness.run();
    assert!(
        harness
            .query_by_label("GVL_Machine.rGone (not declared)")
            .is_some()
    );
}
