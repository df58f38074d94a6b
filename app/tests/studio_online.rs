//! The online workflow in the studio, driven through its accessibility tree against the built-in
//! simulator: build, log in with download, start, watch, force, release, write, trace, stop.

#![allow(clippy::unwrap_used, clippy::expect_used)] // Test helpers may panic: a panic is a failed test.

use std::path::Path;
use std::time::{Duration, Instant};

use app::studio::{Phase, Settings, StudioApp, TracePhase};
use egui::{Key, Modifiers};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use online::TargetState;

/// How long a step may take on a loaded CI machine before the test fails.
const PATIENCE: Duration = Duration::from_secs(30);

/// A copy of the example project whose trace records 50 samples, so a trace completes quickly.
fn example_copy() -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    copy_dir(&assets::example_project_dir(), dir.path());
    let trace = dir
        .path()
        .join("application/Diagnostics/TRC_Conveyor.trace.toml");
    let text = std::fs::read_to_string(&trace).unwrap();
    std::fs::write(
        &trace,
        text.replace("record_count = 2000", "record_count = 50"),
    )
    .unwrap();
    dir
}

fn copy_dir(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).unwrap();
    for entry in std::fs::read_dir(from).unwrap() {
        let entry = entry.unwrap();
        let target = to.join(entry.file_name());
        if entry.file_type().unwrap().is_dir() {
            copy_dir(&entry.path(), &target);
        } else {
            std::fs::copy(entry.path(), target).unwrap();
        }
    }
}

fn studio(project: &Path) -> Harness<'static, StudioApp> {
    let app = StudioApp::new(Settings::default(), Some(project.to_owned()));
    let mut harness = Harness::builder()
        .with_size([1400.0, 900.0])
        .build_ui_state(|ui, app: &mut StudioApp| app.ui(ui), app);
    harness.step();
    harness
}

/// Steps the studio until `done` holds, failing with `what` after [`PATIENCE`].
fn wait_until(harness: &mut Harness<'_, StudioApp>, what: &str, done: impl Fn(&StudioApp) -> bool) {
    let start = Instant::now();
    loop {
        harness.step();
        if done(harness.state()) {
            return;
        }
        assert!(
            start.elapsed() < PATIENCE,
            "waited {PATIENCE:?} for {what}; status: {:?}, phase: {:?}",
            harness.state().status(),
            harness.state().online().phase()
        );
        std::thread::sleep(Duration::from_millis(20));
    }
}

fn value(app: &StudioApp, path: &str) -> Option<(String, bool)> {
    app.online()
        .value(path)
        .map(|value| (value.text.clone(), value.forced))
}

/// Brings the tab labelled `label` forward.
fn show_tab(harness: &mut Harness<'_, StudioApp>, label: &str) {
    harness.get_by_label(label).click();
    harness.step();
    harness.step();
}

/// Adds `path` to the shown watch list through the "Add variable" field.
fn watch(harness: &mut Harness<'_, StudioApp>, path: &str) {
    harness.get_by_label("Add variable").click();
    harness.step();
    harness.get_by_label("Add variable").type_text(path);
    harness.step();
    harness.key_press(Key::Enter);
    harness.step();
    harness.step();
}

/// Types a prepared value for `path` and commits it by pressing Enter.
fn prepare(harness: &mut Harness<'_, StudioApp>, path: &str, text: &str) {
    let label = format!("Prepared value of {path}");
    harness.get_by_label(&label).click();
    harness.step();
    harness.key_press_modifiers(Modifiers::COMMAND, Key::A);
    harness.get_by_label(&label).type_text(text);
    harness.step();
    harness.key_press(Key::Enter);
    harness.step();
    harness.step();
}

