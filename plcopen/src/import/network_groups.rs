//! Where the networks of an LD or FBD body begin and end (`docs/plcopen-xml.md` §3.1): by
//! Rivet's `…/networks` entry, by CODESYS's network titles, or else by the wires.

use std::collections::{HashMap, HashSet};

use super::network_error::NetworkError;
use super::network_graph::{BodyGraph, ObjectFault, Producer};
use crate::add_data::AddData;
use crate::body_object::{BodyObject, ObjectKind};

/// The name Rivet's export gives the `addData` entry that delimits networks.
pub(super) const NETWORKS_ENTRY: &str = "https://rivet-plc.dev/plcopen/1/networks";

/// The objects of one network and what its header shows.
#[derive(Clone, Debug, Default, PartialEq)]
pub(super) struct NetworkGroup {
    /// The objects' indices in document order.
    pub members: Vec<usize>,
    /// The title.
    pub title: String,
    /// The comment.
    pub comment: String,
    /// The jump label.
    pub label: String,
}

/// The networks of a body in order.
pub(super) fn network_groups(
    graph: &BodyGraph<'_>,
    body_add_data: &AddData,
) -> Result<Vec<NetworkGroup>, ObjectFault> {
    if let Some(entry) = body_add_data
        .entries
        .iter()
        .find(|e| e.name == NETWORKS_ENTRY)
    {
        return rivet_groups(graph.objects, &entry.xml);
    }
    if graph.objects.iter().any(is_network_title) {
        return Ok(codesys_groups(graph.objects));
    }
    Ok(wired_groups(graph))
}

/// Whether an object is CODESYS's network title (a vendor element of type `networktitle`).
pub(super) fn is_network_title(object: &BodyObject) -> bool {
    matches!(object.kind, ObjectKind::VendorElement(_))
        && object
            .add_data
            .entry_ending_with("/fbdelementtype")
            .is_some_and(|entry| entry.xml.contains(">networktitle<"))
}

/// The objects that belong to a network's graph (not rails, comments, labels, connectors, …).
fn is_wired(object: &BodyObject) -> bool {
    matches!(
        object.kind,
        ObjectKind::Block(_)
            | ObjectKind::InVariable(_)
            | ObjectKind::OutVariable(_)
            | ObjectKind::InOutVariable(_)
            | ObjectKind::Jump(_)
            | ObjectKind::Return(_)
            | ObjectKind::Contact(_)
            | ObjectKind::Coil(_)
    )
}

fn rivet_groups(objects: &[BodyObject], xml: &str) -> Result<Vec<NetworkGroup>, ObjectFault> {
    // The entry belongs to the body, not to an object: the error stands at the body.
    let fault = |message: String| ObjectFault {
        object: usize::MAX,
        error: NetworkError::NetworksEntry(message),
    };
    let document = roxmltree::Document::parse(xml).map_err(|error| fault(error.to_string()))?;
    let mut groups: Vec<(u64, NetworkGroup)> = Vec::new();
    for node in document
        .descendants()
        .filter(|node| node.tag_name().name() == "network")
    {
        let first = node
            .attribute("first")
            .and_then(|text| text.parse::<u64>().ok())
            .ok_or_else(|| fault("a network without a numeric `first`".to_owned()))?;
        let text = |name| node.attribute(name).unwrap_or_default().to_owned();
        groups.push((
            first,
            NetworkGroup {
                members: Vec::new(),
                title: text("title"),
                comment: text("comment"),
                label: text("label"),
            },
        ));
    }
    let starts: HashMap<u64, usize> = groups
        .iter()
        .enumerate()
        .map(|(at, (first, _))| (*first, at))
        .collect();
    let mut current: Option<usize> = None;
    for (index, object) in objects.iter().enumerate() {
        if let Some(&start) = starts.get(&object.local_id) {
            current = Some(start);
        }
        if is_wired(object) {
            let group = current.unwrap_or(0);
            if let Some((_, group)) = groups.get_mut(group) {
                group.members.push(index);
            }
        }
    }
    let local_ids: HashSet<u64> = objects.iter().map(|object| object.local_id).collect();
    for (first, _) in &groups {
        if !local_ids.contains(first) {
            return Err(fault(format!("no object has the localId {first}")));
        }
    }
    Ok(groups.into_iter().map(|(_, group)| group).collect())
}

/// CODESYS: a network starts at each title (with the comment written just before it).
fn codesys_groups(objects: &[BodyObject]) -> Vec<NetworkGroup> {
    let mut groups: Vec<NetworkGroup> = Vec::new();
    let mut pending_comment: Option<String> = None;
    for (index, object) in objects.iter().enumerate() {
        match &object.kind {
            ObjectKind::Comment(text) => pending_comment = Some(text.text.trim().to_owned()),
            ObjectKind::VendorElement(element) if is_network_title(object) => {
                groups.push(NetworkGroup {
                    title: element.alternative_text.text.trim().to_owned(),
                    comment: pending_comment.take().unwrap_or_default(),
                    ..NetworkGroup::default()
                });
            }
            ObjectKind::Label(label) => {
                if groups.is_empty() {
                    groups.push(NetworkGroup::default());
                }
                if let Some(group) = groups.last_mut() {
                    group.label = label.label.trim().to_owned();
                }
            }
            _ if is_wired(object) => {
                if groups.is_empty() {
                    groups.push(NetworkGroup::default());
                }
                if let Some(group) = groups.last_mut() {
                    group.members.push(index);
                }
            }
            _ => {}
        }
    }
    groups
}

