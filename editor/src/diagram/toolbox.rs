//! The toolbox: the elements the user drags onto the "+" insertion points of the canvas.

use egui::{Id, Ui};
use project_model::{
    Anchor, BodySplice, CoilKind, FlowNode, Network, NetworkEditError, NetworkOutput, ParallelSide,
    Side, insert_network, insert_output, insert_parallel, insert_series, new_coil, new_contact,
    new_jump, new_return,
};

use super::editor::DiagramEditor;
use super::placed::InsertTarget;

/// An element of the toolbox; the payload of a drag from it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ToolboxItem {
    /// A normally open contact.
    Contact,
    /// A normally closed contact.
    NegatedContact,
    /// A contact in a branch parallel to the drop point's element.
    ParallelContact,
    /// A coil.
    Coil,
    /// A set coil.
    SetCoil,
    /// A reset coil.
    ResetCoil,
    /// A box (its type is asked for after the drop).
    Box,
    /// A jump.
    Jump,
    /// A return.
    Return,
    /// An empty network below the drop point's network.
    Network,
}

impl ToolboxItem {
    /// Every item, in the toolbox's order.
    pub const ALL: [Self; 10] = [
        Self::Contact,
        Self::NegatedContact,
        Self::ParallelContact,
        Self::Coil,
        Self::SetCoil,
        Self::ResetCoil,
        Self::Box,
        Self::Jump,
        Self::Return,
        Self::Network,
    ];

    /// Inserts the item (any but [`ToolboxItem::Box`], whose type is asked first) at `target`.
    pub(super) fn insert_at(
        self,
        body: &[Network],
        target: InsertTarget,
    ) -> Result<BodySplice, NetworkEditError> {
        let contact = |negated: bool| {
            let mut node = new_contact("");
            if let FlowNode::Operand(operand) = &mut node {
                operand.negated = negated;
            }
            node
        };
        match self {
            Self::Contact => insert_node(body, target, contact(false)),
            Self::NegatedContact => insert_node(body, target, contact(true)),
            Self::ParallelContact => match target {
                InsertTarget::Series {
                    anchor: Anchor::Element(id),
                    ..
                } => insert_parallel(body, &[id], DROPPED_PARALLEL_SIDE, contact(false)),
                _ => insert_node(body, target, contact(false)),
            },
            Self::Coil => insert_output_at(body, target, new_coil("", CoilKind::Normal)),
            Self::SetCoil => insert_output_at(body, target, new_coil("", CoilKind::Set)),
            Self::ResetCoil => insert_output_at(body, target, new_coil("", CoilKind::Reset)),
            Self::Jump => insert_output_at(body, target, new_jump("")),
            Self::Return => insert_output_at(body, target, new_return()),
            Self::Network | Self::Box => {
                let anchor = match target {
                    InsertTarget::Series { anchor, .. } | InsertTarget::Output { anchor } => anchor,
                    InsertTarget::Parallel { id, .. } => Anchor::Element(id),
                };
                let index = match anchor {
                    Anchor::Network(index) => index,
                    Anchor::Element(id) => body
                        .iter()
                        .position(|network| network.element(id).is_some())
                        .ok_or(NetworkEditError::NoSuchElement { id })?,
                };
                insert_network(body, index, Side::After, Network::default())
            }
        }
    }
}

impl DiagramEditor {
    /// The toolbox column: each item is a drag source.
    pub(super) fn toolbox_ui(&mut self, ui: &mut Ui, id: Id) {
        ui.strong(&self.texts.toolbox);
        ui.separator();
        for item in ToolboxItem::ALL {
            let name = match item {
                ToolboxItem::Contact => &self.texts.contact,
                ToolboxItem::NegatedContact => &self.texts.negated_contact,
                ToolboxItem::ParallelContact => &self.texts.parallel_contact,
                ToolboxItem::Coil => &self.texts.coil,
                ToolboxItem::SetCoil => &self.texts.set_coil,
                ToolboxItem::ResetCoil => &self.texts.reset_coil,
                ToolboxItem::Box => &self.texts.block,
                ToolboxItem::Jump => &self.texts.jump,
                ToolboxItem::Return => &self.texts.return_,
                ToolboxItem::Network => &self.texts.new_network,
            };
            let enabled = !self.read_only;
            ui.add_enabled_ui(enabled, |ui| {
                ui.dnd_drag_source(id.with(("toolbox", item as u8)), item, |ui| {
                    ui.add(egui::Button::new(name.as_str()).sense(egui::Sense::hover()))
                });
            });
        }
    }
}

/// Inserts a contact or box at an insertion point.
pub(super) fn insert_node(
    body: &[Network],
    target: InsertTarget,
    node: FlowNode,
) -> Result<BodySplice, NetworkEditError> {
    match target {
        InsertTarget::Series { anchor, side } => insert_series(body, anchor, side, node),
        InsertTarget::Parallel { id, side } => insert_parallel(body, &[id], side, node),
        InsertTarget::Output { anchor } => match anchor {
            Anchor::Element(_) => insert_series(body, anchor, Side::Before, node),
            Anchor::Network(_) => insert_series(body, anchor, Side::After, node),
        },
    }
}

/// Inserts an output at an insertion point.
fn insert_output_at(
    body: &[Network],
    target: InsertTarget,
    output: NetworkOutput,
) -> Result<BodySplice, NetworkEditError> {
    let anchor = match target {
        InsertTarget::Series { anchor, .. } | InsertTarget::Output { anchor } => anchor,
        InsertTarget::Parallel { id, .. } => Anchor::Element(id),
    };
    insert_output(body, anchor, output)
}

/// The side a parallel contact dropped on a series point goes.
const DROPPED_PARALLEL_SIDE: ParallelSide = ParallelSide::Below;
