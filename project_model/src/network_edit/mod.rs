//! Structural edits of LD/FBD bodies: the operations an editor offers on a selection.
//!
//! Every operation is a pure function of the body (a POU's list of [`Network`]s) and a
//! selection; it returns a [`BodySplice`] (which networks to replace with which) or a
//! [`NetworkEditError`] when it does not apply there, so one gesture is one change the app can
//! turn into one undoable edit. New elements take ids from [`max_element_id`] + 1 upwards, so an
//! id is never reused within a body, and pasted elements get fresh ids the same way.

use std::collections::{BTreeMap, BTreeSet};

use thiserror::Error;

mod find;
mod pins;

pub use pins::{cycle_pin_edge, toggle_en_eno};

use find::{
    chain_feeding_output, chain_holding, edit_element, outputs_fed_by, outputs_holding,
    parallel_with_sole,
};

use crate::{
    BlockCall, BlockInput, BlockOutput, Branch, Coil, CoilKind, Edge, ElementId, FlowNode, Network,
    NetworkOutput, Operand, Parallel, max_element_id,
};

/// Where the user's selection is, for an operation that inserts something.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Anchor {
    /// An element, by its id.
    Element(ElementId),
    /// A network as a whole (its header or its empty rung), by its index in the body.
    Network(usize),
}

/// On which side of the selection a series element or a network goes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Side {
    /// Before it: to its left in a chain, above it in the body.
    Before,
    /// After it: to its right in a chain, below it in the body.
    After,
}

/// On which side of the selection a parallel branch goes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ParallelSide {
    /// A branch above the selection.
    Above,
    /// A branch below the selection.
    Below,
}

/// Which text of a network's header is set.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum HeaderField {
    /// The title, on the header's first line.
    Title,
    /// The comment, under the title.
    Comment,
    /// The jump label.
    Label,
}

/// The change one operation makes: `remove` networks from index `at` are replaced by `insert`.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct BodySplice {
    /// The index of the first replaced network.
    pub at: usize,
    /// How many networks are replaced.
    pub remove: usize,
    /// The networks put in their place.
    pub insert: Vec<Network>,
    /// The element to select after the change (a new or the changed element), if any.
    pub focus: Option<ElementId>,
    /// The network to select after the change when no element is focused.
    pub focus_network: Option<usize>,
}

impl BodySplice {
    /// Applies the splice to `body`; indices past the end are clamped, so a stale splice
    /// cannot panic.
    pub fn apply(&self, body: &mut Vec<Network>) {
        let at = self.at.min(body.len());
        let end = (at + self.remove).min(body.len());
        body.splice(at..end, self.insert.iter().cloned());
    }
}

/// Copied elements or networks, to paste elsewhere with fresh ids. Lives in the editor (or the
/// egui context) between copy and paste and is never saved.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct NetworkClipboard {
    /// Copied chain elements, in display order; pasted in series.
    pub nodes: Vec<FlowNode>,
    /// Copied outputs (coils, jumps, returns, output branches); pasted beside the outputs.
    pub outputs: Vec<NetworkOutput>,
    /// Copied whole networks; pasted below the selected network.
    pub networks: Vec<Network>,
}

impl NetworkClipboard {
    /// Whether nothing was copied.
    pub fn is_empty(&self) -> bool {
        self.nodes.is_empty() && self.outputs.is_empty() && self.networks.is_empty()
    }
}

/// Why an operation does not apply to the selection.
#[derive(Clone, Debug, Error, PartialEq, Eq)]
pub enum NetworkEditError {
    /// The body has no network at this index.
    #[error("there is no network {number} (the body has {count})", number = index + 1)]
    NoSuchNetwork {
        /// The index asked for.
        index: usize,
        /// The number of networks in the body.
        count: usize,
    },
    /// No element of the body has this id.
    #[error("no element has the id {}", id.0)]
    NoSuchElement {
        /// The id asked for.
        id: ElementId,
    },
    /// The operation does not apply to this element (a contact after a coil, negating a box).
    #[error("{operation} does not apply to element {}", id.0)]
    NotApplicable {
        /// The selected element.
        id: ElementId,
        /// The operation, in English, for logs and tests.
        operation: &'static str,
    },
    /// The selected elements are not consecutive elements of one chain.
    #[error("the selected elements are not next to each other in one chain")]
    NotOneChain,
    /// Nothing was selected or copied.
    #[error("nothing is selected")]
    NothingSelected,
}

