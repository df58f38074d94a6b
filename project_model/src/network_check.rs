//! The structural rules of an LD/FBD body, checked on load, on save and by edits.
//!
//! These rules make a body's meaning well-defined for the lowering into Structured Text: every
//! element is found by its id, every jump label names one network, every box pin by its name,
//! and no input is driven twice. Names of variables and types are left to the checker, so an
//! empty operand text or coil variable is allowed here.

use std::collections::HashMap;
use std::fmt;

use crate::{BlockCall, ElementId, FlowNode, Network, NetworkOutput, is_valid_identifier};

/// The deepest nesting of chains (parallel branches, box inputs, output branches) a body may
/// have, so that no file can exhaust the stack of the code that walks it.
pub const MAX_NETWORK_NESTING: usize = 64;

/// A broken rule of an LD/FBD body, at a network and, where it has one, an element.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct NetworkProblem {
    /// The 0-based index of the network in its body.
    pub network: usize,
    /// The network's label, or else its title; empty when it has neither.
    pub network_name: String,
    /// The element the problem is at, if it is at one.
    pub element: Option<ElementId>,
    /// What is wrong, in a sentence without the location.
    pub message: String,
}

impl fmt::Display for NetworkProblem {
    /// Formats as `network 3 'Start', element 17: message`, with the 1-based network number.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "network {}", self.network + 1)?;
        if !self.network_name.is_empty() {
            write!(f, " '{}'", self.network_name)?;
        }
        if let Some(element) = self.element {
            write!(f, ", element {}", element.0)?;
        }
        write!(f, ": {}", self.message)
    }
}

/// Every broken rule of the body `networks`, in network order; empty when the body is sound.
pub fn network_problems(networks: &[Network]) -> Vec<NetworkProblem> {
    let mut checker = Checker {
        problems: Vec::new(),
        ids: HashMap::new(),
        labels: HashMap::new(),
        network: 0,
        network_name: String::new(),
    };
    for (index, network) in networks.iter().enumerate() {
        checker.network = index;
        checker.network_name = if network.label.is_empty() {
            network.title.clone()
        } else {
            network.label.clone()
        };
        checker.check_label(&network.label);
        checker.check_chain(
            &network.rung,
            ChainKind::Rung,
            !network.outputs.is_empty(),
            0,
        );
        checker.check_outputs(&network.outputs, 0);
    }
    checker.problems
}

/// Where a chain is, which decides what feeds its first element.
#[derive(Clone, Copy, PartialEq, Eq)]
enum ChainKind {
    /// A network's rung, fed by the left power rail.
    Rung,
    /// An input's source: a value of its own.
    Source,
    /// A parallel branch, fed by the power before the group.
    ParallelBranch,
    /// An output branch, fed by the power at the end of the rung.
    OutputBranch,
}

struct Checker {
    problems: Vec<NetworkProblem>,
    /// Every id seen so far in the body, with the 1-based number of its network.
    ids: HashMap<ElementId, usize>,
    /// Every label seen so far, lower case, with the 1-based number of its network.
    labels: HashMap<String, usize>,
    network: usize,
    network_name: String,
}

impl Checker {
    fn report(&mut self, element: Option<ElementId>, message: String) {
        self.problems.push(NetworkProblem {
            network: self.network,
            network_name: self.network_name.clone(),
            element,
            message,
        });
    }

    fn check_label(&mut self, label: &str) {
        if label.is_empty() {
            return;
        }
        if !is_valid_identifier(label) {
            self.report(
                None,
                format!("the label '{label}' is not an identifier (letters, digits and '_')"),
            );
            return;
        }
        let key = label.to_lowercase();
        match self.labels.get(&key) {
            Some(other) => {
                let other = *other;
                self.report(
                    None,
                    format!("the label '{label}' is also the label of network {other}"),
                );
            }
            None => {
                self.labels.insert(key, self.network + 1);
            }
        }
    }

