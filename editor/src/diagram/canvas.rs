//! The canvas in a frame: zoom and pan, hit testing, the pointer (selection, rubber band,
//! double-click to edit, drops from the toolbox), and where the text field goes.

use egui::{Id, PointerButton, Pos2, Rect, Response, Stroke, StrokeKind, Ui, pos2, vec2};
use project_model::{Anchor, ElementRef, HeaderField};

use super::canvas_input::{CanvasView, canvas_response, focused_canvas_events, zoom_and_pan_ui};
use super::editor::{DiagramEditor, FrameResult, HEADER_HEIGHT_PX, LEFT_MARGIN_PX};
use super::entry::EntryTarget;
use super::measure::shortened;
use super::placed::{InsertTarget, Shape};
use super::toolbox::{ToolboxBlock, ToolboxItem};
use super::types::DiagramServices;
use crate::EditorPalette;

/// How near to an insertion point a drop must be, in cells.
const DROP_RADIUS_CELLS: f32 = 0.6;

/// What the pointer is over.
#[derive(Clone, Debug, PartialEq)]
pub(super) enum Hit {
    /// An element of a network, and the box input pin at the pointer, if any.
    Element(usize, project_model::ElementId, Option<String>),
    /// A network's header line.
    Header(usize, HeaderField),
    /// A network's drawing, away from its elements.
    Network(usize),
    /// Nothing.
    Empty,
}

impl DiagramEditor {
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
        // Half a view of room below the content, so the last network can be scrolled up from
        // the bottom edge, and beside it once zoomed in, so a zoom keeps the point under the
        // mouse where it is; at 100 % and below a horizontal scrollbar shows only when a
        // network is wider than the pane.
        let content = self.content_px * self.zoom;
        let room_x = if self.zoom > 1.0 + f32::EPSILON {
            viewport.width() * 0.5
        } else {
            0.0
        };
        let size = vec2(
            content.x.max(viewport.width()) + room_x,
            content.y.max(viewport.height()) + viewport.height() * 0.5,
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
        self.pointer_ui(ui, &response, origin, services, frame);
        self.paint_visible(ui, origin, viewport, &response);
        if self.scroll_to_selection {
            self.scroll_to_selection = false;
            if let Some(target) = self.selection_rect_px() {
                let screen = Rect::from_min_max(
                    origin + target.min.to_vec2() * self.zoom,
                    origin + target.max.to_vec2() * self.zoom,
                );
                ui.scroll_to_rect(screen.expand(8.0), None);
            }
        }
        if let Some(entry_rect) = self.entry_rect_px() {
            let screen = Rect::from_min_max(
                origin + entry_rect.min.to_vec2() * self.zoom,
                origin + entry_rect.max.to_vec2() * self.zoom,
            );
            self.entry_ui(ui.ctx(), id, screen, services, frame);
        }
        response
    }

    /// What is at `pos`, in content points at zoom 1.
    pub(super) fn hit(&self, pos: Pos2) -> Hit {
        let count = self.networks.len();
        let index = self.tops_px[1..].partition_point(|end| *end <= pos.y);
        if index >= count {
            return Hit::Empty;
        }
        let top = self.tops_px[index];
        if pos.y < top + HEADER_HEIGHT_PX {
            let field = if pos.x < LEFT_MARGIN_PX {
                HeaderField::Label
            } else if pos.y < top + HEADER_HEIGHT_PX / 2.0 {
                HeaderField::Title
            } else {
                HeaderField::Comment
            };
            return Hit::Header(index, field);
        }
        let origin = self.network_origin_px(index);
        let cell = pos2(
            (pos.x - origin.x) / self.cell_px().x,
            (pos.y - origin.y) / self.cell_px().y,
        );
        let Some(element) = self.layouts[index].element_at(cell) else {
            return Hit::Network(index);
        };
        let Some(id) = element.id else {
            return Hit::Network(index);
        };
        // The left half of a box holds its input pins, one per row.
        let pin = match &element.shape {
            Shape::Box { inputs, .. } if cell.x < element.rect.center().x => inputs
                .iter()
                .rev()
                .find(|pin| pin.row <= cell.y)
                .filter(|pin| !pin.name.is_empty())
                .map(|pin| pin.name.clone()),
            _ => None,
        };
        Hit::Element(index, id, pin)
    }