/// A normally open contact (an FBD input) reading `text`; its id is given when it is inserted.
pub fn new_contact(text: &str) -> FlowNode {
    FlowNode::Operand(Operand {
        id: ElementId(0),
        text: text.to_owned(),
        ..Operand::default()
    })
}

/// A box calling `type_name` with these input and output pins; its first input is left
/// unconnected so the power drives it in a chain.
pub fn new_box(type_name: &str, instance: &str, inputs: &[&str], outputs: &[&str]) -> FlowNode {
    FlowNode::Block(BlockCall {
        id: ElementId(0),
        type_name: type_name.to_owned(),
        instance: instance.to_owned(),
        inputs: inputs
            .iter()
            .map(|pin| BlockInput {
                pin: (*pin).to_owned(),
                ..BlockInput::default()
            })
            .collect(),
        outputs: outputs
            .iter()
            .map(|pin| BlockOutput {
                pin: (*pin).to_owned(),
                ..BlockOutput::default()
            })
            .collect(),
    })
}

/// A coil of `kind` writing `variable`.
pub fn new_coil(variable: &str, kind: CoilKind) -> NetworkOutput {
    NetworkOutput::Coil(Coil {
        id: ElementId(0),
        variable: variable.to_owned(),
        kind,
    })
}

/// A jump to `label`.
pub fn new_jump(label: &str) -> NetworkOutput {
    NetworkOutput::Jump {
        id: ElementId(0),
        label: label.to_owned(),
    }
}

/// A return.
pub fn new_return() -> NetworkOutput {
    NetworkOutput::Return { id: ElementId(0) }
}

/// Inserts `node` (a contact or a box, ids renumbered) in series `side` of the anchor: beside a
/// chain element in its chain, or at the end of the chain that feeds a selected output or a
/// selected network's outputs.
pub fn insert_series(
    body: &[Network],
    anchor: Anchor,
    side: Side,
    mut node: FlowNode,
) -> Result<BodySplice, NetworkEditError> {
    let mut ids = IdSource::after(body);
    ids.renumber_node(&mut node);
    let focus = node.id();
    let (index, mut network) = anchored_network(body, anchor)?;
    match anchor {
        Anchor::Network(_) => network.rung.push(node),
        Anchor::Element(id) => {
            if let Some((chain, position)) = chain_holding(&mut network, id) {
                let at = if side == Side::Before {
                    position
                } else {
                    position + 1
                };
                chain.insert(at, node);
            } else if side == Side::Before
                && let Some(chain) = chain_feeding_output(&mut network, id)
            {
                chain.push(node);
            } else {
                return Err(not_applicable(id, "inserting in series"));
            }
        }
    }
    Ok(one_network(index, network, Some(focus)))
}

