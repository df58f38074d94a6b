//! [`CfcEditor`]: its state, what the app sets each frame, and the frame itself.

use std::borrow::Cow;
use std::collections::{HashMap, HashSet};

use egui::scroll_area::ScrollSource;
use egui::{Pos2, Rect, ScrollArea, Ui, UiBuilder, Vec2, pos2, vec2};
use project_model::{CfcChart, CfcEditError, ElementId, GridPoint, PinRef};

use super::entry::CfcEntry;
use super::geometry::{ElementShape, GRID_PX, element_shape};
use super::router::{GridRect, route};
use super::texts::CfcTexts;
use super::types::{CfcChange, CfcDiagnostic, CfcOrderCommand, CfcOutput, CfcRefusal, CfcTool};
use crate::Severity;
use crate::diagram::{DiagramOnline, DiagramServices, InstanceDeclaration, PreparedOperand};

/// The width of the toolbox, in points.
const TOOLBOX_WIDTH_PX: f32 = 150.0;
/// The empty grid units kept right of and below the chart, so there is room to place more.
const ROOM_UNITS: i32 = 40;

/// What is selected: elements, or one wire (named by the input pin it drives).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct CfcSelection {
    /// The selected elements.
    pub elements: Vec<ElementId>,
    /// The selected wire, by the pin it drives.
    pub wire: Option<PinRef>,
}

/// A pointer gesture in progress.
#[derive(Clone, Debug, PartialEq)]
pub(super) enum Drag {
    /// The selected elements are being moved by `delta` grid units.
    Move {
        /// Where the press was, in grid units (fractional).
        from: Pos2,
        /// The snapped offset so far.
        delta: GridPoint,
    },
    /// A wire is being drawn from a pin.
    Connect {
        /// The pin the drag started on.
        from: PinRef,
        /// Whether that pin is an output.
        from_output: bool,
        /// The pointer, in content points at zoom 1.
        pointer: Pos2,
    },
    /// A control point is being moved.
    ControlPoint {
        /// The wire, by the pin it drives.
        wire: PinRef,
        /// The point's index.
        index: usize,
        /// Where it is now.
        at: GridPoint,
    },
    /// A rubber band from this content point.
    Band {
        /// Where it started, in content points at zoom 1.
        from: Pos2,
        /// Where the pointer is.
        to: Pos2,
    },
}

/// The CFC editor of one chart.
///
/// The app keeps one per open CFC body and, every frame:
/// - calls [`CfcEditor::set_chart`] with the model's chart (nothing happens when it is the
///   same; after undo, redo or a reload the editor takes the new one);
/// - sets the findings ([`CfcEditor::set_diagnostics`]) and, while logged in, the values
///   ([`CfcEditor::set_online`]) when they change;
/// - calls [`CfcEditor::show`] with a label and its [`DiagramServices`];
/// - applies [`CfcOutput::change`] as the model's `Edit::ReplaceChart` after the frame,
///   together with [`CfcOutput::declare_instance`] as one undo step, and handles
///   [`CfcOutput::prepared`] as a value to write or force.
pub struct CfcEditor {
    /// The chart shown: the model's, with this editor's changes applied at once.
    pub(super) chart: CfcChart,
    /// Each element's shape where it stands.
    pub(super) shapes: HashMap<ElementId, ElementShape>,
    /// The routes of the wires, by the pin each drives.
    pub(super) routes: HashMap<PinRef, Vec<GridPoint>>,
    /// The routes of the wires of the elements being dragged, where they would go.
    pub(super) drag_routes: HashMap<PinRef, Vec<GridPoint>>,
    /// The drag offset `drag_routes` were routed for.
    pub(super) drag_routes_for: Option<GridPoint>,
    /// The size of the content at zoom 1, in points.
    pub(super) content_px: Vec2,
    /// Points on screen per point of content.
    pub(super) zoom: f32,
    /// A scroll offset to apply in the next frame (after a zoom or a pan).
    pub(super) pending_offset: Option<Vec2>,
    /// The scroll offset of the last frame.
    pub(super) scroll_offset: Vec2,
    /// What is selected.
    pub(super) selection: CfcSelection,
    /// The toolbox element a click on the canvas places, if one is armed.
    pub(super) tool: Option<CfcTool>,
    /// The pointer gesture in progress.
    pub(super) drag: Option<Drag>,
    /// The open text field, if any.
    pub(super) entry: Option<CfcEntry>,
    /// Whether the execution order numbers are shown.
    pub(super) show_order: bool,
    /// The findings, as the app gave them.
    pub(super) diagnostics: Vec<CfcDiagnostic>,
    /// The worst severity on each element.
    pub(super) marks: HashMap<ElementId, Severity>,
    /// The worst severity on each pin, for the findings that name a pin.
    pub(super) pin_marks: HashMap<(ElementId, String), Severity>,
    /// The online values; `None` while offline.
    pub(super) online: Option<DiagramOnline>,
    /// The words shown.
    pub(super) texts: CfcTexts,
    /// Whether changes are refused (online without online change).
    pub(super) read_only: bool,
    /// Set by [`CfcEditor::request_focus`], honoured by the next `show`.
    pub(super) focus_requested: bool,
    /// Commands from the app's menus, run at the next `show`.
    pub(super) pending_commands: Vec<CfcOrderCommand>,
    /// The screen position of the content's top-left corner in the last frame.
    pub(super) last_origin: Pos2,
    /// What the open context menu was opened on.
    pub(super) context_hit: Option<super::canvas::Hit>,
    /// The debugger's breakpoints, halt and flow marks, as the app gave them.
    pub(super) debug_marks: crate::BodyDebugMarks,
}

