//! A controller that disappears while the studio is logged in: the studio says so, keeps every
//! edit, and connects again when the controller is back.

use std::sync::{Arc, Mutex};

use crate::support::{
    example_copy, login_with_download, replace_in, show_tab, studio, wait_until, watch,
};
use app::studio::{Phase, TargetKind};
use runtime::areas::LocatedAreas;
use runtime::modbus::{MapSlot, ModbusMap, ServerOptions, serve};
use runtime::online::OnlineServices;
use runtime::scheduler::{Scheduler, SchedulerOptions};
use tokio::sync::oneshot;

/// A soft PLC on `port` (0: any) in its own thread; dropping the sender stops it. Returns the
/// port it listens on.
fn controller(port: u16) -> (u16, oneshot::Sender<()>) {
    controller_with(port, true)
}

/// [`controller`] with the debugging services on or off (`rivet-runtime --debug on|off`).
fn controller_with(port: u16, debugging: bool) -> (u16, oneshot::Sender<()>) {
    let listener = std::net::TcpListener::bind(("127.0.0.1", port)).unwrap();
    listener.set_nonblocking(true).unwrap();
    let port = listener.local_addr().unwrap().port();
    let (stop, stopped) = oneshot::channel::<()>();
    std::thread::spawn(move || {
        let runtime = tokio::runtime::Builder::new_current_thread()
            .enable_all()
            .build()
            .unwrap();
        runtime.block_on(async move {
            let areas = Arc::new(Mutex::new(LocatedAreas::default()));
            let scheduler = Arc::new(
                Scheduler::spawn(Arc::clone(&areas), SchedulerOptions::default()).unwrap(),
            );
            let map = MapSlot::new(ModbusMap::default());
            let services = Arc::new(
                OnlineServices::new(scheduler, None)
                    .with_map(Arc::clone(&map))
                    .with_debugging(debugging),
            );
            let options = ServerOptions {
                custom: Some(services.handler()),
                closed: Some(services.closed_handler()),
                ..ServerOptions::default()
            };
            let listener = tokio::net::TcpListener::from_std(listener).unwrap();
            tokio::select! {
                _ = serve(listener, areas, map, options) => {}
                _ = stopped => {}
            }
        });
        // Dropping the runtime closes every connection, as a controller that lost power.
    });
    (port, stop)
}

#[test]
fn a_lost_controller_is_reported_edits_are_kept_and_the_studio_reconnects() {
    let (port, stop) = controller(0);
    let project = example_copy(|dir| {
        replace_in(dir, "rivet.toml", "port = 5020", &format!("port = {port}"));
    });
    let mut harness = studio(project.path());
    harness.state_mut().set_target(TargetKind::Controller);
    // Alt+F8 logs in; the target has no program, so the studio offers the download.
    login_with_download(&mut harness);

    drop(stop);
    wait_until(&mut harness, "the lost connection", |app| {
        matches!(app.online().phase(), Phase::Lost(_))
    });
    let status = harness.state().status().unwrap().clone();
    // The status bar says the target is gone (the last of the messages about it).
    assert!(
        status.is_error
            && (status.text.contains("not reachable")
                || status.text.contains("connection refused")),
        "{status:?}"
    );

    // Editing goes on while the controller is away.
    show_tab(&mut harness, "Watch");
    watch(&mut harness, "Main.rtrigPackage.Q");
    assert!(harness.state().session().unwrap().history.is_dirty());

    // The controller comes back (without its program, as after a power cycle): the studio
    // connects again by itself and offers the download.
    let (_same_port, _keep) = controller(port);
    wait_until(&mut harness, "the reconnection", |app| {
        matches!(app.online().phase(), Phase::ConfirmDownload { .. })
    });
    assert!(harness.state().session().unwrap().history.is_dirty());
}

#[test]
fn a_lost_controller_ends_the_halt_in_the_studio() {
    use egui::{Key, Modifiers};
    use egui_kittest::kittest::Queryable as _;

    let (port, stop) = controller(0);
    let project = example_copy(|dir| {
        replace_in(dir, "rivet.toml", "port = 5020", &format!("port = {port}"));
    });
    let mut harness = studio(project.path());
    harness.state_mut().set_target(TargetKind::Controller);
    harness.state_mut().build();
    wait_until(&mut harness, "the build", |app| {
        app.last_build().is_some_and(|build| build.image.is_some())
    });
    // F9 on the first line of Main's body sets a breakpoint on its first statement.
    harness.get_by_label("Main").focus();
    harness.step();
    harness.key_press(Key::Enter);
    harness.step();
    harness.step();
    harness.get_by_label("Implementation of Main").click();
    harness.step();
    harness.key_press_modifiers(Modifiers::COMMAND, Key::Home);
    harness.step();
    harness.key_press(Key::F9);
    harness.step();
    login_with_download(&mut harness);
    harness.key_press(Key::F5);
    wait_until(&mut harness, "the halt", |app| {
        app.debug_state().is_halted()
    });

    drop(stop);
    wait_until(&mut harness, "the halt ended with the connection", |app| {
        matches!(app.online().phase(), Phase::Lost(_)) && !app.debug_state().is_halted()
    });
    assert_eq!(harness.state().debug_state().shown(), None);
}

#[test]
fn a_controller_without_debugging_is_named_as_such_when_asked_to_halt() {
    use egui_kittest::kittest::Queryable as _;

    let (port, _stop) = controller_with(0, false);
    let project = example_copy(|dir| {
        replace_in(dir, "rivet.toml", "port = 5020", &format!("port = {port}"));
    });
    let mut harness = studio(project.path());
    harness.state_mut().set_target(TargetKind::Controller);
    login_with_download(&mut harness);
    harness.get_by_label("Debug").click();
    // Logged in, the studio repaints every 100 ms, so `run` may never settle under load.
    harness.run_steps(3);
    harness.get_by_label_contains("Halt all").click();
    harness.step();
    harness.step();
    let status = harness.state().status().map(|status| status.text.clone());
    assert_eq!(
        status.as_deref(),
        Some("the target does not offer debugging")
    );
    assert!(!harness.state().debug_state().is_halted());
}
