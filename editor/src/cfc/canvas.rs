//! The canvas in a frame: zoom and pan, hit testing, and the pointer: selecting, moving,
//! connecting pins, moving control points, the rubber band (placing is in `placing.rs`).

use std::collections::HashSet;

use egui::{Id, PointerButton, Pos2, Rect, Response, Ui, pos2, vec2};
use project_model::cfc_edit as edit;
use project_model::{CfcElementKind, ElementId, GridPoint, PinRef};

use super::editor::{CfcEditor, Drag, FrameResult};
use super::geometry::{GRID_PX, ROW_UNITS};
use crate::diagram::DiagramServices;
use crate::diagram::canvas_input::{
    CanvasView, canvas_response, focused_canvas_events, zoom_and_pan_ui,
};

/// How near a pin or a control point the pointer must be to take it, in grid units.
const PIN_RADIUS_UNITS: f32 = 0.8;
/// How near a wire the pointer must be to take it, in grid units.
const WIRE_RADIUS_UNITS: f32 = 0.5;

/// What the pointer is over.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(super) enum Hit {
    /// An input pin.
    Input(PinRef),
    /// An output pin.
    Output(PinRef),
    /// The row above a box, where its instance is named.
    Instance(ElementId),
    /// An element's frame.
    Element(ElementId),
    /// A control point of the selected wire.
    ControlPoint(PinRef, usize),
    /// A wire, by the pin it drives.
    Wire(PinRef),
    /// Nothing.
    Empty,
}

