//! The toolbox: the elements the user drags onto the "+" insertion points of the canvas, or
//! clicks to insert at the selection (as OpenPLC does on click and CODESYS on double click),
//! and the boxes of the blocks used most.

use egui::{Id, ScrollArea, Ui};
use project_model::{
    Anchor, BodySplice, CoilKind, FlowNode, Network, NetworkEditError, NetworkOutput, ParallelSide,
    Side, insert_network, insert_output, insert_parallel, insert_series, new_coil, new_contact,
    new_jump, new_return,
};

use super::commands::DiagramCommand;
use super::editor::{DiagramEditor, FrameResult};
use super::placed::InsertTarget;
use super::types::{DiagramServices, DiagramView};

/// A box of a block from the toolbox's list of the blocks used most; the payload of a drag
/// from it. Its pins come from [`DiagramServices::signature`] when it is inserted.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ToolboxBlock(pub &'static str);

impl ToolboxBlock {
    /// The blocks the toolbox lists: the timers, counters, edges, flip-flops, arithmetic,
    /// comparisons and selections of IEC 61131-3 a PLC program uses most.
    pub const COMMON: [Self; 15] = [
        Self("TON"),
        Self("TOF"),
        Self("CTU"),
        Self("R_TRIG"),
        Self("SR"),
        Self("RS"),
        Self("ADD"),
        Self("SUB"),
        Self("MUL"),
        Self("GT"),
        Self("LT"),
        Self("EQ"),
        Self("SEL"),
        Self("LIMIT"),
        Self("MOVE"),
    ];
}

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

    /// The items of the FBD view's toolbox, in CODESYS's order: an input is a contact's operand
    /// in the chain, an assignment a coil, as the two views map onto one network.
    pub const FUNCTION_BLOCK: [Self; 8] = [
        Self::Contact,
        Self::Box,
        Self::Coil,
        Self::SetCoil,
        Self::ResetCoil,
        Self::Jump,
        Self::Return,
        Self::Network,
    ];

    /// The items the toolbox of `view` offers.
    pub fn of_view(view: DiagramView) -> &'static [Self] {
        match view {
            DiagramView::Ladder => &Self::ALL,
            DiagramView::FunctionBlock => &Self::FUNCTION_BLOCK,
        }
    }

    /// The command that inserts the item at the selection, when it is clicked.
    fn command(self) -> DiagramCommand {
        match self {
            Self::Contact => DiagramCommand::InsertContact { negated: false },
            Self::NegatedContact => DiagramCommand::InsertContact { negated: true },
            Self::ParallelContact => DiagramCommand::InsertParallelContact {
                side: DROPPED_PARALLEL_SIDE,
            },
            Self::Coil => DiagramCommand::InsertCoil {
                kind: CoilKind::Normal,
            },
            Self::SetCoil => DiagramCommand::InsertCoil {
                kind: CoilKind::Set,
            },
            Self::ResetCoil => DiagramCommand::InsertCoil {
                kind: CoilKind::Reset,
            },
            Self::Box => DiagramCommand::InsertBox,
            Self::Jump => DiagramCommand::InsertJump,
            Self::Return => DiagramCommand::InsertReturn,
            Self::Network => DiagramCommand::InsertNetwork { side: Side::After },
        }
    }

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
    /// The toolbox column: each item is a drag source and a button that inserts at the
    /// selection; the blocks used most follow the elements.
    pub(super) fn toolbox_ui(
        &mut self,
        ui: &mut Ui,
        id: Id,
        services: &dyn DiagramServices,
        frame: &mut FrameResult,
    ) {
        ui.strong(&self.texts.toolbox);
        ui.separator();
        let enabled = !self.read_only;
        ScrollArea::vertical()
            .id_salt(id.with("toolbox_scroll"))
            .auto_shrink([false, false])
            .show(ui, |ui| {
                ui.add_enabled_ui(enabled, |ui| {
                    for item in ToolboxItem::of_view(self.view) {
                        let name = self.item_name(*item).to_owned();
                        let clicked =
                            drag_or_click_ui(ui, egui::Button::new(name.as_str()), *item).clicked();
                        if clicked {
                            self.command(item.command(), frame);
                        }
                    }
                    if self.view == DiagramView::FunctionBlock {
                        // A negation is put on what is selected, not dropped on a "+": a
                        // button only, as Ctrl+N.
                        let negation = self.texts.negation.clone();
                        if ui.button(negation).clicked() {
                            self.command(DiagramCommand::Negate, frame);
                        }
                    }
                    ui.add_space(4.0);
                    ui.label(&self.texts.blocks);
                    ui.horizontal_wrapped(|ui| {
                        ui.spacing_mut().item_spacing = egui::vec2(3.0, 3.0);
                        for block in ToolboxBlock::COMMON {
                            let clicked = block_tile_ui(ui, block).clicked();
                            if clicked {
                                let target = self.box_target();
                                self.insert_box(block.0, target, services, frame);
                            }
                        }
                    });
                });
            });
    }

    /// The toolbox's name of `item` in the current view, in the user's language.
    pub(super) fn item_name(&self, item: ToolboxItem) -> &str {
        if self.view == DiagramView::FunctionBlock {
            match item {
                ToolboxItem::Contact => return &self.texts.input,
                ToolboxItem::Coil => return &self.texts.assignment,
                ToolboxItem::SetCoil => return &self.texts.set_assignment,
                ToolboxItem::ResetCoil => return &self.texts.reset_assignment,
                _ => {}
            }
        }
        match item {
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
        }
    }
}

