//! A third-party Modbus TCP device of the project monitored, written, forced and released from
//! the watch and forces panes without logging in to the controller.

use std::sync::{Arc, Mutex};

use crate::support::{
    example_copy, prepare, replace_in, show_tab, studio, value, wait_until, watch,
};
use egui::{Key, Modifiers};
use egui_kittest::kittest::Queryable as _;
use runtime::areas::LocatedAreas;
use runtime::modbus::{MapSlot, ModbusMap, ServerOptions, serve};

/// A Modbus TCP server on loopback standing in for the drive: its holding registers are the
/// `%QW` area of `areas`. Returns its port; it runs until the test ends.
pub(crate) fn drive(areas: Arc<Mutex<LocatedAreas>>) -> u16 {
    let listener = std::net::TcpListener::bind("127.0.0.1:0").unwrap();
    listener.set_nonblocking(true).unwrap();
    let port = listener.local_addr().unwrap().port();
    std::thread::spawn(move || {
        let runtime = tokio::runtime::Builder::new_current_thread()
            .enable_all()
            .build()
            .unwrap();
        runtime.block_on(async move {
            let listener = tokio::net::TcpListener::from_std(listener).unwrap();
            let _ = serve(
                listener,
                areas,
                MapSlot::new(ModbusMap::default()),
                ServerOptions::default(),
            )
            .await;
        });
    });
    port
}

#[test]
fn a_modbus_device_is_watched_written_forced_and_released_without_a_login() {
    let areas = Arc::new(Mutex::new(LocatedAreas::new(16, 64, 8192)));
    let port = drive(Arc::clone(&areas));
    // The example's belt drive, on the loopback server, with its speed in holding registers
    // 0 and 1 so it can be written.
    let project = example_copy(|dir| {
        replace_in(
            dir,
            "rivet.toml",
            "host = \"192.168.1.50\"\nport = 502",
            &format!("host = \"127.0.0.1\"\nport = {port}"),
        );
        replace_in(
            dir,
            "rivet.toml",
            "table = \"input_register\"",
            "table = \"holding_register\"",
        );
        // The project's trace records the drive's speed, 20 polls.
        std::fs::write(
            dir.join("application/Diagnostics/TRC_Conveyor.trace.toml"),
            "task = \"MainTask\"\nevery_n_cycles = 1\nrecord_count = 20\n\n[[variable]]\npath = \"GVL_Machine.rBeltSpeedActual\"\n",
        )
        .unwrap();
    });
    let mut harness = studio(project.path());
    show_tab(&mut harness, "Watch");
    watch(&mut harness, "GVL_Machine.rBeltSpeedActual");
    wait_until(&mut harness, "the drive's speed", |app| {
        value(app, "GVL_Machine.rBeltSpeedActual").is_some()
    });
    assert!(!harness.state().online().is_logged_in());

    // Ctrl+F7 writes the prepared value to the drive's registers, high word first.
    prepare(&mut harness, "GVL_Machine.rBeltSpeedActual", "33.5");
    harness.key_press_modifiers(Modifiers::COMMAND, Key::F7);
    wait_until(&mut harness, "the written speed", |app| {
        value(app, "GVL_Machine.rBeltSpeedActual") == Some(("33.5".into(), false))
    });
    // The watch pane shows it, without a login.
    harness.step();
    assert!(harness.query_by_label("33.5").is_some());
    let registers = {
        let areas = areas.lock().unwrap();
        let q = &areas.output;
        [
            u16::from_le_bytes([q[0], q[1]]),
            u16::from_le_bytes([q[2], q[3]]),
        ]
    };
    let bits = 33.5f32.to_bits();
    assert_eq!(registers, [(bits >> 16) as u16, bits as u16]);

    // F7 forces it: the studio writes it again before every poll, and the forces pane lists it.
    prepare(&mut harness, "GVL_Machine.rBeltSpeedActual", "7.25");
    harness.key_press(Key::F7);
    wait_until(&mut harness, "the forced speed", |app| {
        value(app, "GVL_Machine.rBeltSpeedActual") == Some(("7.25".into(), true))
    });
    harness.get_by_label_contains("Forces (").click();
    harness.step();
    harness.step();
    assert!(
        harness
            .query_by_label("GVL_Machine.rBeltSpeedActual")
            .is_some()
    );

    // Alt+F7 releases it.
    harness.key_press_modifiers(Modifiers::ALT, Key::F7);
    wait_until(&mut harness, "the released force", |app| {
        value(app, "GVL_Machine.rBeltSpeedActual") == Some(("7.25".into(), false))
    });
    assert!(harness.state().online().forced_values().is_empty());

    // The trace pane records the device by polling, without a login.
    show_tab(&mut harness, "Trace");
    harness.get_by_label("Start trace").click();
    harness.step();
    harness.step();
    wait_until(&mut harness, "the device trace", |app| {
        app.online().trace().phase() == app::studio::TracePhase::Uploaded
    });
    let trace = harness.state().online().trace();
    assert_eq!(trace.samples().len(), 20);
    assert!(
        trace
            .samples()
            .iter()
            .all(|s| s.values[0] == 7.25f32.to_le_bytes().to_vec())
    );
}
