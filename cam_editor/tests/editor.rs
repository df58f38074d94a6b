//! The cam editor driven through its accessibility tree and the pointer, as a user would, with
//! the edits it returns applied the way the app applies them: one gesture, one edit.

#![allow(clippy::unwrap_used, clippy::expect_used)] // Test helpers may panic: a panic is a failed test.

use cam_editor::{CamEditor, CamEditorTexts, import_points};
use egui::{Event, Key, Modifiers, PointerButton, Pos2, Role, vec2};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use project_model::{CamKeyPoint, CamProfile, CamTable, MotionLaw, Object, TappetAction};

/// What the app would hold: the cam, the editor, and every edit and request returned.
struct App {
    cam: CamTable,
    editor: CamEditor,
    edits: Vec<(String, CamTable)>,
    import_requests: usize,
    export_requests: usize,
}

fn harness(cam: CamTable) -> Harness<'static, App> {
    let app = App {
        cam,
        editor: CamEditor::new(),
        edits: Vec::new(),
        import_requests: 0,
        export_requests: 0,
    };
    let mut harness = Harness::builder()
        .with_size([1100.0, 1000.0])
        // Real frame times, so two clicks a few frames apart are a double click.
        .with_step_dt(1.0 / 60.0)
        .build_ui_state(
            |ui, app: &mut App| {
                let texts = CamEditorTexts::default();
                let output = app.editor.show(ui, &app.cam, None, &texts, false);
                if let Some((label, cam)) = output.edit {
                    // The app applies the edit after the frame, as one undo step.
                    app.cam = cam.clone();
                    app.edits.push((label, cam));
                }
                app.import_requests += usize::from(output.import_csv);
                app.export_requests += usize::from(output.export_csv);
            },
            app,
        );
    harness.run();
    harness
}

/// The example project's flying knife cam.
fn knife() -> CamTable {
    let loaded = project_model::load_project(&assets::example_project_dir()).unwrap();
    match loaded.project.application.object("CAM_Knife") {
        Some(Object::CamTable(cam)) => cam.clone(),
        other => panic!("CAM_Knife is {other:?}"),
    }
}

fn key_points(cam: &CamTable) -> Vec<CamKeyPoint> {
    match &cam.profile {
        CamProfile::Segments { start, segments } => std::iter::once(*start)
            .chain(segments.iter().map(|segment| segment.end))
            .collect(),
        CamProfile::Points { .. } => panic!("a point table"),
    }
}

fn laws(cam: &CamTable) -> Vec<MotionLaw> {
    match &cam.profile {
        CamProfile::Segments { segments, .. } => segments.iter().map(|s| s.law).collect(),
        CamProfile::Points { .. } => Vec::new(),
    }
}

/// Replaces the text of the field labelled `label` with `text` and presses Enter.
fn type_over(harness: &mut Harness<'static, App>, label: &str, text: &str) {
    harness
        .get_by_role_and_label(Role::TextInput, label)
        .focus();
    harness.run();
    harness.key_press_modifiers(Modifiers::COMMAND, Key::A);
    harness.run();
    harness
        .get_by_role_and_label(Role::TextInput, label)
        .type_text(text);
    harness.run();
    harness.key_press(Key::Enter);
    harness.run();
}

fn show_tab(harness: &mut Harness<'static, App>, tab: &str) {
    harness.get_by_label(tab).click();
    harness.run();
}

/// A press and a release at `pos`.
fn click_at(harness: &mut Harness<'static, App>, pos: Pos2) {
    harness.hover_at(pos);
    harness.run();
    for pressed in [true, false] {
        harness.event(Event::PointerButton {
            pos,
            button: PointerButton::Primary,
            pressed,
            modifiers: Modifiers::NONE,
        });
        harness.step();
    }
    harness.run();
}

/// Two presses and releases at `pos`, one frame apart.
fn double_click_at(harness: &mut Harness<'static, App>, pos: Pos2) {
    harness.hover_at(pos);
    harness.run();
    for pressed in [true, false, true, false] {
        harness.event(Event::PointerButton {
            pos,
            button: PointerButton::Primary,
            pressed,
            modifiers: Modifiers::NONE,
        });
    }
    harness.step();
    harness.run();
}

/// Presses at `from`, moves to `to` in steps and releases there.
fn drag(harness: &mut Harness<'static, App>, from: Pos2, to: Pos2) {
    harness.hover_at(from);
    harness.run();
    harness.drag_at(from);
    harness.step();
    for step in 1..=10 {
        harness.hover_at(from + (to - from) * (step as f32 / 10.0));
        harness.step();
    }
    // Nothing is returned while the drag is in progress.
    assert!(
        harness.state().edits.is_empty(),
        "{:?}",
        harness.state().edits
    );
    harness.drop_at(to);
    harness.run();
}

