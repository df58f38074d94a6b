//! The editor's commands and their keys, and how each becomes a structural edit of the body.
//!
//! The keys are CODESYS's, as its FBD/LD/IL editor documents them
//! (<https://content.helpme-codesys.com/en/CODESYS%20LD%20FBD/>):
//! Insert Contact Ctrl+K (`_cds_cmd_ld_insert_contact.html`: "inserts a contact to the left of
//! the selected element"), Insert Contact Parallel (above) Ctrl+P
//! (`_cds_cmd_ld_insert_contact_parallel_above.html`), Insert Contact Parallel (below) Ctrl+R
//! (`_cds_cmd_ld_insert_contact_parallel_below.html`), Insert Coil Ctrl+A
//! (`_cds_cmd_ld_insert_coil.html`, also Insert Assignment in FBD), Insert Box Ctrl+B (the
//! Safety FBD editor's `sil3_fbd_insertfb.html`, the same command), Insert Jump Ctrl+L
//! (`_cds_cmd_fbd_ld_il_insert_jump.html`), Negation Ctrl+N (`_cds_cmd_fbd_ld_il_negation.html`)
//! and Insert Network Ctrl+I (`_cds_cmd_fbd_ld_il_insert_network.html`, inserted above the
//! selected network as the Safety FBD editor's help says).
//! CODESYS documents no key for Insert Network (below), Insert Return, the edge and set/reset
//! commands or EN/ENO on a box, so they take Ctrl+T, Ctrl+Shift+R, Ctrl+E and Ctrl+Shift+B
//! here.
//! OpenPLC v4's single letters (C, Q, F, B, Shift+E) are not bound: typing on a selected element
//! enters its operand, as in CODESYS, and a letter cannot do both.

use egui::{Key, Modifiers};
use project_model::{
    Anchor, BodySplice, CoilKind, Network, NetworkEditError, ParallelSide, Side, cycle_modifier,
    delete_elements, delete_networks, insert_network, insert_output, insert_parallel,
    insert_series, new_coil, new_contact, new_jump, new_return, toggle_en_eno, toggle_negation,
};

/// A command of the diagram editor, from a key, the toolbox or the app's menus.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DiagramCommand {
    /// A contact in series, left of the selection (Ctrl+K).
    InsertContact {
        /// A normally closed contact.
        negated: bool,
    },
    /// A contact in series, right of the selection.
    InsertContactAfter,
    /// A contact in a branch parallel to the selection (Ctrl+P above, Ctrl+R below).
    InsertParallelContact {
        /// Above or below the selection.
        side: ParallelSide,
    },
    /// A coil among the outputs (Ctrl+A).
    InsertCoil {
        /// Normal, set, reset …
        kind: CoilKind,
    },
    /// A box: asks for its type first (Ctrl+B).
    InsertBox,
    /// A jump among the outputs (Ctrl+L).
    InsertJump,
    /// A return among the outputs (Ctrl+Shift+R).
    InsertReturn,
    /// An empty network above (Ctrl+I) or below (Ctrl+T) the selected one.
    InsertNetwork {
        /// Above or below.
        side: Side,
    },
    /// Negates the selected contact, coil or box pin (Ctrl+N).
    Negate,
    /// Cycles the selected contact's or coil's modifier, or the selected box input's edge
    /// detection (Ctrl+E).
    CycleModifier,
    /// Gives the selected box EN and ENO pins or takes them away (Ctrl+Shift+B).
    ToggleEnEno,
    /// Deletes the selected elements, or the selected network (Delete).
    Delete,
}

