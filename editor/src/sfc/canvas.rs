//! The chart's canvas in a frame: zoom, the pointer (selection, double-click to edit, the
//! context menu), the keys, and where the text field goes.

use egui::{Event, Id, Key, Pos2, Rect, Response, Sense, Ui};
use project_model::sfc_edit::find_node;
use project_model::{ElementId, SfcNode};

use super::commands::{INSERTIONS, SfcCommand, command_for_key};
use super::editor::{FrameResult, SfcEditor};
use crate::DiagramServices;
use crate::diagram::canvas_input::ZOOM_RANGE;
use crate::diagram::canvas_input::{describe_canvas, focused_canvas_events};

/// Which way an arrow key moves the selection.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Direction {
    Up,
    Down,
    Left,
    Right,
}

impl SfcEditor {
    pub(super) fn canvas_ui(
        &mut self,
        ui: &mut Ui,
        id: Id,
        label: &str,
        services: &dyn DiagramServices,
        frame: &mut FrameResult,
    ) -> Response {
        let size = (self.layout.size * self.zoom).max(ui.available_size());
        let (rect, _) = ui.allocate_exact_size(size, Sense::hover());
        let canvas_id = Self::canvas_id(id);
        let response = ui.interact(rect, canvas_id, Sense::click_and_drag());
        describe_canvas(ui, &response, label);
        if std::mem::take(&mut self.focus_requested) || response.clicked() {
            response.request_focus();
        }
        self.last_origin = rect.min;
        if response.hovered() {
            let factor = ui.input(|input| input.zoom_delta());
            if (factor - 1.0).abs() > f32::EPSILON {
                self.zoom = (self.zoom * factor).clamp(ZOOM_RANGE.0, ZOOM_RANGE.1);
            }
        }
        if response.has_focus() && self.entry.is_none() {
            let events = focused_canvas_events(ui, canvas_id);
            self.handle_events(ui.ctx(), &events, frame);
        }
        self.pointer_ui(ui, &response, frame);
        self.paint_ui(ui, &response);
        self.scroll_to_selection(ui);
        if let Some(entry_rect) = self.entry_rect() {
            let screen = self.to_screen(entry_rect);
            self.entry_ui(ui.ctx(), id, screen, services, frame);
        }
        response
    }

    /// Scrolls a new selection into view once it is laid out (a step inserted below the
    /// visible part, a finding revealed in a long chart).
    fn scroll_to_selection(&mut self, ui: &Ui) {
        if self.selection == self.scrolled_to {
            return;
        }
        if self.selection.is_empty() {
            self.scrolled_to.clear();
            return;
        }
        let rect = self
            .selection
            .iter()
            .filter_map(|id| self.layout.element(*id))
            .map(|placed| self.to_screen(placed.rect))
            .reduce(|all, one| all.union(one));
        if let Some(rect) = rect {
            ui.scroll_to_rect(rect, None);
            self.scrolled_to.clone_from(&self.selection);
        }
    }

    /// The content point (zoom 1) under screen point `pos`.
    fn content_pos(&self, pos: Pos2) -> Pos2 {
        Pos2::ZERO + (pos - self.last_origin) / self.zoom
    }