#[test]
fn dragging_a_key_point_gives_one_edit_and_keeps_the_master_order() {
    let original = CamTable::codesys_default("Cam");
    let mut harness = harness(original.clone());
    let state = harness.state();
    let from = state.editor.key_point_screen_pos(&state.cam, 1).unwrap();
    // Far to the right, past key point 3 at 240, and up.
    drag(&mut harness, from, from + vec2(600.0, -60.0));
    let edits = &harness.state().edits;
    assert_eq!(edits.len(), 1, "{edits:?}");
    assert_eq!(edits[0].0, "Move key point 2");
    let moved = key_points(&edits[0].1);
    let before = key_points(&original);
    assert!(
        moved[1].master > 120.0 && moved[1].master < 240.0,
        "{:?}",
        moved[1]
    );
    assert!(moved[1].slave > 120.0, "{:?}", moved[1]);
    // Only that key point moved.
    assert_eq!(
        (moved[0], moved[2], moved[3]),
        (before[0], before[2], before[3])
    );
}

#[test]
fn a_key_point_past_its_neighbour_is_refused_with_the_reason() {
    let mut harness = harness(CamTable::codesys_default("Cam"));
    show_tab(&mut harness, "Cam table");
    type_over(&mut harness, "Key point 2 X", "300");
    assert!(
        harness.state().edits.is_empty(),
        "{:?}",
        harness.state().edits
    );
    assert!(
        harness
            .query_by_label_contains(
                "Key point 2 X: cam Cam: segment 2 (Poly5, 300..240): the master position must increase"
            )
            .is_some(),
        "no reason shown"
    );
    // The cam as the app holds it is untouched, and a valid value is then accepted.
    assert_eq!(harness.state().cam, CamTable::codesys_default("Cam"));
    type_over(&mut harness, "Key point 2 X", "100");
    let edits = &harness.state().edits;
    assert_eq!(edits.len(), 1);
    assert_eq!(key_points(&edits[0].1)[1].master, 100.0);
    assert!(harness.query_by_label_contains("must increase").is_none());
}

#[test]
fn escape_abandons_a_typed_value() {
    let mut harness = harness(CamTable::codesys_default("Cam"));
    show_tab(&mut harness, "Cam table");
    let label = "Key point 2 Y";
    harness
        .get_by_role_and_label(Role::TextInput, label)
        .focus();
    harness.run();
    harness.key_press_modifiers(Modifiers::COMMAND, Key::A);
    harness
        .get_by_role_and_label(Role::TextInput, label)
        .type_text("999");
    harness.run();
    harness.key_press(Key::Escape);
    harness.run();
    assert!(harness.state().edits.is_empty());
    let shown = harness
        .get_by_role_and_label(Role::TextInput, label)
        .value();
    assert_eq!(shown.as_deref(), Some("120"));
}

#[test]
fn a_law_that_cannot_meet_the_boundary_values_is_refused_and_another_is_applied() {
    let mut harness = harness(CamTable::codesys_default("Cam"));
    show_tab(&mut harness, "Cam table");
    harness.get_by_label("Segment 1 law").click();
    harness.run();
    harness.get_by_label("Cycloid").click();
    harness.run();
    assert!(harness.state().edits.is_empty());
    assert!(
        harness
            .query_by_label_contains("segment 1 (Cycloid, 0..120): the law cannot start at velocity 0 and end at velocity 1")
            .is_some()
    );
    harness.get_by_label("Segment 2 law").click();
    harness.run();
    harness.get_by_label("Line").click();
    harness.run();
    let edits = &harness.state().edits;
    assert_eq!(edits.len(), 1);
    assert_eq!(
        laws(&edits[0].1),
        [MotionLaw::Poly5, MotionLaw::Line, MotionLaw::Poly5]
    );
}

#[test]
fn inserting_and_deleting_a_key_point_split_and_merge_a_segment() {
    let original = CamTable::codesys_default("Cam");
    let mut harness = harness(original.clone());
    show_tab(&mut harness, "Cam table");
    harness
        .get_by_label("Insert key point in segment 1")
        .click();
    harness.run();
    let inserted = key_points(&harness.state().cam);
    assert_eq!(inserted.len(), 5);
    assert_eq!(inserted[1].master, 60.0);
    harness.get_by_label("Delete key point 2").click();
    harness.run();
    assert_eq!(harness.state().edits.len(), 2);
    assert_eq!(harness.state().cam, original);
}

