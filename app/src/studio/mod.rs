//! The studio window.

#[cfg(test)]
mod architecture_tests;
mod build_job;
mod cam_documents;
mod chrome;
mod command;
mod cycle_plot;
mod debug;
mod device_documents;
mod device_refusals;
mod device_tree;
mod dock;
mod document_view;
mod documents;
mod error_texts;
mod fonts;
mod graphical_documents;
mod i18n;
mod import_dialog;
#[cfg(test)]
mod literal_tests;
mod login_dialog;
mod modbus_online;
mod online;
mod pane;
mod pane_behavior;
mod pane_states;
mod panes;
mod property_view;
mod recovery;
mod recovery_schedule;
mod references;
mod reveal;
mod session;
mod settings;
mod status;
mod studio_app;
mod task_editor;
mod text_documents;
mod theme;
mod trace_plot;
mod trace_view;
mod tree_actions;
mod tree_node;
mod view;
mod watch_sources;

use std::path::PathBuf;

pub use build_job::{BuildMessage, BuildOutcome};
pub use cycle_plot::{CYCLE_HISTORY_POINTS, CycleFigures, CycleHistory, CyclePoint, cycle_plot_ui};
pub use debug::{
    Beneath, Breakpoint, BreakpointPlace, Breakpoints, DebugCommand, DebugState, DebugTarget,
    GraphicalPlace, HaltedTask, HitMode, StackFrame, place_at_line,
};
pub use dock::Dock;
pub use i18n::{Language, Text};
pub use online::{LiveValue, Online, Phase, TargetKind, TracePhase};
pub use pane::Pane;
pub use recovery::{Recovered, Recovery};
pub use session::{SaveAsError, Session};
pub use settings::{Settings, Theme};
pub use status::StatusMessage;
pub use studio_app::{StudioApp, StudioOptions};
pub use trace_plot::{
    CursorReading, CursorReadings, PngExportError, TraceData, TraceLayout, TracePlotOutput,
    TracePlotView, TraceSample, TraceSeries, crop_to_png, format_reading, nearest_sample_time,
    parse_color,
};
pub use tree_node::TreeNode;

/// Opens the studio window on `project` (the example project when `None`) and returns when the
/// window closes.
pub fn run(project: Option<PathBuf>) -> anyhow::Result<()> {
    let project_dir = project.unwrap_or_else(assets::example_project_dir);
    let options = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_title("Rivet")
            .with_app_id("rivet")
            .with_inner_size([1280.0, 800.0])
            .with_min_inner_size([640.0, 400.0]),
        ..Default::default()
    };
    eframe::run_native(
        "Rivet",
        options,
        Box::new(move |creation| {
            let settings = creation
                .storage
                .and_then(|storage| eframe::get_value(storage, settings::SETTINGS_KEY))
                .unwrap_or_default();
            let layout = creation
                .storage
                .and_then(|storage| eframe::get_value(storage, dock::LAYOUT_KEY));
            Ok(Box::new(StudioApp::with_options(StudioOptions {
                settings,
                layout,
                project: Some(project_dir),
                recovery: Recovery::default_location(),
            })))
        }),
    )
    .map_err(|error| anyhow::anyhow!("the studio window could not be opened: {error}"))
}