/// Beremiz and others: one network per set of objects joined by wires, ordered by the top of
/// their topmost element; comments and labels go to the first network at or below them.
fn wired_groups(graph: &BodyGraph<'_>) -> Vec<NetworkGroup> {
    let objects = graph.objects;
    let mut parent: Vec<usize> = (0..objects.len()).collect();
    fn root(parent: &mut [usize], mut at: usize) -> usize {
        while parent[at] != at {
            parent[at] = parent[parent[at]];
            at = parent[at];
        }
        at
    }
    for (consumer, points) in graph.inputs.iter().enumerate() {
        if !is_wired(&objects[consumer]) {
            continue;
        }
        for point in points {
            for producer in &point.producers {
                if let Producer::Output { object, .. } = producer
                    && is_wired(&objects[*object])
                {
                    let (a, b) = (root(&mut parent, consumer), root(&mut parent, *object));
                    parent[a] = b;
                }
            }
        }
    }
    let top = |index: usize| -> (f64, f64) {
        objects[index]
            .position
            .map_or((0.0, 0.0), |position| (position.y, position.x))
    };
    let mut components: Vec<(usize, Vec<usize>)> = Vec::new();
    let mut component_of_root: HashMap<usize, usize> = HashMap::new();
    for index in (0..objects.len()).filter(|&index| is_wired(&objects[index])) {
        let component = root(&mut parent, index);
        match component_of_root.get(&component) {
            Some(&at) => components[at].1.push(index),
            None => {
                component_of_root.insert(component, components.len());
                components.push((component, vec![index]));
            }
        }
    }
    let topmost = |members: &[usize]| -> (f64, f64, usize) {
        members
            .iter()
            .map(|&index| {
                let (y, x) = top(index);
                (y, x, index)
            })
            .min_by(|a, b| {
                a.0.total_cmp(&b.0)
                    .then(a.1.total_cmp(&b.1))
                    .then(a.2.cmp(&b.2))
            })
            .unwrap_or((0.0, 0.0, 0))
    };
    let bottom = |members: &[usize]| -> f64 {
        members
            .iter()
            .map(|&index| top(index).0)
            .fold(f64::NEG_INFINITY, f64::max)
    };
    components.sort_by(|(_, a), (_, b)| {
        let (a, b) = (topmost(a), topmost(b));
        a.0.total_cmp(&b.0)
            .then(a.1.total_cmp(&b.1))
            .then(a.2.cmp(&b.2))
    });
    let mut groups: Vec<NetworkGroup> = in_data_flow_order(graph, components)
        .into_iter()
        .map(|members| NetworkGroup {
            members,
            ..NetworkGroup::default()
        })
        .collect();
    for (index, object) in objects.iter().enumerate() {
        let (text, is_label) = match &object.kind {
            ObjectKind::Comment(text) => (text.text.trim().to_owned(), false),
            ObjectKind::Label(label) => (label.label.trim().to_owned(), true),
            _ => continue,
        };
        let y = top(index).0;
        // The network beside the comment or label, else the first one below it, else the last.
        let at = groups
            .iter()
            .position(|group| {
                !group.members.is_empty()
                    && topmost(&group.members).0 <= y
                    && y <= bottom(&group.members)
            })
            .or_else(|| {
                groups
                    .iter()
                    .position(|group| group.members.is_empty() || topmost(&group.members).0 >= y)
            });
        let at = match at {
            Some(at) if is_label && !groups[at].label.is_empty() => {
                groups.insert(at, NetworkGroup::default());
                at
            }
            Some(at) => at,
            None if groups
                .last()
                .is_none_or(|group| is_label && !group.label.is_empty()) =>
            {
                groups.push(NetworkGroup::default());
                groups.len() - 1
            }
            None => groups.len() - 1,
        };
        let group = &mut groups[at];
        if is_label {
            group.label = text;
        } else if group.comment.is_empty() {
            group.comment = text;
        } else {
            group.comment = format!("{}\n\n{text}", group.comment);
        }
    }
    groups
}

/// The networks in their order, except that a network reading a variable another network writes
/// through a wire (an instance's output, an `inOutVariable`) comes after it, as the data flow of
/// the drawn graph says; a cycle among them keeps the order of the drawing.
fn in_data_flow_order(graph: &BodyGraph<'_>, ordered: Vec<(usize, Vec<usize>)>) -> Vec<Vec<usize>> {
    let mut network_of = vec![usize::MAX; graph.objects.len()];
    for (network, (_, members)) in ordered.iter().enumerate() {
        for &member in members {
            network_of[member] = network;
        }
    }
    let mut before: Vec<Vec<usize>> = vec![Vec::new(); ordered.len()];
    for (network, (_, members)) in ordered.iter().enumerate() {
        for &member in members {
            for point in &graph.inputs[member] {
                for producer in &point.producers {
                    if let Producer::Read {
                        after: Some(writer),
                        ..
                    } = producer
                    {
                        let first = network_of[*writer];
                        if first != usize::MAX && first != network {
                            before[network].push(first);
                        }
                    }
                }
            }
        }
    }
    if before.iter().all(Vec::is_empty) {
        return ordered.into_iter().map(|(_, members)| members).collect();
    }
    let mut placed = vec![false; ordered.len()];
    let mut order = Vec::with_capacity(ordered.len());
    while order.len() < ordered.len() {
        let next = (0..ordered.len())
            .find(|&network| !placed[network] && before[network].iter().all(|&first| placed[first]))
            .or_else(|| (0..ordered.len()).find(|&network| !placed[network]));
        let Some(next) = next else { break };
        placed[next] = true;
        order.push(next);
    }
    let mut ordered: Vec<Option<Vec<usize>>> = ordered
        .into_iter()
        .map(|(_, members)| Some(members))
        .collect();
    order
        .into_iter()
        .filter_map(|network| ordered[network].take())
        .collect()
}
