//! Helpers shared by the studio's workflow tests: a temporary copy of the example project, a
//! harness, waiting for background work, and typing into the watch pane.

use std::path::Path;
use std::time::{Duration, Instant};

use app::studio::{Phase, Settings, StudioApp};
use egui::{Key, Modifiers};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;

/// How long a step may take on a loaded CI machine before the test fails.
pub const PATIENCE: Duration = Duration::from_secs(30);

/// A copy of the example project, changed by `edit` (given the copy's folder).
pub fn example_copy(edit: impl Fn(&Path)) -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    assets::copy_example_project(dir.path()).unwrap();
    edit(dir.path());
    dir
}

pub fn studio(project: &Path) -> Harness<'static, StudioApp> {
    let app = StudioApp::new(Settings::default(), Some(project.to_owned()));
    let mut harness = Harness::builder()
        .with_size([1400.0, 900.0])
        .build_ui_state(|ui, app: &mut StudioApp| app.ui(ui), app);
    harness.step();
    harness
}

/// Steps the studio until `done` holds, failing with `what` after [`PATIENCE`].
pub fn wait_until(
    harness: &mut Harness<'_, StudioApp>,
    what: &str,
    done: impl Fn(&StudioApp) -> bool,
) {
    let start = Instant::now();
    loop {
        harness.step();
        if done(harness.state()) {
            return;
        }
        assert!(
            start.elapsed() < PATIENCE,
            "waited {PATIENCE:?} for {what}; status: {:?}, phase: {:?}, forces: {:?}",
            harness.state().status(),
            harness.state().online().phase(),
            harness.state().online().forced_values()
        );
        std::thread::sleep(Duration::from_millis(20));
    }
}

pub fn value(app: &StudioApp, path: &str) -> Option<(String, bool)> {
    app.online()
        .value(path)
        .map(|value| (value.text.clone(), value.forced))
}

/// Brings the tab labelled `label` forward.
pub fn show_tab(harness: &mut Harness<'_, StudioApp>, label: &str) {
    harness.get_by_label(label).click();
    harness.step();
    harness.step();
}

/// Adds `path` to the shown watch list through the "Add variable" field.
pub fn watch(harness: &mut Harness<'_, StudioApp>, path: &str) {
    harness.get_by_label("Add variable").click();
    harness.step();
    harness.get_by_label("Add variable").type_text(path);
    harness.step();
    harness.key_press(Key::Enter);
    harness.step();
    harness.step();
}

/// Types a prepared value for `path` and commits it by pressing Enter.
pub fn prepare(harness: &mut Harness<'_, StudioApp>, path: &str, text: &str) {
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

/// Replaces `from` by `to` in the project file `file` of the project in `dir`.
pub fn replace_in(dir: &Path, file: &str, from: &str, to: &str) {
    let path = dir.join(file);
    let text = std::fs::read_to_string(&path).unwrap();
    assert!(text.contains(from), "{file} holds no '{from}'");
    std::fs::write(&path, text.replace(from, to)).unwrap();
}

/// Logs in with Alt+F8 to a target without the project's program, answers the download
/// question with Download and waits until the studio is online.
pub fn login_with_download(harness: &mut Harness<'_, StudioApp>) {
    harness.key_press_modifiers(Modifiers::ALT, Key::F8);
    wait_until(harness, "the download question", |app| {
        matches!(app.online().phase(), Phase::ConfirmDownload { .. })
    });
    harness.step();
    harness.get_by_label("Download").click();
    wait_until(harness, "the download", |app| {
        *app.online().phase() == Phase::Online
    });
}
