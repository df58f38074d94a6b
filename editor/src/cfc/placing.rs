//! Placing: toolbox elements clicked or dropped onto the canvas, control points put on a
//! wire, and variables dropped from the declaration onto pins and elements.

use egui::{Pos2, Response};
use project_model::cfc_edit as edit;
use project_model::{CfcBox, CfcElementKind, CoilKind, ElementId, GridPoint, PinRef};

use super::canvas::{Hit, at, segment_distance};
use super::editor::{CfcEditor, FrameResult};
use super::entry::EntryTarget;
use super::geometry::ROW_UNITS;
use super::types::{CfcTool, VariableDragPayload};

impl CfcEditor {
    /// Places the toolbox element `tool` at grid position `grid` and opens its text field.
    pub(super) fn place(&mut self, tool: CfcTool, grid: Pos2, frame: &mut FrameResult) {
        let point = GridPoint {
            x: grid.x.floor().max(0.0) as i32,
            y: grid.y.floor().max(0.0) as i32,
        };
        let unnamed = || "???".to_owned();
        let (kind, field) = match tool {
            CfcTool::Input => (
                CfcElementKind::Input {
                    expression: unnamed(),
                },
                Some(EntryTarget::Text as fn(ElementId) -> EntryTarget),
            ),
            CfcTool::Output => (
                CfcElementKind::Output {
                    expression: unnamed(),
                    coil: CoilKind::Normal,
                },
                Some(EntryTarget::Text as fn(ElementId) -> EntryTarget),
            ),
            CfcTool::Box => (
                CfcElementKind::Box(CfcBox::default()),
                Some(EntryTarget::BoxType as fn(ElementId) -> EntryTarget),
            ),
            CfcTool::Jump => (
                CfcElementKind::Jump { label: unnamed() },
                Some(EntryTarget::Text as _),
            ),
            CfcTool::Label => (
                CfcElementKind::Label { name: unnamed() },
                Some(EntryTarget::Text as _),
            ),
            CfcTool::Return => (CfcElementKind::Return, None),
            CfcTool::Composer => (
                CfcElementKind::Composer {
                    type_name: unnamed(),
                    inputs: Vec::new(),
                },
                Some(EntryTarget::StructType as _),
            ),
            CfcTool::Selector => (
                CfcElementKind::Selector {
                    type_name: unnamed(),
                    outputs: Vec::new(),
                },
                Some(EntryTarget::StructType as _),
            ),
            CfcTool::Comment => (
                CfcElementKind::Comment {
                    text: String::new(),
                    width: 12,
                    height: 4,
                },
                Some(EntryTarget::Text as _),
            ),
            CfcTool::ConnectionSource => (
                CfcElementKind::ConnectionSource { name: unnamed() },
                Some(EntryTarget::Text as _),
            ),
            CfcTool::ConnectionSink => (
                CfcElementKind::ConnectionSink { name: unnamed() },
                Some(EntryTarget::Text as _),
            ),
            CfcTool::InputPin => {
                let result = match self.hit(grid) {
                    Hit::Element(id) | Hit::Input(PinRef { element: id, .. }) => {
                        edit::extend_box(&self.chart, id)
                    }
                    _ => Err(project_model::CfcEditError::NothingSelected),
                };
                self.apply(result, frame);
                return;
            }
            CfcTool::ControlPoint => {
                self.add_control_point_at(grid, frame);
                return;
            }
        };
        let (chart, id) = edit::add_element(&self.chart, kind, point);
        if self.apply(Ok(chart), frame) {
            self.selection.elements = vec![id];
            self.selection.wire = None;
            if let Some(target) = field {
                self.open_entry(target(id), String::new());
            }
        }
    }

