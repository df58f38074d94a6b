//! The text field over an element: an input's or output's expression with completion of
//! variables, a box's type with completion of blocks (re-creating its pins), an instance, a
//! name, a comment, an execution order number, or a value prepared while online.

use egui::{Id, Pos2, Rect};
use project_model::cfc_edit as edit;
use project_model::{CfcElementKind, ElementId};

use super::editor::{CfcEditor, FrameResult};
use super::geometry::{ROW_UNITS, element_title};
use super::types::CfcRefusal;
use crate::CompletionItem;
use crate::diagram::field::{CompletionField, FieldOutcome};
use crate::diagram::{DiagramServices, InstanceDeclaration, PreparedOperand};

/// What a text field edits.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(super) enum EntryTarget {
    /// The element's own text: an expression, a label, a name, a comment.
    Text(ElementId),
    /// A box's type.
    BoxType(ElementId),
    /// A box's function block instance.
    Instance(ElementId),
    /// A composer's or selector's structure type.
    StructType(ElementId),
    /// The element's place in the execution order.
    Order(ElementId),
    /// A value to prepare for an input's or output's variable while online.
    Prepared(ElementId),
}

impl EntryTarget {
    /// The element the field is over.
    fn element(&self) -> ElementId {
        match self {
            Self::Text(id)
            | Self::BoxType(id)
            | Self::Instance(id)
            | Self::StructType(id)
            | Self::Order(id)
            | Self::Prepared(id) => *id,
        }
    }
}

/// An open text field; lives until it is committed or cancelled.
#[derive(Clone, Debug)]
pub(super) struct CfcEntry {
    /// What it edits.
    pub target: EntryTarget,
    /// The field.
    pub field: CompletionField,
}

impl CfcEditor {
    /// Opens a text field for `target` holding `text`.
    pub(super) fn open_entry(&mut self, target: EntryTarget, text: String) {
        if self.read_only && !matches!(target, EntryTarget::Prepared(_)) {
            return;
        }
        self.entry = Some(CfcEntry {
            target,
            field: CompletionField::new(text),
        });
    }

    /// Opens the field a double click on `hit` asks for.
    pub(super) fn open_entry_at(&mut self, hit: super::canvas::Hit) {
        use super::canvas::Hit;
        let (id, instance_row) = match hit {
            Hit::Element(id) => (id, false),
            Hit::Instance(id) => (id, true),
            _ => return,
        };
        let Some(element) = self.chart.elements.iter().find(|e| e.id == id) else {
            return;
        };
        let shown = |text: &str| {
            if text == "???" {
                String::new()
            } else {
                text.to_owned()
            }
        };
        let (target, text) = match &element.kind {
            CfcElementKind::Input { .. } | CfcElementKind::Output { .. }
                if self.online.is_some() =>
            {
                (EntryTarget::Prepared(id), String::new())
            }
            CfcElementKind::Box(block) if instance_row => {
                (EntryTarget::Instance(id), block.instance.clone())
            }
            CfcElementKind::Box(block) => (EntryTarget::BoxType(id), block.type_name.clone()),
            CfcElementKind::Composer { type_name, .. }
            | CfcElementKind::Selector { type_name, .. } => {
                (EntryTarget::StructType(id), shown(type_name))
            }
            CfcElementKind::Return => return,
            kind => (EntryTarget::Text(id), shown(element_title(kind))),
        };
        self.open_entry(target, text);
    }

