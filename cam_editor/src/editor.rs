//! The cam editor: tabs for the plots with the tappet lanes, the cam table, the tappet tracks
//! and the properties, over one cam of the project.

use egui::{RichText, Ui};
use motion::cam::{ContinuityWarning, SegmentBounds};
use project_model::CamTable;

use crate::convert::{ConvertError, Curve, curve_of};
use crate::number_field::Drafts;
use crate::output::{CamEditorOutput, CamLive};
use crate::plots::PlotState;
use crate::tappet_lanes::LaneState;
use crate::texts::CamEditorTexts;

/// The editor of one cam, kept by the app between frames (one per open cam) and never saved.
///
/// It holds only view state: the tab shown, text being typed, a drag in progress and the
/// curve computed from the cam last shown. The cam itself comes from the project every frame.
#[derive(Default)]
pub struct CamEditor {
    /// The tab shown.
    tab: Tab,
    /// Text typed into fields and the last refused value.
    pub(crate) drafts: Drafts,
    /// The plots' drag, hover and sampling state.
    pub(crate) plots: PlotState,
    /// The tappet lanes' drag and selection.
    pub(crate) lanes: LaneState,
    /// The curve of the cam shown, rebuilt when the cam changes.
    view: Option<CurveView>,
    /// The model's cam last shown, to notice changes from elsewhere (undo, another view).
    seen: Option<CamTable>,
    /// The cam of the last edit returned, which the model holds next frame if the app applied
    /// it: that change keeps the selection, any other clears what was being done.
    emitted: Option<CamTable>,
}

/// The tabs of the editor, as in the CODESYS cam editor.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
enum Tab {
    /// The four plots and the tappet lanes.
    #[default]
    Cam,
    /// The table of key points and segments, or of points.
    Table,
    /// The tappet tracks' settings.
    Tappets,
    /// The cam's properties.
    Properties,
}

/// A cam with what is computed from it: its curve (or why it has none), its continuity
/// warnings and, once asked for, the bounds of its segments.
pub(crate) struct CurveView {
    /// The cam the rest is computed from.
    pub(crate) cam: CamTable,
    /// Its curve, or why it has none.
    pub(crate) curve: Result<Curve, ConvertError>,
    /// Its continuity warnings.
    pub(crate) warnings: Vec<ContinuityWarning>,
    /// The master positions of its key points.
    pub(crate) key_masters: Vec<f64>,
    /// The segment bounds, computed when the table first needs them.
    bounds: Option<Vec<SegmentBounds>>,
    /// Counts rebuilds, so the plots know when to sample again.
    pub(crate) generation: u64,
}

impl CurveView {
    fn new(cam: &CamTable, generation: u64) -> Self {
        let curve = curve_of(cam);
        let (warnings, key_masters) = match &curve {
            Ok(curve) => (curve.check_continuity(cam), curve.key_masters()),
            Err(_) => (Vec::new(), Vec::new()),
        };
        Self {
            cam: cam.clone(),
            curve,
            warnings,
            key_masters,
            bounds: None,
            generation,
        }
    }

    /// The bounds of every segment, computed on first use.
    pub(crate) fn bounds(&mut self) -> &[SegmentBounds] {
        let curve = &self.curve;
        self.bounds.get_or_insert_with(|| match curve {
            Ok(curve) => curve.segment_bounds(),
            Err(_) => Vec::new(),
        })
    }
}

/// What a gesture in one part of the editor came to.
pub(crate) enum Gesture {
    /// A valid changed cam, with its label for the undo menu (boxed: a cam is large and a
    /// refusal small).
    Edit(String, Box<CamTable>),
    /// A refused change: the field or handle's label and the reason.
    Refused(String, String),
}

impl Gesture {
    /// An edit of `cam` labelled `label`.
    pub(crate) fn edit(label: impl Into<String>, cam: CamTable) -> Self {
        Self::Edit(label.into(), Box::new(cam))
    }
}

impl CamEditor {
    /// A new editor showing the plots.
    pub fn new() -> Self {
        Self::default()
    }

