//! The power flow of a network where the lowering stored none: derived from the contacts'
//! values as `docs/graphical-semantics.md` §6.3 says, ANDed along a chain and ORed over the
//! branches of a parallel group.

use std::collections::HashMap;

use project_model::{BlockCall, Edge, ElementId, FlowNode, Network, NetworkOutput, Operand};

/// What the target reported for one body, as the derivation reads it.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(super) struct PowerReadings {
    /// The stored power leaving an element, where the lowering kept it (its power probe).
    pub power: HashMap<ElementId, bool>,
    /// The Boolean value of an element's operand (a contact's variable).
    pub values: HashMap<ElementId, bool>,
    /// The output of an edge contact's detection: TRUE for the cycle of the edge.
    pub edges: HashMap<ElementId, bool>,
    /// The Boolean value of a box's output pin (a timer's `Q`, a comparison's stored result),
    /// by the box and the pin's upper-case name.
    pub pins: HashMap<(ElementId, String), bool>,
}

/// The power leaving every element of `network` whose power is known or can be derived: the
/// stored power where there is one, otherwise the power entering the element ANDed with the
/// contact's state; a parallel group ORs its branches; a coil, jump or return shows the power
/// at the end of its rung.
pub(super) fn network_power(
    network: &Network,
    readings: &PowerReadings,
) -> HashMap<ElementId, bool> {
    let mut power = HashMap::new();
    // The left rail is always powered.
    let end = chain_power(&network.rung, Some(true), readings, &mut power);
    outputs_power(&network.outputs, end, readings, &mut power);
    power
}

/// The power after each node of `chain` entered with `incoming`; returns the power leaving it.
fn chain_power(
    chain: &[FlowNode],
    incoming: Option<bool>,
    readings: &PowerReadings,
    power: &mut HashMap<ElementId, bool>,
) -> Option<bool> {
    let mut flowing = incoming;
    for node in chain {
        let (id, derived) = match node {
            FlowNode::Operand(operand) => (operand.id, contact_power(operand, flowing, readings)),
            FlowNode::Parallel(group) => {
                let mut any = Some(false);
                for branch in &group.branches {
                    any = or(any, chain_power(&branch.rung, flowing, readings, power));
                }
                (group.id, any)
            }
            FlowNode::Block(block) => (block.id, block_power(block, readings, power)),
        };
        // A stored power is what the target computed; it wins over any derivation.
        flowing = readings.power.get(&id).copied().or(derived);
        if let Some(on) = flowing {
            power.insert(id, on);
        }
    }
    flowing
}

/// A contact passes power when power enters and its state is TRUE (negated for a normally
/// closed contact; the detection's output for an edge contact).
fn contact_power(
    operand: &Operand,
    incoming: Option<bool>,
    readings: &PowerReadings,
) -> Option<bool> {
    let state = match operand.edge {
        Edge::None => readings
            .values
            .get(&operand.id)
            .copied()
            .or_else(|| literal(&operand.text))
            .map(|value| value != operand.negated),
        Edge::Rising | Edge::Falling => readings.edges.get(&operand.id).copied(),
    };
    and(incoming, state)
}

/// A box's pins' sources are chains of their own, started powered as an FBD input is. What
/// leaves a box depends on its block (a timer's `Q`, a comparison's result, a number), so it
/// is the value of the output that passes the power on, where that pin's value was read and
/// is not negated (the probe of a negated instance output reads the instance's own output),
/// else unknown rather than guessed from what entered it.
fn block_power(
    block: &BlockCall,
    readings: &PowerReadings,
    power: &mut HashMap<ElementId, bool>,
) -> Option<bool> {
    for input in &block.inputs {
        chain_power(&input.source, Some(true), readings, power);
    }
    let output = block.outputs.get(block.chain_output()?)?;
    if output.negated {
        return None;
    }
    readings
        .pins
        .get(&(block.id, output.pin.trim().to_uppercase()))
        .copied()
}

/// The outputs see the power at the end of the rung; a branch output continues it.
fn outputs_power(
    outputs: &[NetworkOutput],
    incoming: Option<bool>,
    readings: &PowerReadings,
    power: &mut HashMap<ElementId, bool>,
) {
    for output in outputs {
        match output {
            NetworkOutput::Coil(coil) => {
                if let Some(on) = incoming {
                    power.insert(coil.id, on);
                }
            }
            NetworkOutput::Jump { id, .. } | NetworkOutput::Return { id } => {
                if let Some(on) = incoming {
                    power.insert(*id, on);
                }
            }
            NetworkOutput::Branch { id, rung, outputs } => {
                if let Some(on) = incoming {
                    power.insert(*id, on);
                }
                let end = chain_power(rung, incoming, readings, power);
                outputs_power(outputs, end, readings, power);
            }
        }
    }
}

/// A Boolean literal written as a contact's operand.
fn literal(text: &str) -> Option<bool> {
    let text = text.trim();
    if text.eq_ignore_ascii_case("TRUE") {
        Some(true)
    } else if text.eq_ignore_ascii_case("FALSE") {
        Some(false)
    } else {
        None
    }
}

/// AND of two possibly unknown values: FALSE when either is FALSE, whatever the other.
fn and(a: Option<bool>, b: Option<bool>) -> Option<bool> {
    match (a, b) {
        (Some(false), _) | (_, Some(false)) => Some(false),
        (Some(true), Some(true)) => Some(true),
        _ => None,
    }
}

