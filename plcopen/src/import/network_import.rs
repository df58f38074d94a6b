//! LD and FBD bodies → Rivet networks: the entry point the POU conversion calls
//! (`docs/plcopen-xml.md` §3).

use std::collections::BTreeMap;

use project_model::{ElementId, FlowNode, Network, NetworkOutput};

use super::converter::{Converter, Place, is_rivet_entry};
use super::error::{ImportError, ImportErrorKind};
use super::network_build::{BuildFailure, NetworkBuilder};
use super::network_error::NetworkError;
use super::network_graph::{BodyGraph, ObjectFault};
use super::network_groups::{NETWORKS_ENTRY, is_network_title, network_groups};
use super::report::Outcome;
use crate::add_data::AddData;
use crate::body::{Body as XmlBody, BodyContent};
use crate::body_object::ObjectKind;

/// The element id each object of a body became, by the object's `localId` (an object repeated
/// in several places, a contact of a bridge, by its first element in tree order).
pub(super) type ElementIds = BTreeMap<u64, ElementId>;

/// What became of an LD or FBD body.
#[derive(Clone, Debug, PartialEq)]
pub(super) enum NetworkOutcome {
    /// The body's networks, with element ids numbered from 1 in tree order, and the element
    /// each object became, so that the objects' vendor data can follow them (§5.5).
    Networks(Vec<Network>, ElementIds),
    /// A sound graph that structured networks cannot hold (a feedback loop, a value read by
    /// two inputs): the body can be imported as a CFC chart instead.
    NotANetwork {
        /// Why, in a sentence naming the element.
        reason: String,
    },
}