    fn pointer_ui(&mut self, ui: &Ui, response: &Response, frame: &mut FrameResult) {
        // A toolbox item dropped on a node inserts there, as if the node had been selected
        // and the item clicked.
        if let Some(command) = response.dnd_release_payload::<SfcCommand>()
            && let Some(pointer) = response.hover_pos()
        {
            if let Some(hit) = self.layout.hit(self.content_pos(pointer)) {
                self.select(vec![hit]);
                self.command(ui.ctx(), *command, frame);
            }
            return;
        }
        let pointer = response.interact_pointer_pos();
        if response.clicked() || response.secondary_clicked() || response.double_clicked() {
            let hit = pointer.and_then(|pos| self.layout.hit(self.content_pos(pos)));
            let shift = ui.input(|input| input.modifiers.shift);
            match hit {
                Some(hit) if shift && response.clicked() => {
                    if let Some(index) = self.selection.iter().position(|id| *id == hit) {
                        self.selection.remove(index);
                    } else {
                        self.selection.push(hit);
                    }
                    self.panel = None;
                }
                // A right click on a selected node keeps the selection for the menu.
                Some(hit) if response.secondary_clicked() && self.selection.contains(&hit) => {}
                Some(hit) => self.select(vec![hit]),
                None if response.clicked() => self.select(Vec::new()),
                None => {}
            }
            if response.double_clicked()
                && let Some(hit) = hit
            {
                self.double_click(hit, pointer.map(|pos| self.content_pos(pos)));
            }
        }
        let mut chosen = None;
        let breakpoint_place = self.breakpoint_place();
        response.context_menu(|ui| {
            if ui
                .add_enabled(
                    breakpoint_place.is_some(),
                    egui::Button::new(&self.texts.toggle_breakpoint),
                )
                .clicked()
            {
                frame.toggle_breakpoint = breakpoint_place;
                ui.close();
            }
            if !self.read_only {
                for command in INSERTIONS.into_iter().chain([
                    SfcCommand::Delete,
                    SfcCommand::Copy,
                    SfcCommand::Paste,
                    SfcCommand::EditText,
                ]) {
                    if ui.button(self.command_text(command)).clicked() {
                        chosen = Some(command);
                        ui.close();
                    }
                }
            }
            if self.selected_macro().is_some() && ui.button(&self.texts.open_macro).clicked() {
                chosen = Some(SfcCommand::OpenMacro);
                ui.close();
            }
            if !self.macro_path.is_empty() && ui.button(&self.texts.leave_macro).clicked() {
                chosen = Some(SfcCommand::LeaveMacro);
                ui.close();
            }
            if let Some(online) = &self.online {
                if let Some(step) = self.selected_step_id() {
                    let active = online.steps.get(&step).is_some_and(|state| state.active);
                    let text = if active {
                        &self.texts.deactivate_step
                    } else {
                        &self.texts.activate_step
                    };
                    if ui.button(text).clicked() {
                        chosen = Some(SfcCommand::ToggleStepActive);
                        ui.close();
                    }
                }
                if online.tip_mode
                    && self.selected_transition_id().is_some()
                    && ui.button(&self.texts.fire_transition).clicked()
                {
                    chosen = Some(SfcCommand::FireTransition);
                    ui.close();
                }
            }
        });
        if let Some(command) = chosen {
            self.command(ui.ctx(), command, frame);
        }
    }

    /// A double click edits the text under the pointer, or opens a macro step.
    fn double_click(&mut self, hit: ElementId, pos: Option<Pos2>) {
        let Some(placed) = self.layout.element(hit) else {
            return;
        };
        if let (Some(actions), Some(pos)) = (placed.actions, pos)
            && actions.rect.contains(pos)
        {
            let row = ((pos.y - actions.rect.top()) / super::layout::ACTION_ROW_PX) as usize;
            self.open_association_entry(hit, row);
            return;
        }
        if matches!(placed.shape, super::layout::SfcShape::Macro) {
            // A double click zooms into a macro step; F2 edits its name.
            self.macro_path.push(hit);
            self.selection.clear();
            self.entry = None;
            self.panel = None;
            self.relayout();
            return;
        }
        self.open_entry(None);
    }

    fn selected_macro(&self) -> Option<ElementId> {
        let [id] = self.selection[..] else {
            return None;
        };
        matches!(find_node(&self.chart, id), Some(SfcNode::Macro(_))).then_some(id)
    }

    fn selected_step_id(&self) -> Option<ElementId> {
        let [id] = self.selection[..] else {
            return None;
        };
        matches!(find_node(&self.chart, id), Some(SfcNode::Step(_))).then_some(id)
    }

    fn selected_transition_id(&self) -> Option<ElementId> {
        let [id] = self.selection[..] else {
            return None;
        };
        matches!(find_node(&self.chart, id), Some(SfcNode::Transition(_))).then_some(id)
    }