    /// Adds a control point on the wire under `grid`, between the points it passes before
    /// and after.
    fn add_control_point_at(&mut self, grid: Pos2, frame: &mut FrameResult) {
        let Hit::Wire(to) = self.hit(grid) else {
            self.apply(Err(project_model::CfcEditError::NothingSelected), frame);
            return;
        };
        let point = GridPoint {
            x: grid.x.round() as i32,
            y: grid.y.round() as i32,
        };
        let Some(route) = self.routes.get(&to) else {
            return;
        };
        // How far along the route a point lies, so the new point goes between the control
        // points before and after it.
        let along = |target: Pos2| -> f32 {
            let mut walked = 0.0;
            let mut best = (f32::MAX, 0.0);
            for segment in route.windows(2) {
                let (a, b) = (at(segment[0]), at(segment[1]));
                let distance = segment_distance(target, a, b);
                if distance < best.0 {
                    best = (
                        distance,
                        walked + a.distance(target.clamp(a.min(b), a.max(b))),
                    );
                }
                walked += a.distance(b);
            }
            best.1
        };
        let here = along(at(point));
        let index = self.chart.wires.iter().find(|w| w.to == to).map_or(0, |w| {
            w.points.iter().filter(|p| along(at(**p)) < here).count()
        });
        let result = edit::add_control_point(&self.chart, &to, index, point);
        if self.apply(result, frame) {
            self.selection.wire = Some(to);
            self.selection.elements.clear();
        }
    }

    /// A toolbox element or a variable dropped on the canvas.
    pub(super) fn drops_ui(&mut self, response: &Response, origin: Pos2, frame: &mut FrameResult) {
        let Some(pointer) = response.hover_pos() else {
            return;
        };
        let grid = self.grid_at(origin, pointer);
        // Taking a payload clears it whatever its type, so each is taken only when it is the
        // one carried: a variable dropped from the declarations would be lost to the tool's
        // check otherwise.
        if egui::DragAndDrop::has_payload_of_type::<CfcTool>(&response.ctx)
            && let Some(tool) = response.dnd_release_payload::<CfcTool>()
            && !self.read_only
        {
            self.place(*tool, grid, frame);
        }
        if let Some(variable) = response.dnd_release_payload::<VariableDragPayload>()
            && !self.read_only
        {
            self.drop_variable(&variable.name, self.hit(grid), frame);
        }
    }

    /// A variable dropped on a pin connects a new input (on an input pin) or output (on an
    /// output pin) with it; on an input or output element it becomes the expression.
    pub(super) fn drop_variable(&mut self, name: &str, hit: Hit, frame: &mut FrameResult) {
        let result = match hit {
            Hit::Input(pin) if self.is_connectable(&pin.element) => {
                let at = self.shapes[&pin.element]
                    .input(&pin.pin)
                    .unwrap_or_default();
                let width = super::geometry::element_shape(
                    &project_model::CfcElement {
                        id: ElementId(0),
                        x: 0,
                        y: 0,
                        order: None,
                        kind: CfcElementKind::Input {
                            expression: name.to_owned(),
                        },
                    },
                    GridPoint::default(),
                )
                .rect
                .right;
                let (chart, id) = edit::add_element(
                    &self.chart,
                    CfcElementKind::Input {
                        expression: name.to_owned(),
                    },
                    GridPoint {
                        x: (at.x - width - 3).max(0),
                        y: at.y - ROW_UNITS / 2,
                    },
                );
                edit::connect(&chart, &PinRef::new(id, ""), &pin)
            }
            Hit::Output(pin) if self.is_connectable(&pin.element) => {
                let at = self.shapes[&pin.element]
                    .output(&pin.pin)
                    .unwrap_or_default();
                let (chart, id) = edit::add_element(
                    &self.chart,
                    CfcElementKind::Output {
                        expression: name.to_owned(),
                        coil: CoilKind::Normal,
                    },
                    GridPoint {
                        x: at.x + 3,
                        y: at.y - ROW_UNITS / 2,
                    },
                );
                edit::connect(&chart, &pin, &PinRef::new(id, ""))
            }
            Hit::Element(id)
            | Hit::Input(PinRef { element: id, .. })
            | Hit::Output(PinRef { element: id, .. }) => edit::set_text(&self.chart, id, name),
            _ => return,
        };
        self.apply(result, frame);
    }

    /// Whether a variable dropped on a pin of `id` gets an element of its own: on a box,
    /// composer or selector (an input or output element takes it as its expression).
    fn is_connectable(&self, id: &ElementId) -> bool {
        self.chart.elements.iter().any(|e| {
            e.id == *id
                && matches!(
                    e.kind,
                    CfcElementKind::Box(_)
                        | CfcElementKind::Composer { .. }
                        | CfcElementKind::Selector { .. }
                        | CfcElementKind::Jump { .. }
                        | CfcElementKind::Return
                        | CfcElementKind::ConnectionSource { .. }
                        | CfcElementKind::ConnectionSink { .. }
                )
        })
    }
}