/// Inserts `node` (a contact or a box) in a branch parallel to the selected elements, which must
/// be consecutive in one chain: as a new branch of the group when the selection is a parallel
/// group or the only element of one of its branches, else in a new group around the selection.
pub fn insert_parallel(
    body: &[Network],
    selection: &[ElementId],
    side: ParallelSide,
    mut node: FlowNode,
) -> Result<BodySplice, NetworkEditError> {
    let first = *selection.first().ok_or(NetworkEditError::NothingSelected)?;
    let mut ids = IdSource::after(body);
    ids.renumber_node(&mut node);
    let focus = node.id();
    let index = network_index_of(body, first)?;
    let mut network = body[index].clone();
    let new_branch = Branch { rung: vec![node] };
    let single = selection.len() == 1;
    if single && let Some((parallel, branch)) = parallel_with_sole(&mut network, first) {
        let at = if side == ParallelSide::Above {
            branch
        } else {
            branch + 1
        };
        parallel.branches.insert(at, new_branch);
        return Ok(one_network(index, network, Some(focus)));
    }
    let Some((chain, _)) = chain_holding(&mut network, first) else {
        return Err(not_applicable(first, "inserting in parallel"));
    };
    let wanted: BTreeSet<ElementId> = selection.iter().copied().collect();
    let positions: Vec<usize> = chain
        .iter()
        .enumerate()
        .filter(|(_, node)| wanted.contains(&node.id()))
        .map(|(position, _)| position)
        .collect();
    let (Some(&start), Some(&end)) = (positions.first(), positions.last()) else {
        return Err(NetworkEditError::NotOneChain);
    };
    if positions.len() != wanted.len() || end - start + 1 != positions.len() {
        return Err(NetworkEditError::NotOneChain);
    }
    if single && let FlowNode::Parallel(parallel) = &mut chain[start] {
        let at = if side == ParallelSide::Above {
            0
        } else {
            parallel.branches.len()
        };
        parallel.branches.insert(at, new_branch);
        return Ok(one_network(index, network, Some(focus)));
    }
    let selected = Branch {
        rung: chain.drain(start..=end).collect(),
    };
    let branches = if side == ParallelSide::Above {
        vec![new_branch, selected]
    } else {
        vec![selected, new_branch]
    };
    let group = FlowNode::Parallel(Parallel {
        id: ids.next(),
        branches,
    });
    chain.insert(start, group);
    Ok(one_network(index, network, Some(focus)))
}

/// Inserts an output (a coil, jump or return, ids renumbered): below a selected output in its
/// list, or at the bottom of the outputs fed by the selected chain element or network.
pub fn insert_output(
    body: &[Network],
    anchor: Anchor,
    mut output: NetworkOutput,
) -> Result<BodySplice, NetworkEditError> {
    let mut ids = IdSource::after(body);
    ids.renumber_output(&mut output);
    let focus = output.id();
    let (index, mut network) = anchored_network(body, anchor)?;
    match anchor {
        Anchor::Network(_) => network.outputs.push(output),
        Anchor::Element(id) => {
            if let Some((outputs, position)) = outputs_holding(&mut network.outputs, id) {
                outputs.insert(position + 1, output);
            } else if let Some(outputs) = outputs_fed_by(&mut network, id) {
                outputs.push(output);
            } else {
                return Err(not_applicable(id, "inserting an output"));
            }
        }
    }
    Ok(one_network(index, network, Some(focus)))
}

/// Inserts `network` (ids renumbered) above or below network `index`; an empty body takes it
/// as its first network.
pub fn insert_network(
    body: &[Network],
    index: usize,
    side: Side,
    mut network: Network,
) -> Result<BodySplice, NetworkEditError> {
    if !body.is_empty() && index >= body.len() {
        return Err(NetworkEditError::NoSuchNetwork {
            index,
            count: body.len(),
        });
    }
    IdSource::after(body).renumber_network(&mut network);
    let at = if body.is_empty() || side == Side::Before {
        index.min(body.len())
    } else {
        index + 1
    };
    Ok(BodySplice {
        at,
        remove: 0,
        insert: vec![network],
        focus: None,
        focus_network: Some(at),
    })
}

/// Negates a contact (NO ↔ NC, dropping an edge), a coil (normal ↔ negated) or a box output
/// pin chosen by `pin` on a box.
pub fn toggle_negation(
    body: &[Network],
    id: ElementId,
    pin: Option<&str>,
) -> Result<BodySplice, NetworkEditError> {
    let index = network_index_of(body, id)?;
    let mut network = body[index].clone();
    let mut applied = false;
    edit_element(&mut network, id, |element| match element {
        ElementMut::Operand(operand) => {
            operand.negated = !operand.negated;
            operand.edge = Edge::None;
            applied = true;
        }
        ElementMut::Coil(coil) => {
            coil.kind = match coil.kind {
                CoilKind::Negated => CoilKind::Normal,
                _ => CoilKind::Negated,
            };
            applied = true;
        }
        ElementMut::Block(block) => {
            let Some(pin) = pin else { return };
            if let Some(input) = block.inputs.iter_mut().find(|input| input.pin == pin) {
                input.negated = !input.negated;
                applied = true;
            } else if let Some(output) = block.outputs.iter_mut().find(|output| output.pin == pin) {
                output.negated = !output.negated;
                applied = true;
            }
        }
        ElementMut::Jump(_) | ElementMut::Other => {}
    });
    if !applied {
        return Err(not_applicable(id, "negation"));
    }
    Ok(one_network(index, network, Some(id)))
}