    fn check_id(&mut self, id: ElementId) {
        match self.ids.get(&id) {
            Some(&other) if other == self.network + 1 => {
                self.report(Some(id), format!("two elements have the id {}", id.0));
            }
            Some(&other) => {
                self.report(
                    Some(id),
                    format!(
                        "two elements have the id {}; the other is in network {other}",
                        id.0
                    ),
                );
            }
            None => {
                self.ids.insert(id, self.network + 1);
            }
        }
    }

    fn too_deep(&mut self, id: ElementId, depth: usize) -> bool {
        if depth < MAX_NETWORK_NESTING {
            return false;
        }
        self.report(
            Some(id),
            format!("the element is nested more than {MAX_NETWORK_NESTING} levels deep"),
        );
        true
    }

    /// Checks a chain; `result_used` tells whether the value at its end feeds something.
    fn check_chain(
        &mut self,
        chain: &[FlowNode],
        kind: ChainKind,
        result_used: bool,
        depth: usize,
    ) {
        for (index, node) in chain.iter().enumerate() {
            self.check_id(node.id());
            if self.too_deep(node.id(), depth) {
                continue;
            }
            let passes_on = index + 1 < chain.len() || result_used;
            match node {
                FlowNode::Operand(_) => {}
                FlowNode::Parallel(parallel) => {
                    if parallel.branches.len() < 2 {
                        self.report(
                            Some(parallel.id),
                            format!(
                                "a parallel group needs at least two branches; it has {}",
                                parallel.branches.len()
                            ),
                        );
                    }
                    for branch in &parallel.branches {
                        self.check_chain(&branch.rung, ChainKind::ParallelBranch, true, depth + 1);
                    }
                }
                FlowNode::Block(block) => {
                    let fed_by_power = index > 0
                        || matches!(kind, ChainKind::ParallelBranch | ChainKind::OutputBranch);
                    self.check_block(block, fed_by_power, passes_on, depth);
                }
            }
        }
    }

    fn check_block(
        &mut self,
        block: &BlockCall,
        fed_by_power: bool,
        passes_on: bool,
        depth: usize,
    ) {
        let id = Some(block.id);
        if block.type_name.trim().is_empty() {
            self.report(id, "the box has no type name".into());
        }
        let pins = block
            .inputs
            .iter()
            .map(|input| input.pin.as_str())
            .chain(block.outputs.iter().map(|output| output.pin.as_str()));
        let mut seen: Vec<String> = Vec::new();
        for pin in pins {
            if !is_valid_identifier(pin) {
                self.report(
                    id,
                    format!("the pin name '{pin}' is not an identifier (letters, digits and '_')"),
                );
                continue;
            }
            let key = pin.to_lowercase();
            if seen.contains(&key) {
                self.report(id, format!("the box has two pins named '{pin}'"));
            } else {
                seen.push(key);
            }
        }
        if let Some(first) = block.inputs.first()
            && fed_by_power
            && !first.source.is_empty()
        {
            self.report(
                id,
                format!(
                    "the input '{}' is driven twice: by the power flowing into the box and by \
                     its own source; a box whose first input has a source can only stand first \
                     in a rung or an input's source",
                    first.pin
                ),
            );
        }
        if passes_on && block.outputs.is_empty() {
            self.report(
                id,
                "the box has no output, so it cannot pass the power or its value on to what \
                 follows it"
                    .into(),
            );
        }
        for input in &block.inputs {
            self.check_chain(&input.source, ChainKind::Source, true, depth + 1);
        }
    }

    fn check_outputs(&mut self, outputs: &[NetworkOutput], depth: usize) {
        for output in outputs {
            self.check_id(output.id());
            if self.too_deep(output.id(), depth) {
                continue;
            }
            if let NetworkOutput::Branch { rung, outputs, .. } = output {
                self.check_chain(
                    rung,
                    ChainKind::OutputBranch,
                    !outputs.is_empty(),
                    depth + 1,
                );
                self.check_outputs(outputs, depth + 1);
            }
        }
    }
}

#[cfg(test)]
#[path = "network_check_tests.rs"]
mod tests;