/// The distance from `point` to the segment `a`–`b`.
pub(super) fn segment_distance(point: Pos2, a: Pos2, b: Pos2) -> f32 {
    let along = b - a;
    let length = along.length_sq();
    let t = if length > 0.0 {
        ((point - a).dot(along) / length).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (a + along * t).distance(point)
}

/// A grid point as a position, for distances.
pub(super) fn at(point: GridPoint) -> Pos2 {
    pos2(point.x as f32, point.y as f32)
}

impl CfcEditor {
    /// What is at grid position `grid` (fractional).
    pub(super) fn hit(&self, grid: Pos2) -> Hit {
        let near = |point: GridPoint| at(point).distance(grid) <= PIN_RADIUS_UNITS;
        for element in self.chart.elements.iter().rev() {
            let Some(shape) = self.shape_now(element.id) else {
                continue;
            };
            if let Some((name, _)) = shape.inputs.iter().find(|(_, point)| near(*point)) {
                return Hit::Input(PinRef::new(element.id, name.clone()));
            }
            if let Some((name, _)) = shape.outputs.iter().find(|(_, point)| near(*point)) {
                return Hit::Output(PinRef::new(element.id, name.clone()));
            }
        }
        if let Some(wire) = &self.selection.wire
            && let Some(points) = self
                .chart
                .wires
                .iter()
                .find(|w| w.to == *wire)
                .map(|w| &w.points)
            && let Some(index) = points.iter().position(|point| near(*point))
        {
            return Hit::ControlPoint(wire.clone(), index);
        }
        for element in self.chart.elements.iter().rev() {
            let Some(shape) = self.shape_now(element.id) else {
                continue;
            };
            let rect = shape.rect;
            let inside_x = grid.x >= rect.left as f32 && grid.x <= rect.right as f32;
            if inside_x && grid.y >= rect.top as f32 && grid.y <= rect.bottom as f32 {
                return Hit::Element(element.id);
            }
            if inside_x
                && matches!(element.kind, CfcElementKind::Box(_))
                && grid.y >= (rect.top - ROW_UNITS) as f32
                && grid.y < rect.top as f32
            {
                return Hit::Instance(element.id);
            }
        }
        for (to, route) in &self.routes {
            let close = route.windows(2).any(|segment| {
                segment_distance(grid, at(segment[0]), at(segment[1])) <= WIRE_RADIUS_UNITS
            });
            if close {
                return Hit::Wire(to.clone());
            }
        }
        Hit::Empty
    }

    #[allow(clippy::too_many_arguments)]
    pub(super) fn canvas_ui(
        &mut self,
        ui: &mut Ui,
        id: Id,
        label: &str,
        viewport: Rect,
        services: &dyn DiagramServices,
        frame: &mut FrameResult,
    ) -> Response {
        let content = self.content_px * self.zoom;
        let size = vec2(
            content.x.max(viewport.width()),
            content.y.max(viewport.height()),
        );
        let response = canvas_response(ui, size, id, label, &mut self.focus_requested);
        let rect = response.rect;
        let origin = rect.min;
        self.last_origin = origin;
        let view = CanvasView {
            zoom: &mut self.zoom,
            pending_offset: &mut self.pending_offset,
            scroll_offset: self.scroll_offset,
        };
        zoom_and_pan_ui(ui, &response, origin, viewport, view);
        if response.has_focus() && self.entry.is_none() {
            let events = focused_canvas_events(ui, id);
            self.handle_events(ui.ctx(), &events, frame);
        }
        self.pointer_ui(ui, &response, origin, frame);
        self.drops_ui(&response, origin, frame);
        self.context_menu_ui(&response, origin, frame);
        self.route_drag();
        self.paint(
            ui,
            origin,
            viewport.translate(rect.min.to_vec2()),
            &response,
        );
        self.entry_ui(ui.ctx(), id, origin, services, frame);
        response
    }

    fn pointer_ui(&mut self, ui: &Ui, response: &Response, origin: Pos2, frame: &mut FrameResult) {
        // The modifiers of the click itself: a Ctrl+click may release Ctrl in the same frame.
        let modifiers = ui.input(|input| {
            input
                .events
                .iter()
                .rev()
                .find_map(|event| match event {
                    egui::Event::PointerButton { modifiers, .. } => Some(*modifiers),
                    _ => None,
                })
                .unwrap_or(input.modifiers)
        });
        if response.drag_started_by(PointerButton::Primary)
            && let Some(press) = ui.input(|input| input.pointer.press_origin())
        {
            let grid = self.grid_at(origin, press);
            self.start_drag(self.hit(grid), grid, modifiers.shift);
        }
        if response.dragged_by(PointerButton::Primary)
            && let Some(pointer) = response.interact_pointer_pos()
        {
            let grid = self.grid_at(origin, pointer);
            self.continue_drag(grid);
        }
        if response.drag_stopped() {
            if let Some(pointer) = response.interact_pointer_pos() {
                let grid = self.grid_at(origin, pointer);
                self.continue_drag(grid);
            }
            self.finish_drag(frame);
        }
        if response.clicked()
            && let Some(pointer) = response.interact_pointer_pos()
        {
            let grid = self.grid_at(origin, pointer);
            match self.tool {
                Some(tool) if !self.read_only => {
                    self.place(tool, grid, frame);
                    // Ctrl+click places the same element again, as in CODESYS.
                    if !modifiers.command {
                        self.tool = None;
                    }
                }
                _ => self.click(self.hit(grid), modifiers.shift),
            }
        }
        if response.double_clicked()
            && let Some(pointer) = response.interact_pointer_pos()
        {
            let grid = self.grid_at(origin, pointer);
            self.open_entry_at(self.hit(grid));
        }
    }

    fn click(&mut self, hit: Hit, shift: bool) {
        match hit {
            Hit::Element(id)
            | Hit::Instance(id)
            | Hit::Input(PinRef { element: id, .. })
            | Hit::Output(PinRef { element: id, .. }) => {
                self.selection.wire = None;
                if shift {
                    if let Some(index) = self.selection.elements.iter().position(|e| *e == id) {
                        self.selection.elements.remove(index);
                    } else {
                        self.selection.elements.push(id);
                    }
                } else {
                    self.selection.elements = vec![id];
                }
            }
            Hit::Wire(to) | Hit::ControlPoint(to, _) => {
                self.selection.elements.clear();
                self.selection.wire = Some(to);
            }
            Hit::Empty => {
                if !shift {
                    self.selection = Default::default();
                }
            }
        }
    }

    fn start_drag(&mut self, hit: Hit, grid: Pos2, shift: bool) {
        if self.read_only {
            if let Hit::Empty | Hit::Wire(_) = hit {
                self.drag = Some(Drag::Band {
                    from: grid,
                    to: grid,
                });
            }
            return;
        }
        self.drag = Some(match hit {
            Hit::Input(pin) => Drag::Connect {
                from: pin,
                from_output: false,
                pointer: grid,
            },
            Hit::Output(pin) => Drag::Connect {
                from: pin,
                from_output: true,
                pointer: grid,
            },
            Hit::ControlPoint(wire, index) => Drag::ControlPoint {
                at: GridPoint {
                    x: grid.x.round() as i32,
                    y: grid.y.round() as i32,
                },
                wire,
                index,
            },
            Hit::Element(id) | Hit::Instance(id) => {
                if !self.selection.elements.contains(&id) {
                    self.click(Hit::Element(id), shift);
                }
                Drag::Move {
                    from: grid,
                    delta: GridPoint::default(),
                }
            }
            Hit::Wire(_) | Hit::Empty => Drag::Band {
                from: grid,
                to: grid,
            },
        });
    }

    fn continue_drag(&mut self, grid: Pos2) {
        let lowest = self.selection_corner();
        match &mut self.drag {
            Some(Drag::Move { from, delta }) => {
                let (dx, dy) = (grid.x - from.x, grid.y - from.y);
                // The moved elements stay on the positive side of the grid.
                *delta = GridPoint {
                    x: (dx.round() as i32).max(-lowest.x),
                    y: (dy.round() as i32).max(-lowest.y),
                };
            }
            Some(Drag::Connect { pointer, .. }) => *pointer = grid,
            Some(Drag::ControlPoint { at, .. }) => {
                *at = GridPoint {
                    x: grid.x.round() as i32,
                    y: grid.y.round() as i32,
                };
            }
            Some(Drag::Band { to, .. }) => *to = grid,
            None => {}
        }
    }

    /// The smallest column and row of the selected elements.
    fn selection_corner(&self) -> GridPoint {
        let chosen: HashSet<ElementId> = self.selection.elements.iter().copied().collect();
        let (x, y) = self
            .chart
            .elements
            .iter()
            .filter(|e| chosen.contains(&e.id))
            .fold((i32::MAX, i32::MAX), |(x, y), e| (x.min(e.x), y.min(e.y)));
        // An element already left of or above the origin (in a loaded chart) may stay there
        // but goes no further.
        GridPoint {
            x: x.max(0),
            y: y.max(0),
        }
    }

    fn finish_drag(&mut self, frame: &mut FrameResult) {
        match self.drag.take() {
            Some(Drag::Move { delta, .. }) if delta != GridPoint::default() => {
                let result = edit::move_elements(&self.chart, &self.selection.elements, delta);
                self.apply(result, frame);
            }
            Some(Drag::Connect {
                from,
                from_output,
                pointer,
            }) => {
                let result = match (self.hit(pointer), from_output) {
                    (Hit::Input(to), true) => Some(edit::connect(&self.chart, &from, &to)),
                    (Hit::Output(source), false) => {
                        Some(edit::connect(&self.chart, &source, &from))
                    }
                    // Dropped on an element rather than its pin: its only pin of the
                    // matching side, as on an output or an input.
                    (Hit::Element(id), _) => self.only_pin(id, from_output).map(|pin| {
                        if from_output {
                            edit::connect(&self.chart, &from, &pin)
                        } else {
                            edit::connect(&self.chart, &pin, &from)
                        }
                    }),
                    // Output to output or input to input: the pin dropped on is refused.
                    (Hit::Output(target), true) | (Hit::Input(target), false) => {
                        Some(Err(if from_output {
                            project_model::CfcEditError::NotAnInput(target)
                        } else {
                            project_model::CfcEditError::NotAnOutput(target)
                        }))
                    }
                    _ => None,
                };
                if let Some(result) = result {
                    self.apply(result, frame);
                }
            }
            Some(Drag::ControlPoint { wire, index, at }) => {
                let result = edit::move_control_point(&self.chart, &wire, index, at);
                self.apply(result, frame);
            }
            Some(Drag::Band { from, to }) => {
                let band = Rect::from_two_pos(from, to);
                self.selection.wire = None;
                self.selection.elements = self
                    .chart
                    .elements
                    .iter()
                    .filter(|element| {
                        let rect = self.shapes[&element.id].rect;
                        band.contains(pos2(rect.left as f32, rect.top as f32))
                            && band.contains(pos2(rect.right as f32, rect.bottom as f32))
                    })
                    .map(|element| element.id)
                    .collect();
            }
            _ => {}
        }
    }

    /// The pin of element `id` on the input (or output) side when it has exactly one.
    fn only_pin(&self, id: ElementId, input: bool) -> Option<PinRef> {
        let shape = self.shapes.get(&id)?;
        let pins = if input { &shape.inputs } else { &shape.outputs };
        match pins.as_slice() {
            [(name, _)] => Some(PinRef::new(id, name.clone())),
            _ => None,
        }
    }

    /// The screen rectangle of grid rectangle `rect`.
    pub(super) fn screen_rect(&self, origin: Pos2, rect: super::router::GridRect) -> Rect {
        Rect::from_min_max(
            self.screen(origin, rect.left as f32, rect.top as f32),
            self.screen(origin, rect.right as f32, rect.bottom as f32),
        )
    }

    /// The size of a grid unit on screen.
    pub(super) fn unit_px(&self) -> f32 {
        GRID_PX * self.zoom
    }
}
