//! The text field over an element, a network header or a new box, with completion of variable
//! and block names, and the input assistant (F2) that lists them.

use egui::text::{CCursor, CCursorRange};
use egui::{Id, Key, Rect, TextEdit};
use project_model::{
    ElementRef, FlowNode, HeaderField, NetworkOutput, new_box, set_element_text,
    set_network_header, set_pin_operand,
};

use super::editor::{DiagramEditor, FrameResult};
use super::placed::InsertTarget;
use super::toolbox::insert_node;
use super::types::{DiagramRefusal, DiagramServices, InstanceDeclaration, PreparedOperand};
use crate::CompletionItem;

/// How many completion candidates the list under the field shows.
const MAX_CANDIDATES: usize = 8;

/// What a text field edits.
#[derive(Clone, Debug, PartialEq)]
pub(super) enum EntryTarget {
    /// An element's text: a contact's operand, a coil's variable, a jump's label, a box's
    /// instance.
    Element(project_model::ElementId),
    /// The operand driving an input pin of a box.
    Pin(project_model::ElementId, String),
    /// The type of a box to insert at an insertion point.
    NewBox(InsertTarget),
    /// A network's title, comment or label.
    Header(usize, HeaderField),
    /// A value to prepare for an operand while online.
    Prepared {
        /// The element.
        element: project_model::ElementId,
        /// Its operand.
        operand: String,
    },
}

/// An open text field; lives until it is committed or cancelled.
#[derive(Clone, Debug)]
pub(super) struct Entry {
    /// What it edits.
    pub target: EntryTarget,
    /// The text typed so far.
    pub text: String,
    /// Whether the field has been given focus (done once, in its first frame).
    pub focused: bool,
    /// The completion the arrow keys moved to, counted from the best one; reset when the text
    /// changes.
    pub highlighted: usize,
    /// The text `highlighted` was chosen for.
    highlighted_for: String,
}

impl Entry {
    pub fn new(target: EntryTarget, text: String) -> Self {
        Self {
            target,
            highlighted_for: text.clone(),
            text,
            focused: false,
            highlighted: 0,
        }
    }

    /// The candidate Enter or Tab takes: none for an empty field or without candidates, the one
    /// spelled as typed (any case) while nothing was chosen with the arrows, else the one the
    /// arrows moved to.
    fn highlighted_candidate(&self, candidates: &[CompletionItem]) -> Option<usize> {
        if self.text.trim().is_empty() || candidates.is_empty() {
            return None;
        }
        let typed = last_segment(self.text.trim());
        let exact = candidates
            .iter()
            .position(|candidate| candidate.label.eq_ignore_ascii_case(typed));
        let shown = candidates.len().min(MAX_CANDIDATES);
        Some((exact.unwrap_or(0) + self.highlighted) % shown)
    }
}

/// What follows the last dot of `text` (all of it without a dot): the part a member's
/// completion replaces.
fn last_segment(text: &str) -> &str {
    text.rsplit_once('.').map_or(text, |(_, member)| member)
}

/// The field's text once `label` is accepted for what was typed: a member (`Q` after `tonA.`)
/// replaces only what follows the last dot, anything else the whole text.
pub(crate) fn accepted_text(typed: &str, label: &str) -> String {
    match typed.trim().rsplit_once('.') {
        Some((path, _)) if !label.contains('.') => format!("{path}.{label}"),
        _ => label.to_owned(),
    }
}

/// The detail of a completion row without the candidate's own name, which the row already
/// shows (`tWarn : TIME` gives `TIME`, `FUNCTION LIMIT` gives `FUNCTION`).
pub(crate) fn detail_without_label(label: &str, detail: &str) -> String {
    let words: Vec<&str> = detail
        .split_whitespace()
        .filter(|word| !word.eq_ignore_ascii_case(label))
        .collect();
    let words = match words.as_slice() {
        [":", rest @ ..] => rest,
        all => all,
    };
    words.join(" ")
}

impl DiagramEditor {
    /// The text `target` holds now.
    pub(super) fn current_text(&self, target: &EntryTarget) -> String {
        match target {
            EntryTarget::Element(id) => self
                .networks
                .iter()
                .find_map(|network| network.element(*id))
                .map(|element| match element {
                    ElementRef::Operand(operand) => operand.text.clone(),
                    ElementRef::Block(block) => block.instance.clone(),
                    ElementRef::Output(NetworkOutput::Coil(coil)) => coil.variable.clone(),
                    ElementRef::Output(NetworkOutput::Jump { label, .. }) => label.clone(),
                    _ => String::new(),
                })
                .unwrap_or_default(),
            EntryTarget::Pin(id, pin) => self
                .networks
                .iter()
                .find_map(|network| network.element(*id))
                .and_then(|element| match element {
                    ElementRef::Block(block) => block
                        .inputs
                        .iter()
                        .find(|input| input.pin == *pin)
                        .and_then(|input| match input.source.as_slice() {
                            [FlowNode::Operand(operand)] => Some(operand.text.clone()),
                            _ => None,
                        }),
                    _ => None,
                })
                .unwrap_or_default(),
            EntryTarget::Header(index, field) => self
                .networks
                .get(*index)
                .map(|network| match field {
                    HeaderField::Title => network.title.clone(),
                    HeaderField::Comment => network.comment.clone(),
                    HeaderField::Label => network.label.clone(),
                })
                .unwrap_or_default(),
            EntryTarget::NewBox(_) | EntryTarget::Prepared { .. } => String::new(),
        }
    }