/// Cycles the modifier of a contact (NO → NC → P → N → NO) or a coil (normal → negated → S →
/// R → P → N → normal), as OpenPLC v4's Shift+E does.
pub fn cycle_modifier(body: &[Network], id: ElementId) -> Result<BodySplice, NetworkEditError> {
    let index = network_index_of(body, id)?;
    let mut network = body[index].clone();
    let mut applied = false;
    edit_element(&mut network, id, |element| match element {
        ElementMut::Operand(operand) => {
            (operand.negated, operand.edge) = match (operand.negated, operand.edge) {
                (false, Edge::None) => (true, Edge::None),
                (true, _) => (false, Edge::Rising),
                (false, Edge::Rising) => (false, Edge::Falling),
                (false, Edge::Falling) => (false, Edge::None),
            };
            applied = true;
        }
        ElementMut::Coil(coil) => {
            coil.kind = match coil.kind {
                CoilKind::Normal => CoilKind::Negated,
                CoilKind::Negated => CoilKind::Set,
                CoilKind::Set => CoilKind::Reset,
                CoilKind::Reset => CoilKind::Rising,
                CoilKind::Rising => CoilKind::Falling,
                CoilKind::Falling => CoilKind::Normal,
            };
            applied = true;
        }
        ElementMut::Block(_) | ElementMut::Jump(_) | ElementMut::Other => {}
    });
    if !applied {
        return Err(not_applicable(id, "changing the modifier"));
    }
    Ok(one_network(index, network, Some(id)))
}

/// Sets the text of an element: a contact's operand, a coil's variable, a jump's label or a
/// box's instance.
pub fn set_element_text(
    body: &[Network],
    id: ElementId,
    text: &str,
) -> Result<BodySplice, NetworkEditError> {
    let index = network_index_of(body, id)?;
    let mut network = body[index].clone();
    let mut applied = false;
    edit_element(&mut network, id, |element| {
        applied = true;
        match element {
            ElementMut::Operand(operand) => operand.text = text.to_owned(),
            ElementMut::Coil(coil) => coil.variable = text.to_owned(),
            ElementMut::Block(block) => block.instance = text.to_owned(),
            ElementMut::Jump(label) => *label = text.to_owned(),
            ElementMut::Other => applied = false,
        }
    });
    if !applied {
        return Err(not_applicable(id, "setting the text"));
    }
    Ok(one_network(index, network, Some(id)))
}

/// Sets what drives input `pin` of box `id`: one operand reading `text` (an existing single
/// operand keeps its id), or nothing when `text` is empty.
pub fn set_pin_operand(
    body: &[Network],
    id: ElementId,
    pin: &str,
    text: &str,
) -> Result<BodySplice, NetworkEditError> {
    let index = network_index_of(body, id)?;
    let mut network = body[index].clone();
    let mut ids = IdSource::after(body);
    let mut applied = false;
    edit_element(&mut network, id, |element| {
        let ElementMut::Block(block) = element else {
            return;
        };
        let Some(input) = block.inputs.iter_mut().find(|input| input.pin == pin) else {
            return;
        };
        applied = true;
        if text.is_empty() {
            input.source.clear();
        } else if let [FlowNode::Operand(operand)] = input.source.as_mut_slice() {
            operand.text = text.to_owned();
        } else {
            let mut node = new_contact(text);
            ids.renumber_node(&mut node);
            input.source = vec![node];
        }
    });
    if !applied {
        return Err(not_applicable(id, "setting a pin's operand"));
    }
    Ok(one_network(index, network, Some(id)))
}