#[test]
fn build_login_run_watch_force_release_write_trace_and_stop_in_the_simulator() {
    let project = example_copy();
    let mut harness = studio(project.path());

    // F11 builds in the background; the messages panel then counts no error.
    harness.key_press(Key::F11);
    wait_until(&mut harness, "the build", |app| app.last_build().is_some());
    let build = harness.state().last_build().unwrap();
    assert_eq!(build.counts().0, 0, "{:?}", build.messages);
    assert!(build.image.is_some());

    // Alt+F8 logs in to the simulator, which has no program: the studio offers a download.
    harness.key_press_modifiers(Modifiers::ALT, Key::F8);
    wait_until(&mut harness, "the download question", |app| {
        matches!(app.online().phase(), Phase::ConfirmDownload { .. })
    });
    harness.step();
    harness.get_by_label("Download").click();
    wait_until(&mut harness, "the download", |app| {
        *app.online().phase() == Phase::Online
    });
    assert_eq!(
        harness.state().online().target_state(),
        Some(TargetState::Stopped)
    );

    // F5 starts the program.
    harness.key_press(Key::F5);
    wait_until(&mut harness, "the start", |app| {
        app.online().target_state() == Some(TargetState::Running)
    });

    // The watch list of the project shows live values; a variable added by path joins it.
    show_tab(&mut harness, "Watch");
    watch(&mut harness, "GVL_IO.xConveyorMotor");
    wait_until(&mut harness, "the motor output's value", |app| {
        value(app, "GVL_IO.xConveyorMotor") == Some(("FALSE".into(), false))
    });

    // A value of the wrong type is refused in place with the reason and not kept.
    prepare(&mut harness, "GVL_IO.xConveyorMotor", "12.5");
    assert!(
        harness.query_by_label_contains("BOOL").is_some(),
        "the refusal names the type"
    );

    // F7 forces the prepared values: the output the program writes FALSE every cycle stays TRUE.
    prepare(&mut harness, "GVL_IO.xConveyorMotor", "TRUE");
    harness.key_press(Key::F7);
    wait_until(&mut harness, "the forced value", |app| {
        value(app, "GVL_IO.xConveyorMotor") == Some(("TRUE".into(), true))
    });
    let forced_at = harness.state().online().cycle();
    wait_until(&mut harness, "ten more cycles", |app| {
        app.online().cycle() >= forced_at + 10
    });
    assert_eq!(
        value(harness.state(), "GVL_IO.xConveyorMotor"),
        Some(("TRUE".into(), true))
    );
    // The forces list names it.
    harness.get_by_label_contains("Forces (").click();
    harness.step();
    harness.step();
    assert!(harness.query_by_label("GVL_IO.xConveyorMotor").is_some());

    // Alt+F7 releases every force: the program's own value comes back.
    harness.key_press_modifiers(Modifiers::ALT, Key::F7);
    wait_until(&mut harness, "the released value", |app| {
        value(app, "GVL_IO.xConveyorMotor") == Some(("FALSE".into(), false))
    });
    assert!(harness.state().online().forced_values().is_empty());

    // Arm the project's trace (rising edge of the start button), then press the start button
    // with Ctrl+F7: the machine state changes and the trace records.
    show_tab(&mut harness, "Trace");
    harness.get_by_label("Start trace").click();
    wait_until(&mut harness, "the armed trace", |app| {
        matches!(app.online().trace().phase(), TracePhase::Recording { .. })
    });
    show_tab(&mut harness, "Watch");
    prepare(&mut harness, "GVL_IO.xConveyorMotor", "");
    watch(&mut harness, "GVL_IO.xStartButton");
    prepare(&mut harness, "GVL_IO.xStartButton", "TRUE");
    // Enumerations show by name, as the program declares them.
    assert_eq!(
        value(harness.state(), "GVL_Machine.eMachineState"),
        Some(("Idle".into(), false))
    );
    harness.key_press_modifiers(Modifiers::COMMAND, Key::F7);
    wait_until(&mut harness, "the machine state to change", |app| {
        value(app, "GVL_Machine.eMachineState") == Some(("Starting".into(), false))
    });
    wait_until(&mut harness, "the complete trace", |app| {
        app.online().trace().phase() == TracePhase::Complete
    });
    show_tab(&mut harness, "Trace");
    harness.get_by_label("Upload").click();
    wait_until(&mut harness, "the uploaded samples", |app| {
        app.online().trace().phase() == TracePhase::Uploaded
    });
    let trace = harness.state().online().trace();
    assert_eq!(trace.samples().len(), 50);
    let cycles: Vec<u64> = trace.samples().iter().map(|s| s.cycle).collect();
    assert!(cycles.windows(2).all(|w| w[1] == w[0] + 1), "{cycles:?}");

    // Shift+F8 stops the program.
    harness.key_press_modifiers(Modifiers::SHIFT, Key::F8);
    wait_until(&mut harness, "the stop", |app| {
        app.online().target_state() == Some(TargetState::Stopped)
    });
}