    /// Whether the field completes block names rather than variables.
    fn completes_blocks(&self, target: &EntryTarget) -> bool {
        matches!(target, EntryTarget::NewBox(_))
    }

    /// Shows the open text field over `anchor` (screen points) with its completions.
    pub(super) fn entry_ui(
        &mut self,
        ctx: &egui::Context,
        id: Id,
        anchor: Rect,
        services: &dyn DiagramServices,
        frame: &mut FrameResult,
    ) {
        let Some(mut entry) = self.entry.take() else {
            return;
        };
        let field_id = id.with("entry");
        let label = match &entry.target {
            EntryTarget::Element(_) | EntryTarget::Pin(..) => self.texts.operand_field.clone(),
            EntryTarget::NewBox(_) => self.texts.block_type_field.clone(),
            EntryTarget::Header(_, HeaderField::Title) => self.texts.title_field.clone(),
            EntryTarget::Header(_, HeaderField::Comment) => self.texts.comment_field.clone(),
            EntryTarget::Header(_, HeaderField::Label) => self.texts.label_field.clone(),
            EntryTarget::Prepared { .. } => self.texts.prepared_value.clone(),
        };
        let candidates: Vec<CompletionItem> = match &entry.target {
            EntryTarget::Header(..) | EntryTarget::Prepared { .. } => Vec::new(),
            target if self.completes_blocks(target) => services.blocks(&entry.text),
            _ => services.variables(&entry.text),
        };
        if entry.text != entry.highlighted_for {
            entry.highlighted_for = entry.text.clone();
            entry.highlighted = 0;
        }
        let shown = candidates.len().min(MAX_CANDIDATES);
        // The arrows move through the candidates, as in the ST editor; they are taken before
        // the field sees them, which would move its cursor instead.
        if shown > 0 && entry.focused {
            let (down, up) = ctx.input_mut(|input| {
                (
                    input.consume_key(egui::Modifiers::NONE, Key::ArrowDown),
                    input.consume_key(egui::Modifiers::NONE, Key::ArrowUp),
                )
            });
            if down {
                entry.highlighted = (entry.highlighted + 1) % shown;
            }
            if up {
                entry.highlighted = (entry.highlighted + shown - 1) % shown;
            }
        }
        let highlighted = entry.highlighted_candidate(&candidates);
        let mut commit = None;
        let mut cancel = false;
        let mut left = false;
        let area = egui::Area::new(field_id.with("area"))
            .order(egui::Order::Foreground)
            .fixed_pos(anchor.left_top())
            .show(ctx, |ui| {
                egui::Frame::popup(ui.style()).show(ui, |ui| {
                    let width = anchor.width().max(140.0);
                    let response = ui.add(
                        TextEdit::singleline(&mut entry.text)
                            .id(field_id)
                            .desired_width(width)
                            .hint_text(label.clone()),
                    );
                    response
                        .widget_info(|| egui::WidgetInfo::text_edit(true, "", &entry.text, &label));
                    if !entry.focused {
                        entry.focused = true;
                        response.request_focus();
                        let mut state = TextEdit::load_state(ctx, field_id).unwrap_or_default();
                        let end = CCursor::new(entry.text.chars().count());
                        state.cursor.set_char_range(Some(CCursorRange::one(end)));
                        state.store(ctx, field_id);
                    }
                    if ui.input(|input| input.key_pressed(Key::Escape)) {
                        cancel = true;
                    } else if response.lost_focus() {
                        // Enter and Tab take the highlighted completion, as CODESYS and the ST
                        // editor do; what was typed stays when nothing is highlighted.
                        if ui.input(|input| {
                            input.key_pressed(Key::Enter) || input.key_pressed(Key::Tab)
                        }) {
                            commit = Some(match highlighted {
                                Some(index) => accepted_text(&entry.text, &candidates[index].label),
                                None => entry.text.clone(),
                            });
                        } else {
                            left = true;
                        }
                    }
                    for (index, candidate) in candidates.iter().take(MAX_CANDIDATES).enumerate() {
                        let detail = detail_without_label(&candidate.label, &candidate.detail);
                        let text = if detail.is_empty() {
                            candidate.label.clone()
                        } else {
                            format!("{}  {detail}", candidate.label)
                        };
                        if ui
                            .selectable_label(highlighted == Some(index), text)
                            .clicked()
                        {
                            commit = Some(accepted_text(&entry.text, &candidate.label));
                        }
                    }
                });
            });
        if cancel {
            self.request_focus();
            return;
        }
        // A click elsewhere keeps what was typed, as CODESYS does; a click on a candidate in
        // the popup takes the candidate instead.
        let by_leaving = left && commit.is_none() && !area.response.contains_pointer();
        if by_leaving {
            commit = Some(entry.text.clone());
        }
        match commit {
            Some(text) => {
                // Enter or a candidate gives the keyboard back to the canvas; a click elsewhere
                // leaves it where the user clicked.
                if !by_leaving {
                    self.request_focus();
                }
                self.commit_entry(entry.target, text.trim(), services, frame);
            }
            None => self.entry = Some(entry),
        }
    }