    /// Draws the editor of `cam` and returns what the user did. `live` adds the live master
    /// position, slave set point and tappet outputs; `read_only` (while logged in) shows
    /// everything and changes nothing.
    pub fn show(
        &mut self,
        ui: &mut Ui,
        cam: &CamTable,
        live: Option<&CamLive>,
        texts: &CamEditorTexts,
        read_only: bool,
    ) -> CamEditorOutput {
        if self.seen.as_ref() != Some(cam) {
            let own_edit = self.emitted.as_ref() == Some(cam);
            if self.seen.is_some() && !own_edit {
                self.drafts.clear();
                self.plots.cancel_drag();
                self.lanes.cancel();
            }
            self.seen = Some(cam.clone());
            self.emitted = None;
        }
        if read_only {
            self.plots.cancel_drag();
            self.lanes.cancel();
        }
        // While a key point is dragged the plots show the cam as it would be.
        let preview = self.plots.preview().cloned();
        let shown = preview.as_ref().unwrap_or(cam);
        if self.view.as_ref().is_none_or(|view| view.cam != *shown) {
            let generation = self.view.as_ref().map_or(0, |view| view.generation + 1);
            self.view = Some(CurveView::new(shown, generation));
        }
        let mut output = CamEditorOutput::default();
        let mut gesture = None;
        ui.horizontal(|ui| {
            for (tab, text) in [
                (Tab::Cam, &texts.cam_tab),
                (Tab::Table, &texts.table_tab),
                (Tab::Tappets, &texts.tappets_tab),
                (Tab::Properties, &texts.properties_tab),
            ] {
                if ui.selectable_label(self.tab == tab, text).clicked() {
                    self.tab = tab;
                }
            }
            ui.separator();
            output.import_csv = ui
                .add_enabled(!read_only, egui::Button::new(&texts.import_csv))
                .clicked();
            output.export_csv = ui.button(&texts.export_csv).clicked();
        });
        self.drafts.refusal_ui(ui);
        if let Some(live) = live {
            let text = texts
                .live
                .replace("{master}", &format!("{:.3}", live.master))
                .replace("{slave}", &format!("{:.3}", live.slave));
            ui.label(RichText::new(text).color(crate::CamPalette::of(ui).live));
        }
        let Some(view) = self.view.as_mut() else {
            return output;
        };
        if let Err(error) = &view.curve {
            ui.label(
                RichText::new(format!("{}: {error}", texts.invalid_cam))
                    .color(ui.visuals().error_fg_color),
            );
        }
        ui.separator();
        let frame = Frame {
            cam,
            texts,
            read_only,
        };
        match self.tab {
            Tab::Cam => {
                let plot_height =
                    ((ui.available_height() - 40.0 * (cam.tracks.len() as f32 + 3.0)) / 4.0)
                        .clamp(90.0, 260.0);
                egui::ScrollArea::vertical()
                    .id_salt("cam plots")
                    .auto_shrink([false, false])
                    .show(ui, |ui| {
                        gesture = self.plots.plots_ui(ui, &frame, view, live, plot_height);
                        if let Some(transform) = self.plots.transform() {
                            let lanes = self.lanes.lanes_ui(ui, &frame, &transform, live);
                            gesture = gesture.take().or(lanes);
                        }
                        crate::plots::warnings_ui(ui, view, texts);
                    });
            }
            Tab::Table => {
                gesture = crate::segment_table::table_ui(ui, &mut self.drafts, &frame, view);
            }
            Tab::Tappets => {
                gesture = crate::tracks::tracks_ui(ui, &mut self.drafts, &frame);
            }
            Tab::Properties => {
                gesture = crate::properties::properties_ui(ui, &mut self.drafts, &frame);
            }
        }
        match gesture {
            Some(Gesture::Edit(label, changed)) => {
                let changed = *changed;
                self.drafts.accept();
                if changed != *cam {
                    self.emitted = Some(changed.clone());
                    output.edit = Some((label, changed));
                }
            }
            Some(Gesture::Refused(label, reason)) => {
                self.drafts.refusal = Some((label, reason));
            }
            None => {}
        }
        output
    }

    /// Where key point `index` (0-based, 0 the start) of `cam` was drawn on the position plot in
    /// the last frame, if it was in view: for tests and benchmarks that drag it.
    pub fn key_point_screen_pos(&self, cam: &CamTable, index: usize) -> Option<egui::Pos2> {
        let transform = self.plots.transform()?;
        let point = crate::cam_edit::key_points(cam).get(index).copied()?;
        let pos =
            transform.position_from_point(&egui_plot::PlotPoint::new(point.master, point.slave));
        transform.frame().contains(pos).then_some(pos)
    }

    /// Whether a key point is being dragged (its preview is shown, its edit comes on release).
    pub fn is_dragging_key_point(&self) -> bool {
        self.plots.preview().is_some()
    }

    /// Where tappet `tappet` of track `track` (0-based) was drawn in its lane in the last frame.
    pub fn tappet_screen_rect(&self, track: usize, tappet: usize) -> Option<egui::Rect> {
        self.lanes.tappet_rect(track, tappet)
    }
}

/// What every part of the editor is given for one frame.
pub(crate) struct Frame<'a> {
    /// The model's cam.
    pub(crate) cam: &'a CamTable,
    /// The words to show.
    pub(crate) texts: &'a CamEditorTexts,
    /// Whether nothing may change.
    pub(crate) read_only: bool,
}
