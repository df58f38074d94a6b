//! The context menu and the keyboard: execution order commands, pin modifiers, output kinds,
//! control points, deletion, clipboard and moving by arrow keys.

use egui::{Event, Key, Modifiers, Pos2, Response};
use project_model::cfc_edit as edit;
use project_model::{CfcChart, CfcEditError, CfcElementKind, CoilKind, Edge, GridPoint, PinRef};

use super::canvas::Hit;
use super::editor::{CfcEditor, FrameResult};
use super::entry::EntryTarget;
use super::types::CfcOrderCommand;
use crate::diagram::clipboard::{copied_structure, copy_structure, keep_structure};

/// Where pasted elements go, relative to where they were copied, in grid units.
const PASTE_OFFSET: GridPoint = GridPoint { x: 2, y: 2 };

impl CfcEditor {
    /// The context menu of what was right-clicked.
    pub(super) fn context_menu_ui(
        &mut self,
        response: &Response,
        origin: Pos2,
        frame: &mut FrameResult,
    ) {
        if response.secondary_clicked()
            && let Some(pointer) = response.interact_pointer_pos()
        {
            let hit = self.hit(self.grid_at(origin, pointer));
            match &hit {
                Hit::Element(id)
                | Hit::Instance(id)
                | Hit::Input(PinRef { element: id, .. })
                | Hit::Output(PinRef { element: id, .. }) => {
                    if !self.selection.elements.contains(id) {
                        self.selection.elements = vec![*id];
                        self.selection.wire = None;
                    }
                }
                Hit::Wire(to) | Hit::ControlPoint(to, _) => {
                    self.selection.elements.clear();
                    self.selection.wire = Some(to.clone());
                }
                Hit::Empty => {}
            }
            self.context_hit = Some(hit);
        }
        let Some(hit) = self.context_hit.clone() else {
            return;
        };
        let texts = self.texts.clone();
        let breakpoint_place = self.breakpoint_place();
        response.context_menu(|ui| {
            if ui
                .add_enabled(
                    breakpoint_place.is_some(),
                    egui::Button::new(&texts.toggle_breakpoint),
                )
                .clicked()
            {
                frame.toggle_breakpoint = breakpoint_place;
                ui.close();
            }
            ui.checkbox(&mut self.show_order, &texts.display_execution_order);
            if self.read_only {
                return;
            }
            ui.menu_button(&texts.execution_order, |ui| {
                let commands = [
                    (&texts.send_to_front, CfcOrderCommand::SendToFront),
                    (&texts.send_to_back, CfcOrderCommand::SendToBack),
                    (&texts.move_up, CfcOrderCommand::MoveUp),
                    (&texts.move_down, CfcOrderCommand::MoveDown),
                ];
                for (words, command) in commands {
                    if ui.button(words).clicked() {
                        self.order_command(command, frame);
                        ui.close();
                    }
                }
                if ui.button(&texts.set_execution_order).clicked() {
                    if let [id] = self.selection.elements.as_slice() {
                        let id = *id;
                        let current = self
                            .chart
                            .elements
                            .iter()
                            .find(|e| e.id == id)
                            .and_then(|e| e.order);
                        match current {
                            Some(order) => {
                                self.entry = Some(super::entry::CfcEntry {
                                    target: EntryTarget::Order(id),
                                    field: crate::diagram::field::CompletionField::new(
                                        order.to_string(),
                                    ),
                                });
                            }
                            None => {
                                self.apply(Err(CfcEditError::NotExecutable(id)), frame);
                            }
                        }
                    }
                    ui.close();
                }
                ui.separator();
                for (words, command) in [
                    (&texts.order_by_data_flow, CfcOrderCommand::OrderByDataFlow),
                    (&texts.order_by_topology, CfcOrderCommand::OrderByTopology),
                ] {
                    if ui.button(words).clicked() {
                        self.order_command(command, frame);
                        ui.close();
                    }
                }
            });
            match &hit {
                Hit::Input(pin) | Hit::Output(pin) => {
                    if ui.button(&texts.negate).clicked() {
                        let result = edit::toggle_negation(&self.chart, pin);
                        self.apply(result, frame);
                        ui.close();
                    }
                    if matches!(hit, Hit::Input(_)) {
                        for (words, edge) in [
                            (&texts.rising_edge, Edge::Rising),
                            (&texts.falling_edge, Edge::Falling),
                            (&texts.no_edge, Edge::None),
                        ] {
                            if ui.button(words).clicked() {
                                let result = edit::set_edge(&self.chart, pin, edge);
                                self.apply(result, frame);
                                ui.close();
                            }
                        }
                        if ui.button(&texts.input_pin).clicked() {
                            let result = edit::extend_box(&self.chart, pin.element);
                            self.apply(result, frame);
                            ui.close();
                        }
                    }
                }
                Hit::ControlPoint(to, index)
                    if ui.button(&texts.remove_control_point).clicked() =>
                {
                    let result = edit::remove_control_point(&self.chart, to, *index);
                    self.apply(result, frame);
                    ui.close();
                }
                _ => {}
            }
            if let Some(id) = self.selection.elements.first().copied()
                && self
                    .chart
                    .elements
                    .iter()
                    .any(|e| e.id == id && matches!(e.kind, CfcElementKind::Output { .. }))
            {
                for (words, coil) in [
                    (&texts.plain_output, CoilKind::Normal),
                    (&texts.set_output, CoilKind::Set),
                    (&texts.reset_output, CoilKind::Reset),
                ] {
                    if ui.button(words).clicked() {
                        let result = edit::set_coil(&self.chart, id, coil);
                        self.apply(result, frame);
                        ui.close();
                    }
                }
            }
            if matches!(hit, Hit::Element(_) | Hit::Instance(_) | Hit::Wire(_))
                && ui.button(&texts.delete).clicked()
            {
                self.delete_selection(frame);
                ui.close();
            }
        });
    }