/// What a frame collects for its output.
#[derive(Default)]
pub(super) struct FrameResult {
    pub change: Option<CfcChange>,
    pub declare_instance: Option<InstanceDeclaration>,
    pub prepared: Option<PreparedOperand>,
    pub refusal: Option<CfcRefusal>,
    pub toggle_breakpoint: Option<crate::BodyPlace>,
}

impl CfcEditor {
    /// An editor for `chart`.
    pub fn new(chart: &CfcChart) -> Self {
        let mut editor = Self {
            chart: chart.clone(),
            shapes: HashMap::new(),
            routes: HashMap::new(),
            drag_routes: HashMap::new(),
            drag_routes_for: None,
            content_px: Vec2::ZERO,
            zoom: 1.0,
            pending_offset: None,
            scroll_offset: Vec2::ZERO,
            selection: CfcSelection::default(),
            tool: None,
            drag: None,
            entry: None,
            show_order: true,
            diagnostics: Vec::new(),
            marks: HashMap::new(),
            pin_marks: HashMap::new(),
            online: None,
            texts: CfcTexts::default(),
            read_only: false,
            focus_requested: false,
            pending_commands: Vec::new(),
            last_origin: Pos2::ZERO,
            context_hit: None,
            debug_marks: crate::BodyDebugMarks::default(),
        };
        editor.rebuild();
        editor
    }

    /// The chart the editor shows.
    pub fn chart(&self) -> &CfcChart {
        &self.chart
    }

    /// Takes the model's chart when it differs from the shown one (after undo, redo or a
    /// change made elsewhere).
    pub fn set_chart(&mut self, chart: &CfcChart) {
        if self.chart == *chart {
            return;
        }
        self.chart = chart.clone();
        self.rebuild();
        let present: HashSet<ElementId> = self.chart.elements.iter().map(|e| e.id).collect();
        self.selection.elements.retain(|id| present.contains(id));
        if let Some(wire) = &self.selection.wire
            && !self.chart.wires.iter().any(|w| w.to == *wire)
        {
            self.selection.wire = None;
        }
    }

    /// The selection.
    pub fn selection(&self) -> &CfcSelection {
        &self.selection
    }

    /// Selects the element `id` (as the messages pane does for a finding).
    pub fn reveal(&mut self, id: ElementId) {
        self.selection = CfcSelection {
            elements: vec![id],
            wire: None,
        };
    }

    /// Makes the editor take keyboard focus at the next `show`.
    pub fn request_focus(&mut self) {
        self.focus_requested = true;
    }