    fn pointer_ui(
        &mut self,
        ui: &Ui,
        response: &Response,
        origin: Pos2,
        services: &dyn DiagramServices,
        frame: &mut FrameResult,
    ) {
        let zoom = self.zoom;
        let to_content = |screen: Pos2| ((screen - origin) / zoom).to_pos2();
        if let Some(item) = response.dnd_release_payload::<ToolboxItem>()
            && let Some(pointer) = response.hover_pos()
        {
            if let Some((_, target)) = self.drop_target(to_content(pointer)) {
                self.drop_item(*item, target, frame);
            }
            return;
        }
        if let Some(block) = response.dnd_release_payload::<ToolboxBlock>()
            && let Some(pointer) = response.hover_pos()
        {
            if let Some((_, target)) = self.drop_target(to_content(pointer)) {
                self.insert_box(block.0, target, services, frame);
            }
            return;
        }
        if response.clicked_by(PointerButton::Primary)
            && let Some(pointer) = response.interact_pointer_pos()
        {
            let shift = ui.input(|input| input.modifiers.shift);
            let hit = self.hit(to_content(pointer));
            self.click(hit, shift);
        }
        if response.secondary_clicked()
            && let Some(pointer) = response.interact_pointer_pos()
        {
            // A right-click selects what it is on, unless that is selected already, so the
            // menu acts on what the user pointed at.
            match self.hit(to_content(pointer)) {
                Hit::Element(network, element, _) => {
                    if !self.selection.elements.contains(&element) {
                        self.select(Some(network), vec![element]);
                    }
                }
                Hit::Header(network, _) | Hit::Network(network) => {
                    self.select(Some(network), Vec::new());
                }
                Hit::Empty => {}
            }
        }
        let toggle_words = self.texts.toggle_breakpoint.clone();
        let place = self.breakpoint_place();
        response.context_menu(|ui| {
            if ui
                .add_enabled(place.is_some(), egui::Button::new(&toggle_words))
                .clicked()
            {
                frame.toggle_breakpoint = place;
                ui.close();
            }
        });
        if response.double_clicked()
            && let Some(pointer) = response.interact_pointer_pos()
        {
            match self.hit(to_content(pointer)) {
                Hit::Element(_, element, Some(pin)) => {
                    self.open_entry(EntryTarget::Pin(element, pin), None)
                }
                Hit::Element(_, element, None) => {
                    self.open_entry(EntryTarget::Element(element), None)
                }
                Hit::Header(index, field) => {
                    self.open_entry(EntryTarget::Header(index, field), None)
                }
                Hit::Network(_) | Hit::Empty => {}
            }
        }
        if response.drag_started_by(PointerButton::Primary)
            && let Some(pointer) = response.interact_pointer_pos()
        {
            let from = to_content(pointer);
            if !matches!(self.hit(from), Hit::Element(..)) {
                self.rubber_band_from = Some(from);
            }
        }
        if let Some(from) = self.rubber_band_from
            && let Some(pointer) = ui.input(|input| input.pointer.interact_pos())
        {
            let band = Rect::from_two_pos(from, to_content(pointer));
            if response.drag_stopped() {
                self.rubber_band_from = None;
                self.select_in(band, ui.input(|input| input.modifiers.shift));
            } else {
                let screen = Rect::from_two_pos(origin + from.to_vec2() * self.zoom, pointer);
                let palette = EditorPalette::of(ui);
                ui.painter()
                    .rect_filled(screen, 0.0, palette.diagram_selection);
                ui.painter().rect_stroke(
                    screen,
                    0.0,
                    Stroke::new(1.0, palette.power_on),
                    StrokeKind::Inside,
                );
            }
        }
        if let Some(pointer) = response.hover_pos()
            && let Hit::Element(network, element, _) = self.hit(to_content(pointer))
        {
            // A shortened operand shows in full first, then the findings on the element.
            let full_text = self.layouts[network]
                .element(element)
                .and_then(|placed| placed.shape.text())
                .filter(|text| shortened(text).1)
                .map(str::to_owned);
            let messages: Vec<String> = full_text
                .into_iter()
                .chain(
                    self.diagnostics
                        .iter()
                        .filter(|diagnostic| diagnostic.element == Some(element))
                        .map(|diagnostic| match &diagnostic.pin {
                            Some(pin) => {
                                format!("{} ({pin}): {}", diagnostic.code, diagnostic.message)
                            }
                            None => format!("{}: {}", diagnostic.code, diagnostic.message),
                        }),
                )
                .collect();
            if !messages.is_empty()
                && let Some(at) = self.element_screen_rect(element)
            {
                // The tooltip belongs to the element, not to the canvas, whose own tooltip
                // would go below the whole canvas, far from what it explains.
                let text = messages.join("\n");
                egui::Tooltip::always_open(
                    ui.ctx().clone(),
                    response.layer_id,
                    response.id.with("element tooltip"),
                    at,
                )
                .show(|ui| ui.label(text));
            }
        }
    }

    fn click(&mut self, hit: Hit, shift: bool) {
        match hit {
            Hit::Element(network, element, pin) => {
                if let Some(operand) = self.online_operand(element) {
                    self.selection.network = Some(network);
                    self.selection.elements = vec![element];
                    self.open_entry(EntryTarget::Prepared { element, operand }, None);
                } else if shift {
                    if let Some(position) =
                        self.selection.elements.iter().position(|id| *id == element)
                    {
                        self.selection.elements.remove(position);
                    } else {
                        self.selection.elements.push(element);
                    }
                    self.selection.network.get_or_insert(network);
                } else {
                    self.select(Some(network), vec![element]);
                    self.selected_pin = pin;
                }
            }
            Hit::Header(network, _) | Hit::Network(network) => {
                self.select(Some(network), Vec::new())
            }
            Hit::Empty => self.select(None, Vec::new()),
        }
        self.scroll_to_selection = false;
    }