    /// Deletes the selected elements, or the selected wire.
    pub(super) fn delete_selection(&mut self, frame: &mut FrameResult) {
        if let Some(wire) = self.selection.wire.take() {
            let result = edit::disconnect(&self.chart, &wire);
            self.apply(result, frame);
        } else if !self.selection.elements.is_empty() {
            let result = edit::delete_elements(&self.chart, &self.selection.elements);
            if self.apply(result, frame) {
                self.selection.elements.clear();
            }
        }
    }

    /// The keys of the focused canvas.
    pub(super) fn handle_events(
        &mut self,
        ctx: &egui::Context,
        events: &[Event],
        frame: &mut FrameResult,
    ) {
        for event in events {
            match event {
                Event::Copy => self.copy(ctx),
                Event::Cut => {
                    self.copy(ctx);
                    self.delete_selection(frame);
                }
                Event::Paste(text) => self.paste(ctx, text, frame),
                Event::Key {
                    key,
                    pressed: true,
                    modifiers,
                    ..
                } => self.key(*key, *modifiers, frame),
                _ => {}
            }
        }
    }

    fn key(&mut self, key: Key, modifiers: Modifiers, frame: &mut FrameResult) {
        if key == Key::F9 && modifiers.is_none() {
            frame.toggle_breakpoint = self.breakpoint_place();
            return;
        }
        let command = modifiers.command;
        let order = match (key, command) {
            (Key::Home, true) => Some(CfcOrderCommand::SendToFront),
            (Key::End, true) => Some(CfcOrderCommand::SendToBack),
            (Key::PageUp, true) => Some(CfcOrderCommand::MoveUp),
            (Key::PageDown, true) => Some(CfcOrderCommand::MoveDown),
            _ => None,
        };
        if let Some(order) = order {
            if !self.read_only {
                self.order_command(order, frame);
            }
            return;
        }
        let step = |dx: i32, dy: i32| GridPoint { x: dx, y: dy };
        let delta = match key {
            Key::ArrowLeft => Some(step(-1, 0)),
            Key::ArrowRight => Some(step(1, 0)),
            Key::ArrowUp => Some(step(0, -1)),
            Key::ArrowDown => Some(step(0, 1)),
            _ => None,
        };
        match key {
            _ if delta.is_some() => {
                if let Some(delta) = delta
                    && !self.selection.elements.is_empty()
                {
                    let result = edit::move_elements(&self.chart, &self.selection.elements, delta);
                    self.apply(result, frame);
                }
            }
            Key::Delete | Key::Backspace => self.delete_selection(frame),
            // Enter and F2 type into the selected element, as a double click does.
            Key::Enter | Key::F2 => {
                if let [id] = self.selection.elements.as_slice() {
                    self.open_entry_at(Hit::Element(*id));
                }
            }
            Key::Escape => {
                self.tool = None;
                self.drag = None;
                self.selection = Default::default();
            }
            Key::A if command => {
                self.selection.wire = None;
                self.selection.elements = self.chart.elements.iter().map(|e| e.id).collect();
            }
            _ => {}
        }
    }

    fn clipboard_id() -> egui::Id {
        egui::Id::unique("editor::cfc::clipboard")
    }

    /// Copies the selected elements with the wires between them. Other applications get their
    /// texts; a CFC editor pastes the elements kept in the context, shared by all of them.
    fn copy(&self, ctx: &egui::Context) {
        let Ok(fragment) = edit::copy_elements(&self.chart, &self.selection.elements) else {
            return;
        };
        let words: Vec<String> = fragment
            .elements
            .iter()
            .map(|element| super::geometry::element_title(&element.kind).to_owned())
            .collect();
        copy_structure(ctx, Self::clipboard_id(), words, fragment);
    }

    /// Pastes the elements copied last beside where they were, or, when the system clipboard
    /// holds other text (a name copied elsewhere), types that text into the selected element.
    fn paste(&mut self, ctx: &egui::Context, text: &str, frame: &mut FrameResult) {
        if self.read_only {
            return;
        }
        let copied = copied_structure::<CfcChart>(ctx, Self::clipboard_id(), text);
        let Some(copied) = copied else {
            if let [id] = self.selection.elements.as_slice()
                && !text.trim().is_empty()
            {
                let result = edit::set_text(&self.chart, *id, text.trim());
                self.apply(result, frame);
            }
            return;
        };
        let (chart, ids) = edit::paste_elements(&self.chart, &copied.structure, PASTE_OFFSET);
        if self.apply(Ok(chart), frame) {
            self.selection.elements = ids.clone();
            self.selection.wire = None;
            // A second paste lands beside the first.
            if let Ok(moved) = edit::move_elements(
                &copied.structure,
                &copied
                    .structure
                    .elements
                    .iter()
                    .map(|e| e.id)
                    .collect::<Vec<_>>(),
                PASTE_OFFSET,
            ) {
                keep_structure(ctx, Self::clipboard_id(), copied.text.clone(), moved);
            }
        }
    }
}
