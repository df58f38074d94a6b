//! The keyboard and the clipboard: commands by key, arrows, typing into the selected element,
//! cut, copy and paste, and running commands and toolbox drops as structural edits.

use egui::{Event, Id, Key};
use project_model::{
    Anchor, ElementRef, HeaderField, NetworkClipboard, NetworkEditError, Side, copy_elements,
    copy_networks, paste,
};

use super::clipboard::{copied_structure, copy_structure};
use super::commands::{DiagramCommand, command_for_key, run_command};
use super::editor::{DiagramEditor, FrameResult};
use super::entry::{Entry, EntryTarget};
use super::navigate::Direction;
use super::placed::InsertTarget;
use super::toolbox::ToolboxItem;
use super::types::DiagramRefusal;

impl DiagramEditor {
    /// Handles the keys, text and clipboard events of a frame while the canvas has focus.
    pub(super) fn handle_events(
        &mut self,
        ctx: &egui::Context,
        events: &[Event],
        frame: &mut FrameResult,
    ) {
        for event in events {
            match event {
                Event::Key {
                    key,
                    pressed: true,
                    modifiers,
                    ..
                } => {
                    if let Some(command) = command_for_key(*key, *modifiers) {
                        self.command(command, frame);
                        continue;
                    }
                    match key {
                        Key::ArrowLeft => self.navigate(Direction::Left),
                        Key::ArrowRight => self.navigate(Direction::Right),
                        Key::ArrowUp => self.navigate(Direction::Up),
                        Key::ArrowDown => self.navigate(Direction::Down),
                        Key::Enter => self.open_selected_entry(None),
                        Key::F2 => {
                            self.assistant_open = true;
                            self.open_selected_entry(None);
                        }
                        Key::Escape => self.select(None, Vec::new()),
                        Key::F9 if modifiers.is_none() => {
                            frame.toggle_breakpoint = self.breakpoint_place();
                        }
                        _ => {}
                    }
                }
                Event::Text(text) if !self.read_only => self.open_selected_entry(Some(text)),
                Event::Copy => self.copy(ctx),
                Event::Cut => {
                    self.copy(ctx);
                    self.command(DiagramCommand::Delete, frame);
                }
                Event::Paste(text) => self.paste(ctx, text, frame),
                _ => {}
            }
        }
    }

    /// Opens the text field of the selected element or network title, with `typed` in it.
    fn open_selected_entry(&mut self, typed: Option<&str>) {
        if let [element] = self.selection.elements.as_slice() {
            let element = *element;
            let target = match self.selected_pin.clone() {
                Some(pin) => EntryTarget::Pin(element, pin),
                None => EntryTarget::Element(element),
            };
            self.open_entry(target, typed);
        } else if self.selection.elements.is_empty()
            && let Some(index) = self.selection.network
        {
            self.open_entry(EntryTarget::Header(index, HeaderField::Title), typed);
        }
    }

    fn clipboard_id() -> Id {
        Id::unique("editor::diagram::clipboard")
    }

    fn copy(&self, ctx: &egui::Context) {
        let copied = if self.selection.elements.is_empty() {
            match self.selection.network {
                Some(index) => copy_networks(&self.networks, index..index + 1),
                None => Err(NetworkEditError::NothingSelected),
            }
        } else {
            copy_elements(&self.networks, &self.selection.elements)
        };
        if let Ok(clipboard) = copied {
            // Other applications get the operands as text; a diagram editor pastes the
            // structure kept in the context, shared by all editors of the studio.
            let mut words = Vec::new();
            for network in &clipboard.networks {
                network.for_each_element(&mut |element| words.push(element_word(&element)));
            }
            project_model::walk_chain(&clipboard.nodes, &mut |element| {
                words.push(element_word(&element))
            });
            project_model::walk_outputs(&clipboard.outputs, &mut |element| {
                words.push(element_word(&element))
            });
            copy_structure(ctx, Self::clipboard_id(), words, clipboard);
        }
    }