impl Converter<'_> {
    /// Converts the LD or FBD `body` of the object at `place` (`what` names it in the report)
    /// into networks; `None` when the body is in another language.
    pub fn networks(
        &mut self,
        body: &XmlBody,
        place: &Place,
        what: &str,
    ) -> Result<Option<NetworkOutcome>, ImportError> {
        let objects = match &body.content {
            BodyContent::Ld(objects) | BodyContent::Fbd(objects) if body.cfc.is_none() => objects,
            _ => return Ok(None),
        };
        let language = body.content.language();
        let body_path = format!("{}/body/{language}", place.path);
        let fault = |converter: &Self, fault: ObjectFault| -> ImportError {
            let object_place = match objects.get(fault.object) {
                Some(object) => Place {
                    path: format!(
                        "{body_path}/{}[@localId='{}']",
                        object.kind.element_name(),
                        object.local_id
                    ),
                    line: object.line,
                    column: object.column,
                },
                None => Place {
                    path: body_path.clone(),
                    line: body.line,
                    column: 1,
                },
            };
            converter.error(&object_place, ImportErrorKind::Network(fault.error))
        };
        // Rivet's export keeps power that fans out (an operand or a box output several branches
        // or outputs follow) as wires, and always writes its `…/networks` entry; another tool's
        // variables are read again for each reader, as they always were (§3.3).
        let plain = BodyGraph::new(objects, false).map_err(|error| fault(self, error))?;
        let outcome = if body
            .add_data
            .entries
            .iter()
            .any(|entry| entry.name == NETWORKS_ENTRY)
        {
            let wired = BodyGraph::new(objects, true).map_err(|error| fault(self, error))?;
            rivet_networks(&wired, &plain, &body.add_data)
        } else {
            build_networks(&plain, &body.add_data).map(|networks| (networks, Vec::new()))
        };
        let (mut networks, read_again) = match outcome {
            Ok(built) => built,
            Err(BuildFailure::Fault(error)) => return Err(fault(self, error)),
            Err(BuildFailure::NotANetwork(reason)) => {
                return Ok(Some(NetworkOutcome::NotANetwork { reason }));
            }
        };
        for network in read_again {
            self.report.push(
                Outcome::Converted,
                format!("network {} of {what}", network + 1),
                &body_path,
                body.line,
                "its wires no longer fit Rivet's export (another tool changed them): \
                 read as another tool's network, each variable read again for each reader",
            );
        }
        // Series-parallel reduction nests parallel groups as deep as the wires do; the normal
        // form and the numbering recurse, so the nesting is checked first.
        if networks.iter().any(project_model::is_nested_too_deeply) {
            let place = Place {
                path: body_path.clone(),
                line: body.line,
                column: 1,
            };
            return Err(self.error(
                &place,
                ImportErrorKind::Network(NetworkError::TooDeep {
                    limit: project_model::MAX_NETWORK_NESTING,
                }),
            ));
        }
        project_model::normalize_networks(&mut networks);
        let element_ids: ElementIds = number_elements(&mut networks)
            .into_iter()
            .filter_map(|(object, id)| Some((objects.get(object)?.local_id, id)))
            .collect();
        if let Some(problem) = project_model::network_problems(&networks).first() {
            let place = Place {
                path: body_path.clone(),
                line: body.line,
                column: 1,
            };
            return Err(self.error(
                &place,
                ImportErrorKind::Network(NetworkError::Problem(problem.to_string())),
            ));
        }
        for object in objects {
            let object_path = format!(
                "{body_path}/{}[@localId='{}']",
                object.kind.element_name(),
                object.local_id
            );
            match &object.kind {
                ObjectKind::VendorElement(_) if !is_network_title(object) => self.report.push(
                    Outcome::NotConverted,
                    format!("vendorElement of {what}"),
                    &object_path,
                    object.line,
                    "Rivet's networks have no element of another tool's own",
                ),
                ObjectKind::Error(text) => self.report.push(
                    Outcome::NotConverted,
                    format!("error element of {what}"),
                    &object_path,
                    object.line,
                    text.text.trim().to_owned(),
                ),
                _ => {}
            }
            // The data of a wire (CODESYS's `ldbranchid`) has no element to go with: the
            // networks' wires follow from their structure, so it is listed, not kept.
            for point in object.kind.graph_inputs() {
                for connection in &point.connections {
                    for entry in &connection.add_data.entries {
                        if is_rivet_entry(&entry.name) {
                            continue;
                        }
                        let entry_path = format!(
                            "{object_path}/connectionPointIn/connection[@refLocalId='{}']/addData/data[@name='{}']",
                            connection.ref_local_id, entry.name
                        );
                        // A body read for a condition and again for its chart says it once.
                        if !self.reported_object_data.insert(entry_path.clone()) {
                            continue;
                        }
                        self.report.push(
                            Outcome::NotConverted,
                            format!("addData '{}'", entry.name),
                            &entry_path,
                            object.line,
                            "the data of a wire: Rivet's networks rebuild their wires from the rungs, so it has nothing to go with",
                        );
                    }
                }
            }
        }
        Ok(Some(NetworkOutcome::Networks(networks, element_ids)))
    }
}

/// The networks of another tool's body whose wires are `graph`, or why they are none.
fn build_networks(
    graph: &BodyGraph<'_>,
    body_add_data: &AddData,
) -> Result<Vec<Network>, BuildFailure> {
    refuse_loops(graph)?;
    let groups = network_groups(graph, body_add_data)?;
    let mut networks = Vec::with_capacity(groups.len());
    for group in groups {
        let builder = NetworkBuilder::new(graph, &group.members, false);
        networks.push(builder.build(group.title, group.comment, group.label)?);
    }
    Ok(networks)
}

/// The id an element built from the body's object at `object` (its index) carries until
/// [`number_elements`] gives it its own: the index + 1, so the numbering can tell which object
/// each element came from (0 is no object).
pub(super) fn provisional_id(object: usize) -> ElementId {
    ElementId(u32::try_from(object).map_or(0, |index| index.saturating_add(1)))
}

/// `node` (an operand) marked as built from the body's object at `object`.
pub(super) fn from_object(mut node: FlowNode, object: usize) -> FlowNode {
    if let FlowNode::Operand(operand) = &mut node {
        operand.id = provisional_id(object);
    }
    node
}

