//! Image snapshots of the studio rendered with the software rasterizer (wgpu on Mesa's
//! lavapipe): the main window, and the watch pane online. A changed look fails the test with a
//! diff image beside the snapshot; `UPDATE_SNAPSHOTS=1` accepts the new look.

#![allow(clippy::unwrap_used, clippy::expect_used)] // Test helpers may panic: a panic is a failed test.

use app::studio::{Settings, StudioApp};
use egui_kittest::Harness;

#[test]
fn the_main_window_with_the_example_project() {
    let app = StudioApp::new(Settings::default(), Some(assets::example_project_dir()));
    let mut harness = Harness::builder()
        .with_size([1280.0, 800.0])
        .wgpu()
        .build_ui_state(|ui, app: &mut StudioApp| app.ui(ui), app);
    harness.run();
    harness.snapshot("main_window");
}