    /// Shows the open text field over its element.
    pub(super) fn entry_ui(
        &mut self,
        ctx: &egui::Context,
        id: Id,
        origin: Pos2,
        services: &dyn DiagramServices,
        frame: &mut FrameResult,
    ) {
        let Some(mut entry) = self.entry.take() else {
            return;
        };
        let Some(shape) = self.shapes.get(&entry.target.element()) else {
            return;
        };
        let mut anchor = self.screen_rect(origin, shape.rect);
        if entry.target == EntryTarget::Instance(entry.target.element()) {
            anchor = anchor.translate(egui::vec2(0.0, -(ROW_UNITS as f32) * self.unit_px()));
        }
        let anchor = Rect::from_min_size(anchor.min, egui::vec2(anchor.width(), 20.0));
        let element_kind = self
            .chart
            .elements
            .iter()
            .find(|e| e.id == entry.target.element())
            .map(|e| e.kind.clone());
        let (label, candidates): (String, Vec<CompletionItem>) =
            match (&entry.target, &element_kind) {
                (EntryTarget::BoxType(_), _) => (
                    self.texts.block_type_field.clone(),
                    services.blocks(&entry.field.text),
                ),
                (EntryTarget::Instance(_), _) => (
                    self.texts.instance_field.clone(),
                    services.variables(&entry.field.text),
                ),
                (
                    EntryTarget::Text(_),
                    Some(CfcElementKind::Input { .. } | CfcElementKind::Output { .. }),
                ) => (
                    self.texts.expression_field.clone(),
                    services.variables(&entry.field.text),
                ),
                // A jump completes the chart's labels.
                (EntryTarget::Text(_), Some(CfcElementKind::Jump { .. })) => {
                    let typed = entry.field.text.to_lowercase();
                    let labels = self
                        .chart
                        .elements
                        .iter()
                        .filter_map(|element| match &element.kind {
                            CfcElementKind::Label { name }
                                if name.to_lowercase().starts_with(&typed) =>
                            {
                                Some(CompletionItem {
                                    label: name.clone(),
                                    kind: crate::CompletionKind::Other,
                                    detail: String::new(),
                                })
                            }
                            _ => None,
                        })
                        .collect();
                    (self.texts.name_field.clone(), labels)
                }
                (EntryTarget::Text(_), Some(CfcElementKind::Comment { .. })) => {
                    (self.texts.comment_field.clone(), Vec::new())
                }
                (EntryTarget::Order(_), _) => (self.texts.order_field.clone(), Vec::new()),
                (EntryTarget::Prepared(_), _) => (self.texts.prepared_value.clone(), Vec::new()),
                _ => (self.texts.name_field.clone(), Vec::new()),
            };
        let field_id = id.with("entry");
        let text = match entry.field.ui(ctx, field_id, anchor, &label, &candidates) {
            FieldOutcome::Open => {
                self.entry = Some(entry);
                return;
            }
            FieldOutcome::Cancelled => {
                self.request_focus();
                return;
            }
            FieldOutcome::Committed(text) => {
                self.request_focus();
                text
            }
            FieldOutcome::Left(text) => text,
        };
        self.commit_entry(entry.target, text.trim(), services, frame);
    }

    /// Applies what was typed in a text field.
    pub(super) fn commit_entry(
        &mut self,
        target: EntryTarget,
        text: &str,
        services: &dyn DiagramServices,
        frame: &mut FrameResult,
    ) {
        match target {
            EntryTarget::Text(id) => {
                let result = edit::set_text(&self.chart, id, text);
                self.apply(result, frame);
            }
            EntryTarget::BoxType(id) => {
                if text.is_empty() {
                    return;
                }
                let Some(signature) = services.signature(text) else {
                    frame.refusal = Some(CfcRefusal::UnknownBlock(text.to_owned()));
                    return;
                };
                let result = edit::set_box_type(
                    &self.chart,
                    id,
                    text,
                    &signature.inputs,
                    &signature.outputs,
                );
                let needs_instance = signature.function_block && self.instance_of(id).is_empty();
                if self.apply(result, frame) && needs_instance {
                    self.open_entry(EntryTarget::Instance(id), String::new());
                }
            }
            EntryTarget::Instance(id) => {
                let result = edit::set_instance(&self.chart, id, text);
                if self.apply(result, frame) && !text.is_empty() && !services.is_declared(text) {
                    let type_name = self.type_of(id);
                    if services
                        .signature(&type_name)
                        .is_some_and(|signature| signature.function_block)
                    {
                        frame.declare_instance = Some(InstanceDeclaration {
                            name: text.to_owned(),
                            type_name,
                        });
                    }
                }
            }
            EntryTarget::StructType(id) => {
                let Some(members) = services.structure_members(text) else {
                    frame.refusal = Some(CfcRefusal::UnknownStructure(text.to_owned()));
                    return;
                };
                let result = edit::set_members(&self.chart, id, text, &members);
                self.apply(result, frame);
            }
            EntryTarget::Order(id) => match text.parse::<u32>() {
                Ok(order) => {
                    let result = edit::set_execution_order(&self.chart, id, order);
                    self.apply(result, frame);
                }
                Err(_) => {
                    frame.refusal = Some(CfcRefusal::NotANumber(text.to_owned()));
                }
            },
            EntryTarget::Prepared(id) => {
                let operand = self
                    .chart
                    .elements
                    .iter()
                    .find(|e| e.id == id)
                    .map(|e| element_title(&e.kind).to_owned())
                    .unwrap_or_default();
                if !text.is_empty() {
                    frame.prepared = Some(PreparedOperand {
                        element: id,
                        operand,
                        value: text.to_owned(),
                    });
                }
            }
        }
    }

    /// The instance of box `id` (empty if none).
    fn instance_of(&self, id: ElementId) -> String {
        self.chart
            .elements
            .iter()
            .find_map(|e| match &e.kind {
                CfcElementKind::Box(block) if e.id == id => Some(block.instance.clone()),
                _ => None,
            })
            .unwrap_or_default()
    }

    /// The type of box `id` (empty if none).
    fn type_of(&self, id: ElementId) -> String {
        self.chart
            .elements
            .iter()
            .find_map(|e| match &e.kind {
                CfcElementKind::Box(block) if e.id == id => Some(block.type_name.clone()),
                _ => None,
            })
            .unwrap_or_default()
    }
}