/// The command bound to `key` with `modifiers`, if any.
pub(super) fn command_for_key(key: Key, modifiers: Modifiers) -> Option<DiagramCommand> {
    if key == Key::Delete && !modifiers.command {
        return Some(DiagramCommand::Delete);
    }
    if !modifiers.command || modifiers.alt {
        return None;
    }
    let command = match (key, modifiers.shift) {
        (Key::K, false) => DiagramCommand::InsertContact { negated: false },
        (Key::P, false) => DiagramCommand::InsertParallelContact {
            side: ParallelSide::Above,
        },
        (Key::R, false) => DiagramCommand::InsertParallelContact {
            side: ParallelSide::Below,
        },
        (Key::A, false) => DiagramCommand::InsertCoil {
            kind: CoilKind::Normal,
        },
        (Key::B, false) => DiagramCommand::InsertBox,
        (Key::B, true) => DiagramCommand::ToggleEnEno,
        (Key::L, false) => DiagramCommand::InsertJump,
        (Key::R, true) => DiagramCommand::InsertReturn,
        (Key::I, false) => DiagramCommand::InsertNetwork { side: Side::Before },
        (Key::T, false) => DiagramCommand::InsertNetwork { side: Side::After },
        (Key::N, false) => DiagramCommand::Negate,
        (Key::E, false) => DiagramCommand::CycleModifier,
        _ => return None,
    };
    Some(command)
}

/// What the command works on: the selected elements, or else the selected network.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct DiagramSelection {
    /// The selected elements, in the order they were selected.
    pub elements: Vec<project_model::ElementId>,
    /// The selected network (the one the elements are in, or a network selected as a whole).
    pub network: Option<usize>,
}

impl DiagramSelection {
    /// Where an insertion goes: the first selected element, or the network.
    pub fn anchor(&self) -> Option<Anchor> {
        self.elements
            .first()
            .map(|id| Anchor::Element(*id))
            .or(self.network.map(Anchor::Network))
    }
}

/// Runs `command` (any but [`DiagramCommand::InsertBox`], which asks for a type first) on
/// `body`. An insertion into an empty body first makes a network to insert into, in the same
/// change.
pub(super) fn run_command(
    body: &[Network],
    selection: &DiagramSelection,
    command: DiagramCommand,
) -> Result<BodySplice, NetworkEditError> {
    let inserts = !matches!(
        command,
        DiagramCommand::Negate
            | DiagramCommand::CycleModifier
            | DiagramCommand::ToggleEnEno
            | DiagramCommand::Delete
    );
    if body.is_empty() && inserts && !matches!(command, DiagramCommand::InsertNetwork { .. }) {
        let fresh = vec![Network::default()];
        let selection = DiagramSelection {
            elements: Vec::new(),
            network: Some(0),
        };
        let mut splice = run_command(&fresh, &selection, command)?;
        splice.remove = 0;
        return Ok(splice);
    }
    let anchor = selection.anchor().ok_or(NetworkEditError::NothingSelected);
    let first = selection
        .elements
        .first()
        .copied()
        .ok_or(NetworkEditError::NothingSelected);
    match command {
        DiagramCommand::InsertContact { negated } => {
            let mut contact = new_contact("");
            if let project_model::FlowNode::Operand(operand) = &mut contact {
                operand.negated = negated;
            }
            insert_series(body, anchor?, Side::Before, contact)
        }
        DiagramCommand::InsertContactAfter => {
            insert_series(body, anchor?, Side::After, new_contact(""))
        }
        DiagramCommand::InsertParallelContact { side } => {
            insert_parallel(body, &selection.elements, side, new_contact(""))
        }
        DiagramCommand::InsertCoil { kind } => insert_output(body, anchor?, new_coil("", kind)),
        DiagramCommand::InsertJump => insert_output(body, anchor?, new_jump("")),
        DiagramCommand::InsertReturn => insert_output(body, anchor?, new_return()),
        DiagramCommand::InsertNetwork { side } => {
            let index = selection.network.unwrap_or(body.len().saturating_sub(1));
            insert_network(body, index, side, Network::default())
        }
        DiagramCommand::Negate => toggle_negation(body, first?, None),
        DiagramCommand::CycleModifier => cycle_modifier(body, first?),
        DiagramCommand::ToggleEnEno => toggle_en_eno(body, first?),
        DiagramCommand::Delete => {
            if selection.elements.is_empty() {
                let index = selection.network.ok_or(NetworkEditError::NothingSelected)?;
                delete_networks(body, index..index + 1)
            } else {
                delete_elements(body, &selection.elements)
            }
        }
        DiagramCommand::InsertBox => Err(NetworkEditError::NothingSelected),
    }
}