    /// The operand of `element` when online and the element reads or writes a variable.
    fn online_operand(&self, element: project_model::ElementId) -> Option<String> {
        self.online.as_ref()?;
        let network = self
            .networks
            .iter()
            .find(|network| network.element(element).is_some())?;
        match network.element(element)? {
            ElementRef::Operand(operand) if !operand.text.is_empty() => Some(operand.text.clone()),
            ElementRef::Output(project_model::NetworkOutput::Coil(coil))
                if !coil.variable.is_empty() =>
            {
                Some(coil.variable.clone())
            }
            _ => None,
        }
    }

    /// Selects the elements whose cells meet `band` (content points at zoom 1).
    fn select_in(&mut self, band: Rect, add: bool) {
        if !add {
            self.selection.elements.clear();
            self.selection.network = None;
        }
        let range = self.networks_between(band.top(), band.bottom());
        for index in range {
            let origin = self.network_origin_px(index);
            for element in &self.layouts[index].elements {
                let Some(id) = element.id else { continue };
                if matches!(element.shape, Shape::Group) {
                    continue;
                }
                let rect = Rect::from_min_max(
                    origin + element.rect.min.to_vec2() * self.cell_px(),
                    origin + element.rect.max.to_vec2() * self.cell_px(),
                );
                if band.intersects(rect) && !self.selection.elements.contains(&id) {
                    self.selection.elements.push(id);
                    self.selection.network.get_or_insert(index);
                }
            }
        }
    }

    /// The nearest insertion point to `pos` (content points at zoom 1) in the networks there.
    pub(super) fn drop_target(&self, pos: Pos2) -> Option<(usize, InsertTarget)> {
        let range = self.networks_between(pos.y - self.cell_px().y, pos.y + self.cell_px().y);
        range
            .filter_map(|index| {
                let origin = self.network_origin_px(index);
                let cell = ((pos - origin) / self.cell_px()).to_pos2();
                self.layouts[index]
                    .insert_point_near(cell, DROP_RADIUS_CELLS)
                    .map(|point| (index, point.target, point.pos.distance(cell)))
            })
            .min_by(|a, b| a.2.total_cmp(&b.2))
            .map(|(index, target, _)| (index, target))
    }

    /// The content rectangle (points at zoom 1) of the selection, to scroll it into view.
    fn selection_rect_px(&self) -> Option<Rect> {
        let index = self.selection.network?;
        let origin = self.network_origin_px(index);
        let top = self.tops_px[index];
        let element = self
            .selection
            .elements
            .first()
            .and_then(|id| self.layouts.get(index)?.element(*id));
        Some(match element {
            Some(element) => Rect::from_min_max(
                origin + element.rect.min.to_vec2() * self.cell_px(),
                origin + element.rect.max.to_vec2() * self.cell_px(),
            ),
            None => {
                Rect::from_min_size(pos2(0.0, top), vec2(LEFT_MARGIN_PX * 4.0, HEADER_HEIGHT_PX))
            }
        })
    }

    /// The content rectangle (points at zoom 1) the open text field goes over.
    fn entry_rect_px(&self) -> Option<Rect> {
        let entry = self.entry.as_ref()?;
        let in_network = |index: usize, cells: Rect| {
            let origin = self.network_origin_px(index);
            Rect::from_min_max(
                origin + cells.min.to_vec2() * self.cell_px(),
                origin + cells.max.to_vec2() * self.cell_px(),
            )
        };
        match &entry.target {
            EntryTarget::Element(id)
            | EntryTarget::Pin(id, _)
            | EntryTarget::Prepared { element: id, .. } => {
                let index = self
                    .networks
                    .iter()
                    .position(|network| network.element(*id).is_some())?;
                Some(in_network(index, self.layouts[index].element(*id)?.rect))
            }
            EntryTarget::NewBox(target) => {
                let index = match target {
                    InsertTarget::Series { anchor, .. } | InsertTarget::Output { anchor } => {
                        match anchor {
                            Anchor::Network(index) => *index,
                            Anchor::Element(id) => self
                                .networks
                                .iter()
                                .position(|network| network.element(*id).is_some())?,
                        }
                    }
                    InsertTarget::Parallel { id, .. } => self
                        .networks
                        .iter()
                        .position(|network| network.element(*id).is_some())?,
                };
                let point = self
                    .layouts
                    .get(index)?
                    .insert_points
                    .iter()
                    .find(|point| point.target == *target);
                let at = point.map_or(pos2(0.0, 0.0), |point| point.pos);
                Some(in_network(index, Rect::from_min_size(at, vec2(2.0, 1.0))))
            }
            EntryTarget::Header(index, field) => {
                let index = (*index).min(self.networks.len().checked_sub(1)?);
                let top = self.tops_px[index]
                    + if *field == HeaderField::Comment {
                        18.0
                    } else {
                        0.0
                    };
                Some(Rect::from_min_size(
                    pos2(LEFT_MARGIN_PX, top),
                    vec2(self.cell_px().x * 4.0, 20.0),
                ))
            }
        }
    }
}
