//! Rivet's cam and tappet editor: segments and key points over the master range, plots of slave
//! position, velocity, acceleration and jerk, tappet lanes and CSV import and export.
//!
//! Like every editor it never changes the project while drawing: it emits edits that the app
//! applies after the frame.
//!
//! - [`curve_of`] and [`continuity_warnings`] turn a `project_model::CamTable` into a `motion`
//!   curve and check it; the studio's command line uses them too.
//! - [`import_points`] and [`export_points`] read and write the Rivet CSV of points; the app
//!   does the file I/O.
//! - [`CamEditor`] is the widget, kept by the app per cam; [`CamEditor::show`] returns a
//!   [`CamEditorOutput`] with at most one edit per gesture.

mod cam_edit;
mod convert;
mod editor;
mod number_field;
mod output;
mod palette;
mod plot_sampling;
mod plots;
mod points_csv;
mod properties;
mod segment_table;
mod tappet_lanes;
mod texts;
mod tracks;

pub use cam_edit::{CamEditError, delete_key_point, insert_key_point, next_action, set_key_point};
pub use convert::{ConvertError, Curve, continuity_warnings, curve_of};
pub use editor::CamEditor;
pub use output::{CamEditorOutput, CamLive};
pub use palette::CamPalette;
pub use plot_sampling::{PlotSamples, sample_for_plot};
pub use points_csv::{PointsCsvError, export_points, import_points};
pub use texts::CamEditorTexts;