    /// Handles the keys and clipboard events of a frame while the canvas has focus.
    fn handle_events(&mut self, ctx: &egui::Context, events: &[Event], frame: &mut FrameResult) {
        for event in events {
            match event {
                Event::Key {
                    key,
                    pressed: true,
                    modifiers,
                    ..
                } => {
                    if modifiers.command && *key == Key::Enter {
                        let command = if self.selected_transition_id().is_some() {
                            SfcCommand::FireTransition
                        } else {
                            SfcCommand::ToggleStepActive
                        };
                        self.command(ctx, command, frame);
                        continue;
                    }
                    if let Some(command) = command_for_key(*key, *modifiers) {
                        self.command(ctx, command, frame);
                        continue;
                    }
                    if *key == Key::F9 && modifiers.is_none() {
                        frame.toggle_breakpoint = self.breakpoint_place();
                        continue;
                    }
                    let extend = modifiers.shift;
                    match key {
                        Key::ArrowUp => self.navigate(Direction::Up, extend),
                        Key::ArrowDown => self.navigate(Direction::Down, extend),
                        Key::ArrowLeft => self.navigate(Direction::Left, false),
                        Key::ArrowRight => self.navigate(Direction::Right, false),
                        Key::Enter if self.selected_macro().is_some() => {
                            self.command(ctx, SfcCommand::OpenMacro, frame);
                        }
                        Key::Enter => self.open_entry(None),
                        Key::Escape => self.select(Vec::new()),
                        _ => {}
                    }
                }
                Event::Text(text) if !self.read_only && !text.trim().is_empty() => {
                    self.open_entry(Some(text.as_str()));
                }
                Event::Copy => self.command(ctx, SfcCommand::Copy, frame),
                Event::Cut => {
                    self.command(ctx, SfcCommand::Copy, frame);
                    self.command(ctx, SfcCommand::Delete, frame);
                }
                Event::Paste(_) => self.command(ctx, SfcCommand::Paste, frame),
                _ => {}
            }
        }
    }

    /// Moves the selection with an arrow: up and down along the layout's order (Shift extends
    /// the selection), left and right to the nearest node beside it.
    pub(super) fn navigate(&mut self, direction: Direction, extend: bool) {
        let order: Vec<(ElementId, Rect)> = self
            .layout
            .elements
            .iter()
            .map(|placed| (placed.id, placed.rect))
            .collect();
        let Some(&current) = self.selection.last() else {
            if let Some((first, _)) = order.first() {
                self.select(vec![*first]);
            }
            return;
        };
        let Some(index) = order.iter().position(|(id, _)| *id == current) else {
            return;
        };
        let current_rect = order[index].1;
        let next = match direction {
            Direction::Up => index.checked_sub(1).map(|i| order[i].0),
            Direction::Down => order.get(index + 1).map(|(id, _)| *id),
            Direction::Left | Direction::Right => order
                .iter()
                .filter(|(_, rect)| match direction {
                    Direction::Left => rect.center().x < current_rect.center().x - 1.0,
                    _ => rect.center().x > current_rect.center().x + 1.0,
                })
                .min_by(|(_, a), (_, b)| {
                    // A node on the same row (in the next branch) comes before any other;
                    // among the rest, nearness counts vertical distance double.
                    let distance = |rect: &Rect| {
                        let same_row = rect.y_range().intersects(current_rect.y_range());
                        let row_penalty = if same_row { 0.0 } else { 10_000.0 };
                        row_penalty
                            + (rect.center().y - current_rect.center().y).abs() * 2.0
                            + (rect.center().x - current_rect.center().x).abs()
                    };
                    distance(a).total_cmp(&distance(b))
                })
                .map(|(id, _)| *id),
        };
        if let Some(next) = next {
            if extend {
                if !self.selection.contains(&next) {
                    self.selection.push(next);
                }
                self.panel = None;
            } else {
                self.select(vec![next]);
            }
        }
    }
}