/// OR of two possibly unknown values: TRUE when either is TRUE, whatever the other.
fn or(a: Option<bool>, b: Option<bool>) -> Option<bool> {
    match (a, b) {
        (Some(true), _) | (_, Some(true)) => Some(true),
        (Some(false), Some(false)) => Some(false),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use project_model::{Branch, Coil, Parallel};

    fn contact(id: u32, text: &str, negated: bool) -> FlowNode {
        FlowNode::Operand(Operand {
            id: ElementId(id),
            text: text.to_owned(),
            negated,
            ..Operand::default()
        })
    }

    fn coil(id: u32) -> NetworkOutput {
        NetworkOutput::Coil(Coil {
            id: ElementId(id),
            variable: "xOut".to_owned(),
            ..Coil::default()
        })
    }

    fn network(rung: Vec<FlowNode>) -> Network {
        Network {
            rung,
            outputs: vec![coil(99)],
            ..Network::default()
        }
    }

    fn values(pairs: &[(u32, bool)]) -> PowerReadings {
        PowerReadings {
            values: pairs.iter().map(|(id, on)| (ElementId(*id), *on)).collect(),
            ..PowerReadings::default()
        }
    }

    #[test]
    fn a_series_chain_ands_its_contacts_and_a_closed_contact_negates() {
        let net = network(vec![contact(1, "a", false), contact(2, "b", true)]);
        let power = network_power(&net, &values(&[(1, true), (2, false)]));
        assert!(power[&ElementId(1)]);
        assert!(power[&ElementId(2)]);
        assert!(power[&ElementId(99)]);
        let power = network_power(&net, &values(&[(1, false), (2, false)]));
        assert!(!power[&ElementId(1)]);
        // Without power entering, the second contact passes none whatever its value.
        assert!(!power[&ElementId(2)]);
        assert!(!power[&ElementId(99)]);
    }

    #[test]
    fn a_parallel_group_ors_its_branches() {
        let group = FlowNode::Parallel(Parallel {
            id: ElementId(5),
            branches: vec![
                Branch {
                    rung: vec![contact(6, "a", false)],
                },
                Branch {
                    rung: vec![contact(7, "b", false)],
                },
            ],
        });
        let net = network(vec![group, contact(8, "c", false)]);
        let power = network_power(&net, &values(&[(6, false), (7, true), (8, true)]));
        assert!(!power[&ElementId(6)]);
        assert!(power[&ElementId(7)]);
        assert!(power[&ElementId(5)]);
        assert!(power[&ElementId(99)]);
        let power = network_power(&net, &values(&[(6, false), (7, false), (8, true)]));
        assert!(!power[&ElementId(5)]);
        assert!(!power[&ElementId(99)]);
    }

    #[test]
    fn unknown_values_stay_unknown_unless_the_other_side_decides() {
        let net = network(vec![contact(1, "a", false), contact(2, "b", false)]);
        let power = network_power(&net, &values(&[(2, true)]));
        assert_eq!(power.get(&ElementId(1)), None);
        assert_eq!(power.get(&ElementId(2)), None);
        let power = network_power(&net, &values(&[(2, false)]));
        assert!(!power[&ElementId(2)]);
    }

    #[test]
    fn a_stored_power_wins_and_edges_read_their_detection() {
        let mut edge = Operand {
            id: ElementId(3),
            text: "a".to_owned(),
            edge: Edge::Rising,
            ..Operand::default()
        };
        edge.negated = false;
        let net = network(vec![FlowNode::Operand(edge), contact(4, "TRUE", false)]);
        let mut readings = values(&[(3, true)]);
        readings.edges.insert(ElementId(3), false);
        let power = network_power(&net, &readings);
        // The variable is TRUE but no edge happened this cycle.
        assert!(!power[&ElementId(3)]);
        readings.edges.insert(ElementId(3), true);
        readings.power.insert(ElementId(4), false);
        let power = network_power(&net, &readings);
        assert!(power[&ElementId(3)]);
        assert!(!power[&ElementId(4)]);
        assert!(!power[&ElementId(99)]);
    }

    #[test]
    fn a_box_passes_its_stored_power_and_nothing_guessed() {
        let block = FlowNode::Block(BlockCall {
            id: ElementId(11),
            type_name: "TON".to_owned(),
            instance: "tonDelay".to_owned(),
            inputs: Vec::new(),
            outputs: Vec::new(),
        });
        let net = network(vec![contact(10, "a", false), block]);
        let mut readings = values(&[(10, true)]);
        let power = network_power(&net, &readings);
        assert!(power[&ElementId(10)]);
        assert_eq!(power.get(&ElementId(11)), None);
        assert_eq!(power.get(&ElementId(99)), None);
        readings.power.insert(ElementId(11), true);
        let power = network_power(&net, &readings);
        assert!(power[&ElementId(11)]);
        assert!(power[&ElementId(99)]);
    }

    #[test]
    fn a_box_passes_the_value_of_its_chain_output_pin() {
        let compare = |negated: bool| BlockCall {
            id: ElementId(11),
            type_name: "GT".to_owned(),
            instance: String::new(),
            inputs: Vec::new(),
            outputs: vec![project_model::BlockOutput {
                pin: "OUT".to_owned(),
                negated,
                ..project_model::BlockOutput::default()
            }],
        };
        let mut readings = values(&[(10, true)]);
        readings
            .pins
            .insert((ElementId(11), "OUT".to_owned()), false);
        let net = network(vec![
            contact(10, "a", false),
            FlowNode::Block(compare(false)),
        ]);
        let power = network_power(&net, &readings);
        assert_eq!(power.get(&ElementId(11)), Some(&false));
        assert_eq!(power.get(&ElementId(99)), Some(&false));
        let net = network(vec![
            contact(10, "a", false),
            FlowNode::Block(compare(true)),
        ]);
        assert_eq!(network_power(&net, &readings).get(&ElementId(11)), None);
    }
}