    /// Runs an execution order `command` (from the app's menu) at the next `show`, on the
    /// selection.
    pub fn run_command(&mut self, command: CfcOrderCommand) {
        self.pending_commands.push(command);
    }

    /// Whether the execution order numbers are shown (View ▸ Display Execution Order).
    pub fn shows_execution_order(&self) -> bool {
        self.show_order
    }

    /// Shows or hides the execution order numbers.
    pub fn set_show_execution_order(&mut self, show: bool) {
        self.show_order = show;
    }

    /// In read-only mode the chart can be viewed, selected and copied but not changed.
    pub fn set_read_only(&mut self, read_only: bool) {
        self.read_only = read_only;
        if read_only {
            self.tool = None;
            self.drag = None;
        }
    }

    /// Sets the words shown, in the user's language.
    pub fn set_texts(&mut self, texts: CfcTexts) {
        self.texts = texts;
    }

    /// Sets the findings shown on the elements.
    pub fn set_diagnostics(&mut self, diagnostics: Vec<CfcDiagnostic>) {
        let rank = |severity: &Severity| match severity {
            Severity::Error => 2,
            Severity::Warning => 1,
            Severity::Info => 0,
        };
        self.marks.clear();
        self.pin_marks.clear();
        for diagnostic in &diagnostics {
            if let Some(id) = diagnostic.element {
                let mark = self.marks.entry(id).or_insert(diagnostic.severity);
                if rank(&diagnostic.severity) > rank(mark) {
                    *mark = diagnostic.severity;
                }
                if let Some(pin) = &diagnostic.pin {
                    let mark = self
                        .pin_marks
                        .entry((id, pin.clone()))
                        .or_insert(diagnostic.severity);
                    if rank(&diagnostic.severity) > rank(mark) {
                        *mark = diagnostic.severity;
                    }
                }
            }
        }
        self.diagnostics = diagnostics;
    }

    /// The debugger's marks to draw until replaced; an empty value removes them.
    pub fn set_debug_marks(&mut self, marks: crate::BodyDebugMarks) {
        self.debug_marks = marks;
    }

    /// The debugger's marks being drawn.
    pub fn debug_marks(&self) -> &crate::BodyDebugMarks {
        &self.debug_marks
    }

    /// Where a breakpoint toggled now would go: the one selected element (the chart is
    /// network 0); `None` for no element or several.
    pub fn breakpoint_place(&self) -> Option<crate::BodyPlace> {
        match self.selection.elements.as_slice() {
            [id] => Some(crate::BodyPlace {
                network: 0,
                element: Some(*id),
            }),
            _ => None,
        }
    }

    /// Sets the values read from the target (`None` when offline): by element and pin, the
    /// pin `None` for an input's or output's expression.
    pub fn set_online(&mut self, online: Option<DiagramOnline>) {
        self.online = online;
    }

    /// The online values shown; `None` while offline.
    pub fn online(&self) -> Option<&DiagramOnline> {
        self.online.as_ref()
    }

    /// The zoom factor.
    pub fn zoom(&self) -> f32 {
        self.zoom
    }

