//! The text field over an element, a network header or a new box, with completion of variable
//! and block names, and the input assistant (F2) that lists them.

use egui::{Id, Rect};
use project_model::{
    ElementRef, FlowNode, HeaderField, NetworkOutput, new_box, set_element_text,
    set_network_header, set_pin_operand,
};

use super::editor::{DiagramEditor, FrameResult};
use super::field::{CompletionField, FieldOutcome, detail_without_label};
use super::placed::InsertTarget;
use super::toolbox::insert_node;
use super::types::{DiagramRefusal, DiagramServices, InstanceDeclaration, PreparedOperand};
use crate::CompletionItem;

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
    /// The field: its text and its completion state.
    pub field: CompletionField,
}

impl Entry {
    pub fn new(target: EntryTarget, text: String) -> Self {
        Self {
            target,
            field: CompletionField::new(text),
        }
    }
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
            target if self.completes_blocks(target) => services.blocks(&entry.field.text),
            _ => services.variables(&entry.field.text),
        };
        let (commit, by_leaving) = match entry.field.ui(ctx, field_id, anchor, &label, &candidates)
        {
            FieldOutcome::Open => (None, false),
            FieldOutcome::Cancelled => {
                self.request_focus();
                return;
            }
            FieldOutcome::Committed(text) => (Some(text), false),
            FieldOutcome::Left(text) => (Some(text), true),
        };
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