/// Sets the title, comment or label of network `index`.
pub fn set_network_header(
    body: &[Network],
    index: usize,
    field: HeaderField,
    text: &str,
) -> Result<BodySplice, NetworkEditError> {
    let mut network = network_at(body, index)?.clone();
    let target = match field {
        HeaderField::Title => &mut network.title,
        HeaderField::Comment => &mut network.comment,
        HeaderField::Label => &mut network.label,
    };
    *target = text.to_owned();
    let mut splice = one_network(index, network, None);
    splice.focus_network = Some(index);
    Ok(splice)
}

/// Deletes the selected elements with everything nested in them; a parallel group left with one
/// branch becomes that branch's chain, and one left with none disappears.
pub fn delete_elements(
    body: &[Network],
    selection: &[ElementId],
) -> Result<BodySplice, NetworkEditError> {
    if selection.is_empty() {
        return Err(NetworkEditError::NothingSelected);
    }
    let wanted: BTreeSet<ElementId> = selection.iter().copied().collect();
    let mut changed = BTreeMap::new();
    for &id in &wanted {
        let index = network_index_of(body, id)?;
        changed.entry(index).or_insert_with(|| body[index].clone());
    }
    for network in changed.values_mut() {
        delete_in_chain(&mut network.rung, &wanted);
        delete_in_outputs(&mut network.outputs, &wanted);
    }
    let focus_network = changed.keys().next().copied();
    let mut splice = splice_of(body, changed);
    splice.focus_network = focus_network;
    Ok(splice)
}

/// Deletes the networks in `range` (indices into the body).
pub fn delete_networks(
    body: &[Network],
    range: std::ops::Range<usize>,
) -> Result<BodySplice, NetworkEditError> {
    if range.is_empty() {
        return Err(NetworkEditError::NothingSelected);
    }
    if range.end > body.len() {
        return Err(NetworkEditError::NoSuchNetwork {
            index: range.end - 1,
            count: body.len(),
        });
    }
    Ok(BodySplice {
        at: range.start,
        remove: range.len(),
        insert: Vec::new(),
        focus: None,
        focus_network: (body.len() > range.len())
            .then(|| range.start.min(body.len() - range.len() - 1)),
    })
}

/// Copies the selected elements (an element nested in a selected one comes with it, not twice).
pub fn copy_elements(
    body: &[Network],
    selection: &[ElementId],
) -> Result<NetworkClipboard, NetworkEditError> {
    let wanted: BTreeSet<ElementId> = selection.iter().copied().collect();
    let mut clipboard = NetworkClipboard::default();
    for network in body {
        copy_from_chain(&network.rung, &wanted, &mut clipboard);
        copy_from_outputs(&network.outputs, &wanted, &mut clipboard);
    }
    if clipboard.is_empty() {
        return Err(NetworkEditError::NothingSelected);
    }
    Ok(clipboard)
}

/// Copies the networks in `range`.
pub fn copy_networks(
    body: &[Network],
    range: std::ops::Range<usize>,
) -> Result<NetworkClipboard, NetworkEditError> {
    let networks = body.get(range.clone()).unwrap_or_default().to_vec();
    if networks.is_empty() {
        return Err(NetworkEditError::NoSuchNetwork {
            index: range.start,
            count: body.len(),
        });
    }
    Ok(NetworkClipboard {
        networks,
        ..NetworkClipboard::default()
    })
}