    /// Shows the editor filling the available space: a bar with the execution order toggle,
    /// the toolbox and the canvas. `label` is its accessible name and keeps its state apart
    /// from other editors.
    pub fn show(&mut self, ui: &mut Ui, label: &str, services: &dyn DiagramServices) -> CfcOutput {
        let id = ui.make_persistent_id(("cfc_editor", label));
        let mut frame = FrameResult::default();
        for command in std::mem::take(&mut self.pending_commands) {
            self.order_command(command, &mut frame);
        }
        ui.horizontal(|ui| {
            ui.checkbox(&mut self.show_order, &self.texts.display_execution_order);
            ui.separator();
            ui.label(format!("{:.0} %", self.zoom * 100.0))
                .on_hover_text(&self.texts.zoom);
        });
        let available = ui.available_rect_before_wrap();
        let toolbox =
            Rect::from_min_size(available.min, vec2(TOOLBOX_WIDTH_PX, available.height()));
        let canvas =
            Rect::from_min_max(pos2(toolbox.right() + 4.0, available.top()), available.max);
        ui.scope_builder(UiBuilder::new().max_rect(toolbox), |ui| {
            self.toolbox_ui(ui, id);
        });
        let response = ui
            .scope_builder(UiBuilder::new().max_rect(canvas), |ui| {
                let mut area = ScrollArea::both()
                    .id_salt(id.with("scroll"))
                    .auto_shrink([false, false])
                    .scroll_source(ScrollSource::SCROLL_BAR | ScrollSource::MOUSE_WHEEL);
                if let Some(offset) = self.pending_offset.take() {
                    area = area.scroll_offset(offset);
                }
                let output = area.show_viewport(ui, |ui, viewport| {
                    self.canvas_ui(ui, id, label, viewport, services, &mut frame)
                });
                self.scroll_offset = output.state.clamped_offset();
                output.inner
            })
            .inner;
        ui.advance_cursor_after_rect(available);
        CfcOutput {
            response,
            change: frame.change,
            declare_instance: frame.declare_instance,
            prepared: frame.prepared,
            refusal: frame.refusal,
            toggle_breakpoint: frame.toggle_breakpoint,
        }
    }

    /// Takes the result of a model edit: the new chart is shown at once and is the frame's
    /// change; a refusal is the frame's refusal.
    pub(super) fn apply(
        &mut self,
        result: Result<CfcChart, CfcEditError>,
        frame: &mut FrameResult,
    ) -> bool {
        if self.read_only {
            return false;
        }
        match result {
            Ok(chart) => {
                if chart != self.chart {
                    self.chart = chart;
                    self.rebuild();
                    frame.change = Some(CfcChange {
                        chart: self.chart.clone(),
                    });
                }
                true
            }
            Err(error) => {
                frame.refusal = Some(CfcRefusal::Edit(error));
                false
            }
        }
    }

    /// Runs an execution order command on the selection.
    pub(super) fn order_command(&mut self, command: CfcOrderCommand, frame: &mut FrameResult) {
        use project_model::cfc_edit as edit;
        let ids = self.selection.elements.clone();
        let result = match command {
            CfcOrderCommand::SendToFront => edit::send_to_front(&self.chart, &ids),
            CfcOrderCommand::SendToBack => edit::send_to_back(&self.chart, &ids),
            CfcOrderCommand::MoveUp => edit::move_up(&self.chart, &ids),
            CfcOrderCommand::MoveDown => edit::move_down(&self.chart, &ids),
            CfcOrderCommand::SetExecutionOrder(order) => match ids.as_slice() {
                [id] => edit::set_execution_order(&self.chart, *id, order),
                _ => Err(CfcEditError::NothingSelected),
            },
            CfcOrderCommand::OrderByDataFlow => Ok(edit::order_by_data_flow(&self.chart)),
            CfcOrderCommand::OrderByTopology => Ok(edit::order_by_topology(&self.chart)),
        };
        self.apply(result, frame);
    }

    /// Measures every element, routes every wire and sizes the content.
    pub(super) fn rebuild(&mut self) {
        self.shapes = self
            .chart
            .elements
            .iter()
            .map(|element| (element.id, element_shape(element, GridPoint::default())))
            .collect();
        let obstacles = self.obstacles(&HashSet::new(), GridPoint::default());
        self.routes = self
            .chart
            .wires
            .iter()
            .filter_map(|wire| {
                let from = self
                    .shapes
                    .get(&wire.from.element)?
                    .output(&wire.from.pin)?;
                let to = self.shapes.get(&wire.to.element)?.input(&wire.to.pin)?;
                Some((wire.to.clone(), route(from, to, &wire.points, &obstacles)))
            })
            .collect();
        self.drag_routes.clear();
        self.drag_routes_for = None;
        let (right, bottom) = self.shapes.values().fold((0, 0), |(right, bottom), shape| {
            (right.max(shape.rect.right), bottom.max(shape.rect.bottom))
        });
        self.content_px = vec2(
            (right + ROOM_UNITS) as f32 * GRID_PX,
            (bottom + ROOM_UNITS) as f32 * GRID_PX,
        );
    }

