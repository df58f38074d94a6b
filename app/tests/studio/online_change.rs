//! Logging in to a simulator that runs another version of the project (`docs/debugging.md`
//! §6): the dialog offers the online change and lists it, the change keeps the program running
//! with its values, and a task configuration change is refused with its reason and leaves only
//! the download, which stops the program and leaves it stopped until the user starts it.

use std::path::Path;

use app::studio::Phase;
use egui::{Key, Modifiers};
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT as _, Queryable as _};
use online::TargetState;

use app::studio::StudioApp;

use crate::support::{
    example_copy, login_with_download, prepare, replace_in, show_tab, studio, value, wait_until,
    watch,
};

/// A counter of the program `Main`, declared and counted by one.
fn add_counter(dir: &Path) {
    let declarations = dir.join("application/Main.pou.toml");
    let mut text = std::fs::read_to_string(&declarations).unwrap();
    text.push_str("\n[[variable]]\nname = \"udiTicks\"\nsection = \"VAR\"\ntype = \"UDINT\"\n");
    std::fs::write(&declarations, text).unwrap();
    let body = dir.join("application/Main.st");
    let mut text = std::fs::read_to_string(&body).unwrap();
    text.push_str("\nudiTicks := udiTicks + 1;\n");
    std::fs::write(&body, text).unwrap();
}

/// Logs out, opens the project again after `edit` changed its files, and logs in: the
/// studio builds, sends the program and asks how to log in.
fn change_and_log_in(harness: &mut Harness<'_, StudioApp>, dir: &Path, edit: impl Fn(&Path)) {
    harness.key_press_modifiers(Modifiers::COMMAND, Key::F8);
    harness.step();
    edit(dir);
    harness.state_mut().open_project(dir);
    harness.step();
    harness.key_press_modifiers(Modifiers::ALT, Key::F8);
    wait_until(harness, "the login choices", |app| {
        matches!(app.online().phase(), Phase::ChooseLogin(_))
    });
    // The dialog takes a few frames to find its size and place before it is clicked.
    for _ in 0..4 {
        harness.step();
    }
}

#[test]
fn an_online_change_keeps_the_counter_and_a_task_change_offers_only_the_download_which_stops() {
    let project = example_copy(add_counter);
    let dir = project.path();
    let mut harness = studio(dir);
    login_with_download(&mut harness);
    harness.key_press(Key::F5);
    wait_until(&mut harness, "the start", |app| {
        app.online().target_state() == Some(TargetState::Running)
    });
    // The counter gets a value a restarted program could not reach in the test's time.
    show_tab(&mut harness, "Watch");
    watch(&mut harness, "Main.udiTicks");
    prepare(&mut harness, "Main.udiTicks", "1000000");
    harness.key_press_modifiers(Modifiers::COMMAND, Key::F7);
    wait_until(&mut harness, "the written counter", |app| {
        value(app, "Main.udiTicks")
            .and_then(|(text, _)| text.parse::<u64>().ok())
            .is_some_and(|ticks| ticks >= 1_000_000)
    });

    // A variable added and an expression changed: the online change is offered and listed.
    change_and_log_in(&mut harness, dir, |dir| {
        replace_in(
            dir,
            "application/Main.pou.toml",
            "name = \"udiTicks\"",
            "name = \"udiTicks\"\nsection = \"VAR\"\ntype = \"UDINT\"\n\n[[variable]]\nname = \"udiSeen\"",
        );
        replace_in(
            dir,
            "application/Main.st",
            "udiTicks := udiTicks + 1;",
            "udiTicks := udiTicks + 2;\nudiSeen := udiTicks;",
        );
    });
    let choice = harness.get_by_label("Login with online change");
    assert!(
        !choice.accesskit_node().is_disabled(),
        "the online change is possible"
    );
    assert!(harness.query_by_label("Login with download").is_some());
    assert!(harness.query_by_label("Login without change").is_some());
    assert!(harness.query_by_label_contains("Variables added").is_some());
    assert!(harness.query_by_label_contains("Main.udiSeen").is_some());
    assert!(
        harness
            .query_by_label_contains("POUs whose code changed")
            .is_some()
    );
    harness.get_by_label("Login with online change").click();
    wait_until(&mut harness, "the online change", |app| {
        *app.online().phase() == Phase::Online
    });
    assert_eq!(
        harness.state().online().target_state(),
        Some(TargetState::Running)
    );
    // The counter kept its value, and the new code runs: the new variable follows it.
    show_tab(&mut harness, "Watch");
    watch(&mut harness, "Main.udiTicks");
    watch(&mut harness, "Main.udiSeen");
    let number = |app: &StudioApp, path: &str| {
        value(app, path)
            .and_then(|(text, _)| text.parse::<u64>().ok())
            .unwrap_or(0)
    };
    wait_until(
        &mut harness,
        "the carried counter and the new variable",
        |app| number(app, "Main.udiTicks") >= 1_000_000 && number(app, "Main.udiSeen") >= 1_000_000,
    );

    // The main task's interval changes: no online change, the reason, and the download.
    change_and_log_in(&mut harness, dir, |dir| {
        replace_in(
            dir,
            "rivet.toml",
            "interval_us = 10000",
            "interval_us = 20000",
        );
    });
    let choice = harness.get_by_label("Login with online change");
    assert!(choice.accesskit_node().is_disabled());
    assert!(
        harness
            .query_by_label_contains("the task configuration changed")
            .is_some()
    );
    assert!(
        harness
            .query_by_label_contains("task 'MainTask': interval changed from 10 ms to 20 ms")
            .is_some()
    );
    harness.get_by_label("Login with download").click();
    wait_until(&mut harness, "the download", |app| {
        *app.online().phase() == Phase::Online
    });
    // As CODESYS's login with download: the running program was stopped, and the new one
    // waits for the user's start with its variables at their initial values.
    assert_eq!(
        harness.state().online().target_state(),
        Some(TargetState::Stopped)
    );
    show_tab(&mut harness, "Watch");
    watch(&mut harness, "Main.udiTicks");
    wait_until(&mut harness, "the counter at its initial value", |app| {
        value(app, "Main.udiTicks").is_some_and(|(text, _)| text == "0")
    });
    // A few refreshes later it still is: no cycle ran.
    for _ in 0..20 {
        harness.step();
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    assert_eq!(
        value(harness.state(), "Main.udiTicks").map(|(text, _)| text),
        Some("0".to_owned())
    );
    harness.key_press(Key::F5);
    wait_until(&mut harness, "the start", |app| {
        app.online().target_state() == Some(TargetState::Running)
    });
    wait_until(&mut harness, "the counter counting from its start", |app| {
        value(app, "Main.udiTicks")
            .and_then(|(text, _)| text.parse::<u64>().ok())
            .is_some_and(|ticks| ticks > 0 && ticks < 1_000_000)
    });
}
