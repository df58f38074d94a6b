//! The trace view drawn in a test harness: its toolbar, its output and its messages.

#![allow(clippy::unwrap_used)]

use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;

use super::*;

/// Three cycles of an analogue and a BOOL variable, the trigger on the second.
fn sample_data() -> TraceData {
    TraceData {
        variables: vec![
            TraceSeries {
                path: "PLC_PRG.speed".into(),
                color: parse_color("#ff8000"),
                is_bool: false,
            },
            TraceSeries {
                path: "PLC_PRG.running".into(),
                color: None,
                is_bool: true,
            },
        ],
        samples: (0..3)
            .map(|cycle| TraceSample {
                cycle,
                time_ns: cycle * 2_000_000,
                values: vec![cycle as f64 * 1.5, (cycle % 2) as f64],
            })
            .collect(),
        trigger_sample: Some(1),
        cycle_time_ns: Some(2_000_000),
    }
}

/// The view, its data and the output of the last frame.
struct State {
    view: TracePlotView,
    data: TraceData,
    output: TracePlotOutput,
}

fn harness(data: TraceData) -> Harness<'static, State> {
    let state = State {
        view: TracePlotView::default(),
        data,
        output: TracePlotOutput::default(),
    };
    Harness::builder()
        .with_size(egui::vec2(900.0, 600.0))
        .build_ui_state(
            |ui, state: &mut State| {
                let output = state.view.ui(ui, &state.data);
                // Keep a click's report until the test reads it; the frames after the click
                // report nothing.
                state.output.export_csv |= output.export_csv;
                state.output.export_png = state.output.export_png.or(output.export_png);
            },
            state,
        )
}

#[test]
fn export_csv_is_reported_to_the_app() {
    let mut harness = harness(sample_data());
    assert!(!harness.state().output.export_csv);
    harness.get_by_label("Export CSV…").click();
    harness.run();
    assert!(harness.state().output.export_csv);
    assert_eq!(harness.state().output.export_png, None);
}

#[test]
fn export_png_reports_the_plot_rect() {
    let mut harness = harness(sample_data());
    harness.get_by_label("Export PNG…").click();
    harness.run();
    let rect = harness.state().output.export_png.unwrap();
    assert!(rect.width() > 800.0 && rect.height() > 200.0, "{rect:?}");
    assert!(!harness.state().output.export_csv);
}

#[test]
fn the_toolbar_and_the_plot_are_labelled() {
    let harness = harness(sample_data());
    for label in [
        "One y-axis",
        "One plot per signal",
        "Reset view",
        "Trace plot",
    ] {
        harness.get_by_label(label);
    }
    harness.get_by_label("3 samples · cycle 2 ms");
}

#[test]
fn one_plot_per_signal_draws_a_plot_for_each_series() {
    let mut harness = harness(sample_data());
    harness.get_by_label("One plot per signal").click();
    harness.run();
    assert_eq!(harness.state().view.layout, TraceLayout::OnePlotPerSignal);
    assert_eq!(harness.query_all_by_label("Trace plot").count(), 2);
}

#[test]
fn a_click_places_cursor_a_and_a_shift_click_cursor_b() {
    let mut harness = harness(sample_data());
    let plot = harness.get_by_label("Trace plot").rect();
    // The samples lie at −2, 0 and 2 ms; the plot spans them plus a margin, so a click a little
    // right of the left edge is nearest the first sample and one left of the right edge the last.
    harness.get_by_label("Trace plot").hover();
    let left = egui::pos2(plot.left() + plot.width() * 0.1, plot.center().y);
    let right = egui::pos2(plot.left() + plot.width() * 0.9, plot.center().y);
    click_at(&mut harness, left, egui::Modifiers::NONE);
    click_at(&mut harness, right, egui::Modifiers::SHIFT);
    assert_eq!(harness.state().view.cursor_a_ms, Some(-2.0));
    assert_eq!(harness.state().view.cursor_b_ms, Some(2.0));
    // The table shows both readings and the difference: speed 0 → 3, Δt 4 ms.
    harness.get_by_label("4");
    assert_eq!(harness.query_all_by_label("3").count(), 2);
    harness.get_by_label("Clear cursors").click();
    harness.run();
    assert_eq!(harness.state().view.cursor_a_ms, None);
}

/// A press and release of the primary button at `pos` with `modifiers` held.
fn click_at(harness: &mut Harness<'static, State>, pos: egui::Pos2, modifiers: egui::Modifiers) {
    harness.hover_at(pos);
    harness.run();
    for pressed in [true, false] {
        harness.event(egui::Event::PointerButton {
            pos,
            button: egui::PointerButton::Primary,
            pressed,
            modifiers,
        });
        harness.run();
    }
}

#[test]
fn no_samples_shows_how_to_get_some_and_disables_export() {
    let mut harness = harness(TraceData::default());
    harness.get_by_label("No samples yet");
    harness.get_by_label("Export CSV…").click();
    harness.run();
    assert!(!harness.state().output.export_csv);
}

#[test]
fn readings_are_printed_for_people() {
    assert_eq!(format_reading(Some(1.0), true), "TRUE");
    assert_eq!(format_reading(Some(0.0), true), "FALSE");
    assert_eq!(format_reading(Some(2.5), false), "2.5");
    assert_eq!(format_reading(Some(-0.0000001), false), "0");
    assert_eq!(format_reading(Some(3.0), false), "3");
    assert_eq!(format_reading(None, false), "—");
}
