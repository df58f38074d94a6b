//! Image snapshots of the studio rendered with the software rasterizer (wgpu on Mesa's
//! lavapipe): the main window, and the watch pane online. A changed look fails the test with a
//! diff image beside the snapshot; `UPDATE_SNAPSHOTS=1` accepts the new look.

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

/// Steps until `done` holds, for at most 30 s.
fn wait(harness: &mut Harness<'_, StudioApp>, what: &str, done: impl Fn(&StudioApp) -> bool) {
    let start = std::time::Instant::now();
    while !done(harness.state()) {
        assert!(start.elapsed().as_secs() < 30, "waited for {what}");
        harness.step();
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
}

#[test]
fn the_st_editor_online_with_values_inline() {
    use egui_kittest::kittest::Queryable as _;

    let app = StudioApp::new(Settings::default(), Some(assets::example_project_dir()));
    let mut harness = Harness::builder()
        .with_size([1280.0, 800.0])
        .wgpu()
        .build_ui_state(|ui, app: &mut StudioApp| app.ui(ui), app);
    harness.step();
    harness
        .state_mut()
        .open(app::studio::TreeNode::Object("Main".into()));
    harness.step();
    let ctx = harness.ctx.clone();
    harness.state_mut().login(&ctx);
    wait(&mut harness, "the download question", |app| {
        matches!(
            app.online().phase(),
            app::studio::Phase::ConfirmDownload { .. }
        )
    });
    harness.state_mut().confirm_download();
    wait(&mut harness, "the login", |app| {
        *app.online().phase() == app::studio::Phase::Online
    });
    harness.state_mut().start();
    wait(&mut harness, "the inline values", |app| {
        app.online().value("GVL_Machine.udiTotalPackages").is_some()
            && app.online().value("GVL_IO.iBeltSpeedSetpoint").is_some()
            && app.online().target_state() == Some(online::TargetState::Running)
    });
    // Let every value arrive once more, so none is drawn as just changed.
    for _ in 0..20 {
        harness.step();
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    // The cycle counter in the status bar differs from run to run.
    let cycle = harness.get_by_label_contains("cycle ").rect();
    harness.mask(cycle);
    harness.snapshot("st_editor_online");
}

#[test]
fn the_trace_view_with_cursors() {
    use app::studio::{TraceData, TracePlotView, TraceSample, TraceSeries};

    let samples = (0..200u64)
        .map(|i| TraceSample {
            cycle: 1000 + i,
            time_ns: i * 10_000_000,
            values: vec![
                f64::from(u8::from(i % 50 >= 25)),
                (i as f64 * 0.05).sin() * 100.0,
                (i as f64).min(120.0),
            ],
        })
        .collect();
    let data = TraceData {
        variables: vec![
            TraceSeries {
                path: "GVL_IO.xConveyorMotor".into(),
                color: None,
                is_bool: true,
            },
            TraceSeries {
                path: "GVL_Machine.lrMasterPosition".into(),
                color: None,
                is_bool: false,
            },
            TraceSeries {
                path: "Main.ctuPackages.CV".into(),
                color: None,
                is_bool: false,
            },
        ],
        samples,
        trigger_sample: Some(20),
        cycle_time_ns: Some(10_000_000),
    };
    let mut view = TracePlotView::default();
    view.cursor_a_ms = Some(300.0);
    view.cursor_b_ms = Some(900.0);
    let mut harness = Harness::builder()
        .with_size([1000.0, 560.0])
        .wgpu()
        .build_ui_state(
            move |ui, view: &mut TracePlotView| {
                view.ui(ui, &data);
            },
            view,
        );
    harness.run();
    harness.snapshot("trace_view");
}