    /// Applies what was typed in a text field.
    fn commit_entry(
        &mut self,
        target: EntryTarget,
        text: &str,
        services: &dyn DiagramServices,
        frame: &mut FrameResult,
    ) {
        let result = match &target {
            EntryTarget::Element(id) => {
                let result = set_element_text(&self.networks, *id, text);
                if result.is_ok() {
                    self.declare_if_instance(*id, text, services, frame);
                }
                result
            }
            EntryTarget::Pin(id, pin) => set_pin_operand(&self.networks, *id, pin, text),
            EntryTarget::Header(index, field) => {
                set_network_header(&self.networks, *index, *field, text)
            }
            EntryTarget::Prepared { element, operand } => {
                frame.prepared = Some(PreparedOperand {
                    element: *element,
                    operand: operand.clone(),
                    value: text.to_owned(),
                });
                return;
            }
            EntryTarget::NewBox(insert) => {
                let insert = *insert;
                self.insert_box(text, insert, services, frame);
                return;
            }
        };
        match result {
            Ok(splice) => self.apply_splice(splice, frame),
            Err(error) => frame.refusal = Some(DiagramRefusal::Edit(error)),
        }
    }

    /// Inserts a box of block `type_name` at `insert` with the pins its signature gives; a
    /// function block's box then asks for its instance's name at once.
    pub(super) fn insert_box(
        &mut self,
        type_name: &str,
        insert: InsertTarget,
        services: &dyn DiagramServices,
        frame: &mut FrameResult,
    ) {
        let Some(signature) = services.signature(type_name) else {
            frame.refusal = Some(DiagramRefusal::UnknownBlock(type_name.to_owned()));
            return;
        };
        let inputs: Vec<&str> = signature.inputs.iter().map(String::as_str).collect();
        let outputs: Vec<&str> = signature.outputs.iter().map(String::as_str).collect();
        let block = new_box(type_name, "", &inputs, &outputs);
        match insert_node(&self.networks, insert, block) {
            Ok(splice) => {
                let focus = splice.focus;
                self.apply_splice(splice, frame);
                if signature.function_block
                    && let Some(focus) = focus
                {
                    self.open_entry(EntryTarget::Element(focus), None);
                }
            }
            Err(error) => frame.refusal = Some(DiagramRefusal::Edit(error)),
        }
    }

    /// Asks the app to declare `name` when element `id` is a function block's box and no
    /// variable of that name exists, as CODESYS offers when an instance is named.
    fn declare_if_instance(
        &self,
        id: project_model::ElementId,
        name: &str,
        services: &dyn DiagramServices,
        frame: &mut FrameResult,
    ) {
        let Some(ElementRef::Block(block)) =
            self.networks.iter().find_map(|network| network.element(id))
        else {
            return;
        };
        let is_function_block = services
            .signature(&block.type_name)
            .is_some_and(|signature| signature.function_block);
        if is_function_block && !name.is_empty() && !services.is_declared(name) {
            frame.declare_instance = Some(InstanceDeclaration {
                name: name.to_owned(),
                type_name: block.type_name.clone(),
            });
        }
    }

    /// The input assistant (F2): every variable and block; a click puts the name in the open
    /// field.
    pub(super) fn assistant_ui(
        &mut self,
        ctx: &egui::Context,
        id: Id,
        services: &dyn DiagramServices,
        frame: &mut FrameResult,
    ) {
        if !self.assistant_open {
            return;
        }
        let mut open = true;
        let mut chosen = None;
        egui::Window::new(self.texts.input_assistant.clone())
            .id(id.with("assistant"))
            .open(&mut open)
            .collapsible(false)
            .default_width(260.0)
            .show(ctx, |ui| {
                egui::ScrollArea::vertical()
                    .max_height(320.0)
                    .show(ui, |ui| {
                        for (heading, items) in [
                            (&self.texts.variables, services.variables("")),
                            (&self.texts.blocks, services.blocks("")),
                        ] {
                            ui.strong(heading);
                            for item in items {
                                let detail = detail_without_label(&item.label, &item.detail);
                                let text = format!("{}  {detail}", item.label);
                                if ui.selectable_label(false, text).clicked() {
                                    chosen = Some(item.label.clone());
                                }
                            }
                        }
                    });
            });
        if let Some(name) = chosen {
            open = false;
            match self.entry.take() {
                Some(entry) => self.commit_entry(entry.target, &name, services, frame),
                None => {
                    if let [element] = self.selection.elements.as_slice() {
                        let element = *element;
                        self.commit_entry(EntryTarget::Element(element), &name, services, frame);
                    }
                }
            }
        }
        self.assistant_open = open;
    }
}
