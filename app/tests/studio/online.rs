//! The online workflow in the studio, driven through its accessibility tree against the built-in
//! simulator: build, log in with download, start, watch, force, release, write, trace, stop.

use app::studio::TracePhase;
use egui::{Key, Modifiers};
use egui_kittest::kittest::Queryable as _;
use online::TargetState;

use crate::support::{
    example_copy, login_with_download, prepare, show_tab, studio, value, wait_until, watch,
};

#[test]
fn build_login_run_watch_force_release_write_trace_and_stop_in_the_simulator() {
    // The project's trace records 50 samples here, so it completes quickly.
    let project = example_copy(|dir| {
        crate::support::replace_in(
            dir,
            "application/Diagnostics/TRC_Conveyor.trace.toml",
            "record_count = 2000",
            "record_count = 50",
        );
    });
    let mut harness = studio(project.path());

    // F11 builds in the background; the messages panel then counts no error.
    harness.key_press(Key::F11);
    wait_until(&mut harness, "the build", |app| app.last_build().is_some());
    let build = harness.state().last_build().unwrap();
    assert_eq!(build.counts().0, 0, "{:?}", build.messages);
    assert!(build.image.is_some());

    // Alt+F8 logs in to the simulator, which has no program: the studio offers a download.
    // Alt+F8 logs in; the target has no program, so the studio offers the download.
    login_with_download(&mut harness);
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
