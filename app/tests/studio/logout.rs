//! Logging out of a controller that has a password ends the studio's token with `LOGOUT`
//! before the connection closes, when the user logs out and when the studio quits.

use std::sync::{Arc, Mutex};
use std::time::Instant;

use crate::support::{PATIENCE, example_copy, login_with_download, replace_in, studio, wait_until};
use app::studio::TargetKind;
use egui::{Key, Modifiers};
use egui_kittest::kittest::Queryable as _;
use runtime::areas::LocatedAreas;
use runtime::modbus::{ConnectionClosed, MapSlot, ModbusMap, ServerOptions, serve};
use runtime::online::OnlineServices;
use runtime::scheduler::{Scheduler, SchedulerOptions};

const PASSWORD: &str = "studio secret";

/// A soft PLC with [`PASSWORD`] in its own thread, for the life of the test. Returns its port
/// and, for each connection that closed, how many connections still held a token just before
/// (so 0 when the closing connection had logged out first).
fn controller() -> (u16, Arc<Mutex<Vec<usize>>>) {
    let listener = std::net::TcpListener::bind(("127.0.0.1", 0)).unwrap();
    listener.set_nonblocking(true).unwrap();
    let port = listener.local_addr().unwrap().port();
    let logged_in_at_close = Arc::new(Mutex::new(Vec::new()));
    let seen = Arc::clone(&logged_in_at_close);
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
                OnlineServices::new(scheduler, Some(PASSWORD.to_owned()))
                    .with_map(Arc::clone(&map)),
            );
            let closed = services.closed_handler();
            let watching = Arc::clone(&services);
            let noting: ConnectionClosed = Arc::new(move |connection| {
                seen.lock().unwrap().push(watching.logged_in_connections());
                closed(connection);
            });
            let options = ServerOptions {
                custom: Some(services.handler()),
                closed: Some(noting),
                ..ServerOptions::default()
            };
            let listener = tokio::net::TcpListener::from_std(listener).unwrap();
            let _ = serve(listener, areas, map, options).await;
        });
    });
    (port, logged_in_at_close)
}

/// Waits until `closes` has `count` entries.
fn wait_for_closes(closes: &Mutex<Vec<usize>>, count: usize) -> Vec<usize> {
    let start = Instant::now();
    loop {
        let seen = closes.lock().unwrap().clone();
        if seen.len() >= count {
            return seen;
        }
        assert!(
            start.elapsed() < PATIENCE,
            "waited for {count} closes: {seen:?}"
        );
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
}

#[test]
fn logging_out_and_quitting_end_the_token_before_the_connection_closes() {
    let (port, closes) = controller();
    let project = example_copy(|dir| {
        replace_in(dir, "rivet.toml", "port = 5020", &format!("port = {port}"));
    });
    let mut harness = studio(project.path());
    harness.state_mut().set_target(TargetKind::Controller);
    harness.step();
    harness.get_by_label("Password").focus();
    harness.step();
    harness.get_by_label("Password").type_text(PASSWORD);
    harness.step();
    login_with_download(&mut harness);
    assert!(closes.lock().unwrap().is_empty());

    // Ctrl+F8: the session logs out, then closes; the token was gone before the close.
    harness.key_press_modifiers(Modifiers::COMMAND, Key::F8);
    harness.step();
    assert_eq!(wait_for_closes(&closes, 1), [0]);

    // Logged in again, the studio quits: dropping it waits for the logout.
    harness.key_press_modifiers(Modifiers::ALT, Key::F8);
    wait_until(&mut harness, "the second login", |app| {
        app.online().is_online()
    });
    drop(harness);
    assert_eq!(wait_for_closes(&closes, 2), [0, 0]);
}