    /// The rectangles wires go around: every element but the comments, the elements `moved`
    /// displaced by `delta`.
    pub(super) fn obstacles(&self, moved: &HashSet<ElementId>, delta: GridPoint) -> Vec<GridRect> {
        self.chart
            .elements
            .iter()
            .filter(|element| {
                !matches!(element.kind, project_model::CfcElementKind::Comment { .. })
            })
            .map(|element| {
                if moved.contains(&element.id) {
                    element_shape(element, delta).rect
                } else {
                    self.shapes[&element.id].rect
                }
            })
            .collect()
    }

    /// The shape of `id` as drawn this frame: displaced while it is dragged.
    pub(super) fn shape_now(&self, id: ElementId) -> Option<Cow<'_, ElementShape>> {
        let delta = self.drag_delta();
        if delta != GridPoint::default() && self.selection.elements.contains(&id) {
            let element = self.chart.elements.iter().find(|e| e.id == id)?;
            return Some(Cow::Owned(element_shape(element, delta)));
        }
        self.shapes.get(&id).map(Cow::Borrowed)
    }

    /// The offset of the move in progress, zero when nothing is moved.
    pub(super) fn drag_delta(&self) -> GridPoint {
        match &self.drag {
            Some(Drag::Move { delta, .. }) => *delta,
            _ => GridPoint::default(),
        }
    }

    /// Routes again the wires of the elements being moved, for the offset of this frame; the
    /// other wires keep their routes until the move ends.
    pub(super) fn route_drag(&mut self) {
        let delta = self.drag_delta();
        if delta == GridPoint::default() {
            self.drag_routes.clear();
            self.drag_routes_for = None;
            return;
        }
        if self.drag_routes_for == Some(delta) {
            return;
        }
        let moved: HashSet<ElementId> = self.selection.elements.iter().copied().collect();
        let obstacles = self.obstacles(&moved, delta);
        let shape = |id: ElementId| -> Option<ElementShape> {
            let element = self.chart.elements.iter().find(|e| e.id == id)?;
            Some(if moved.contains(&id) {
                element_shape(element, delta)
            } else {
                self.shapes.get(&id)?.clone()
            })
        };
        let mut routes = HashMap::new();
        for wire in &self.chart.wires {
            if !moved.contains(&wire.from.element) && !moved.contains(&wire.to.element) {
                continue;
            }
            let (Some(from), Some(to)) = (
                shape(wire.from.element).and_then(|s| s.output(&wire.from.pin)),
                shape(wire.to.element).and_then(|s| s.input(&wire.to.pin)),
            ) else {
                continue;
            };
            let points: Vec<GridPoint> =
                if moved.contains(&wire.from.element) && moved.contains(&wire.to.element) {
                    wire.points
                        .iter()
                        .map(|p| GridPoint {
                            x: p.x + delta.x,
                            y: p.y + delta.y,
                        })
                        .collect()
                } else {
                    wire.points.clone()
                };
            routes.insert(wire.to.clone(), route(from, to, &points, &obstacles));
        }
        self.drag_routes = routes;
        self.drag_routes_for = Some(delta);
    }

    /// Whether the wire from `from` into `to` is a feedback: it reads an element that runs
    /// later (or the same element), so it carries the previous cycle's value.
    pub(super) fn is_feedback(&self, from: ElementId, to: ElementId) -> bool {
        let order = |id: ElementId| {
            self.chart
                .elements
                .iter()
                .find(|e| e.id == id)
                .and_then(|e| e.order)
        };
        match (order(from), order(to)) {
            (Some(source), Some(target)) => source >= target,
            _ => false,
        }
    }

    /// The screen point of grid point `point`.
    pub(super) fn screen(&self, origin: Pos2, x: f32, y: f32) -> Pos2 {
        origin + vec2(x, y) * GRID_PX * self.zoom
    }

    /// The grid position (fractional) of screen point `pos`.
    pub(super) fn grid_at(&self, origin: Pos2, pos: Pos2) -> Pos2 {
        let grid = (pos - origin) / (GRID_PX * self.zoom);
        pos2(grid.x, grid.y)
    }
}