    /// Pastes the structure copied last, or, when the system clipboard holds other text (a
    /// name copied elsewhere), types that text into the selected element.
    fn paste(&mut self, ctx: &egui::Context, text: &str, frame: &mut FrameResult) {
        if self.read_only {
            return;
        }
        let copied = copied_structure::<NetworkClipboard>(ctx, Self::clipboard_id(), text);
        let Some(copied) = copied else {
            if !text.is_empty() {
                self.open_selected_entry(Some(text.trim()));
            }
            return;
        };
        let clipboard = &copied.structure;
        let anchor = self
            .selection
            .anchor()
            .unwrap_or(Anchor::Network(self.networks.len().saturating_sub(1)));
        let result = if self.networks.is_empty() && !clipboard.networks.is_empty() {
            let mut splice = paste(
                &[project_model::Network::default()],
                Anchor::Network(0),
                clipboard,
            );
            if let Ok(splice) = &mut splice {
                splice.at = 0;
            }
            splice
        } else {
            paste(&self.networks, anchor, clipboard)
        };
        match result {
            Ok(splice) => self.apply_splice(splice, frame),
            Err(error) => frame.refusal = Some(DiagramRefusal::Edit(error)),
        }
    }

    /// Where a box goes for the selection: after the selected element (before a selected
    /// output), or at the end of the selected or last network.
    pub(super) fn box_target(&self) -> InsertTarget {
        match self.selection.anchor() {
            Some(Anchor::Element(id)) => {
                let is_output = self
                    .networks
                    .iter()
                    .any(|network| matches!(network.element(id), Some(ElementRef::Output(_))));
                InsertTarget::Series {
                    anchor: Anchor::Element(id),
                    side: if is_output { Side::Before } else { Side::After },
                }
            }
            Some(anchor) => InsertTarget::Series {
                anchor,
                side: Side::After,
            },
            None => InsertTarget::Series {
                anchor: Anchor::Network(self.networks.len().saturating_sub(1)),
                side: Side::After,
            },
        }
    }

    /// Runs a command on the selection.
    pub(super) fn command(&mut self, command: DiagramCommand, frame: &mut FrameResult) {
        if self.read_only {
            return;
        }
        if command == DiagramCommand::InsertBox {
            let target = self.box_target();
            self.open_entry(EntryTarget::NewBox(target), None);
            return;
        }
        if matches!(
            command,
            DiagramCommand::Negate | DiagramCommand::CycleModifier
        ) && let (Some(pin), [element]) = (
            self.selected_pin.clone(),
            self.selection.elements.as_slice(),
        ) {
            // On a selected pin, negation and the modifier act on the pin, not the box.
            let result = if command == DiagramCommand::Negate {
                project_model::toggle_negation(&self.networks, *element, Some(&pin))
            } else {
                project_model::cycle_pin_edge(&self.networks, *element, &pin)
            };
            match result {
                Ok(splice) => {
                    self.apply_splice(splice, frame);
                    self.selected_pin = Some(pin);
                }
                Err(error) => frame.refusal = Some(DiagramRefusal::Edit(error)),
            }
            return;
        }
        match run_command(&self.networks, &self.selection, command) {
            Ok(splice) => self.apply_splice(splice, frame),
            Err(error) => frame.refusal = Some(DiagramRefusal::Edit(error)),
        }
    }

    /// Inserts a toolbox element at an insertion point.
    pub(super) fn drop_item(
        &mut self,
        item: ToolboxItem,
        target: InsertTarget,
        frame: &mut FrameResult,
    ) {
        if self.read_only {
            return;
        }
        if item == ToolboxItem::Box {
            self.open_entry(EntryTarget::NewBox(target), None);
            return;
        }
        match item.insert_at(&self.networks, target) {
            Ok(splice) => self.apply_splice(splice, frame),
            Err(error) => frame.refusal = Some(DiagramRefusal::Edit(error)),
        }
    }

    /// Opens a text field over `target`, holding `typed` or else the current text.
    pub(super) fn open_entry(&mut self, target: EntryTarget, typed: Option<&str>) {
        if self.read_only && !matches!(target, EntryTarget::Prepared { .. }) {
            return;
        }
        let text = match typed {
            Some(typed) => typed.to_owned(),
            None => self.current_text(&target),
        };
        self.entry = Some(Entry::new(target, text));
    }
}

/// The word an element contributes to the clipboard's text.
fn element_word(element: &ElementRef<'_>) -> String {
    match element {
        ElementRef::Operand(operand) => operand.text.clone(),
        ElementRef::Block(block) => block.type_name.clone(),
        ElementRef::Output(project_model::NetworkOutput::Coil(coil)) => coil.variable.clone(),
        _ => String::new(),
    }
}