#[test]
fn properties_refuse_an_empty_range_and_a_word_in_place() {
    let mut harness = harness(CamTable::codesys_default("Cam"));
    show_tab(&mut harness, "Properties");
    type_over(&mut harness, "Master start", "400");
    assert!(
        harness
            .query_by_label_contains("Master start: the start must be below the end")
            .is_some()
    );
    type_over(&mut harness, "Slave end", "abc");
    assert!(
        harness
            .query_by_label_contains("Slave end: \"abc\" is not a number")
            .is_some()
    );
    assert!(harness.state().edits.is_empty());
    type_over(&mut harness, "Master end", "720");
    let edits = &harness.state().edits;
    assert_eq!(edits.len(), 1);
    assert_eq!(edits[0].1.master.end, 720.0);
    assert_eq!(key_points(&edits[0].1)[3].master, 720.0);
}

#[test]
fn a_table_format_refuses_fewer_than_two_elements() {
    let mut harness = harness(CamTable::codesys_default("Cam"));
    show_tab(&mut harness, "Properties");
    harness.get_by_label("1-D table").click();
    harness.run();
    assert_eq!(
        harness.state().cam.compile_format,
        project_model::CamCompileFormat::Table1d { elements: 256 }
    );
    type_over(&mut harness, "Elements", "1");
    assert!(
        harness
            .query_by_label_contains("a table needs at least 2 elements")
            .is_some()
    );
    assert_eq!(harness.state().edits.len(), 1);
}

#[test]
fn a_periodic_cam_whose_end_does_not_join_its_start_shows_a_warning() {
    // CAM_Knife runs periodically (smooth transition) from slave 0 to 360 with a slave period
    // of 360, so its end joins its start: no warning. The velocities join too (Poly5 to 1, Line
    // at 1, Poly5 from 1).
    let cam = knife();
    assert_eq!(cam.period.slave_period, Some(360.0));
    assert_eq!(cam_editor::continuity_warnings(&cam).unwrap(), Vec::new());
    // Without the slave period its end 360 is compared with its start 0.
    let mut cam = cam;
    cam.period.slave_period = None;
    let warnings = cam_editor::continuity_warnings(&cam).unwrap();
    assert_eq!(warnings.len(), 1, "{warnings:?}");
    let harness = harness(cam);
    // In the list under the plots and on the mark at the joint.
    let shown = harness
        .query_all_by_label_contains("Key point 1, X 0: Position 360 / 0")
        .count();
    assert_eq!(shown, 2);
}

#[test]
fn clicking_a_tappet_end_cycles_its_pass_action() {
    let mut harness = harness(knife());
    let rect = harness.state().editor.tappet_screen_rect(0, 0).unwrap();
    // Upper half: the positive pass, On -> Off.
    click_at(&mut harness, rect.center() - vec2(0.0, rect.height() / 4.0));
    let edits = &harness.state().edits;
    assert_eq!(edits.len(), 1, "{edits:?}");
    let tappet = edits[0].1.tracks[0].tappets[0];
    assert_eq!(
        (tappet.on_positive, tappet.on_negative),
        (TappetAction::Off, TappetAction::Off)
    );
    // Lower half: the negative pass, Off -> Invert.
    click_at(&mut harness, rect.center() + vec2(0.0, rect.height() / 4.0));
    let tappet = harness.state().cam.tracks[0].tappets[0];
    assert_eq!(tappet.on_negative, TappetAction::Invert);
    // The tappet is selected now; Delete removes it.
    harness.key_press(Key::Delete);
    harness.run();
    assert_eq!(harness.state().cam.tracks[0].tappets.len(), 1);
    assert_eq!(harness.state().edits.len(), 3);
}

#[test]
fn dragging_a_tappet_moves_it_in_one_edit_and_a_double_click_adds_one() {
    let mut harness = harness(knife());
    let rect = harness.state().editor.tappet_screen_rect(0, 0).unwrap();
    drag(&mut harness, rect.center(), rect.center() + vec2(80.0, 0.0));
    let edits = &harness.state().edits;
    assert_eq!(edits.len(), 1, "{edits:?}");
    let position = edits[0].1.tracks[0].tappets[0].position;
    assert!(position > 30.0 && position < 90.0, "{position}");

    let lane = harness.get_by_label("Track 2").rect();
    let at = lane.center() + vec2(lane.width() / 4.0, 0.0);
    double_click_at(&mut harness, at);
    let track = &harness.state().cam.tracks[1];
    assert_eq!(track.tappets.len(), 2, "{:?}", track.tappets);
    assert_eq!(harness.state().edits.len(), 2);
}