/// The networks of a body Rivet's export wrote (`wired`: power that fans out kept as wires),
/// with the indices of the networks that only `plain` (every variable read again for each
/// reader) gives, as another tool's file: a network another tool edited falls back alone.
fn rivet_networks(
    wired: &BodyGraph<'_>,
    plain: &BodyGraph<'_>,
    body_add_data: &AddData,
) -> Result<(Vec<Network>, Vec<usize>), BuildFailure> {
    // Wires kept where reads were can close a loop the plain graph does not have; a loop
    // belongs to the whole body, so the whole body is read as another tool's.
    if wired.object_on_loop().is_some() {
        let networks = build_networks(plain, body_add_data)?;
        let every = (0..networks.len()).collect();
        return Ok((networks, every));
    }
    let groups = network_groups(wired, body_add_data)?;
    let mut networks = Vec::with_capacity(groups.len());
    let mut read_again = Vec::new();
    for (index, group) in groups.into_iter().enumerate() {
        let builder = NetworkBuilder::new(wired, &group.members, true);
        let built = builder.build(
            group.title.clone(),
            group.comment.clone(),
            group.label.clone(),
        );
        let network = match built {
            Ok(network) => network,
            Err(_) => {
                read_again.push(index);
                NetworkBuilder::new(plain, &group.members, false).build(
                    group.title,
                    group.comment,
                    group.label,
                )?
            }
        };
        networks.push(network);
    }
    Ok((networks, read_again))
}

/// Refuses a body with a wire loop as no set of networks.
fn refuse_loops(graph: &BodyGraph<'_>) -> Result<(), BuildFailure> {
    match graph.object_on_loop() {
        Some(object) => {
            let object = &graph.objects[object];
            Err(BuildFailure::NotANetwork(format!(
                "the {} with local id {} is on a feedback loop",
                object.kind.element_name(),
                object.local_id
            )))
        }
        None => Ok(()),
    }
}

/// Gives every element a fresh id, from 1 in tree order (networks in order; in a network its
/// rung, then its outputs; an element before the chains inside it); gives the fresh id of the
/// first element built from each object (by the object's index), as [`provisional_id`] marked
/// them.
pub(crate) fn number_elements(networks: &mut [Network]) -> BTreeMap<usize, ElementId> {
    let mut numbering = Numbering::default();
    for network in networks {
        number_chain(&mut network.rung, &mut numbering);
        number_outputs(&mut network.outputs, &mut numbering);
    }
    numbering.of_object
}

/// The numbering of one body's elements.
#[derive(Default)]
struct Numbering {
    /// The last id given.
    last: u32,
    /// The fresh id of the first element of each object, by the object's index.
    of_object: BTreeMap<usize, ElementId>,
}

impl Numbering {
    /// A fresh id for the element that carries `provisional`.
    fn fresh(&mut self, provisional: ElementId) -> ElementId {
        self.last += 1;
        let id = ElementId(self.last);
        if let Some(object) = provisional.0.checked_sub(1) {
            self.of_object.entry(object as usize).or_insert(id);
        }
        id
    }
}

fn number_chain(chain: &mut [FlowNode], next: &mut Numbering) {
    for node in chain {
        match node {
            FlowNode::Operand(operand) => operand.id = next.fresh(operand.id),
            FlowNode::Parallel(parallel) => {
                parallel.id = next.fresh(parallel.id);
                for branch in &mut parallel.branches {
                    number_chain(&mut branch.rung, next);
                }
            }
            FlowNode::Block(block) => {
                block.id = next.fresh(block.id);
                for input in &mut block.inputs {
                    number_chain(&mut input.source, next);
                }
            }
        }
    }
}

fn number_outputs(outputs: &mut [NetworkOutput], next: &mut Numbering) {
    for output in outputs {
        match output {
            NetworkOutput::Coil(coil) => coil.id = next.fresh(coil.id),
            NetworkOutput::Jump { id, .. } | NetworkOutput::Return { id } => *id = next.fresh(*id),
            NetworkOutput::Branch {
                id, rung, outputs, ..
            } => {
                *id = next.fresh(*id);
                number_chain(rung, next);
                number_outputs(outputs, next);
            }
        }
    }
}