/// A toolbox button that inserts at the selection when clicked and carries `payload` to the
/// canvas when dragged. egui's `dnd_drag_source` puts a drag-only area over its contents, which
/// takes the clicks of the button under it, so the button senses both itself.
pub(crate) fn drag_or_click_ui<Payload>(
    ui: &mut Ui,
    button: egui::Button<'_>,
    payload: Payload,
) -> egui::Response
where
    Payload: std::any::Any + Send + Sync,
{
    let response = ui.add(button.sense(egui::Sense::click_and_drag()));
    if response.drag_started() {
        egui::DragAndDrop::set_payload(ui.ctx(), payload);
    }
    if response.dragged() {
        ui.ctx().set_cursor_icon(egui::CursorIcon::Grabbing);
    } else if response.hovered() {
        ui.ctx().set_cursor_icon(egui::CursorIcon::Grab);
    }
    response
}

/// A block's tile in the toolbox: its name on a button face, clicked to insert at the selection
/// and dragged to a "+". Painted directly rather than as an `egui::Button`, whose text layout
/// cost a visible share of every frame for fifteen tiles.
fn block_tile_ui(ui: &mut Ui, block: ToolboxBlock) -> egui::Response {
    let font = egui::TextStyle::Monospace.resolve(ui.style());
    let char_width = font.size * 0.62;
    let padding = egui::vec2(4.0, 2.0);
    let size = egui::vec2(
        block.0.len() as f32 * char_width + 2.0 * padding.x,
        font.size + 2.0 * padding.y,
    );
    let (rect, response) = ui.allocate_exact_size(size, egui::Sense::click_and_drag());
    let enabled = ui.is_enabled();
    response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Button, enabled, block.0));
    if ui.is_rect_visible(rect) {
        let visuals = ui.style().interact(&response);
        ui.painter()
            .rect_filled(rect, visuals.corner_radius, visuals.weak_bg_fill);
        ui.painter().text(
            rect.center(),
            egui::Align2::CENTER_CENTER,
            block.0,
            font,
            visuals.text_color(),
        );
    }
    if response.drag_started() {
        egui::DragAndDrop::set_payload(ui.ctx(), block);
    }
    if response.dragged() {
        ui.ctx().set_cursor_icon(egui::CursorIcon::Grabbing);
    }
    response
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