#[test]
fn tracks_are_added_renamed_and_removed() {
    let mut harness = harness(knife());
    show_tab(&mut harness, "Tappets");
    harness.get_by_label("Add track").click();
    harness.run();
    assert_eq!(harness.state().cam.tracks.last().unwrap().id, 3);
    type_over(&mut harness, "Track 3 name", "Labeller");
    type_over(&mut harness, "Track 3 dead time (µs)", "-1500");
    let track = harness.state().cam.tracks.last().unwrap();
    assert_eq!(
        (track.name.as_str(), track.dead_time_us),
        ("Labeller", -1500)
    );
    type_over(&mut harness, "Track 3 hysteresis", "x");
    assert!(
        harness
            .query_by_label_contains("\"x\" is not a number")
            .is_some()
    );
    harness.get_by_label("Remove track 3").click();
    harness.run();
    assert_eq!(harness.state().cam.tracks.len(), 2);
    assert_eq!(harness.state().edits.len(), 4);
}

#[test]
fn import_and_export_are_requests_for_the_app() {
    let mut harness = harness(CamTable::codesys_default("Cam"));
    harness.get_by_label("Import CSV…").click();
    harness.run();
    harness.get_by_label("Export CSV…").click();
    harness.run();
    assert_eq!(
        (
            harness.state().import_requests,
            harness.state().export_requests
        ),
        (1, 1)
    );
}

#[test]
fn a_csv_import_replaces_the_profile_and_a_bad_file_names_the_line() {
    let cam = CamTable::codesys_default("Cam");
    let imported = import_points(&cam, "master,slave\n0,0\n180,90\n360,0\n").unwrap();
    let CamProfile::Points { points, .. } = &imported.profile else {
        panic!("not a point table");
    };
    assert_eq!(points.len(), 3);
    assert_eq!(imported.tracks, cam.tracks);
    let error = import_points(&cam, "master,slave\n0,0\n180,90\n90,0\n").unwrap_err();
    assert_eq!(
        error.to_string(),
        "line 4: master 90 is not greater than 180 on line 3"
    );
    // The imported table shows its rows.
    let mut harness = harness(imported);
    show_tab(&mut harness, "Cam table");
    assert!(harness.query_by_label("Row 3 Y").is_some());
    harness.get_by_label("Cubic").click();
    harness.run();
    let CamProfile::Points { interpolation, .. } = &harness.state().cam.profile else {
        panic!("not a point table");
    };
    assert_eq!(*interpolation, project_model::PointInterpolation::Cubic);
    assert_eq!(harness.state().edits.len(), 1);
}

#[test]
fn a_read_only_editor_changes_nothing() {
    let app = App {
        cam: CamTable::codesys_default("Cam"),
        editor: CamEditor::new(),
        edits: Vec::new(),
        import_requests: 0,
        export_requests: 0,
    };
    let mut harness = Harness::builder()
        .with_size([1100.0, 1000.0])
        .build_ui_state(
            |ui, app: &mut App| {
                let output = app
                    .editor
                    .show(ui, &app.cam, None, &CamEditorTexts::default(), true);
                if let Some(edit) = output.edit {
                    app.edits.push(edit);
                }
            },
            app,
        );
    harness.run();
    let from = harness
        .state()
        .editor
        .key_point_screen_pos(&harness.state().cam, 1)
        .unwrap();
    drag(&mut harness, from, from + vec2(40.0, -40.0));
    show_tab(&mut harness, "Cam table");
    assert!(
        harness
            .query_by_label("Insert key point in segment 1")
            .is_none()
    );
    assert!(harness.state().edits.is_empty());
}

#[test]
fn a_key_point_of_a_dense_table_is_dragged_by_its_handle_near_the_pointer() {
    let mut cam = CamTable::codesys_default("Dense");
    let points = (0..2_000)
        .map(|i| project_model::CamTablePoint {
            master: f64::from(i) * 0.18,
            slave: f64::from(i % 7),
        })
        .collect();
    cam.profile = CamProfile::Points {
        interpolation: project_model::PointInterpolation::Linear,
        points,
    };
    let mut harness = harness(cam);
    let state = harness.state();
    let from = state
        .editor
        .key_point_screen_pos(&state.cam, 1_000)
        .unwrap();
    drag(&mut harness, from, from + vec2(0.0, -30.0));
    let edits = &harness.state().edits;
    assert_eq!(
        edits.len(),
        1,
        "{:?}",
        edits.iter().map(|e| &e.0).collect::<Vec<_>>()
    );
    assert!(edits[0].0.starts_with("Move key point"), "{}", edits[0].0);
}