/// Pastes `clipboard` with fresh ids: networks below the anchor's network, elements in series
/// after the anchor (or at the end of its rung), outputs below the anchor's outputs.
pub fn paste(
    body: &[Network],
    anchor: Anchor,
    clipboard: &NetworkClipboard,
) -> Result<BodySplice, NetworkEditError> {
    if clipboard.is_empty() {
        return Err(NetworkEditError::NothingSelected);
    }
    let mut ids = IdSource::after(body);
    if !clipboard.networks.is_empty() {
        let at = match anchor {
            Anchor::Network(index) => index + 1,
            Anchor::Element(id) => network_index_of(body, id)? + 1,
        }
        .min(body.len());
        let mut networks = clipboard.networks.clone();
        for network in &mut networks {
            ids.renumber_network(network);
        }
        return Ok(BodySplice {
            at,
            remove: 0,
            insert: networks,
            focus: None,
            focus_network: Some(at),
        });
    }
    let (index, mut network) = anchored_network(body, anchor)?;
    let mut nodes = clipboard.nodes.clone();
    for node in &mut nodes {
        ids.renumber_node(node);
    }
    let mut outputs = clipboard.outputs.clone();
    for output in &mut outputs {
        ids.renumber_output(output);
    }
    let focus = nodes
        .first()
        .map(FlowNode::id)
        .or_else(|| outputs.first().map(NetworkOutput::id));
    let anchor_id = match anchor {
        Anchor::Element(id) => Some(id),
        Anchor::Network(_) => None,
    };
    if !nodes.is_empty() {
        if let Some(id) = anchor_id {
            if let Some((chain, position)) = chain_holding(&mut network, id) {
                let at = position + 1;
                chain.splice(at..at, std::mem::take(&mut nodes));
            } else if let Some(chain) = chain_feeding_output(&mut network, id) {
                chain.append(&mut nodes);
            }
        }
        // Without a chain at the anchor the elements go to the end of the rung.
        network.rung.append(&mut nodes);
    }
    if !outputs.is_empty() {
        let list = match anchor_id.and_then(|id| outputs_fed_by(&mut network, id)) {
            Some(list) => list,
            None => &mut network.outputs,
        };
        list.extend(outputs);
    }
    Ok(one_network(index, network, focus))
}

/// Hands out fresh ids above the body's largest.
struct IdSource {
    /// The next id to hand out.
    next: u32,
}

impl IdSource {
    fn after(body: &[Network]) -> Self {
        Self {
            next: max_element_id(body).0.saturating_add(1),
        }
    }

    fn next(&mut self) -> ElementId {
        let id = ElementId(self.next);
        self.next = self.next.saturating_add(1);
        id
    }

    fn renumber_network(&mut self, network: &mut Network) {
        for node in &mut network.rung {
            self.renumber_node(node);
        }
        for output in &mut network.outputs {
            self.renumber_output(output);
        }
    }

    fn renumber_node(&mut self, node: &mut FlowNode) {
        match node {
            FlowNode::Operand(operand) => operand.id = self.next(),
            FlowNode::Parallel(parallel) => {
                parallel.id = self.next();
                for branch in &mut parallel.branches {
                    for node in &mut branch.rung {
                        self.renumber_node(node);
                    }
                }
            }
            FlowNode::Block(block) => {
                block.id = self.next();
                for input in &mut block.inputs {
                    for node in &mut input.source {
                        self.renumber_node(node);
                    }
                }
            }
        }
    }

    fn renumber_output(&mut self, output: &mut NetworkOutput) {
        match output {
            NetworkOutput::Coil(coil) => coil.id = self.next(),
            NetworkOutput::Jump { id, .. } | NetworkOutput::Return { id } => *id = self.next(),
            NetworkOutput::Branch { id, rung, outputs } => {
                *id = self.next();
                for node in rung {
                    self.renumber_node(node);
                }
                for output in outputs {
                    self.renumber_output(output);
                }
            }
        }
    }
}

/// One element, mutably, as the edits need it.
enum ElementMut<'a> {
    Operand(&'a mut Operand),
    Coil(&'a mut Coil),
    Block(&'a mut BlockCall),
    Jump(&'a mut String),
    Other,
}

fn not_applicable(id: ElementId, operation: &'static str) -> NetworkEditError {
    NetworkEditError::NotApplicable { id, operation }
}

fn network_at(body: &[Network], index: usize) -> Result<&Network, NetworkEditError> {
    body.get(index).ok_or(NetworkEditError::NoSuchNetwork {
        index,
        count: body.len(),
    })
}

fn network_index_of(body: &[Network], id: ElementId) -> Result<usize, NetworkEditError> {
    body.iter()
        .position(|network| network.element(id).is_some())
        .ok_or(NetworkEditError::NoSuchElement { id })
}

fn anchored_network(
    body: &[Network],
    anchor: Anchor,
) -> Result<(usize, Network), NetworkEditError> {
    let index = match anchor {
        Anchor::Network(index) => index,
        Anchor::Element(id) => network_index_of(body, id)?,
    };
    Ok((index, network_at(body, index)?.clone()))
}

fn one_network(index: usize, network: Network, focus: Option<ElementId>) -> BodySplice {
    BodySplice {
        at: index,
        remove: 1,
        insert: vec![network],
        focus,
        focus_network: Some(index),
    }
}

/// One splice replacing every network from the first changed one to the last.
fn splice_of(body: &[Network], changed: BTreeMap<usize, Network>) -> BodySplice {
    let (Some(&first), Some(&last)) = (changed.keys().next(), changed.keys().next_back()) else {
        return BodySplice::default();
    };
    let insert = (first..=last)
        .map(|index| {
            changed
                .get(&index)
                .cloned()
                .unwrap_or_else(|| body[index].clone())
        })
        .collect();
    BodySplice {
        at: first,
        remove: last - first + 1,
        insert,
        focus: None,
        focus_network: Some(first),
    }
}

/// Removes the wanted elements from `chain` and what is nested in it; returns whether anything
/// was removed.
fn delete_in_chain(chain: &mut Vec<FlowNode>, wanted: &BTreeSet<ElementId>) -> bool {
    let before = chain.len();
    chain.retain(|node| !wanted.contains(&node.id()));
    let mut changed = chain.len() != before;
    let mut position = 0;
    while position < chain.len() {
        match &mut chain[position] {
            FlowNode::Operand(_) => {}
            FlowNode::Parallel(parallel) => {
                let mut touched = false;
                for branch in &mut parallel.branches {
                    touched |= delete_in_chain(&mut branch.rung, wanted);
                }
                if touched {
                    changed = true;
                    // Only branches this deletion emptied go; an empty branch drawn on purpose
                    // (a bypass) would have been left alone had nothing in the group changed.
                    parallel.branches.retain(|branch| !branch.rung.is_empty());
                    match parallel.branches.len() {
                        0 => {
                            chain.remove(position);
                            continue;
                        }
                        1 => {
                            let rung = std::mem::take(&mut parallel.branches[0].rung);
                            let count = rung.len();
                            chain.splice(position..=position, rung);
                            position += count;
                            continue;
                        }
                        _ => {}
                    }
                }
            }
            FlowNode::Block(block) => {
                for input in &mut block.inputs {
                    changed |= delete_in_chain(&mut input.source, wanted);
                }
            }
        }
        position += 1;
    }
    changed
}

fn delete_in_outputs(outputs: &mut Vec<NetworkOutput>, wanted: &BTreeSet<ElementId>) {
    outputs.retain(|output| !wanted.contains(&output.id()));
    for output in outputs {
        if let NetworkOutput::Branch { rung, outputs, .. } = output {
            delete_in_chain(rung, wanted);
            delete_in_outputs(outputs, wanted);
        }
    }
}

fn copy_from_chain(chain: &[FlowNode], wanted: &BTreeSet<ElementId>, into: &mut NetworkClipboard) {
    for node in chain {
        if wanted.contains(&node.id()) {
            into.nodes.push(node.clone());
            continue;
        }
        match node {
            FlowNode::Operand(_) => {}
            FlowNode::Parallel(parallel) => {
                for branch in &parallel.branches {
                    copy_from_chain(&branch.rung, wanted, into);
                }
            }
            FlowNode::Block(block) => {
                for input in &block.inputs {
                    copy_from_chain(&input.source, wanted, into);
                }
            }
        }
    }
}

fn copy_from_outputs(
    outputs: &[NetworkOutput],
    wanted: &BTreeSet<ElementId>,
    into: &mut NetworkClipboard,
) {
    for output in outputs {
        if wanted.contains(&output.id()) {
            into.outputs.push(output.clone());
        } else if let NetworkOutput::Branch { rung, outputs, .. } = output {
            copy_from_chain(rung, wanted, into);
            copy_from_outputs(outputs, wanted, into);
        }
    }
}

#[cfg(test)]
mod tests;
